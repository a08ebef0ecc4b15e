// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Objects;

/**
 * Per-point descriptors (o3d.pipelines.registration.Feature): a {@link #dimension()} x {@link #num()}
 * matrix of doubles stored descriptor by descriptor (descriptor i is data[i * dimension .. (i + 1) *
 * dimension - 1]). Close it (try-with-resources); a Cleaner destroys forgotten features. FPFH, matching
 * and files: {@link Registration#computeFpfhFeature}, {@link Registration#correspondencesFromFeatures},
 * {@link IO#readFeature}.
 */
public final class Feature extends NativeResource {
    Feature(long handle) {
        super(handle, O3dNative::o3d_feature_destroy);
    }

    static long count(long value, String name) {
        if (value < 0) throw new IllegalArgumentException(name + " must be >= 0, got " + value);
        return value;
    }

    private static long create(long dimension, long num) {
        long[] h = new long[1];
        O3dNative.o3d_feature_create(h, count(dimension, "dimension"), count(num, "num"));
        return h[0];
    }

    private static long createFromData(double[] data, long dimension, long num) {
        Objects.requireNonNull(data, "data");
        if (data.length != count(dimension, "dimension") * count(num, "num"))
            throw new IllegalArgumentException("data: expected " + dimension * num + " values (dimension x num), got " + data.length);
        long[] h = new long[1];
        O3dNative.o3d_feature_create_from_data(h, data, dimension, num);
        return h[0];
    }

    /** An empty (0 x 0) feature. */
    public Feature() {
        this(create(0, 0));
    }

    /** A {@code dimension} x {@code num} feature of zeros. */
    public Feature(long dimension, long num) {
        this(create(dimension, num));
    }

    /** A feature holding a copy of {@code data} (dimension * num values; non-finite values throw). */
    public Feature(double[] data, long dimension, long num) {
        this(createFromData(data, dimension, num));
    }

    /** Deep copy. */
    public Feature copy() {
        long[] h = new long[1];
        O3dNative.o3d_feature_clone(h, handle());
        Reference.reachabilityFence(this);
        return new Feature(h[0]);
    }

    /** Descriptor length (33 for FPFH). */
    public long dimension() {
        long[] v = new long[1];
        O3dNative.o3d_feature_dimension(v, handle());
        Reference.reachabilityFence(this);
        return v[0];
    }

    /** Number of descriptors (points). */
    public long num() {
        long[] v = new long[1];
        O3dNative.o3d_feature_num(v, handle());
        Reference.reachabilityFence(this);
        return v[0];
    }

    private int size() {
        return Math.toIntExact(Math.multiplyExact(dimension(), num()));
    }

    /** All dimension * num values, descriptor by descriptor (a copy). */
    public double[] data() {
        double[] values = new double[size()];
        O3dNative.o3d_feature_get_data(values, values.length, handle());
        Reference.reachabilityFence(this);
        return values;
    }

    /** Copy {@code values} in; the length must be dimension * num ({@link #resize} first to change the shape). */
    public void setData(double[] values) {
        Objects.requireNonNull(values, "values");
        int size = size();
        if (values.length != size)
            throw new IllegalArgumentException("values: expected " + size + " values (dimension x num), got " + values.length);
        dataView().asDoubleBuffer().put(values);
        Reference.reachabilityFence(this);
    }

    /**
     * Borrowed, writable direct ByteBuffer (native order) over the dimension * num doubles; use
     * asDoubleBuffer(). Valid ONLY until the feature is resized or closed.
     */
    public ByteBuffer dataView() {
        long[] data = new long[1];
        O3dNative.o3d_feature_data(data, handle());
        long bytes = (long) size() * Double.BYTES;
        Reference.reachabilityFence(this);
        ByteBuffer b = O3dNative.o3dj_direct_buffer(data[0], bytes);
        if (b == null) b = ByteBuffer.allocateDirect(0);
        return b.order(ByteOrder.nativeOrder());
    }

    /** Resize to dimension x num (Feature.resize): kept values stay when the dimension is unchanged, new ones are zero. */
    public void resize(long dimension, long num) {
        O3dNative.o3d_feature_resize(handle(), count(dimension, "dimension"), count(num, "num"));
        Reference.reachabilityFence(this);
    }

    /** The descriptors of {@code indices} in that order, or of every other point (ascending) when {@code invert}. */
    public Feature selectByIndex(long[] indices, boolean invert) {
        Objects.requireNonNull(indices, "indices");
        long[] h = new long[1];
        O3dNative.o3d_feature_select_by_index(h, handle(), indices, indices.length, invert ? 1 : 0);
        Reference.reachabilityFence(this);
        return new Feature(h[0]);
    }

    public Feature selectByIndex(long[] indices) { return selectByIndex(indices, false); }
}
