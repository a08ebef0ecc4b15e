// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.Objects;

/**
 * A sparse voxel grid (o3d.geometry.VoxelGrid): occupied cells of edge {@link #voxelSize()} on a grid whose
 * cell (0,0,0) starts at {@link #origin()}. Made by the static factories; close it.
 */
public final class VoxelGrid extends NativeResource {
    VoxelGrid(long handle) {
        super(handle, O3dNative::o3d_voxelgrid_destroy);
    }

    /** Voxels holding at least one point; origin = min bound - voxelSize / 2 (create_from_point_cloud). */
    public static VoxelGrid createFromPointCloud(PointCloud cloud, double voxelSize) {
        Objects.requireNonNull(cloud, "cloud");
        long[] h = new long[1];
        O3dNative.o3d_voxelgrid_create_from_point_cloud(h, cloud.handle(), voxelSize);
        Reference.reachabilityFence(cloud);
        return new VoxelGrid(h[0]);
    }

    /** As {@link #createFromPointCloud} on the grid starting at {@code min}; points outside are ignored. */
    public static VoxelGrid createFromPointCloudWithinBounds(PointCloud cloud, double voxelSize, double[] min,
                                                             double[] max) {
        Objects.requireNonNull(cloud, "cloud");
        long[] h = new long[1];
        O3dNative.o3d_voxelgrid_create_from_point_cloud_within_bounds(h, cloud.handle(), voxelSize,
                fixed(min, 3, "min", false), fixed(max, 3, "max", false));
        Reference.reachabilityFence(cloud);
        return new VoxelGrid(h[0]);
    }

    /** Voxels intersecting at least one triangle of {@code mesh} (create_from_triangle_mesh). */
    public static VoxelGrid createFromTriangleMesh(TriangleMesh mesh, double voxelSize) {
        Objects.requireNonNull(mesh, "mesh");
        long[] h = new long[1];
        O3dNative.o3d_voxelgrid_create_from_triangle_mesh(h, mesh.handle(), voxelSize);
        Reference.reachabilityFence(mesh);
        return new VoxelGrid(h[0]);
    }

    public double voxelSize() {
        double[] v = new double[1];
        O3dNative.o3d_voxelgrid_get_voxel_size(v, handle());
        Reference.reachabilityFence(this);
        return v[0];
    }

    /** Corner of voxel (0,0,0). */
    public double[] origin() {
        double[] v = new double[3];
        O3dNative.o3d_voxelgrid_get_origin(v, handle());
        Reference.reachabilityFence(this);
        return v;
    }

    public long numVoxels() {
        long[] n = new long[1];
        O3dNative.o3d_voxelgrid_num_voxels(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    /** The occupied voxels, sorted by grid index (get_voxels). */
    public Voxels getVoxels() {
        long h = handle();
        long[] n = new long[1];
        O3dNative.o3d_voxelgrid_get_voxels(null, null, 0, n, h);
        int len = Math.toIntExact(n[0] * 3);
        int[] indices = new int[len];
        double[] colors = new double[len];
        O3dNative.o3d_voxelgrid_get_voxels(indices, colors, n[0], n, h);
        Reference.reachabilityFence(this);
        return new Voxels(indices, colors);
    }

    /** Grid index of the cell containing {@code point}, occupied or not (get_voxel). */
    public int[] getVoxel(double[] point) {
        int[] index = new int[3];
        O3dNative.o3d_voxelgrid_get_voxel(index, handle(), fixed(point, 3, "point", false));
        Reference.reachabilityFence(this);
        return index;
    }

    /** For each of the (N x 3) {@code points}, whether its cell is occupied (check_if_included). */
    public boolean[] checkIfIncluded(double[] points) {
        Objects.requireNonNull(points, "points");
        long n = rows3(points.length, "points");
        int[] flags = new int[(int) n];
        O3dNative.o3d_voxelgrid_check_if_included(flags, handle(), points, n);
        Reference.reachabilityFence(this);
        boolean[] result = new boolean[flags.length];
        for (int i = 0; i < flags.length; i++) result[i] = flags[i] != 0;
        return result;
    }
}
