// SPDX-License-Identifier: MIT
package org.o3d;

/** Open3D's PinholeCameraIntrinsicParameters presets. */
public enum PinholeCameraIntrinsicParameters {
    PRIME_SENSE_DEFAULT(O3dNativeConstants.O3D_INTRINSIC_PRIMESENSE_DEFAULT),
    KINECT2_DEPTH_CAMERA_DEFAULT(O3dNativeConstants.O3D_INTRINSIC_KINECT2_DEPTH_DEFAULT),
    KINECT2_COLOR_CAMERA_DEFAULT(O3dNativeConstants.O3D_INTRINSIC_KINECT2_COLOR_DEFAULT);

    private final int code;

    PinholeCameraIntrinsicParameters(int code) {
        this.code = code;
    }

    /** The C constant. */
    public int code() {
        return code;
    }
}
