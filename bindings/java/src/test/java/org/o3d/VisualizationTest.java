// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * OffscreenRenderer: pixels against a known pinhole camera (the same scenarios as
 * bindings/csharp/tests/VisualizationTest.cs). The scene is a unit box [-0.5, 0.5]^2 x [2.5, 3.5] seen from
 * the origin along +z with fx = fy = 100 and the principal point at the image centre (79.5, 59.5) of a
 * 160 x 120 image, so its front face (z = 2.5) covers the 40 x 40 pixels 60..99 x 40..79 and the depth along
 * the axis there is 2.5.
 */
class VisualizationTest {
    @TempDir
    Path tmp;

    static final int W = 160, H = 120;
    static final int CU = 80, CV = 60; // a pixel on the box's front face, next to the optical axis
    static final double[] BOX_COLOR = {0.2, 0.4, 0.6};
    static final double[] WHITE = {1, 1, 1};

    static PinholeCameraIntrinsic camera() {
        return ImageCameraTest.intrinsic(W, H, 100, 100, 79.5, 59.5);
    }

    static TriangleMesh unitBox(double[] color) {
        TriangleMesh box = TriangleMesh.createBox(1, 1, 1);
        box.translate(new double[] {-0.5, -0.5, 2.5}, 1);
        box.paintUniformColor(color);
        return box;
    }

    static RenderMaterial unlit() {
        RenderMaterial m = new RenderMaterial();
        m.setShader(Library.SHADER_DEFAULT_UNLIT);
        return m;
    }

    /** A renderer looking through camera() from the origin. */
    static OffscreenRenderer pinholeRenderer() {
        OffscreenRenderer r = OffscreenRenderer.create(W, H, Library.RENDER_BACKEND_AUTO);
        r.setupCamera(camera(), IDENTITY);
        return r;
    }

    static int[] pixel(byte[] rgb, int u, int v) {
        int i = (v * W + u) * 3;
        return new int[] {rgb[i] & 0xff, rgb[i + 1] & 0xff, rgb[i + 2] & 0xff};
    }

    /** {@code color} in [0, 1] as 8-bit, within one step (rounding or truncation). */
    static void assertRgb(int[] got, double[] color, String what) {
        for (int c = 0; c < 3; c++) assertEquals(255 * color[c], got[c], 1.0, what + " channel " + c);
    }

    static void assertCorners(byte[] rgb, double[] color) {
        assertRgb(pixel(rgb, 0, 0), color, "corner (0, 0)");
        assertRgb(pixel(rgb, W - 1, 0), color, "corner (w-1, 0)");
        assertRgb(pixel(rgb, 0, H - 1), color, "corner (0, h-1)");
        assertRgb(pixel(rgb, W - 1, H - 1), color, "corner (w-1, h-1)");
    }

    /** Pixels more than one step away from {@code background} in some channel. */
    static int countNot(byte[] rgb, double[] background) {
        int n = 0;
        for (int i = 0; i < rgb.length; i += 3)
            for (int c = 0; c < 3; c++)
                if (Math.abs((rgb[i + c] & 0xff) - 255 * background[c]) > 1) {
                    n++;
                    break;
                }
        return n;
    }

    static byte[] renderRgb(OffscreenRenderer r) {
        try (Image img = r.renderToImage()) {
            return img.getArray(Library.IMAGE_DATA);
        }
    }

    static float depthAt(OffscreenRenderer r, boolean zInViewSpace, int u, int v) {
        try (Image img = r.renderToDepthImage(zInViewSpace ? 1 : 0)) {
            return Images.toFloatArray(img)[v * W + u];
        }
    }

    static int differingPixels(byte[] a, byte[] b) {
        int n = 0;
        for (int i = 0; i < a.length; i += 3)
            if (a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2]) n++;
        return n;
    }

    @Test
    void optionAndMaterialDefaultsAreOpen3Ds() {
        try (RenderOption o = new RenderOption(); RenderMaterial m = new RenderMaterial()) {
            assertArrayEquals(WHITE, o.getBackgroundColor(), 0);
            assertEquals(5, o.getPointSize());
            assertEquals(1, o.getLineWidth());
            assertEquals(1, o.getLightOn());
            assertEquals(Library.COLOR_OPTION_DEFAULT, o.getPointColorOption());
            assertEquals(Library.COLOR_OPTION_COLOR, o.getMeshColorOption());
            assertEquals(Library.MESH_SHADE_FLAT, o.getMeshShadeOption());
            assertArrayEquals(new double[] {0.7, 0.7, 0.7}, o.getDefaultMeshColor(), 0);
            assertArrayEquals(new double[] {0.66, 0.66, 0.66, 0.66}, o.getLightDiffusePower(), 0);
            assertEquals(Library.SHADER_DEFAULT_LIT, m.getShader());
            assertArrayEquals(new double[] {1, 1, 1, 1}, m.getBaseColor(), 0);
            assertEquals(0, m.getPointSize());
            assertEquals(0, m.getLineWidth());
        }
    }

    @Test
    void optionJsonRoundTrip() {
        String path = tmp.resolve("option.json").toString();
        try (RenderOption o = new RenderOption()) {
            o.setBackgroundColor(new double[] {0.1, 0.2, 0.3});
            o.setPointSize(7);
            o.setMeshShowWireframe(1);
            o.setMeshColorOption(Library.COLOR_OPTION_Z);
            RenderOption.saveJson(path, o);
            try (RenderOption back = RenderOption.loadJson(path)) {
                assertArrayEquals(new double[] {0.1, 0.2, 0.3}, back.getBackgroundColor(), 0);
                assertEquals(7, back.getPointSize());
                assertEquals(1, back.getMeshShowWireframe());
                assertEquals(Library.COLOR_OPTION_Z, back.getMeshColorOption());
            }
        }
        assertStatus(Library.ERROR_IO, () -> RenderOption.loadJson(tmp.resolve("missing.json").toString()));
    }

    @Test
    void optionFromOpen3DsFile() {
        // Open3D's file differs from the defaults only in point_color_option (9, Normal).
        try (RenderOption file = RenderOption.loadJson(data("open3d/renderoption.json"))) {
            assertEquals(Library.COLOR_OPTION_NORMAL, file.getPointColorOption());
            assertArrayEquals(WHITE, file.getBackgroundColor(), 0);
        }
    }

    @Test
    void unlitBoxColorDepthAndSilhouetteUnderAPinholeCamera() {
        try (OffscreenRenderer r = pinholeRenderer(); TriangleMesh box = unitBox(BOX_COLOR); RenderMaterial unlit = unlit()) {
            int backend = r.getBackend();
            assertTrue(backend == Library.RENDER_BACKEND_EGL || backend == Library.RENDER_BACKEND_GLFW, "backend " + backend);
            try (GetSizeResult size = r.getSize()) {
                assertEquals(W, size.width());
                assertEquals(H, size.height());
            }
            r.addTrianglemesh("box", box, unlit);
            try (Image img = r.renderToImage()) {
                assertEquals(W, img.width());
                assertEquals(H, img.height());
                assertEquals(3, img.numChannels());
                assertEquals(1, img.bytesPerChannel());
            }
            byte[] rgb = renderRgb(r);
            assertCorners(rgb, WHITE);
            assertRgb(pixel(rgb, CU, CV), BOX_COLOR, "box centre");
            assertRgb(pixel(rgb, 61, 41), BOX_COLOR, "inside the face's top-left corner");
            assertRgb(pixel(rgb, 58, CV), WHITE, "left of the face");
            assertRgb(pixel(rgb, CU, 81), WHITE, "below the face");
            assertEquals(1600, countNot(rgb, WHITE), 0.02 * 1600, "silhouette: the 40 x 40 front face");

            assertEquals(2.5, depthAt(r, true, CU, CV), 1e-3);
            assertEquals(2.5, depthAt(r, true, 61, 41), 1e-3);
            assertEquals(0f, depthAt(r, true, 0, 0));
            float buffer = depthAt(r, false, CU, CV);
            assertTrue(buffer > 0 && buffer < 1, "depth buffer " + buffer);
            assertEquals(1f, depthAt(r, false, W - 1, H - 1));

            try (GetCameraResult cam = r.getCamera()) {
                ImageCameraTest.assertIntrinsic(camera(), cam.intrinsic());
                assertArrayEquals(IDENTITY, cam.extrinsic(), 1e-12);
            }
        }
    }

    @Test
    void backgroundTintAndAmbientOnlyLight() {
        try (OffscreenRenderer r = pinholeRenderer(); RenderOption o = new RenderOption(); TriangleMesh box = unitBox(BOX_COLOR);
                RenderMaterial tinted = unlit(); RenderMaterial lit = new RenderMaterial()) {
            double[] background = {0.1, 0.2, 0.3};
            o.setBackgroundColor(background);
            r.setRenderOption(o);
            try (RenderOption got = r.getRenderOption()) {
                assertArrayEquals(background, got.getBackgroundColor(), 0);
            }
            tinted.setBaseColor(new double[] {0.5, 1, 1, 1});
            r.addTrianglemesh("box", box, tinted);
            byte[] rgb = renderRgb(r);
            assertCorners(rgb, background);
            assertRgb(pixel(rgb, CU, CV), new double[] {0.1, 0.4, 0.6}, "tinted box");

            // Lit with only ambient light: color * ambient (the header's formula, every light at power 0).
            o.setLightOn(1);
            o.setLightAmbientColor(new double[] {0.5, 0.5, 0.5});
            o.setLightDiffusePower(new double[4]);
            o.setLightSpecularPower(new double[4]);
            r.setRenderOption(o);
            r.clearGeometries();
            r.addTrianglemesh("box", box, lit);
            assertRgb(pixel(renderRgb(r), CU, CV), new double[] {0.1, 0.2, 0.3}, "ambient-lit box");
        }
    }

    @Test
    void sceneAddHasRemoveClear() {
        try (OffscreenRenderer r = pinholeRenderer(); TriangleMesh box = unitBox(BOX_COLOR); RenderMaterial unlit = unlit()) {
            assertFalse(r.hasGeometry("box"));
            r.addTrianglemesh("box", box, unlit);
            assertTrue(r.hasGeometry("box"));
            assertInvalid(() -> r.addTrianglemesh("box", box, unlit));
            assertInvalid(() -> r.addTrianglemesh("", box, unlit));
            r.removeGeometry("box");
            assertFalse(r.hasGeometry("box"));
            assertInvalid(() -> r.removeGeometry("box"));
            assertRgb(pixel(renderRgb(r), CU, CV), WHITE, "removed box");

            // Geometries are copied: painting the mesh afterwards does not show.
            r.addTrianglemesh("a", box, unlit);
            box.paintUniformColor(new double[] {1, 0, 0});
            assertRgb(pixel(renderRgb(r), CU, CV), BOX_COLOR, "the copy added");
            r.addTrianglemesh("b", box, null); // null material: the defaults
            r.clearGeometries();
            assertFalse(r.hasGeometry("a") || r.hasGeometry("b"));
            assertEquals(0, countNot(renderRgb(r), WHITE));
        }
    }

    @Test
    void pointCloudLineSetAndVoxelGridOnTheAxis() {
        try (OffscreenRenderer r = pinholeRenderer(); PointCloud point = cloud(new double[] {0, 0, 2.5}); RenderMaterial big = unlit()) {
            point.paintUniformColor(new double[] {1, 0, 0});
            big.setPointSize(9);
            r.addPointcloud("cloud", point, big);
            byte[] rgb = renderRgb(r);
            assertRgb(pixel(rgb, CU, CV), new double[] {1, 0, 0}, "point");
            assertRgb(pixel(rgb, CU + 10, CV), WHITE, "beside the point");
        }
        try (OffscreenRenderer r = pinholeRenderer(); LineSet line = new LineSet(); RenderMaterial wide = unlit()) {
            // A horizontal line through the axis, 5 pixels wide.
            line.setArray(Library.LINESET_POINTS, new double[] {-1, 0, 2.5, 1, 0, 2.5});
            line.setIndexArray(Library.LINESET_LINES, new int[] {0, 1});
            line.paintUniformColor(new double[] {0, 1, 0});
            wide.setLineWidth(5);
            r.addLineset("line", line, wide);
            byte[] rgb = renderRgb(r);
            assertRgb(pixel(rgb, CU, CV), new double[] {0, 1, 0}, "line");
            assertRgb(pixel(rgb, CU + 30, CV), new double[] {0, 1, 0}, "line, 30 pixels along");
            assertRgb(pixel(rgb, CU, CV + 10), WHITE, "below the line");
        }
        try (OffscreenRenderer r = pinholeRenderer(); PointCloud centre = cloud(new double[] {0, 0, 3}); RenderMaterial unlit = unlit()) {
            // One voxel of edge 1 around (0, 0, 3): the unit box again.
            centre.paintUniformColor(new double[] {0, 0, 1});
            try (VoxelGrid grid = VoxelGrid.createFromPointCloud(centre, 1.0)) {
                r.addVoxelgrid("grid", grid, unlit);
            }
            byte[] rgb = renderRgb(r);
            assertRgb(pixel(rgb, CU, CV), new double[] {0, 0, 1}, "voxel");
            assertEquals(1600, countNot(rgb, WHITE), 0.02 * 1600, "voxel silhouette");
            assertEquals(2.5, depthAt(r, true, CU, CV), 1e-3);
        }
    }

    @Test
    void fovAndLookatCamerasLookAtTheBox() {
        try (OffscreenRenderer r = OffscreenRenderer.create(W, H, Library.RENDER_BACKEND_AUTO); TriangleMesh box = unitBox(BOX_COLOR);
                RenderMaterial unlit = unlit()) {
            r.addTrianglemesh("box", box, unlit);
            // From the origin towards +z with image-down = world +y: the pinhole camera, as a field of view.
            double fov = Math.toDegrees(2 * Math.atan(60.0 / 100.0)); // fy = (H / 2) / tan(fov / 2) = 100
            r.setupCameraFov(fov, new double[] {0, 0, 3}, new double[] {0, 0, 0}, new double[] {0, -1, 0});
            try (GetCameraResult cam = r.getCamera()) {
                assertEquals(100, cam.intrinsic().getFx(), 1e-6);
                assertEquals(100, cam.intrinsic().getFy(), 1e-6);
                assertArrayEquals(IDENTITY, cam.extrinsic(), 1e-9);
            }
            assertEquals(2.5, depthAt(r, true, CU, CV), 1e-3);

            // Open3D's view, looking at a point off the box's centre from -z (zoom 2 keeps the box inside the
            // image): that point projects on the optical axis, in front of the camera.
            double[] at = {0.2, 0.1, 3};
            r.setupCameraLookat(at, new double[] {0, 0, -1}, new double[] {0, -1, 0}, 2.0);
            try (GetCameraResult cam = r.getCamera(); OffscreenRenderer again = OffscreenRenderer.create(W, H, Library.RENDER_BACKEND_AUTO)) {
                double[] p = applyTransform(cam.extrinsic(), at);
                assertEquals(0, p[0], 1e-9);
                assertEquals(0, p[1], 1e-9);
                assertTrue(p[2] > 1, "lookat in front: " + p[2]);
                byte[] rgb = renderRgb(r);
                assertRgb(pixel(rgb, W / 2, H / 2), BOX_COLOR, "lookat centre");
                assertCorners(rgb, WHITE);

                // setupCamera(getCamera()) reproduces the image (the box is off-centre, so a flip would show).
                again.addTrianglemesh("box", box, unlit);
                again.setupCamera(cam.intrinsic(), cam.extrinsic());
                int differ = differingPixels(rgb, renderRgb(again));
                assertTrue(differ <= 20, differ + " pixels differ");
            }
        }
    }

    @Test
    void renderToPngWritesTheImage() {
        String path = tmp.resolve("box.png").toString();
        try (OffscreenRenderer r = pinholeRenderer(); TriangleMesh box = unitBox(BOX_COLOR); RenderMaterial unlit = unlit()) {
            r.addTrianglemesh("box", box, unlit);
            r.renderToPng(path);
            try (Image png = Library.ioReadImage(path, null)) {
                assertEquals(3, png.numChannels());
                assertArrayEquals(renderRgb(r), png.getArray(Library.IMAGE_DATA));
            }
            assertStatus(Library.ERROR_IO, () -> r.renderToPng("/nonexistent/dir/box.png"));
        }
    }

    @Test
    void badArgumentsThrow() {
        assertInvalid(() -> OffscreenRenderer.create(0, 10, Library.RENDER_BACKEND_AUTO));
        try (OffscreenRenderer r = OffscreenRenderer.create(W, H, Library.RENDER_BACKEND_AUTO); RenderOption o = new RenderOption()) {
            assertInvalid(() -> r.setupCamera(ImageCameraTest.intrinsic(W + 1, H, 100, 100, 80, 60), IDENTITY));
            double[] scaled = IDENTITY.clone();
            scaled[0] = 2;
            assertInvalid(() -> r.setupCamera(camera(), scaled));
            assertInvalid(() -> r.setupCamera(camera(), new double[12]));
            assertInvalid(() -> r.setupCameraLookat(new double[3], new double[] {0, 0, 1}, new double[] {0, 0, 1}, 0.7));
            assertInvalid(() -> r.setupCameraLookat(new double[3], new double[] {0, 0, 1}, new double[] {0, 1, 0}, 5));
            assertInvalid(() -> r.setupCameraFov(0, new double[] {0, 0, 1}, new double[3], new double[] {0, 1, 0}));
            o.setPointSize(100);
            assertInvalid(() -> r.setRenderOption(o));
        }
    }
}
