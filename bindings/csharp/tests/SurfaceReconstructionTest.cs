// SPDX-License-Identifier: MIT
// Surface reconstruction, tetra meshes, consistent normal orientation, duplicated points and ISS keypoints from
// C#, through the generated classes only: Poisson and ball pivoting rebuild a sampled sphere, the alpha shape of
// a convex sampling with a huge alpha is its convex hull, the Delaunay tetra mesh of a cube fills it, progress
// rises and cancels, and bad input throws O3dException.
using System;
using System.Collections.Generic;
using System.Linq;
using O3d;

static partial class Test
{
    // `n` points spread evenly over the sphere of `radius` about the origin (a Fibonacci lattice, spacing about
    // radius * sqrt(4 pi / n)), with outward unit normals.
    static PointCloud SphereCloud(int n, double radius)
    {
        double golden = Math.PI * (3 - Math.Sqrt(5));
        var p = new double[3 * n];
        var nrm = new double[3 * n];
        for (int i = 0; i < n; i++)
        {
            double z = 1 - (2.0 * i + 1) / n, r = Math.Sqrt(1 - z * z), phi = golden * i;
            nrm[3 * i] = r * Math.Cos(phi); nrm[3 * i + 1] = r * Math.Sin(phi); nrm[3 * i + 2] = z;
            for (int k = 0; k < 3; k++) p[3 * i + k] = radius * nrm[3 * i + k];
        }
        var pc = new PointCloud(p);
        pc.Normals = nrm;
        return pc;
    }

    static double Norm3(double[] a, int i) { return Math.Sqrt(a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1] + a[3 * i + 2] * a[3 * i + 2]); }

    // Sum of |det| / 6 over the tetras of `t`.
    static double TetraVolume(TetraMesh t)
    {
        double[] v = t.GetArray(Library.TETRAMESH_VERTICES);
        int[] q = t.GetIndexArray(Library.TETRAMESH_TETRAS);
        double total = 0;
        for (int i = 0; i < q.Length; i += 4)
        {
            var m = new double[9];
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) m[3 * r + c] = v[3 * q[i + r + 1] + c] - v[3 * q[i] + c];
            total += Math.Abs(Det3(m, 0)) / 6;
        }
        return total;
    }

    static double[] CubeCorners()
    {
        var p = new List<double>();
        for (int c = 0; c < 8; c++) { p.Add(c & 1); p.Add((c >> 1) & 1); p.Add((c >> 2) & 1); }
        return p.ToArray();
    }

    static void SurfaceReconstructionTests()
    {
        Run("poisson: a sphere with outward normals gives a closed sphere; progress rises and cancels", () =>
        {
            using (var pc = SphereCloud(2000, 2))
            using (var opts = new PoissonOptions())
            {
                Check(opts.Depth == 8 && opts.Scale == 1.1 && opts.LinearFit == 0 && opts.Width == 0, "defaults from o3d_poisson_options_init");
                opts.Depth = 6;
                double last = -1;
                bool rising = true;
                opts.SetProgress(f => { rising &= f >= last && f <= 1; last = f; return true; });
                using (var res = TriangleMesh.CreateFromPointCloudPoisson(pc, opts))
                using (var mesh = res.Mesh())
                using (var densities = res.Densities())
                {
                    Check(mesh.NumTriangles() > 100, "triangles: " + mesh.NumTriangles());
                    Check(densities.Dimension() == 1 && densities.Num() == mesh.NumVertices(), "one density per vertex");
                    Check(densities.GetArray(Library.FEATURE_DATA).All(x => !double.IsNaN(x) && !double.IsInfinity(x)), "finite densities");
                    var v = mesh.Vertices;
                    // Cells at depth 6 of a 4.4-wide cube are 0.07 wide: the vertices lie on the sphere to a fraction of that.
                    for (int i = 0; i < v.Length / 3; i++) Near(Norm3(v, i), 2, 0.05, "vertex " + i + " on the sphere");
                    Check(mesh.IsEdgeManifold(0) && mesh.EulerPoincareCharacteristic() == 2, "closed, a sphere's topology");
                    Near(mesh.GetVolume(), 4.0 / 3 * Math.PI * 8, 0.01 * 4.0 / 3 * Math.PI * 8, "volume");
                    // Open3D's trim: drop the vertices whose density is below a quantile.
                    var d = densities.GetArray(Library.FEATURE_DATA);
                    double cut = d.OrderBy(x => x).ElementAt(d.Length / 10);
                    var low = d.Select(x => x < cut ? (byte)1 : (byte)0).ToArray();
                    long before = mesh.NumVertices();
                    mesh.RemoveVerticesByMask(low);
                    Check(mesh.NumVertices() == before - low.Count(b => b == 1), "trimmed by density");
                }
                Check(last >= 0 && rising, "progress rises within [0, 1]");
                opts.SetProgress(f => false);
                ThrowsStatus(Library.ERROR_CANCELLED, () => TriangleMesh.CreateFromPointCloudPoisson(pc, opts), "cancel");
                opts.SetProgress(null);
                opts.Depth = 17;
                Invalid(() => TriangleMesh.CreateFromPointCloudPoisson(pc, opts), "depth 17");
            }
            using (var bare = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 }))
                Invalid(() => TriangleMesh.CreateFromPointCloudPoisson(bare, null), "no normals");
            Invalid(() => TriangleMesh.CreateFromPointCloudPoisson(null, null), "null cloud");
        });

        Run("ball pivoting: a dense sphere's area on its own points; progress cancels", () =>
        {
            // 4000 points on the unit sphere are about 0.056 apart: balls of twice and three times that close it.
            using (var pc = SphereCloud(4000, 1))
            {
                using (var mesh = TriangleMesh.CreateFromPointCloudBallPivoting(pc, new[] { 0.1, 0.15 }, null))
                {
                    Check(mesh.Vertices.SequenceEqual(pc.Points), "the vertices are the points");
                    Check(mesh.IsEdgeManifold(0) && mesh.EulerPoincareCharacteristic() == 2, "closed: " + mesh.NumTriangles());
                    Near(mesh.GetSurfaceArea(), 4 * Math.PI, 0.01 * 4 * Math.PI, "area");
                }
                using (var opts = new ProgressOptions())
                {
                    Check(opts.NumThreads == 0, "defaults from o3d_progress_options_init");
                    int calls = 0;
                    opts.SetProgress(f => { calls++; return true; });
                    using (var mesh = TriangleMesh.CreateFromPointCloudBallPivoting(pc, new[] { 0.1, 0.15 }, opts))
                        Check(mesh.NumTriangles() > 7000 && calls > 0, "with a callback: " + calls + " calls");
                    opts.SetProgress(f => false);
                    ThrowsStatus(Library.ERROR_CANCELLED, () => TriangleMesh.CreateFromPointCloudBallPivoting(pc, new[] { 0.1 }, opts), "cancel");
                }
                Invalid(() => TriangleMesh.CreateFromPointCloudBallPivoting(pc, new double[0], null), "no radius");
                Invalid(() => TriangleMesh.CreateFromPointCloudBallPivoting(pc, new[] { 0.1, -0.2 }, null), "negative radius");
            }
        });

        Run("alpha shape: a huge alpha gives the convex hull; a tetra mesh is reused", () =>
        {
            // Random points in a cube: in general position, so the hull's faces are triangles.
            using (var pc = new PointCloud(RandomPoints(400, 5)))
            using (var hull = pc.ComputeConvexHull(0))
            using (var hullMesh = hull.Mesh())
            using (var shape = TriangleMesh.CreateFromPointCloudAlphaShape(pc, 1e6, null, null, null))
            {
                Check(shape.NumTriangles() == hullMesh.NumTriangles(), "hull triangles: " + shape.NumTriangles() + " vs " + hullMesh.NumTriangles());
                // The alpha is beyond every circumradius: even the flat slivers on the hull (four nearly coplanar
                // points; here two have radii over 1e3) are in, so the shape is the whole Delaunay volume.
                Near(shape.GetSurfaceArea(), hullMesh.GetSurfaceArea(), 1e-9, "hull area");
                Near(shape.GetVolume(), hullMesh.GetVolume(), 1e-9, "hull volume");
                using (var tetra = TetraMesh.CreateFromPointCloud(pc))
                using (var t = tetra.Value())
                {
                    int[] map = tetra.PointMap();
                    foreach (var alpha in new[] { 0.3, 1e6 })
                        using (var fresh = TriangleMesh.CreateFromPointCloudAlphaShape(pc, alpha, null, null, null))
                        using (var reused = TriangleMesh.CreateFromPointCloudAlphaShape(pc, alpha, t, map, null))
                            Check(fresh.NumTriangles() == reused.NumTriangles() && Math.Abs(fresh.GetSurfaceArea() - reused.GetSurfaceArea()) < 1e-9,
                                  "same shape with the tetra mesh, alpha " + alpha);
                    Invalid(() => TriangleMesh.CreateFromPointCloudAlphaShape(pc, 1, t, map.Take(map.Length - 1).ToArray(), null), "short point map");
                }
                using (var none = TriangleMesh.CreateFromPointCloudAlphaShape(pc, 1e-4, null, null, null))
                    Check(none.NumTriangles() == 0, "no tetra is that small");
                using (var opts = new ProgressOptions())
                {
                    opts.SetProgress(f => false);
                    ThrowsStatus(Library.ERROR_CANCELLED, () => TriangleMesh.CreateFromPointCloudAlphaShape(pc, 0.5, null, null, opts), "cancel");
                }
                Invalid(() => TriangleMesh.CreateFromPointCloudAlphaShape(pc, 0, null, null, null), "alpha 0");
                Invalid(() => TriangleMesh.CreateFromPointCloudAlphaShape(pc, -1, null, null, null), "negative alpha");
            }
        });

        Run("tetra mesh: Delaunay of a cube fills it; a linear field's iso-surface is a plane", () =>
        {
            var corners = CubeCorners();
            using (var pc = new PointCloud(corners))
            using (var res = TetraMesh.CreateFromPointCloud(pc))
            using (var t = res.Value())
            {
                Check(t.NumVertices() == 8 && t.NumTetras() >= 5 && t.NumTetras() <= 6, "8 vertices, 5 or 6 tetras: " + t.NumTetras());
                Near(TetraVolume(t), 1, 1e-12, "volume");
                int[] map = res.PointMap();
                Check(map.OrderBy(i => i).SequenceEqual(Range(0, 8)), "the point map is a permutation");
                double[] v = t.GetArray(Library.TETRAMESH_VERTICES);
                for (int i = 0; i < 8; i++)
                    for (int k = 0; k < 3; k++) Check(v[3 * i + k] == corners[3 * map[i] + k], "vertex " + i + " is point " + map[i]);
                // z = 0.5 cuts the cube in the unit square.
                var z = Enumerable.Range(0, 8).Select(i => v[3 * i + 2]).ToArray();
                using (var square = t.ExtractTriangleMesh(z, 0.5))
                {
                    Near(square.GetSurfaceArea(), 1, 1e-9, "section area");
                    var sv = square.Vertices;
                    for (int i = 0; i < sv.Length / 3; i++) Near(sv[3 * i + 2], 0.5, 1e-12, "on the plane");
                }
                Invalid(() => t.ExtractTriangleMesh(new double[7], 0.5), "7 values for 8 vertices");
                using (var copy = t.Clone())
                {
                    copy.SetIndexArray(Library.TETRAMESH_TETRAS, new[] { 0, 1, 2, 8 });
                    Check(copy.NumTetras() == 1 && t.NumTetras() >= 5, "clone is deep");
                    Invalid(() => copy.ExtractTriangleMesh(z, 0.5), "tetra index out of range");
                }
            }
            using (var t = new TetraMesh())
            {
                t.SetArray(Library.TETRAMESH_VERTICES, new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 });
                t.SetIndexArray(Library.TETRAMESH_TETRAS, new[] { 0, 1, 2, 3 });
                var shape = t.ArrayShape(Library.TETRAMESH_TETRAS);
                Check(shape.Rows() == 1 && shape.Cols() == 4, "tetras are rows of 4");
                Near(TetraVolume(t), 1.0 / 6, 1e-15, "unit tetra");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => t.SetIndexArray(Library.TETRAMESH_TETRAS, new[] { 0, 1, 2 }), "not whole rows");
            }
            using (var flat = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.3, 0.6, 0 }))
                Invalid(() => TetraMesh.CreateFromPointCloud(flat), "coplanar points");
        });

        Run("point cloud: consistent tangent-plane normals, duplicated points, ISS keypoints", () =>
        {
            using (var pc = SphereCloud(1000, 1))
            {
                var n = pc.Normals;
                var rng = new Random(3);
                for (int i = 0; i < n.Length / 3; i++)
                    if (rng.Next(2) == 1) for (int k = 0; k < 3; k++) n[3 * i + k] = -n[3 * i + k];
                pc.Normals = n;
                pc.OrientNormalsConsistentTangentPlane(10, 0, 1);
                var p = pc.Points;
                var got = pc.Normals;
                Func<int, double> dot = i => got[3 * i] * p[3 * i] + got[3 * i + 1] * p[3 * i + 1] + got[3 * i + 2] * p[3 * i + 2];
                double sign = dot(0);
                for (int i = 0; i < got.Length / 3; i++) Near(dot(i) * sign, 1, 1e-12, "normal " + i + " agrees");
                Invalid(() => pc.OrientNormalsConsistentTangentPlane(0, 0, 1), "k = 0");
            }
            using (var bare = new PointCloud(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0 }))
                Invalid(() => bare.OrientNormalsConsistentTangentPlane(5, 0, 1), "no normals");

            using (var dup = new PointCloud(new double[] { 0, 0, 0, 1, 2, 3, 0, 0, 0, 4, 5, 6, 1, 2, 3 }))
            {
                dup.Colors = new double[] { 0, 0, 0, 0.1, 0, 0, 0.2, 0, 0, 0.3, 0, 0, 0.4, 0, 0 };
                dup.RemoveDuplicatedPoints();
                Check(dup.Points.SequenceEqual(new double[] { 0, 0, 0, 1, 2, 3, 4, 5, 6 }), "first of each kept, in order");
                Check(dup.Colors.SequenceEqual(new double[] { 0, 0, 0, 0.1, 0, 0, 0.3, 0, 0 }), "colors follow");
            }

            // The surface of the unit cube on a grid of 21 points a side: keypoints only at the corners.
            var box = new List<double>();
            for (int i = 0; i <= 20; i++)
                for (int j = 0; j <= 20; j++)
                    for (int k = 0; k <= 20; k++)
                        if (i == 0 || i == 20 || j == 0 || j == 20 || k == 0 || k == 20) box.AddRange(new[] { i / 20.0, j / 20.0, k / 20.0 });
            var pts = box.ToArray();
            using (var pc = new PointCloud(pts))
            using (var opts = new IssOptions { SalientRadius = 0.2, NonMaxRadius = 0.6 })
            {
                using (var defaults = new IssOptions())
                    Check(defaults.SalientRadius == 0 && defaults.NonMaxRadius == 0 && defaults.Gamma21 == 0.975 &&
                          defaults.Gamma32 == 0.975 && defaults.MinNeighbors == 5, "defaults from o3d_iss_options_init");
                using (var res = pc.ComputeIssKeypoints(opts))
                using (var kp = res.Cloud())
                {
                    int[] idx = res.Indices();
                    double[] k = kp.Points;
                    Check(idx.Length > 0 && idx.Length == kp.Size(), "keypoints: " + idx.Length);
                    var corners = new HashSet<int>();
                    for (int i = 0; i < idx.Length; i++)
                    {
                        double d2 = 0;
                        for (int c = 0; c < 3; c++)
                        {
                            Check(k[3 * i + c] == pts[3 * idx[i] + c], "index names the point");
                            double m = Math.Min(k[3 * i + c], 1 - k[3 * i + c]);
                            d2 += m * m;
                        }
                        Check(Math.Sqrt(d2) < 0.2, "keypoint " + i + " near a corner");
                        corners.Add((k[3 * i] > 0.5 ? 1 : 0) + (k[3 * i + 1] > 0.5 ? 2 : 0) + (k[3 * i + 2] > 0.5 ? 4 : 0));
                    }
                    Check(corners.Count == 8, "every corner has one: " + corners.Count);
                }
                opts.SalientRadius = -1;
                Invalid(() => pc.ComputeIssKeypoints(opts), "negative radius");
            }
        });
    }
}
