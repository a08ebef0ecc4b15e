// SPDX-License-Identifier: MIT
// Assert-based tests of the generated O3d C# binding. Prints "N passed, M failed" last; exit code 1 on failure.
//   mcs -target:exe -out:Test.exe -r:O3d.dll *.cs && mono Test.exe
// Data: $O3D_TEST_DATA (else $O3D_TEST_DATA_DEFAULT, else ../shared/data); tests needing it are skipped
// when it is missing, unless O3D_REQUIRE_TEST_DATA=1 (then they fail).
using System;
using System.Collections.Generic;
using System.Linq;
using O3d;

static partial class Test
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
    static void ThrowsStatus(int s, Action a, string what)
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
    static PointCloud Cloud(double[] pts)
    {
        var pc = new PointCloud();
        pc.SetArray(Library.POINTCLOUD_POINTS, pts);
        return pc;
    }
    static SearchParam Param(int kind, int knn, double radius)
    {
        return new SearchParam { Kind = kind, Knn = knn, Radius = radius };
    }
    static int[] Range(int start, int count) { return Enumerable.Range(start, count).ToArray(); }

    static int Main()
    {
        Run("version and status strings", () =>
        {
            Check(Library.VersionMajor() == Library.VERSION_MAJOR, "major");
            Check(Library.Version() == Library.VersionMajor() + "." + Library.VersionMinor() + "." + Library.VersionPatch(), "version string");
            Check(Library.StatusString(Library.ERROR_IO) == "O3D_ERROR_IO", "status string");
        });

        Run("points round trip float64 and float32, one array family", () =>
        {
            var pts = new double[] { 1, 2, 3, 4.5, -5.25, 6, 1e-3, 7, -8 };
            using (var pc = new PointCloud())
            {
                Check(pc.Size() == 0 && !pc.HasArray(Library.POINTCLOUD_POINTS), "empty");
                pc.SetArray(Library.POINTCLOUD_POINTS, pts);
                Check(pc.Size() == 3 && !pc.HasArray(Library.POINTCLOUD_NORMALS), "size 3");
                AllNear(pc.GetArray(Library.POINTCLOUD_POINTS), pts, 0, "f64");
                pts[0] = 99; // the cloud holds a copy
                Near(pc.GetArray(Library.POINTCLOUD_POINTS)[0], 1, 0, "copy in");
                var f = new float[] { 0.5f, 1.25f, -2f, 3f, 4f, 5.5f };
                pc.SetArray(Library.POINTCLOUD_POINTS, f);
                Check(pc.Size() == 2, "f32 size");
                AllNear(pc.GetArray(Library.POINTCLOUD_POINTS), f.Select(x => (double)x).ToArray(), 0, "f32");
                pc.SetArray(Library.POINTCLOUD_COLORS, new float[] { 1, 0, 0, 0, 0.5f, 1 });
                AllNear(pc.GetArray(Library.POINTCLOUD_COLORS), new double[] { 1, 0, 0, 0, 0.5, 1 }, 0, "colors");
                var shape = pc.ArrayShape(Library.POINTCLOUD_POINTS);
                Check(shape.Rows() == 2 && shape.Cols() == 3, "shape");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SetArray(Library.POINTCLOUD_POINTS, new double[4]), "length not multiple of 3");
                using (var c = pc.Clone())
                {
                    pc.Clear();
                    Check(pc.Size() == 0 && c.Size() == 2, "clone is deep");
                }
            }
        });

        Run("voxel_down_sample averages", () =>
        {
            var pts = new double[] { 0, 0, 0, 0.1, 0, 0, 0, 0.1, 0.2, 5, 5, 5, 5.2, 5, 5 };
            using (var pc = Cloud(pts))
            using (var down = pc.VoxelDownSample(1.0))
            {
                Check(down.Size() == 2, "2 voxels, got " + down.Size());
                var d = down.GetArray(Library.POINTCLOUD_POINTS);
                int a = d[0] < d[3] ? 0 : 1, b = 1 - a;
                AllNear(d.Skip(3 * a).Take(3).ToArray(), new double[] { 0.1 / 3, 0.1 / 3, 0.2 / 3 }, 1e-12, "cluster A mean");
                AllNear(d.Skip(3 * b).Take(3).ToArray(), new double[] { 5.1, 5, 5 }, 1e-12, "cluster B mean");
                Check(pc.Size() == 5, "input untouched");
            }
        });

        Run("knn vs brute force, search results copied out", () =>
        {
            var pts = RandomPoints(500, 1);
            var queries = RandomPoints(20, 2);
            const int k = 5;
            using (var tree = KDTreeFlann.CreateFromPoints(pts))
            using (var p = Param(Library.SEARCH_KNN, k, 0))
            using (var res = tree.Search(queries, p, 0))
            {
                Check(tree.Size() == 500, "tree size");
                var idx = res.GetIndices();
                var d2 = res.GetDistances2();
                var off = res.GetOffsets();
                Check(idx.Length == 20 * k && off.Length == 21, "counts");
                for (int q = 0; q < 20; q++)
                {
                    var d = Enumerable.Range(0, 500).Select(i =>
                    {
                        double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                        return new { i, d2 = dx * dx + dy * dy + dz * dz };
                    }).OrderBy(x => x.d2).Take(k).ToArray();
                    Check(off[q] == q * k, "offset");
                    for (int j = 0; j < k; j++)
                    {
                        Check(idx[q * k + j] == d[j].i, "index q" + q + " j" + j);
                        Near(d2[q * k + j], d[j].d2, 1e-12, "d2");
                    }
                }
                using (var one = Param(Library.SEARCH_KNN, 1, 0))
                using (var r32 = tree.Search(queries.Select(x => (float)x).ToArray(), one, 0))
                {
                    var i32 = r32.GetIndices();
                    for (int q = 0; q < 20; q++) Check(i32[q] == idx[q * k], "f32 nearest q" + q);
                }
            }
        });

        Run("ICP recovers a known transform; progress callback cancels", () =>
        {
            var src = RandomPoints(800, 3, 1.0, 2.0, 0.5);
            double a = 5 * Math.PI / 180, c = Math.Cos(a), s = Math.Sin(a);
            var T = new double[] { c, -s, 0, 0.05, s, c, 0, -0.03, 0, 0, 1, 0.02, 0, 0, 0, 1 };
            using (var source = Cloud(src))
            using (var target = Cloud(ApplyTransform(T, src)))
            using (var opts = new IcpOptions { MaxIteration = 100, RelativeFitness = 1e-10, RelativeRmse = 1e-10 })
            {
                int calls = 0;
                Check(opts.Estimation == Library.ESTIMATION_POINT_TO_POINT && opts.WithScaling == 0, "defaults from o3d_icp_options_init");
                opts.SetProgress(f => { calls++; return true; });
                using (var r = Library.RegisterIcp(source, target, 0.3, null, opts))
                {
                    AllNear(r.GetTransformation(), T, 1e-4, "transformation");
                    Near(r.GetFitness(), 1, 1e-9, "fitness");
                    Check(r.GetInlierRmse() < 1e-4, "rmse");
                    Check(r.GetCorrespondenceSet().Length == 2 * 800, "correspondences");
                }
                Check(calls > 0, "progress called");
                using (var e = Library.EvaluateRegistration(source, target, 0.01, T)) Near(e.GetFitness(), 1, 1e-12, "evaluate fitness");
                var info = Library.GetInformationMatrixFromPointClouds(source, target, 0.01, T);
                Check(info.Length == 36 && info[0] > 0, "information matrix");
                opts.SetProgress(f => false);
                ThrowsStatus(Library.ERROR_CANCELLED, () => Library.RegisterIcp(source, target, 0.3, null, opts), "cancel");
                opts.SetProgress(f => { throw new InvalidOperationException("boom"); });
                ThrowsStatus(Library.ERROR_CANCELLED, () => Library.RegisterIcp(source, target, 0.3, null, opts), "throwing callback cancels");
                opts.SetProgress(null);
                using (var r = Library.RegisterIcp(source, target, 0.3, null, opts)) Near(r.GetFitness(), 1, 1e-9, "no callback");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => Library.RegisterIcp(source, target, 0.3, new double[15], opts), "init of 15");
            }
        });

        Run("memory round trip and exceptions on bad input", () =>
        {
            var pts = RandomPoints(100, 4);
            using (var pc = Cloud(pts))
            using (var w = new WriteOptions())
            {
                foreach (var opt in new[] { 0, 1 })
                {
                    w.WriteAscii = opt;
                    using (var buf = Library.IoWritePointCloudToMemory(pc, "pcd", w))
                    {
                        byte[] bytes = buf.GetData();
                        Check(bytes.Length > 100 * 3 * 4, "pcd bytes");
                        using (var back = Library.IoReadPointCloudFromMemory(bytes, "pcd", null))
                            AllNear(back.GetArray(Library.POINTCLOUD_POINTS), pts, 1e-5, "memory points");
                    }
                }
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.VoxelDownSample(double.NaN), "NaN voxel size");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SelectByIndex(new[] { 500 }, 0), "index out of range");
                Check(Library.LastErrorMessage().Length > 0 && Library.LastErrorCode() == Library.ERROR_INVALID_ARGUMENT, "last error");
                Library.ClearError();
                Check(Library.LastErrorCode() == Library.OK, "cleared");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.CropAabb(new double[] { 0, 0 }, new double[] { 1, 1, 1 }, 0), "short bound");
            }
            ThrowsStatus(Library.ERROR_IO, () => Library.IoReadPointCloud("/nonexistent/dir/none.pcd", null, null), "missing file");
            ThrowsStatus(Library.ERROR_PARSE, () => Library.IoReadPointCloudFromMemory(System.Text.Encoding.ASCII.GetBytes("ply\nformat garbage\n"), "ply", null), "malformed ply");
            Throws<O3dException>(() => Library.SetNumThreads(-1), "negative threads");
        });

        Run("Dispose is idempotent, a disposed object throws", () =>
        {
            var pc = Cloud(new double[] { 1, 2, 3 });
            var tree = KDTreeFlann.CreateFromPointcloud(pc);
            pc.Dispose();
            pc.Dispose();
            Throws<ObjectDisposedException>(() => pc.Size(), "Size after Dispose");
            Throws<ObjectDisposedException>(() => pc.VoxelDownSample(0.1), "VoxelDownSample after Dispose");
            Check(tree.Size() == 1, "tree outlives its cloud");
            tree.Dispose(); tree.Dispose();
            for (int i = 0; i < 100; i++) Cloud(new double[] { i, i, i }); // finalizers free forgotten clouds
            GC.Collect(); GC.WaitForPendingFinalizers();
        });

        Run("outliers, segment_plane, dbscan (results with several outputs)", () =>
        {
            var p = new List<double>();
            for (int i = 0; i < 10; i++) for (int j = 0; j < 10; j++) { p.Add(i * 0.1); p.Add(j * 0.1); p.Add(0); }
            p.AddRange(new double[] { 5, 5, 5, -5, -5, 5 });
            using (var pc = Cloud(p.ToArray()))
            {
                using (var r = pc.RemoveStatisticalOutlier(8, 2.0))
                {
                    Check(r.Indices().SequenceEqual(Range(0, 100)), "statistical: kept indices");
                    using (var kept = r.Cloud()) Check(kept.Size() == 100, "kept cloud");
                    ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => r.Cloud(), "cloud taken twice");
                }
                using (var r = pc.RemoveRadiusOutlier(9, 0.15)) Check(r.Indices().Length == 0, "radius: none kept");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.RemoveStatisticalOutlier(0, 2.0), "nb_neighbors 0");
                using (var sp = pc.SegmentPlane(0.01, 3, 1000, 0.99999999, 42))
                {
                    Check(sp.Indices().SequenceEqual(Range(0, 100)), "plane inliers");
                    Near(Math.Abs(sp.Plane()[2]), 1, 1e-9, "plane z = 0");
                }
                var labels = pc.ClusterDbscan(0.15, 3);
                Check(labels.Length == 102 && labels.Take(100).All(l => l == 0) && labels[100] == -1 && labels[101] == -1, "dbscan labels");
            }
        });

        Run("meshes, value structs filled by *_init", () =>
        {
            using (var box = TriangleMesh.CreateBox(1, 1, 1))
            {
                Check(box.NumVertices() == 8 && box.NumTriangles() == 12, "box counts");
                Near(box.GetSurfaceArea(), 6, 1e-12, "area");
                Near(box.GetVolume(), 1, 1e-12, "volume");
                Check(box.IsWatertight() && box.IsOrientable(), "closed manifold");
                Check(box.EulerPoincareCharacteristic() == 2, "Euler characteristic");
                Check(box.GetIndexArray(Library.MESH_TRIANGLES).All(t => t >= 0 && t < 8), "triangle indices");
                using (var obb = box.GetOrientedBoundingBox(0))
                    AllNear(obb.GetCenter(), new double[] { 0.5, 0.5, 0.5 }, 1e-9, "obb center");
            }
            using (var edge = new PoseGraphEdge())
            {
                Near(edge.Confidence, 1, 0, "edge default confidence from o3d_pose_graph_edge_init");
                edge.SetTransformation(Enumerable.Range(0, 16).Select(i => (double)i).ToArray());
                Check(edge.GetTransformation()[15] == 15, "fixed array field round trip");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => edge.SetTransformation(new double[3]), "fixed array length");
            }
        });

        Run("log handler", () =>
        {
            var lines = new List<string>();
            int old = Library.GetVerbosityLevel();
            Library.SetVerbosityLevel(Library.LOG_DEBUG);
            Library.SetLogHandler((level, msg) => { lock (lines) lines.Add(level + ": " + msg); });
            try { Library.IoReadPointCloud("/nonexistent/none.ply", null, null); } catch (O3dException) { }
            Library.SetLogHandler(null);
            Library.SetVerbosityLevel(old);
            Console.WriteLine("  (log handler received " + lines.Count + " line(s))");
        });

        PortedTests(); // Ported.cs
        RegistrationPipelineTests(); // RegistrationPipelineTest.cs
        CameraRgbdTests(); // CameraRgbdTest.cs
        VisualizationTests(); // VisualizationTest.cs
        VisualizerTests(); // VisualizerTest.cs
        SelectionTests(); // SelectionTest.cs
        OdometryTests(); // OdometryTest.cs
        IntegrationTests(); // IntegrationTest.cs
        ColorMapTests(); // ColorMapTest.cs
        ReconstructionTests(); // ReconstructionTest.cs
        SurfaceReconstructionTests(); // SurfaceReconstructionTest.cs
        GeometryAlgorithmsTests(); // GeometryAlgorithmsTest.cs
        if (skipped > 0) Console.WriteLine("(" + skipped + " skipped)");
        Console.WriteLine(passed + " passed, " + failed + " failed");
        return failed == 0 ? 0 : 1;
    }
}
