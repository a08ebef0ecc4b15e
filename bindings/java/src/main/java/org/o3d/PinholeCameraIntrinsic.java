// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * o3d.camera.PinholeCameraIntrinsic as an immutable value: image size, focal lengths and principal
 * point in pixels. Compared by value.
 */
public final class PinholeCameraIntrinsic {
    private final int width;
    private final int height;
    private final double fx;
    private final double fy;
    private final double cx;
    private final double cy;

    public PinholeCameraIntrinsic(int width, int height, double fx, double fy, double cx, double cy) {
        this.width = width;
        this.height = height;
        this.fx = fx;
        this.fy = fy;
        this.cx = cx;
        this.cy = cy;
    }

    /** One of Open3D's presets. */
    public static PinholeCameraIntrinsic fromPreset(PinholeCameraIntrinsicParameters preset) {
        o3d_pinhole_intrinsic_t n = new o3d_pinhole_intrinsic_t();
        try {
            O3dNative.o3d_pinhole_intrinsic_set_preset(n, preset.code());
            return fromNative(n);
        } finally {
            n.delete();
        }
    }

    public int width() { return width; }
    public int height() { return height; }
    public double fx() { return fx; }
    public double fy() { return fy; }
    public double cx() { return cx; }
    public double cy() { return cy; }

    /** Row-major 3x3 [[fx, 0, cx], [0, fy, cy], [0, 0, 1]]. */
    public double[] intrinsicMatrix() {
        return new double[] {fx, 0, cx, 0, fy, cy, 0, 0, 1};
    }

    /** A new native struct; the caller deletes it. */
    o3d_pinhole_intrinsic_t toNative() {
        o3d_pinhole_intrinsic_t n = new o3d_pinhole_intrinsic_t();
        n.setWidth(width);
        n.setHeight(height);
        n.setFx(fx);
        n.setFy(fy);
        n.setCx(cx);
        n.setCy(cy);
        return n;
    }

    static PinholeCameraIntrinsic fromNative(o3d_pinhole_intrinsic_t n) {
        return new PinholeCameraIntrinsic(n.getWidth(), n.getHeight(), n.getFx(), n.getFy(), n.getCx(), n.getCy());
    }

    @Override
    public boolean equals(Object o) {
        if (!(o instanceof PinholeCameraIntrinsic)) return false;
        PinholeCameraIntrinsic k = (PinholeCameraIntrinsic) o;
        return width == k.width && height == k.height && Double.compare(fx, k.fx) == 0 && Double.compare(fy, k.fy) == 0
                && Double.compare(cx, k.cx) == 0 && Double.compare(cy, k.cy) == 0;
    }

    @Override
    public int hashCode() {
        return java.util.Objects.hash(width, height, fx, fy, cx, cy);
    }

    @Override
    public String toString() {
        return "PinholeCameraIntrinsic(" + width + "x" + height + ", fx=" + fx + ", fy=" + fy + ", cx=" + cx + ", cy=" + cy + ")";
    }
}
