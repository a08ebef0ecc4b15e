// SPDX-License-Identifier: MIT
package org.o3d;

/** Result of {@link PointCloud#segmentPlane} (Open3D's {@code (plane_model, inliers)}). */
public final class PlaneSegmentationResult {
    /** (a, b, c, d) with a x + b y + c z + d = 0 and |(a, b, c)| = 1. */
    public final double[] plane;
    /** Indices of the inlier points, ascending. */
    public final int[] inliers;

    PlaneSegmentationResult(double[] plane, int[] inliers) {
        this.plane = plane;
        this.inliers = inliers;
    }
}
