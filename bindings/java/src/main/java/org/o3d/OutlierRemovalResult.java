// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * Result of {@link PointCloud#removeStatisticalOutlier} / {@link PointCloud#removeRadiusOutlier}
 * (Open3D's {@code (cloud, ind)} tuple): the kept points as a new cloud and their indices (ascending)
 * in the input. Closing it closes {@link #cloud}.
 */
public final class OutlierRemovalResult implements AutoCloseable {
    /** The kept points (with their normals and colors); owned by the caller. */
    public final PointCloud cloud;
    /** Indices of the kept points in the input cloud, ascending. */
    public final int[] indices;

    OutlierRemovalResult(PointCloud cloud, int[] indices) {
        this.cloud = cloud;
        this.indices = indices;
    }

    @Override
    public void close() {
        cloud.close();
    }
}
