// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>o3d.geometry.OctreeNodeInfo: where a node sits.</summary>
    public sealed class OctreeNodeInfo
    {
        internal OctreeNodeInfo(double[] origin, double size, int depth, int childIndex)
        {
            Origin = origin; Size = size; Depth = depth; ChildIndex = childIndex;
        }

        /// <summary>The node cube's min corner.</summary>
        public double[] Origin { get; private set; }
        /// <summary>The node cube's edge.</summary>
        public double Size { get; private set; }
        /// <summary>0 for the root.</summary>
        public int Depth { get; private set; }
        /// <summary>0..7 within its parent.</summary>
        public int ChildIndex { get; private set; }
    }

    /// <summary>A leaf found by <see cref="Octree.LocateLeafNode"/>: its node info, mean color and point indices.</summary>
    public sealed class OctreeLeaf
    {
        internal OctreeLeaf(OctreeNodeInfo info, double[] color, int[] indices) { Info = info; Color = color; Indices = indices; }

        public OctreeNodeInfo Info { get; private set; }
        /// <summary>Mean RGB color of the leaf's points.</summary>
        public double[] Color { get; private set; }
        /// <summary>Indices of the leaf's points in the cloud, ascending.</summary>
        public int[] Indices { get; private set; }
    }

    /// <summary>
    /// An octree over a point cloud (o3d.geometry.Octree with color leaves): a cube of edge
    /// <see cref="Size"/> at <see cref="Origin"/>, split to <see cref="MaxDepth"/>. Dispose it.
    /// </summary>
    public sealed class Octree : NativeHandle
    {
        internal Octree(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_octree_destroy(handle); }

        static IntPtr Create(int maxDepth)
        {
            IntPtr h;
            O3dNative.o3d_octree_create(out h, maxDepth);
            return h;
        }

        /// <summary>An empty octree of <paramref name="maxDepth"/> &gt;= 1 levels.</summary>
        public Octree(int maxDepth) : base(Create(maxDepth)) { }

        /// <summary>
        /// Rebuild from <paramref name="cloud"/>: the root is its bounding cube enlarged by the fraction
        /// <paramref name="sizeExpand"/> (convert_from_point_cloud).
        /// </summary>
        public Octree ConvertFromPointCloud(PointCloud cloud, double sizeExpand = 0.01)
        {
            if (cloud == null) throw new ArgumentNullException("cloud");
            O3dNative.o3d_octree_convert_from_point_cloud(Handle, cloud.Handle, sizeExpand);
            GC.KeepAlive(cloud); GC.KeepAlive(this);
            return this;
        }

        void Root(out double[] origin, out double size, out int maxDepth)
        {
            origin = new double[3];
            O3dNative.o3d_octree_get_root(origin, out size, out maxDepth, Handle);
            GC.KeepAlive(this);
        }

        /// <summary>Min corner of the root cube.</summary>
        public double[] Origin { get { double[] o; double s; int d; Root(out o, out s, out d); return o; } }
        /// <summary>Edge of the root cube.</summary>
        public double Size { get { double[] o; double s; int d; Root(out o, out s, out d); return s; } }
        public int MaxDepth { get { double[] o; double s; int d; Root(out o, out s, out d); return d; } }

        /// <summary>Number of non-empty leaves.</summary>
        public long NumLeafNodes
        {
            get { ulong n; O3dNative.o3d_octree_num_leaf_nodes(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        /// <summary>The leaf containing <paramref name="point"/>, or null outside the root or in an empty cell.</summary>
        public OctreeLeaf LocateLeafNode(double[] point)
        {
            var p = Checks.Fixed(point, 3, "point", false);
            IntPtr h = Handle;
            int found; ulong n;
            var color = new double[3];
            using (var info = new o3d_octree_node_info_t())
            {
                O3dNative.o3d_octree_locate_leaf_node(out found, info, color, null, 0, out n, h, p); // count query
                if (found == 0) { GC.KeepAlive(this); return null; }
                var indices = new int[n];
                O3dNative.o3d_octree_locate_leaf_node(out found, info, color, indices, n, out n, h, p);
                GC.KeepAlive(this);
                var origin = new double[3];
                O3dNative.o3dx_octree_node_info_origin(info, origin);
                return new OctreeLeaf(new OctreeNodeInfo(origin, info.size, info.depth, info.child_index), color,
                                      Checks.Trim(indices, n));
            }
        }
    }
}
