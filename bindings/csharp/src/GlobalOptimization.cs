// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    public enum GlobalOptimizationMethod
    {
        /// <summary>GlobalOptimizationGaussNewton</summary>
        GaussNewton = O3dNative.O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON,
        /// <summary>GlobalOptimizationLevenbergMarquardt (default)</summary>
        LevenbergMarquardt = O3dNative.O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT,
    }

    /// <summary>
    /// The method, GlobalOptimizationConvergenceCriteria and GlobalOptimizationOption of <see cref="Registration.GlobalOptimization"/>,
    /// plus threads and progress. Defaults are Open3D's (from o3d_global_optimization_options_init).
    /// </summary>
    public sealed class GlobalOptimizationOptions
    {
        public GlobalOptimizationMethod Method { get; set; }
        public int MaxIteration { get; set; }
        public double MinRelativeIncrement { get; set; }
        public double MinRelativeResidualIncrement { get; set; }
        public double MinRightTerm { get; set; }
        public double MinResidual { get; set; }
        /// <summary>Levenberg-Marquardt damping retries per iteration.</summary>
        public int MaxIterationLm { get; set; }
        public double UpperScaleFactor { get; set; }
        public double LowerScaleFactor { get; set; }
        /// <summary>Sets the line-process scale mu (default 0.075).</summary>
        public double MaxCorrespondenceDistance { get; set; }
        /// <summary>Uncertain edges whose confidence ends below it are removed (default 0.25).</summary>
        public double EdgePruneThreshold { get; set; }
        /// <summary>Weight of loop closures against odometry (default 1).</summary>
        public double PreferenceLoopClosure { get; set; }
        /// <summary>The node kept fixed; -1 (default): the first node.</summary>
        public int ReferenceNode { get; set; }
        public int NumThreads { get; set; }
        /// <summary>Fraction of MaxIteration done over both passes; return false to cancel (O3dException with Status.Cancelled,
        /// the graph left unchanged). May be null.</summary>
        public Func<double, bool> Progress { get; set; }

        public GlobalOptimizationOptions()
        {
            using (var o = NewNative())
            {
                Method = (GlobalOptimizationMethod)o.method;
                MaxIteration = o.max_iteration;
                MinRelativeIncrement = o.min_relative_increment;
                MinRelativeResidualIncrement = o.min_relative_residual_increment;
                MinRightTerm = o.min_right_term;
                MinResidual = o.min_residual;
                MaxIterationLm = o.max_iteration_lm;
                UpperScaleFactor = o.upper_scale_factor;
                LowerScaleFactor = o.lower_scale_factor;
                MaxCorrespondenceDistance = o.max_correspondence_distance;
                EdgePruneThreshold = o.edge_prune_threshold;
                PreferenceLoopClosure = o.preference_loop_closure;
                ReferenceNode = o.reference_node;
                NumThreads = o.num_threads;
            }
        }

        static o3d_global_optimization_options_t NewNative()
        {
            var o = new o3d_global_optimization_options_t();
            O3dNative.o3d_global_optimization_options_init(o, O3dNative.o3dx_sizeof_global_optimization_options());
            return o;
        }

        internal o3d_global_optimization_options_t ToNative(ProgressBridge progress)
        {
            var o = NewNative();
            o.method = (int)Method;
            o.max_iteration = MaxIteration;
            o.min_relative_increment = MinRelativeIncrement;
            o.min_relative_residual_increment = MinRelativeResidualIncrement;
            o.min_right_term = MinRightTerm;
            o.min_residual = MinResidual;
            o.max_iteration_lm = MaxIterationLm;
            o.upper_scale_factor = UpperScaleFactor;
            o.lower_scale_factor = LowerScaleFactor;
            o.max_correspondence_distance = MaxCorrespondenceDistance;
            o.edge_prune_threshold = EdgePruneThreshold;
            o.preference_loop_closure = PreferenceLoopClosure;
            o.reference_node = ReferenceNode;
            o.num_threads = NumThreads;
            o.progress = progress.Function;
            o.user_data = progress.UserData;
            return o;
        }
    }

    /// <summary>What a global optimization did.</summary>
    public sealed class GlobalOptimizationSummary
    {
        /// <summary>Iterations of both passes.</summary>
        public int Iterations { get; private set; }
        /// <summary>The robust objective before the first pass.</summary>
        public double InitialResidual { get; private set; }
        /// <summary>The robust objective after the last pass.</summary>
        public double FinalResidual { get; private set; }
        /// <summary>Edges removed for a confidence below EdgePruneThreshold.</summary>
        public int PrunedEdges { get; private set; }

        internal GlobalOptimizationSummary(o3d_global_optimization_summary_t s)
        {
            Iterations = s.iterations;
            InitialResidual = s.initial_residual;
            FinalResidual = s.final_residual;
            PrunedEdges = s.pruned_edges;
        }
    }

    public static partial class Registration
    {
        /// <summary>
        /// Optimize the node poses of <paramref name="graph"/> in place (global_optimization): optimize with the line process,
        /// remove uncertain edges whose confidence fell below EdgePruneThreshold, optimize again; edge confidences are updated.
        /// An edge naming a missing node throws and leaves the graph unchanged, as does cancelling.
        /// </summary>
        public static GlobalOptimizationSummary GlobalOptimization(PoseGraph graph, GlobalOptimizationOptions options = null)
        {
            if (graph == null) throw new ArgumentNullException("graph");
            options = options ?? new GlobalOptimizationOptions();
            using (var summary = new o3d_global_optimization_summary_t())
            {
                summary.struct_size = O3dNative.o3dx_sizeof_global_optimization_summary();
                using (var progress = new ProgressBridge(options.Progress))
                using (var o = options.ToNative(progress))
                    O3dNative.o3d_global_optimization(summary, graph.Handle, o);
                GC.KeepAlive(graph);
                return new GlobalOptimizationSummary(summary);
            }
        }
    }
}
