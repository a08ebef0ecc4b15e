// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * Result of the convex hull and hidden-point removal (Open3D's {@code (mesh, indices)} tuple): the mesh
 * (outward-facing triangles) and, for each of its vertices, the index of the input point it came from.
 * Closing it closes {@link #mesh}.
 */
public final class ConvexHullResult implements AutoCloseable {
    public final TriangleMesh mesh;
    /** Input point index of each mesh vertex. */
    public final int[] pointIndices;

    ConvexHullResult(TriangleMesh mesh, int[] pointIndices) {
        this.mesh = mesh;
        this.pointIndices = pointIndices;
    }

    @Override
    public void close() {
        mesh.close();
    }
}
