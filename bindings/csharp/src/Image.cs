// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>Image.filter kernels (Open3D's Image.FilterType).</summary>
    public enum ImageFilterType
    {
        Gaussian3 = O3dNative.O3D_IMAGE_FILTER_GAUSSIAN3,
        Gaussian5 = O3dNative.O3D_IMAGE_FILTER_GAUSSIAN5,
        Gaussian7 = O3dNative.O3D_IMAGE_FILTER_GAUSSIAN7,
        Sobel3Dx = O3dNative.O3D_IMAGE_FILTER_SOBEL3_DX,
        Sobel3Dy = O3dNative.O3D_IMAGE_FILTER_SOBEL3_DY,
    }

    /// <summary>How color becomes gray in <see cref="Image.CreateFloatImage"/> (Image.ColorToIntensityConversionType).</summary>
    public enum ImageConvertType
    {
        Equal = O3dNative.O3D_IMAGE_CONVERT_EQUAL,
        Weighted = O3dNative.O3D_IMAGE_CONVERT_WEIGHTED,
    }

    /// <summary>
    /// A 2D image (o3d.geometry.Image): 1, 3 or 4 interleaved channels of uint8 (1 byte), uint16 (2) or
    /// float32 (4), rows top to bottom. Pixels cross the boundary in one bulk copy (byte[], or ushort[] /
    /// float[] for the typed helpers, in native byte order). Dispose it; a finalizer destroys forgotten images.
    /// </summary>
    public sealed class Image : NativeHandle
    {
        internal Image(IntPtr handle) : base(handle) { }
        internal override void Destroy(IntPtr handle) { O3dNative.o3d_image_destroy(handle); }

        static IntPtr Create(int width, int height, int numChannels, int bytesPerChannel)
        {
            IntPtr h;
            O3dNative.o3d_image_create(out h, width, height, numChannels, bytesPerChannel);
            return h;
        }

        /// <summary>A zero-filled image (width, height &gt;= 1; 1, 3 or 4 channels; 1, 2 or 4 bytes per channel).</summary>
        public Image(int width, int height, int numChannels = 1, int bytesPerChannel = 1)
            : base(Create(width, height, numChannels, bytesPerChannel)) { }

        /// <summary>An image holding a copy of <paramref name="data"/> (exactly width*height*channels*bytesPerChannel bytes).</summary>
        public static Image FromBytes(int width, int height, int numChannels, int bytesPerChannel, byte[] data)
        {
            if (data == null) throw new ArgumentNullException("data");
            IntPtr h;
            O3dNative.o3d_image_create_from_data(out h, width, height, numChannels, bytesPerChannel, data, (ulong)data.Length);
            return new Image(h);
        }

        /// <summary>A uint16 image (e.g. raw depth in millimetres) from width*height*channels values.</summary>
        public static Image FromUInt16(int width, int height, int numChannels, ushort[] values)
        {
            if (values == null) throw new ArgumentNullException("values");
            var bytes = new byte[values.Length * 2];
            Buffer.BlockCopy(values, 0, bytes, 0, bytes.Length);
            return FromBytes(width, height, numChannels, 2, bytes);
        }

        /// <summary>A float32 image (e.g. depth in metres) from width*height*channels values.</summary>
        public static Image FromFloat(int width, int height, int numChannels, float[] values)
        {
            if (values == null) throw new ArgumentNullException("values");
            var bytes = new byte[values.Length * 4];
            Buffer.BlockCopy(values, 0, bytes, 0, bytes.Length);
            return FromBytes(width, height, numChannels, 4, bytes);
        }

        /// <summary>Deep copy.</summary>
        public Image Clone()
        {
            IntPtr h;
            O3dNative.o3d_image_clone(out h, Handle);
            GC.KeepAlive(this);
            return new Image(h);
        }

        delegate int IntGetter(IntPtr image, out int value);
        int GetInt(IntGetter fn) { int v; fn(Handle, out v); GC.KeepAlive(this); return v; }

        public int Width { get { return GetInt(O3dNative.o3d_image_width); } }
        public int Height { get { return GetInt(O3dNative.o3d_image_height); } }
        public int NumChannels { get { return GetInt(O3dNative.o3d_image_num_channels); } }
        public int BytesPerChannel { get { return GetInt(O3dNative.o3d_image_bytes_per_channel); } }

        /// <summary>The pixel bytes (a copy, one native call after the size query).</summary>
        public byte[] Data
        {
            get
            {
                IntPtr h = Handle;
                ulong n;
                O3dNative.o3d_image_get_array(null, 0, out n, h, O3D_IMAGE_DATA);
                var bytes = new byte[n];
                O3dNative.o3d_image_get_array(bytes, n, out n, h, O3D_IMAGE_DATA);
                GC.KeepAlive(this);
                return bytes;
            }
        }

        /// <summary>The pixels of a uint16 image as values (a copy).</summary>
        public ushort[] ToUInt16Array()
        {
            if (BytesPerChannel != 2) throw new InvalidOperationException("not a uint16 image");
            var bytes = Data;
            var values = new ushort[bytes.Length / 2];
            Buffer.BlockCopy(bytes, 0, values, 0, bytes.Length);
            return values;
        }

        /// <summary>The pixels of a float32 image as values (a copy).</summary>
        public float[] ToFloatArray()
        {
            if (BytesPerChannel != 4) throw new InvalidOperationException("not a float32 image");
            var bytes = Data;
            var values = new float[bytes.Length / 4];
            Buffer.BlockCopy(bytes, 0, values, 0, bytes.Length);
            return values;
        }

        // Borrowed views: the address of the image's own bytes, valid until the next mutating call or Dispose.
        public IntPtr DataView(out long size)
        {
            IntPtr data;
            ulong n;
            O3dNative.o3d_image_array_view(out data, out n, Handle, O3D_IMAGE_DATA);
            GC.KeepAlive(this);
            size = (long)n;
            return data;
        }

        public IntPtr DataMutableView(out long size)
        {
            IntPtr data;
            ulong n;
            O3dNative.o3d_image_array_mutable_view(out data, out n, Handle, O3D_IMAGE_DATA);
            GC.KeepAlive(this);
            size = (long)n;
            return data;
        }

        delegate int UnaryFn(out IntPtr result, IntPtr image);
        Image Unary(UnaryFn fn)
        {
            IntPtr h;
            fn(out h, Handle);
            GC.KeepAlive(this);
            return new Image(h);
        }

        /// <summary>Filtered copy of a 1-channel float32 image (see <see cref="CreateFloatImage"/>).</summary>
        public Image Filter(ImageFilterType filterType)
        {
            IntPtr h;
            O3dNative.o3d_image_filter(out h, Handle, (int)filterType);
            GC.KeepAlive(this);
            return new Image(h);
        }

        /// <summary>Open3D's create_pyramid: level 0 is a copy, each next level the previous one (Gaussian3
        /// filtered when asked) downsampled by 2. 1-channel float32 input.</summary>
        public Image[] CreatePyramid(int numOfLevels, bool withGaussianFilter = true)
        {
            if (numOfLevels < 0) throw new ArgumentOutOfRangeException(nameof(numOfLevels));
            if (NumChannels != 1 || BytesPerChannel != 4)
                throw new InvalidOperationException("CreatePyramid needs a 1-channel float32 image");
            var levels = new Image[numOfLevels];
            for (int i = 0; i < numOfLevels; ++i)
            {
                if (i == 0) { levels[0] = Clone(); continue; }
                if (!withGaussianFilter) { levels[i] = levels[i - 1].Downsample(); continue; }
                using (var smoothed = levels[i - 1].Filter(ImageFilterType.Gaussian3)) levels[i] = smoothed.Downsample();
            }
            return levels;
        }

        /// <summary>Half-size 1-channel float32 image (2x2 block means).</summary>
        public Image Downsample() { return Unary(O3dNative.o3d_image_downsample); }
        public Image FlipVertical() { return Unary(O3dNative.o3d_image_flip_vertical); }
        public Image FlipHorizontal() { return Unary(O3dNative.o3d_image_flip_horizontal); }

        /// <summary>1-channel float32 copy (8-bit values / 255, 16-bit as they are, color averaged).</summary>
        public Image CreateFloatImage(ImageConvertType convertType = ImageConvertType.Weighted)
        {
            IntPtr h;
            O3dNative.o3d_image_create_float_image(out h, Handle, (int)convertType);
            GC.KeepAlive(this);
            return new Image(h);
        }

        /// <summary>Depth in metres: raw / depthScale, with values beyond depthTrunc set to 0 (float32).</summary>
        public Image ConvertDepthToFloat(double depthScale = 1000.0, double depthTrunc = 3.0)
        {
            IntPtr h;
            O3dNative.o3d_image_convert_depth_to_float(out h, Handle, depthScale, depthTrunc);
            GC.KeepAlive(this);
            return new Image(h);
        }
    }
}
