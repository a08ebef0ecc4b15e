// SPDX-License-Identifier: MIT
package org.o3d;

/** o3d.geometry.OctreeNodeInfo: where a node sits. */
public final class OctreeNodeInfo {
    /** The node cube's min corner. */
    public final double[] origin;
    /** The node cube's edge. */
    public final double size;
    /** 0 for the root. */
    public final int depth;
    /** 0..7 within its parent. */
    public final int childIndex;

    OctreeNodeInfo(double[] origin, double size, int depth, int childIndex) {
        this.origin = origin;
        this.size = size;
        this.depth = depth;
        this.childIndex = childIndex;
    }
}
