// SPDX-License-Identifier: MIT
package org.o3d;

/** FastGlobalRegistrationOption plus seed, threads and progress; defaults are Open3D's (o3d_fgr_options_init). */
public final class FgrOptions {
    /** &gt; 1: mu is divided by it each annealing step (default 1.4). */
    public double divisionFactor;
    /** Distances in the clouds' units instead of the normalised scale. */
    public boolean useAbsoluteScale;
    /** Anneal mu (graduated non-convexity); default true. */
    public boolean decreaseMu;
    /** &gt; 0 (default 0.025). */
    public double maximumCorrespondenceDistance;
    public int iterationNumber;
    /** Edge-length similarity of the tuple test, in (0, 1] (default 0.95). */
    public double tupleScale;
    public int maximumTupleCount;
    public boolean tupleTest;
    /** Seed of the tuple draws (unsigned 64-bit); null (default): from the global generator. */
    public Long seed;
    public int numThreads;
    /** Fraction of iterationNumber done; returning false cancels. May be null. */
    public ProgressCallback progress;

    public FgrOptions() {
        o3d_fgr_options_t o = newNative();
        try {
            divisionFactor = o.getDivision_factor();
            useAbsoluteScale = o.getUse_absolute_scale() != 0;
            decreaseMu = o.getDecrease_mu() != 0;
            maximumCorrespondenceDistance = o.getMaximum_correspondence_distance();
            iterationNumber = o.getIteration_number();
            tupleScale = o.getTuple_scale();
            maximumTupleCount = o.getMaximum_tuple_count();
            tupleTest = o.getTuple_test() != 0;
            seed = o.getUse_seed() != 0 ? o.getSeed() : null;
            numThreads = o.getNum_threads();
        } finally {
            o.delete();
        }
    }

    public FgrOptions divisionFactor(double v) { divisionFactor = v; return this; }
    public FgrOptions useAbsoluteScale(boolean v) { useAbsoluteScale = v; return this; }
    public FgrOptions decreaseMu(boolean v) { decreaseMu = v; return this; }
    public FgrOptions maximumCorrespondenceDistance(double v) { maximumCorrespondenceDistance = v; return this; }
    public FgrOptions iterationNumber(int v) { iterationNumber = v; return this; }
    public FgrOptions tupleScale(double v) { tupleScale = v; return this; }
    public FgrOptions maximumTupleCount(int v) { maximumTupleCount = v; return this; }
    public FgrOptions tupleTest(boolean v) { tupleTest = v; return this; }
    public FgrOptions seed(Long v) { seed = v; return this; }
    public FgrOptions numThreads(int v) { numThreads = v; return this; }
    public FgrOptions progress(ProgressCallback v) { progress = v; return this; }

    private static o3d_fgr_options_t newNative() {
        o3d_fgr_options_t o = new o3d_fgr_options_t();
        O3dNative.o3d_fgr_options_init(o, O3dNative.o3dx_sizeof_fgr_options());
        return o;
    }

    /** The native options (the caller deletes them); {@code progress} must stay open during the call. */
    o3d_fgr_options_t toNative(ProgressRef progress) {
        o3d_fgr_options_t o = newNative();
        o.setDivision_factor(divisionFactor);
        o.setUse_absolute_scale(useAbsoluteScale ? 1 : 0);
        o.setDecrease_mu(decreaseMu ? 1 : 0);
        o.setMaximum_correspondence_distance(maximumCorrespondenceDistance);
        o.setIteration_number(iterationNumber);
        o.setTuple_scale(tupleScale);
        o.setMaximum_tuple_count(maximumTupleCount);
        o.setTuple_test(tupleTest ? 1 : 0);
        o.setUse_seed(seed != null ? 1 : 0);
        o.setSeed(seed != null ? seed : 0L);
        o.setNum_threads(numThreads);
        o.setProgress(progress.function);
        o.setUser_data(progress.userData);
        return o;
    }
}
