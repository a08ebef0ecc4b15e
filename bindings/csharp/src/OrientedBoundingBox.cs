// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>
    /// o3d.geometry.OrientedBoundingBox as an immutable value: center, row-major 3x3 rotation R (column k
    /// is the direction of Extent[k]) and full edge lengths. Getters return copies.
    /// </summary>
    public sealed class OrientedBoundingBox
    {
        readonly double[] center;
        readonly double[] r;
        readonly double[] extent;

        public OrientedBoundingBox(double[] center, double[] R, double[] extent)
        {
            this.center = (double[])Checks.Fixed(center, 3, "center", false).Clone();
            this.r = (double[])Checks.Fixed(R, 9, "R", false).Clone();
            this.extent = (double[])Checks.Fixed(extent, 3, "extent", false).Clone();
        }

        public double[] Center { get { return (double[])center.Clone(); } }
        /// <summary>Row-major 3x3 rotation (9 values).</summary>
        public double[] R { get { return (double[])r.Clone(); } }
        /// <summary>Full edge lengths along the box axes.</summary>
        public double[] Extent { get { return (double[])extent.Clone(); } }
        /// <summary>Product of the extents.</summary>
        public double Volume { get { return extent[0] * extent[1] * extent[2]; } }

        /// <summary>
        /// PCA box of the convex hull of (N x 3) <paramref name="points"/> (N &gt;= 4, not coplanar unless
        /// <paramref name="robust"/>, which joggles the hull input) (create_from_points).
        /// </summary>
        public static OrientedBoundingBox CreateFromPoints(double[] points, bool robust = false)
        {
            ulong n = Checks.Rows3(points, "points");
            using (var b = new o3d_obb_t())
            {
                O3dNative.o3d_obb_create_from_points(b, points, n, robust ? 1 : 0);
                return FromNative(b);
            }
        }

        /// <summary>The box equal to the axis-aligned box <paramref name="min"/>..<paramref name="max"/> (R = I).</summary>
        public static OrientedBoundingBox CreateFromAxisAlignedBoundingBox(double[] min, double[] max)
        {
            using (var b = new o3d_obb_t())
            {
                O3dNative.o3d_obb_create_from_axis_aligned_bounding_box(b, Checks.Fixed(min, 3, "min", false),
                                                                        Checks.Fixed(max, 3, "max", false));
                return FromNative(b);
            }
        }

        /// <summary>The 8 corners (8 x 3, row-major) in Open3D's get_box_points order.</summary>
        public double[] GetBoxPoints()
        {
            var corners = new double[24];
            using (var b = ToNative()) O3dNative.o3d_obb_get_box_points(corners, b);
            return corners;
        }

        /// <summary>Ascending indices of the (N x 3) <paramref name="points"/> inside the box (boundary included).</summary>
        public int[] GetPointIndicesWithinBoundingBox(double[] points)
        {
            ulong n = Checks.Rows3(points, "points");
            var indices = new int[n];
            ulong count;
            using (var b = ToNative()) O3dNative.o3d_obb_get_point_indices_within(indices, n, out count, b, points, n);
            return Checks.Trim(indices, count);
        }

        /// <summary>A new native struct; the caller disposes it.</summary>
        internal o3d_obb_t ToNative()
        {
            var b = new o3d_obb_t();
            var values = new double[15];
            Array.Copy(center, 0, values, 0, 3);
            Array.Copy(r, 0, values, 3, 9);
            Array.Copy(extent, 0, values, 12, 3);
            O3dNative.o3dx_obb_set(b, values);
            return b;
        }

        internal static OrientedBoundingBox FromNative(o3d_obb_t b)
        {
            var values = new double[15];
            O3dNative.o3dx_obb_get(b, values);
            var c = new double[3]; var rot = new double[9]; var e = new double[3];
            Array.Copy(values, 0, c, 0, 3);
            Array.Copy(values, 3, rot, 0, 9);
            Array.Copy(values, 12, e, 0, 3);
            return new OrientedBoundingBox(c, rot, e);
        }

        public override string ToString()
        {
            return string.Format("OrientedBoundingBox(center=({0}, {1}, {2}), extent=({3}, {4}, {5}))",
                                 center[0], center[1], center[2], extent[0], extent[1], extent[2]);
        }
    }

    /// <summary>
    /// Result of the convex hull and hidden-point removal (Open3D's <c>(mesh, indices)</c> tuple): the mesh
    /// (outward-facing triangles) and, for each of its vertices, the index of the input point it came from.
    /// Disposing it disposes <see cref="Mesh"/>.
    /// </summary>
    public sealed class ConvexHullResult : IDisposable
    {
        internal ConvexHullResult(TriangleMesh mesh, int[] pointIndices) { Mesh = mesh; PointIndices = pointIndices; }

        public TriangleMesh Mesh { get; private set; }
        /// <summary>Input point index of each mesh vertex.</summary>
        public int[] PointIndices { get; private set; }

        public void Dispose() { Mesh.Dispose(); }
    }
}
