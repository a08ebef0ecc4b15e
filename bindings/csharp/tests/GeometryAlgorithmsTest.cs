// SPDX-License-Identifier: MIT
// The geometry algorithms of issue 22's second half from C#, through the generated classes only: mesh analysis
// (adjacency, non-manifold elements, intersections, orientation, sharpening, ARAP), bounding volumes (minimal box,
// ellipsoid, their meshes), point-cloud smoothing, static covariances, planar patches, traced down-sampling and
// half-edge meshes, each against an analytic answer, with bad input throwing O3dException.
using System;
using System.Linq;
using O3d;

static partial class Test
{
    static TriangleMesh MeshOf(double[] v, int[] t)
    {
        var m = new TriangleMesh();
        m.SetArray(Library.MESH_VERTICES, v);
        m.SetIndexArray(Library.MESH_TRIANGLES, t);
        return m;
    }

    static int[][] ListsOf(IndexLists lists)
    {
        long[] off = lists.GetOffsets();
        int[] val = lists.GetValues();
        return Enumerable.Range(0, off.Length - 1)
            .Select(i => val.Skip((int)off[i]).Take((int)(off[i + 1] - off[i])).ToArray()).ToArray();
    }

    static void GeometryAlgorithmsTests()
    {
        Run("geometry: adjacency list, non-manifold edges and vertices of small meshes", () =>
        {
            using (var strip = MeshOf(new double[15], new[] { 0, 1, 2, 2, 1, 3 }))
            using (var adj = strip.ComputeAdjacencyList())
            {
                var lists = ListsOf(adj);
                Check(lists.Length == 5 && lists[1].SequenceEqual(new[] { 0, 2, 3 }) && lists[4].Length == 0, "strip adjacency");
            }
            using (var fin = MeshOf(new double[15], new[] { 0, 1, 2, 1, 0, 3, 0, 1, 4 }))
            {
                Check(fin.GetNonManifoldEdges(1).SequenceEqual(new[] { 0, 1 }), "edge (0,1) has three triangles");
                Check(fin.GetNonManifoldEdges(0).Length == 2 * 7, "plus six boundary edges");
                Check(!fin.OrientTriangles(), "an edge of three triangles cannot be oriented");
            }
            using (var bowtie = MeshOf(new double[15], new[] { 0, 1, 2, 0, 3, 4 }))
                Check(bowtie.GetNonManifoldVertices().SequenceEqual(new[] { 0 }), "the bow tie's shared vertex");
        });

        Run("geometry: intersections, orientation, sharpening and the ellipsoid primitive", () =>
        {
            using (var a = TriangleMesh.CreateSphere(1.0, 10))
            using (var b = TriangleMesh.CreateSphere(1.0, 10))
            using (var far = TriangleMesh.CreateSphere(1.0, 10))
            {
                b.Translate(new[] { 1.5, 0, 0 }, 1);
                far.Translate(new[] { 2.5, 0, 0 }, 1);
                Check(a.IsIntersecting(b) && !a.IsIntersecting(far), "overlapping spheres intersect, distant ones do not");
                Check(a.GetSelfIntersectingTriangles().Length == 0, "a sphere does not self-intersect");
            }
            using (var box = TriangleMesh.CreateBox(1, 2, 3))
            {
                int[] t = box.GetIndexArray(Library.MESH_TRIANGLES);
                for (int i = 0; i < t.Length; i += 9) { int x = t[i + 1]; t[i + 1] = t[i + 2]; t[i + 2] = x; }
                box.SetIndexArray(Library.MESH_TRIANGLES, t);
                Check(box.OrientTriangles(), "a box with flipped triangles is orientable");
                Near(box.GetVolume(), 6, 1e-12, "volume after orienting");
                using (var sharp = box.FilterSharpen(1, 0.0, Library.FILTER_SCOPE_ALL))
                    Check(sharp.Vertices.SequenceEqual(box.Vertices), "strength 0 changes nothing");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => box.FilterSharpen(1, double.NaN, Library.FILTER_SCOPE_ALL), "NaN strength");
            }
            using (var e = TriangleMesh.CreateEllipsoid(1, 2, 0.5, 10, 0))
            {
                var v = e.Vertices;
                for (int i = 0; i < v.Length / 3; i++)
                    Near(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] / 4 + v[3 * i + 2] * v[3 * i + 2] * 4, 1, 1e-12, "on the ellipsoid");
            }
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => TriangleMesh.CreateEllipsoid(-1, 1, 1, 10, 0), "negative radius");
        });

        Run("geometry: minimal box, ellipsoid and their meshes", () =>
        {
            var obb = new OrientedBoundingBox();
            obb.SetCenter(new[] { 1.0, 2, 3 });
            double c = Math.Cos(0.3), s = Math.Sin(0.3);
            obb.SetR(new[] { c, -s, 0, s, c, 0, 0, 0, 1 });
            obb.SetExtent(new[] { 2.0, 4, 6 });
            using (obb)
            using (var m = TriangleMesh.CreateFromOrientedBoundingBox(obb, null, 0))
            using (var minimal = m.GetMinimalOrientedBoundingBox(0))
            using (var fit = OrientedBoundingEllipsoid.CreateFromPoints(m.Vertices, 0))
            {
                Near(m.GetVolume(), 48, 1e-9, "box mesh volume");
                var ext = minimal.GetExtent();
                Near(ext[0] * ext[1] * ext[2], 48, 1e-6, "the minimal box of a box is the box");
                var radii = fit.GetRadii().OrderBy(x => x).ToArray();
                for (int k = 0; k < 3; k++) Near(radii[k], Math.Sqrt(3) * (k + 1), 1e-3 * (k + 1), "corner ellipsoid radius " + k);
                using (var em = TriangleMesh.CreateFromOrientedBoundingEllipsoid(fit, null, 12, 0))
                    Check(em.NumVertices() == 2 + 11 * 24, "ellipsoid mesh vertices: " + em.NumVertices());
            }
            ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => OrientedBoundingEllipsoid.CreateFromPoints(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 }, 0), "a flat set");
        });

        Run("geometry: smoothing, static covariances, planar patches and traced down-sampling of clouds", () =>
        {
            var rnd = new Random(5);
            var plane = new double[3 * 400];
            for (int i = 0; i < 400; i++) { plane[3 * i] = 0.01 * (i % 20); plane[3 * i + 1] = 0.01 * (i / 20); plane[3 * i + 2] = 0.002 * (rnd.NextDouble() - 0.5); }
            Func<double[], double> meanZ = p => Enumerable.Range(0, p.Length / 3).Average(i => Math.Abs(p[3 * i + 2])); // mean |z|
            using (var pc = new PointCloud(plane))
            using (var lap = pc.SmoothLaplacian(10, 0.5, 8, 0))
            using (var tau = pc.SmoothTaubin(10, 0.5, -0.53, 8, 0))
            using (var param = new SearchParam { Kind = Library.SEARCH_HYBRID, Radius = 0.035, Knn = 30 })
            using (var mls = pc.SmoothMls(param))
            using (var bil = pc.SmoothBilateral(param, 0.02, 0.01))
            {
                Check(meanZ(lap.Points) < 0.5 * meanZ(plane), "Laplacian flattens: " + meanZ(lap.Points) + " of " + meanZ(plane));
                Check(meanZ(mls.Points) < 0.5 * meanZ(plane), "MLS flattens: " + meanZ(mls.Points) + " of " + meanZ(plane));
                Check(meanZ(tau.Points) < meanZ(plane) && meanZ(bil.Points) < meanZ(plane), "Taubin and bilateral flatten");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.SmoothLaplacian(1, 0.5, 0, 0), "knn 0");
            }
            using (var five = new PointCloud(new[] { 0.0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 1 }))
            using (var knn5 = new SearchParam { Kind = Library.SEARCH_KNN, Knn = 5 })
            {
                var cov = five.EstimatePointCovariances(knn5, 0);
                Check(cov.Length == 45, "five 3x3 matrices");
                Near(cov[0], 0.2, 1e-12, "var x"); Near(cov[4], 0.2, 1e-12, "var y"); Near(cov[8], 0.16, 1e-12, "var z");
            }
            var pts = new double[] { 0.2, 0.2, 0.2, 0.7, 0.2, 0.2, 0.3, 0.8, 0.9, 1.2, 0.1, 0.1, 1.9, 0.9, 0.9, 1.1, 0.1, 0.6 };
            using (var pc = new PointCloud(pts))
            using (var res = pc.VoxelDownSampleAndTrace(1.0, new[] { 0.0, 0, 0 }, new[] { 2.0, 1, 1 }, 0))
            using (var cloud = res.Cloud())
            using (var cubic = res.CubicIds())
            using (var traced = res.OriginalIndices())
            {
                Check(cloud.Size() == 2, "two voxels");
                var t = ListsOf(traced);
                Check(t[0].SequenceEqual(new[] { 0, 1, 2 }) && t[1].SequenceEqual(new[] { 3, 4, 5 }), "traced indices");
                Check(ListsOf(cubic)[1].SequenceEqual(new[] { 3, -1, -1, -1, 5, -1, -1, 4 }), "octants of voxel 1");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => pc.VoxelDownSampleAndTrace(0.0, new[] { 0.0, 0, 0 }, new[] { 2.0, 1, 1 }, 0), "voxel size 0");
            }
            // A floor and a wall with normals: two planar patches, their normals along z and x.
            var p2 = new System.Collections.Generic.List<double>();
            var n2 = new System.Collections.Generic.List<double>();
            for (int plane2 = 0; plane2 < 2; plane2++)
                for (int i = 0; i < 40; i++)
                    for (int j = 0; j < 40; j++)
                    {
                        double a = 0.05 * i + 0.01, b = 0.05 * j + 0.01, w = 0.001 * (rnd.NextDouble() - 0.5);
                        if (plane2 == 0) { p2.AddRange(new[] { a, b, w }); n2.AddRange(new[] { 0.0, 0, 1 }); }
                        else { p2.AddRange(new[] { w, a, b + 0.05 }); n2.AddRange(new[] { 1.0, 0, 0 }); }
                    }
            using (var pc = new PointCloud(p2.ToArray()))
            using (var opts = new PlanarPatchOptions())
            {
                pc.Normals = n2.ToArray();
                Check(opts.NormalVarianceThresholdDeg == 60 && opts.CoplanarityDeg == 75, "defaults from the init");
                var boxes = pc.DetectPlanarPatches(opts);
                Check(boxes.Length == 2 * 15, "two patches, 15 doubles each: " + boxes.Length / 15);
                var normalZ = Enumerable.Range(0, 2).Select(i => Math.Abs(boxes[15 * i + 3 + 8])).OrderBy(x => x).ToArray();
                Check(normalZ[0] < 1e-3 && normalZ[1] > 1 - 1e-3, "one normal along z, one across it");
            }
        });

        Run("geometry: as-rigid-as-possible deformation reproduces a rigid motion", () =>
        {
            using (var sphere = TriangleMesh.CreateSphere(1.0, 8))
            {
                var v = sphere.Vertices;
                double c = Math.Cos(Math.PI / 6), s = Math.Sin(Math.PI / 6);
                Func<int, double[]> moved = i => new[] { c * v[3 * i] - s * v[3 * i + 1] + 0.5, s * v[3 * i] + c * v[3 * i + 1] - 0.25, v[3 * i + 2] + 2 };
                var ids = Enumerable.Range(0, v.Length / 3).Where(i => i % 3 == 0).ToArray();
                var pos = ids.SelectMany(moved).ToArray();
                using (var outMesh = sphere.DeformAsRigidAsPossible(ids, pos, 50, Library.ARAP_ENERGY_SPOKES, 0.01))
                {
                    var w = outMesh.Vertices;
                    for (int i = 0; i < v.Length / 3; i++)
                        for (int k = 0; k < 3; k++) Near(w[3 * i + k], moved(i)[k], 1e-5, "vertex " + i);
                }
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => sphere.DeformAsRigidAsPossible(new[] { 0, 0 }, new double[6], 5, Library.ARAP_ENERGY_SPOKES, 0.01), "a repeated index");
            }
        });

        Run("geometry: half-edge mesh of a closed and an open mesh", () =>
        {
            using (var ico = TriangleMesh.CreateIcosahedron(1.0))
            using (var h = HalfEdgeTriangleMesh.CreateFromTriangleMesh(ico))
            using (var loops = h.GetBoundaries())
            {
                var he = h.GetHalfEdges();
                Check(he.Length == 60 * 5, "60 half-edges");
                for (int i = 0; i < 60; i++)
                {
                    int twin = he[5 * i + 1];
                    Check(twin >= 0 && he[5 * twin + 2] == he[5 * i + 3] && he[5 * twin + 3] == he[5 * i + 2], "twin reversed");
                }
                Check(ListsOf(loops).Length == 0, "closed: no boundary");
            }
            using (var strip = MeshOf(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 }, new[] { 0, 1, 3, 0, 3, 2 }))
            using (var h = HalfEdgeTriangleMesh.CreateFromTriangleMesh(strip))
            {
                Check(h.BoundaryVerticesFromVertex(0).SequenceEqual(new[] { 0, 1, 3, 2 }), "the square's boundary from vertex 0");
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => h.BoundaryVerticesFromVertex(7), "vertex out of range");
            }
            using (var fin = MeshOf(new double[] { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1 }, new[] { 0, 1, 2, 1, 0, 3, 0, 1, 4 }))
                ThrowsStatus(Library.ERROR_INVALID_ARGUMENT, () => HalfEdgeTriangleMesh.CreateFromTriangleMesh(fin), "non-manifold input");
        });
    }
}
