// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>
    /// Flat batch search result copied into managed arrays: neighbours of query i are
    /// Indices[Offsets[i] .. Offsets[i+1]-1], sorted by increasing distance, with squared distances.
    /// </summary>
    public sealed class NeighborResult
    {
        public long[] Offsets { get; private set; }
        public int[] Indices { get; private set; }
        public double[] Distances2 { get; private set; }
        public int NumQueries { get { return Offsets.Length - 1; } }

        internal NeighborResult(long[] offsets, int[] indices, double[] distances2)
        {
            Offsets = offsets; Indices = indices; Distances2 = distances2;
        }

        /// <summary>Neighbour indices of query <paramref name="query"/>.</summary>
        public int[] IndicesOf(int query)
        {
            long b = Offsets[query], e = Offsets[query + 1];
            var r = new int[e - b];
            Array.Copy(Indices, b, r, 0, e - b);
            return r;
        }
    }

    /// <summary>
    /// Native search result (o3d_search_result_t). Use <see cref="ToManaged"/> to copy it out, or
    /// <see cref="GetView"/> for zero-copy access (addresses valid until Dispose).
    /// </summary>
    public sealed class SearchResult : NativeHandle
    {
        internal SearchResult(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_search_result_destroy(handle); }

        /// <summary>Number of queries and total number of neighbours.</summary>
        public void GetCounts(out long numQueries, out long total)
        {
            ulong q, t;
            O3dNative.o3d_search_result_counts(out q, out t, Handle);
            GC.KeepAlive(this);
            numQueries = (long)q; total = (long)t;
        }

        /// <summary>
        /// Borrowed addresses: offsets (numQueries + 1 int64), indices (total int32), squared distances
        /// (total double). Valid until this result is disposed; read with Marshal.Copy.
        /// </summary>
        public void GetView(out IntPtr offsets, out IntPtr indices, out IntPtr distances2)
        {
            O3dNative.o3d_search_result_view(out offsets, out indices, out distances2, Handle);
            GC.KeepAlive(this);
        }

        public NeighborResult ToManaged()
        {
            long nq, total;
            GetCounts(out nq, out total);
            var offsets = new long[nq + 1];
            var indices = new int[total];
            var d2 = new double[total];
            O3dNative.o3d_search_result_get_offsets(offsets, (ulong)offsets.Length, Handle);
            O3dNative.o3d_search_result_get_indices(indices, (ulong)indices.Length, Handle);
            O3dNative.o3d_search_result_get_distances2(d2, (ulong)d2.Length, Handle);
            GC.KeepAlive(this);
            return new NeighborResult(offsets, indices, d2);
        }
    }

    /// <summary>
    /// KD-tree (o3d.geometry.KDTreeFlann) over 3-D points, or over points of any dimension (a <see cref="Feature"/>'s
    /// descriptors, <see cref="FromPointsXd"/>) searched with the *Xd methods. It copies the points it indexes.
    /// </summary>
    public sealed class KDTreeFlann : NativeHandle
    {
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_kdtree_destroy(handle); }

        static IntPtr FromCloud(PointCloud pc)
        {
            if (pc == null) throw new ArgumentNullException("pc");
            IntPtr h;
            O3dNative.o3d_kdtree_create_from_pointcloud(out h, pc.Handle);
            GC.KeepAlive(pc);
            return h;
        }

        static IntPtr FromPoints(double[] xyz)
        {
            IntPtr h;
            O3dNative.o3d_kdtree_create_from_points(out h, xyz, Checks.Rows3(xyz, "xyz"));
            return h;
        }

        static IntPtr FromFeature(Feature feature)
        {
            if (feature == null) throw new ArgumentNullException("feature");
            IntPtr h;
            O3dNative.o3d_kdtree_create_from_feature(out h, feature.Handle);
            GC.KeepAlive(feature);
            return h;
        }

        KDTreeFlann(IntPtr handle) : base(handle) { }
        public KDTreeFlann(PointCloud pc) : base(FromCloud(pc)) { }
        /// <summary>Tree over the descriptors of <paramref name="feature"/> (dimension Feature.Dimension).</summary>
        public KDTreeFlann(Feature feature) : base(FromFeature(feature)) { }
        /// <summary>Tree over (N x 3) row-major points.</summary>
        public KDTreeFlann(double[] xyz) : base(FromPoints(xyz)) { }

        /// <summary>Tree over (N x <paramref name="dimension"/>) row-major points.</summary>
        public static KDTreeFlann FromPointsXd(double[] data, long dimension)
        {
            if (data == null) throw new ArgumentNullException("data");
            ulong d = Checks.Count(dimension, "dimension");
            if (d == 0 || (ulong)data.Length % d != 0)
                throw new ArgumentException("data: length " + data.Length + " is not a multiple of dimension " + dimension, "data");
            IntPtr h;
            O3dNative.o3d_kdtree_create_from_points_xd(out h, data, d, (ulong)data.Length / d);
            return new KDTreeFlann(h);
        }

        /// <summary>Dimension of the indexed points (3 for trees over clouds).</summary>
        public long Dimension { get { ulong d; O3dNative.o3d_kdtree_dimension(out d, Handle); GC.KeepAlive(this); return (long)d; } }

        public long Size { get { ulong n; O3dNative.o3d_kdtree_size(out n, Handle); GC.KeepAlive(this); return (long)n; } }

        /// <summary>Batch search of (M x 3) queries; the caller disposes the native result.</summary>
        public SearchResult Search(double[] queries, SearchParam param, int numThreads = 0)
        {
            if (param == null) throw new ArgumentNullException("param");
            ulong m = Checks.Rows3(queries, "queries");
            IntPtr r;
            using (var p = param.ToNative())
                O3dNative.o3d_kdtree_search(out r, Handle, queries, m, p, numThreads);
            GC.KeepAlive(this);
            return new SearchResult(r);
        }

        /// <summary>As <see cref="Search(double[],SearchParam,int)"/> with float32 queries.</summary>
        public SearchResult Search(float[] queries, SearchParam param, int numThreads = 0)
        {
            if (param == null) throw new ArgumentNullException("param");
            ulong m = Checks.Rows3(queries, "queries");
            IntPtr r;
            using (var p = param.ToNative())
                O3dNative.o3d_kdtree_search_f32(out r, Handle, queries, m, p, numThreads);
            GC.KeepAlive(this);
            return new SearchResult(r);
        }

        /// <summary>Batch search of (M x Dimension) row-major queries of this tree's dimension; the caller disposes the native result.</summary>
        public SearchResult SearchXd(double[] queries, SearchParam param, int numThreads = 0)
        {
            if (queries == null) throw new ArgumentNullException("queries");
            if (param == null) throw new ArgumentNullException("param");
            long d = Dimension;
            if (d == 0 || queries.Length % d != 0)
                throw new ArgumentException("queries: length " + queries.Length + " is not a multiple of the tree's dimension " + d, "queries");
            IntPtr r;
            using (var p = param.ToNative())
                O3dNative.o3d_kdtree_search_xd(out r, Handle, queries, (ulong)(queries.Length / d), (ulong)d, p, numThreads);
            GC.KeepAlive(this);
            return new SearchResult(r);
        }

        /// <summary>The <paramref name="knn"/> nearest points of each xd query (search_knn_vector_xd), copied into arrays.</summary>
        public NeighborResult SearchKnnXd(double[] queries, int knn, int numThreads = 0)
        { return Managed(SearchXd(queries, SearchParam.Knn(knn), numThreads)); }
        public NeighborResult SearchRadiusXd(double[] queries, double radius, int numThreads = 0)
        { return Managed(SearchXd(queries, SearchParam.RadiusSearch(radius), numThreads)); }
        public NeighborResult SearchHybridXd(double[] queries, double radius, int maxNN, int numThreads = 0)
        { return Managed(SearchXd(queries, SearchParam.Hybrid(radius, maxNN), numThreads)); }

        NeighborResult Managed(SearchResult r) { using (r) return r.ToManaged(); }

        public NeighborResult SearchKnn(double[] queries, int knn, int numThreads = 0)
        { return Managed(Search(queries, SearchParam.Knn(knn), numThreads)); }
        public NeighborResult SearchKnn(float[] queries, int knn, int numThreads = 0)
        { return Managed(Search(queries, SearchParam.Knn(knn), numThreads)); }
        public NeighborResult SearchRadius(double[] queries, double radius, int numThreads = 0)
        { return Managed(Search(queries, SearchParam.RadiusSearch(radius), numThreads)); }
        public NeighborResult SearchHybrid(double[] queries, double radius, int maxNN, int numThreads = 0)
        { return Managed(Search(queries, SearchParam.Hybrid(radius, maxNN), numThreads)); }
    }
}
