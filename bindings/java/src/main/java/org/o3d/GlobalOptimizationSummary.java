// SPDX-License-Identifier: MIT
package org.o3d;

/** What a global optimization did. */
public final class GlobalOptimizationSummary {
    /** Iterations of both passes. */
    public final int iterations;
    /** The robust objective before the first pass. */
    public final double initialResidual;
    /** The robust objective after the last pass. */
    public final double finalResidual;
    /** Edges removed for a confidence below edgePruneThreshold. */
    public final int prunedEdges;

    GlobalOptimizationSummary(o3d_global_optimization_summary_t s) {
        iterations = s.getIterations();
        initialResidual = s.getInitial_residual();
        finalResidual = s.getFinal_residual();
        prunedEdges = s.getPruned_edges();
    }

    @Override
    public String toString() {
        return "GlobalOptimizationSummary(iterations " + iterations + ", residual " + initialResidual + " -> " + finalResidual
                + ", pruned " + prunedEdges + ")";
    }
}
