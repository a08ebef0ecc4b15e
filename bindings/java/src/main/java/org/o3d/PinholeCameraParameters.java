// SPDX-License-Identifier: MIT
package org.o3d;

import java.util.Objects;

/** o3d.camera.PinholeCameraParameters: an intrinsic and a row-major 4x4 world-to-camera extrinsic (a value). */
public final class PinholeCameraParameters {
    private final PinholeCameraIntrinsic intrinsic;
    private final double[] extrinsic;

    public PinholeCameraParameters(PinholeCameraIntrinsic intrinsic, double[] extrinsic) {
        this.intrinsic = Objects.requireNonNull(intrinsic, "intrinsic");
        this.extrinsic = NativeResource.fixed(extrinsic, 16, "extrinsic", false).clone();
    }

    public PinholeCameraIntrinsic intrinsic() { return intrinsic; }

    /** Row-major 4x4 (a copy). */
    public double[] extrinsic() { return extrinsic.clone(); }
}
