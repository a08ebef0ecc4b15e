// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>The float64 arrays of a mesh (for the borrowed views).</summary>
    public enum MeshArray
    {
        Vertices = O3dNative.O3D_MESH_VERTICES,
        VertexNormals = O3dNative.O3D_MESH_VERTEX_NORMALS,
        VertexColors = O3dNative.O3D_MESH_VERTEX_COLORS,
        TriangleNormals = O3dNative.O3D_MESH_TRIANGLE_NORMALS,
        /// <summary>(3 * num_triangles x 2): three UV rows per triangle.</summary>
        TriangleUvs = O3dNative.O3D_MESH_TRIANGLE_UVS,
    }

    /// <summary>The int32 arrays of a mesh (for the borrowed views).</summary>
    public enum MeshIndexArray
    {
        Triangles = O3dNative.O3D_MESH_TRIANGLES,
        TriangleMaterialIds = O3dNative.O3D_MESH_TRIANGLE_MATERIAL_IDS,
    }

    /// <summary>Vertex-clustering contraction (Open3D's SimplificationContraction).</summary>
    public enum SimplificationContraction
    {
        Average = O3dNative.O3D_SIMPLIFICATION_AVERAGE,
        Quadric = O3dNative.O3D_SIMPLIFICATION_QUADRIC,
    }

    /// <summary>What the smoothing filters change (Open3D's FilterScope).</summary>
    public enum FilterScope
    {
        All = O3dNative.O3D_FILTER_SCOPE_ALL,
        Color = O3dNative.O3D_FILTER_SCOPE_COLOR,
        Normal = O3dNative.O3D_FILTER_SCOPE_NORMAL,
        Vertex = O3dNative.O3D_FILTER_SCOPE_VERTEX,
    }

    /// <summary>Result of <see cref="TriangleMesh.ClusterConnectedTriangles"/>.</summary>
    public sealed class TriangleClusters
    {
        internal TriangleClusters(int[] triangleClusters, int[] clusterNTriangles, double[] clusterArea)
        {
            TriangleClusterIndices = triangleClusters; ClusterNTriangles = clusterNTriangles; ClusterArea = clusterArea;
        }

        /// <summary>Cluster of each triangle (clusters numbered by their lowest triangle index).</summary>
        public int[] TriangleClusterIndices { get; private set; }
        /// <summary>Number of triangles of each cluster.</summary>
        public int[] ClusterNTriangles { get; private set; }
        /// <summary>Surface area of each cluster.</summary>
        public double[] ClusterArea { get; private set; }
    }

    /// <summary>
    /// A triangle mesh (o3d.geometry.TriangleMesh). Vertices, normals, colors are (N x 3) row-major
    /// double arrays, triangles (M x 3) int arrays; properties copy out on get and in on set, one native
    /// call each. Clean-up methods edit in place and return this; processing methods return a new mesh.
    /// Dispose it (or use <c>using</c>); a finalizer destroys forgotten meshes.
    /// </summary>
    public sealed partial class TriangleMesh : NativeHandle
    {
        internal TriangleMesh(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_trianglemesh_destroy(handle); }

        static IntPtr Create()
        {
            IntPtr h;
            O3dNative.o3d_trianglemesh_create(out h);
            return h;
        }

        /// <summary>An empty mesh.</summary>
        public TriangleMesh() : base(Create()) { }

        /// <summary>A mesh with (N x 3) vertices and (M x 3) triangles.</summary>
        public TriangleMesh(double[] vertices, int[] triangles) : this()
        {
            try { Vertices = vertices; Triangles = triangles; }
            catch { Dispose(); throw; }
        }

        /// <summary>Deep copy (textures included).</summary>
        public TriangleMesh Clone()
        {
            IntPtr h;
            O3dNative.o3d_trianglemesh_clone(out h, Handle);
            GC.KeepAlive(this);
            return new TriangleMesh(h);
        }

        /// <summary>Remove all arrays and textures.</summary>
        public TriangleMesh Clear() { O3dNative.o3d_trianglemesh_clear(Handle); GC.KeepAlive(this); return this; }

        public long NumVertices
        {
            get { ulong n; O3dNative.o3d_trianglemesh_num_vertices(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        public long NumTriangles
        {
            get { ulong n; O3dNative.o3d_trianglemesh_num_triangles(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        bool Has(int which) { var v = new int[1]; O3dNative.o3d_trianglemesh_has_array(v, Handle, which); GC.KeepAlive(this); return v[0] != 0; }

        public bool HasVertices { get { return Has(O3dNative.O3D_MESH_VERTICES); } }
        public bool HasVertexNormals { get { return Has(O3dNative.O3D_MESH_VERTEX_NORMALS); } }
        public bool HasVertexColors { get { return Has(O3dNative.O3D_MESH_VERTEX_COLORS); } }
        public bool HasTriangles { get { return Has(O3dNative.O3D_MESH_TRIANGLES); } }
        public bool HasTriangleNormals { get { return Has(O3dNative.O3D_MESH_TRIANGLE_NORMALS); } }
        public bool HasTriangleUvs { get { return Has(O3dNative.O3D_MESH_TRIANGLE_UVS); } }
        public bool HasTriangleMaterialIds { get { return Has(O3dNative.O3D_MESH_TRIANGLE_MATERIAL_IDS); } }
        public bool HasTextures { get { return TextureCount > 0; } }

        // ---- bulk arrays ------------------------------------------------------------------------

        double[] GetArray(int which, int columns)
        {
            IntPtr h = Handle;
            ulong rows;
            O3dNative.o3d_trianglemesh_get_array(null, 0, out rows, h, which);
            var result = new double[checked((long)rows * columns)];
            O3dNative.o3d_trianglemesh_get_array(result, rows, out rows, h, which);
            GC.KeepAlive(this);
            return result;
        }

        void SetArray(int which, double[] values, int columns)
        {
            if (values == null) throw new ArgumentNullException("value");
            if (values.Length % columns != 0)
                throw new ArgumentException("value: length " + values.Length + " is not a multiple of " + columns, "value");
            O3dNative.o3d_trianglemesh_set_array(Handle, which, values, (ulong)(values.Length / columns));
            GC.KeepAlive(this);
        }

        int[] GetIndexArray(int which, int columns)
        {
            IntPtr h = Handle;
            ulong rows;
            O3dNative.o3d_trianglemesh_get_index_array(null, 0, out rows, h, which);
            var result = new int[checked((long)rows * columns)];
            O3dNative.o3d_trianglemesh_get_index_array(result, rows, out rows, h, which);
            GC.KeepAlive(this);
            return result;
        }

        void SetIndexArray(int which, int[] values, int columns)
        {
            if (values == null) throw new ArgumentNullException("value");
            if (values.Length % columns != 0)
                throw new ArgumentException("value: length " + values.Length + " is not a multiple of " + columns, "value");
            O3dNative.o3d_trianglemesh_set_index_array(Handle, which, values, (ulong)(values.Length / columns));
            GC.KeepAlive(this);
        }

        /// <summary>Vertices x0,y0,z0,x1,... (a copy; setting copies in, length 3N).</summary>
        public double[] Vertices
        {
            get { return GetArray(O3dNative.O3D_MESH_VERTICES, 3); }
            set { SetArray(O3dNative.O3D_MESH_VERTICES, value, 3); }
        }

        public double[] VertexNormals
        {
            get { return GetArray(O3dNative.O3D_MESH_VERTEX_NORMALS, 3); }
            set { SetArray(O3dNative.O3D_MESH_VERTEX_NORMALS, value, 3); }
        }

        /// <summary>Vertex colors, RGB in [0,1].</summary>
        public double[] VertexColors
        {
            get { return GetArray(O3dNative.O3D_MESH_VERTEX_COLORS, 3); }
            set { SetArray(O3dNative.O3D_MESH_VERTEX_COLORS, value, 3); }
        }

        public double[] TriangleNormals
        {
            get { return GetArray(O3dNative.O3D_MESH_TRIANGLE_NORMALS, 3); }
            set { SetArray(O3dNative.O3D_MESH_TRIANGLE_NORMALS, value, 3); }
        }

        /// <summary>Triangle UVs u0,v0,u1,v1,... three (u, v) rows per triangle in corner order.</summary>
        public double[] TriangleUvs
        {
            get { return GetArray(O3dNative.O3D_MESH_TRIANGLE_UVS, 2); }
            set { SetArray(O3dNative.O3D_MESH_TRIANGLE_UVS, value, 2); }
        }

        /// <summary>Triangles as vertex indices a0,b0,c0,a1,... (a copy; setting copies in, length 3M).</summary>
        public int[] Triangles
        {
            get { return GetIndexArray(O3dNative.O3D_MESH_TRIANGLES, 3); }
            set { SetIndexArray(O3dNative.O3D_MESH_TRIANGLES, value, 3); }
        }

        /// <summary>Material (texture) index of each triangle.</summary>
        public int[] TriangleMaterialIds
        {
            get { return GetIndexArray(O3dNative.O3D_MESH_TRIANGLE_MATERIAL_IDS, 1); }
            set { SetIndexArray(O3dNative.O3D_MESH_TRIANGLE_MATERIAL_IDS, value, 1); }
        }

        // Borrowed views: the address of the mesh's own storage (IntPtr.Zero when empty), valid until the
        // next mutating call on this mesh or Dispose. Write only through the mutable views.

        public IntPtr ArrayView(MeshArray which, out long rows)
        {
            IntPtr data; ulong n;
            O3dNative.o3d_trianglemesh_array_view(out data, out n, Handle, (int)which);
            GC.KeepAlive(this); rows = (long)n; return data;
        }

        public IntPtr ArrayMutableView(MeshArray which, out long rows)
        {
            IntPtr data; ulong n;
            O3dNative.o3d_trianglemesh_array_mutable_view(out data, out n, Handle, (int)which);
            GC.KeepAlive(this); rows = (long)n; return data;
        }

        public IntPtr IndexArrayView(MeshIndexArray which, out long rows)
        {
            IntPtr data; ulong n;
            O3dNative.o3d_trianglemesh_index_array_view(out data, out n, Handle, (int)which);
            GC.KeepAlive(this); rows = (long)n; return data;
        }

        public IntPtr IndexArrayMutableView(MeshIndexArray which, out long rows)
        {
            IntPtr data; ulong n;
            O3dNative.o3d_trianglemesh_index_array_mutable_view(out data, out n, Handle, (int)which);
            GC.KeepAlive(this); rows = (long)n; return data;
        }

        // ---- textures -----------------------------------------------------------------------------

        public long TextureCount
        {
            get { ulong n; O3dNative.o3d_trianglemesh_texture_count(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        /// <summary>A copy of texture <paramref name="index"/>; dispose it.</summary>
        public Image GetTexture(long index)
        {
            if (index < 0) throw new ArgumentOutOfRangeException("index");
            IntPtr h;
            O3dNative.o3d_trianglemesh_get_texture(out h, Handle, (ulong)index);
            GC.KeepAlive(this);
            return new Image(h);
        }

        /// <summary>Append a copy of <paramref name="image"/> to the textures.</summary>
        public TriangleMesh AddTexture(Image image)
        {
            if (image == null) throw new ArgumentNullException("image");
            O3dNative.o3d_trianglemesh_add_texture(Handle, image.Handle);
            GC.KeepAlive(image); GC.KeepAlive(this);
            return this;
        }

        public TriangleMesh ClearTextures() { O3dNative.o3d_trianglemesh_clear_textures(Handle); GC.KeepAlive(this); return this; }

        /// <summary>Concatenate <paramref name="other"/> onto this mesh (Open3D <c>mesh += other</c>).</summary>
        public TriangleMesh Append(TriangleMesh other)
        {
            if (other == null) throw new ArgumentNullException("other");
            O3dNative.o3d_trianglemesh_append(Handle, other.Handle);
            GC.KeepAlive(other); GC.KeepAlive(this);
            return this;
        }
    }
}
