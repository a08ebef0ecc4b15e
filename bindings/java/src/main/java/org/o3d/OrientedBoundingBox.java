// SPDX-License-Identifier: MIT
package org.o3d;

import java.util.Arrays;
import java.util.Objects;

/**
 * o3d.geometry.OrientedBoundingBox as an immutable value: center, row-major 3x3 rotation R (column k is the
 * direction of extent[k]) and full edge lengths. Getters return copies.
 */
public final class OrientedBoundingBox {
    private final double[] center;
    private final double[] r;
    private final double[] extent;

    public OrientedBoundingBox(double[] center, double[] R, double[] extent) {
        this.center = NativeResource.fixed(center, 3, "center", false).clone();
        this.r = NativeResource.fixed(R, 9, "R", false).clone();
        this.extent = NativeResource.fixed(extent, 3, "extent", false).clone();
    }

    public double[] center() { return center.clone(); }
    /** Row-major 3x3 rotation (9 values). */
    public double[] R() { return r.clone(); }
    /** Full edge lengths along the box axes. */
    public double[] extent() { return extent.clone(); }
    /** Product of the extents. */
    public double volume() { return extent[0] * extent[1] * extent[2]; }

    /**
     * PCA box of the convex hull of (N x 3) {@code points} (N >= 4, not coplanar unless {@code robust},
     * which joggles the hull input) (create_from_points).
     */
    public static OrientedBoundingBox createFromPoints(double[] points, boolean robust) {
        Objects.requireNonNull(points, "points");
        long n = NativeResource.rows3(points.length, "points");
        o3d_obb_t b = new o3d_obb_t();
        try {
            O3dNative.o3d_obb_create_from_points(b, points, n, robust ? 1 : 0);
            return fromNative(b);
        } finally {
            b.delete();
        }
    }

    public static OrientedBoundingBox createFromPoints(double[] points) { return createFromPoints(points, false); }

    /** The box equal to the axis-aligned box {@code min}..{@code max} (R = I). */
    public static OrientedBoundingBox createFromAxisAlignedBoundingBox(double[] min, double[] max) {
        o3d_obb_t b = new o3d_obb_t();
        try {
            O3dNative.o3d_obb_create_from_axis_aligned_bounding_box(b, NativeResource.fixed(min, 3, "min", false),
                    NativeResource.fixed(max, 3, "max", false));
            return fromNative(b);
        } finally {
            b.delete();
        }
    }

    /** The 8 corners (8 x 3, row-major) in Open3D's get_box_points order. */
    public double[] getBoxPoints() {
        double[] corners = new double[24];
        o3d_obb_t b = toNative();
        try {
            O3dNative.o3d_obb_get_box_points(corners, b);
        } finally {
            b.delete();
        }
        return corners;
    }

    /** Ascending indices of the (N x 3) {@code points} inside the box (boundary included). */
    public int[] getPointIndicesWithinBoundingBox(double[] points) {
        Objects.requireNonNull(points, "points");
        long n = NativeResource.rows3(points.length, "points");
        int[] indices = new int[(int) n];
        long[] count = new long[1];
        o3d_obb_t b = toNative();
        try {
            O3dNative.o3d_obb_get_point_indices_within(indices, n, count, b, points, n);
        } finally {
            b.delete();
        }
        return NativeResource.trimTo(indices, count[0]);
    }

    /** A new native struct; the caller deletes it. */
    o3d_obb_t toNative() {
        double[] values = new double[15];
        System.arraycopy(center, 0, values, 0, 3);
        System.arraycopy(r, 0, values, 3, 9);
        System.arraycopy(extent, 0, values, 12, 3);
        o3d_obb_t b = new o3d_obb_t();
        O3dNative.o3dx_obb_set(b, values);
        return b;
    }

    static OrientedBoundingBox fromNative(o3d_obb_t b) {
        double[] values = new double[15];
        O3dNative.o3dx_obb_get(b, values);
        return new OrientedBoundingBox(Arrays.copyOfRange(values, 0, 3), Arrays.copyOfRange(values, 3, 12),
                Arrays.copyOfRange(values, 12, 15));
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof OrientedBoundingBox)) return false;
        OrientedBoundingBox b = (OrientedBoundingBox) o;
        return Arrays.equals(center, b.center) && Arrays.equals(r, b.r) && Arrays.equals(extent, b.extent);
    }

    @Override
    public int hashCode() {
        return Objects.hash(Arrays.hashCode(center), Arrays.hashCode(r), Arrays.hashCode(extent));
    }

    @Override
    public String toString() {
        return "OrientedBoundingBox(center=" + Arrays.toString(center) + ", extent=" + Arrays.toString(extent) + ")";
    }
}
