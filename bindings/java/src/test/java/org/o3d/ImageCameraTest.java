// SPDX-License-Identifier: MIT
package org.o3d;

import static org.junit.jupiter.api.Assertions.*;
import static org.o3d.T.*;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Image, camera and RGB-D: the same scenarios as bindings/csharp/tests/Test.cs (GeometryTests). */
class ImageCameraTest {
    @TempDir
    Path tmp;

    static final int DATA = Library.IMAGE_DATA;

    // Synthetic depth: d(u, v) = 1 + 0.25 u + 0.5 v on a 4x3 image, pixel (2, 1) invalid (0);
    // camera fx = 2, fy = 3, cx = 1.5, cy = 1.
    static final int DW = 4, DH = 3;

    static double depthAt(int u, int v) {
        return (u == 2 && v == 1) ? 0 : 1 + 0.25 * u + 0.5 * v;
    }

    static PinholeCameraIntrinsic intrinsic(int w, int h, double fx, double fy, double cx, double cy) {
        PinholeCameraIntrinsic k = new PinholeCameraIntrinsic();
        k.setWidth(w);
        k.setHeight(h);
        k.setFx(fx);
        k.setFy(fy);
        k.setCx(cx);
        k.setCy(cy);
        return k;
    }

    static void assertIntrinsic(PinholeCameraIntrinsic expect, PinholeCameraIntrinsic got) {
        assertArrayEquals(new double[] {expect.getWidth(), expect.getHeight(), expect.getFx(), expect.getFy(), expect.getCx(), expect.getCy()},
                new double[] {got.getWidth(), got.getHeight(), got.getFx(), got.getFy(), got.getCx(), got.getCy()}, 1e-12);
    }

    static PinholeCameraIntrinsic depthCamera() {
        return intrinsic(DW, DH, 2, 3, 1.5, 1);
    }

    static DepthToCloudOptions depthOptions(double scale, double trunc, int stride, boolean validOnly) {
        DepthToCloudOptions o = new DepthToCloudOptions();
        o.setDepthScale(scale);
        o.setDepthTrunc(trunc);
        o.setStride(stride);
        o.setProjectValidDepthOnly(validOnly ? 1 : 0);
        return o;
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

    static byte[] encode(Image img, String fmt, int quality) {
        try (Buffer b = Library.ioWriteImageToMemory(img, fmt, quality)) {
            return b.getData();
        }
    }

    @Test
    void pngRoundTripAndTypedPixels() {
        byte[] px = new byte[5 * 4 * 3];
        for (int i = 0; i < px.length; i++) px[i] = (byte) (i * 7);
        try (Image img = Image.createFromData(5, 4, 3, 1, px)) {
            assertEquals(5, img.width());
            assertEquals(4, img.height());
            assertEquals(3, img.numChannels());
            assertEquals(1, img.bytesPerChannel());
            assertArrayEquals(px, img.getArray(DATA));
            byte[] png = encode(img, "png", -1);
            assertEquals((byte) 0x89, png[0]);
            assertEquals('P', png[1]);
            assertEquals('N', png[2]);
            assertEquals('G', png[3]);
            try (Image back = Library.ioReadImageFromMemory(png, "png")) {
                assertEquals(5, back.width());
                assertEquals(3, back.numChannels());
                assertArrayEquals(px, back.getArray(DATA));
            }
            String path = tmp.resolve("img.png").toString();
            Library.ioWriteImage(path, img, null, -1);
            try (Image back = Library.ioReadImage(path, null)) {
                assertArrayEquals(px, back.getArray(DATA));
            }
            String ppm = tmp.resolve("img.ppm").toString();
            Library.ioWriteImage(ppm, img, null, -1);
            try (Image back = Library.ioReadImage(ppm, "ppm")) {
                assertArrayEquals(px, back.getArray(DATA));
            }
            try (ImageArrayShapeResult s = img.arrayShape(DATA)) {
                assertEquals(px.length, s.rows());
            }
            assertEquals(px.length, img.arrayView(DATA).capacity());
            assertTrue(img.arrayView(DATA).isReadOnly());
            img.arrayMutableView(DATA).put(0, (byte) 200);
            assertEquals((byte) 200, img.getArray(DATA)[0]);
            try (Image c = img.clone()) {
                assertArrayEquals(img.getArray(DATA), c.getArray(DATA));
            }
        }
        short[] depth = {0, 1, 1000, (short) 65535, 300, 42};
        try (Image d16 = Images.fromUInt16(3, 2, 1, depth); Image back = Library.ioReadImageFromMemory(encode(d16, "png", -1), "png")) {
            assertEquals(2, back.bytesPerChannel());
            assertArrayEquals(depth, Images.toUInt16Array(back));
            assertEquals(65535, Short.toUnsignedInt(Images.toUInt16Array(back)[3]));
        }
        byte[] flat = new byte[64];
        java.util.Arrays.fill(flat, (byte) 128);
        try (Image gray = Image.createFromData(8, 8, 1, 1, flat); Image back = Library.ioReadImageFromMemory(encode(gray, "jpg", 95), "jpg")) {
            assertEquals(8, back.width());
            for (byte b : back.getArray(DATA)) assertTrue(Math.abs((b & 0xff) - 128) <= 2, "jpeg of a flat image stays flat");
        }
    }

    @Test
    void flipsConversionsFilters() {
        try (Image row = Image.createFromData(3, 1, 1, 1, new byte[] {1, 2, 3}); Image f = row.flipHorizontal(); Image s = row.flipVertical()) {
            assertArrayEquals(new byte[] {3, 2, 1}, f.getArray(DATA));
            assertArrayEquals(new byte[] {1, 2, 3}, s.getArray(DATA));
        }
        try (Image col = Image.createFromData(1, 3, 1, 1, new byte[] {1, 2, 3}); Image f = col.flipVertical()) {
            assertArrayEquals(new byte[] {3, 2, 1}, f.getArray(DATA));
        }
        try (Image g = Image.createFromData(3, 1, 1, 1, new byte[] {0, (byte) 255, 51});
             Image f = g.createFloatImage(Library.IMAGE_CONVERT_WEIGHTED)) {
            assertEquals(4, f.bytesPerChannel());
            assertArrayEquals(new double[] {0, 1, 0.2}, toDouble(Images.toFloatArray(f)), 1e-6);
        }
        try (Image rgb = Image.createFromData(1, 1, 3, 1, new byte[] {(byte) 255, 0, 0});
             Image w = rgb.createFloatImage(Library.IMAGE_CONVERT_WEIGHTED);
             Image e = rgb.createFloatImage(Library.IMAGE_CONVERT_EQUAL)) {
            assertEquals(0.299, Images.toFloatArray(w)[0], 1e-6);
            assertEquals(1.0 / 3, Images.toFloatArray(e)[0], 1e-6);
        }
        try (Image raw = Images.fromUInt16(3, 1, 1, new short[] {500, 4000, 1500}); Image m = raw.convertDepthToFloat(1000, 3.0)) {
            assertArrayEquals(new double[] {0.5, 0, 1.5}, toDouble(Images.toFloatArray(m)), 1e-6);
        }
        float[] half = new float[20];
        java.util.Arrays.fill(half, 0.5f);
        try (Image flat = Images.fromFloat(5, 4, 1, half)) {
            for (int t : new int[] {Library.IMAGE_FILTER_GAUSSIAN3, Library.IMAGE_FILTER_GAUSSIAN5, Library.IMAGE_FILTER_GAUSSIAN7})
                try (Image f = flat.filter(t)) {
                    for (float x : Images.toFloatArray(f)) assertEquals(0.5, x, 1e-6, "filter " + t);
                }
            for (int t : new int[] {Library.IMAGE_FILTER_SOBEL3_DX, Library.IMAGE_FILTER_SOBEL3_DY})
                try (Image f = flat.filter(t)) {
                    for (float x : Images.toFloatArray(f)) assertEquals(0, x, 1e-6, "filter " + t);
                }
        }
        try (Image img = Images.fromFloat(4, 2, 1, new float[] {1, 3, 5, 7, 1, 3, 5, 7}); Image h = img.downsample()) {
            assertEquals(2, h.width());
            assertEquals(1, h.height());
            assertArrayEquals(new double[] {2, 6}, toDouble(Images.toFloatArray(h)), 1e-6);
        }
    }

    @Test
    void intrinsicPresetsTrajectoryJson() {
        PinholeCameraIntrinsic ps = PinholeCameraIntrinsic.setPreset(Library.INTRINSIC_PRIMESENSE_DEFAULT);
        assertIntrinsic(intrinsic(640, 480, 525, 525, 319.5, 239.5), ps);
        PinholeCameraIntrinsic k2d = PinholeCameraIntrinsic.setPreset(Library.INTRINSIC_KINECT2_DEPTH_DEFAULT);
        assertIntrinsic(intrinsic(512, 424, 365.456, 365.456, 254.878, 205.395), k2d);
        PinholeCameraIntrinsic k2c = PinholeCameraIntrinsic.setPreset(Library.INTRINSIC_KINECT2_COLOR_DEFAULT);
        assertEquals(1920, k2c.getWidth());
        assertEquals(1080, k2c.getHeight());
        assertEquals(1059.9718, k2c.getFx(), 1e-9);
        assertEquals(975.7193, k2c.getCx(), 1e-9);
        assertEquals(545.9533, k2c.getCy(), 1e-9);
        assertInvalid(() -> PinholeCameraIntrinsic.setPreset(99));

        double[] pose = {0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1};
        try (PinholeCameraTrajectory traj = new PinholeCameraTrajectory()) {
            assertEquals(0, traj.size());
            traj.append(ps, pose);
            traj.append(k2d, IDENTITY);
            assertEquals(2, traj.size());
            try (GetResult g = traj.get(0)) {
                assertIntrinsic(ps, g.intrinsic());
                assertArrayEquals(pose, g.extrinsic(), 0);
            }
            assertInvalid(() -> traj.get(5));
            double[] bad = pose.clone();
            bad[15] = 2;
            assertInvalid(() -> traj.append(ps, bad));
            String json = tmp.resolve("traj.json").toString();
            Library.ioWritePinholeCameraTrajectory(json, traj, null);
            try (PinholeCameraTrajectory back = Library.ioReadPinholeCameraTrajectory(json, null);
                 GetResult a = back.get(0); GetResult b = back.get(1)) {
                assertEquals(2, back.size());
                assertIntrinsic(ps, a.intrinsic());
                assertIntrinsic(k2d, b.intrinsic());
                assertArrayEquals(pose, a.extrinsic(), 1e-12);
            }
            String log = tmp.resolve("traj.log").toString();
            Library.ioWritePinholeCameraTrajectory(log, traj, "log");
            try (PinholeCameraTrajectory back = Library.ioReadPinholeCameraTrajectory(log, "log"); GetResult a = back.get(0)) {
                assertEquals(2, back.size());
                assertArrayEquals(pose, a.extrinsic(), 1e-9);
                assertIntrinsic(ps, a.intrinsic()); // log intrinsic is the PrimeSense default
            }
            traj.clear();
            assertEquals(0, traj.size());
        }
        String ipath = tmp.resolve("intrinsic.json").toString();
        Library.ioWritePinholeCameraIntrinsic(ipath, k2d);
        assertIntrinsic(k2d, Library.ioReadPinholeCameraIntrinsic(ipath));
        String ppath = tmp.resolve("params.json").toString();
        Library.ioWritePinholeCameraParameters(ppath, ps, pose);
        try (IoReadPinholeCameraParametersResult pp = Library.ioReadPinholeCameraParameters(ppath)) {
            assertIntrinsic(ps, pp.intrinsic());
            assertArrayEquals(pose, pp.extrinsic(), 1e-12);
        }
        assertStatus(Library.ERROR_IO, () -> Library.ioReadPinholeCameraIntrinsic(tmp.resolve("none.json").toString()));
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
        try (Image fdepth = Images.fromFloat(DW, DH, 1, metres); Image udepth = Images.fromUInt16(DW, DH, 1, mm)) {
            try (DepthToCloudOptions defaults = new DepthToCloudOptions()) {
                assertEquals(1000, defaults.getDepthScale(), 0, "defaults from o3d_depth_to_cloud_options_init");
                assertEquals(1, defaults.getStride());
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, null, null)) {
                assertArrayEquals(expectedDepthPoints(0, 0, 0), points(pc), 1e-6);
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(udepth, cam, null, depthOptions(1000, 1000, 1, true))) {
                assertArrayEquals(expectedDepthPoints(0, 0, 0), points(pc), 1e-6);
            }
            double[] ext = {1, 0, 0, 0.5, 0, 1, 0, -1, 0, 0, 1, 2, 0, 0, 0, 1};
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, ext, depthOptions(1000, 1000, 1, true))) {
                assertArrayEquals(expectedDepthPoints(0.5, -1, 2), points(pc), 1e-6);
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, null, depthOptions(1000, 1000, 2, true))) {
                assertEquals(4, pc.size(), "stride 2: pixels (0,0),(2,0),(0,2),(2,2)");
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, null, depthOptions(1000, 2.0, 1, true))) {
                // Open3D drops depth >= depth_trunc: the five pixels at 2 m or deeper
                assertEquals(expectedDepthPoints(0, 0, 0).length / 3 - 5, pc.size());
            }
            try (PointCloud pc = PointCloud.createFromDepthImage(fdepth, cam, null, depthOptions(1000, 1000, 1, false))) {
                assertEquals(DW * DH, pc.size());
                assertTrue(Double.isNaN(points(pc)[3 * (DW + 2)]), "invalid pixel is NaN");
            }

            byte[] color = new byte[DW * DH * 3];
            for (int i = 0; i < DW * DH; i++) {
                color[3 * i] = (byte) (10 * i);
                color[3 * i + 1] = 100;
                color[3 * i + 2] = (byte) 200;
            }
            try (Image cimg = Image.createFromData(DW, DH, 3, 1, color)) {
                try (RgbdOptions o = new RgbdOptions()) {
                    o.setDepthScale(1000);
                    o.setDepthTrunc(3.0);
                    o.setConvertRgbToIntensity(0);
                    try (RGBDImage rgbd = RGBDImage.createFromColorAndDepth(cimg, udepth, o)) {
                        try (Image d = rgbd.getDepth()) {
                            assertArrayEquals(toDouble(metres), toDouble(Images.toFloatArray(d)), 1e-6);
                        }
                        try (Image c = rgbd.getColor()) {
                            assertArrayEquals(color, c.getArray(DATA));
                        }
                        try (PointCloud pc = PointCloud.createFromRgbdImage(rgbd, cam, null, 1)) {
                            assertArrayEquals(expectedDepthPoints(0, 0, 0), points(pc), 1e-6);
                            List<Double> expect = new ArrayList<>();
                            for (int i = 0; i < DW * DH; i++)
                                if (metres[i] > 0) {
                                    expect.add((color[3 * i] & 0xff) / 255.0);
                                    expect.add(100 / 255.0);
                                    expect.add(200 / 255.0);
                                }
                            assertArrayEquals(expect.stream().mapToDouble(Double::doubleValue).toArray(),
                                    pc.getArray(Library.POINTCLOUD_COLORS), 1e-6);
                        }
                    }
                }
                try (RGBDImage rgbd = RGBDImage.createFromColorAndDepth(cimg, udepth, null); Image c = rgbd.getColor()) {
                    assertEquals(1, c.numChannels());
                    assertEquals(4, c.bytesPerChannel());
                    assertEquals((0.587 * 100 + 0.114 * 200) / 255.0, Images.toFloatArray(c)[0], 1e-5);
                }
                short[] far = mm.clone();
                far[0] = 4500;
                try (Image fd = Images.fromUInt16(DW, DH, 1, far);
                     RGBDImage rgbd = RGBDImage.createFromDatasetFormat(Library.RGBD_FORMAT_REDWOOD, cimg, fd, 1); Image d = rgbd.getDepth()) {
                    assertEquals(0, Images.toFloatArray(d)[0], 0, "4.5 m truncated");
                    assertEquals(1.25, Images.toFloatArray(d)[1], 1e-6);
                }
                try (RGBDImage rgbd = RGBDImage.createFromDatasetFormat(Library.RGBD_FORMAT_TUM, cimg, udepth, 1); Image d = rgbd.getDepth()) {
                    assertEquals(1250 / 5000.0, Images.toFloatArray(d)[1], 1e-6);
                }
                try (RGBDImage rgbd = RGBDImage.createFromDatasetFormat(Library.RGBD_FORMAT_SUN, cimg, udepth, 1); Image d = rgbd.getDepth()) {
                    assertEquals(DW, d.width());
                }
                try (RGBDImage rgbd = RGBDImage.createFromDatasetFormat(Library.RGBD_FORMAT_NYU, cimg, udepth, 1); Image d = rgbd.getDepth()) {
                    assertEquals(DH, d.height());
                }
                try (Image small = Image.create(2, 2, 1, 2)) {
                    assertInvalid(() -> RGBDImage.createFromColorAndDepth(cimg, small, null));
                }
                assertInvalid(() -> PointCloud.createFromDepthImage(cimg, cam, null, null));
            }
        }
    }

    @Test
    void errorsForBadInputAndMisuse() {
        assertInvalid(() -> Image.create(0, 0, 1, 1));
        assertInvalid(() -> Image.create(2, 2, 2, 1));
        assertInvalid(() -> Image.createFromData(2, 2, 1, 1, new byte[3]));
        assertStatus(Library.ERROR_PARSE, () -> Library.ioReadImageFromMemory(new byte[] {(byte) 0x89, 'P', 'N', 'G', 1, 2, 3}, "png"));
        assertStatus(Library.ERROR_IO, () -> Library.ioReadImage("/nonexistent/dir/none.png", null));
        try (Image img = Image.create(2, 2, 1, 1)) {
            assertInvalid(() -> img.filter(Library.IMAGE_FILTER_GAUSSIAN3));
            assertThrows(IllegalArgumentException.class, () -> Images.toFloatArray(img));
        }
        try (Image f = Images.fromFloat(2, 2, 1, new float[4])) {
            assertThrows(O3dException.class, () -> encode(f, "png", -1));
        }
        assertInvalid(() -> Library.ioWriteImage(tmp.resolve("x.png").toString(), null, null, -1));
        assertInvalid(() -> PointCloud.createFromDepthImage(null, depthCamera(), null, null));
        assertInvalid(() -> RGBDImage.createFromColorAndDepth(null, null, null));

        Image image = Image.create(2, 2, 1, 1);
        PinholeCameraTrajectory traj = new PinholeCameraTrajectory();
        image.close();
        traj.close();
        image.close();
        assertThrows(IllegalStateException.class, image::width);
        assertThrows(IllegalStateException.class, traj::size);
    }

    @Test
    void createPyramidHalvesEachLevelAndKeepsAConstant() {
        float[] flat = new float[32];
        java.util.Arrays.fill(flat, 0.5f);
        try (Image img = Images.fromFloat(8, 4, 1, flat)) {
            Image[] levels = Images.createPyramid(img, 3, true);
            assertEquals(3, levels.length);
            assertEquals(8, levels[0].width());
            assertEquals(4, levels[1].width());
            assertEquals(2, levels[2].width());
            assertEquals(1, levels[2].height());
            for (Image level : levels) {
                for (float v : Images.toFloatArray(level)) assertEquals(0.5f, v);
                level.close();
            }
        }
        try (Image ramp = Images.fromFloat(4, 2, 1, new float[] {0, 1, 2, 3, 0, 1, 2, 3})) {
            Image[] plain = Images.createPyramid(ramp, 2, false);
            assertArrayEquals(new float[] {0.5f, 2.5f}, Images.toFloatArray(plain[1]));
            for (Image level : plain) level.close();
            assertThrows(IllegalArgumentException.class, () -> Images.createPyramid(ramp, 0, false));
        }
    }
}
