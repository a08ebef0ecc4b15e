// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.util.Arrays;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Colour-map optimization on tests/capi/test_color_map.c's scene, whose answer is known: a box room with a smooth
 * colour texture, ray-cast into five 8-bit RGB + float depth views of one corner, given with each pose turned by 1.5
 * degrees and moved about 2 cm. Both optimizers move the poses toward the truth and the colours toward the texture
 * (the images pass as an RGBDImage[]); and the errors.
 */
class ColorMapTest {
    static final int W = 160, H = 120, GRID = 31;
    static final double[] LO = {-1.2, -1.0, -1.0}, HI = {1.2, 1.0, 1.6};
    static TriangleMesh mesh;
    static RGBDImage[] images = new RGBDImage[5];
    static PinholeCameraTrajectory start;
    static double[][] truth = new double[5][]; // world to camera

    static double[] texture(double[] p) {
        return new double[] {
            0.5 + 0.2 * Math.sin(5.0 * p[0] + 2.0 * p[2]) * Math.cos(4.0 * p[1]) + 0.15 * Math.sin(11.0 * p[2] + 3.0 * p[1]),
            0.5 + 0.2 * Math.cos(4.5 * p[1] + 1.0) * Math.sin(5.5 * p[2] - p[0]) + 0.15 * Math.cos(10.0 * p[0] - 4.0 * p[1]),
            0.5 + 0.25 * Math.sin(3.0 * (p[0] + p[1] + p[2])) + 0.15 * Math.cos(12.0 * p[1] - 5.0 * p[2] + 3.0 * p[0])};
    }

    static double[] mul(double[] a, double[] b) {
        double[] t = new double[16];
        for (int r = 0; r < 4; r++)
            for (int c = 0; c < 4; c++)
                for (int k = 0; k < 4; k++) t[4 * r + c] += a[4 * r + k] * b[4 * k + c];
        return t;
    }

    static double[] rigidInverse(double[] m) {
        double[] o = new double[16];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) {
                o[4 * r + c] = m[4 * c + r];
                o[4 * r + 3] -= m[4 * c + r] * m[4 * c + 3];
            }
        o[15] = 1;
        return o;
    }

    static double[] unit(double[] v) {
        double n = Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        return new double[] {v[0] / n, v[1] / n, v[2] / n};
    }

    static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    /** Camera-to-world pose at {@code c} looking at {@code t} (world y points down). */
    static double[] lookAt(double[] c, double[] t) {
        double[] z = unit(new double[] {t[0] - c[0], t[1] - c[1], t[2] - c[2]});
        double[] x = unit(cross(new double[] {0, 1, 0}, z)), y = cross(z, x), m = new double[16];
        for (int r = 0; r < 3; r++) {
            m[4 * r] = x[r];
            m[4 * r + 1] = y[r];
            m[4 * r + 2] = z[r];
            m[4 * r + 3] = c[r];
        }
        m[15] = 1;
        return m;
    }

    /** Rotation by {@code deg} about {@code axis} (Rodrigues), then translation t. */
    static double[] motion(double[] axis, double deg, double[] t) {
        double[] k = unit(axis), m = new double[16];
        double a = Math.toRadians(deg), c = Math.cos(a), s = Math.sin(a);
        for (int r = 0; r < 3; r++) {
            for (int q = 0; q < 3; q++) m[4 * r + q] = (1 - c) * k[r] * k[q] + (r == q ? c : 0);
            m[4 * r + 3] = t[r];
        }
        m[1] -= s * k[2]; m[2] += s * k[1]; m[4] += s * k[2]; m[6] -= s * k[0]; m[8] -= s * k[1]; m[9] += s * k[0];
        m[15] = 1;
        return m;
    }

    /** The RGB-D view from camera-to-world {@code pose}: each ray meets the room's box where it leaves it. */
    static RGBDImage render(double[] pose) {
        byte[] rgb = new byte[3 * W * H];
        float[] depth = new float[W * H];
        for (int v = 0; v < H; v++)
            for (int u = 0; u < W; u++) {
                double[] dc = {(u - 79.5) / 140.0, (v - 59.5) / 140.0, 1.0}, d = new double[3], p = new double[3];
                double t = Double.POSITIVE_INFINITY;
                for (int r = 0; r < 3; r++) d[r] = pose[4 * r] * dc[0] + pose[4 * r + 1] * dc[1] + pose[4 * r + 2] * dc[2];
                for (int a = 0; a < 3; a++)
                    if (d[a] != 0) t = Math.min(t, ((d[a] > 0 ? HI[a] : LO[a]) - pose[4 * a + 3]) / d[a]);
                for (int r = 0; r < 3; r++) p[r] = pose[4 * r + 3] + t * d[r];
                double[] col = texture(p);
                for (int k = 0; k < 3; k++) rgb[3 * (v * W + u) + k] = (byte) Math.round(255.0 * col[k]);
                depth[v * W + u] = (float) t; // the camera ray has z = 1: t is the depth
            }
        try (Image c = Image.createFromData(W, H, 3, 1, rgb); Image d = Images.fromFloat(W, H, 1, depth);
             RgbdOptions o = new RgbdOptions()) {
            o.setDepthScale(1.0);
            o.setDepthTrunc(10.0);
            o.setConvertRgbToIntensity(0);
            return RGBDImage.createFromColorAndDepth(c, d, o);
        }
    }

    @BeforeAll
    static void scene() {
        double[] xyz = new double[3 * 6 * GRID * GRID];
        int n = 0;
        for (int axis = 0; axis < 3; axis++)
            for (int side = 0; side < 2; side++)
                for (int j = 0; j < GRID; j++)
                    for (int i = 0; i < GRID; i++, n++) {
                        int a = (axis + 1) % 3, b = (axis + 2) % 3;
                        xyz[3 * n + axis] = side == 1 ? HI[axis] : LO[axis];
                        xyz[3 * n + a] = LO[a] + (HI[a] - LO[a]) * i / (GRID - 1);
                        xyz[3 * n + b] = LO[b] + (HI[b] - LO[b]) * j / (GRID - 1);
                    }
        mesh = new TriangleMesh();
        mesh.setArray(Library.MESH_VERTICES, xyz);
        double[][] centres = {{0, 0, 0}, {-0.6, -0.4, -0.5}, {0.5, -0.5, 0.3}, {-0.5, 0.5, 0.5}, {0.4, 0.4, -0.6}};
        double[][] targets = {{1.2, 1.0, 1.6}, {1.0, 1.0, 1.6}, {1.2, 0.8, 1.6}, {1.2, 1.0, 1.4}, {1.1, 0.9, 1.5}};
        double[][] axes = {{1, 2, 0}, {-1, 0, 2}, {0, 1, 1}, {2, -1, 1}, {1, 1, -1}};
        double[][] shifts = {{0.02, -0.01, 0.01}, {-0.01, 0.02, 0}, {0, -0.02, -0.015}, {0.015, 0.01, 0.01}, {-0.02, 0, 0.01}};
        start = new PinholeCameraTrajectory();
        PinholeCameraIntrinsic camera = ImageCameraTest.intrinsic(W, H, 140, 140, 79.5, 59.5);
        for (int c = 0; c < 5; c++) {
            double[] pose = lookAt(centres[c], targets[c]);
            images[c] = render(pose);
            truth[c] = rigidInverse(pose);
            start.append(camera, mul(motion(axes[c], 1.5, shifts[c]), truth[c]));
        }
    }

    @AfterAll
    static void free() {
        mesh.close();
        start.close();
        for (RGBDImage i : images) i.close();
    }

    /** Mean rotation error (degrees) and camera-centre distance (metres) against the truth. */
    static double[] poseError(PinholeCameraTrajectory t) {
        double deg = 0, metres = 0;
        for (int c = 0; c < 5; c++)
            try (GetResult g = t.get(c)) {
                double[] a = g.extrinsic(), e = mul(a, rigidInverse(truth[c])), ia = rigidInverse(a), ib = rigidInverse(truth[c]);
                deg += Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (e[0] + e[5] + e[10] - 1) / 2)))) / 5;
                metres += Math.sqrt(Math.pow(ia[3] - ib[3], 2) + Math.pow(ia[7] - ib[7], 2) + Math.pow(ia[11] - ib[11], 2)) / 5;
            }
        return new double[] {deg, metres};
    }

    /** Mean RGB distance from the texture over the vertices within 1 m of the corner the cameras see. */
    static double colorError(TriangleMesh m) {
        double[] xyz = m.getArray(Library.MESH_VERTICES), rgb = m.getArray(Library.MESH_VERTEX_COLORS);
        assertEquals(xyz.length, rgb.length);
        double sum = 0;
        int used = 0;
        for (int i = 0; i < xyz.length / 3; i++) {
            double[] p = Arrays.copyOfRange(xyz, 3 * i, 3 * i + 3), t = texture(p);
            if (Math.abs(p[0] - HI[0]) + Math.abs(p[1] - HI[1]) + Math.abs(p[2] - HI[2]) > 1.0 + 1e-9) continue;
            sum += Math.sqrt(Math.pow(rgb[3 * i] - t[0], 2) + Math.pow(rgb[3 * i + 1] - t[1], 2) + Math.pow(rgb[3 * i + 2] - t[2], 2));
            used++;
        }
        assertTrue(used > 50);
        return sum / used;
    }

    static ColorMapRigidOptions rigidOptions(int iterations) {
        ColorMapRigidOptions o = new ColorMapRigidOptions();
        o.setMaximumIteration(iterations);
        o.setMaximumAllowableDepth(4.0);
        o.setDepthThresholdForDiscontinuityCheck(1.0); // slanted walls at 160 x 120 are no discontinuity
        o.setDepthThresholdForVisibilityCheck(0.2); // the poses start a few cm off
        o.setImageBoundaryMargin(4);
        return o;
    }

    @Test
    void bothOptimizersRecoverThePoses() {
        double rigidColor;
        try (ColorMapRigidOptions o0 = rigidOptions(0); ColorMapRigidOptions o1 = rigidOptions(150);
             ColorMapRunRigidOptimizerResult r0 = Library.colorMapRunRigidOptimizer(mesh, images, start, o0);
             ColorMapRunRigidOptimizerResult r1 = Library.colorMapRunRigidOptimizer(mesh, images, start, o1);
             TriangleMesh m0 = r0.coloredMesh(); PinholeCameraTrajectory t0 = r0.refinedTrajectory();
             TriangleMesh m1 = r1.coloredMesh(); PinholeCameraTrajectory t1 = r1.refinedTrajectory()) {
            double[] e0 = poseError(t0), e1 = poseError(t1);
            assertEquals(1.5, e0[0], 1e-9); // no iterations: the poses as given
            assertTrue(e1[0] < 0.5 * e0[0] && e1[1] < 0.6 * e0[1], e1[0] + " deg " + e1[1] + " m");
            rigidColor = colorError(m1);
            assertTrue(rigidColor < 0.5 * colorError(m0));
            assertFalse(mesh.hasArray(Library.MESH_VERTEX_COLORS)); // the result is a copy
        }
        try (ColorMapNonRigidOptions o = new ColorMapNonRigidOptions()) {
            o.setNumberOfVerticalAnchors(6);
            o.setMaximumIteration(150);
            o.setMaximumAllowableDepth(4.0);
            o.setDepthThresholdForDiscontinuityCheck(1.0);
            o.setDepthThresholdForVisibilityCheck(0.2);
            o.setImageBoundaryMargin(4);
            try (ColorMapRunNonRigidOptimizerResult r = Library.colorMapRunNonRigidOptimizer(mesh, images, start, o);
                 TriangleMesh m = r.coloredMesh(); PinholeCameraTrajectory t = r.refinedTrajectory()) {
                double[] e = poseError(t);
                assertTrue(e[0] < 0.75 && e[1] < 0.015, e[0] + " deg " + e[1] + " m");
                assertTrue(colorError(m) < 1.1 * rigidColor);
            }
        }
    }

    @Test
    void errors() {
        try (ColorMapRigidOptions o = rigidOptions(1)) {
            assertInvalid(() -> Library.colorMapRunRigidOptimizer(mesh, Arrays.copyOf(images, 2), start, o));
            RGBDImage[] withNull = images.clone();
            withNull[2] = null;
            assertInvalid(() -> Library.colorMapRunRigidOptimizer(mesh, withNull, start, o));
        }
    }
}
