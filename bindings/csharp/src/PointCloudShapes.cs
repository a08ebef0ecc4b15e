// SPDX-License-Identifier: MIT
// PointCloud: oriented boxes, convex hull, hidden-point removal and per-point covariances.
using System;

namespace O3d
{
    public sealed partial class PointCloud
    {
        /// <summary>Oriented box of the points (get_oriented_bounding_box); robust joggles degenerate sets.</summary>
        public OrientedBoundingBox GetOrientedBoundingBox(bool robust = false)
        {
            using (var b = new o3d_obb_t())
            {
                O3dNative.o3d_pointcloud_get_oriented_bounding_box(b, Handle, robust ? 1 : 0);
                GC.KeepAlive(this);
                return OrientedBoundingBox.FromNative(b);
            }
        }

        /// <summary>New cloud with the points inside <paramref name="box"/> (outside when <paramref name="invert"/>).</summary>
        public PointCloud Crop(OrientedBoundingBox box, bool invert = false)
        {
            if (box == null) throw new ArgumentNullException("box");
            IntPtr h;
            using (var b = box.ToNative()) O3dNative.o3d_pointcloud_crop_obb(out h, Handle, b, invert ? 1 : 0);
            GC.KeepAlive(this);
            return new PointCloud(h);
        }

        /// <summary>Axis-aligned crop (Open3D's crop with an AxisAlignedBoundingBox); same as <see cref="CropAabb"/>.</summary>
        public PointCloud Crop(double[] min, double[] max, bool invert = false) { return CropAabb(min, max, invert); }

        /// <summary>
        /// Convex hull of the points through Qhull (compute_convex_hull): at least 4 points, not coplanar
        /// unless <paramref name="joggleInputs"/>.
        /// </summary>
        public ConvexHullResult ComputeConvexHull(bool joggleInputs = false)
        {
            ulong cap = (ulong)Size;
            var indices = new int[cap];
            IntPtr h; ulong n;
            O3dNative.o3d_pointcloud_compute_convex_hull(out h, indices, cap, out n, Handle, joggleInputs ? 1 : 0);
            GC.KeepAlive(this);
            return new ConvexHullResult(new TriangleMesh(h), Checks.Trim(indices, n));
        }

        /// <summary>
        /// The points visible from <paramref name="cameraLocation"/> (hidden_point_removal, Katz et al. 2007):
        /// the hull mesh and the indices of the visible points. Larger <paramref name="radius"/> keeps more.
        /// </summary>
        public ConvexHullResult HiddenPointRemoval(double[] cameraLocation, double radius)
        {
            var cam = Checks.Fixed(cameraLocation, 3, "cameraLocation", false);
            ulong cap = (ulong)Size + 1;
            var indices = new int[cap];
            IntPtr h; ulong n;
            O3dNative.o3d_pointcloud_hidden_point_removal(out h, indices, cap, out n, Handle, cam, radius);
            GC.KeepAlive(this);
            return new ConvexHullResult(new TriangleMesh(h), Checks.Trim(indices, n));
        }

        // ---- per-point covariances ---------------------------------------------------------------

        /// <summary>True when the cloud has one covariance per point.</summary>
        public bool HasCovariances
        {
            get { int v; O3dNative.o3d_pointcloud_has_array(out v, Handle, O3D_POINTCLOUD_COVARIANCES); GC.KeepAlive(this); return v != 0; }
        }

        /// <summary>Covariances: N row-major 3x3 matrices, 9N values (a copy; setting copies in).</summary>
        public double[] Covariances
        {
            get
            {
                IntPtr h = Handle;
                ulong n;
                O3dNative.o3d_pointcloud_get_array(null, 0, out n, h, O3D_POINTCLOUD_COVARIANCES);
                var result = new double[checked((long)n * 9)];
                O3dNative.o3d_pointcloud_get_array(result, n, out n, h, O3D_POINTCLOUD_COVARIANCES);
                GC.KeepAlive(this);
                return result;
            }
            set
            {
                if (value == null) throw new ArgumentNullException("value");
                if (value.Length % 9 != 0)
                    throw new ArgumentException("value: length " + value.Length + " is not a multiple of 9", "value");
                O3dNative.o3d_pointcloud_set_array(Handle, O3D_POINTCLOUD_COVARIANCES, value, (ulong)(value.Length / 9));
                GC.KeepAlive(this);
            }
        }

        /// <summary>Borrowed view of the covariances (<paramref name="rows"/> x 9 doubles), as the other views.</summary>
        public IntPtr CovariancesView(out long rows)
        {
            IntPtr data; ulong n;
            O3dNative.o3d_pointcloud_array_view(out data, out n, Handle, O3D_POINTCLOUD_COVARIANCES);
            GC.KeepAlive(this); rows = (long)n; return data;
        }

        /// <summary>Covariance of each point's neighbourhood (estimate_covariances; null param: KNN 30).</summary>
        public PointCloud EstimateCovariances(SearchParam param = null)
        {
            o3d_search_param_t p = param != null ? param.ToNative() : null;
            try { O3dNative.o3d_pointcloud_estimate_covariances(Handle, p); }
            finally { if (p != null) p.Dispose(); }
            GC.KeepAlive(this);
            return this;
        }
    }

    public sealed partial class TriangleMesh
    {
        /// <summary>Oriented box of the vertices (get_oriented_bounding_box).</summary>
        public OrientedBoundingBox GetOrientedBoundingBox(bool robust = false)
        {
            using (var b = new o3d_obb_t())
            {
                O3dNative.o3d_trianglemesh_get_oriented_bounding_box(b, Handle, robust ? 1 : 0);
                GC.KeepAlive(this);
                return OrientedBoundingBox.FromNative(b);
            }
        }

        /// <summary>New mesh of the triangles whose three vertices lie inside <paramref name="box"/>.</summary>
        public TriangleMesh Crop(OrientedBoundingBox box)
        {
            if (box == null) throw new ArgumentNullException("box");
            IntPtr h;
            using (var b = box.ToNative()) O3dNative.o3d_trianglemesh_crop_obb(out h, Handle, b);
            GC.KeepAlive(this);
            return new TriangleMesh(h);
        }

        /// <summary>Convex hull of the vertices (compute_convex_hull).</summary>
        public ConvexHullResult ComputeConvexHull(bool joggleInputs = false)
        {
            ulong cap = (ulong)NumVertices;
            var indices = new int[cap];
            IntPtr h; ulong n;
            O3dNative.o3d_trianglemesh_compute_convex_hull(out h, indices, cap, out n, Handle, joggleInputs ? 1 : 0);
            GC.KeepAlive(this);
            return new ConvexHullResult(new TriangleMesh(h), Checks.Trim(indices, n));
        }
    }
}
