// SPDX-License-Identifier: MIT
package org.o3d;

/** Result of {@link PointCloud#computeMeanAndCovariance()}. */
public final class MeanAndCovariance {
    /** Mean point (3 values). */
    public final double[] mean;
    /** Covariance, row-major 3x3 (9 values), divided by N. */
    public final double[] covariance;

    MeanAndCovariance(double[] mean, double[] covariance) {
        this.mean = mean;
        this.covariance = covariance;
    }
}
