// SPDX-License-Identifier: MIT
package org.o3d;

/** Image.filter kernels (Open3D's Image.FilterType). */
public enum ImageFilterType {
    GAUSSIAN3(O3dNativeConstants.O3D_IMAGE_FILTER_GAUSSIAN3),
    GAUSSIAN5(O3dNativeConstants.O3D_IMAGE_FILTER_GAUSSIAN5),
    GAUSSIAN7(O3dNativeConstants.O3D_IMAGE_FILTER_GAUSSIAN7),
    SOBEL3_DX(O3dNativeConstants.O3D_IMAGE_FILTER_SOBEL3_DX),
    SOBEL3_DY(O3dNativeConstants.O3D_IMAGE_FILTER_SOBEL3_DY);

    private final int code;

    ImageFilterType(int code) {
        this.code = code;
    }

    /** The C constant. */
    public int code() {
        return code;
    }
}
