// SPDX-License-Identifier: MIT
package org.o3d;

/** Result of {@link TriangleMesh#clusterConnectedTriangles()} (Open3D's three arrays). */
public final class TriangleClusters {
    /** Cluster of each triangle (clusters numbered by their lowest triangle index). */
    public final int[] triangleClusters;
    /** Number of triangles of each cluster. */
    public final int[] clusterNTriangles;
    /** Surface area of each cluster. */
    public final double[] clusterArea;

    TriangleClusters(int[] triangleClusters, int[] clusterNTriangles, double[] clusterArea) {
        this.triangleClusters = triangleClusters;
        this.clusterNTriangles = clusterNTriangles;
        this.clusterArea = clusterArea;
    }
}
