// SPDX-License-Identifier: MIT
package org.o3d;

/** A leaf found by {@link Octree#locateLeafNode}: its node info, mean color and point indices. */
public final class OctreeLeaf {
    public final OctreeNodeInfo info;
    /** Mean RGB color of the leaf's points. */
    public final double[] color;
    /** Indices of the leaf's points in the cloud, ascending. */
    public final int[] indices;

    OctreeLeaf(OctreeNodeInfo info, double[] color, int[] indices) {
        this.info = info;
        this.color = color;
        this.indices = indices;
    }
}
