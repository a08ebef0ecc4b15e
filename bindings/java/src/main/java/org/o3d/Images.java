// SPDX-License-Identifier: MIT
package org.o3d;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/** Typed pixels and pyramids over {@link Image} (Image's bytes are native-order samples, row-major). */
public final class Images {
    private Images() {}

    /** A 4-byte float image from {@code width * height * channels} samples. */
    public static Image fromFloat(int width, int height, int channels, float[] samples) {
        ByteBuffer b = ByteBuffer.allocate(4 * samples.length).order(ByteOrder.nativeOrder());
        b.asFloatBuffer().put(samples);
        return Image.createFromData(width, height, channels, 4, b.array());
    }

    /** A 2-byte unsigned image (e.g. depth in millimetres) from {@code width * height * channels} samples. */
    public static Image fromUInt16(int width, int height, int channels, short[] samples) {
        ByteBuffer b = ByteBuffer.allocate(2 * samples.length).order(ByteOrder.nativeOrder());
        b.asShortBuffer().put(samples);
        return Image.createFromData(width, height, channels, 2, b.array());
    }

    /** The samples of a 4-byte (float) image. */
    public static float[] toFloatArray(Image image) {
        if (image.bytesPerChannel() != 4) throw new IllegalArgumentException("not a float image");
        java.nio.FloatBuffer f = ByteBuffer.wrap(image.getArray(Library.IMAGE_DATA)).order(ByteOrder.nativeOrder()).asFloatBuffer();
        float[] out = new float[f.remaining()];
        f.get(out);
        return out;
    }

    /** The samples of a 2-byte image (read with Short.toUnsignedInt). */
    public static short[] toUInt16Array(Image image) {
        if (image.bytesPerChannel() != 2) throw new IllegalArgumentException("not a 16-bit image");
        java.nio.ShortBuffer s = ByteBuffer.wrap(image.getArray(Library.IMAGE_DATA)).order(ByteOrder.nativeOrder()).asShortBuffer();
        short[] out = new short[s.remaining()];
        s.get(out);
        return out;
    }

    /**
     * Open3D's Image.create_pyramid: level 0 is a copy, each further level is the previous one
     * (Gaussian3-filtered first when {@code withGaussianFilter}) downsampled by 2. The caller closes the levels.
     */
    public static Image[] createPyramid(Image image, int numLevels, boolean withGaussianFilter) {
        if (numLevels < 1) throw new IllegalArgumentException("numLevels must be >= 1");
        Image[] levels = new Image[numLevels];
        levels[0] = image.clone();
        try {
            for (int i = 1; i < numLevels; i++) {
                if (withGaussianFilter) {
                    try (Image blurred = levels[i - 1].filter(Library.IMAGE_FILTER_GAUSSIAN3)) {
                        levels[i] = blurred.downsample();
                    }
                } else {
                    levels[i] = levels[i - 1].downsample();
                }
            }
        } catch (RuntimeException e) {
            for (Image level : levels) if (level != null) level.close();
            throw e;
        }
        return levels;
    }
}
