// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.Objects;

/**
 * PoseGraph: nodes (row-major 4x4 poses, 16 values) and {@link PoseGraphEdge}s, copied in and out one at
 * a time. Close it (try-with-resources); a Cleaner destroys forgotten graphs. Files: {@link IO#readPoseGraph};
 * optimization: {@link Registration#globalOptimization}.
 */
public final class PoseGraph extends NativeResource {
    PoseGraph(long handle) {
        super(handle, O3dNative::o3d_pose_graph_destroy);
    }

    private static long create() {
        long[] h = new long[1];
        O3dNative.o3d_pose_graph_create(h);
        return h[0];
    }

    /** An empty graph. */
    public PoseGraph() {
        this(create());
    }

    /** Deep copy. */
    public PoseGraph copy() {
        long[] h = new long[1];
        O3dNative.o3d_pose_graph_clone(h, handle());
        Reference.reachabilityFence(this);
        return new PoseGraph(h[0]);
    }

    public long nodeCount() {
        long[] n = new long[1];
        O3dNative.o3d_pose_graph_num_nodes(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    public long edgeCount() {
        long[] n = new long[1];
        O3dNative.o3d_pose_graph_num_edges(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    /** Append a node (PoseGraphNode) with {@code pose} (null: identity), a finite rigid transform. */
    public void addNode(double[] pose) {
        O3dNative.o3d_pose_graph_add_node(handle(), fixed(pose, 16, "pose", true));
        Reference.reachabilityFence(this);
    }

    /** The pose of node {@code index} (16 values). */
    public double[] getNode(long index) {
        double[] pose = new double[16];
        O3dNative.o3d_pose_graph_get_node(pose, handle(), Feature.count(index, "index"));
        Reference.reachabilityFence(this);
        return pose;
    }

    public void setNode(long index, double[] pose) {
        O3dNative.o3d_pose_graph_set_node(handle(), Feature.count(index, "index"), fixed(pose, 16, "pose", false));
        Reference.reachabilityFence(this);
    }

    /** Append an edge. Node ids are checked by global optimization, not here. */
    public void addEdge(PoseGraphEdge edge) {
        o3d_pose_graph_edge_t e = Objects.requireNonNull(edge, "edge").toNative();
        try {
            O3dNative.o3d_pose_graph_add_edge(handle(), e);
        } finally {
            e.delete();
        }
        Reference.reachabilityFence(this);
    }

    public PoseGraphEdge getEdge(long index) {
        PoseGraphEdge e = PoseGraphEdge.get(handle(), Feature.count(index, "index"));
        Reference.reachabilityFence(this);
        return e;
    }

    public void setEdge(long index, PoseGraphEdge edge) {
        long i = Feature.count(index, "index");
        o3d_pose_graph_edge_t e = Objects.requireNonNull(edge, "edge").toNative();
        try {
            O3dNative.o3d_pose_graph_set_edge(handle(), i, e);
        } finally {
            e.delete();
        }
        Reference.reachabilityFence(this);
    }

    /** Every node pose (copies), in order. */
    public double[][] nodes() {
        double[][] nodes = new double[Math.toIntExact(nodeCount())][];
        for (int i = 0; i < nodes.length; i++) nodes[i] = getNode(i);
        return nodes;
    }

    /** Every edge (copies), in order. */
    public PoseGraphEdge[] edges() {
        PoseGraphEdge[] edges = new PoseGraphEdge[Math.toIntExact(edgeCount())];
        for (int i = 0; i < edges.length; i++) edges[i] = getEdge(i);
        return edges;
    }

    /** Remove every node and edge. */
    public void clear() {
        O3dNative.o3d_pose_graph_clear(handle());
        Reference.reachabilityFence(this);
    }
}
