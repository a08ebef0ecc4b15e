// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;

/** o3d.pipelines.registration. */
public final class Registration {
    private Registration() {}

    /** ICP from {@code source} onto {@code target}, starting at {@code init} (null: identity; options null: defaults). */
    public static RegistrationResult registrationIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                     double[] init, IcpOptions options) {
        long[] ref = new long[1];
        long[] r = new long[1];
        o3d_icp_options_t o = (options != null ? options : new IcpOptions()).toNative(ref);
        try {
            O3dNative.o3d_register_icp(r, source.handle(), target.handle(), maxCorrespondenceDistance,
                    NativeResource.fixed(init, 16, "init", true), o);
        } finally {
            o.delete();
            O3dNative.o3dj_delete_global_ref(ref[0]);
        }
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return RegistrationResult.fromNative(r[0]);
    }

    public static RegistrationResult registrationIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance) {
        return registrationIcp(source, target, maxCorrespondenceDistance, null, null);
    }

    /** Fitness, inlier RMSE and correspondences of source moved by transformation (null: identity). */
    public static RegistrationResult evaluateRegistration(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                          double[] transformation) {
        long[] r = new long[1];
        O3dNative.o3d_evaluate_registration(r, source.handle(), target.handle(), maxCorrespondenceDistance,
                NativeResource.fixed(transformation, 16, "transformation", true));
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return RegistrationResult.fromNative(r[0]);
    }

    /** The 6x6 information matrix (row-major, 36 values). */
    public static double[] getInformationMatrixFromPointClouds(PointCloud source, PointCloud target,
                                                               double maxCorrespondenceDistance, double[] transformation) {
        double[] m = new double[36];
        O3dNative.o3d_get_information_matrix_from_point_clouds(source.handle(), target.handle(), maxCorrespondenceDistance,
                NativeResource.fixed(transformation, 16, "transformation", false), m);
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return m;
    }
}
