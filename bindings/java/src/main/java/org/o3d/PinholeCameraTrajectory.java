// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

/** o3d.camera.PinholeCameraTrajectory: a list of camera poses. Close it. */
public final class PinholeCameraTrajectory extends NativeResource {
    PinholeCameraTrajectory(long handle) {
        super(handle, O3dNative::o3d_camera_trajectory_destroy);
    }

    private static long create() {
        long[] h = new long[1];
        O3dNative.o3d_camera_trajectory_create(h);
        return h[0];
    }

    /** An empty trajectory. */
    public PinholeCameraTrajectory() {
        this(create());
    }

    /** Number of poses. */
    public long size() {
        long[] n = new long[1];
        O3dNative.o3d_camera_trajectory_size(n, handle());
        Reference.reachabilityFence(this);
        return n[0];
    }

    /** Pose {@code index} (out of range: O3dException INVALID_ARGUMENT). */
    public PinholeCameraParameters get(long index) {
        if (index < 0) throw new IndexOutOfBoundsException("index " + index);
        double[] extrinsic = new double[16];
        o3d_pinhole_intrinsic_t n = new o3d_pinhole_intrinsic_t();
        try {
            O3dNative.o3d_camera_trajectory_get(n, extrinsic, handle(), index);
            Reference.reachabilityFence(this);
            return new PinholeCameraParameters(PinholeCameraIntrinsic.fromNative(n), extrinsic);
        } finally {
            n.delete();
        }
    }

    /** All poses (Open3D's {@code parameters}), copied. */
    public List<PinholeCameraParameters> parameters() {
        long count = size();
        List<PinholeCameraParameters> list = new ArrayList<>();
        for (long i = 0; i < count; i++) list.add(get(i));
        return list;
    }

    /** Append a pose; the extrinsic's last row must be (0, 0, 0, 1). */
    public void append(PinholeCameraIntrinsic intrinsic, double[] extrinsic) {
        Objects.requireNonNull(intrinsic, "intrinsic");
        o3d_pinhole_intrinsic_t n = intrinsic.toNative();
        try {
            O3dNative.o3d_camera_trajectory_append(handle(), n, fixed(extrinsic, 16, "extrinsic", false));
        } finally {
            n.delete();
        }
        Reference.reachabilityFence(this);
    }

    public void append(PinholeCameraParameters parameters) {
        append(parameters.intrinsic(), parameters.extrinsic());
    }

    public void clear() {
        O3dNative.o3d_camera_trajectory_clear(handle());
        Reference.reachabilityFence(this);
    }
}
