// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>
    /// A point cloud (o3d.geometry.PointCloud): points, normals and colors as (N x 3) row-major
    /// double arrays. Properties copy out on get and copy in on set, in one native call each.
    /// Dispose it (or use <c>using</c>); a finalizer destroys forgotten clouds.
    /// </summary>
    public sealed partial class PointCloud : NativeHandle
    {
        internal PointCloud(IntPtr handle) : base(handle) { }

        internal override void Destroy(IntPtr handle) { O3dNative.o3d_pointcloud_destroy(handle); }

        static IntPtr Create()
        {
            IntPtr h;
            O3dNative.o3d_pointcloud_create(out h);
            return h;
        }

        /// <summary>An empty cloud.</summary>
        public PointCloud() : base(Create()) { }

        /// <summary>A cloud with the given (N x 3) points.</summary>
        public PointCloud(double[] points) : this() { Points = points; }

        /// <summary>Deep copy.</summary>
        public PointCloud Clone()
        {
            IntPtr h;
            O3dNative.o3d_pointcloud_clone(out h, Handle);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        /// <summary>Number of points.</summary>
        public long Size
        {
            get { ulong n; O3dNative.o3d_pointcloud_size(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        public bool HasPoints { get { int v; O3dNative.o3d_pointcloud_has_array(out v, Handle, O3D_POINTCLOUD_POINTS); GC.KeepAlive(this); return v != 0; } }
        public bool HasNormals { get { int v; O3dNative.o3d_pointcloud_has_array(out v, Handle, O3D_POINTCLOUD_NORMALS); GC.KeepAlive(this); return v != 0; } }
        public bool HasColors { get { int v; O3dNative.o3d_pointcloud_has_array(out v, Handle, O3D_POINTCLOUD_COLORS); GC.KeepAlive(this); return v != 0; } }

        /// <summary>Remove points, normals and colors.</summary>
        public void Clear() { O3dNative.o3d_pointcloud_clear(Handle); GC.KeepAlive(this); }

        delegate int Getter(IntPtr pc, double[] out_, ulong capacity, out ulong n);

        double[] CopyOut(Getter get)
        {
            IntPtr h = Handle;
            ulong n;
            get(h, null, 0, out n); // count query
            var result = new double[checked((long)n * 3)];
            get(h, result, n, out n);
            GC.KeepAlive(this);
            return result;
        }

        /// <summary>Points as x0,y0,z0,x1,... (a copy). Setting copies the array in (length 3N).</summary>
        public double[] Points
        {
            get { return CopyOut(O3dNative.o3d_pointcloud_get_points); }
            set { O3dNative.o3d_pointcloud_set_array(Handle, O3D_POINTCLOUD_POINTS, value, Checks.Rows3(value, "value")); GC.KeepAlive(this); }
        }

        /// <summary>Normals (a copy; empty when none). Setting copies the array in.</summary>
        public double[] Normals
        {
            get { return CopyOut(O3dNative.o3d_pointcloud_get_normals); }
            set { O3dNative.o3d_pointcloud_set_array(Handle, O3D_POINTCLOUD_NORMALS, value, Checks.Rows3(value, "value")); GC.KeepAlive(this); }
        }

        /// <summary>Colors, RGB in [0,1] (a copy; empty when none). Setting copies the array in.</summary>
        public double[] Colors
        {
            get { return CopyOut(O3dNative.o3d_pointcloud_get_colors); }
            set { O3dNative.o3d_pointcloud_set_array(Handle, O3D_POINTCLOUD_COLORS, value, Checks.Rows3(value, "value")); GC.KeepAlive(this); }
        }

        /// <summary>Set the points from float32 (converted in the single copy).</summary>
        public void SetPoints(float[] xyz) { O3dNative.o3d_pointcloud_set_array_f32(Handle, O3D_POINTCLOUD_POINTS, xyz, Checks.Rows3(xyz, "xyz")); GC.KeepAlive(this); }
        public void SetPoints(double[] xyz) { Points = xyz; }
        public void SetNormals(float[] xyz) { O3dNative.o3d_pointcloud_set_array_f32(Handle, O3D_POINTCLOUD_NORMALS, xyz, Checks.Rows3(xyz, "xyz")); GC.KeepAlive(this); }
        public void SetNormals(double[] xyz) { Normals = xyz; }
        public void SetColors(float[] rgb) { O3dNative.o3d_pointcloud_set_array_f32(Handle, O3D_POINTCLOUD_COLORS, rgb, Checks.Rows3(rgb, "rgb")); GC.KeepAlive(this); }
        public void SetColors(double[] rgb) { Colors = rgb; }

        // ---- borrowed views -------------------------------------------------------------------
        // A view is the address of the cloud's own storage: `rows` rows of 3 doubles (IntPtr.Zero when
        // empty). It is valid only until the next mutating call on this cloud, or Dispose; keep the
        // cloud alive (GC.KeepAlive) while using it. Read with Marshal.Copy(view, array, 0, rows * 3)
        // or unsafe code; write only through the *MutableView addresses.

        delegate int ViewFn(IntPtr pc, out IntPtr data, out ulong n);

        IntPtr View(ViewFn fn, out long rows)
        {
            IntPtr data;
            ulong n;
            fn(Handle, out data, out n);
            GC.KeepAlive(this);
            rows = (long)n;
            return data;
        }

        public IntPtr PointsView(out long rows) { return View(O3dNative.o3d_pointcloud_points_view, out rows); }
        public IntPtr NormalsView(out long rows) { return View(O3dNative.o3d_pointcloud_normals_view, out rows); }
        public IntPtr ColorsView(out long rows) { return View(O3dNative.o3d_pointcloud_colors_view, out rows); }
        public IntPtr PointsMutableView(out long rows) { return View(O3dNative.o3d_pointcloud_points_mutable_view, out rows); }
        public IntPtr NormalsMutableView(out long rows) { return View(O3dNative.o3d_pointcloud_normals_mutable_view, out rows); }
        public IntPtr ColorsMutableView(out long rows) { return View(O3dNative.o3d_pointcloud_colors_mutable_view, out rows); }

        // ---- geometry ---------------------------------------------------------------------------

        /// <summary>Concatenate <paramref name="other"/> onto this cloud (Open3D <c>pcd += other</c>).</summary>
        public PointCloud Append(PointCloud other)
        {
            if (other == null) throw new ArgumentNullException("other");
            O3dNative.o3d_pointcloud_append(Handle, other.Handle);
            GC.KeepAlive(other); GC.KeepAlive(this);
            return this;
        }

        /// <summary>Apply a row-major 4x4 transform (16 values).</summary>
        public PointCloud Transform(double[] transform)
        {
            O3dNative.o3d_pointcloud_transform(Handle, Checks.Fixed(transform, 16, "transform", false));
            GC.KeepAlive(this); return this;
        }

        public PointCloud Translate(double[] translation, bool relative = true)
        {
            O3dNative.o3d_pointcloud_translate(Handle, Checks.Fixed(translation, 3, "translation", false), relative ? 1 : 0);
            GC.KeepAlive(this); return this;
        }

        /// <summary>Rotate by a row-major 3x3 matrix about <paramref name="center"/> (null: the cloud's center).</summary>
        public PointCloud Rotate(double[] rotation, double[] center = null)
        {
            O3dNative.o3d_pointcloud_rotate(Handle, Checks.Fixed(rotation, 9, "rotation", false), Checks.Fixed(center, 3, "center", true));
            GC.KeepAlive(this); return this;
        }

        public PointCloud Scale(double scale, double[] center = null)
        {
            O3dNative.o3d_pointcloud_scale(Handle, scale, Checks.Fixed(center, 3, "center", true));
            GC.KeepAlive(this); return this;
        }

        delegate int Vec3Fn(IntPtr pc, double[] out_);
        double[] Vec3(Vec3Fn fn) { var v = new double[3]; fn(Handle, v); GC.KeepAlive(this); return v; }

        public double[] MinBound { get { return Vec3(O3dNative.o3d_pointcloud_get_min_bound); } }
        public double[] MaxBound { get { return Vec3(O3dNative.o3d_pointcloud_get_max_bound); } }
        public double[] Center { get { return Vec3(O3dNative.o3d_pointcloud_get_center); } }

        /// <summary>Axis-aligned bounding box as min and max corners.</summary>
        public void GetAxisAlignedBoundingBox(out double[] min, out double[] max)
        {
            min = new double[3]; max = new double[3];
            O3dNative.o3d_pointcloud_get_axis_aligned_bounding_box(min, max, Handle);
            GC.KeepAlive(this);
        }

        public PointCloud PaintUniformColor(double[] rgb)
        {
            O3dNative.o3d_pointcloud_paint_uniform_color(Handle, Checks.Fixed(rgb, 3, "rgb", false));
            GC.KeepAlive(this); return this;
        }

        /// <summary>New cloud with the points at <paramref name="indices"/> (or all others when invert).</summary>
        public PointCloud SelectByIndex(int[] indices, bool invert = false)
        {
            if (indices == null) throw new ArgumentNullException("indices");
            IntPtr h;
            O3dNative.o3d_pointcloud_select_by_index(out h, Handle, indices, (ulong)indices.Length, invert ? 1 : 0);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        public PointCloud RemoveNonFinitePoints(bool removeNan = true, bool removeInfinite = true)
        {
            O3dNative.o3d_pointcloud_remove_non_finite_points(Handle, removeNan ? 1 : 0, removeInfinite ? 1 : 0);
            GC.KeepAlive(this); return this;
        }

        public PointCloud NormalizeNormals() { O3dNative.o3d_pointcloud_normalize_normals(Handle); GC.KeepAlive(this); return this; }

        // ---- down-sampling ------------------------------------------------------------------------

        /// <summary>Average points (normals, colors) per voxel of edge <paramref name="voxelSize"/> &gt; 0.</summary>
        public PointCloud VoxelDownSample(double voxelSize)
        {
            IntPtr h;
            O3dNative.o3d_pointcloud_voxel_down_sample(out h, Handle, voxelSize);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        public PointCloud UniformDownSample(long everyKPoints)
        {
            if (everyKPoints < 0) throw new ArgumentOutOfRangeException("everyKPoints");
            IntPtr h;
            O3dNative.o3d_pointcloud_uniform_down_sample(out h, Handle, (ulong)everyKPoints);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        public PointCloud RandomDownSample(double samplingRatio, ulong seed = 0)
        {
            IntPtr h;
            O3dNative.o3d_pointcloud_random_down_sample(out h, Handle, samplingRatio, seed);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        public PointCloud FarthestPointDownSample(long numSamples, long startIndex = 0)
        {
            if (numSamples < 0) throw new ArgumentOutOfRangeException("numSamples");
            if (startIndex < 0) throw new ArgumentOutOfRangeException("startIndex");
            IntPtr h;
            O3dNative.o3d_pointcloud_farthest_point_down_sample(out h, Handle, (ulong)numSamples, (ulong)startIndex);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        // ---- normals --------------------------------------------------------------------------------

        /// <summary>PCA normals (null param: KNN 30). numThreads 0 = library default.</summary>
        public void EstimateNormals(SearchParam param = null, int numThreads = 0)
        {
            o3d_search_param_t p = param != null ? param.ToNative() : null;
            try { O3dNative.o3d_pointcloud_estimate_normals(Handle, p, numThreads); }
            finally { if (p != null) p.Dispose(); }
            GC.KeepAlive(this);
        }

        /// <summary>Flip normals towards <paramref name="direction"/> (null: +Z).</summary>
        public void OrientNormalsToAlignWithDirection(double[] direction = null)
        {
            O3dNative.o3d_pointcloud_orient_normals_to_align_with_direction(Handle, Checks.Fixed(direction, 3, "direction", true));
            GC.KeepAlive(this);
        }

        /// <summary>Flip normals towards <paramref name="cameraLocation"/> (null: origin).</summary>
        public void OrientNormalsTowardsCameraLocation(double[] cameraLocation = null)
        {
            O3dNative.o3d_pointcloud_orient_normals_towards_camera_location(Handle, Checks.Fixed(cameraLocation, 3, "cameraLocation", true));
            GC.KeepAlive(this);
        }

        /// <summary>Distance from each point to its nearest other point.</summary>
        public double[] ComputeNearestNeighborDistance(int numThreads = 0)
        {
            ulong n = (ulong)Size;
            var result = new double[n];
            O3dNative.o3d_pointcloud_compute_nearest_neighbor_distance(result, n, out n, Handle, numThreads);
            GC.KeepAlive(this);
            return result;
        }

        /// <summary>For each point of this cloud, the distance to the closest point of <paramref name="target"/>.</summary>
        public double[] ComputePointCloudDistance(PointCloud target, int numThreads = 0)
        {
            if (target == null) throw new ArgumentNullException("target");
            ulong n = (ulong)Size;
            var result = new double[n];
            O3dNative.o3d_pointcloud_compute_point_cloud_distance(result, n, out n, Handle, target.Handle, numThreads);
            GC.KeepAlive(target); GC.KeepAlive(this);
            return result;
        }

        // ---- filters, segmentation, statistics ----------------------------------------------------------

        // Indices are at most Size, so a Size-long buffer always fits; trimmed to the reported count.
        static int[] Trim(int[] indices, ulong n)
        {
            if (n == (ulong)indices.Length) return indices;
            var r = new int[n];
            Array.Copy(indices, r, (long)n);
            return r;
        }

        delegate int OutlierFn(out IntPtr out_, IntPtr pc, int a, double b, int[] indices, ulong capacity, out ulong n);

        OutlierRemovalResult RemoveOutliers(OutlierFn fn, int a, double b)
        {
            ulong cap = (ulong)Size;
            var indices = new int[cap];
            IntPtr h;
            ulong n;
            fn(out h, Handle, a, b, indices, cap, out n);
            GC.KeepAlive(this);
            return new OutlierRemovalResult(new PointCloud(h), Trim(indices, n));
        }

        /// <summary>
        /// Statistical outlier removal (o3d.geometry.PointCloud.remove_statistical_outlier): drop the points
        /// whose mean distance to their <paramref name="nbNeighbors"/> nearest points exceeds the cloud's mean
        /// of that distance by more than <paramref name="stdRatio"/> standard deviations.
        /// </summary>
        /// <exception cref="O3dException">InvalidArgument when nbNeighbors &lt; 1, stdRatio &lt;= 0 or the cloud is empty.</exception>
        public OutlierRemovalResult RemoveStatisticalOutlier(int nbNeighbors, double stdRatio)
        {
            return RemoveOutliers(O3dNative.o3d_pointcloud_remove_statistical_outlier, nbNeighbors, stdRatio);
        }

        /// <summary>
        /// Radius outlier removal (remove_radius_outlier): keep the points with at least
        /// <paramref name="nbPoints"/> other points closer than <paramref name="radius"/>.
        /// </summary>
        /// <exception cref="O3dException">InvalidArgument when nbPoints &lt; 1, radius &lt;= 0 or the cloud is empty.</exception>
        public OutlierRemovalResult RemoveRadiusOutlier(int nbPoints, double radius)
        {
            return RemoveOutliers(O3dNative.o3d_pointcloud_remove_radius_outlier, nbPoints, radius);
        }

        /// <summary>
        /// New cloud with the points inside the box <paramref name="min"/>..<paramref name="max"/> (bounds
        /// inclusive), or outside it when <paramref name="invert"/> (o3d.geometry.PointCloud.crop with an
        /// AxisAlignedBoundingBox).
        /// </summary>
        public PointCloud CropAabb(double[] min, double[] max, bool invert = false)
        {
            IntPtr h;
            O3dNative.o3d_pointcloud_crop_aabb(out h, Handle, Checks.Fixed(min, 3, "min", false),
                                               Checks.Fixed(max, 3, "max", false), invert ? 1 : 0);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        /// <summary>
        /// RANSAC plane segmentation (segment_plane). Deterministic for a <paramref name="seed"/>, whatever
        /// the thread count.
        /// </summary>
        /// <exception cref="O3dException">InvalidArgument on a negative threshold, ransacN &lt; 3,
        /// numIterations &lt; 1, probability outside (0, 1] or fewer than ransacN points; NotConverged when
        /// every sample was degenerate.</exception>
        public PlaneSegmentationResult SegmentPlane(double distanceThreshold, int ransacN, int numIterations,
                                                    double probability = 0.99999999, ulong seed = 0)
        {
            ulong cap = (ulong)Size;
            var plane = new double[4];
            var inliers = new int[cap];
            ulong n;
            O3dNative.o3d_pointcloud_segment_plane(plane, inliers, cap, out n, Handle, distanceThreshold, ransacN,
                                                   numIterations, probability, seed);
            GC.KeepAlive(this);
            return new PlaneSegmentationResult(plane, Trim(inliers, n));
        }

        /// <summary>
        /// DBSCAN (cluster_dbscan): one label per point, clusters 0, 1, ... in order of their lowest point
        /// index, -1 for noise.
        /// </summary>
        public int[] ClusterDbscan(double eps, int minPoints)
        {
            ulong cap = (ulong)Size;
            var labels = new int[cap];
            ulong n;
            O3dNative.o3d_pointcloud_cluster_dbscan(labels, cap, out n, Handle, eps, minPoints);
            GC.KeepAlive(this);
            return Trim(labels, n);
        }

        /// <summary>Mean and covariance (row-major 3x3, divided by N) of the points.</summary>
        /// <exception cref="O3dException">InvalidArgument on an empty cloud.</exception>
        public MeanAndCovariance ComputeMeanAndCovariance()
        {
            var mean = new double[3];
            var covariance = new double[9];
            O3dNative.o3d_pointcloud_compute_mean_and_covariance(mean, covariance, Handle);
            GC.KeepAlive(this);
            return new MeanAndCovariance(mean, covariance);
        }

        /// <summary>Mahalanobis distance of each point to the cloud's distribution.</summary>
        public double[] ComputeMahalanobisDistance()
        {
            ulong cap = (ulong)Size;
            var result = new double[cap];
            ulong n;
            O3dNative.o3d_pointcloud_compute_mahalanobis_distance(result, cap, out n, Handle);
            GC.KeepAlive(this);
            return result;
        }
    }
}
