// SPDX-License-Identifier: MIT
package org.o3d;

/** How color becomes gray in Image.createFloatImage (Open3D's ColorToIntensityConversionType). */
public enum ImageConvertType {
    EQUAL(O3dNativeConstants.O3D_IMAGE_CONVERT_EQUAL),
    WEIGHTED(O3dNativeConstants.O3D_IMAGE_CONVERT_WEIGHTED);

    private final int code;

    ImageConvertType(int code) {
        this.code = code;
    }

    /** The C constant. */
    public int code() {
        return code;
    }
}
