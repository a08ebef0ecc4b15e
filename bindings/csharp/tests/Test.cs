// SPDX-License-Identifier: MIT
// Assert-based tests of the O3d C# binding. Prints "N passed, M failed" last; exit code 1 on failure.
//   mcs -target:exe -out:Test.exe -r:O3d.dll Test.cs && mono Test.exe
// Data: $O3D_TEST_DATA (else $O3D_TEST_DATA_DEFAULT, else ../shared/data); tests needing it are
// skipped when it is missing, unless O3D_REQUIRE_TEST_DATA=1 (then they fail).
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using O3d;

static class Test
{
    static int passed, failed, skipped;

    class SkipException : Exception { public SkipException(string m) : base(m) { } }

    static void Check(bool cond, string what) { if (!cond) throw new Exception("check failed: " + what); }
    static void Near(double a, double b, double tol, string what)
    {
        if (!(Math.Abs(a - b) <= tol)) throw new Exception(string.Format("{0}: {1} vs {2} (tol {3})", what, a, b, tol));
    }
    static void AllNear(double[] a, double[] b, double tol, string what)
    {
        Check(a.Length == b.Length, what + ": length " + a.Length + " vs " + b.Length);
        for (int i = 0; i < a.Length; i++) Near(a[i], b[i], tol, what + "[" + i + "]");
    }
    static T Throws<T>(Action a, string what) where T : Exception
    {
        try { a(); }
        catch (T e) { return e; }
        catch (Exception e) { throw new Exception(what + ": expected " + typeof(T).Name + ", got " + e.GetType().Name + ": " + e.Message); }
        throw new Exception(what + ": expected " + typeof(T).Name + ", nothing thrown");
    }
    static void ThrowsStatus(Status s, Action a, string what)
    {
        var e = Throws<O3dException>(a, what);
        Check(e.Status == s, what + ": status " + e.Status + ", expected " + s);
        Check(e.Message.Length > 0, what + ": empty message");
    }

    static void Run(string name, Action body)
    {
        try { body(); passed++; Console.WriteLine("PASS " + name); }
        catch (SkipException e) { skipped++; Console.WriteLine("SKIP " + name + ": " + e.Message); }
        catch (Exception e) { failed++; Console.WriteLine("FAIL " + name + ": " + e.GetType().Name + ": " + e.Message); }
    }

    static string DataFile(string rel)
    {
        string dir = Environment.GetEnvironmentVariable("O3D_TEST_DATA");
        if (string.IsNullOrEmpty(dir)) dir = Environment.GetEnvironmentVariable("O3D_TEST_DATA_DEFAULT");
        if (string.IsNullOrEmpty(dir)) dir = Path.Combine("..", "shared", "data");
        string path = Path.Combine(dir, rel);
        if (!File.Exists(path))
        {
            if (Environment.GetEnvironmentVariable("O3D_REQUIRE_TEST_DATA") == "1")
                throw new Exception("missing test data (O3D_REQUIRE_TEST_DATA=1): " + path);
            throw new SkipException("missing test data " + path);
        }
        return path;
    }

    static string TempDir()
    {
        string d = Path.Combine(Path.GetTempPath(), "o3d_cs_" + Guid.NewGuid().ToString("N"));
        Directory.CreateDirectory(d);
        return d;
    }

    static double[] RandomPoints(int n, int seed, double sx = 1, double sy = 1, double sz = 1)
    {
        var r = new Random(seed);
        var p = new double[3 * n];
        for (int i = 0; i < n; i++) { p[3 * i] = r.NextDouble() * sx; p[3 * i + 1] = r.NextDouble() * sy; p[3 * i + 2] = r.NextDouble() * sz; }
        return p;
    }

    static double[] ApplyTransform(double[] T, double[] p)
    {
        var q = new double[p.Length];
        for (int i = 0; i < p.Length / 3; i++)
            for (int r = 0; r < 3; r++)
                q[3 * i + r] = T[4 * r] * p[3 * i] + T[4 * r + 1] * p[3 * i + 1] + T[4 * r + 2] * p[3 * i + 2] + T[4 * r + 3];
        return q;
    }

    // ---- fixtures of the point-cloud tools tests (the same in O3dTest.java) ----
    // A 10 x 10 grid (spacing 0.1) at z = 0, indices 0..99, then two far outliers (100, 101).
    static double[] GridWithOutliers()
    {
        var p = new List<double>();
        for (int i = 0; i < 10; i++)
            for (int j = 0; j < 10; j++) { p.Add(i * 0.1); p.Add(j * 0.1); p.Add(0); }
        p.AddRange(new double[] { 5, 5, 5, -5, -5, 5 });
        return p.ToArray();
    }
    static int[] Range(int start, int count) { return Enumerable.Range(start, count).ToArray(); }
    // Points of a 3 x 3 x 3 grid (spacing 0.1) around (cx, cy, cz).
    static IEnumerable<double> Blob(double cx, double cy, double cz)
    {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++) { yield return cx + i * 0.1; yield return cy + j * 0.1; yield return cz + k * 0.1; }
    }

    static int Main()
    {
        Run("version", () =>
        {
            Check(Library.VersionMajor == 0, "major");
            Check(Library.Version == Library.VersionMajor + "." + Library.VersionMinor + "." + Library.VersionPatch, "version string");
            Check(Library.StatusString(Status.IO) == "O3D_ERROR_IO", "status string");
        });

        Run("points round trip float64 and float32", () =>
        {
            var pts = new double[] { 1, 2, 3, 4.5, -5.25, 6, 1e-3, 7, -8 };
            using (var pc = new PointCloud())
            {
                Check(pc.Size == 0 && !pc.HasPoints, "empty");
                pc.Points = pts;
                Check(pc.Size == 3 && pc.HasPoints && !pc.HasNormals && !pc.HasColors, "size 3");
                AllNear(pc.Points, pts, 0, "f64");
                pts[0] = 99; // the cloud holds a copy
                Near(pc.Points[0], 1, 0, "copy in");
                var f = new float[] { 0.5f, 1.25f, -2f, 3f, 4f, 5.5f };
                pc.SetPoints(f);
                Check(pc.Size == 2, "f32 size");
                AllNear(pc.Points, f.Select(x => (double)x).ToArray(), 0, "f32");
                pc.Normals = new double[] { 0, 0, 1, 0, 1, 0 };
                pc.SetColors(new float[] { 1, 0, 0, 0, 0.5f, 1 });
                Check(pc.HasNormals && pc.HasColors, "normals/colors");
                AllNear(pc.Colors, new double[] { 1, 0, 0, 0, 0.5, 1 }, 0, "colors");
                Throws<ArgumentException>(() => pc.Points = new double[4], "length not multiple of 3");
                long rows;
                IntPtr v = pc.PointsView(out rows);
                Check(rows == 2 && v != IntPtr.Zero, "view");
                var copy = new double[6];
                Marshal.Copy(v, copy, 0, 6);
                AllNear(copy, pc.Points, 0, "view contents");
                IntPtr mv = pc.PointsMutableView(out rows);
                Marshal.Copy(new double[] { 7, 8, 9 }, 0, mv, 3);
                AllNear(pc.Points.Take(3).ToArray(), new double[] { 7, 8, 9 }, 0, "mutable view write");
                using (var c = pc.Clone())
                {
                    pc.Clear();
                    Check(pc.Size == 0 && c.Size == 2, "clone is deep");
                }
            }
        });

        Run("voxel_down_sample averages", () =>
        {
            var pts = new double[] { 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.2, 5, 5, 5, 5.2, 5, 5 };
            using (var pc = new PointCloud(pts))
            using (var down = pc.VoxelDownSample(1.0))
            {
                Check(down.Size == 2, "2 voxels, got " + down.Size);
                var d = down.Points;
                int a = d[0] < d[3] ? 0 : 1, b = 1 - a;
                AllNear(d.Skip(3 * a).Take(3).ToArray(), new double[] { 0.1 / 3, 0.1 / 3, 0.2 / 3 }, 1e-12, "cluster A mean");
                AllNear(d.Skip(3 * b).Take(3).ToArray(), new double[] { 5.1, 5, 5 }, 1e-12, "cluster B mean");
                Check(pc.Size == 5, "input untouched");
            }
        });

        Run("normals of a sampled plane", () =>
        {
            var pts = new List<double>();
            for (int i = 0; i < 20; i++)
                for (int j = 0; j < 20; j++) { double x = i * 0.05, y = j * 0.05; pts.Add(x); pts.Add(y); pts.Add(0.3 * x + 0.2 * y); }
            double nn = Math.Sqrt(0.09 + 0.04 + 1);
            using (var pc = new PointCloud(pts.ToArray()))
            {
                pc.EstimateNormals(SearchParam.Hybrid(0.2, 16));
                Check(pc.HasNormals, "has normals");
                var n = pc.Normals;
                Check(n.Length == pts.Count, "one per point");
                for (int i = 0; i < n.Length / 3; i++)
                {
                    double dot = (-0.3 * n[3 * i] - 0.2 * n[3 * i + 1] + n[3 * i + 2]) / nn;
                    Near(Math.Abs(dot), 1, 1e-6, "normal " + i);
                }
                pc.OrientNormalsToAlignWithDirection(new double[] { 0, 0, -1 });
                Check(pc.Normals[2] < 0, "oriented to -Z");
                pc.EstimateNormals(); // default KNN 30 keeps working
            }
        });

        Run("knn vs brute force", () =>
        {
            var pts = RandomPoints(500, 1);
            var queries = RandomPoints(20, 2);
            const int k = 5;
            using (var tree = new KDTreeFlann(pts))
            {
                Check(tree.Size == 500, "tree size");
                var res = tree.SearchKnn(queries, k);
                Check(res.NumQueries == 20 && res.Indices.Length == 20 * k, "counts");
                for (int q = 0; q < 20; q++)
                {
                    var d = Enumerable.Range(0, 500).Select(i =>
                    {
                        double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                        return new { i, d2 = dx * dx + dy * dy + dz * dz };
                    }).OrderBy(x => x.d2).Take(k).ToArray();
                    Check(res.Offsets[q] == q * k, "offset");
                    for (int j = 0; j < k; j++)
                    {
                        Check(res.Indices[q * k + j] == d[j].i, "index q" + q + " j" + j);
                        Near(res.Distances2[q * k + j], d[j].d2, 1e-12, "d2");
                    }
                }
                // float32 queries and the zero-copy view give the same neighbours
                var fq = queries.Select(x => (float)x).ToArray();
                using (var pc = new PointCloud(pts))
                using (var tree2 = new KDTreeFlann(pc))
                using (var raw = tree2.Search(fq, SearchParam.Knn(1)))
                {
                    long nq, total;
                    raw.GetCounts(out nq, out total);
                    Check(nq == 20 && total == 20, "raw counts");
                    IntPtr po, pi, pd;
                    raw.GetView(out po, out pi, out pd);
                    var idx = new int[20];
                    Marshal.Copy(pi, idx, 0, 20);
                    for (int q = 0; q < 20; q++) Check(idx[q] == res.Indices[q * k], "f32 nearest q" + q);
                }
                var rad = tree.SearchRadius(queries, 0.1);
                for (int q = 0; q < 20; q++)
                {
                    int expect = Enumerable.Range(0, 500).Count(i =>
                    {
                        double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                        return dx * dx + dy * dy + dz * dz <= 0.01;
                    });
                    Check(rad.Offsets[q + 1] - rad.Offsets[q] == expect, "radius count q" + q);
                }
            }
        });

        Run("ICP recovers a known transform", () =>
        {
            var src = RandomPoints(800, 3, 1.0, 2.0, 0.5);
            double a = 5 * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a);
            var T = new double[] { c, -s, 0, 0.05, s, c, 0, -0.03, 0, 0, 1, 0.02, 0, 0, 0, 1 };
            using (var source = new PointCloud(src))
            using (var target = new PointCloud(ApplyTransform(T, src)))
            {
                int calls = 0;
                var opts = new IcpOptions { MaxIteration = 100, RelativeFitness = 1e-10, RelativeRmse = 1e-10, Progress = f => { calls++; return true; } };
                Check(opts.Estimation == EstimationMethod.PointToPoint && !opts.WithScaling, "defaults");
                var r = Registration.RegistrationIcp(source, target, 0.3, null, opts);
                AllNear(r.Transformation, T, 1e-4, "transformation");
                Near(r.Fitness, 1, 1e-9, "fitness");
                Check(r.InlierRmse < 1e-4, "rmse " + r.InlierRmse);
                Check(r.CorrespondenceSet.Length == 2 * 800, "correspondences");
                Check(calls > 0, "progress called");
                var e = Registration.EvaluateRegistration(source, target, 0.01, T);
                Near(e.Fitness, 1, 1e-12, "evaluate fitness");
                var info = Registration.GetInformationMatrixFromPointClouds(source, target, 0.01, T);
                Check(info.Length == 36 && info[0] > 0, "information matrix");
                opts.Progress = f => false;
                ThrowsStatus(Status.Cancelled, () => Registration.RegistrationIcp(source, target, 0.3, null, opts), "cancel");
            }
        });

        Run("read/write file and memory round trip", () =>
        {
            var pts = RandomPoints(100, 4);
            var nrm = Enumerable.Range(0, 100).SelectMany(i => new double[] { 0, 0, 1 }).ToArray();
            string dir = TempDir();
            try
            {
                using (var pc = new PointCloud(pts))
                {
                    pc.Normals = nrm;
                    pc.PaintUniformColor(new double[] { 1, 0.5, 0 });
                    foreach (var fmt in new[] { "ply", "pcd", "xyz" })
                    {
                        string path = Path.Combine(dir, "c." + fmt);
                        IO.WritePointCloud(path, pc);
                        Check(File.Exists(path), fmt + " written");
                        using (var back = IO.ReadPointCloud(path))
                        {
                            Check(back.Size == 100, fmt + " size");
                            AllNear(back.Points, pts, 1e-5, fmt + " points");
                        }
                    }
                    using (var back = IO.ReadPointCloud(Path.Combine(dir, "c.ply")))
                    {
                        Check(back.HasNormals && back.HasColors, "ply keeps normals+colors");
                        AllNear(back.Normals, nrm, 1e-6, "ply normals");
                    }
                    foreach (var opt in new[] { new WriteOptions(), new WriteOptions { WriteAscii = true }, new WriteOptions { Compressed = true } })
                    {
                        byte[] bytes = IO.WritePointCloudToMemory(pc, "pcd", opt);
                        Check(bytes.Length > 100 * 3 * 4, "pcd bytes");
                        using (var back = IO.ReadPointCloudFromMemory(bytes, "pcd"))
                        {
                            Check(back.Size == 100, "memory size");
                            AllNear(back.Points, pts, 1e-5, "memory points");
                        }
                    }
                    using (var buf = IO.WritePointCloudToNativeBuffer(pc, "ply"))
                    {
                        long size;
                        IntPtr p = buf.View(out size);
                        var bytes = buf.ToArray();
                        Check(size == bytes.Length && size > 0, "buffer size");
                        var viewed = new byte[size];
                        Marshal.Copy(p, viewed, 0, (int)size);
                        Check(viewed.SequenceEqual(bytes), "buffer view == copy");
                        Check(System.Text.Encoding.ASCII.GetString(bytes, 0, 3) == "ply", "ply magic");
                    }
                }
            }
            finally { Directory.Delete(dir, true); }
        });

        Run("exceptions on bad input", () =>
        {
            using (var pc = new PointCloud(new double[] { 0, 0, 0, 1, 1, 1 }))
            {
                ThrowsStatus(Status.InvalidArgument, () => pc.VoxelDownSample(double.NaN), "NaN voxel size");
                ThrowsStatus(Status.InvalidArgument, () => pc.VoxelDownSample(-1), "negative voxel size");
                ThrowsStatus(Status.InvalidArgument, () => pc.SelectByIndex(new[] { 5 }), "index out of range");
                Check(Library.LastErrorMessage.Length > 0, "last error message kept");
                Check(Library.LastErrorCode == Status.InvalidArgument, "last error code");
                Library.ClearError();
                Check(Library.LastErrorCode == Status.Ok && Library.LastErrorMessage == "", "cleared");
            }
            ThrowsStatus(Status.IO, () => IO.ReadPointCloud("/nonexistent/dir/none.pcd"), "missing file");
            ThrowsStatus(Status.Parse, () => IO.ReadPointCloudFromMemory(System.Text.Encoding.ASCII.GetBytes("ply\nformat garbage\n"), "ply"), "malformed ply");
            ThrowsStatus(Status.Parse, () => IO.ReadPointCloudFromMemory(System.Text.Encoding.ASCII.GetBytes("# .PCD v0.7\nFIELDS x y\nPOINTS x\n"), "pcd"), "malformed pcd");
            Throws<ArgumentNullException>(() => IO.ReadPointCloudFromMemory(null, "ply"), "null bytes");
            Throws<O3dException>(() => Library.NumThreads = -1, "negative threads");
            var e = Throws<O3dException>(() => IO.ReadPointCloud("/nonexistent/x.pcd"), "message");
            Check(e.Message.Contains("O3D_ERROR_IO"), "message names the status: " + e.Message);
        });

        Run("disposed objects throw, Dispose is idempotent", () =>
        {
            var pc = new PointCloud(new double[] { 1, 2, 3 });
            var tree = new KDTreeFlann(pc);
            pc.Dispose();
            Check(pc.IsDisposed, "disposed");
            pc.Dispose(); // idempotent
            Throws<ObjectDisposedException>(() => { var n = pc.Size; }, "Size after Dispose");
            Throws<ObjectDisposedException>(() => pc.VoxelDownSample(0.1), "VoxelDownSample after Dispose");
            Check(tree.Size == 1, "tree outlives its cloud");
            tree.Dispose(); tree.Dispose();
            Throws<ObjectDisposedException>(() => tree.SearchKnn(new double[] { 0, 0, 0 }, 1), "search after Dispose");
            // finalizer safety net: forgotten clouds are collected without crashing
            for (int i = 0; i < 100; i++) new PointCloud(new double[] { i, i, i });
            GC.Collect(); GC.WaitForPendingFinalizers();
        });

        Run("library settings, log handler", () =>
        {
            int old = Library.NumThreads;
            Library.NumThreads = 2;
            Check(Library.NumThreads == 2, "threads");
            Library.NumThreads = 0;
            Check(Library.NumThreads >= 1, "default threads");
            var lv = Library.VerbosityLevel;
            Library.VerbosityLevel = LogLevel.Debug;
            Check(Library.VerbosityLevel == LogLevel.Debug, "verbosity");
            var lines = new List<string>();
            Library.SetLogHandler((level, msg) => { lock (lines) lines.Add(level + ": " + msg); });
            using (var pc = new PointCloud(RandomPoints(50, 5)))
            using (var d = pc.VoxelDownSample(0.2)) { }
            try { IO.ReadPointCloud("/nonexistent/none.ply"); } catch (O3dException) { }
            Library.SetLogHandler(null); // back to stderr
            Library.VerbosityLevel = lv;
            Console.WriteLine("  (log handler received " + lines.Count + " line(s))");
        });

        Run("remove statistical / radius outliers", () =>
        {
            var pts = GridWithOutliers();
            using (var pc = new PointCloud(pts))
            {
                using (var r = pc.RemoveStatisticalOutlier(8, 2.0))
                {
                    Check(r.Indices.SequenceEqual(Range(0, 100)), "statistical: kept indices " + string.Join(",", r.Indices));
                    Check(r.Cloud.Size == 100, "statistical: kept cloud size");
                    AllNear(r.Cloud.Points, pts.Take(300).ToArray(), 0, "statistical: kept points");
                }
                using (var r = pc.RemoveRadiusOutlier(3, 0.15))
                {
                    Check(r.Indices.SequenceEqual(Range(0, 100)), "radius: kept indices " + string.Join(",", r.Indices));
                    AllNear(r.Cloud.Points, pts.Take(300).ToArray(), 0, "radius: kept points");
                }
                // every grid point has at most 8 others within 0.15: nothing survives nb_points = 9
                using (var r = pc.RemoveRadiusOutlier(9, 0.15))
                {
                    Check(r.Indices.Length == 0 && r.Cloud.Size == 0, "radius: none kept");
                }
                Check(pc.Size == 102, "input untouched");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveStatisticalOutlier(0, 2.0), "nb_neighbors 0");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveStatisticalOutlier(8, -1), "negative std_ratio");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveRadiusOutlier(3, 0), "radius 0");
                ThrowsStatus(Status.InvalidArgument, () => pc.RemoveRadiusOutlier(0, 0.1), "nb_points 0");
            }
            using (var empty = new PointCloud())
                ThrowsStatus(Status.InvalidArgument, () => empty.RemoveStatisticalOutlier(8, 2.0), "empty cloud");
        });

        Run("crop to an axis-aligned box (inclusive, invert)", () =>
        {
            var pts = new double[] { 0, 0, 0,  1, 1, 1,  0.5, 0.5, 0.5,  2, 0, 0,  1, 1, 1.0001,  0.5, -1e-9, 0.5 };
            using (var pc = new PointCloud(pts))
            {
                pc.Colors = Enumerable.Range(0, 18).Select(i => i / 18.0).ToArray();
                double[] min = { 0, 0, 0 }, max = { 1, 1, 1 };
                using (var inside = pc.CropAabb(min, max))
                {
                    AllNear(inside.Points, new double[] { 0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5 }, 0, "inside (bounds inclusive)");
                    AllNear(inside.Colors, Enumerable.Range(0, 9).Select(i => i / 18.0).ToArray(), 0, "colors follow");
                }
                using (var outside = pc.CropAabb(min, max, invert: true))
                    AllNear(outside.Points, new double[] { 2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5 }, 0, "outside");
                ThrowsStatus(Status.InvalidArgument, () => pc.CropAabb(max, min), "min > max");
                ThrowsStatus(Status.InvalidArgument, () => pc.CropAabb(new double[] { 0, 0, double.NaN }, max), "NaN bound");
                Throws<ArgumentException>(() => pc.CropAabb(new double[] { 0, 0 }, max), "short bound");
                Throws<ArgumentNullException>(() => pc.CropAabb(null, max), "null bound");
            }
        });

        Run("segment_plane recovers a known plane", () =>
        {
            // z = 0.5 x + 0.2 y + 1  <=>  0.5 x + 0.2 y - z + 1 = 0; 400 inliers then 20 points >= 1.7 off it
            var p = new List<double>();
            for (int i = 0; i < 20; i++)
                for (int j = 0; j < 20; j++) { double x = i * 0.1, y = j * 0.1; p.Add(x); p.Add(y); p.Add(0.5 * x + 0.2 * y + 1); }
            for (int k = 0; k < 20; k++) { double x = (k % 5) * 0.4, y = (k / 5) * 0.5; p.Add(x); p.Add(y); p.Add(0.5 * x + 0.2 * y + 3 + 0.1 * k); }
            double norm = Math.Sqrt(0.25 + 0.04 + 1);
            var expected = new[] { 0.5 / norm, 0.2 / norm, -1 / norm, 1 / norm };
            using (var pc = new PointCloud(p.ToArray()))
            {
                var r = pc.SegmentPlane(0.01, 3, 1000, 0.99999999, 42);
                Check(r.Inliers.SequenceEqual(Range(0, 400)), "inliers " + r.Inliers.Length);
                Check(r.Plane.Length == 4, "plane length");
                double sign = r.Plane[2] < 0 ? 1 : -1; // normal up to sign
                AllNear(r.Plane.Select(v => v * sign).ToArray(), expected, 1e-9, "plane");
                var again = pc.SegmentPlane(0.01, 3, 1000, 0.99999999, 42);
                AllNear(again.Plane, r.Plane, 0, "same seed, same plane");
                Check(again.Inliers.SequenceEqual(r.Inliers), "same seed, same inliers");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(0.01, 2, 1000), "ransac_n 2");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(0.01, 3, 0), "0 iterations");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(-0.01, 3, 100), "negative threshold");
                ThrowsStatus(Status.InvalidArgument, () => pc.SegmentPlane(0.01, 3, 100, 1.5), "probability > 1");
            }
        });

        Run("cluster_dbscan on separated blobs", () =>
        {
            // blob at (10, 0, 0): 0..26, a lone noise point: 27, blob at the origin: 28..54
            var pts = Blob(10, 0, 0).Concat(new double[] { 5, 5, 5 }).Concat(Blob(0, 0, 0)).ToArray();
            using (var pc = new PointCloud(pts))
            {
                var labels = pc.ClusterDbscan(0.15, 3);
                Check(labels.Length == 55, "one label per point");
                for (int i = 0; i < 55; i++)
                    Check(labels[i] == (i < 27 ? 0 : i == 27 ? -1 : 1), "label[" + i + "] = " + labels[i]);
                Check(pc.ClusterDbscan(0.05, 1).SequenceEqual(Range(0, 55)), "eps below the spacing: singletons");
                ThrowsStatus(Status.InvalidArgument, () => pc.ClusterDbscan(0, 3), "eps 0");
                ThrowsStatus(Status.InvalidArgument, () => pc.ClusterDbscan(0.1, -1), "min_points < 0");
            }
        });

        Run("mean, covariance and Mahalanobis distance (analytic)", () =>
        {
            // (1, 2, 3) +- (1, 0, 0), (0, 2, 0), (0, 0, 3): mean (1, 2, 3), covariance diag(1/3, 4/3, 3)
            var pts = new double[] { 2, 2, 3, 0, 2, 3, 1, 4, 3, 1, 0, 3, 1, 2, 6, 1, 2, 0 };
            using (var pc = new PointCloud(pts))
            {
                var mc = pc.ComputeMeanAndCovariance();
                AllNear(mc.Mean, new double[] { 1, 2, 3 }, 1e-12, "mean");
                AllNear(mc.Covariance, new double[] { 1.0 / 3, 0, 0, 0, 4.0 / 3, 0, 0, 0, 3 }, 1e-12, "covariance");
                var d = pc.ComputeMahalanobisDistance();
                AllNear(d, Enumerable.Repeat(Math.Sqrt(3), 6).ToArray(), 1e-9, "mahalanobis");
            }
            using (var empty = new PointCloud())
            {
                ThrowsStatus(Status.InvalidArgument, () => empty.ComputeMeanAndCovariance(), "empty mean");
                ThrowsStatus(Status.InvalidArgument, () => empty.ComputeMahalanobisDistance(), "empty mahalanobis");
            }
        });

        Run("Figure 1 on cloud_bin_0.pcd", () =>
        {
            string input = DataFile("open3d/Feature/cloud_bin_0.pcd");
            string dir = TempDir();
            try
            {
                using (var pcd = IO.ReadPointCloud(input))
                {
                    Check(pcd.Size == 3903, "input size " + pcd.Size + " (the PCD header says 3903)");
                    using (var down = pcd.VoxelDownSample(0.05))
                    {
                        // 2655: Open3D 0.20.0 voxel_down_sample(0.05) on the same file.
                        Check(down.Size == 2655, "down size " + down.Size);
                        down.EstimateNormals(SearchParam.Hybrid(0.1, 30));
                        Check(down.HasNormals, "normals");
                        var n = down.Normals;
                        for (int i = 0; i < n.Length / 3; i++)
                            Near(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2], 1, 1e-6, "unit normal");
                        string outPath = Path.Combine(dir, "down.ply");
                        IO.WritePointCloud(outPath, down);
                        using (var back = IO.ReadPointCloud(outPath))
                        {
                            Check(back.Size == down.Size, "same count after re-read");
                            Check(back.HasNormals, "normals written");
                        }
                    }
                }
            }
            finally { Directory.Delete(dir, true); }
        });

        if (skipped > 0) Console.WriteLine("(" + skipped + " skipped)");
        Console.WriteLine(passed + " passed, " + failed + " failed");
        return failed == 0 ? 0 : 1;
    }
}
