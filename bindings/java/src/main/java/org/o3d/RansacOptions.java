// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * RANSAC options: estimation, ransac_n, RANSACConvergenceCriteria (maxIteration, confidence), the mutual
 * filter of feature matching, seed, threads and progress. Defaults are Open3D's (o3d_ransac_options_init).
 */
public final class RansacOptions {
    /** POINT_TO_POINT (default) or POINT_TO_PLANE. */
    public IcpOptions.Estimation estimation;
    /** Point-to-point: also estimate a scale. */
    public boolean withScaling;
    /** Correspondences drawn per hypothesis, &gt;= 3. */
    public int ransacN;
    /** RANSACConvergenceCriteria.max_iteration (default 100000). */
    public int maxIteration;
    /** RANSACConvergenceCriteria.confidence in [0, 1] (default 0.999). */
    public double confidence;
    /** Feature matching only: keep mutual nearest pairs. */
    public boolean mutualFilter;
    /**
     * Seed of this call (an unsigned 64-bit value); null (default) draws one from the global generator
     * ({@link Utility.Random#seed}). The same seed gives the same result on any thread count.
     */
    public Long seed;
    /** 0 = library default. */
    public int numThreads;
    /**
     * Fraction of maxIteration done (jumps to 1 when confident), on the calling thread; returning false
     * cancels (the call then throws O3dException with CANCELLED). May be null.
     */
    public ProgressCallback progress;

    public RansacOptions() {
        o3d_ransac_options_t o = newNative();
        try {
            estimation = IcpOptions.Estimation.fromCode(o.getEstimation());
            withScaling = o.getWith_scaling() != 0;
            ransacN = o.getRansac_n();
            maxIteration = o.getMax_iteration();
            confidence = o.getConfidence();
            mutualFilter = o.getMutual_filter() != 0;
            seed = o.getUse_seed() != 0 ? o.getSeed() : null;
            numThreads = o.getNum_threads();
        } finally {
            o.delete();
        }
    }

    public RansacOptions estimation(IcpOptions.Estimation v) { estimation = v; return this; }
    public RansacOptions withScaling(boolean v) { withScaling = v; return this; }
    public RansacOptions ransacN(int v) { ransacN = v; return this; }
    public RansacOptions maxIteration(int v) { maxIteration = v; return this; }
    public RansacOptions confidence(double v) { confidence = v; return this; }
    public RansacOptions mutualFilter(boolean v) { mutualFilter = v; return this; }
    public RansacOptions seed(Long v) { seed = v; return this; }
    public RansacOptions numThreads(int v) { numThreads = v; return this; }
    public RansacOptions progress(ProgressCallback v) { progress = v; return this; }

    private static o3d_ransac_options_t newNative() {
        o3d_ransac_options_t o = new o3d_ransac_options_t();
        O3dNative.o3d_ransac_options_init(o, O3dNative.o3dx_sizeof_ransac_options());
        return o;
    }

    /** The native options (the caller deletes them); {@code progress} must stay open during the call. */
    o3d_ransac_options_t toNative(ProgressRef progress) {
        o3d_ransac_options_t o = newNative();
        o.setEstimation(estimation.code);
        o.setWith_scaling(withScaling ? 1 : 0);
        o.setRansac_n(ransacN);
        o.setMax_iteration(maxIteration);
        o.setConfidence(confidence);
        o.setMutual_filter(mutualFilter ? 1 : 0);
        o.setUse_seed(seed != null ? 1 : 0);
        o.setSeed(seed != null ? seed : 0L);
        o.setNum_threads(numThreads);
        o.setProgress(progress.function);
        o.setUser_data(progress.userData);
        return o;
    }
}
