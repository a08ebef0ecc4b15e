// SPDX-License-Identifier: MIT
package org.o3d;

/** ICP options: estimation method plus ICPConvergenceCriteria; defaults are Open3D's (from o3d_icp_options_init). */
public final class IcpOptions {
    public enum Estimation {
        POINT_TO_POINT(O3dNativeConstants.O3D_ESTIMATION_POINT_TO_POINT),
        /** The target needs normals. */
        POINT_TO_PLANE(O3dNativeConstants.O3D_ESTIMATION_POINT_TO_PLANE);

        final int code;

        Estimation(int code) {
            this.code = code;
        }
    }

    public Estimation estimation;
    /** Point-to-point only: also estimate a scale. */
    public boolean withScaling;
    public double relativeFitness;
    public double relativeRmse;
    public int maxIteration;
    /** 0 = library default. */
    public int numThreads;
    /** Called after each iteration with iteration/max_iteration; may be null. */
    public ProgressCallback progress;

    public IcpOptions() {
        o3d_icp_options_t o = newNative();
        try {
            estimation = o.getEstimation() == Estimation.POINT_TO_PLANE.code ? Estimation.POINT_TO_PLANE : Estimation.POINT_TO_POINT;
            withScaling = o.getWith_scaling() != 0;
            relativeFitness = o.getRelative_fitness();
            relativeRmse = o.getRelative_rmse();
            maxIteration = o.getMax_iteration();
            numThreads = o.getNum_threads();
        } finally {
            o.delete();
        }
    }

    public IcpOptions maxIteration(int v) { maxIteration = v; return this; }
    public IcpOptions relativeFitness(double v) { relativeFitness = v; return this; }
    public IcpOptions relativeRmse(double v) { relativeRmse = v; return this; }
    public IcpOptions estimation(Estimation v) { estimation = v; return this; }
    public IcpOptions withScaling(boolean v) { withScaling = v; return this; }
    public IcpOptions numThreads(int v) { numThreads = v; return this; }
    public IcpOptions progress(ProgressCallback v) { progress = v; return this; }

    private static o3d_icp_options_t newNative() {
        o3d_icp_options_t o = new o3d_icp_options_t();
        O3dNative.o3d_icp_options_init(o, O3dNative.o3dx_sizeof_icp_options());
        return o;
    }

    /**
     * The native options. When a progress callback is set, {@code globalRef[0]} receives a JNI global
     * reference (the callback's user_data) that the caller must release with o3dj_delete_global_ref.
     */
    o3d_icp_options_t toNative(long[] globalRef) {
        o3d_icp_options_t o = newNative();
        o.setEstimation(estimation.code);
        o.setWith_scaling(withScaling ? 1 : 0);
        o.setRelative_fitness(relativeFitness);
        o.setRelative_rmse(relativeRmse);
        o.setMax_iteration(maxIteration);
        o.setNum_threads(numThreads);
        if (progress != null) {
            globalRef[0] = O3dNative.o3dj_new_global_ref(progress);
            o.setProgress(O3dNative.o3dj_progress_trampoline_address());
            o.setUser_data(globalRef[0]);
        }
        return o;
    }
}
