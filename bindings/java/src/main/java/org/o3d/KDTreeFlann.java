// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;

/** KD-tree over 3-D points (o3d.geometry.KDTreeFlann). It copies the points it indexes. */
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

    public KDTreeFlann(PointCloud pc) {
        this(fromCloud(pc));
    }

    /** Tree over (N x 3) row-major points. */
    public KDTreeFlann(double[] xyz) {
        this(fromPoints(xyz));
    }

    public long size() {
        long[] n = new long[1];
        O3dNative.o3d_kdtree_size(handle(), n);
        Reference.reachabilityFence(this);
        return n[0];
    }

    /** Batch search of (M x 3) queries; the caller closes the native result. */
    public SearchResult search(double[] queries, SearchParam param, int numThreads) {
        long m = rows3(queries.length, "queries");
        long[] r = new long[1];
        o3d_search_param_t p = param.toNative();
        try {
            O3dNative.o3d_kdtree_search(handle(), queries, m, p, numThreads, r);
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
            O3dNative.o3d_kdtree_search_f32(handle(), queries, m, p, numThreads, r);
        } finally {
            p.delete();
        }
        Reference.reachabilityFence(this);
        return new SearchResult(r[0]);
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
