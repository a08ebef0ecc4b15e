// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import org.junit.jupiter.api.Test;

/**
 * RGB-D odometry, the scenarios of tests/capi/test_odometry.c: a frame onto itself is the identity, and Open3D's
 * result on its RGBD frames 0 -> 1 (open3d 0.20, hybrid term, default options, PrimeSense intrinsics).
 */
class OdometryTest {
    static final int W = 160, H = 120;

    /** A textured float intensity on a slanted plane of float depth (metres). */
    static RGBDImage syntheticFrame() {
        float[] color = new float[W * H], depth = new float[W * H];
        for (int v = 0; v < H; v++)
            for (int u = 0; u < W; u++) {
                color[v * W + u] = (float) (0.5 + 0.2 * Math.sin(0.3 * u) * Math.cos(0.25 * v) + 0.1 * Math.sin(0.11 * (u + v)));
                depth[v * W + u] = (float) (1.5 + 0.004 * u + 0.002 * v);
            }
        try (Image c = Images.fromFloat(W, H, 1, color); Image d = Images.fromFloat(W, H, 1, depth);
             RgbdOptions o = new RgbdOptions()) {
            o.setDepthScale(1.0);  // already metres
            return RGBDImage.createFromColorAndDepth(c, d, o);
        }
    }

    static RGBDImage open3dFrame(int i) {
        try (Image c = Library.ioReadImage(data("open3d/RGBD/color/0000" + i + ".jpg"), null);
             Image d = Library.ioReadImage(data("open3d/RGBD/depth/0000" + i + ".png"), null)) {
            return RGBDImage.createFromColorAndDepth(c, d, null);
        }
    }

    @Test
    void aFrameOntoItselfIsTheIdentity() {
        PinholeCameraIntrinsic k = ImageCameraTest.intrinsic(W, H, 130, 130, 79.5, 59.5);
        try (RGBDImage frame = syntheticFrame()) {
            for (int j : new int[] {Library.ODOMETRY_JACOBIAN_COLOR_TERM, Library.ODOMETRY_JACOBIAN_HYBRID_TERM}) {
                try (OdometryComputeRgbdResult r = Library.odometryComputeRgbd(frame, frame, k, null, j, null, null)) {
                    assertTrue(r.success(), "jacobian " + j);
                    assertArrayEquals(IDENTITY, r.transformation(), 1e-12, "jacobian " + j);
                    assertEquals(36, r.information().length);
                    // Every pixel but the border the smoothing and the pyramid eat corresponds.
                    assertTrue(r.information()[3 * 6 + 3] > 0.9 * W * H);
                }
            }
        }
    }

    @Test
    void open3dFramesZeroToOne() {
        PinholeCameraIntrinsic primesense = ImageCameraTest.intrinsic(640, 480, 525, 525, 319.5, 239.5);
        try (RGBDImage source = open3dFrame(0); RGBDImage target = open3dFrame(1); OdometryOptions o = new OdometryOptions();
             OdometryComputeRgbdResult r = Library.odometryComputeRgbd(source, target, primesense, null,
                     Library.ODOMETRY_JACOBIAN_HYBRID_TERM, new int[] {20, 10, 5}, o)) {
            assertTrue(r.success());
            double[] t = r.transformation();
            assertEquals(-0.0010704978, t[3], 1e-5);
            assertEquals(0.0232280983, t[7], 1e-5);
            assertEquals(0.0014059205, t[11], 1e-5);
            assertEquals(252387, r.information()[3 * 6 + 3], 0.001 * 252387);
        }
    }
}
