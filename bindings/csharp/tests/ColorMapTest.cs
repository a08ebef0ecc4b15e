// SPDX-License-Identifier: MIT
// Colour-map optimization from C#, on tests/capi/test_color_map.c's scene whose answer is known: a box room with a
// smooth colour texture, ray-cast into five 8-bit RGB + float depth views of one corner, given with each pose turned
// by 1.5 degrees and moved about 2 cm. Both optimizers move the poses toward the truth and the colours toward the
// texture (the images pass as an RGBDImage[]); and the errors.
using System;
using System.Linq;
using O3d;

static partial class Test
{
    const int CW = 160, CH = 120;
    static readonly double[] RoomLo = { -1.2, -1.0, -1.0 }, RoomHi = { 1.2, 1.0, 1.6 };

    static double[] RoomTexture(double[] p) => new[] {
        0.5 + 0.2 * Math.Sin(5.0 * p[0] + 2.0 * p[2]) * Math.Cos(4.0 * p[1]) + 0.15 * Math.Sin(11.0 * p[2] + 3.0 * p[1]),
        0.5 + 0.2 * Math.Cos(4.5 * p[1] + 1.0) * Math.Sin(5.5 * p[2] - p[0]) + 0.15 * Math.Cos(10.0 * p[0] - 4.0 * p[1]),
        0.5 + 0.25 * Math.Sin(3.0 * (p[0] + p[1] + p[2])) + 0.15 * Math.Cos(12.0 * p[1] - 5.0 * p[2] + 3.0 * p[0]) };

    // (Mul4: RegistrationPipelineTest.cs)
    static double[] RigidInverse(double[] m)
    {
        var o = new double[16];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) { o[4 * r + c] = m[4 * c + r]; o[4 * r + 3] -= m[4 * c + r] * m[4 * c + 3]; }
        o[15] = 1;
        return o;
    }

    static double[] Unit(double[] v) { double n = Math.Sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); return new[] { v[0] / n, v[1] / n, v[2] / n }; }
    static double[] Cross(double[] a, double[] b) => new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };

    // Camera-to-world pose at `c` looking at `t` (world y points down).
    static double[] LookAt(double[] c, double[] t)
    {
        var z = Unit(new[] { t[0] - c[0], t[1] - c[1], t[2] - c[2] });
        var x = Unit(Cross(new double[] { 0, 1, 0 }, z));
        var y = Cross(z, x);
        var m = new double[16];
        for (int r = 0; r < 3; r++) { m[4 * r] = x[r]; m[4 * r + 1] = y[r]; m[4 * r + 2] = z[r]; m[4 * r + 3] = c[r]; }
        m[15] = 1;
        return m;
    }

    // Rotation by `deg` about `axis` (Rodrigues), then translation t.
    static double[] Motion(double[] axis, double deg, double[] t)
    {
        var k = Unit(axis);
        double a = deg * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a);
        var m = new double[16];
        for (int r = 0; r < 3; r++) { for (int q = 0; q < 3; q++) m[4 * r + q] = (1 - c) * k[r] * k[q] + (r == q ? c : 0); m[4 * r + 3] = t[r]; }
        m[1] -= s * k[2]; m[2] += s * k[1]; m[4] += s * k[2]; m[6] -= s * k[0]; m[8] -= s * k[1]; m[9] += s * k[0];
        m[15] = 1;
        return m;
    }

    // The RGB-D view from camera-to-world `pose`: each ray meets the room's box where it leaves it.
    static RGBDImage RenderRoom(double[] pose)
    {
        var rgb = new byte[3 * CW * CH];
        var depth = new float[CW * CH];
        for (int v = 0; v < CH; v++)
            for (int u = 0; u < CW; u++)
            {
                double[] dc = { (u - 79.5) / 140.0, (v - 59.5) / 140.0, 1.0 }, d = new double[3], p = new double[3];
                double t = double.PositiveInfinity;
                for (int r = 0; r < 3; r++) d[r] = pose[4 * r] * dc[0] + pose[4 * r + 1] * dc[1] + pose[4 * r + 2] * dc[2];
                for (int a = 0; a < 3; a++) if (d[a] != 0) t = Math.Min(t, ((d[a] > 0 ? RoomHi[a] : RoomLo[a]) - pose[4 * a + 3]) / d[a]);
                for (int r = 0; r < 3; r++) p[r] = pose[4 * r + 3] + t * d[r];
                var col = RoomTexture(p);
                for (int k = 0; k < 3; k++) rgb[3 * (v * CW + u) + k] = (byte)Math.Round(255.0 * col[k]);
                depth[v * CW + u] = (float)t;  // the camera ray has z = 1: t is the depth
            }
        using (var c = Image.FromArray(CW, CH, 3, rgb))
        using (var d = Image.FromArray(CW, CH, 1, depth))
        using (var o = new RgbdOptions { DepthScale = 1.0, DepthTrunc = 10.0, ConvertRgbToIntensity = 0 })
            return RGBDImage.CreateFromColorAndDepth(c, d, o);
    }

    static TriangleMesh RoomMesh()
    {
        const int grid = 31;
        var xyz = new double[3 * 6 * grid * grid];
        int n = 0;
        for (int axis = 0; axis < 3; axis++)
            for (int side = 0; side < 2; side++)
                for (int j = 0; j < grid; j++)
                    for (int i = 0; i < grid; i++, n++)
                    {
                        int a = (axis + 1) % 3, b = (axis + 2) % 3;
                        xyz[3 * n + axis] = side == 1 ? RoomHi[axis] : RoomLo[axis];
                        xyz[3 * n + a] = RoomLo[a] + (RoomHi[a] - RoomLo[a]) * i / (grid - 1);
                        xyz[3 * n + b] = RoomLo[b] + (RoomHi[b] - RoomLo[b]) * j / (grid - 1);
                    }
        var mesh = new TriangleMesh();
        mesh.SetArray(Library.MESH_VERTICES, xyz);
        return mesh;
    }

    // Mean rotation error (degrees) and camera-centre distance (metres) against the truth.
    static double[] PoseError(PinholeCameraTrajectory t, double[][] truth)
    {
        double deg = 0, metres = 0;
        for (int c = 0; c < truth.Length; c++)
            using (var g = t.Get((uint)c))
            {
                var a = g.Extrinsic();
                var e = Mul4(a, RigidInverse(truth[c]));
                deg += Math.Acos(Math.Max(-1, Math.Min(1, (e[0] + e[5] + e[10] - 1) / 2))) * 180 / Math.PI / truth.Length;
                double[] ia = RigidInverse(a), ib = RigidInverse(truth[c]);
                metres += Math.Sqrt(Math.Pow(ia[3] - ib[3], 2) + Math.Pow(ia[7] - ib[7], 2) + Math.Pow(ia[11] - ib[11], 2)) / truth.Length;
            }
        return new[] { deg, metres };
    }

    // Mean RGB distance from the texture over the vertices within 1 m of the corner the cameras see.
    static double ColorError(TriangleMesh mesh)
    {
        double[] xyz = mesh.GetArray(Library.MESH_VERTICES), rgb = mesh.GetArray(Library.MESH_VERTEX_COLORS);
        Check(rgb.Length == xyz.Length, "a colour per vertex");
        double sum = 0;
        int used = 0;
        for (int i = 0; i < xyz.Length / 3; i++)
        {
            var p = new[] { xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2] };
            if (Math.Abs(p[0] - RoomHi[0]) + Math.Abs(p[1] - RoomHi[1]) + Math.Abs(p[2] - RoomHi[2]) > 1.0 + 1e-9) continue;
            var t = RoomTexture(p);
            sum += Math.Sqrt(Enumerable.Range(0, 3).Sum(k => Math.Pow(rgb[3 * i + k] - t[k], 2)));
            used++;
        }
        Check(used > 50, "vertices near the corner");
        return sum / used;
    }

    static ColorMapRigidOptions RoomOptions(int iterations) => new ColorMapRigidOptions {
        MaximumIteration = iterations, MaximumAllowableDepth = 4.0, ImageBoundaryMargin = 4,
        DepthThresholdForDiscontinuityCheck = 1.0,  // slanted walls at 160 x 120 are no discontinuity
        DepthThresholdForVisibilityCheck = 0.2 };   // the poses start a few cm off

    static void ColorMapTests()
    {
        Run("color map: both optimizers recover the poses", () =>
        {
            double[][] centres = { new[] { 0.0, 0, 0 }, new[] { -0.6, -0.4, -0.5 }, new[] { 0.5, -0.5, 0.3 }, new[] { -0.5, 0.5, 0.5 }, new[] { 0.4, 0.4, -0.6 } };
            double[][] targets = { new[] { 1.2, 1.0, 1.6 }, new[] { 1.0, 1.0, 1.6 }, new[] { 1.2, 0.8, 1.6 }, new[] { 1.2, 1.0, 1.4 }, new[] { 1.1, 0.9, 1.5 } };
            double[][] axes = { new[] { 1.0, 2, 0 }, new[] { -1.0, 0, 2 }, new[] { 0.0, 1, 1 }, new[] { 2.0, -1, 1 }, new[] { 1.0, 1, -1 } };
            double[][] shifts = { new[] { 0.02, -0.01, 0.01 }, new[] { -0.01, 0.02, 0 }, new[] { 0, -0.02, -0.015 }, new[] { 0.015, 0.01, 0.01 }, new[] { -0.02, 0, 0.01 } };
            var images = new RGBDImage[5];
            var truth = new double[5][];
            using (var mesh = RoomMesh())
            using (var start = new PinholeCameraTrajectory())
            using (var camera = Intrinsic(CW, CH, 140, 140, 79.5, 59.5))
            {
                for (int c = 0; c < 5; c++)
                {
                    var pose = LookAt(centres[c], targets[c]);
                    images[c] = RenderRoom(pose);
                    truth[c] = RigidInverse(pose);
                    start.Append(camera, Mul4(Motion(axes[c], 1.5, shifts[c]), truth[c]));
                }
                double rigidColor;
                using (var o0 = RoomOptions(0))
                using (var o1 = RoomOptions(150))
                using (var r0 = Library.ColorMapRunRigidOptimizer(mesh, images, start, o0))
                using (var r1 = Library.ColorMapRunRigidOptimizer(mesh, images, start, o1))
                using (var m0 = r0.ColoredMesh()) using (var t0 = r0.RefinedTrajectory())
                using (var m1 = r1.ColoredMesh()) using (var t1 = r1.RefinedTrajectory())
                {
                    double[] e0 = PoseError(t0, truth), e1 = PoseError(t1, truth);
                    Near(e0[0], 1.5, 1e-9, "no iterations: the poses as given");
                    Check(e1[0] < 0.5 * e0[0] && e1[1] < 0.6 * e0[1], "rigid pose error " + e1[0] + " deg " + e1[1] + " m");
                    rigidColor = ColorError(m1);
                    Check(rigidColor < 0.5 * ColorError(m0), "colour error falls");
                    Check(!mesh.HasArray(Library.MESH_VERTEX_COLORS), "the input keeps no colours");
                }
                using (var n = new ColorMapNonRigidOptions { NumberOfVerticalAnchors = 6, MaximumIteration = 150, MaximumAllowableDepth = 4.0,
                                                               ImageBoundaryMargin = 4, DepthThresholdForDiscontinuityCheck = 1.0,
                                                               DepthThresholdForVisibilityCheck = 0.2 })
                using (var r = Library.ColorMapRunNonRigidOptimizer(mesh, images, start, n))
                using (var m = r.ColoredMesh()) using (var t = r.RefinedTrajectory())
                {
                    var e = PoseError(t, truth);
                    Check(e[0] < 0.75 && e[1] < 0.015, "non-rigid pose error " + e[0] + " deg " + e[1] + " m");
                    Check(ColorError(m) < 1.1 * rigidColor, "non-rigid colours");
                }
                using (var o = RoomOptions(1))
                    ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => Library.ColorMapRunRigidOptimizer(mesh, images.Take(2).ToArray(), start, o),
                                 "fewer images than poses");
                foreach (var i in images) i.Dispose();
            }
        });
    }
}
