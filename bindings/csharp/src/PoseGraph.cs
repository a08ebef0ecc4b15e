// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>
    /// PoseGraphEdge, a value copied in and out of a <see cref="PoseGraph"/>: the edge (s, t, T) says that T maps points
    /// of node s's frame into node t's frame. Matrices are row-major. Defaults: ids 0, identity matrices, certain, confidence 1.
    /// </summary>
    public sealed class PoseGraphEdge
    {
        public int SourceNodeId { get; set; }
        public int TargetNodeId { get; set; }
        /// <summary>Row-major 4x4 (16 values).</summary>
        public double[] Transformation { get; set; }
        /// <summary>Row-major 6x6 information matrix (36 values; rotation first, then translation).</summary>
        public double[] Information { get; set; }
        /// <summary>A loop closure the line process may prune (false: odometry).</summary>
        public bool Uncertain { get; set; }
        /// <summary>Line-process weight in [0, 1].</summary>
        public double Confidence { get; set; }

        /// <summary>An edge with the library's defaults where an argument is null.</summary>
        public PoseGraphEdge(int sourceNodeId = 0, int targetNodeId = 0, double[] transformation = null, double[] information = null,
                             bool uncertain = false, double? confidence = null)
        {
            using (var e = NewNative())
            {
                var m = new double[52];
                O3dNative.o3dx_pose_graph_edge_get_matrices(e, m);
                SourceNodeId = sourceNodeId;
                TargetNodeId = targetNodeId;
                Transformation = transformation != null ? (double[])Checks.Fixed(transformation, 16, "transformation", false).Clone() : Slice(m, 0, 16);
                Information = information != null ? (double[])Checks.Fixed(information, 36, "information", false).Clone() : Slice(m, 16, 36);
                Uncertain = uncertain;
                Confidence = confidence ?? e.confidence;
            }
        }

        static double[] Slice(double[] values, int start, int length)
        {
            var r = new double[length];
            Array.Copy(values, start, r, 0, length);
            return r;
        }

        static o3d_pose_graph_edge_t NewNative()
        {
            var e = new o3d_pose_graph_edge_t();
            O3dNative.o3d_pose_graph_edge_init(e, O3dNative.o3dx_sizeof_pose_graph_edge());
            return e;
        }

        internal o3d_pose_graph_edge_t ToNative()
        {
            var m = new double[52];
            Array.Copy(Checks.Fixed(Transformation, 16, "Transformation", false), 0, m, 0, 16);
            Array.Copy(Checks.Fixed(Information, 36, "Information", false), 0, m, 16, 36);
            var e = NewNative();
            e.source_node_id = SourceNodeId;
            e.target_node_id = TargetNodeId;
            O3dNative.o3dx_pose_graph_edge_set_matrices(e, m);
            e.uncertain = Uncertain ? 1 : 0;
            e.confidence = Confidence;
            return e;
        }

        /// <summary>The graph's edge <paramref name="index"/>, copied out.</summary>
        internal static PoseGraphEdge Get(IntPtr graph, ulong index)
        {
            using (var e = NewNative())
            {
                O3dNative.o3d_pose_graph_get_edge(e, graph, index);
                var m = new double[52];
                O3dNative.o3dx_pose_graph_edge_get_matrices(e, m);
                return new PoseGraphEdge(e.source_node_id, e.target_node_id, Slice(m, 0, 16), Slice(m, 16, 36), e.uncertain != 0, e.confidence);
            }
        }

        public override string ToString()
        {
            return "PoseGraphEdge(" + SourceNodeId + " -> " + TargetNodeId + (Uncertain ? ", uncertain" : "") + ", confidence " + Confidence + ")";
        }
    }

    /// <summary>
    /// PoseGraph: nodes (row-major 4x4 poses, 16 values) and <see cref="PoseGraphEdge"/>s, copied in and out one at a
    /// time. Dispose it (or use <c>using</c>); a finalizer destroys forgotten graphs.
    /// </summary>
    public sealed class PoseGraph : NativeHandle
    {
        internal PoseGraph(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_pose_graph_destroy(handle); }

        static IntPtr Create()
        {
            IntPtr h;
            O3dNative.o3d_pose_graph_create(out h);
            return h;
        }

        /// <summary>An empty graph.</summary>
        public PoseGraph() : base(Create()) { }

        /// <summary>Deep copy.</summary>
        public PoseGraph Clone()
        {
            IntPtr h;
            O3dNative.o3d_pose_graph_clone(out h, Handle);
            GC.KeepAlive(this);
            return new PoseGraph(h);
        }

        public long NodeCount { get { ulong n; O3dNative.o3d_pose_graph_num_nodes(out n, Handle); GC.KeepAlive(this); return (long)n; } }
        public long EdgeCount { get { ulong n; O3dNative.o3d_pose_graph_num_edges(out n, Handle); GC.KeepAlive(this); return (long)n; } }

        /// <summary>Append a node (PoseGraphNode) with <paramref name="pose"/> (null: identity), a finite rigid transform.</summary>
        public void AddNode(double[] pose = null)
        {
            O3dNative.o3d_pose_graph_add_node(Handle, Checks.Fixed(pose, 16, "pose", true));
            GC.KeepAlive(this);
        }

        /// <summary>The pose of node <paramref name="index"/> (16 values).</summary>
        public double[] GetNode(long index)
        {
            var pose = new double[16];
            O3dNative.o3d_pose_graph_get_node(pose, Handle, Checks.Count(index, "index"));
            GC.KeepAlive(this);
            return pose;
        }

        public void SetNode(long index, double[] pose)
        {
            O3dNative.o3d_pose_graph_set_node(Handle, Checks.Count(index, "index"), Checks.Fixed(pose, 16, "pose", false));
            GC.KeepAlive(this);
        }

        /// <summary>Append an edge. Node ids are checked by global optimization, not here.</summary>
        public void AddEdge(PoseGraphEdge edge)
        {
            if (edge == null) throw new ArgumentNullException("edge");
            using (var e = edge.ToNative()) O3dNative.o3d_pose_graph_add_edge(Handle, e);
            GC.KeepAlive(this);
        }

        public PoseGraphEdge GetEdge(long index)
        {
            var e = PoseGraphEdge.Get(Handle, Checks.Count(index, "index"));
            GC.KeepAlive(this);
            return e;
        }

        public void SetEdge(long index, PoseGraphEdge edge)
        {
            if (edge == null) throw new ArgumentNullException("edge");
            ulong i = Checks.Count(index, "index");
            using (var e = edge.ToNative()) O3dNative.o3d_pose_graph_set_edge(Handle, i, e);
            GC.KeepAlive(this);
        }

        /// <summary>Every node pose (copies), in order.</summary>
        public double[][] Nodes
        {
            get
            {
                var nodes = new double[NodeCount][];
                for (long i = 0; i < nodes.Length; i++) nodes[i] = GetNode(i);
                return nodes;
            }
        }

        /// <summary>Every edge (copies), in order.</summary>
        public PoseGraphEdge[] Edges
        {
            get
            {
                var edges = new PoseGraphEdge[EdgeCount];
                for (long i = 0; i < edges.Length; i++) edges[i] = GetEdge(i);
                return edges;
            }
        }

        /// <summary>Remove every node and edge.</summary>
        public void Clear() { O3dNative.o3d_pose_graph_clear(Handle); GC.KeepAlive(this); }
    }

    public static partial class IO
    {
        /// <summary>Read Open3D's JSON pose graph.</summary>
        public static PoseGraph ReadPoseGraph(string path)
        {
            if (path == null) throw new ArgumentNullException("path");
            IntPtr h;
            O3dNative.o3d_io_read_pose_graph(out h, path);
            return new PoseGraph(h);
        }

        /// <summary>Write <paramref name="graph"/> in Open3D's JSON layout.</summary>
        public static void WritePoseGraph(string path, PoseGraph graph)
        {
            if (path == null) throw new ArgumentNullException("path");
            if (graph == null) throw new ArgumentNullException("graph");
            O3dNative.o3d_io_write_pose_graph(path, graph.Handle);
            GC.KeepAlive(graph);
        }
    }
}
