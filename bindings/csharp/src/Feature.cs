// SPDX-License-Identifier: MIT
using System;
using System.Runtime.InteropServices;

namespace O3d
{
    /// <summary>
    /// Per-point descriptors (o3d.pipelines.registration.Feature): a <see cref="Dimension"/> x <see cref="Num"/>
    /// matrix of doubles stored descriptor by descriptor (descriptor i is Data[i * Dimension .. (i + 1) * Dimension - 1]).
    /// Dispose it (or use <c>using</c>); a finalizer destroys forgotten features.
    /// </summary>
    public sealed class Feature : NativeHandle
    {
        internal Feature(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_feature_destroy(handle); }

        static IntPtr Create(long dimension, long num)
        {
            IntPtr h;
            O3dNative.o3d_feature_create(out h, Checks.Count(dimension, "dimension"), Checks.Count(num, "num"));
            return h;
        }

        static IntPtr CreateFromData(double[] data, long dimension, long num)
        {
            if (data == null) throw new ArgumentNullException("data");
            ulong d = Checks.Count(dimension, "dimension"), n = Checks.Count(num, "num");
            if ((ulong)data.Length != d * n)
                throw new ArgumentException("data: expected " + (d * n) + " values (dimension x num), got " + data.Length, "data");
            IntPtr h;
            O3dNative.o3d_feature_create_from_data(out h, data, d, n);
            return h;
        }

        /// <summary>A <paramref name="dimension"/> x <paramref name="num"/> feature of zeros (both may be 0).</summary>
        public Feature(long dimension = 0, long num = 0) : base(Create(dimension, num)) { }

        /// <summary>A feature holding a copy of <paramref name="data"/> (dimension * num values; non-finite values throw).</summary>
        public Feature(double[] data, long dimension, long num) : base(CreateFromData(data, dimension, num)) { }

        /// <summary>Deep copy.</summary>
        public Feature Clone()
        {
            IntPtr h;
            O3dNative.o3d_feature_clone(out h, Handle);
            GC.KeepAlive(this);
            return new Feature(h);
        }

        /// <summary>Descriptor length (33 for FPFH).</summary>
        public long Dimension { get { ulong v; O3dNative.o3d_feature_dimension(out v, Handle); GC.KeepAlive(this); return (long)v; } }

        /// <summary>Number of descriptors (points).</summary>
        public long Num { get { ulong v; O3dNative.o3d_feature_num(out v, Handle); GC.KeepAlive(this); return (long)v; } }

        /// <summary>
        /// All Dimension * Num values, descriptor by descriptor (a copy). Setting copies the array in; its
        /// length must be Dimension * Num (use <see cref="Resize"/> first to change the shape).
        /// </summary>
        public double[] Data
        {
            get
            {
                var values = new double[checked(Dimension * Num)];
                O3dNative.o3d_feature_get_data(values, (ulong)values.Length, Handle);
                GC.KeepAlive(this);
                return values;
            }
            set
            {
                if (value == null) throw new ArgumentNullException("value");
                long size = checked(Dimension * Num);
                if (value.Length != size)
                    throw new ArgumentException("value: expected " + size + " values (dimension x num), got " + value.Length, "value");
                IntPtr view = DataView();
                if (size > 0) Marshal.Copy(value, 0, view, value.Length);
                GC.KeepAlive(this);
            }
        }

        /// <summary>
        /// Borrowed, writable address of the Dimension * Num doubles (IntPtr.Zero when empty), valid until the
        /// feature is resized or disposed; keep the feature alive (GC.KeepAlive) while using it.
        /// </summary>
        public IntPtr DataView()
        {
            IntPtr view;
            O3dNative.o3d_feature_data(out view, Handle);
            GC.KeepAlive(this);
            return view;
        }

        /// <summary>Resize to dimension x num (Feature.resize): kept values stay when the dimension is unchanged, new ones are zero.</summary>
        public void Resize(long dimension, long num)
        {
            O3dNative.o3d_feature_resize(Handle, Checks.Count(dimension, "dimension"), Checks.Count(num, "num"));
            GC.KeepAlive(this);
        }

        /// <summary>The descriptors of <paramref name="indices"/> in that order, or of every other point (ascending) when inverted.</summary>
        public Feature SelectByIndex(long[] indices, bool invert = false)
        {
            if (indices == null) throw new ArgumentNullException("indices");
            IntPtr h;
            O3dNative.o3d_feature_select_by_index(out h, Handle, indices, (ulong)indices.Length, invert ? 1 : 0);
            GC.KeepAlive(this);
            return new Feature(h);
        }
    }

    public static partial class Registration
    {
        /// <summary>
        /// Fast Point Feature Histograms, 33 x N (compute_fpfh_feature); the cloud needs normals. <paramref name="param"/>
        /// null = KNN 30 (Open3D's tutorial: Hybrid(0.25, 100) on a 0.05 voxel grid). With <paramref name="indices"/> only
        /// those points get a descriptor. The result does not depend on <paramref name="numThreads"/> (0 = default).
        /// </summary>
        public static Feature ComputeFpfhFeature(PointCloud cloud, SearchParam param = null, long[] indices = null, int numThreads = 0)
        {
            if (cloud == null) throw new ArgumentNullException("cloud");
            IntPtr h;
            using (var p = param != null ? param.ToNative() : null)
                O3dNative.o3d_compute_fpfh_feature(out h, cloud.Handle, p, indices, indices == null ? 0UL : (ulong)indices.Length, numThreads);
            GC.KeepAlive(cloud);
            return new Feature(h);
        }

        /// <summary>
        /// Each source descriptor's nearest target descriptor as flattened (source, target) pairs in ascending source
        /// order (correspondences_from_features). With <paramref name="mutualFilter"/> only mutual nearest pairs are kept,
        /// unless fewer than <paramref name="mutualConsistencyRatio"/> * Num(source) survive (then all pairs).
        /// </summary>
        public static int[] CorrespondencesFromFeatures(Feature source, Feature target, bool mutualFilter = false,
                                                        double mutualConsistencyRatio = 0.1, int numThreads = 0)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            var pairs = new int[checked(2 * source.Num)];
            ulong n;
            O3dNative.o3d_correspondences_from_features(pairs, (ulong)(pairs.Length / 2), out n, source.Handle,
                                                        target.Handle, mutualFilter ? 1 : 0, mutualConsistencyRatio,
                                                        numThreads);
            GC.KeepAlive(source); GC.KeepAlive(target);
            return Checks.Trim(pairs, 2 * n);
        }
    }

    public static partial class IO
    {
        /// <summary>Read Open3D's binary feature file (int32 dimension, int32 num, num x dimension float64); bad files throw Parse.</summary>
        public static Feature ReadFeature(string path)
        {
            if (path == null) throw new ArgumentNullException("path");
            IntPtr h;
            O3dNative.o3d_io_read_feature(out h, path);
            return new Feature(h);
        }

        /// <summary>Write <paramref name="feature"/> in the layout ReadFeature reads.</summary>
        public static void WriteFeature(string path, Feature feature)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (feature == null) throw new ArgumentNullException("feature");
            O3dNative.o3d_io_write_feature(path, feature.Handle);
            GC.KeepAlive(feature);
        }
    }
}
