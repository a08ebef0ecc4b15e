// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>The occupied voxels of a <see cref="VoxelGrid"/>, sorted by grid index (x, then y, then z).</summary>
    public sealed class Voxels
    {
        internal Voxels(int[] gridIndices, double[] colors) { GridIndices = gridIndices; Colors = colors; }

        /// <summary>Grid index (i, j, k) of each voxel, 3 ints per voxel.</summary>
        public int[] GridIndices { get; private set; }
        /// <summary>Mean RGB color of each voxel, 3 doubles per voxel.</summary>
        public double[] Colors { get; private set; }
        public int Count { get { return GridIndices.Length / 3; } }
    }

    /// <summary>
    /// A sparse voxel grid (o3d.geometry.VoxelGrid): occupied cells of edge <see cref="VoxelSize"/> on a grid
    /// whose cell (0,0,0) starts at <see cref="Origin"/>. Made by the static factories; dispose it.
    /// </summary>
    public sealed class VoxelGrid : NativeHandle
    {
        internal VoxelGrid(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_voxelgrid_destroy(handle); }

        /// <summary>Voxels holding at least one point; origin = min bound - voxelSize / 2 (create_from_point_cloud).</summary>
        public static VoxelGrid CreateFromPointCloud(PointCloud cloud, double voxelSize)
        {
            if (cloud == null) throw new ArgumentNullException("cloud");
            IntPtr h;
            O3dNative.o3d_voxelgrid_create_from_point_cloud(out h, cloud.Handle, voxelSize);
            GC.KeepAlive(cloud);
            return new VoxelGrid(h);
        }

        /// <summary>As <see cref="CreateFromPointCloud"/> on the grid starting at <paramref name="min"/>; points outside ignored.</summary>
        public static VoxelGrid CreateFromPointCloudWithinBounds(PointCloud cloud, double voxelSize, double[] min, double[] max)
        {
            if (cloud == null) throw new ArgumentNullException("cloud");
            IntPtr h;
            O3dNative.o3d_voxelgrid_create_from_point_cloud_within_bounds(out h, cloud.Handle, voxelSize,
                                                                          Checks.Fixed(min, 3, "min", false),
                                                                          Checks.Fixed(max, 3, "max", false));
            GC.KeepAlive(cloud);
            return new VoxelGrid(h);
        }

        /// <summary>Voxels intersecting at least one triangle of <paramref name="mesh"/> (create_from_triangle_mesh).</summary>
        public static VoxelGrid CreateFromTriangleMesh(TriangleMesh mesh, double voxelSize)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            IntPtr h;
            O3dNative.o3d_voxelgrid_create_from_triangle_mesh(out h, mesh.Handle, voxelSize);
            GC.KeepAlive(mesh);
            return new VoxelGrid(h);
        }

        public double VoxelSize
        {
            get { double v; O3dNative.o3d_voxelgrid_get_voxel_size(out v, Handle); GC.KeepAlive(this); return v; }
        }

        /// <summary>Corner of voxel (0,0,0).</summary>
        public double[] Origin
        {
            get { var v = new double[3]; O3dNative.o3d_voxelgrid_get_origin(v, Handle); GC.KeepAlive(this); return v; }
        }

        public long NumVoxels
        {
            get { ulong n; O3dNative.o3d_voxelgrid_num_voxels(out n, Handle); GC.KeepAlive(this); return (long)n; }
        }

        /// <summary>The occupied voxels, sorted by grid index (get_voxels).</summary>
        public Voxels GetVoxels()
        {
            IntPtr h = Handle;
            ulong n;
            O3dNative.o3d_voxelgrid_get_voxels(null, null, 0, out n, h);
            var indices = new int[checked((long)n * 3)];
            var colors = new double[checked((long)n * 3)];
            O3dNative.o3d_voxelgrid_get_voxels(indices, colors, n, out n, h);
            GC.KeepAlive(this);
            return new Voxels(indices, colors);
        }

        /// <summary>Grid index of the cell containing <paramref name="point"/>, occupied or not (get_voxel).</summary>
        public int[] GetVoxel(double[] point)
        {
            var index = new int[3];
            O3dNative.o3d_voxelgrid_get_voxel(index, Handle, Checks.Fixed(point, 3, "point", false));
            GC.KeepAlive(this);
            return index;
        }

        /// <summary>For each of the (N x 3) <paramref name="points"/>, whether its cell is occupied (check_if_included).</summary>
        public bool[] CheckIfIncluded(double[] points)
        {
            ulong n = Checks.Rows3(points, "points");
            var flags = new int[n];
            O3dNative.o3d_voxelgrid_check_if_included(flags, Handle, points, n);
            GC.KeepAlive(this);
            var result = new bool[n];
            for (long i = 0; i < (long)n; ++i) result[i] = flags[i] != 0;
            return result;
        }
    }
}
