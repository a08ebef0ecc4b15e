// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.Objects;

/**
 * An octree over a point cloud (o3d.geometry.Octree with color leaves): a cube of edge {@link #size()} at
 * {@link #origin()}, split to {@link #maxDepth()}. Close it.
 */
public final class Octree extends NativeResource {
    private static long create(int maxDepth) {
        long[] h = new long[1];
        O3dNative.o3d_octree_create(h, maxDepth);
        return h[0];
    }

    /** An empty octree of {@code maxDepth} >= 1 levels. */
    public Octree(int maxDepth) {
        super(create(maxDepth), O3dNative::o3d_octree_destroy);
    }

    /**
     * Rebuild from {@code cloud}: the root is its bounding cube enlarged by the fraction {@code sizeExpand}
     * (convert_from_point_cloud).
     */
    public Octree convertFromPointCloud(PointCloud cloud, double sizeExpand) {
        Objects.requireNonNull(cloud, "cloud");
        O3dNative.o3d_octree_convert_from_point_cloud(handle(), cloud.handle(), sizeExpand);
        Reference.reachabilityFence(cloud);
        Reference.reachabilityFence(this);
        return this;
    }

    public Octree convertFromPointCloud(PointCloud cloud) { return convertFromPointCloud(cloud, 0.01); }

    /** Min corner of the root cube. */
    public double[] origin() {
        double[] o = new double[3];
        O3dNative.o3d_octree_get_root(o, new double[1], new int[1], handle());
        Reference.reachabilityFence(this);
        return o;
    }

    /** Edge of the root cube. */
    public double size() {
        double[] s = new double[1];
        O3dNative.o3d_octree_get_root(null, s, new int[1], handle());
        Reference.reachabilityFence(this);
        return s[0];
    }

    public int maxDepth() {
        int[] d = new int[1];
        O3dNative.o3d_octree_get_root(null, new double[1], d, handle());
        Reference.reachabilityFence(this);
        return d[0];
    }

    /** Number of non-empty leaves. */
    public long numLeafNodes() {
        long[] n = new long[1];
        O3dNative.o3d_octree_num_leaf_nodes(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    /** The leaf containing {@code point}, or null outside the root or in an empty cell (locate_leaf_node). */
    public OctreeLeaf locateLeafNode(double[] point) {
        double[] p = fixed(point, 3, "point", false);
        long h = handle();
        int[] found = new int[1];
        long[] n = new long[1];
        double[] color = new double[3];
        o3d_octree_node_info_t info = new o3d_octree_node_info_t();
        try {
            O3dNative.o3d_octree_locate_leaf_node(found, info, color, null, 0, n, h, p); // count query
            if (found[0] == 0) return null;
            int[] indices = new int[Math.toIntExact(n[0])];
            O3dNative.o3d_octree_locate_leaf_node(found, info, color, indices, n[0], n, h, p);
            double[] origin = new double[3];
            O3dNative.o3dx_octree_node_info_origin(info, origin);
            return new OctreeLeaf(new OctreeNodeInfo(origin, info.getSize(), info.getDepth(), info.getChild_index()),
                    color, trimTo(indices, n[0]));
        } finally {
            info.delete();
            Reference.reachabilityFence(this);
        }
    }
}
