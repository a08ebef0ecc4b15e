// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.Objects;

/**
 * o3d.geometry.RGBDImage: a color (or float intensity) image and a float32 depth image in metres, of
 * the same size. Close it.
 */
public final class RGBDImage extends NativeResource {
    RGBDImage(long handle) {
        super(handle, O3dNative::o3d_rgbd_image_destroy);
    }

    /**
     * Pair an 8-bit color image (1 or 3 channels) with a uint16 or float32 depth image
     * (RGBDImage.create_from_color_and_depth: depth becomes raw / depthScale metres, 0 beyond depthTrunc).
     */
    public static RGBDImage createFromColorAndDepth(Image color, Image depth, double depthScale, double depthTrunc,
            boolean convertRgbToIntensity) {
        Objects.requireNonNull(color, "color");
        Objects.requireNonNull(depth, "depth");
        long[] h = new long[1];
        o3d_rgbd_options_t o = new o3d_rgbd_options_t();
        try {
            O3dNative.o3d_rgbd_options_init(o, O3dNative.o3dx_sizeof_rgbd_options());
            o.setDepth_scale(depthScale);
            o.setDepth_trunc(depthTrunc);
            o.setConvert_rgb_to_intensity(convertRgbToIntensity ? 1 : 0);
            O3dNative.o3d_rgbd_image_create_from_color_and_depth(h, color.handle(), depth.handle(), o);
        } finally {
            o.delete();
        }
        Reference.reachabilityFence(color);
        Reference.reachabilityFence(depth);
        return new RGBDImage(h[0]);
    }

    /** With Open3D's defaults: depth scale 1000, truncation 3 m, color converted to intensity. */
    public static RGBDImage createFromColorAndDepth(Image color, Image depth) {
        return createFromColorAndDepth(color, depth, 1000.0, 3.0, true);
    }

    private static RGBDImage fromDataset(int format, Image color, Image depth, boolean convertRgbToIntensity) {
        Objects.requireNonNull(color, "color");
        Objects.requireNonNull(depth, "depth");
        long[] h = new long[1];
        O3dNative.o3d_rgbd_image_create_from_dataset_format(h, format, color.handle(), depth.handle(),
                convertRgbToIntensity ? 1 : 0);
        Reference.reachabilityFence(color);
        Reference.reachabilityFence(depth);
        return new RGBDImage(h[0]);
    }

    /** Redwood: depth in mm (uint16), truncated at 4 m. */
    public static RGBDImage createFromRedwoodFormat(Image color, Image depth, boolean convertRgbToIntensity) {
        return fromDataset(O3dNativeConstants.O3D_RGBD_FORMAT_REDWOOD, color, depth, convertRgbToIntensity);
    }

    /** TUM: depth scale 5000, truncated at 4 m. */
    public static RGBDImage createFromTUMFormat(Image color, Image depth, boolean convertRgbToIntensity) {
        return fromDataset(O3dNativeConstants.O3D_RGBD_FORMAT_TUM, color, depth, convertRgbToIntensity);
    }

    /** SUN RGB-D: depth bits rotated right by 3, in mm, truncated at 7 m. */
    public static RGBDImage createFromSUNFormat(Image color, Image depth, boolean convertRgbToIntensity) {
        return fromDataset(O3dNativeConstants.O3D_RGBD_FORMAT_SUN, color, depth, convertRgbToIntensity);
    }

    /** NYU raw PGM: byte-swapped disparity converted to metres, truncated at 7 m. */
    public static RGBDImage createFromNYUFormat(Image color, Image depth, boolean convertRgbToIntensity) {
        return fromDataset(O3dNativeConstants.O3D_RGBD_FORMAT_NYU, color, depth, convertRgbToIntensity);
    }

    public static RGBDImage createFromRedwoodFormat(Image color, Image depth) { return createFromRedwoodFormat(color, depth, true); }
    public static RGBDImage createFromTUMFormat(Image color, Image depth) { return createFromTUMFormat(color, depth, true); }
    public static RGBDImage createFromSUNFormat(Image color, Image depth) { return createFromSUNFormat(color, depth, true); }
    public static RGBDImage createFromNYUFormat(Image color, Image depth) { return createFromNYUFormat(color, depth, true); }

    /** A copy of the color (or intensity) image; close it. */
    public Image color() {
        long[] h = new long[1];
        O3dNative.o3d_rgbd_image_get_color(h, handle());
        Reference.reachabilityFence(this);
        return new Image(h[0]);
    }

    /** A copy of the depth image (1-channel float32, metres); close it. */
    public Image depth() {
        long[] h = new long[1];
        O3dNative.o3d_rgbd_image_get_depth(h, handle());
        Reference.reachabilityFence(this);
        return new Image(h[0]);
    }
}
