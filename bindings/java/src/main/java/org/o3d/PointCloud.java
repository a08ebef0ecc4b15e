// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * A point cloud (o3d.geometry.PointCloud): points, normals and colors as (N x 3) row-major double
 * arrays. Getters copy out and setters copy in, one native call each. Close it (try-with-resources);
 * a Cleaner destroys forgotten clouds.
 */
public final class PointCloud extends NativeResource {
    PointCloud(long handle) {
        super(handle, O3dNative::o3d_pointcloud_destroy);
    }

    private static long create() {
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_create(h);
        return h[0];
    }

    /** An empty cloud. */
    public PointCloud() {
        this(create());
    }

    /** A cloud with the given (N x 3) points. */
    public PointCloud(double[] points) {
        this(create());
        try {
            setPoints(points);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    static PointCloud wrap(long[] h) {
        return new PointCloud(h[0]);
    }

    /** Deep copy. */
    public PointCloud copy() {
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_clone(h, handle());
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    /** Number of points. */
    public long size() {
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_size(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    public boolean hasPoints() {
        int[] v = new int[1];
        O3dNative.o3d_pointcloud_has_array(v, handle(), O3D_POINTCLOUD_POINTS);
        Reference.reachabilityFence(this);
        return v[0] != 0;
    }

    public boolean hasNormals() {
        int[] v = new int[1];
        O3dNative.o3d_pointcloud_has_array(v, handle(), O3D_POINTCLOUD_NORMALS);
        Reference.reachabilityFence(this);
        return v[0] != 0;
    }

    public boolean hasColors() {
        int[] v = new int[1];
        O3dNative.o3d_pointcloud_has_array(v, handle(), O3D_POINTCLOUD_COLORS);
        Reference.reachabilityFence(this);
        return v[0] != 0;
    }

    /** Remove points, normals and colors. */
    public void clear() {
        O3dNative.o3d_pointcloud_clear(handle());
        Reference.reachabilityFence(this);
    }

    private interface Getter {
        int get(long pc, double[] out, long capacity, long[] outN);
    }

    private double[] copyOut(Getter g) {
        long h = handle();
        long[] n = new long[1];
        g.get(h, null, 0, n); // count query
        if (n[0] * 3 > Integer.MAX_VALUE - 8) throw new IllegalStateException("cloud too large for a Java array");
        double[] out = new double[(int) (n[0] * 3)];
        g.get(h, out, n[0], n);
        Reference.reachabilityFence(this);
        return out;
    }

    /** Points as x0,y0,z0,x1,... (a copy). */
    public double[] getPoints() { return copyOut(O3dNative::o3d_pointcloud_get_points); }
    /** Normals (a copy; empty when none). */
    public double[] getNormals() { return copyOut(O3dNative::o3d_pointcloud_get_normals); }
    /** Colors, RGB in [0,1] (a copy; empty when none). */
    public double[] getColors() { return copyOut(O3dNative::o3d_pointcloud_get_colors); }

    /** Replace the points (length 3N, copied once). */
    public void setPoints(double[] xyz) {
        O3dNative.o3d_pointcloud_set_array(handle(), O3D_POINTCLOUD_POINTS, xyz, rows3(xyz.length, "xyz"));
        Reference.reachabilityFence(this);
    }

    /** Replace the points from float32 (converted in the single copy). */
    public void setPoints(float[] xyz) {
        O3dNative.o3d_pointcloud_set_array_f32(handle(), O3D_POINTCLOUD_POINTS, xyz, rows3(xyz.length, "xyz"));
        Reference.reachabilityFence(this);
    }

    public void setNormals(double[] xyz) {
        O3dNative.o3d_pointcloud_set_array(handle(), O3D_POINTCLOUD_NORMALS, xyz, rows3(xyz.length, "xyz"));
        Reference.reachabilityFence(this);
    }

    public void setNormals(float[] xyz) {
        O3dNative.o3d_pointcloud_set_array_f32(handle(), O3D_POINTCLOUD_NORMALS, xyz, rows3(xyz.length, "xyz"));
        Reference.reachabilityFence(this);
    }

    public void setColors(double[] rgb) {
        O3dNative.o3d_pointcloud_set_array(handle(), O3D_POINTCLOUD_COLORS, rgb, rows3(rgb.length, "rgb"));
        Reference.reachabilityFence(this);
    }

    public void setColors(float[] rgb) {
        O3dNative.o3d_pointcloud_set_array_f32(handle(), O3D_POINTCLOUD_COLORS, rgb, rows3(rgb.length, "rgb"));
        Reference.reachabilityFence(this);
    }

    // ---- borrowed views ------------------------------------------------------------------------
    // A view is a direct ByteBuffer (native byte order) over the cloud's own storage: rows x 3
    // doubles; use asDoubleBuffer(). It is valid ONLY until the next mutating call on this cloud or
    // close(); using it afterwards reads freed memory. Read-only views are returned read-only.

    private interface ViewFn {
        int view(long pc, long[] data, long[] n);
    }

    private ByteBuffer view(ViewFn fn, boolean writable) {
        long[] data = new long[1];
        long[] n = new long[1];
        fn.view(handle(), data, n);
        Reference.reachabilityFence(this);
        ByteBuffer b = O3dNative.o3dj_direct_buffer(data[0], n[0] * 3 * Double.BYTES);
        if (b == null) b = ByteBuffer.allocateDirect(0);
        b.order(ByteOrder.nativeOrder());
        return writable ? b : b.asReadOnlyBuffer().order(ByteOrder.nativeOrder());
    }

    public ByteBuffer pointsView() { return view(O3dNative::o3d_pointcloud_points_view, false); }
    public ByteBuffer normalsView() { return view(O3dNative::o3d_pointcloud_normals_view, false); }
    public ByteBuffer colorsView() { return view(O3dNative::o3d_pointcloud_colors_view, false); }
    public ByteBuffer pointsMutableView() { return view(O3dNative::o3d_pointcloud_points_mutable_view, true); }
    public ByteBuffer normalsMutableView() { return view(O3dNative::o3d_pointcloud_normals_mutable_view, true); }
    public ByteBuffer colorsMutableView() { return view(O3dNative::o3d_pointcloud_colors_mutable_view, true); }

    // ---- geometry --------------------------------------------------------------------------------

    /** Concatenate {@code other} onto this cloud (Open3D {@code pcd += other}). */
    public PointCloud append(PointCloud other) {
        O3dNative.o3d_pointcloud_append(handle(), other.handle());
        Reference.reachabilityFence(other);
        Reference.reachabilityFence(this);
        return this;
    }

    /** Apply a row-major 4x4 transform (16 values). */
    public PointCloud transform(double[] transform) {
        O3dNative.o3d_pointcloud_transform(handle(), fixed(transform, 16, "transform", false));
        Reference.reachabilityFence(this);
        return this;
    }

    /** relative: add {@code t}; otherwise move the center to {@code t}. */
    public PointCloud translate(double[] translation, boolean relative) {
        O3dNative.o3d_pointcloud_translate(handle(), fixed(translation, 3, "translation", false), relative ? 1 : 0);
        Reference.reachabilityFence(this);
        return this;
    }

    public PointCloud translate(double[] translation) { return translate(translation, true); }

    /** Rotate by a row-major 3x3 matrix about {@code center} (null: the cloud's center). */
    public PointCloud rotate(double[] rotation, double[] center) {
        O3dNative.o3d_pointcloud_rotate(handle(), fixed(rotation, 9, "rotation", false), fixed(center, 3, "center", true));
        Reference.reachabilityFence(this);
        return this;
    }

    public PointCloud scale(double scale, double[] center) {
        O3dNative.o3d_pointcloud_scale(handle(), scale, fixed(center, 3, "center", true));
        Reference.reachabilityFence(this);
        return this;
    }

    private interface Vec3Fn {
        int get(long pc, double[] out);
    }

    private double[] vec3(Vec3Fn fn) {
        double[] v = new double[3];
        fn.get(handle(), v);
        Reference.reachabilityFence(this);
        return v;
    }

    public double[] getMinBound() { return vec3(O3dNative::o3d_pointcloud_get_min_bound); }
    public double[] getMaxBound() { return vec3(O3dNative::o3d_pointcloud_get_max_bound); }
    public double[] getCenter() { return vec3(O3dNative::o3d_pointcloud_get_center); }

    /** Axis-aligned bounding box: {min, max}. */
    public double[][] getAxisAlignedBoundingBox() {
        double[] min = new double[3];
        double[] max = new double[3];
        O3dNative.o3d_pointcloud_get_axis_aligned_bounding_box(min, max, handle());
        Reference.reachabilityFence(this);
        return new double[][] {min, max};
    }

    public PointCloud paintUniformColor(double[] rgb) {
        O3dNative.o3d_pointcloud_paint_uniform_color(handle(), fixed(rgb, 3, "rgb", false));
        Reference.reachabilityFence(this);
        return this;
    }

    /** New cloud with the points at {@code indices} (or all others when invert). */
    public PointCloud selectByIndex(int[] indices, boolean invert) {
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_select_by_index(h, handle(), indices, indices.length, invert ? 1 : 0);
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    public PointCloud selectByIndex(int[] indices) { return selectByIndex(indices, false); }

    public PointCloud removeNonFinitePoints(boolean removeNan, boolean removeInfinite) {
        O3dNative.o3d_pointcloud_remove_non_finite_points(handle(), removeNan ? 1 : 0, removeInfinite ? 1 : 0);
        Reference.reachabilityFence(this);
        return this;
    }

    public PointCloud normalizeNormals() {
        O3dNative.o3d_pointcloud_normalize_normals(handle());
        Reference.reachabilityFence(this);
        return this;
    }

    // ---- down-sampling -----------------------------------------------------------------------------

    /** Average points (normals, colors) per voxel of edge {@code voxelSize} &gt; 0. */
    public PointCloud voxelDownSample(double voxelSize) {
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_voxel_down_sample(h, handle(), voxelSize);
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    public PointCloud uniformDownSample(long everyKPoints) {
        if (everyKPoints < 0) throw new IllegalArgumentException("everyKPoints < 0");
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_uniform_down_sample(h, handle(), everyKPoints);
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    /** Keep round(ratio * N) random points; same seed, same output. The seed is an unsigned 64-bit value. */
    public PointCloud randomDownSample(double samplingRatio, long seed) {
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_random_down_sample(h, handle(), samplingRatio, seed);
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    public PointCloud farthestPointDownSample(long numSamples, long startIndex) {
        if (numSamples < 0 || startIndex < 0) throw new IllegalArgumentException("negative count");
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_farthest_point_down_sample(h, handle(), numSamples, startIndex);
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    // ---- normals -----------------------------------------------------------------------------------

    /** PCA normals over each point's neighbourhood (null param: KNN 30); numThreads 0 = default. */
    public void estimateNormals(SearchParam param, int numThreads) {
        o3d_search_param_t p = param != null ? param.toNative() : null;
        try {
            O3dNative.o3d_pointcloud_estimate_normals(handle(), p, numThreads);
        } finally {
            if (p != null) p.delete();
        }
        Reference.reachabilityFence(this);
    }

    public void estimateNormals(SearchParam param) { estimateNormals(param, 0); }
    public void estimateNormals() { estimateNormals(null, 0); }

    /** Flip normals towards {@code direction} (null: +Z). */
    public void orientNormalsToAlignWithDirection(double[] direction) {
        O3dNative.o3d_pointcloud_orient_normals_to_align_with_direction(handle(), fixed(direction, 3, "direction", true));
        Reference.reachabilityFence(this);
    }

    /** Flip normals towards {@code cameraLocation} (null: origin). */
    public void orientNormalsTowardsCameraLocation(double[] cameraLocation) {
        O3dNative.o3d_pointcloud_orient_normals_towards_camera_location(handle(), fixed(cameraLocation, 3, "cameraLocation", true));
        Reference.reachabilityFence(this);
    }

    /** Distance from each point to its nearest other point. */
    public double[] computeNearestNeighborDistance(int numThreads) {
        long n = size();
        double[] out = new double[(int) n];
        long[] outN = new long[1];
        O3dNative.o3d_pointcloud_compute_nearest_neighbor_distance(out, n, outN, handle(), numThreads);
        Reference.reachabilityFence(this);
        return out;
    }

    /** For each point of this cloud, the distance to the closest point of {@code target}. */
    public double[] computePointCloudDistance(PointCloud target, int numThreads) {
        long n = size();
        double[] out = new double[(int) n];
        long[] outN = new long[1];
        O3dNative.o3d_pointcloud_compute_point_cloud_distance(out, n, outN, handle(), target.handle(), numThreads);
        Reference.reachabilityFence(target);
        Reference.reachabilityFence(this);
        return out;
    }

    // ---- filters, segmentation, statistics ---------------------------------------------------------

    /** Indices are at most size(), so a size()-long buffer always fits; trimmed to the reported count. */
    private int capacity() {
        return Math.toIntExact(size());
    }

    private static int[] trim(int[] values, long n) {
        return n == values.length ? values : java.util.Arrays.copyOf(values, (int) n);
    }

    private interface OutlierFn {
        int call(long[] out, long pc, int a, double b, int[] indices, long capacity, long[] outN);
    }

    private OutlierRemovalResult removeOutliers(OutlierFn fn, int a, double b) {
        int cap = capacity();
        int[] indices = new int[cap];
        long[] h = new long[1];
        long[] n = new long[1];
        fn.call(h, handle(), a, b, indices, cap, n);
        Reference.reachabilityFence(this);
        return new OutlierRemovalResult(wrap(h), trim(indices, n[0]));
    }

    /**
     * Statistical outlier removal (o3d.geometry.PointCloud.remove_statistical_outlier): drop the points
     * whose mean distance to their {@code nbNeighbors} nearest points exceeds the cloud's mean of that
     * distance by more than {@code stdRatio} standard deviations.
     * @throws O3dException INVALID_ARGUMENT when nbNeighbors &lt; 1, stdRatio &lt;= 0 or the cloud is empty
     */
    public OutlierRemovalResult removeStatisticalOutlier(int nbNeighbors, double stdRatio) {
        return removeOutliers(O3dNative::o3d_pointcloud_remove_statistical_outlier, nbNeighbors, stdRatio);
    }

    /**
     * Radius outlier removal (remove_radius_outlier): keep the points with at least {@code nbPoints}
     * other points closer than {@code radius}.
     * @throws O3dException INVALID_ARGUMENT when nbPoints &lt; 1, radius &lt;= 0 or the cloud is empty
     */
    public OutlierRemovalResult removeRadiusOutlier(int nbPoints, double radius) {
        return removeOutliers(O3dNative::o3d_pointcloud_remove_radius_outlier, nbPoints, radius);
    }

    /**
     * New cloud with the points inside the box {@code min}..{@code max} (bounds inclusive), or outside
     * it when {@code invert} (o3d.geometry.PointCloud.crop with an AxisAlignedBoundingBox).
     */
    public PointCloud cropAabb(double[] min, double[] max, boolean invert) {
        long[] h = new long[1];
        O3dNative.o3d_pointcloud_crop_aabb(h, handle(), fixed(min, 3, "min", false), fixed(max, 3, "max", false),
                invert ? 1 : 0);
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    public PointCloud cropAabb(double[] min, double[] max) { return cropAabb(min, max, false); }

    /**
     * RANSAC plane segmentation (segment_plane), deterministic for a seed whatever the thread count.
     * The seed is an unsigned 64-bit value.
     * @throws O3dException INVALID_ARGUMENT on a negative threshold, ransacN &lt; 3, numIterations &lt; 1,
     *     probability outside (0, 1] or fewer than ransacN points; NOT_CONVERGED when every sample was degenerate
     */
    public PlaneSegmentationResult segmentPlane(double distanceThreshold, int ransacN, int numIterations,
            double probability, long seed) {
        int cap = capacity();
        double[] plane = new double[4];
        int[] inliers = new int[cap];
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_segment_plane(plane, inliers, cap, n, handle(), distanceThreshold, ransacN,
                numIterations, probability, seed);
        Reference.reachabilityFence(this);
        return new PlaneSegmentationResult(plane, trim(inliers, n[0]));
    }

    /** {@link #segmentPlane(double, int, int, double, long)} with Open3D's probability 0.99999999 and seed 0. */
    public PlaneSegmentationResult segmentPlane(double distanceThreshold, int ransacN, int numIterations) {
        return segmentPlane(distanceThreshold, ransacN, numIterations, 0.99999999, 0);
    }

    /**
     * DBSCAN (cluster_dbscan): one label per point, clusters 0, 1, ... in order of their lowest point
     * index, -1 for noise.
     */
    public int[] clusterDbscan(double eps, int minPoints) {
        int cap = capacity();
        int[] labels = new int[cap];
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_cluster_dbscan(labels, cap, n, handle(), eps, minPoints);
        Reference.reachabilityFence(this);
        return trim(labels, n[0]);
    }

    /** Mean and covariance (row-major 3x3, divided by N) of the points. @throws O3dException on an empty cloud */
    public MeanAndCovariance computeMeanAndCovariance() {
        double[] mean = new double[3];
        double[] covariance = new double[9];
        O3dNative.o3d_pointcloud_compute_mean_and_covariance(mean, covariance, handle());
        Reference.reachabilityFence(this);
        return new MeanAndCovariance(mean, covariance);
    }

    /** Mahalanobis distance of each point to the cloud's distribution. */
    public double[] computeMahalanobisDistance() {
        int cap = capacity();
        double[] out = new double[cap];
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_compute_mahalanobis_distance(out, cap, n, handle());
        Reference.reachabilityFence(this);
        return out;
    }

    // ---- from depth and RGB-D images (rgbd.h) ------------------------------------------------------

    /**
     * Back-project a 1-channel depth image (uint16 raw, or float32 metres) through {@code intrinsic}, then
     * to world coordinates with the inverse of {@code extrinsic} (row-major 4x4; null: identity).
     * Open3D's PointCloud.create_from_depth_image; stride: every stride-th pixel; projectValidDepthOnly
     * false keeps invalid pixels as NaN points (an organised cloud).
     */
    public static PointCloud createFromDepthImage(Image depth, PinholeCameraIntrinsic intrinsic, double[] extrinsic,
            double depthScale, double depthTrunc, int stride, boolean projectValidDepthOnly) {
        java.util.Objects.requireNonNull(depth, "depth");
        java.util.Objects.requireNonNull(intrinsic, "intrinsic");
        double[] e = fixed(extrinsic, 16, "extrinsic", true);
        long[] h = new long[1];
        o3d_pinhole_intrinsic_t k = intrinsic.toNative();
        o3d_depth_to_cloud_options_t o = new o3d_depth_to_cloud_options_t();
        try {
            O3dNative.o3d_depth_to_cloud_options_init(o, O3dNative.o3dx_sizeof_depth_to_cloud_options());
            o.setDepth_scale(depthScale);
            o.setDepth_trunc(depthTrunc);
            o.setStride(stride);
            o.setProject_valid_depth_only(projectValidDepthOnly ? 1 : 0);
            O3dNative.o3d_pointcloud_create_from_depth_image(h, depth.handle(), k, e, o);
        } finally {
            o.delete();
            k.delete();
        }
        Reference.reachabilityFence(depth);
        return wrap(h);
    }

    /** With Open3D's defaults: identity extrinsic, depth scale 1000, truncation 1000 m, stride 1, valid depth only. */
    public static PointCloud createFromDepthImage(Image depth, PinholeCameraIntrinsic intrinsic) {
        return createFromDepthImage(depth, intrinsic, null, 1000.0, 1000.0, 1, true);
    }

    /** As createFromDepthImage for an RGB-D image, with per-point colors (extrinsic null: identity). */
    public static PointCloud createFromRGBDImage(RGBDImage image, PinholeCameraIntrinsic intrinsic, double[] extrinsic,
            boolean projectValidDepthOnly) {
        java.util.Objects.requireNonNull(image, "image");
        java.util.Objects.requireNonNull(intrinsic, "intrinsic");
        double[] e = fixed(extrinsic, 16, "extrinsic", true);
        long[] h = new long[1];
        o3d_pinhole_intrinsic_t k = intrinsic.toNative();
        try {
            O3dNative.o3d_pointcloud_create_from_rgbd_image(h, image.handle(), k, e, projectValidDepthOnly ? 1 : 0);
        } finally {
            k.delete();
        }
        Reference.reachabilityFence(image);
        return wrap(h);
    }

    public static PointCloud createFromRGBDImage(RGBDImage image, PinholeCameraIntrinsic intrinsic) {
        return createFromRGBDImage(image, intrinsic, null, true);
    }

    // ---- oriented boxes, convex hull, hidden-point removal ----------------------------------------

    /** Oriented box of the points (get_oriented_bounding_box); robust joggles degenerate sets. */
    public OrientedBoundingBox getOrientedBoundingBox(boolean robust) {
        o3d_obb_t b = new o3d_obb_t();
        try {
            O3dNative.o3d_pointcloud_get_oriented_bounding_box(b, handle(), robust ? 1 : 0);
            Reference.reachabilityFence(this);
            return OrientedBoundingBox.fromNative(b);
        } finally {
            b.delete();
        }
    }

    public OrientedBoundingBox getOrientedBoundingBox() { return getOrientedBoundingBox(false); }

    /** New cloud with the points inside {@code box} (outside when {@code invert}) (crop). */
    public PointCloud crop(OrientedBoundingBox box, boolean invert) {
        java.util.Objects.requireNonNull(box, "box");
        long[] h = new long[1];
        o3d_obb_t b = box.toNative();
        try {
            O3dNative.o3d_pointcloud_crop_obb(h, handle(), b, invert ? 1 : 0);
        } finally {
            b.delete();
        }
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    public PointCloud crop(OrientedBoundingBox box) { return crop(box, false); }

    /**
     * Convex hull of the points through Qhull (compute_convex_hull): at least 4 points, not coplanar
     * unless {@code joggleInputs}.
     */
    public ConvexHullResult computeConvexHull(boolean joggleInputs) {
        int cap = capacity();
        int[] indices = new int[cap];
        long[] h = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_compute_convex_hull(h, indices, cap, n, handle(), joggleInputs ? 1 : 0);
        Reference.reachabilityFence(this);
        return new ConvexHullResult(TriangleMesh.wrap(h), trim(indices, n[0]));
    }

    public ConvexHullResult computeConvexHull() { return computeConvexHull(false); }

    /**
     * The points visible from {@code cameraLocation} (hidden_point_removal, Katz et al. 2007): the hull
     * mesh and the indices of the visible points. A larger {@code radius} keeps more points.
     */
    public ConvexHullResult hiddenPointRemoval(double[] cameraLocation, double radius) {
        double[] cam = fixed(cameraLocation, 3, "cameraLocation", false);
        int cap = capacity() + 1;
        int[] indices = new int[cap];
        long[] h = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_hidden_point_removal(h, indices, cap, n, handle(), cam, radius);
        Reference.reachabilityFence(this);
        return new ConvexHullResult(TriangleMesh.wrap(h), trim(indices, n[0]));
    }

    // ---- per-point covariances ----------------------------------------------------------------------

    /** True when the cloud has one covariance per point. */
    public boolean hasCovariances() {
        int[] v = new int[1];
        O3dNative.o3d_pointcloud_has_array(v, handle(), O3D_POINTCLOUD_COVARIANCES);
        Reference.reachabilityFence(this);
        return v[0] != 0;
    }

    /** Covariances: N row-major 3x3 matrices, 9N values (a copy). */
    public double[] getCovariances() {
        long h = handle();
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_get_array(null, 0, n, h, O3D_POINTCLOUD_COVARIANCES);
        if (n[0] * 9 > Integer.MAX_VALUE - 8) throw new IllegalStateException("cloud too large for a Java array");
        double[] out = new double[(int) (n[0] * 9)];
        O3dNative.o3d_pointcloud_get_array(out, n[0], n, h, O3D_POINTCLOUD_COVARIANCES);
        Reference.reachabilityFence(this);
        return out;
    }

    /** Replace the covariances (9 values per point, copied once). */
    public void setCovariances(double[] covariances) {
        java.util.Objects.requireNonNull(covariances, "covariances");
        if (covariances.length % 9 != 0)
            throw new IllegalArgumentException("covariances: length " + covariances.length + " is not a multiple of 9");
        O3dNative.o3d_pointcloud_set_array(handle(), O3D_POINTCLOUD_COVARIANCES, covariances, covariances.length / 9);
        Reference.reachabilityFence(this);
    }

    /** Borrowed read-only view of the covariances (rows x 9 doubles), valid as the other views. */
    public ByteBuffer covariancesView() {
        long[] data = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_pointcloud_array_view(data, n, handle(), O3D_POINTCLOUD_COVARIANCES);
        Reference.reachabilityFence(this);
        return readOnlyView(data[0], n[0] * 9 * Double.BYTES);
    }

    /** Covariance of each point's neighbourhood (estimate_covariances; null param: KNN 30). */
    public PointCloud estimateCovariances(SearchParam param) {
        o3d_search_param_t p = param != null ? param.toNative() : null;
        try {
            O3dNative.o3d_pointcloud_estimate_covariances(handle(), p);
        } finally {
            if (p != null) p.delete();
        }
        Reference.reachabilityFence(this);
        return this;
    }

    public PointCloud estimateCovariances() { return estimateCovariances(null); }
}
