// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * The method, GlobalOptimizationConvergenceCriteria and GlobalOptimizationOption of
 * {@link Registration#globalOptimization}, plus threads and progress. Defaults are Open3D's (from
 * o3d_global_optimization_options_init).
 */
public final class GlobalOptimizationOptions {
    public enum Method {
        /** GlobalOptimizationGaussNewton */
        GAUSS_NEWTON(O3dNativeConstants.O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON),
        /** GlobalOptimizationLevenbergMarquardt (default) */
        LEVENBERG_MARQUARDT(O3dNativeConstants.O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT);

        final int code;

        Method(int code) {
            this.code = code;
        }

        static Method fromCode(int code) {
            for (Method m : values()) {
                if (m.code == code) return m;
            }
            throw new IllegalArgumentException("unknown global optimization method " + code);
        }
    }

    public Method method;
    public int maxIteration;
    public double minRelativeIncrement;
    public double minRelativeResidualIncrement;
    public double minRightTerm;
    public double minResidual;
    /** Levenberg-Marquardt damping retries per iteration. */
    public int maxIterationLm;
    public double upperScaleFactor;
    public double lowerScaleFactor;
    /** Sets the line-process scale mu (default 0.075). */
    public double maxCorrespondenceDistance;
    /** Uncertain edges whose confidence ends below it are removed (default 0.25). */
    public double edgePruneThreshold;
    /** Weight of loop closures against odometry (default 1). */
    public double preferenceLoopClosure;
    /** The node kept fixed; -1 (default): the first node. */
    public int referenceNode;
    public int numThreads;
    /** Fraction of maxIteration done over both passes; returning false cancels (graph unchanged). May be null. */
    public ProgressCallback progress;

    public GlobalOptimizationOptions() {
        o3d_global_optimization_options_t o = newNative();
        try {
            method = Method.fromCode(o.getMethod());
            maxIteration = o.getMax_iteration();
            minRelativeIncrement = o.getMin_relative_increment();
            minRelativeResidualIncrement = o.getMin_relative_residual_increment();
            minRightTerm = o.getMin_right_term();
            minResidual = o.getMin_residual();
            maxIterationLm = o.getMax_iteration_lm();
            upperScaleFactor = o.getUpper_scale_factor();
            lowerScaleFactor = o.getLower_scale_factor();
            maxCorrespondenceDistance = o.getMax_correspondence_distance();
            edgePruneThreshold = o.getEdge_prune_threshold();
            preferenceLoopClosure = o.getPreference_loop_closure();
            referenceNode = o.getReference_node();
            numThreads = o.getNum_threads();
        } finally {
            o.delete();
        }
    }

    public GlobalOptimizationOptions method(Method v) { method = v; return this; }
    public GlobalOptimizationOptions maxIteration(int v) { maxIteration = v; return this; }
    public GlobalOptimizationOptions maxCorrespondenceDistance(double v) { maxCorrespondenceDistance = v; return this; }
    public GlobalOptimizationOptions edgePruneThreshold(double v) { edgePruneThreshold = v; return this; }
    public GlobalOptimizationOptions preferenceLoopClosure(double v) { preferenceLoopClosure = v; return this; }
    public GlobalOptimizationOptions referenceNode(int v) { referenceNode = v; return this; }
    public GlobalOptimizationOptions numThreads(int v) { numThreads = v; return this; }
    public GlobalOptimizationOptions progress(ProgressCallback v) { progress = v; return this; }

    private static o3d_global_optimization_options_t newNative() {
        o3d_global_optimization_options_t o = new o3d_global_optimization_options_t();
        O3dNative.o3d_global_optimization_options_init(o, O3dNative.o3dx_sizeof_global_optimization_options());
        return o;
    }

    /** The native options (the caller deletes them); {@code progress} must stay open during the call. */
    o3d_global_optimization_options_t toNative(ProgressRef progress) {
        o3d_global_optimization_options_t o = newNative();
        o.setMethod(method.code);
        o.setMax_iteration(maxIteration);
        o.setMin_relative_increment(minRelativeIncrement);
        o.setMin_relative_residual_increment(minRelativeResidualIncrement);
        o.setMin_right_term(minRightTerm);
        o.setMin_residual(minResidual);
        o.setMax_iteration_lm(maxIterationLm);
        o.setUpper_scale_factor(upperScaleFactor);
        o.setLower_scale_factor(lowerScaleFactor);
        o.setMax_correspondence_distance(maxCorrespondenceDistance);
        o.setEdge_prune_threshold(edgePruneThreshold);
        o.setPreference_loop_closure(preferenceLoopClosure);
        o.setReference_node(referenceNode);
        o.setNum_threads(numThreads);
        o.setProgress(progress.function);
        o.setUser_data(progress.userData);
        return o;
    }
}
