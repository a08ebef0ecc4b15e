// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Image, camera and RGB-D: the same scenarios as bindings/csharp/tests/Test.cs (GeometryTests). */
class ImageCameraTest {
    @TempDir
    Path tmp;

    static O3dException assertStatus(Status s, org.junit.jupiter.api.function.Executable e) {
        O3dException ex = assertThrows(O3dException.class, e);
        assertEquals(s, ex.getStatus(), ex.getMessage());
        assertFalse(ex.getMessage().isEmpty());
        return ex;
    }

    static double[] toDouble(float[] f) {
        double[] d = new double[f.length];
        for (int i = 0; i < f.length; i++) d[i] = f[i];
        return d;
    }

    // Synthetic depth: d(u, v) = 1 + 0.25 u + 0.5 v on a 4x3 image, pixel (2, 1) invalid (0);
    // camera fx = 2, fy = 3, cx = 1.5, cy = 1.
    static final int DW = 4, DH = 3;

    static double depthAt(int u, int v) {
        return (u == 2 && v == 1) ? 0 : 1 + 0.25 * u + 0.5 * v;
    }

    static PinholeCameraIntrinsic depthCamera() {
        return new PinholeCameraIntrinsic(DW, DH, 2, 3, 1.5, 1);
    }

    /** The analytic back-projection, row by row (Open3D's order), minus t (world = camera - t). */
    static double[] expectedDepthPoints(double tx, double ty, double tz) {
        List<Double> pts = new ArrayList<>();
        for (int v = 0; v < DH; v++)
            for (int u = 0; u < DW; u++) {
                double d = depthAt(u, v);
                if (d <= 0) continue;
                pts.add((u - 1.5) * d / 2 - tx);
                pts.add((v - 1.0) * d / 3 - ty);
                pts.add(d - tz);
            }
        return pts.stream().mapToDouble(Double::doubleValue).toArray();
    }

    @Test
    void pngRoundTripAndTypedPixels() {
        byte[] px = new byte[5 * 4 * 3];
        for (int i = 0; i < px.length; i++) px[i] = (byte) (i * 7);
        try (Image img = Image.fromBytes(5, 4, 3, 1, px)) {
            assertEquals(5, img.width());
            assertEquals(4, img.height());
            assertEquals(3, img.numChannels());
            assertEquals(1, img.bytesPerChannel());
            assertArrayEquals(px, img.getData());
            byte[] png = IO.writeImageToMemory(img, "png");
            assertEquals((byte) 0x89, png[0]);
            assertEquals('P', png[1]);
            assertEquals('N', png[2]);
            assertEquals('G', png[3]);
            try (Image back = IO.readImageFromMemory(png, "png")) {
                assertEquals(5, back.width());
                assertEquals(3, back.numChannels());
                assertArrayEquals(px, back.getData());
            }
            String path = tmp.resolve("img.png").toString();
            IO.writeImage(path, img);
            try (Image back = IO.readImage(path)) {
                assertArrayEquals(px, back.getData());
            }
            String ppm = tmp.resolve("img.ppm").toString();
            IO.writeImage(ppm, img, null, -1);
            try (Image back = IO.readImage(ppm, "ppm")) {
                assertArrayEquals(px, back.getData());
            }
            assertEquals(px.length, img.dataView().capacity());
            assertTrue(img.dataView().isReadOnly());
            img.dataMutableView().put(0, (byte) 200);
            assertEquals((byte) 200, img.getData()[0]);
            try (Image c = img.copy()) {
                assertArrayEquals(img.getData(), c.getData());
            }
        }
        short[] depth = {0, 1, 1000, (short) 65535, 300, 42};
        try (Image d16 = Image.fromUInt16(3, 2, 1, depth);
                NativeBuffer nb = IO.writeImageToNativeBuffer(d16, "png", -1);
                Image back = IO.readImageFromMemory(nb.toByteArray(), "png")) {
            assertEquals(2, back.bytesPerChannel());
            assertArrayEquals(depth, back.toUInt16Array());
            assertEquals(65535, Short.toUnsignedInt(back.toUInt16Array()[3]));
        }
        byte[] flat = new byte[64];
        java.util.Arrays.fill(flat, (byte) 128);
        try (Image gray = Image.fromBytes(8, 8, 1, 1, flat); Image back = IO.readImageFromMemory(IO.writeImageToMemory(gray, "jpg", 95), "jpg")) {
            assertEquals(8, back.width());
            for (byte b : back.getData()) assertTrue(Math.abs((b & 0xff) - 128) <= 2, "jpeg of a flat image stays flat");
        }
    }

    @Test
    void flipsConversionsFilters() {
        try (Image row = Image.fromBytes(3, 1, 1, 1, new byte[] {1, 2, 3}); Image f = row.flipHorizontal(); Image s = row.flipVertical()) {
            assertArrayEquals(new byte[] {3, 2, 1}, f.getData());
            assertArrayEquals(new byte[] {1, 2, 3}, s.getData());
        }
        try (Image col = Image.fromBytes(1, 3, 1, 1, new byte[] {1, 2, 3}); Image f = col.flipVertical()) {
            assertArrayEquals(new byte[] {3, 2, 1}, f.getData());
        }
        try (Image g = Image.fromBytes(3, 1, 1, 1, new byte[] {0, (byte) 255, 51}); Image f = g.createFloatImage()) {
            assertEquals(4, f.bytesPerChannel());
            assertArrayEquals(new double[] {0, 1, 0.2}, toDouble(f.toFloatArray()), 1e-6);
        }
        try (Image rgb = Image.fromBytes(1, 1, 3, 1, new byte[] {(byte) 255, 0, 0});
                Image w = rgb.createFloatImage(ImageConvertType.WEIGHTED);
                Image e = rgb.createFloatImage(ImageConvertType.EQUAL)) {
            assertEquals(0.299, w.toFloatArray()[0], 1e-6);
            assertEquals(1.0 / 3, e.toFloatArray()[0], 1e-6);
        }
        try (Image raw = Image.fromUInt16(3, 1, 1, new short[] {500, 4000, 1500}); Image m = raw.convertDepthToFloat(1000, 3.0)) {
            assertArrayEquals(new double[] {0.5, 0, 1.5}, toDouble(m.toFloatArray()), 1e-6);
        }
        float[] half = new float[20];
        java.util.Arrays.fill(half, 0.5f);
        try (Image flat = Image.fromFloat(5, 4, 1, half)) {
            for (ImageFilterType t : new ImageFilterType[] {ImageFilterType.GAUSSIAN3, ImageFilterType.GAUSSIAN5, ImageFilterType.GAUSSIAN7})
                try (Image f = flat.filter(t)) {
                    for (float x : f.toFloatArray()) assertEquals(0.5, x, 1e-6, t.name());
                }
            for (ImageFilterType t : new ImageFilterType[] {ImageFilterType.SOBEL3_DX, ImageFilterType.SOBEL3_DY})
                try (Image f = flat.filter(t)) {
                    for (float x : f.toFloatArray()) assertEquals(0, x, 1e-6, t.name());
                }
        }
        try (Image img = Image.fromFloat(4, 2, 1, new float[] {1, 3, 5, 7, 1, 3, 5, 7}); Image h = img.downsample()) {
            assertEquals(2, h.width());
            assertEquals(1, h.height());
            assertArrayEquals(new double[] {2, 6}, toDouble(h.toFloatArray()), 1e-6);
        }
    }

    @Test
    void intrinsicPresetsTrajectoryJson() {
        PinholeCameraIntrinsic ps = PinholeCameraIntrinsic.fromPreset(PinholeCameraIntrinsicParameters.PRIME_SENSE_DEFAULT);
        assertEquals(new PinholeCameraIntrinsic(640, 480, 525, 525, 319.5, 239.5), ps);
        assertEquals(new PinholeCameraIntrinsic(640, 480, 525, 525, 319.5, 239.5).hashCode(), ps.hashCode());
        assertArrayEquals(new double[] {525, 0, 319.5, 0, 525, 239.5, 0, 0, 1}, ps.intrinsicMatrix(), 0);
        PinholeCameraIntrinsic k2d = PinholeCameraIntrinsic.fromPreset(PinholeCameraIntrinsicParameters.KINECT2_DEPTH_CAMERA_DEFAULT);
        assertEquals(new PinholeCameraIntrinsic(512, 424, 365.456, 365.456, 254.878, 205.395), k2d);
        PinholeCameraIntrinsic k2c = PinholeCameraIntrinsic.fromPreset(PinholeCameraIntrinsicParameters.KINECT2_COLOR_CAMERA_DEFAULT);
        assertEquals(1920, k2c.width());
        assertEquals(1080, k2c.height());
        assertEquals(1059.9718, k2c.fx(), 1e-9);
        assertEquals(975.7193, k2c.cx(), 1e-9);
        assertEquals(545.9533, k2c.cy(), 1e-9);
        assertStatus(Status.INVALID_ARGUMENT, () -> {
            o3d_pinhole_intrinsic_t n = new o3d_pinhole_intrinsic_t();
            try {
                O3dNative.o3d_pinhole_intrinsic_set_preset(n, 99);
            } finally {
                n.delete();
            }
        });

        double[] pose = {0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
        double[] identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        try (PinholeCameraTrajectory traj = new PinholeCameraTrajectory()) {
            assertEquals(0, traj.size());
            traj.append(ps, pose);
            traj.append(new PinholeCameraParameters(k2d, identity));
            assertEquals(2, traj.size());
            assertEquals(ps, traj.get(0).intrinsic());
            assertArrayEquals(pose, traj.get(0).extrinsic(), 0);
            assertStatus(Status.INVALID_ARGUMENT, () -> traj.get(5));
            double[] bad = pose.clone();
            bad[15] = 2;
            assertStatus(Status.INVALID_ARGUMENT, () -> traj.append(ps, bad));
            String json = tmp.resolve("traj.json").toString();
            IO.writePinholeCameraTrajectory(json, traj);
            try (PinholeCameraTrajectory back = IO.readPinholeCameraTrajectory(json)) {
                List<PinholeCameraParameters> list = back.parameters();
                assertEquals(2, list.size());
                assertEquals(ps, list.get(0).intrinsic());
                assertEquals(k2d, list.get(1).intrinsic());
                assertArrayEquals(pose, list.get(0).extrinsic(), 1e-12);
            }
            String log = tmp.resolve("traj.log").toString();
            IO.writePinholeCameraTrajectory(log, traj, "log");
            try (PinholeCameraTrajectory back = IO.readPinholeCameraTrajectory(log, "log")) {
                assertEquals(2, back.size());
                assertArrayEquals(pose, back.get(0).extrinsic(), 1e-9);
                assertEquals(ps, back.get(0).intrinsic(), "log intrinsic is the PrimeSense default");
            }
            traj.clear();
            assertEquals(0, traj.size());
        }
        String ipath = tmp.resolve("intrinsic.json").toString();
        IO.writePinholeCameraIntrinsic(ipath, k2d);
        assertEquals(k2d, IO.readPinholeCameraIntrinsic(ipath));
        String ppath = tmp.resolve("params.json").toString();
        IO.writePinholeCameraParameters(ppath, new PinholeCameraParameters(ps, pose));
        PinholeCameraParameters pp = IO.readPinholeCameraParameters(ppath);
        assertEquals(ps, pp.intrinsic());
        assertArrayEquals(pose, pp.extrinsic(), 1e-12);
        assertStatus(Status.IO, () -> IO.readPinholeCameraIntrinsic(tmp.resolve("none.json").toString()));
    }

    @Test
    void depthBackProjectedToAnalyticPoints() {
        float[] metres = new float[DW * DH];
        short[] mm = new short[DW * DH];
        for (int v = 0; v < DH; v++)
            for (int u = 0; u < DW; u++) {
                metres[v * DW + u] = (float) depthAt(u, v);
                mm[v * DW + u] = (short) Math.round(depthAt(u, v) * 1000);
            }
        PinholeCameraIntrinsic cam = depthCamera();
        try (Image fdepth = Image.fromFloat(DW, DH, 1, metres); Image udepth = Image.fromUInt16(DW, DH, 1, mm)) {
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam)) {
                assertArrayEquals(expectedDepthPoints(0, 0, 0), pc.getPoints(), 1e-6);
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(udepth, cam, null, 1000, 1000, 1, true)) {
                assertArrayEquals(expectedDepthPoints(0, 0, 0), pc.getPoints(), 1e-6);
            }
            double[] ext = {1, 0, 0, 0.5, 0, 1, 0, -1, 0, 0, 1, 2, 0, 0, 0, 1};
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, ext, 1000, 1000, 1, true)) {
                assertArrayEquals(expectedDepthPoints(0.5, -1, 2), pc.getPoints(), 1e-6);
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, null, 1000, 1000, 2, true)) {
                assertEquals(4, pc.size(), "stride 2: pixels (0,0),(2,0),(0,2),(2,2)");
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, null, 1000, 2.0, 1, true)) {
                // Open3D drops depth >= depth_trunc: the five pixels at 2 m or deeper
                assertEquals(expectedDepthPoints(0, 0, 0).length / 3 - 5, pc.size());
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, null, 1000, 1000, 1, false)) {
                assertEquals(DW * DH, pc.size());
                assertTrue(Double.isNaN(pc.getPoints()[3 * (DW + 2)]), "invalid pixel is NaN");
            }

            byte[] color = new byte[DW * DH * 3];
            for (int i = 0; i < DW * DH; i++) {
                color[3 * i] = (byte) (10 * i);
                color[3 * i + 1] = 100;
                color[3 * i + 2] = (byte) 200;
            }
            try (Image cimg = Image.fromBytes(DW, DH, 3, 1, color)) {
                try (RGBDImage rgbd = RGBDImage.createFromColorAndDepth(cimg, udepth, 1000, 3.0, false)) {
                    try (Image d = rgbd.depth()) {
                        assertArrayEquals(toDouble(metres), toDouble(d.toFloatArray()), 1e-6);
                    }
                    try (Image c = rgbd.color()) {
                        assertArrayEquals(color, c.getData());
                    }
                    try (PointCloud pc = PointCloud.createFromRGBDImage(rgbd, cam)) {
                        assertArrayEquals(expectedDepthPoints(0, 0, 0), pc.getPoints(), 1e-6);
                        List<Double> expect = new ArrayList<>();
                        for (int i = 0; i < DW * DH; i++)
                            if (metres[i] > 0) {
                                expect.add((color[3 * i] & 0xff) / 255.0);
                                expect.add(100 / 255.0);
                                expect.add(200 / 255.0);
                            }
                        assertArrayEquals(expect.stream().mapToDouble(Double::doubleValue).toArray(), pc.getColors(), 1e-6);
                    }
                }
                try (RGBDImage rgbd = RGBDImage.createFromColorAndDepth(cimg, udepth); Image c = rgbd.color()) {
                    assertEquals(1, c.numChannels());
                    assertEquals(4, c.bytesPerChannel());
                    assertEquals((0.587 * 100 + 0.114 * 200) / 255.0, c.toFloatArray()[0], 1e-5);
                }
                short[] far = mm.clone();
                far[0] = 4500;
                try (Image fd = Image.fromUInt16(DW, DH, 1, far); RGBDImage rgbd = RGBDImage.createFromRedwoodFormat(cimg, fd);
                        Image d = rgbd.depth()) {
                    assertEquals(0, d.toFloatArray()[0], 0, "4.5 m truncated");
                    assertEquals(1.25, d.toFloatArray()[1], 1e-6);
                }
                try (RGBDImage rgbd = RGBDImage.createFromTUMFormat(cimg, udepth); Image d = rgbd.depth()) {
                    assertEquals(1250 / 5000.0, d.toFloatArray()[1], 1e-6);
                }
                try (RGBDImage rgbd = RGBDImage.createFromSUNFormat(cimg, udepth); Image d = rgbd.depth()) {
                    assertEquals(DW, d.width());
                }
                try (RGBDImage rgbd = RGBDImage.createFromNYUFormat(cimg, udepth); Image d = rgbd.depth()) {
                    assertEquals(DH, d.height());
                }
                try (Image small = new Image(2, 2, 1, 2)) {
                    assertStatus(Status.INVALID_ARGUMENT, () -> RGBDImage.createFromColorAndDepth(cimg, small));
                }
                assertStatus(Status.INVALID_ARGUMENT, () -> PointCloud.createFromDepthImage(cimg, cam));
            }
        }
    }

    @Test
    void errorsForBadInputAndMisuse() {
        assertStatus(Status.INVALID_ARGUMENT, () -> new Image(0, 0));
        assertStatus(Status.INVALID_ARGUMENT, () -> new Image(2, 2, 2, 1));
        assertStatus(Status.INVALID_ARGUMENT, () -> Image.fromBytes(2, 2, 1, 1, new byte[3]));
        assertStatus(Status.PARSE, () -> IO.readImageFromMemory(new byte[] {(byte) 0x89, 'P', 'N', 'G', 1, 2, 3}, "png"));
        assertStatus(Status.IO, () -> IO.readImage("/nonexistent/dir/none.png"));
        try (Image img = new Image(2, 2)) {
            assertStatus(Status.INVALID_ARGUMENT, () -> img.filter(ImageFilterType.GAUSSIAN3));
        }
        try (Image f = Image.fromFloat(2, 2, 1, new float[4])) {
            assertThrows(O3dException.class, () -> IO.writeImageToMemory(f, "png"));
        }
        assertThrows(NullPointerException.class, () -> IO.writeImage("x.png", null));
        assertThrows(NullPointerException.class, () -> PointCloud.createFromDepthImage(null, depthCamera()));
        // NULL handles straight into the raw layer: an error, never a crash
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_image_width(new int[1], 0));
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_camera_trajectory_size(new long[1], 0));
        assertStatus(Status.INVALID_ARGUMENT, () -> O3dNative.o3d_rgbd_image_get_depth(new long[1], 0));

        Image image = new Image(2, 2);
        PinholeCameraTrajectory traj = new PinholeCameraTrajectory();
        image.close();
        traj.close();
        assertThrows(IllegalStateException.class, image::width);
        assertThrows(IllegalStateException.class, traj::size);
    }

    @Test
    void createPyramidHalvesEachLevelAndKeepsAConstant() {
        float[] flat = new float[32];
        java.util.Arrays.fill(flat, 0.5f);
        try (Image img = Image.fromFloat(8, 4, 1, flat)) {
            Image[] levels = img.createPyramid(3, true);
            assertEquals(3, levels.length);
            assertEquals(4, levels[1].width());
            assertEquals(2, levels[2].width());
            assertEquals(1, levels[2].height());
            for (Image level : levels) {
                for (float v : level.toFloatArray()) assertEquals(0.5f, v);
                level.close();
            }
        }
        try (Image ramp = Image.fromFloat(4, 2, 1, new float[] {0, 1, 2, 3, 0, 1, 2, 3})) {
            Image[] plain = ramp.createPyramid(2, false);
            assertArrayEquals(new float[] {0.5f, 2.5f}, plain[1].toFloatArray());
            for (Image level : plain) level.close();
        }
    }
}
