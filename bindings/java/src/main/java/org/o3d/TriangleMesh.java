// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Objects;

/**
 * A triangle mesh (o3d.geometry.TriangleMesh). Vertices, normals and colors are (N x 3) row-major double
 * arrays, triangles (M x 3) int arrays; getters copy out and setters copy in, one native call each.
 * Clean-up methods edit in place and return this; processing methods return a new mesh. Close it
 * (try-with-resources); a Cleaner destroys forgotten meshes.
 */
public final class TriangleMesh extends NativeResource {
    TriangleMesh(long handle) {
        super(handle, O3dNative::o3d_trianglemesh_destroy);
    }

    private static long create() {
        long[] h = new long[1];
        O3dNative.o3d_trianglemesh_create(h);
        return h[0];
    }

    /** An empty mesh. */
    public TriangleMesh() {
        this(create());
    }

    /** A mesh with (N x 3) vertices and (M x 3) triangles. */
    public TriangleMesh(double[] vertices, int[] triangles) {
        this(create());
        try {
            setVertices(vertices);
            setTriangles(triangles);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    static TriangleMesh wrap(long[] h) {
        return new TriangleMesh(h[0]);
    }

    /** Deep copy (textures included). */
    public TriangleMesh copy() {
        long[] h = new long[1];
        O3dNative.o3d_trianglemesh_clone(h, handle());
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    /** Remove all arrays and textures. */
    public TriangleMesh clear() {
        O3dNative.o3d_trianglemesh_clear(handle());
        Reference.reachabilityFence(this);
        return this;
    }

    public long numVertices() {
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_num_vertices(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    public long numTriangles() {
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_num_triangles(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    private boolean has(int which) {
        int[] v = new int[1];
        O3dNative.o3d_trianglemesh_has_array(v, handle(), which);
        Reference.reachabilityFence(this);
        return v[0] != 0;
    }

    public boolean hasVertices() { return has(O3dNativeConstants.O3D_MESH_VERTICES); }
    public boolean hasVertexNormals() { return has(O3dNativeConstants.O3D_MESH_VERTEX_NORMALS); }
    public boolean hasVertexColors() { return has(O3dNativeConstants.O3D_MESH_VERTEX_COLORS); }
    public boolean hasTriangles() { return has(O3dNativeConstants.O3D_MESH_TRIANGLES); }
    public boolean hasTriangleNormals() { return has(O3dNativeConstants.O3D_MESH_TRIANGLE_NORMALS); }
    public boolean hasTriangleUvs() { return has(O3dNativeConstants.O3D_MESH_TRIANGLE_UVS); }
    public boolean hasTriangleMaterialIds() { return has(O3dNativeConstants.O3D_MESH_TRIANGLE_MATERIAL_IDS); }
    public boolean hasTextures() { return textureCount() > 0; }

    // ---- bulk arrays ------------------------------------------------------------------------------

    private static int javaLength(long rows, int columns) {
        if (rows * columns > Integer.MAX_VALUE - 8) throw new IllegalStateException("mesh too large for a Java array");
        return (int) (rows * columns);
    }

    private static long rows(int length, int columns, String name) {
        if (length % columns != 0)
            throw new IllegalArgumentException(name + ": length " + length + " is not a multiple of " + columns);
        return length / columns;
    }

    private double[] getArray(int which, int columns) {
        long h = handle();
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_get_array(null, 0, n, h, which);
        double[] out = new double[javaLength(n[0], columns)];
        O3dNative.o3d_trianglemesh_get_array(out, n[0], n, h, which);
        Reference.reachabilityFence(this);
        return out;
    }

    private void setArray(int which, double[] values, int columns, String name) {
        Objects.requireNonNull(values, name);
        O3dNative.o3d_trianglemesh_set_array(handle(), which, values, rows(values.length, columns, name));
        Reference.reachabilityFence(this);
    }

    private int[] getIndexArray(int which, int columns) {
        long h = handle();
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_get_index_array(null, 0, n, h, which);
        int[] out = new int[javaLength(n[0], columns)];
        O3dNative.o3d_trianglemesh_get_index_array(out, n[0], n, h, which);
        Reference.reachabilityFence(this);
        return out;
    }

    private void setIndexArray(int which, int[] values, int columns, String name) {
        Objects.requireNonNull(values, name);
        O3dNative.o3d_trianglemesh_set_index_array(handle(), which, values, rows(values.length, columns, name));
        Reference.reachabilityFence(this);
    }

    /** Vertices x0,y0,z0,x1,... (a copy). */
    public double[] getVertices() { return getArray(O3dNativeConstants.O3D_MESH_VERTICES, 3); }
    public double[] getVertexNormals() { return getArray(O3dNativeConstants.O3D_MESH_VERTEX_NORMALS, 3); }
    /** Vertex colors, RGB in [0,1] (a copy). */
    public double[] getVertexColors() { return getArray(O3dNativeConstants.O3D_MESH_VERTEX_COLORS, 3); }
    public double[] getTriangleNormals() { return getArray(O3dNativeConstants.O3D_MESH_TRIANGLE_NORMALS, 3); }
    /** Triangle UVs u0,v0,u1,v1,...: three (u, v) rows per triangle in corner order (a copy). */
    public double[] getTriangleUvs() { return getArray(O3dNativeConstants.O3D_MESH_TRIANGLE_UVS, 2); }
    /** Triangles as vertex indices a0,b0,c0,a1,... (a copy). */
    public int[] getTriangles() { return getIndexArray(O3dNativeConstants.O3D_MESH_TRIANGLES, 3); }
    /** Material (texture) index of each triangle (a copy). */
    public int[] getTriangleMaterialIds() { return getIndexArray(O3dNativeConstants.O3D_MESH_TRIANGLE_MATERIAL_IDS, 1); }

    /** Replace the vertices (length 3N, copied once). */
    public void setVertices(double[] xyz) { setArray(O3dNativeConstants.O3D_MESH_VERTICES, xyz, 3, "xyz"); }
    public void setVertexNormals(double[] xyz) { setArray(O3dNativeConstants.O3D_MESH_VERTEX_NORMALS, xyz, 3, "xyz"); }
    public void setVertexColors(double[] rgb) { setArray(O3dNativeConstants.O3D_MESH_VERTEX_COLORS, rgb, 3, "rgb"); }
    public void setTriangleNormals(double[] xyz) { setArray(O3dNativeConstants.O3D_MESH_TRIANGLE_NORMALS, xyz, 3, "xyz"); }
    public void setTriangleUvs(double[] uv) { setArray(O3dNativeConstants.O3D_MESH_TRIANGLE_UVS, uv, 2, "uv"); }
    /** Replace the triangles (length 3M, copied once). */
    public void setTriangles(int[] triangles) { setIndexArray(O3dNativeConstants.O3D_MESH_TRIANGLES, triangles, 3, "triangles"); }
    public void setTriangleMaterialIds(int[] ids) { setIndexArray(O3dNativeConstants.O3D_MESH_TRIANGLE_MATERIAL_IDS, ids, 1, "ids"); }

    // ---- borrowed views ---------------------------------------------------------------------------
    // Direct ByteBuffers (native order) over the mesh's own storage; use asDoubleBuffer() /
    // asIntBuffer(). Valid ONLY until the next mutating call on this mesh or close().

    private ByteBuffer wrapView(long data, long bytes, boolean writable) {
        ByteBuffer b = O3dNative.o3dj_direct_buffer(data, bytes);
        if (b == null) b = ByteBuffer.allocateDirect(0);
        b.order(ByteOrder.nativeOrder());
        return writable ? b : b.asReadOnlyBuffer().order(ByteOrder.nativeOrder());
    }

    private static int columns(MeshArray which) {
        return which == MeshArray.TRIANGLE_UVS ? 2 : 3;
    }

    private static int columns(MeshIndexArray which) {
        return which == MeshIndexArray.TRIANGLES ? 3 : 1;
    }

    public ByteBuffer arrayView(MeshArray which) {
        long[] data = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_array_view(data, n, handle(), which.code());
        Reference.reachabilityFence(this);
        return wrapView(data[0], n[0] * columns(which) * Double.BYTES, false);
    }

    public ByteBuffer arrayMutableView(MeshArray which) {
        long[] data = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_array_mutable_view(data, n, handle(), which.code());
        Reference.reachabilityFence(this);
        return wrapView(data[0], n[0] * columns(which) * Double.BYTES, true);
    }

    public ByteBuffer indexArrayView(MeshIndexArray which) {
        long[] data = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_index_array_view(data, n, handle(), which.code());
        Reference.reachabilityFence(this);
        return wrapView(data[0], n[0] * columns(which) * Integer.BYTES, false);
    }

    public ByteBuffer indexArrayMutableView(MeshIndexArray which) {
        long[] data = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_index_array_mutable_view(data, n, handle(), which.code());
        Reference.reachabilityFence(this);
        return wrapView(data[0], n[0] * columns(which) * Integer.BYTES, true);
    }

    // ---- textures ---------------------------------------------------------------------------------

    public long textureCount() {
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_texture_count(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    /** A copy of texture {@code index}; close it. */
    public Image getTexture(long index) {
        if (index < 0) throw new IndexOutOfBoundsException("index " + index);
        long[] h = new long[1];
        O3dNative.o3d_trianglemesh_get_texture(h, handle(), index);
        Reference.reachabilityFence(this);
        return new Image(h[0]);
    }

    /** Append a copy of {@code image} to the textures. */
    public TriangleMesh addTexture(Image image) {
        O3dNative.o3d_trianglemesh_add_texture(handle(), image.handle());
        Reference.reachabilityFence(image);
        Reference.reachabilityFence(this);
        return this;
    }

    public TriangleMesh clearTextures() {
        O3dNative.o3d_trianglemesh_clear_textures(handle());
        Reference.reachabilityFence(this);
        return this;
    }

    /** Concatenate {@code other} onto this mesh (Open3D {@code mesh += other}). */
    public TriangleMesh append(TriangleMesh other) {
        O3dNative.o3d_trianglemesh_append(handle(), other.handle());
        Reference.reachabilityFence(other);
        Reference.reachabilityFence(this);
        return this;
    }

    // ---- normals, colors, transforms, bounds ------------------------------------------------------

    private interface EditFn {
        int apply(long mesh);
    }

    private TriangleMesh edit(EditFn fn) {
        fn.apply(handle());
        Reference.reachabilityFence(this);
        return this;
    }

    /** Area-weighted vertex normals (unit length when {@code normalized}). */
    public TriangleMesh computeVertexNormals(boolean normalized) {
        return edit(m -> O3dNative.o3d_trianglemesh_compute_vertex_normals(m, normalized ? 1 : 0));
    }

    public TriangleMesh computeVertexNormals() { return computeVertexNormals(true); }

    public TriangleMesh computeTriangleNormals(boolean normalized) {
        return edit(m -> O3dNative.o3d_trianglemesh_compute_triangle_normals(m, normalized ? 1 : 0));
    }

    public TriangleMesh computeTriangleNormals() { return computeTriangleNormals(true); }

    public TriangleMesh normalizeNormals() { return edit(O3dNative::o3d_trianglemesh_normalize_normals); }

    public TriangleMesh paintUniformColor(double[] rgb) {
        double[] c = fixed(rgb, 3, "rgb", false);
        return edit(m -> O3dNative.o3d_trianglemesh_paint_uniform_color(m, c));
    }

    /** Apply a row-major 4x4 transform (16 values); normals are rotated. */
    public TriangleMesh transform(double[] transform) {
        double[] t = fixed(transform, 16, "transform", false);
        return edit(m -> O3dNative.o3d_trianglemesh_transform(m, t));
    }

    /** relative: add {@code t}; otherwise move the center to {@code t}. */
    public TriangleMesh translate(double[] translation, boolean relative) {
        double[] t = fixed(translation, 3, "translation", false);
        return edit(m -> O3dNative.o3d_trianglemesh_translate(m, t, relative ? 1 : 0));
    }

    public TriangleMesh translate(double[] translation) { return translate(translation, true); }

    /** Rotate by a row-major 3x3 matrix about {@code center} (null: the mesh's center). */
    public TriangleMesh rotate(double[] rotation, double[] center) {
        double[] r = fixed(rotation, 9, "rotation", false);
        double[] c = fixed(center, 3, "center", true);
        return edit(m -> O3dNative.o3d_trianglemesh_rotate(m, r, c));
    }

    public TriangleMesh scale(double scale, double[] center) {
        double[] c = fixed(center, 3, "center", true);
        return edit(m -> O3dNative.o3d_trianglemesh_scale(m, scale, c));
    }

    private interface Vec3Fn {
        int get(long mesh, double[] out);
    }

    private double[] vec3(Vec3Fn fn) {
        double[] v = new double[3];
        fn.get(handle(), v);
        Reference.reachabilityFence(this);
        return v;
    }

    public double[] getMinBound() { return vec3(O3dNative::o3d_trianglemesh_get_min_bound); }
    public double[] getMaxBound() { return vec3(O3dNative::o3d_trianglemesh_get_max_bound); }
    public double[] getCenter() { return vec3(O3dNative::o3d_trianglemesh_get_center); }

    /** Axis-aligned bounding box: {min, max}. */
    public double[][] getAxisAlignedBoundingBox() {
        double[] min = new double[3];
        double[] max = new double[3];
        O3dNative.o3d_trianglemesh_get_axis_aligned_bounding_box(min, max, handle());
        Reference.reachabilityFence(this);
        return new double[][] {min, max};
    }

    // ---- clean-up (in place) ----------------------------------------------------------------------

    public TriangleMesh removeDuplicatedVertices() { return edit(O3dNative::o3d_trianglemesh_remove_duplicated_vertices); }
    public TriangleMesh removeDuplicatedTriangles() { return edit(O3dNative::o3d_trianglemesh_remove_duplicated_triangles); }
    public TriangleMesh removeDegenerateTriangles() { return edit(O3dNative::o3d_trianglemesh_remove_degenerate_triangles); }
    public TriangleMesh removeUnreferencedVertices() { return edit(O3dNative::o3d_trianglemesh_remove_unreferenced_vertices); }
    public TriangleMesh removeNonManifoldEdges() { return edit(O3dNative::o3d_trianglemesh_remove_non_manifold_edges); }

    /** Merge vertices closer than {@code eps} (&gt;= 0) into their mean. */
    public TriangleMesh mergeCloseVertices(double eps) {
        return edit(m -> O3dNative.o3d_trianglemesh_merge_close_vertices(m, eps));
    }

    // ---- queries ----------------------------------------------------------------------------------

    private interface DoubleQuery {
        int get(long mesh, double[] out);
    }

    private interface FlagQuery {
        int get(long mesh, int[] out);
    }

    private double query(DoubleQuery fn) {
        double[] v = new double[1];
        fn.get(handle(), v);
        Reference.reachabilityFence(this);
        return v[0];
    }

    private boolean flag(FlagQuery fn) {
        int[] v = new int[1];
        fn.get(handle(), v);
        Reference.reachabilityFence(this);
        return v[0] != 0;
    }

    /** Sum of the triangle areas. */
    public double getSurfaceArea() { return query(O3dNative::o3d_trianglemesh_get_surface_area); }
    /** Enclosed volume; throws O3dException (INVALID_ARGUMENT) unless watertight and orientable. */
    public double getVolume() { return query(O3dNative::o3d_trianglemesh_get_volume); }
    public boolean isWatertight() { return flag(O3dNative::o3d_trianglemesh_is_watertight); }
    public boolean isVertexManifold() { return flag(O3dNative::o3d_trianglemesh_is_vertex_manifold); }
    public boolean isSelfIntersecting() { return flag(O3dNative::o3d_trianglemesh_is_self_intersecting); }
    public boolean isOrientable() { return flag(O3dNative::o3d_trianglemesh_is_orientable); }

    public boolean isEdgeManifold(boolean allowBoundaryEdges) {
        return flag((m, out) -> O3dNative.o3d_trianglemesh_is_edge_manifold(out, m, allowBoundaryEdges ? 1 : 0));
    }

    public boolean isEdgeManifold() { return isEdgeManifold(true); }

    /** V - E + F. */
    public long eulerPoincareCharacteristic() {
        long[] v = new long[1];
        O3dNative.o3d_trianglemesh_euler_poincare_characteristic(v, handle());
        Reference.reachabilityFence(this);
        return v[0];
    }

    /** Edge-connected components: each triangle's cluster, each cluster's size and area. */
    public TriangleClusters clusterConnectedTriangles() {
        long h = handle();
        long[] m = new long[1];
        long[] k = new long[1];
        O3dNative.o3d_trianglemesh_cluster_connected_triangles(null, null, null, 0, m, k, h);
        int len = javaLength(m[0], 1);
        int[] clusters = new int[len];
        int[] counts = new int[len];
        double[] areas = new double[len];
        O3dNative.o3d_trianglemesh_cluster_connected_triangles(clusters, counts, areas, len, m, k, h);
        Reference.reachabilityFence(this);
        return new TriangleClusters(clusters, java.util.Arrays.copyOf(counts, (int) k[0]),
                java.util.Arrays.copyOf(areas, (int) k[0]));
    }

    // Processing (new mesh or cloud) and primitives: TriangleMeshOps.
    public PointCloud samplePointsUniformly(long numberOfPoints, boolean useTriangleNormal, long seed) {
        return TriangleMeshOps.samplePointsUniformly(this, numberOfPoints, useTriangleNormal, seed);
    }

    public PointCloud samplePointsUniformly(long numberOfPoints) { return samplePointsUniformly(numberOfPoints, false, 0); }

    public PointCloud samplePointsPoissonDisk(long numberOfPoints, double initFactor, boolean useTriangleNormal, long seed) {
        return TriangleMeshOps.samplePointsPoissonDisk(this, numberOfPoints, initFactor, useTriangleNormal, seed);
    }

    public PointCloud samplePointsPoissonDisk(long numberOfPoints) { return samplePointsPoissonDisk(numberOfPoints, 5, false, 0); }

    public TriangleMesh simplifyVertexClustering(double voxelSize, SimplificationContraction contraction) {
        return TriangleMeshOps.process(this, (out, m) ->
                O3dNative.o3d_trianglemesh_simplify_vertex_clustering(out, m, voxelSize, contraction.code()));
    }

    public TriangleMesh simplifyVertexClustering(double voxelSize) {
        return simplifyVertexClustering(voxelSize, SimplificationContraction.AVERAGE);
    }

    /** Quadric edge-collapse decimation down to {@code targetNumberOfTriangles}. */
    public TriangleMesh simplifyQuadricDecimation(long targetNumberOfTriangles, double maximumError, double boundaryWeight) {
        if (targetNumberOfTriangles < 0) throw new IllegalArgumentException("targetNumberOfTriangles < 0");
        return TriangleMeshOps.process(this, (out, m) -> O3dNative.o3d_trianglemesh_simplify_quadric_decimation(
                out, m, targetNumberOfTriangles, maximumError, boundaryWeight));
    }

    public TriangleMesh simplifyQuadricDecimation(long targetNumberOfTriangles) {
        return simplifyQuadricDecimation(targetNumberOfTriangles, Double.POSITIVE_INFINITY, 1.0);
    }

    public TriangleMesh filterSmoothSimple(int numberOfIterations, FilterScope scope) {
        return TriangleMeshOps.process(this, (out, m) ->
                O3dNative.o3d_trianglemesh_filter_smooth_simple(out, m, numberOfIterations, scope.code()));
    }

    public TriangleMesh filterSmoothSimple(int numberOfIterations) { return filterSmoothSimple(numberOfIterations, FilterScope.ALL); }

    public TriangleMesh filterSmoothLaplacian(int numberOfIterations, double lambdaFilter, FilterScope scope) {
        return TriangleMeshOps.process(this, (out, m) ->
                O3dNative.o3d_trianglemesh_filter_smooth_laplacian(out, m, numberOfIterations, lambdaFilter, scope.code()));
    }

    public TriangleMesh filterSmoothLaplacian(int numberOfIterations) {
        return filterSmoothLaplacian(numberOfIterations, 0.5, FilterScope.ALL);
    }

    public TriangleMesh filterSmoothTaubin(int numberOfIterations, double lambdaFilter, double mu, FilterScope scope) {
        return TriangleMeshOps.process(this, (out, m) ->
                O3dNative.o3d_trianglemesh_filter_smooth_taubin(out, m, numberOfIterations, lambdaFilter, mu, scope.code()));
    }

    public TriangleMesh filterSmoothTaubin(int numberOfIterations) {
        return filterSmoothTaubin(numberOfIterations, 0.5, -0.53, FilterScope.ALL);
    }

    public TriangleMesh subdivideMidpoint(int numberOfIterations) {
        return TriangleMeshOps.process(this, (out, m) -> O3dNative.o3d_trianglemesh_subdivide_midpoint(out, m, numberOfIterations));
    }

    public TriangleMesh subdivideLoop(int numberOfIterations) {
        return TriangleMeshOps.process(this, (out, m) -> O3dNative.o3d_trianglemesh_subdivide_loop(out, m, numberOfIterations));
    }

    /** The triangles whose three vertices lie in [minBound, maxBound]. */
    public TriangleMesh crop(double[] minBound, double[] maxBound) {
        double[] lo = fixed(minBound, 3, "minBound", false);
        double[] hi = fixed(maxBound, 3, "maxBound", false);
        return TriangleMeshOps.process(this, (out, m) -> O3dNative.o3d_trianglemesh_crop_aabb(out, m, lo, hi));
    }

    // ---- primitives (Open3D's create_*; the no-argument overloads use its defaults) ----------------

    /** Box [0,w] x [0,h] x [0,d]. */
    public static TriangleMesh createBox(double width, double height, double depth) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_box(out, width, height, depth));
    }

    public static TriangleMesh createBox() { return createBox(1, 1, 1); }

    public static TriangleMesh createSphere(double radius, int resolution) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_sphere(out, radius, resolution));
    }

    public static TriangleMesh createSphere() { return createSphere(1, 20); }

    public static TriangleMesh createCylinder(double radius, double height, int resolution, int split) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_cylinder(out, radius, height, resolution, split));
    }

    public static TriangleMesh createCylinder() { return createCylinder(1, 2, 20, 4); }

    public static TriangleMesh createCone(double radius, double height, int resolution, int split) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_cone(out, radius, height, resolution, split));
    }

    public static TriangleMesh createCone() { return createCone(1, 2, 20, 1); }

    public static TriangleMesh createTorus(double torusRadius, double tubeRadius, int radialResolution, int tubularResolution) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_torus(out, torusRadius, tubeRadius,
                radialResolution, tubularResolution));
    }

    public static TriangleMesh createTorus() { return createTorus(1, 0.5, 30, 20); }

    public static TriangleMesh createArrow(double cylinderRadius, double coneRadius, double cylinderHeight, double coneHeight,
            int resolution, int cylinderSplit, int coneSplit) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_arrow(out, cylinderRadius, coneRadius,
                cylinderHeight, coneHeight, resolution, cylinderSplit, coneSplit));
    }

    public static TriangleMesh createArrow() { return createArrow(1, 1.5, 5, 4, 20, 4, 1); }

    /** Axes (x red, y green, z blue) of length {@code size} at {@code origin} (null: 0,0,0). */
    public static TriangleMesh createCoordinateFrame(double size, double[] origin) {
        double[] o = fixed(origin, 3, "origin", true);
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_coordinate_frame(out, size, o));
    }

    public static TriangleMesh createCoordinateFrame() { return createCoordinateFrame(1, null); }

    public static TriangleMesh createTetrahedron(double radius) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_tetrahedron(out, radius));
    }

    public static TriangleMesh createOctahedron(double radius) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_octahedron(out, radius));
    }

    public static TriangleMesh createIcosahedron(double radius) {
        return TriangleMeshOps.make(out -> O3dNative.o3d_trianglemesh_create_icosahedron(out, radius));
    }

    // ---- oriented boxes and convex hull ----------------------------------------------------------

    /** Oriented box of the vertices (get_oriented_bounding_box). */
    public OrientedBoundingBox getOrientedBoundingBox(boolean robust) {
        o3d_obb_t b = new o3d_obb_t();
        try {
            O3dNative.o3d_trianglemesh_get_oriented_bounding_box(b, handle(), robust ? 1 : 0);
            Reference.reachabilityFence(this);
            return OrientedBoundingBox.fromNative(b);
        } finally {
            b.delete();
        }
    }

    public OrientedBoundingBox getOrientedBoundingBox() { return getOrientedBoundingBox(false); }

    /** New mesh of the triangles whose three vertices lie inside {@code box} (crop). */
    public TriangleMesh crop(OrientedBoundingBox box) {
        Objects.requireNonNull(box, "box");
        long[] h = new long[1];
        o3d_obb_t b = box.toNative();
        try {
            O3dNative.o3d_trianglemesh_crop_obb(h, handle(), b);
        } finally {
            b.delete();
        }
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    /** Convex hull of the vertices (compute_convex_hull). */
    public ConvexHullResult computeConvexHull(boolean joggleInputs) {
        int cap = Math.toIntExact(numVertices());
        int[] indices = new int[cap];
        long[] h = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_trianglemesh_compute_convex_hull(h, indices, cap, n, handle(), joggleInputs ? 1 : 0);
        Reference.reachabilityFence(this);
        return new ConvexHullResult(wrap(h), trimTo(indices, n[0]));
    }

    public ConvexHullResult computeConvexHull() { return computeConvexHull(false); }
}
