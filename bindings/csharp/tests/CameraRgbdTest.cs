// SPDX-License-Identifier: MIT
// Cameras and RGB-D from C#: intrinsic presets, trajectories, JSON/log files, depth back-projection, dataset
// formats (the same scenarios as ImageCameraTest.java).
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using O3d;

static partial class Test
{
    // Synthetic depth: d(u, v) = 1 + 0.25 u + 0.5 v on a 4x3 image, pixel (2, 1) invalid (0); camera fx 2, fy 3, cx 1.5, cy 1.
    const int DW = 4, DH = 3;
    static double DepthAt(int u, int v) { return (u == 2 && v == 1) ? 0 : 1 + 0.25 * u + 0.5 * v; }
    static PinholeCameraIntrinsic Intrinsic(int w, int h, double fx, double fy, double cx, double cy)
    {
        return new PinholeCameraIntrinsic { Width = w, Height = h, Fx = fx, Fy = fy, Cx = cx, Cy = cy };
    }
    static void SameIntrinsic(PinholeCameraIntrinsic e, PinholeCameraIntrinsic g, string what)
    {
        AllNear(new double[] { g.Width, g.Height, g.Fx, g.Fy, g.Cx, g.Cy }, new double[] { e.Width, e.Height, e.Fx, e.Fy, e.Cx, e.Cy }, 1e-12, what);
    }
    static DepthToCloudOptions DepthOptions(double scale, double trunc, int stride, bool validOnly)
    {
        return new DepthToCloudOptions { DepthScale = scale, DepthTrunc = trunc, Stride = stride, ProjectValidDepthOnly = validOnly ? 1 : 0 };
    }
    // The analytic back-projection, row by row (Open3D's order), minus t (world = camera - t).
    static double[] ExpectedDepthPoints(double tx, double ty, double tz)
    {
        var pts = new List<double>();
        for (int v = 0; v < DH; v++)
            for (int u = 0; u < DW; u++)
            {
                double d = DepthAt(u, v);
                if (d > 0) pts.AddRange(new[] { (u - 1.5) * d / 2 - tx, (v - 1.0) * d / 3 - ty, d - tz });
            }
        return pts.ToArray();
    }

    static void CameraRgbdTests()
    {
        Run("camera: intrinsic presets, trajectory, JSON round trips", () =>
        {
            var ps = PinholeCameraIntrinsic.SetPreset(Library.INTRINSIC_PRIMESENSE_DEFAULT);
            SameIntrinsic(Intrinsic(640, 480, 525, 525, 319.5, 239.5), ps, "PrimeSense");
            var k2d = PinholeCameraIntrinsic.SetPreset(Library.INTRINSIC_KINECT2_DEPTH_DEFAULT);
            SameIntrinsic(Intrinsic(512, 424, 365.456, 365.456, 254.878, 205.395), k2d, "Kinect2 depth");
            var k2c = PinholeCameraIntrinsic.SetPreset(Library.INTRINSIC_KINECT2_COLOR_DEFAULT);
            Check(k2c.Width == 1920 && k2c.Height == 1080, "Kinect2 color size");
            Near(k2c.Fx, 1059.9718, 1e-9, "fx"); Near(k2c.Cx, 975.7193, 1e-9, "cx"); Near(k2c.Cy, 545.9533, 1e-9, "cy");
            Invalid(() => PinholeCameraIntrinsic.SetPreset(99), "preset 99");

            var pose = new double[] { 0, -1, 0, 1, 1, 0, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1 };
            string dir = TempDir();
            try
            {
                using (var traj = new PinholeCameraTrajectory())
                {
                    Check(traj.Size() == 0, "empty");
                    traj.Append(ps, pose);
                    traj.Append(k2d, IDENTITY);
                    Check(traj.Size() == 2, "2 cameras");
                    using (var g = traj.Get(0)) { SameIntrinsic(ps, g.Intrinsic(), "get 0"); AllNear(g.Extrinsic(), pose, 0, "extrinsic 0"); }
                    Invalid(() => traj.Get(5), "index 5");
                    var bad = (double[])pose.Clone(); bad[15] = 2;
                    Invalid(() => traj.Append(ps, bad), "not rigid");
                    string json = Path.Combine(dir, "traj.json");
                    Library.IoWritePinholeCameraTrajectory(json, traj, null);
                    using (var back = Library.IoReadPinholeCameraTrajectory(json, null))
                    using (var a = back.Get(0))
                    using (var b = back.Get(1))
                    {
                        Check(back.Size() == 2, "json size");
                        SameIntrinsic(ps, a.Intrinsic(), "json 0"); SameIntrinsic(k2d, b.Intrinsic(), "json 1");
                        AllNear(a.Extrinsic(), pose, 1e-12, "json extrinsic");
                    }
                    string log = Path.Combine(dir, "traj.log");
                    Library.IoWritePinholeCameraTrajectory(log, traj, "log");
                    using (var back = Library.IoReadPinholeCameraTrajectory(log, "log"))
                    using (var a = back.Get(0))
                    {
                        Check(back.Size() == 2, "log size");
                        AllNear(a.Extrinsic(), pose, 1e-9, "log extrinsic");
                        SameIntrinsic(ps, a.Intrinsic(), "log intrinsic is the PrimeSense default");
                    }
                    traj.Clear();
                    Check(traj.Size() == 0, "cleared");
                }
                string ipath = Path.Combine(dir, "intrinsic.json");
                Library.IoWritePinholeCameraIntrinsic(ipath, k2d);
                SameIntrinsic(k2d, Library.IoReadPinholeCameraIntrinsic(ipath), "intrinsic JSON");
                string ppath = Path.Combine(dir, "params.json");
                Library.IoWritePinholeCameraParameters(ppath, ps, pose);
                using (var pp = Library.IoReadPinholeCameraParameters(ppath))
                {
                    SameIntrinsic(ps, pp.Intrinsic(), "parameters intrinsic");
                    AllNear(pp.Extrinsic(), pose, 1e-12, "parameters extrinsic");
                }
                ThrowsStatus(Library.ERROR_IO, () => Library.IoReadPinholeCameraIntrinsic(Path.Combine(dir, "none.json")), "missing file");
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("rgbd: synthetic depth image back-projected to the analytic points; dataset formats", () =>
        {
            var metres = new float[DW * DH];
            var mm = new ushort[DW * DH];
            for (int v = 0; v < DH; v++)
                for (int u = 0; u < DW; u++) { metres[v * DW + u] = (float)DepthAt(u, v); mm[v * DW + u] = (ushort)Math.Round(DepthAt(u, v) * 1000); }
            var cam = Intrinsic(DW, DH, 2, 3, 1.5, 1);
            using (var fdepth = Image.FromArray(DW, DH, 1, metres))
            using (var udepth = Image.FromArray(DW, DH, 1, mm))
            {
                using (var defaults = new DepthToCloudOptions())
                    Check(defaults.DepthScale == 1000 && defaults.Stride == 1, "defaults from o3d_depth_to_cloud_options_init");
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, null, null)) AllNear(pc.Points, ExpectedDepthPoints(0, 0, 0), 1e-6, "float depth");
                using (var o = DepthOptions(1000, 1000, 1, true))
                using (var pc = PointCloud.CreateFromDepthImage(udepth, cam, null, o)) AllNear(pc.Points, ExpectedDepthPoints(0, 0, 0), 1e-6, "uint16 depth");
                var ext = new double[] { 1, 0, 0, 0.5, 0, 1, 0, -1, 0, 0, 1, 2, 0, 0, 0, 1 };
                using (var o = DepthOptions(1000, 1000, 1, true))
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, ext, o)) AllNear(pc.Points, ExpectedDepthPoints(0.5, -1, 2), 1e-6, "extrinsic");
                using (var o = DepthOptions(1000, 1000, 2, true))
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, null, o)) Check(pc.Size() == 4, "stride 2: pixels (0,0),(2,0),(0,2),(2,2)");
                using (var o = DepthOptions(1000, 2.0, 1, true))
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, null, o))
                    Check(pc.Size() == ExpectedDepthPoints(0, 0, 0).Length / 3 - 5, "Open3D drops depth >= depth_trunc (five pixels)");
                using (var o = DepthOptions(1000, 1000, 1, false))
                using (var pc = PointCloud.CreateFromDepthImage(fdepth, cam, null, o))
                    Check(pc.Size() == DW * DH && double.IsNaN(pc.Points[3 * (DW + 2)]), "invalid pixel is NaN");

                var color = new byte[DW * DH * 3];
                for (int i = 0; i < DW * DH; i++) { color[3 * i] = (byte)(10 * i); color[3 * i + 1] = 100; color[3 * i + 2] = 200; }
                using (var cimg = Image.CreateFromData(DW, DH, 3, 1, color))
                {
                    using (var o = new RgbdOptions { DepthScale = 1000, DepthTrunc = 3.0, ConvertRgbToIntensity = 0 })
                    using (var rgbd = RGBDImage.CreateFromColorAndDepth(cimg, udepth, o))
                    {
                        using (var d = rgbd.GetDepth()) AllNear(F2D(d.ToFloatArray()), F2D(metres), 1e-6, "depth in metres");
                        using (var c = rgbd.GetColor()) Check(c.GetArray(Library.IMAGE_DATA).SequenceEqual(color), "color kept");
                        using (var pc = PointCloud.CreateFromRgbdImage(rgbd, cam, null, 1))
                        {
                            AllNear(pc.Points, ExpectedDepthPoints(0, 0, 0), 1e-6, "rgbd points");
                            var expect = Enumerable.Range(0, DW * DH).Where(i => metres[i] > 0)
                                .SelectMany(i => new[] { color[3 * i] / 255.0, 100 / 255.0, 200 / 255.0 }).ToArray();
                            AllNear(pc.Colors, expect, 1e-6, "rgbd colors");
                        }
                    }
                    using (var rgbd = RGBDImage.CreateFromColorAndDepth(cimg, udepth, null))
                    using (var c = rgbd.GetColor())
                    {
                        Check(c.NumChannels() == 1 && c.BytesPerChannel() == 4, "intensity by default");
                        Near(c.ToFloatArray()[0], (0.587 * 100 + 0.114 * 200) / 255.0, 1e-5, "intensity");
                    }
                    var far = (ushort[])mm.Clone(); far[0] = 4500;
                    using (var fd = Image.FromArray(DW, DH, 1, far))
                    using (var rgbd = RGBDImage.CreateFromDatasetFormat(Library.RGBD_FORMAT_REDWOOD, cimg, fd, 1))
                    using (var d = rgbd.GetDepth())
                    {
                        Near(d.ToFloatArray()[0], 0, 0, "Redwood: 4.5 m truncated");
                        Near(d.ToFloatArray()[1], 1.25, 1e-6, "Redwood: metres");
                    }
                    using (var rgbd = RGBDImage.CreateFromDatasetFormat(Library.RGBD_FORMAT_TUM, cimg, udepth, 1))
                    using (var d = rgbd.GetDepth()) Near(d.ToFloatArray()[1], 1250 / 5000.0, 1e-6, "TUM: depth scale 5000");
                    using (var rgbd = RGBDImage.CreateFromDatasetFormat(Library.RGBD_FORMAT_SUN, cimg, udepth, 1))
                    using (var d = rgbd.GetDepth()) Check(d.Width() == DW, "SUN");
                    using (var rgbd = RGBDImage.CreateFromDatasetFormat(Library.RGBD_FORMAT_NYU, cimg, udepth, 1))
                    using (var d = rgbd.GetDepth()) Check(d.Height() == DH, "NYU");
                    using (var small = Image.Create(2, 2, 1, 2)) Invalid(() => RGBDImage.CreateFromColorAndDepth(cimg, small, null), "sizes differ");
                    Invalid(() => PointCloud.CreateFromDepthImage(cimg, cam, null, null), "color image as depth");
                }
            }
        });

        Run("image, camera, rgbd: errors for bad input and misuse", () =>
        {
            using (var img = Image.Create(2, 2, 1, 1)) Throws<InvalidOperationException>(() => img.ToFloatArray(), "8-bit image as floats");
            Invalid(() => Library.IoWriteImage(Path.Combine(Path.GetTempPath(), "o3d_none.png"), null, null, -1), "null image");
            Invalid(() => PointCloud.CreateFromDepthImage(null, Intrinsic(DW, DH, 2, 3, 1.5, 1), null, null), "null depth");
            Invalid(() => RGBDImage.CreateFromColorAndDepth(null, null, null), "null images");
            var image = Image.Create(2, 2, 1, 1);
            var traj = new PinholeCameraTrajectory();
            image.Dispose(); traj.Dispose(); image.Dispose();
            Throws<ObjectDisposedException>(() => image.Width(), "image after Dispose");
            Throws<ObjectDisposedException>(() => traj.Size(), "trajectory after Dispose");
        });
    }
}
