// SPDX-License-Identifier: MIT
package org.o3d;

import java.lang.ref.Reference;
import java.util.List;
import java.util.Objects;

/**
 * o3d.pipelines.registration: local refinement (ICP with every estimation), features and their matching,
 * global registration (RANSAC with correspondence checkers, FGR) and pose-graph optimization. Long calls
 * report progress through a {@link ProgressCallback} in their options; returning false cancels them
 * (O3dException with CANCELLED).
 */
public final class Registration {
    private Registration() {}

    // ---- local refinement ------------------------------------------------------------------------

    /**
     * ICP from {@code source} onto {@code target}, starting at {@code init} (null: identity; options null:
     * defaults), with any estimation ({@link IcpOptions#estimation}).
     */
    public static RegistrationResult registrationIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                     double[] init, IcpOptions options) {
        return icp(source, target, maxCorrespondenceDistance, init, options, null);
    }

    public static RegistrationResult registrationIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance) {
        return registrationIcp(source, target, maxCorrespondenceDistance, null, null);
    }

    /** Colored ICP (Park et al. 2017): registrationIcp with COLORED, whatever options.estimation says. */
    public static RegistrationResult registrationColoredIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                            double[] init, IcpOptions options) {
        return icp(source, target, maxCorrespondenceDistance, init, options, IcpOptions.Estimation.COLORED);
    }

    /** Generalized ICP (Segal et al. 2009): registrationIcp with GENERALIZED. */
    public static RegistrationResult registrationGeneralizedIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                                double[] init, IcpOptions options) {
        return icp(source, target, maxCorrespondenceDistance, init, options, IcpOptions.Estimation.GENERALIZED);
    }

    /** Symmetric point-to-plane ICP (Rusinkiewicz 2019): registrationIcp with SYMMETRIC. */
    public static RegistrationResult registrationSymmetricIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                              double[] init, IcpOptions options) {
        return icp(source, target, maxCorrespondenceDistance, init, options, IcpOptions.Estimation.SYMMETRIC);
    }

    private static RegistrationResult icp(PointCloud source, PointCloud target, double maxCorrespondenceDistance, double[] init,
                                          IcpOptions options, IcpOptions.Estimation estimation) {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(target, "target");
        IcpOptions opts = options != null ? options : new IcpOptions();
        long[] r = new long[1];
        try (ProgressRef progress = new ProgressRef(opts.progress)) {
            o3d_icp_options_t o = opts.toNative(progress);
            try {
                if (estimation != null) o.setEstimation(estimation.code);
                O3dNative.o3d_register_icp(r, source.handle(), target.handle(), maxCorrespondenceDistance,
                        NativeResource.fixed(init, 16, "init", true), o);
            } finally {
                o.delete();
            }
        }
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return RegistrationResult.fromNative(r[0]);
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
        O3dNative.o3d_get_information_matrix_from_point_clouds(m, source.handle(), target.handle(),
                maxCorrespondenceDistance, NativeResource.fixed(transformation, 16, "transformation", false));
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return m;
    }

    // ---- features --------------------------------------------------------------------------------

    /**
     * Fast Point Feature Histograms, 33 x N (compute_fpfh_feature); the cloud needs normals. {@code param}
     * null = KNN 30 (Open3D's tutorial: hybrid(0.25, 100) on a 0.05 voxel grid). With {@code indices}
     * (null: all) only those points get a descriptor. The result does not depend on {@code numThreads}
     * (0 = default).
     */
    public static Feature computeFpfhFeature(PointCloud cloud, SearchParam param, long[] indices, int numThreads) {
        Objects.requireNonNull(cloud, "cloud");
        long[] h = new long[1];
        o3d_search_param_t p = param != null ? param.toNative() : null;
        try {
            O3dNative.o3d_compute_fpfh_feature(h, cloud.handle(), p, indices, indices == null ? 0 : indices.length, numThreads);
        } finally {
            if (p != null) p.delete();
        }
        Reference.reachabilityFence(cloud);
        return new Feature(h[0]);
    }

    public static Feature computeFpfhFeature(PointCloud cloud, SearchParam param) {
        return computeFpfhFeature(cloud, param, null, 0);
    }

    /**
     * Each source descriptor's nearest target descriptor as flattened (source, target) pairs in ascending
     * source order (correspondences_from_features). With {@code mutualFilter} only mutual nearest pairs are
     * kept, unless fewer than {@code mutualConsistencyRatio} * num(source) survive (then all pairs).
     */
    public static int[] correspondencesFromFeatures(Feature source, Feature target, boolean mutualFilter,
                                                    double mutualConsistencyRatio, int numThreads) {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(target, "target");
        int[] pairs = new int[Math.toIntExact(Math.multiplyExact(2L, source.num()))];
        long[] n = new long[1];
        O3dNative.o3d_correspondences_from_features(pairs, pairs.length / 2, n, source.handle(), target.handle(),
                mutualFilter ? 1 : 0, mutualConsistencyRatio, numThreads);
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return NativeResource.trimTo(pairs, 2 * n[0]);
    }

    public static int[] correspondencesFromFeatures(Feature source, Feature target) {
        return correspondencesFromFeatures(source, target, false, 0.1, 0);
    }

    // ---- global registration ---------------------------------------------------------------------

    /** Pairs in a flattened (source, target) index array. */
    static long pairs(int[] corres, String name) {
        Objects.requireNonNull(corres, name);
        if (corres.length % 2 != 0)
            throw new IllegalArgumentException(name + ": length " + corres.length + " is not a multiple of 2");
        return corres.length / 2;
    }

    /**
     * RANSAC over feature correspondences (registration_ransac_based_on_feature_matching): each hypothesis
     * fits ransacN drawn pairs, must pass every checker (may be null), and is scored by the share of pairs
     * within {@code maxCorrespondenceDistance} after the move. Options null: defaults.
     */
    public static RegistrationResult registrationRansacBasedOnFeatureMatching(
            PointCloud source, PointCloud target, Feature sourceFeature, Feature targetFeature, double maxCorrespondenceDistance,
            List<CorrespondenceChecker> checkers, RansacOptions options) {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(target, "target");
        Objects.requireNonNull(sourceFeature, "sourceFeature");
        Objects.requireNonNull(targetFeature, "targetFeature");
        RansacOptions opts = options != null ? options : new RansacOptions();
        long[] r = new long[1];
        try (CorrespondenceChecker.NativeArray c = new CorrespondenceChecker.NativeArray(checkers);
             ProgressRef progress = new ProgressRef(opts.progress)) {
            o3d_ransac_options_t o = opts.toNative(progress);
            try {
                O3dNative.o3d_register_ransac_based_on_feature_matching(r, source.handle(), target.handle(),
                        sourceFeature.handle(), targetFeature.handle(), maxCorrespondenceDistance, c.array, c.count, o);
            } finally {
                o.delete();
            }
        }
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        Reference.reachabilityFence(sourceFeature);
        Reference.reachabilityFence(targetFeature);
        return RegistrationResult.fromNative(r[0]);
    }

    /** RANSAC over given flattened (source, target) pairs (registration_ransac_based_on_correspondence); options.mutualFilter is ignored. */
    public static RegistrationResult registrationRansacBasedOnCorrespondence(
            PointCloud source, PointCloud target, int[] corres, double maxCorrespondenceDistance,
            List<CorrespondenceChecker> checkers, RansacOptions options) {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(target, "target");
        long n = pairs(corres, "corres");
        RansacOptions opts = options != null ? options : new RansacOptions();
        long[] r = new long[1];
        try (CorrespondenceChecker.NativeArray c = new CorrespondenceChecker.NativeArray(checkers);
             ProgressRef progress = new ProgressRef(opts.progress)) {
            o3d_ransac_options_t o = opts.toNative(progress);
            try {
                O3dNative.o3d_register_ransac_based_on_correspondence(r, source.handle(), target.handle(), corres, n,
                        maxCorrespondenceDistance, c.array, c.count, o);
            } finally {
                o.delete();
            }
        }
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return RegistrationResult.fromNative(r[0]);
    }

    /** Fast Global Registration (Zhou, Park, Koltun 2016) on mutual feature matches (options null: defaults). */
    public static RegistrationResult registrationFgrBasedOnFeatureMatching(
            PointCloud source, PointCloud target, Feature sourceFeature, Feature targetFeature, FgrOptions options) {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(target, "target");
        Objects.requireNonNull(sourceFeature, "sourceFeature");
        Objects.requireNonNull(targetFeature, "targetFeature");
        FgrOptions opts = options != null ? options : new FgrOptions();
        long[] r = new long[1];
        try (ProgressRef progress = new ProgressRef(opts.progress)) {
            o3d_fgr_options_t o = opts.toNative(progress);
            try {
                O3dNative.o3d_register_fgr_based_on_feature_matching(r, source.handle(), target.handle(),
                        sourceFeature.handle(), targetFeature.handle(), o);
            } finally {
                o.delete();
            }
        }
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        Reference.reachabilityFence(sourceFeature);
        Reference.reachabilityFence(targetFeature);
        return RegistrationResult.fromNative(r[0]);
    }

    /** Fast Global Registration on given flattened (source, target) pairs. */
    public static RegistrationResult registrationFgrBasedOnCorrespondence(PointCloud source, PointCloud target, int[] corres,
                                                                          FgrOptions options) {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(target, "target");
        long n = pairs(corres, "corres");
        FgrOptions opts = options != null ? options : new FgrOptions();
        long[] r = new long[1];
        try (ProgressRef progress = new ProgressRef(opts.progress)) {
            o3d_fgr_options_t o = opts.toNative(progress);
            try {
                O3dNative.o3d_register_fgr_based_on_correspondence(r, source.handle(), target.handle(), corres, n, o);
            } finally {
                o.delete();
            }
        }
        Reference.reachabilityFence(source);
        Reference.reachabilityFence(target);
        return RegistrationResult.fromNative(r[0]);
    }

    // ---- multiway registration -------------------------------------------------------------------

    /**
     * Optimize the node poses of {@code graph} in place (global_optimization): optimize with the line process,
     * remove uncertain edges whose confidence fell below edgePruneThreshold, optimize again; edge confidences
     * are updated. An edge naming a missing node throws and leaves the graph unchanged, as does cancelling.
     */
    public static GlobalOptimizationSummary globalOptimization(PoseGraph graph, GlobalOptimizationOptions options) {
        Objects.requireNonNull(graph, "graph");
        GlobalOptimizationOptions opts = options != null ? options : new GlobalOptimizationOptions();
        o3d_global_optimization_summary_t summary = new o3d_global_optimization_summary_t();
        try (ProgressRef progress = new ProgressRef(opts.progress)) {
            summary.setStruct_size(O3dNative.o3dx_sizeof_global_optimization_summary());
            o3d_global_optimization_options_t o = opts.toNative(progress);
            try {
                O3dNative.o3d_global_optimization(summary, graph.handle(), o);
            } finally {
                o.delete();
            }
            Reference.reachabilityFence(graph);
            return new GlobalOptimizationSummary(summary);
        } finally {
            summary.delete();
        }
    }

    public static GlobalOptimizationSummary globalOptimization(PoseGraph graph) {
        return globalOptimization(graph, null);
    }
}
