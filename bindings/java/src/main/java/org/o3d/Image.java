// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Objects;

/**
 * A 2D image (o3d.geometry.Image): 1, 3 or 4 interleaved channels of uint8 (1 byte), uint16 (2) or
 * float32 (4), rows top to bottom. Pixels cross the boundary in one bulk copy (byte[] in native byte
 * order, or short[] / float[] for the typed helpers). Close it; a Cleaner destroys forgotten images.
 */
public final class Image extends NativeResource {
    Image(long handle) {
        super(handle, O3dNative::o3d_image_destroy);
    }

    private static long create(int width, int height, int numChannels, int bytesPerChannel) {
        long[] h = new long[1];
        O3dNative.o3d_image_create(h, width, height, numChannels, bytesPerChannel);
        return h[0];
    }

    /** A zero-filled image (width, height &gt;= 1; 1, 3 or 4 channels; 1, 2 or 4 bytes per channel). */
    public Image(int width, int height, int numChannels, int bytesPerChannel) {
        this(create(width, height, numChannels, bytesPerChannel));
    }

    /** A zero-filled 8-bit gray image. */
    public Image(int width, int height) {
        this(width, height, 1, 1);
    }

    /** An image holding a copy of {@code data} (exactly width*height*channels*bytesPerChannel bytes). */
    public static Image fromBytes(int width, int height, int numChannels, int bytesPerChannel, byte[] data) {
        Objects.requireNonNull(data, "data");
        long[] h = new long[1];
        O3dNative.o3d_image_create_from_data(h, width, height, numChannels, bytesPerChannel, data, data.length);
        return new Image(h[0]);
    }

    /** A uint16 image (e.g. raw depth in millimetres; values read as unsigned) from width*height*channels values. */
    public static Image fromUInt16(int width, int height, int numChannels, short[] values) {
        Objects.requireNonNull(values, "values");
        ByteBuffer b = ByteBuffer.allocate(values.length * 2).order(ByteOrder.nativeOrder());
        b.asShortBuffer().put(values);
        return fromBytes(width, height, numChannels, 2, b.array());
    }

    /** A float32 image (e.g. depth in metres) from width*height*channels values. */
    public static Image fromFloat(int width, int height, int numChannels, float[] values) {
        Objects.requireNonNull(values, "values");
        ByteBuffer b = ByteBuffer.allocate(values.length * 4).order(ByteOrder.nativeOrder());
        b.asFloatBuffer().put(values);
        return fromBytes(width, height, numChannels, 4, b.array());
    }

    /** Deep copy. */
    public Image copy() {
        long[] h = new long[1];
        O3dNative.o3d_image_clone(h, handle());
        Reference.reachabilityFence(this);
        return new Image(h[0]);
    }

    private interface IntGetter {
        int get(long image, int[] out);
    }

    private int getInt(IntGetter fn) {
        int[] v = new int[1];
        fn.get(handle(), v);
        Reference.reachabilityFence(this);
        return v[0];
    }

    public int width() { return getInt(O3dNative::o3d_image_width); }
    public int height() { return getInt(O3dNative::o3d_image_height); }
    public int numChannels() { return getInt(O3dNative::o3d_image_num_channels); }
    public int bytesPerChannel() { return getInt(O3dNative::o3d_image_bytes_per_channel); }

    /** The pixel bytes (a copy). */
    public byte[] getData() {
        long h = handle();
        long[] n = new long[1];
        O3dNative.o3d_image_get_array(null, 0, n, h, O3D_IMAGE_DATA);
        if (n[0] > Integer.MAX_VALUE - 8) throw new IllegalStateException("image too large for a Java array");
        byte[] out = new byte[(int) n[0]];
        O3dNative.o3d_image_get_array(out, out.length, n, h, O3D_IMAGE_DATA);
        Reference.reachabilityFence(this);
        return out;
    }

    /** The pixels of a uint16 image (a copy; read them with Short.toUnsignedInt). */
    public short[] toUInt16Array() {
        if (bytesPerChannel() != 2) throw new IllegalStateException("not a uint16 image");
        byte[] bytes = getData();
        short[] out = new short[bytes.length / 2];
        ByteBuffer.wrap(bytes).order(ByteOrder.nativeOrder()).asShortBuffer().get(out);
        return out;
    }

    /** The pixels of a float32 image (a copy). */
    public float[] toFloatArray() {
        if (bytesPerChannel() != 4) throw new IllegalStateException("not a float32 image");
        byte[] bytes = getData();
        float[] out = new float[bytes.length / 4];
        ByteBuffer.wrap(bytes).order(ByteOrder.nativeOrder()).asFloatBuffer().get(out);
        return out;
    }

    // Borrowed views: direct ByteBuffers (native order) over the image's own bytes, valid ONLY until
    // the next mutating call on this image or close().

    private interface ViewFn {
        int view(long image, long[] data, long[] size);
    }

    private ByteBuffer view(ViewFn fn, boolean writable) {
        long[] data = new long[1];
        long[] n = new long[1];
        fn.view(handle(), data, n);
        Reference.reachabilityFence(this);
        ByteBuffer b = O3dNative.o3dj_direct_buffer(data[0], n[0]);
        if (b == null) b = ByteBuffer.allocateDirect(0);
        b.order(ByteOrder.nativeOrder());
        return writable ? b : b.asReadOnlyBuffer().order(ByteOrder.nativeOrder());
    }

    public ByteBuffer dataView() { return view(O3dNative::o3d_image_data_view, false); }
    public ByteBuffer dataMutableView() { return view(O3dNative::o3d_image_data_mutable_view, true); }

    private interface UnaryFn {
        int apply(long[] out, long image);
    }

    private Image unary(UnaryFn fn) {
        long[] h = new long[1];
        fn.apply(h, handle());
        Reference.reachabilityFence(this);
        return new Image(h[0]);
    }

    /** Filtered copy of a 1-channel float32 image (see {@link #createFloatImage}). */
    public Image filter(ImageFilterType filterType) {
        return unary((out, img) -> O3dNative.o3d_image_filter(out, img, filterType.code()));
    }

    /**
     * Open3D's create_pyramid: level 0 is a copy, each next level the previous one (Gaussian3 filtered when
     * asked) downsampled by 2. 1-channel float32 input.
     */
    public Image[] createPyramid(int numOfLevels, boolean withGaussianFilter) {
        if (numOfLevels < 0) throw new IllegalArgumentException("numOfLevels must be >= 0");
        if (numChannels() != 1 || bytesPerChannel() != 4)
            throw new IllegalStateException("createPyramid needs a 1-channel float32 image");
        Image[] levels = new Image[numOfLevels];
        for (int i = 0; i < numOfLevels; ++i) {
            if (i == 0) {
                levels[0] = copy();
            } else if (withGaussianFilter) {
                try (Image smoothed = levels[i - 1].filter(ImageFilterType.GAUSSIAN3)) {
                    levels[i] = smoothed.downsample();
                }
            } else {
                levels[i] = levels[i - 1].downsample();
            }
        }
        return levels;
    }

    /** Half-size 1-channel float32 image (2x2 block means). */
    public Image downsample() { return unary(O3dNative::o3d_image_downsample); }
    public Image flipVertical() { return unary(O3dNative::o3d_image_flip_vertical); }
    public Image flipHorizontal() { return unary(O3dNative::o3d_image_flip_horizontal); }

    /** 1-channel float32 copy (8-bit values / 255, 16-bit as they are, color averaged). */
    public Image createFloatImage(ImageConvertType convertType) {
        return unary((out, img) -> O3dNative.o3d_image_create_float_image(out, img, convertType.code()));
    }

    /** {@link #createFloatImage(ImageConvertType)} with Open3D's default, WEIGHTED. */
    public Image createFloatImage() { return createFloatImage(ImageConvertType.WEIGHTED); }

    /** Depth in metres: raw / depthScale, values beyond depthTrunc set to 0 (float32). */
    public Image convertDepthToFloat(double depthScale, double depthTrunc) {
        return unary((out, img) -> O3dNative.o3d_image_convert_depth_to_float(out, img, depthScale, depthTrunc));
    }

    /** {@link #convertDepthToFloat(double, double)} with 1000 and 3.0. */
    public Image convertDepthToFloat() { return convertDepthToFloat(1000.0, 3.0); }
}
