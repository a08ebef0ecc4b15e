// SPDX-License-Identifier: MIT
package org.o3d;

import java.util.Arrays;

/**
 * PoseGraphEdge, a value copied in and out of a {@link PoseGraph}: the edge (s, t, T) says that T maps
 * points of node s's frame into node t's frame. Matrices are row-major. {@code new PoseGraphEdge()} has
 * the library's defaults: ids 0, identity matrices, certain, confidence 1.
 */
public final class PoseGraphEdge {
    public int sourceNodeId;
    public int targetNodeId;
    /** Row-major 4x4 (16 values). */
    public double[] transformation;
    /** Row-major 6x6 information matrix (36 values; rotation first, then translation). */
    public double[] information;
    /** A loop closure the line process may prune (false: odometry). */
    public boolean uncertain;
    /** Line-process weight in [0, 1]. */
    public double confidence;

    public PoseGraphEdge() {
        o3d_pose_graph_edge_t e = newNative();
        try {
            read(e);
        } finally {
            e.delete();
        }
    }

    /** An edge from {@code source} to {@code target}; the other fields keep their defaults. */
    public PoseGraphEdge(int source, int target, double[] transformation, double[] information, boolean uncertain) {
        this();
        this.sourceNodeId = source;
        this.targetNodeId = target;
        if (transformation != null) this.transformation = NativeResource.fixed(transformation, 16, "transformation", false).clone();
        if (information != null) this.information = NativeResource.fixed(information, 36, "information", false).clone();
        this.uncertain = uncertain;
    }

    private void read(o3d_pose_graph_edge_t e) {
        double[] m = new double[52];
        O3dNative.o3dx_pose_graph_edge_get_matrices(e, m);
        sourceNodeId = e.getSource_node_id();
        targetNodeId = e.getTarget_node_id();
        transformation = Arrays.copyOfRange(m, 0, 16);
        information = Arrays.copyOfRange(m, 16, 52);
        uncertain = e.getUncertain() != 0;
        confidence = e.getConfidence();
    }

    private static o3d_pose_graph_edge_t newNative() {
        o3d_pose_graph_edge_t e = new o3d_pose_graph_edge_t();
        O3dNative.o3d_pose_graph_edge_init(e, O3dNative.o3dx_sizeof_pose_graph_edge());
        return e;
    }

    /** The native edge; the caller deletes it. */
    o3d_pose_graph_edge_t toNative() {
        double[] m = new double[52];
        System.arraycopy(NativeResource.fixed(transformation, 16, "transformation", false), 0, m, 0, 16);
        System.arraycopy(NativeResource.fixed(information, 36, "information", false), 0, m, 16, 36);
        o3d_pose_graph_edge_t e = newNative();
        e.setSource_node_id(sourceNodeId);
        e.setTarget_node_id(targetNodeId);
        O3dNative.o3dx_pose_graph_edge_set_matrices(e, m);
        e.setUncertain(uncertain ? 1 : 0);
        e.setConfidence(confidence);
        return e;
    }

    /** Edge {@code index} of the native graph {@code graph}, copied out. */
    static PoseGraphEdge get(long graph, long index) {
        o3d_pose_graph_edge_t e = newNative();
        try {
            O3dNative.o3d_pose_graph_get_edge(e, graph, index);
            PoseGraphEdge edge = new PoseGraphEdge();
            edge.read(e);
            return edge;
        } finally {
            e.delete();
        }
    }

    @Override
    public String toString() {
        return "PoseGraphEdge(" + sourceNodeId + " -> " + targetNodeId + (uncertain ? ", uncertain" : "") + ", confidence " + confidence + ")";
    }
}
