// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;

/**
 * KD-tree (o3d.geometry.KDTreeFlann) over 3-D points, or over points of any dimension (a {@link Feature}'s
 * descriptors, {@link #fromPointsXd}) searched with the *Xd methods. It copies the points it indexes.
 */
public final class KDTreeFlann extends NativeResource {
    private KDTreeFlann(long handle) {
        super(handle, O3dNative::o3d_kdtree_destroy);
    }

    private static long fromCloud(PointCloud pc) {
        long[] h = new long[1];
        O3dNative.o3d_kdtree_create_from_pointcloud(h, pc.handle());
        Reference.reachabilityFence(pc);
        return h[0];
    }

    private static long fromPoints(double[] xyz) {
        long[] h = new long[1];
        O3dNative.o3d_kdtree_create_from_points(h, xyz, rows3(xyz.length, "xyz"));
        return h[0];
    }

    private static long fromFeature(Feature feature) {
        long[] h = new long[1];
        O3dNative.o3d_kdtree_create_from_feature(h, feature.handle());
        Reference.reachabilityFence(feature);
        return h[0];
    }

    public KDTreeFlann(PointCloud pc) {
        this(fromCloud(pc));
    }

    /** Tree over the descriptors of {@code feature} (dimension feature.dimension()). */
    public KDTreeFlann(Feature feature) {
        this(fromFeature(feature));
    }

    /** Tree over (N x {@code dimension}) row-major points. */
    public static KDTreeFlann fromPointsXd(double[] data, long dimension) {
        java.util.Objects.requireNonNull(data, "data");
        if (dimension <= 0 || data.length % dimension != 0)
            throw new IllegalArgumentException("data: length " + data.length + " is not a multiple of dimension " + dimension);
        long[] h = new long[1];
        O3dNative.o3d_kdtree_create_from_points_xd(h, data, dimension, data.length / dimension);
        return new KDTreeFlann(h[0]);
    }

    /** Dimension of the indexed points (3 for trees over clouds). */
    public long dimension() {
        long[] d = new long[1];
        O3dNative.o3d_kdtree_dimension(d, handle());
        Reference.reachabilityFence(this);
        return d[0];
    }

    /** Tree over (N x 3) row-major points. */
    public KDTreeFlann(double[] xyz) {
        this(fromPoints(xyz));
    }

    public long size() {
        long[] n = new long[1];
        O3dNative.o3d_kdtree_size(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    /** Batch search of (M x 3) queries; the caller closes the native result. */
    public SearchResult search(double[] queries, SearchParam param, int numThreads) {
        long m = rows3(queries.length, "queries");
        long[] r = new long[1];
        o3d_search_param_t p = param.toNative();
        try {
            O3dNative.o3d_kdtree_search(r, handle(), queries, m, p, numThreads);
        } finally {
            p.delete();
        }
        Reference.reachabilityFence(this);
        return new SearchResult(r[0]);
    }

    /** As {@link #search(double[], SearchParam, int)} with float32 queries. */
    public SearchResult search(float[] queries, SearchParam param, int numThreads) {
        long m = rows3(queries.length, "queries");
        long[] r = new long[1];
        o3d_search_param_t p = param.toNative();
        try {
            O3dNative.o3d_kdtree_search_f32(r, handle(), queries, m, p, numThreads);
        } finally {
            p.delete();
        }
        Reference.reachabilityFence(this);
        return new SearchResult(r[0]);
    }

    /** Batch search of (M x dimension()) row-major queries; the caller closes the native result. */
    public SearchResult searchXd(double[] queries, SearchParam param, int numThreads) {
        java.util.Objects.requireNonNull(queries, "queries");
        long d = dimension();
        if (d == 0 || queries.length % d != 0)
            throw new IllegalArgumentException("queries: length " + queries.length + " is not a multiple of the tree's dimension " + d);
        long[] r = new long[1];
        o3d_search_param_t p = param.toNative();
        try {
            O3dNative.o3d_kdtree_search_xd(r, handle(), queries, queries.length / d, d, p, numThreads);
        } finally {
            p.delete();
        }
        Reference.reachabilityFence(this);
        return new SearchResult(r[0]);
    }

    /** The {@code knn} nearest points of each xd query (search_knn_vector_xd), copied into arrays. */
    public NeighborResult searchKnnXd(double[] queries, int knn) { return managed(searchXd(queries, SearchParam.knn(knn), 0)); }
    public NeighborResult searchRadiusXd(double[] queries, double radius) { return managed(searchXd(queries, SearchParam.radius(radius), 0)); }
    public NeighborResult searchHybridXd(double[] queries, double radius, int maxNN) {
        return managed(searchXd(queries, SearchParam.hybrid(radius, maxNN), 0));
    }

    private static NeighborResult managed(SearchResult r) {
        try (r) {
            return r.toArrays();
        }
    }

    /** The {@code knn} nearest points of each query, copied into arrays. */
    public NeighborResult searchKnn(double[] queries, int knn) { return managed(search(queries, SearchParam.knn(knn), 0)); }
    public NeighborResult searchKnn(float[] queries, int knn) { return managed(search(queries, SearchParam.knn(knn), 0)); }
    public NeighborResult searchRadius(double[] queries, double radius) { return managed(search(queries, SearchParam.radius(radius), 0)); }
    public NeighborResult searchHybrid(double[] queries, double radius, int maxNN) {
        return managed(search(queries, SearchParam.hybrid(radius, maxNN), 0));
    }
}
