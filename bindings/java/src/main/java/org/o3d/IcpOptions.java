// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * ICP options: estimation method, its parameters and ICPConvergenceCriteria; defaults are Open3D's (from
 * o3d_icp_options_init).
 */
public final class IcpOptions {
    public enum Estimation {
        POINT_TO_POINT(O3dNativeConstants.O3D_ESTIMATION_POINT_TO_POINT),
        /** The target needs normals. */
        POINT_TO_PLANE(O3dNativeConstants.O3D_ESTIMATION_POINT_TO_PLANE),
        /** TransformationEstimationForColoredICP: both clouds need colors, the target normals. */
        COLORED(O3dNativeConstants.O3D_ESTIMATION_COLORED),
        /** TransformationEstimationForGeneralizedICP (covariances from the clouds, their normals, or estimated). */
        GENERALIZED(O3dNativeConstants.O3D_ESTIMATION_GENERALIZED),
        /** TransformationEstimationSymmetric: both clouds need normals. */
        SYMMETRIC(O3dNativeConstants.O3D_ESTIMATION_SYMMETRIC);

        final int code;

        Estimation(int code) {
            this.code = code;
        }

        static Estimation fromCode(int code) {
            for (Estimation e : values()) {
                if (e.code == code) return e;
            }
            throw new IllegalArgumentException("unknown estimation " + code);
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
    /** Robust kernel of point-to-plane, colored, generalized and symmetric ICP (default L2Loss; null = L2). */
    public RobustKernel kernel;
    /** Colored ICP: weight of the geometric term, in [0, 1] (default 0.968). */
    public double lambdaGeometric;
    /** Generalized ICP: covariance regularisation, &gt; 0 (default 1e-3). */
    public double epsilon;
    /** Called after each iteration with iteration/max_iteration; may be null. */
    public ProgressCallback progress;

    public IcpOptions() {
        o3d_icp_options_t o = newNative();
        try {
            estimation = Estimation.fromCode(o.getEstimation());
            withScaling = o.getWith_scaling() != 0;
            relativeFitness = o.getRelative_fitness();
            relativeRmse = o.getRelative_rmse();
            maxIteration = o.getMax_iteration();
            numThreads = o.getNum_threads();
            kernel = new RobustKernel(RobustKernel.Kind.fromCode(o.getKernel()), o.getKernel_k());
            lambdaGeometric = o.getLambda_geometric();
            epsilon = o.getEpsilon();
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
    public IcpOptions kernel(RobustKernel v) { kernel = v; return this; }
    public IcpOptions lambdaGeometric(double v) { lambdaGeometric = v; return this; }
    public IcpOptions epsilon(double v) { epsilon = v; return this; }
    public IcpOptions progress(ProgressCallback v) { progress = v; return this; }

    private static o3d_icp_options_t newNative() {
        o3d_icp_options_t o = new o3d_icp_options_t();
        O3dNative.o3d_icp_options_init(o, O3dNative.o3dx_sizeof_icp_options());
        return o;
    }

    /** The native options (the caller deletes them); {@code progress} must stay open during the call. */
    o3d_icp_options_t toNative(ProgressRef progress) {
        o3d_icp_options_t o = newNative();
        o.setEstimation(estimation.code);
        o.setWith_scaling(withScaling ? 1 : 0);
        o.setRelative_fitness(relativeFitness);
        o.setRelative_rmse(relativeRmse);
        o.setMax_iteration(maxIteration);
        o.setNum_threads(numThreads);
        RobustKernel k = kernel != null ? kernel : RobustKernel.l2Loss();
        o.setKernel(k.kind().code);
        o.setKernel_k(k.k());
        o.setLambda_geometric(lambdaGeometric);
        o.setEpsilon(epsilon);
        o.setProgress(progress.function);
        o.setUser_data(progress.userData);
        return o;
    }
}
