// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.nio.ByteBuffer;
import java.util.Objects;

/**
 * A line set (o3d.geometry.LineSet): (N x 3) points, (M x 2) int lines between them and (M x 3) per-line
 * colors, row-major. Getters copy out and setters copy in. Close it (try-with-resources).
 */
public final class LineSet extends NativeResource {
    LineSet(long handle) {
        super(handle, O3dNative::o3d_lineset_destroy);
    }

    private static long create() {
        long[] h = new long[1];
        O3dNative.o3d_lineset_create(h);
        return h[0];
    }

    static LineSet wrap(long[] h) {
        return new LineSet(h[0]);
    }

    /** An empty line set. */
    public LineSet() {
        this(create());
    }

    /** A line set with (N x 3) points and (M x 2) lines. */
    public LineSet(double[] points, int[] lines) {
        this(create());
        try {
            setPoints(points);
            setLines(lines);
        } catch (RuntimeException e) {
            close();
            throw e;
        }
    }

    public LineSet copy() {
        long[] h = new long[1];
        O3dNative.o3d_lineset_clone(h, handle());
        Reference.reachabilityFence(this);
        return wrap(h);
    }

    public long numPoints() {
        long[] n = new long[1];
        O3dNative.o3d_lineset_num_points(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    public long numLines() {
        long[] n = new long[1];
        O3dNative.o3d_lineset_num_lines(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    private double[] getArray(int which) {
        long h = handle();
        long[] n = new long[1];
        O3dNative.o3d_lineset_get_array(null, 0, n, h, which);
        double[] out = new double[Math.toIntExact(n[0] * 3)];
        O3dNative.o3d_lineset_get_array(out, n[0], n, h, which);
        Reference.reachabilityFence(this);
        return out;
    }

    private void setArray(int which, double[] values, String name) {
        Objects.requireNonNull(values, name);
        O3dNative.o3d_lineset_set_array(handle(), which, values, rows3(values.length, name));
        Reference.reachabilityFence(this);
    }

    /** Points x0,y0,z0,x1,... (a copy). */
    public double[] getPoints() { return getArray(O3dNativeConstants.O3D_LINESET_POINTS); }
    public void setPoints(double[] points) { setArray(O3dNativeConstants.O3D_LINESET_POINTS, points, "points"); }
    /** One RGB color in [0,1] per line (a copy). */
    public double[] getColors() { return getArray(O3dNativeConstants.O3D_LINESET_COLORS); }
    public void setColors(double[] colors) { setArray(O3dNativeConstants.O3D_LINESET_COLORS, colors, "colors"); }

    /** Lines as point indices a0,b0,a1,b1,... (a copy). */
    public int[] getLines() {
        long h = handle();
        long[] n = new long[1];
        O3dNative.o3d_lineset_get_index_array(null, 0, n, h, O3D_LINESET_LINES);
        int[] out = new int[Math.toIntExact(n[0] * 2)];
        O3dNative.o3d_lineset_get_index_array(out, n[0], n, h, O3D_LINESET_LINES);
        Reference.reachabilityFence(this);
        return out;
    }

    /** Replace the lines (length 2M; indices are checked by the operations that follow them). */
    public void setLines(int[] lines) {
        Objects.requireNonNull(lines, "lines");
        if (lines.length % 2 != 0)
            throw new IllegalArgumentException("lines: length " + lines.length + " is not a multiple of 2");
        O3dNative.o3d_lineset_set_index_array(handle(), O3D_LINESET_LINES, lines, lines.length / 2);
        Reference.reachabilityFence(this);
    }

    // Borrowed read-only views (direct ByteBuffers, native order), valid until the next mutating call or close().
    private ByteBuffer arrayView(int which) {
        long[] data = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_lineset_array_view(data, n, handle(), which);
        Reference.reachabilityFence(this);
        return readOnlyView(data[0], n[0] * 3 * Double.BYTES);
    }

    public ByteBuffer pointsView() { return arrayView(O3dNativeConstants.O3D_LINESET_POINTS); }
    public ByteBuffer colorsView() { return arrayView(O3dNativeConstants.O3D_LINESET_COLORS); }

    public ByteBuffer linesView() {
        long[] data = new long[1];
        long[] n = new long[1];
        O3dNative.o3d_lineset_index_array_view(data, n, handle(), O3D_LINESET_LINES);
        Reference.reachabilityFence(this);
        return readOnlyView(data[0], n[0] * 2 * Integer.BYTES);
    }

    public LineSet paintUniformColor(double[] rgb) {
        O3dNative.o3d_lineset_paint_uniform_color(handle(), fixed(rgb, 3, "rgb", false));
        Reference.reachabilityFence(this);
        return this;
    }

    /** Apply a row-major 4x4 transform (16 values) to the points. */
    public LineSet transform(double[] transform) {
        O3dNative.o3d_lineset_transform(handle(), fixed(transform, 16, "transform", false));
        Reference.reachabilityFence(this);
        return this;
    }

    // ---- factories --------------------------------------------------------------------------------

    /**
     * Points of both clouds (cloud0's first) and one line per (index in cloud0, index in cloud1) pair
     * (create_from_point_cloud_correspondences).
     */
    public static LineSet createFromPointCloudCorrespondences(PointCloud cloud0, PointCloud cloud1, int[] pairs) {
        Objects.requireNonNull(cloud0, "cloud0");
        Objects.requireNonNull(cloud1, "cloud1");
        Objects.requireNonNull(pairs, "pairs");
        if (pairs.length % 2 != 0)
            throw new IllegalArgumentException("pairs: length " + pairs.length + " is not a multiple of 2");
        long[] h = new long[1];
        O3dNative.o3d_lineset_create_from_point_cloud_correspondences(h, cloud0.handle(), cloud1.handle(), pairs,
                pairs.length / 2);
        Reference.reachabilityFence(cloud0);
        Reference.reachabilityFence(cloud1);
        return wrap(h);
    }

    /** The 12 edges of {@code box} (points in get_box_points order). */
    public static LineSet createFromOrientedBoundingBox(OrientedBoundingBox box) {
        Objects.requireNonNull(box, "box");
        long[] h = new long[1];
        o3d_obb_t b = box.toNative();
        try {
            O3dNative.o3d_lineset_create_from_oriented_bounding_box(h, b);
        } finally {
            b.delete();
        }
        return wrap(h);
    }

    /** The 12 edges of the axis-aligned box {@code min}..{@code max}. */
    public static LineSet createFromAxisAlignedBoundingBox(double[] min, double[] max) {
        long[] h = new long[1];
        O3dNative.o3d_lineset_create_from_axis_aligned_bounding_box(h, fixed(min, 3, "min", false),
                fixed(max, 3, "max", false));
        return wrap(h);
    }

    /** The unique edges of {@code mesh} on its vertices (create_from_triangle_mesh). */
    public static LineSet createFromTriangleMesh(TriangleMesh mesh) {
        Objects.requireNonNull(mesh, "mesh");
        long[] h = new long[1];
        O3dNative.o3d_lineset_create_from_triangle_mesh(h, mesh.handle());
        Reference.reachabilityFence(mesh);
        return wrap(h);
    }
}
