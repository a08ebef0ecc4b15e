// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>
    /// o3d.geometry.RGBDImage: a color (or float intensity) image and a float32 depth image in metres,
    /// of the same size. Dispose it.
    /// </summary>
    public sealed class RGBDImage : NativeHandle
    {
        internal RGBDImage(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_rgbd_image_destroy(handle); }

        /// <summary>
        /// Pair an 8-bit color image (1 or 3 channels) with a uint16 or float32 depth image
        /// (RGBDImage.create_from_color_and_depth; depth becomes float metres = raw / depthScale, 0 beyond depthTrunc).
        /// </summary>
        public static RGBDImage CreateFromColorAndDepth(Image color, Image depth, double depthScale = 1000.0,
                                                        double depthTrunc = 3.0, bool convertRgbToIntensity = true)
        {
            if (color == null) throw new ArgumentNullException("color");
            if (depth == null) throw new ArgumentNullException("depth");
            IntPtr h;
            using (var o = new o3d_rgbd_options_t())
            {
                O3dNative.o3d_rgbd_options_init(o, O3dNative.o3dx_sizeof_rgbd_options());
                o.depth_scale = depthScale;
                o.depth_trunc = depthTrunc;
                o.convert_rgb_to_intensity = convertRgbToIntensity ? 1 : 0;
                O3dNative.o3d_rgbd_image_create_from_color_and_depth(out h, color.Handle, depth.Handle, o);
            }
            GC.KeepAlive(color); GC.KeepAlive(depth);
            return new RGBDImage(h);
        }

        static RGBDImage FromDataset(int format, Image color, Image depth, bool convertRgbToIntensity)
        {
            if (color == null) throw new ArgumentNullException("color");
            if (depth == null) throw new ArgumentNullException("depth");
            IntPtr h;
            O3dNative.o3d_rgbd_image_create_from_dataset_format(out h, format, color.Handle, depth.Handle,
                                                                convertRgbToIntensity ? 1 : 0);
            GC.KeepAlive(color); GC.KeepAlive(depth);
            return new RGBDImage(h);
        }

        /// <summary>Redwood: depth in mm (uint16), truncated at 4 m.</summary>
        public static RGBDImage CreateFromRedwoodFormat(Image color, Image depth, bool convertRgbToIntensity = true)
        { return FromDataset(O3dNative.O3D_RGBD_FORMAT_REDWOOD, color, depth, convertRgbToIntensity); }

        /// <summary>TUM: depth scale 5000, truncated at 4 m.</summary>
        public static RGBDImage CreateFromTUMFormat(Image color, Image depth, bool convertRgbToIntensity = true)
        { return FromDataset(O3dNative.O3D_RGBD_FORMAT_TUM, color, depth, convertRgbToIntensity); }

        /// <summary>SUN RGB-D: depth bits rotated right by 3, in mm, truncated at 7 m.</summary>
        public static RGBDImage CreateFromSUNFormat(Image color, Image depth, bool convertRgbToIntensity = true)
        { return FromDataset(O3dNative.O3D_RGBD_FORMAT_SUN, color, depth, convertRgbToIntensity); }

        /// <summary>NYU raw PGM: byte-swapped disparity converted to metres, truncated at 7 m.</summary>
        public static RGBDImage CreateFromNYUFormat(Image color, Image depth, bool convertRgbToIntensity = true)
        { return FromDataset(O3dNative.O3D_RGBD_FORMAT_NYU, color, depth, convertRgbToIntensity); }

        /// <summary>A copy of the color (or intensity) image; dispose it.</summary>
        public Image Color
        {
            get { IntPtr h; O3dNative.o3d_rgbd_image_get_color(out h, Handle); GC.KeepAlive(this); return new Image(h); }
        }

        /// <summary>A copy of the depth image (1-channel float32, metres); dispose it.</summary>
        public Image Depth
        {
            get { IntPtr h; O3dNative.o3d_rgbd_image_get_depth(out h, Handle); GC.KeepAlive(this); return new Image(h); }
        }
    }

    public sealed partial class PointCloud
    {
        /// <summary>
        /// Back-project a 1-channel depth image (uint16 raw, or float32 metres) through <paramref name="intrinsic"/>,
        /// then to world coordinates with the inverse of <paramref name="extrinsic"/> (row-major 4x4; null: identity).
        /// Open3D's PointCloud.create_from_depth_image.
        /// </summary>
        public static PointCloud CreateFromDepthImage(Image depth, PinholeCameraIntrinsic intrinsic, double[] extrinsic = null,
                                                      double depthScale = 1000.0, double depthTrunc = 1000.0,
                                                      int stride = 1, bool projectValidDepthOnly = true)
        {
            if (depth == null) throw new ArgumentNullException("depth");
            if (intrinsic == null) throw new ArgumentNullException("intrinsic");
            IntPtr h;
            using (var k = intrinsic.ToNative())
            using (var o = new o3d_depth_to_cloud_options_t())
            {
                O3dNative.o3d_depth_to_cloud_options_init(o, O3dNative.o3dx_sizeof_depth_to_cloud_options());
                o.depth_scale = depthScale;
                o.depth_trunc = depthTrunc;
                o.stride = stride;
                o.project_valid_depth_only = projectValidDepthOnly ? 1 : 0;
                O3dNative.o3d_pointcloud_create_from_depth_image(out h, depth.Handle, k,
                    Checks.Fixed(extrinsic, 16, "extrinsic", true), o);
            }
            GC.KeepAlive(depth);
            return new PointCloud(h);
        }

        /// <summary>As <see cref="CreateFromDepthImage"/> for an RGB-D image, with per-point colors.</summary>
        public static PointCloud CreateFromRGBDImage(RGBDImage image, PinholeCameraIntrinsic intrinsic, double[] extrinsic = null,
                                                     bool projectValidDepthOnly = true)
        {
            if (image == null) throw new ArgumentNullException("image");
            if (intrinsic == null) throw new ArgumentNullException("intrinsic");
            IntPtr h;
            using (var k = intrinsic.ToNative())
                O3dNative.o3d_pointcloud_create_from_rgbd_image(out h, image.Handle, k,
                    Checks.Fixed(extrinsic, 16, "extrinsic", true), projectValidDepthOnly ? 1 : 0);
            GC.KeepAlive(image);
            return new PointCloud(h);
        }
    }
}
