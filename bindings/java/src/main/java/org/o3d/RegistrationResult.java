// SPDX-License-Identifier: MIT
package org.o3d;

/** Result of a registration, copied out of the native o3d_registration_result_t. */
public final class RegistrationResult {
    /** Row-major 4x4 transformation (16 values). */
    public final double[] transformation;
    /** Inlier count / number of source points. */
    public final double fitness;
    /** RMS distance of the inlier pairs. */
    public final double inlierRmse;
    /** (source, target) index pairs, flattened: 2 values per pair. */
    public final int[] correspondenceSet;

    private RegistrationResult(double[] t, double fitness, double rmse, int[] pairs) {
        this.transformation = t;
        this.fitness = fitness;
        this.inlierRmse = rmse;
        this.correspondenceSet = pairs;
    }

    /** Copies everything out of a native result and destroys it. */
    static RegistrationResult fromNative(long r) {
        try {
            double[] t = new double[16];
            O3dNative.o3d_registration_result_get_transformation(t, r);
            double[] f = new double[1];
            double[] rmse = new double[1];
            O3dNative.o3d_registration_result_get_fitness(f, r);
            O3dNative.o3d_registration_result_get_inlier_rmse(rmse, r);
            long[] n = new long[1];
            O3dNative.o3d_registration_result_get_correspondence_set(null, 0, n, r);
            int[] pairs = new int[(int) (n[0] * 2)];
            O3dNative.o3d_registration_result_get_correspondence_set(pairs, n[0], n, r);
            return new RegistrationResult(t, f[0], rmse[0], pairs);
        } finally {
            O3dNative.o3d_registration_result_destroy(r);
        }
    }
}
