// SPDX-License-Identifier: MIT
// TriangleMesh: normals, transforms, clean-up, queries, processing and primitives (Open3D's names).
using System;

namespace O3d
{
    public sealed partial class TriangleMesh
    {
        delegate int MakeFn(out IntPtr result);

        static TriangleMesh Make(MakeFn fn)
        {
            IntPtr h;
            fn(out h);
            return new TriangleMesh(h);
        }

        TriangleMesh Edit(Func<IntPtr, int> fn) { fn(Handle); GC.KeepAlive(this); return this; }

        // ---- normals, colors, transforms, bounds ------------------------------------------------

        /// <summary>Area-weighted vertex normals (unit length when <paramref name="normalized"/>).</summary>
        public TriangleMesh ComputeVertexNormals(bool normalized = true)
        { return Edit(h => O3dNative.o3d_trianglemesh_compute_vertex_normals(h, normalized ? 1 : 0)); }

        public TriangleMesh ComputeTriangleNormals(bool normalized = true)
        { return Edit(h => O3dNative.o3d_trianglemesh_compute_triangle_normals(h, normalized ? 1 : 0)); }

        public TriangleMesh NormalizeNormals() { return Edit(O3dNative.o3d_trianglemesh_normalize_normals); }

        public TriangleMesh PaintUniformColor(double[] rgb)
        {
            var c = Checks.Fixed(rgb, 3, "rgb", false);
            return Edit(h => O3dNative.o3d_trianglemesh_paint_uniform_color(h, c));
        }

        /// <summary>Apply a row-major 4x4 transform (16 values); normals are rotated.</summary>
        public TriangleMesh Transform(double[] transform)
        {
            var t = Checks.Fixed(transform, 16, "transform", false);
            return Edit(h => O3dNative.o3d_trianglemesh_transform(h, t));
        }

        public TriangleMesh Translate(double[] translation, bool relative = true)
        {
            var t = Checks.Fixed(translation, 3, "translation", false);
            return Edit(h => O3dNative.o3d_trianglemesh_translate(h, t, relative ? 1 : 0));
        }

        /// <summary>Rotate by a row-major 3x3 matrix about <paramref name="center"/> (null: the mesh's center).</summary>
        public TriangleMesh Rotate(double[] rotation, double[] center = null)
        {
            var r = Checks.Fixed(rotation, 9, "rotation", false);
            var c = Checks.Fixed(center, 3, "center", true);
            return Edit(h => O3dNative.o3d_trianglemesh_rotate(h, r, c));
        }

        public TriangleMesh Scale(double scale, double[] center = null)
        {
            var c = Checks.Fixed(center, 3, "center", true);
            return Edit(h => O3dNative.o3d_trianglemesh_scale(h, scale, c));
        }

        delegate int Vec3Fn(IntPtr mesh, double[] out_);
        double[] Vec3(Vec3Fn fn) { var v = new double[3]; fn(Handle, v); GC.KeepAlive(this); return v; }

        public double[] MinBound { get { return Vec3(O3dNative.o3d_trianglemesh_get_min_bound); } }
        public double[] MaxBound { get { return Vec3(O3dNative.o3d_trianglemesh_get_max_bound); } }
        public double[] Center { get { return Vec3(O3dNative.o3d_trianglemesh_get_center); } }

        /// <summary>Axis-aligned bounding box as min and max corners.</summary>
        public void GetAxisAlignedBoundingBox(out double[] min, out double[] max)
        {
            min = new double[3]; max = new double[3];
            O3dNative.o3d_trianglemesh_get_axis_aligned_bounding_box(min, max, Handle);
            GC.KeepAlive(this);
        }

        // ---- clean-up (in place) ------------------------------------------------------------------

        public TriangleMesh RemoveDuplicatedVertices() { return Edit(O3dNative.o3d_trianglemesh_remove_duplicated_vertices); }
        public TriangleMesh RemoveDuplicatedTriangles() { return Edit(O3dNative.o3d_trianglemesh_remove_duplicated_triangles); }
        public TriangleMesh RemoveDegenerateTriangles() { return Edit(O3dNative.o3d_trianglemesh_remove_degenerate_triangles); }
        public TriangleMesh RemoveUnreferencedVertices() { return Edit(O3dNative.o3d_trianglemesh_remove_unreferenced_vertices); }
        public TriangleMesh RemoveNonManifoldEdges() { return Edit(O3dNative.o3d_trianglemesh_remove_non_manifold_edges); }

        /// <summary>Merge vertices closer than <paramref name="eps"/> (&gt;= 0) into their mean.</summary>
        public TriangleMesh MergeCloseVertices(double eps)
        { return Edit(h => O3dNative.o3d_trianglemesh_merge_close_vertices(h, eps)); }

        // ---- queries ------------------------------------------------------------------------------

        delegate int DoubleQuery(IntPtr mesh, double[] out_);
        delegate int FlagQuery(IntPtr mesh, int[] out_);
        double Query(DoubleQuery fn) { var v = new double[1]; fn(Handle, v); GC.KeepAlive(this); return v[0]; }
        bool Flag(FlagQuery fn) { var v = new int[1]; fn(Handle, v); GC.KeepAlive(this); return v[0] != 0; }

        /// <summary>Sum of the triangle areas.</summary>
        public double GetSurfaceArea() { return Query(O3dNative.o3d_trianglemesh_get_surface_area); }
        /// <summary>Enclosed volume; throws O3dException (InvalidArgument) unless watertight and orientable.</summary>
        public double GetVolume() { return Query(O3dNative.o3d_trianglemesh_get_volume); }
        public bool IsWatertight() { return Flag(O3dNative.o3d_trianglemesh_is_watertight); }
        public bool IsVertexManifold() { return Flag(O3dNative.o3d_trianglemesh_is_vertex_manifold); }
        public bool IsSelfIntersecting() { return Flag(O3dNative.o3d_trianglemesh_is_self_intersecting); }
        public bool IsOrientable() { return Flag(O3dNative.o3d_trianglemesh_is_orientable); }

        public bool IsEdgeManifold(bool allowBoundaryEdges = true)
        {
            var v = new int[1];
            O3dNative.o3d_trianglemesh_is_edge_manifold(v, Handle, allowBoundaryEdges ? 1 : 0);
            GC.KeepAlive(this);
            return v[0] != 0;
        }

        /// <summary>V - E + F.</summary>
        public long EulerPoincareCharacteristic()
        {
            var v = new long[1];
            O3dNative.o3d_trianglemesh_euler_poincare_characteristic(v, Handle);
            GC.KeepAlive(this);
            return v[0];
        }

        /// <summary>Edge-connected components: each triangle's cluster, each cluster's size and area.</summary>
        public TriangleClusters ClusterConnectedTriangles()
        {
            IntPtr h = Handle;
            ulong m, k;
            O3dNative.o3d_trianglemesh_cluster_connected_triangles(null, null, null, 0, out m, out k, h);
            var clusters = new int[m];
            var counts = new int[m];
            var areas = new double[m];
            O3dNative.o3d_trianglemesh_cluster_connected_triangles(clusters, counts, areas, m, out m, out k, h);
            GC.KeepAlive(this);
            Array.Resize(ref counts, (int)k);
            Array.Resize(ref areas, (int)k);
            return new TriangleClusters(clusters, counts, areas);
        }

        // ---- processing (new mesh or cloud) -------------------------------------------------------

        delegate int CloudFn(out IntPtr result, IntPtr mesh);
        PointCloud ToCloud(CloudFn fn) { IntPtr r; fn(out r, Handle); GC.KeepAlive(this); return new PointCloud(r); }
        delegate int MeshFn(out IntPtr result, IntPtr mesh);
        TriangleMesh ToMesh(MeshFn fn) { IntPtr r; fn(out r, Handle); GC.KeepAlive(this); return new TriangleMesh(r); }

        static ulong Count(long n, string name)
        {
            if (n < 0) throw new ArgumentOutOfRangeException(name);
            return (ulong)n;
        }

        /// <summary>Area-weighted uniform surface samples; same seed, same output.</summary>
        public PointCloud SamplePointsUniformly(long numberOfPoints = 100, bool useTriangleNormal = false, ulong seed = 0)
        {
            ulong n = Count(numberOfPoints, "numberOfPoints");
            return ToCloud((out IntPtr r, IntPtr m) =>
                O3dNative.o3d_trianglemesh_sample_points_uniformly(out r, m, n, useTriangleNormal ? 1 : 0, seed));
        }

        /// <summary>Poisson-disk samples by sample elimination from initFactor * numberOfPoints uniform samples.</summary>
        public PointCloud SamplePointsPoissonDisk(long numberOfPoints, double initFactor = 5, bool useTriangleNormal = false,
                                                  ulong seed = 0)
        {
            ulong n = Count(numberOfPoints, "numberOfPoints");
            return ToCloud((out IntPtr r, IntPtr m) =>
                O3dNative.o3d_trianglemesh_sample_points_poisson_disk(out r, m, n, initFactor, useTriangleNormal ? 1 : 0, seed));
        }

        public TriangleMesh SimplifyVertexClustering(double voxelSize,
                                                     SimplificationContraction contraction = SimplificationContraction.Average)
        {
            return ToMesh((out IntPtr r, IntPtr m) =>
                O3dNative.o3d_trianglemesh_simplify_vertex_clustering(out r, m, voxelSize, (int)contraction));
        }

        /// <summary>Quadric edge-collapse decimation down to <paramref name="targetNumberOfTriangles"/>.</summary>
        public TriangleMesh SimplifyQuadricDecimation(long targetNumberOfTriangles, double maximumError = double.PositiveInfinity,
                                                      double boundaryWeight = 1.0)
        {
            ulong n = Count(targetNumberOfTriangles, "targetNumberOfTriangles");
            return ToMesh((out IntPtr r, IntPtr m) =>
                O3dNative.o3d_trianglemesh_simplify_quadric_decimation(out r, m, n, maximumError, boundaryWeight));
        }

        public TriangleMesh FilterSmoothSimple(int numberOfIterations = 1, FilterScope scope = FilterScope.All)
        {
            return ToMesh((out IntPtr r, IntPtr m) =>
                O3dNative.o3d_trianglemesh_filter_smooth_simple(out r, m, numberOfIterations, (int)scope));
        }

        public TriangleMesh FilterSmoothLaplacian(int numberOfIterations = 1, double lambdaFilter = 0.5,
                                                  FilterScope scope = FilterScope.All)
        {
            return ToMesh((out IntPtr r, IntPtr m) =>
                O3dNative.o3d_trianglemesh_filter_smooth_laplacian(out r, m, numberOfIterations, lambdaFilter, (int)scope));
        }

        public TriangleMesh FilterSmoothTaubin(int numberOfIterations = 1, double lambdaFilter = 0.5, double mu = -0.53,
                                               FilterScope scope = FilterScope.All)
        {
            return ToMesh((out IntPtr r, IntPtr m) =>
                O3dNative.o3d_trianglemesh_filter_smooth_taubin(out r, m, numberOfIterations, lambdaFilter, mu, (int)scope));
        }

        public TriangleMesh SubdivideMidpoint(int numberOfIterations = 1)
        {
            return ToMesh((out IntPtr r, IntPtr m) => O3dNative.o3d_trianglemesh_subdivide_midpoint(out r, m, numberOfIterations));
        }

        public TriangleMesh SubdivideLoop(int numberOfIterations = 1)
        {
            return ToMesh((out IntPtr r, IntPtr m) => O3dNative.o3d_trianglemesh_subdivide_loop(out r, m, numberOfIterations));
        }

        /// <summary>The triangles whose three vertices lie in [minBound, maxBound].</summary>
        public TriangleMesh Crop(double[] minBound, double[] maxBound)
        {
            var lo = Checks.Fixed(minBound, 3, "minBound", false);
            var hi = Checks.Fixed(maxBound, 3, "maxBound", false);
            return ToMesh((out IntPtr r, IntPtr m) => O3dNative.o3d_trianglemesh_crop_aabb(out r, m, lo, hi));
        }

        // ---- primitives (Open3D's create_* and defaults) --------------------------------------------

        /// <summary>Box [0,w] x [0,h] x [0,d].</summary>
        public static TriangleMesh CreateBox(double width = 1, double height = 1, double depth = 1)
        { return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_box(out r, width, height, depth)); }

        public static TriangleMesh CreateSphere(double radius = 1, int resolution = 20)
        { return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_sphere(out r, radius, resolution)); }

        public static TriangleMesh CreateCylinder(double radius = 1, double height = 2, int resolution = 20, int split = 4)
        { return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_cylinder(out r, radius, height, resolution, split)); }

        public static TriangleMesh CreateCone(double radius = 1, double height = 2, int resolution = 20, int split = 1)
        { return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_cone(out r, radius, height, resolution, split)); }

        public static TriangleMesh CreateTorus(double torusRadius = 1, double tubeRadius = 0.5, int radialResolution = 30,
                                               int tubularResolution = 20)
        {
            return Make((out IntPtr r) =>
                O3dNative.o3d_trianglemesh_create_torus(out r, torusRadius, tubeRadius, radialResolution, tubularResolution));
        }

        public static TriangleMesh CreateArrow(double cylinderRadius = 1, double coneRadius = 1.5, double cylinderHeight = 5,
                                               double coneHeight = 4, int resolution = 20, int cylinderSplit = 4, int coneSplit = 1)
        {
            return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_arrow(out r, cylinderRadius, coneRadius,
                cylinderHeight, coneHeight, resolution, cylinderSplit, coneSplit));
        }

        /// <summary>Axes (x red, y green, z blue) of length <paramref name="size"/> at <paramref name="origin"/> (null: 0).</summary>
        public static TriangleMesh CreateCoordinateFrame(double size = 1, double[] origin = null)
        {
            var o = Checks.Fixed(origin, 3, "origin", true);
            return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_coordinate_frame(out r, size, o));
        }

        public static TriangleMesh CreateTetrahedron(double radius = 1)
        { return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_tetrahedron(out r, radius)); }

        public static TriangleMesh CreateOctahedron(double radius = 1)
        { return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_octahedron(out r, radius)); }

        public static TriangleMesh CreateIcosahedron(double radius = 1)
        { return Make((out IntPtr r) => O3dNative.o3d_trianglemesh_create_icosahedron(out r, radius)); }
    }
}
