// SPDX-License-Identifier: MIT
// RGB-D odometry from C#, the scenarios of tests/capi/test_odometry.c: a frame onto itself is the identity, and
// Open3D's result on its RGBD frames 0 -> 1 (open3d 0.20, hybrid term, default options, PrimeSense intrinsics).
using System;
using O3d;

static partial class Test
{
    const int OW = 160, OH = 120;

    // A textured float intensity on a slanted plane of float depth (metres).
    static RGBDImage OdometryFrame()
    {
        var color = new float[OW * OH];
        var depth = new float[OW * OH];
        for (int v = 0; v < OH; v++)
            for (int u = 0; u < OW; u++)
            {
                color[v * OW + u] = (float)(0.5 + 0.2 * Math.Sin(0.3 * u) * Math.Cos(0.25 * v) + 0.1 * Math.Sin(0.11 * (u + v)));
                depth[v * OW + u] = (float)(1.5 + 0.004 * u + 0.002 * v);
            }
        using (var c = Image.FromArray(OW, OH, 1, color))
        using (var d = Image.FromArray(OW, OH, 1, depth))
        using (var o = new RgbdOptions { DepthScale = 1.0 })  // already metres
            return RGBDImage.CreateFromColorAndDepth(c, d, o);
    }

    static RGBDImage Open3dFrame(int i)
    {
        using (var c = Library.IoReadImage(DataFile("open3d/RGBD/color/0000" + i + ".jpg"), null))
        using (var d = Library.IoReadImage(DataFile("open3d/RGBD/depth/0000" + i + ".png"), null))
            return RGBDImage.CreateFromColorAndDepth(c, d, null);
    }

    static void OdometryTests()
    {
        Run("odometry: a frame onto itself is the identity", () =>
        {
            var identity = new double[] { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
            using (var frame = OdometryFrame())
                foreach (int j in new[] { Library.ODOMETRY_JACOBIAN_COLOR_TERM, Library.ODOMETRY_JACOBIAN_HYBRID_TERM })
                    using (var r = Library.OdometryComputeRgbd(frame, frame, Intrinsic(OW, OH, 130, 130, 79.5, 59.5), null, j, null, null))
                    {
                        Check(r.Success(), "success, jacobian " + j);
                        AllNear(r.Transformation(), identity, 1e-12, "identity, jacobian " + j);
                        Check(r.Information().Length == 36 && r.Information()[3 * 6 + 3] > 0.9 * OW * OH, "correspondences");
                    }
        });
        Run("odometry: Open3D's frames 0 -> 1", () =>
        {
            using (var source = Open3dFrame(0))
            using (var target = Open3dFrame(1))
            using (var r = Library.OdometryComputeRgbd(source, target, Intrinsic(640, 480, 525, 525, 319.5, 239.5), null,
                                                       Library.ODOMETRY_JACOBIAN_HYBRID_TERM, new[] { 20, 10, 5 }, new OdometryOptions()))
            {
                Check(r.Success(), "success");
                var t = r.Transformation();
                Near(t[3], -0.0010704978, 1e-5, "tx");
                Near(t[7], 0.0232280983, 1e-5, "ty");
                Near(t[11], 0.0014059205, 1e-5, "tz");
                Near(r.Information()[3 * 6 + 3], 252387, 0.001 * 252387, "information(3,3)");
            }
        });
    }
}
