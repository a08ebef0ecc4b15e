// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>
    /// A line set (o3d.geometry.LineSet): (N x 3) points, (M x 2) int lines between them and (M x 3) per-line
    /// colors, row-major. Properties copy out on get and in on set. Dispose it (or use <c>using</c>).
    /// </summary>
    public sealed class LineSet : NativeHandle
    {
        internal LineSet(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_lineset_destroy(handle); }

        static IntPtr Create()
        {
            IntPtr h;
            O3dNative.o3d_lineset_create(out h);
            return h;
        }

        /// <summary>An empty line set.</summary>
        public LineSet() : base(Create()) { }

        /// <summary>A line set with (N x 3) points and (M x 2) lines.</summary>
        public LineSet(double[] points, int[] lines) : this()
        {
            try { Points = points; Lines = lines; }
            catch { Dispose(); throw; }
        }

        public LineSet Clone()
        {
            IntPtr h;
            O3dNative.o3d_lineset_clone(out h, Handle);
            GC.KeepAlive(this);
            return new LineSet(h);
        }

        public long NumPoints
        {
            get { ulong n; O3dNative.o3d_lineset_num_points(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        public long NumLines
        {
            get { ulong n; O3dNative.o3d_lineset_num_lines(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        double[] GetArray(int which)
        {
            IntPtr h = Handle;
            ulong rows;
            O3dNative.o3d_lineset_get_array(null, 0, out rows, h, which);
            var result = new double[checked((long)rows * 3)];
            O3dNative.o3d_lineset_get_array(result, rows, out rows, h, which);
            GC.KeepAlive(this);
            return result;
        }

        void SetArray(int which, double[] values)
        {
            O3dNative.o3d_lineset_set_array(Handle, which, values, Checks.Rows3(values, "value"));
            GC.KeepAlive(this);
        }

        /// <summary>Points x0,y0,z0,x1,... (length 3N).</summary>
        public double[] Points
        {
            get { return GetArray(O3dNative.O3D_LINESET_POINTS); }
            set { SetArray(O3dNative.O3D_LINESET_POINTS, value); }
        }

        /// <summary>One RGB color in [0,1] per line (length 3M).</summary>
        public double[] Colors
        {
            get { return GetArray(O3dNative.O3D_LINESET_COLORS); }
            set { SetArray(O3dNative.O3D_LINESET_COLORS, value); }
        }

        public bool HasColors { get { return NumLines > 0 && Colors.Length == 3 * NumLines; } }

        /// <summary>Lines as point indices a0,b0,a1,b1,... (length 2M).</summary>
        public int[] Lines
        {
            get
            {
                IntPtr h = Handle;
                ulong rows;
                O3dNative.o3d_lineset_get_index_array(null, 0, out rows, h, O3D_LINESET_LINES);
                var result = new int[checked((long)rows * 2)];
                O3dNative.o3d_lineset_get_index_array(result, rows, out rows, h, O3D_LINESET_LINES);
                GC.KeepAlive(this);
                return result;
            }
            set
            {
                if (value == null) throw new ArgumentNullException("value");
                if (value.Length % 2 != 0)
                    throw new ArgumentException("value: length " + value.Length + " is not a multiple of 2", "value");
                O3dNative.o3d_lineset_set_index_array(Handle, O3D_LINESET_LINES, value, (ulong)(value.Length / 2));
                GC.KeepAlive(this);
            }
        }

        // Borrowed views (IntPtr.Zero when empty), valid until the next mutating call or Dispose.
        public IntPtr PointsView(out long rows) { return ArrayView(O3dNative.O3D_LINESET_POINTS, out rows); }
        public IntPtr ColorsView(out long rows) { return ArrayView(O3dNative.O3D_LINESET_COLORS, out rows); }

        IntPtr ArrayView(int which, out long rows)
        {
            IntPtr data; ulong n;
            O3dNative.o3d_lineset_array_view(out data, out n, Handle, which);
            GC.KeepAlive(this); rows = (long)n; return data;
        }

        public IntPtr LinesView(out long rows)
        {
            IntPtr data; ulong n;
            O3dNative.o3d_lineset_index_array_view(out data, out n, Handle, O3D_LINESET_LINES);
            GC.KeepAlive(this); rows = (long)n; return data;
        }

        public LineSet PaintUniformColor(double[] rgb)
        {
            O3dNative.o3d_lineset_paint_uniform_color(Handle, Checks.Fixed(rgb, 3, "rgb", false));
            GC.KeepAlive(this); return this;
        }

        /// <summary>Apply a row-major 4x4 transform (16 values) to the points.</summary>
        public LineSet Transform(double[] transform)
        {
            O3dNative.o3d_lineset_transform(Handle, Checks.Fixed(transform, 16, "transform", false));
            GC.KeepAlive(this); return this;
        }

        // ---- factories ------------------------------------------------------------------------------

        /// <summary>
        /// Points of both clouds (cloud0's first) and one line per (index in cloud0, index in cloud1) pair
        /// (create_from_point_cloud_correspondences).
        /// </summary>
        public static LineSet CreateFromPointCloudCorrespondences(PointCloud cloud0, PointCloud cloud1, int[] pairs)
        {
            if (cloud0 == null) throw new ArgumentNullException("cloud0");
            if (cloud1 == null) throw new ArgumentNullException("cloud1");
            if (pairs == null) throw new ArgumentNullException("pairs");
            if (pairs.Length % 2 != 0) throw new ArgumentException("pairs: length " + pairs.Length + " is not a multiple of 2", "pairs");
            IntPtr h;
            O3dNative.o3d_lineset_create_from_point_cloud_correspondences(out h, cloud0.Handle, cloud1.Handle, pairs,
                                                                         (ulong)(pairs.Length / 2));
            GC.KeepAlive(cloud0); GC.KeepAlive(cloud1);
            return new LineSet(h);
        }

        /// <summary>The 12 edges of <paramref name="box"/> (points in get_box_points order).</summary>
        public static LineSet CreateFromOrientedBoundingBox(OrientedBoundingBox box)
        {
            if (box == null) throw new ArgumentNullException("box");
            IntPtr h;
            using (var b = box.ToNative()) O3dNative.o3d_lineset_create_from_oriented_bounding_box(out h, b);
            return new LineSet(h);
        }

        /// <summary>The 12 edges of the axis-aligned box <paramref name="min"/>..<paramref name="max"/>.</summary>
        public static LineSet CreateFromAxisAlignedBoundingBox(double[] min, double[] max)
        {
            IntPtr h;
            O3dNative.o3d_lineset_create_from_axis_aligned_bounding_box(out h, Checks.Fixed(min, 3, "min", false),
                                                                        Checks.Fixed(max, 3, "max", false));
            return new LineSet(h);
        }

        /// <summary>The unique edges of <paramref name="mesh"/> on its vertices (create_from_triangle_mesh).</summary>
        public static LineSet CreateFromTriangleMesh(TriangleMesh mesh)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            IntPtr h;
            O3dNative.o3d_lineset_create_from_triangle_mesh(out h, mesh.Handle);
            GC.KeepAlive(mesh);
            return new LineSet(h);
        }
    }
}
