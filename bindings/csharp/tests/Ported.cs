// SPDX-License-Identifier: MIT
// The rest of the C# suite (ported from the hand-written binding's Test.cs to the generated API): views,
// normals, radius search, file I/O, settings, point-cloud tools, meshes, images, cameras, RGB-D, shapes.
using System;
using System.Collections.Generic;
using System.IO;
using System.Linq;
using System.Runtime.InteropServices;
using O3d;

static partial class Test
{
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
    static double[] GridWithOutliers()
    {
        var p = new List<double>();
        for (int i = 0; i < 10; i++)
            for (int j = 0; j < 10; j++) { p.Add(i * 0.1); p.Add(j * 0.1); p.Add(0); }
        p.AddRange(new double[] { 5, 5, 5, -5, -5, 5 });
        return p.ToArray();
    }
    static IEnumerable<double> Blob(double cx, double cy, double cz)
    {
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                for (int k = 0; k < 3; k++) { yield return cx + i * 0.1; yield return cy + j * 0.1; yield return cz + k * 0.1; }
    }
    static T[] Copy<T>(View v, int n) where T : struct
    {
        var a = new T[n];
        if (a is double[]) Marshal.Copy(v.Data, a as double[], 0, n);
        else if (a is int[]) Marshal.Copy(v.Data, a as int[], 0, n);
        else if (a is long[]) Marshal.Copy(v.Data, a as long[], 0, n);
        else Marshal.Copy(v.Data, a as byte[], 0, n);
        return a;
    }
    static SearchParam Hybrid(double r, int k) { return Param(Library.SEARCH_HYBRID, k, r); }
    static SearchParam Knn(int k) { return Param(Library.SEARCH_KNN, k, 0); }
    static double[] F2D(float[] f) { return f.Select(x => (double)x).ToArray(); }

    static void PortedTests()
    {
        Run("views: point cloud arrays, zero copy, writable", () =>
        {
            using (var pc = new PointCloud(new double[] { 0.5, 1.25, -2, 3, 4, 5.5 }))
            {
                var v = pc.ArrayView(Library.POINTCLOUD_POINTS);
                Check(v.Rows == 2 && v.Bytes == 48 && v.Data != IntPtr.Zero, "view rows/bytes");
                AllNear(Copy<double>(v, 6), pc.Points, 0, "view contents");
                var mv = pc.ArrayMutableView(Library.POINTCLOUD_POINTS);
                Marshal.Copy(new double[] { 7, 8, 9 }, 0, mv.Data, 3);
                AllNear(pc.Points.Take(3).ToArray(), new double[] { 7, 8, 9 }, 0, "mutable view write");
                Check(pc.ArrayView(Library.POINTCLOUD_NORMALS).Rows == 0, "empty array: 0 rows");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.ArrayView(12345), "unknown which");
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
                pc.EstimateNormals(Hybrid(0.2, 16), 0);
                Check(pc.HasArray(Library.POINTCLOUD_NORMALS), "has normals");
                var n = pc.Normals;
                Check(n.Length == pts.Count, "one per point");
                for (int i = 0; i < n.Length / 3; i++)
                    Near(Math.Abs((-0.3 * n[3 * i] - 0.2 * n[3 * i + 1] + n[3 * i + 2]) / nn), 1, 1e-6, "normal " + i);
                pc.OrientNormalsToAlignWithDirection(new double[] { 0, 0, -1 });
                Check(pc.Normals[2] < 0, "oriented to -Z");
                pc.EstimateNormals(Knn(30), 0);
            }
        });

        Run("radius search and the search result view", () =>
        {
            var pts = RandomPoints(500, 1);
            var queries = RandomPoints(20, 2);
            using (var tree = KDTreeFlann.CreateFromPoints(pts))
            {
                using (var rad = tree.Search(queries, Param(Library.SEARCH_RADIUS, 0, 0.1), 0))
                {
                    var off = rad.GetOffsets();
                    for (int q = 0; q < 20; q++)
                    {
                        int expect = Enumerable.Range(0, 500).Count(i =>
                        {
                            double dx = pts[3 * i] - queries[3 * q], dy = pts[3 * i + 1] - queries[3 * q + 1], dz = pts[3 * i + 2] - queries[3 * q + 2];
                            return dx * dx + dy * dy + dz * dz <= 0.01;
                        });
                        Check(off[q + 1] - off[q] == expect, "radius count q" + q);
                    }
                }
                using (var one = Knn(1))
                using (var res = tree.Search(queries.Select(x => (float)x).ToArray(), one, 0))
                using (var counts = res.Counts())
                using (SearchResultView view = res.View())
                {
                    Check(counts.NumQueries() == 20 && counts.Total() == 20, "counts");
                    Check(view.Offsets().Rows == 21 && view.Indices().Rows == 20 && view.Distances2().Bytes == 160, "view rows");
                    Check(Copy<int>(view.Indices(), 20).SequenceEqual(res.GetIndices()), "indices view == copy");
                    Check(Copy<long>(view.Offsets(), 21).SequenceEqual(res.GetOffsets()), "offsets view == copy");
                    AllNear(Copy<double>(view.Distances2(), 20), res.GetDistances2(), 0, "distances view == copy");
                }
            }
        });

        Run("read/write file and memory round trip, buffer view", () =>
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
                        Library.IoWritePointCloud(path, pc, null, null);
                        Check(File.Exists(path), fmt + " written");
                        using (var back = Library.IoReadPointCloud(path, null, null))
                        {
                            Check(back.Size() == 100, fmt + " size");
                            AllNear(back.Points, pts, 1e-5, fmt + " points");
                        }
                    }
                    using (var back = Library.IoReadPointCloud(Path.Combine(dir, "c.ply"), null, null))
                    {
                        Check(back.HasArray(Library.POINTCLOUD_NORMALS) && back.HasArray(Library.POINTCLOUD_COLORS), "ply keeps normals+colors");
                        AllNear(back.Normals, nrm, 1e-6, "ply normals");
                    }
                    using (var w = new WriteOptions { Compressed = 1 })
                    using (var buf = Library.IoWritePointCloudToMemory(pc, "pcd", w))
                    using (var back = Library.IoReadPointCloudFromMemory(buf.GetData(), "pcd", null))
                        AllNear(back.Points, pts, 1e-5, "compressed pcd");
                    using (var buf = Library.IoWritePointCloudToMemory(pc, "ply", null))
                    {
                        var v = buf.View();
                        var bytes = buf.GetData();
                        Check(v.Bytes == bytes.Length && v.Rows == bytes.Length && bytes.Length > 0, "buffer size");
                        Check(Copy<byte>(v, bytes.Length).SequenceEqual(bytes), "buffer view == copy");
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
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.VoxelDownSample(-1), "negative voxel size");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SelectByIndex(new[] { 5 }, 0), "index out of range");
                Library.ClearError();
                Check(Library.LastErrorCode() == Library.OK && Library.LastErrorMessage() == "", "cleared");
            }
            ThrowsStatus(Library.ERROR_PARSE, () => Library.IoReadPointCloudFromMemory(System.Text.Encoding.ASCII.GetBytes("# .PCD v0.7\nFIELDS x y\nPOINTS x\n"), "pcd", null), "malformed pcd");
            Throws<O3dException>(() => Library.IoReadPointCloudFromMemory(null, "ply", null), "null bytes");
            var e = Throws<O3dException>(() => Library.IoReadPointCloud("/nonexistent/x.pcd", null, null), "message");
            Check(e.Message.Contains("O3D_ERROR_IO"), "message names the status: " + e.Message);
        });

        Run("IsDisposed; disposed objects throw; options finalized without Dispose", () =>
        {
            var pc = new PointCloud(new double[] { 1, 2, 3 });
            Check(!pc.IsDisposed, "alive");
            var tree = KDTreeFlann.CreateFromPointcloud(pc);
            pc.Dispose();
            Check(pc.IsDisposed, "disposed");
            tree.Dispose();
            Throws<ObjectDisposedException>(() => tree.Search(new double[] { 0, 0, 0 }, Knn(1), 0), "search after Dispose");
            var weak = new List<WeakReference>();
            for (int i = 0; i < 20; i++)
            {
                var o = new IcpOptions();
                o.SetProgress(f => o.MaxIteration > 0); // the callback captures its options object
                weak.Add(new WeakReference(o));
            }
            GC.Collect(); GC.WaitForPendingFinalizers(); GC.Collect();
            Check(weak.Count(w => w.IsAlive) < 20, "options with a self-capturing callback are collected");
        });

        Run("library settings", () =>
        {
            int old = Library.GetNumThreads();
            Library.SetNumThreads(2);
            Check(Library.GetNumThreads() == 2, "threads");
            Library.SetNumThreads(0);
            Check(Library.GetNumThreads() >= 1, "default threads");
            Library.SetNumThreads(old);
            int lv = Library.GetVerbosityLevel();
            Library.SetVerbosityLevel(Library.LOG_DEBUG);
            Check(Library.GetVerbosityLevel() == Library.LOG_DEBUG, "verbosity");
            Library.SetVerbosityLevel(lv);
        });

        Run("remove statistical / radius outliers", () =>
        {
            var pts = GridWithOutliers();
            using (var pc = new PointCloud(pts))
            {
                using (var r = pc.RemoveStatisticalOutlier(8, 2.0))
                using (var kept = r.Cloud())
                {
                    Check(r.Indices().SequenceEqual(Range(0, 100)), "statistical: kept indices");
                    AllNear(kept.Points, pts.Take(300).ToArray(), 0, "statistical: kept points");
                }
                using (var r = pc.RemoveRadiusOutlier(3, 0.15))
                using (var kept = r.Cloud())
                {
                    Check(r.Indices().SequenceEqual(Range(0, 100)), "radius: kept indices");
                    AllNear(kept.Points, pts.Take(300).ToArray(), 0, "radius: kept points");
                }
                using (var r = pc.RemoveRadiusOutlier(9, 0.15))
                using (var kept = r.Cloud()) Check(r.Indices().Length == 0 && kept.Size() == 0, "radius: none kept");
                Check(pc.Size() == 102, "input untouched");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.RemoveStatisticalOutlier(8, -1), "negative std_ratio");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.RemoveRadiusOutlier(3, 0), "radius 0");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.RemoveRadiusOutlier(0, 0.1), "nb_points 0");
            }
            using (var empty = new PointCloud())
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => empty.RemoveStatisticalOutlier(8, 2.0), "empty cloud");
        });

        Run("crop to an axis-aligned box (inclusive, invert)", () =>
        {
            var pts = new double[] { 0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5, 2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5 };
            using (var pc = new PointCloud(pts))
            {
                pc.Colors = Enumerable.Range(0, 18).Select(i => i / 18.0).ToArray();
                double[] min = { 0, 0, 0 }, max = { 1, 1, 1 };
                using (var inside = pc.CropAabb(min, max, 0))
                {
                    AllNear(inside.Points, new double[] { 0, 0, 0, 1, 1, 1, 0.5, 0.5, 0.5 }, 0, "inside (bounds inclusive)");
                    AllNear(inside.Colors, Enumerable.Range(0, 9).Select(i => i / 18.0).ToArray(), 0, "colors follow");
                }
                using (var outside = pc.CropAabb(min, max, 1))
                    AllNear(outside.Points, new double[] { 2, 0, 0, 1, 1, 1.0001, 0.5, -1e-9, 0.5 }, 0, "outside");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.CropAabb(max, min, 0), "min > max");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.CropAabb(new double[] { 0, 0, double.NaN }, max, 0), "NaN bound");
                Throws<O3dException>(() => pc.CropAabb(null, max, 0), "null bound");
            }
        });

        Run("segment_plane recovers a known plane", () =>
        {
            var p = new List<double>();
            for (int i = 0; i < 20; i++)
                for (int j = 0; j < 20; j++) { double x = i * 0.1, y = j * 0.1; p.Add(x); p.Add(y); p.Add(0.5 * x + 0.2 * y + 1); }
            for (int k = 0; k < 20; k++) { double x = (k % 5) * 0.4, y = (k / 5) * 0.5; p.Add(x); p.Add(y); p.Add(0.5 * x + 0.2 * y + 3 + 0.1 * k); }
            double norm = Math.Sqrt(0.25 + 0.04 + 1);
            var expected = new[] { 0.5 / norm, 0.2 / norm, -1 / norm, 1 / norm };
            using (var pc = new PointCloud(p.ToArray()))
            using (var r = pc.SegmentPlane(0.01, 3, 1000, 0.99999999, 42))
            using (var again = pc.SegmentPlane(0.01, 3, 1000, 0.99999999, 42))
            {
                Check(r.Indices().SequenceEqual(Range(0, 400)), "inliers");
                double sign = r.Plane()[2] < 0 ? 1 : -1;
                AllNear(r.Plane().Select(v => v * sign).ToArray(), expected, 1e-9, "plane");
                AllNear(again.Plane(), r.Plane(), 0, "same seed, same plane");
                Check(again.Indices().SequenceEqual(r.Indices()), "same seed, same inliers");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SegmentPlane(0.01, 2, 1000, 0.99, 0), "ransac_n 2");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SegmentPlane(0.01, 3, 0, 0.99, 0), "0 iterations");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SegmentPlane(-0.01, 3, 100, 0.99, 0), "negative threshold");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SegmentPlane(0.01, 3, 100, 1.5, 0), "probability > 1");
            }
        });

        Run("cluster_dbscan on separated blobs", () =>
        {
            var pts = Blob(10, 0, 0).Concat(new double[] { 5, 5, 5 }).Concat(Blob(0, 0, 0)).ToArray();
            using (var pc = new PointCloud(pts))
            {
                var labels = pc.ClusterDbscan(0.15, 3);
                Check(labels.Length == 55, "one label per point");
                for (int i = 0; i < 55; i++) Check(labels[i] == (i < 27 ? 0 : i == 27 ? -1 : 1), "label[" + i + "] = " + labels[i]);
                Check(pc.ClusterDbscan(0.05, 1).SequenceEqual(Range(0, 55)), "eps below the spacing: singletons");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.ClusterDbscan(0, 3), "eps 0");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.ClusterDbscan(0.1, -1), "min_points < 0");
            }
        });

        Run("mean, covariance and Mahalanobis distance (analytic)", () =>
        {
            var pts = new double[] { 2, 2, 3, 0, 2, 3, 1, 4, 3, 1, 0, 3, 1, 2, 6, 1, 2, 0 };
            using (var pc = new PointCloud(pts))
            using (var mc = pc.ComputeMeanAndCovariance())
            {
                AllNear(mc.Mean(), new double[] { 1, 2, 3 }, 1e-12, "mean");
                AllNear(mc.Covariance(), new double[] { 1.0 / 3, 0, 0, 0, 4.0 / 3, 0, 0, 0, 3 }, 1e-12, "covariance");
                AllNear(pc.ComputeMahalanobisDistance(), Enumerable.Repeat(Math.Sqrt(3), 6).ToArray(), 1e-9, "mahalanobis");
            }
            using (var empty = new PointCloud())
            {
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => empty.ComputeMeanAndCovariance(), "empty mean");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => empty.ComputeMahalanobisDistance(), "empty mahalanobis");
            }
        });

        Run("Figure 1 on cloud_bin_0.pcd", () =>
        {
            string input = DataFile("open3d/Feature/cloud_bin_0.pcd");
            string dir = TempDir();
            try
            {
                using (var pcd = Library.IoReadPointCloud(input, null, null))
                using (var down = pcd.VoxelDownSample(0.05))
                {
                    Check(pcd.Size() == 3903, "input size " + pcd.Size());
                    Check(down.Size() == 2655, "down size " + down.Size());
                    down.EstimateNormals(Hybrid(0.1, 30), 0);
                    var n = down.Normals;
                    for (int i = 0; i < n.Length / 3; i++)
                        Near(n[3 * i] * n[3 * i] + n[3 * i + 1] * n[3 * i + 1] + n[3 * i + 2] * n[3 * i + 2], 1, 1e-6, "unit normal");
                    string outPath = Path.Combine(dir, "down.ply");
                    Library.IoWritePointCloud(outPath, down, null, null);
                    using (var back = Library.IoReadPointCloud(outPath, null, null))
                        Check(back.Size() == down.Size() && back.HasArray(Library.POINTCLOUD_NORMALS), "re-read");
                }
            }
            finally { Directory.Delete(dir, true); }
        });

        MeshImageTests();   // PortedGeometry.cs
    }
}
