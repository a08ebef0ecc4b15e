// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;

/** Shared plumbing of TriangleMesh's processing methods and primitives (each writes a new handle). */
final class TriangleMeshOps {
    private TriangleMeshOps() {}

    interface MakeFn {
        int apply(long[] out);
    }

    interface ProcessFn {
        int apply(long[] out, long mesh);
    }

    static TriangleMesh make(MakeFn fn) {
        long[] h = new long[1];
        fn.apply(h);
        return TriangleMesh.wrap(h);
    }

    static TriangleMesh process(TriangleMesh mesh, ProcessFn fn) {
        long[] h = new long[1];
        fn.apply(h, mesh.handle());
        Reference.reachabilityFence(mesh);
        return TriangleMesh.wrap(h);
    }

    static PointCloud samplePointsUniformly(TriangleMesh mesh, long numberOfPoints, boolean useTriangleNormal, long seed) {
        if (numberOfPoints < 0) throw new IllegalArgumentException("numberOfPoints < 0");
        long[] h = new long[1];
        O3dNative.o3d_trianglemesh_sample_points_uniformly(h, mesh.handle(), numberOfPoints, useTriangleNormal ? 1 : 0, seed);
        Reference.reachabilityFence(mesh);
        return new PointCloud(h[0]);
    }

    static PointCloud samplePointsPoissonDisk(TriangleMesh mesh, long numberOfPoints, double initFactor,
            boolean useTriangleNormal, long seed) {
        if (numberOfPoints < 0) throw new IllegalArgumentException("numberOfPoints < 0");
        long[] h = new long[1];
        O3dNative.o3d_trianglemesh_sample_points_poisson_disk(h, mesh.handle(), numberOfPoints, initFactor,
                useTriangleNormal ? 1 : 0, seed);
        Reference.reachabilityFence(mesh);
        return new PointCloud(h[0]);
    }
}
