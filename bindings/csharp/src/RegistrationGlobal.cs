// SPDX-License-Identifier: MIT
using System;
using System.Collections.Generic;

namespace O3d
{
    /// <summary>
    /// RANSAC options: estimation, ransac_n, RANSACConvergenceCriteria (MaxIteration, Confidence), the mutual filter of
    /// feature matching, seed, threads and progress. Defaults are Open3D's (from o3d_ransac_options_init).
    /// </summary>
    public sealed class RansacOptions
    {
        /// <summary>PointToPoint (default) or PointToPlane.</summary>
        public EstimationMethod Estimation { get; set; }
        /// <summary>Point-to-point: also estimate a scale.</summary>
        public bool WithScaling { get; set; }
        /// <summary>Correspondences drawn per hypothesis, &gt;= 3.</summary>
        public int RansacN { get; set; }
        /// <summary>RANSACConvergenceCriteria.max_iteration (default 100000).</summary>
        public int MaxIteration { get; set; }
        /// <summary>RANSACConvergenceCriteria.confidence in [0, 1] (default 0.999).</summary>
        public double Confidence { get; set; }
        /// <summary>Feature matching only: keep mutual nearest pairs.</summary>
        public bool MutualFilter { get; set; }
        /// <summary>Seed of this call; null (default) draws one from the global generator (<see cref="Utility.Random.Seed"/>).
        /// The same seed gives the same result on any thread count.</summary>
        public ulong? Seed { get; set; }
        /// <summary>0 = library default.</summary>
        public int NumThreads { get; set; }
        /// <summary>Fraction of MaxIteration done (jumps to 1 when confident), on the calling thread; return false to cancel
        /// (the call then throws O3dException with Status.Cancelled). May be null.</summary>
        public Func<double, bool> Progress { get; set; }

        public RansacOptions()
        {
            using (var o = NewNative())
            {
                Estimation = (EstimationMethod)o.estimation;
                WithScaling = o.with_scaling != 0;
                RansacN = o.ransac_n;
                MaxIteration = o.max_iteration;
                Confidence = o.confidence;
                MutualFilter = o.mutual_filter != 0;
                Seed = o.use_seed != 0 ? (ulong?)o.seed : null;
                NumThreads = o.num_threads;
            }
        }

        static o3d_ransac_options_t NewNative()
        {
            var o = new o3d_ransac_options_t();
            O3dNative.o3d_ransac_options_init(o, O3dNative.o3dx_sizeof_ransac_options());
            return o;
        }

        internal o3d_ransac_options_t ToNative(ProgressBridge progress)
        {
            var o = NewNative();
            o.estimation = (int)Estimation;
            o.with_scaling = WithScaling ? 1 : 0;
            o.ransac_n = RansacN;
            o.max_iteration = MaxIteration;
            o.confidence = Confidence;
            o.mutual_filter = MutualFilter ? 1 : 0;
            o.use_seed = Seed.HasValue ? 1 : 0;
            o.seed = Seed.GetValueOrDefault();
            o.num_threads = NumThreads;
            o.progress = progress.Function;
            o.user_data = progress.UserData;
            return o;
        }
    }

    /// <summary>FastGlobalRegistrationOption plus seed, threads and progress; defaults are Open3D's (o3d_fgr_options_init).</summary>
    public sealed class FgrOptions
    {
        /// <summary>&gt; 1: mu is divided by it each annealing step (default 1.4).</summary>
        public double DivisionFactor { get; set; }
        /// <summary>Distances in the clouds' units instead of the normalised scale.</summary>
        public bool UseAbsoluteScale { get; set; }
        /// <summary>Anneal mu (graduated non-convexity); default true.</summary>
        public bool DecreaseMu { get; set; }
        /// <summary>&gt; 0 (default 0.025).</summary>
        public double MaximumCorrespondenceDistance { get; set; }
        public int IterationNumber { get; set; }
        /// <summary>Edge-length similarity of the tuple test, in (0, 1] (default 0.95).</summary>
        public double TupleScale { get; set; }
        public int MaximumTupleCount { get; set; }
        public bool TupleTest { get; set; }
        /// <summary>Seed of the tuple draws; null (default): from the global generator.</summary>
        public ulong? Seed { get; set; }
        public int NumThreads { get; set; }
        /// <summary>Fraction of IterationNumber done; return false to cancel. May be null.</summary>
        public Func<double, bool> Progress { get; set; }

        public FgrOptions()
        {
            using (var o = NewNative())
            {
                DivisionFactor = o.division_factor;
                UseAbsoluteScale = o.use_absolute_scale != 0;
                DecreaseMu = o.decrease_mu != 0;
                MaximumCorrespondenceDistance = o.maximum_correspondence_distance;
                IterationNumber = o.iteration_number;
                TupleScale = o.tuple_scale;
                MaximumTupleCount = o.maximum_tuple_count;
                TupleTest = o.tuple_test != 0;
                Seed = o.use_seed != 0 ? (ulong?)o.seed : null;
                NumThreads = o.num_threads;
            }
        }

        static o3d_fgr_options_t NewNative()
        {
            var o = new o3d_fgr_options_t();
            O3dNative.o3d_fgr_options_init(o, O3dNative.o3dx_sizeof_fgr_options());
            return o;
        }

        internal o3d_fgr_options_t ToNative(ProgressBridge progress)
        {
            var o = NewNative();
            o.division_factor = DivisionFactor;
            o.use_absolute_scale = UseAbsoluteScale ? 1 : 0;
            o.decrease_mu = DecreaseMu ? 1 : 0;
            o.maximum_correspondence_distance = MaximumCorrespondenceDistance;
            o.iteration_number = IterationNumber;
            o.tuple_scale = TupleScale;
            o.maximum_tuple_count = MaximumTupleCount;
            o.tuple_test = TupleTest ? 1 : 0;
            o.use_seed = Seed.HasValue ? 1 : 0;
            o.seed = Seed.GetValueOrDefault();
            o.num_threads = NumThreads;
            o.progress = progress.Function;
            o.user_data = progress.UserData;
            return o;
        }
    }

    /// <summary>o3d.utility.</summary>
    public static class Utility
    {
        /// <summary>o3d.utility.random: the global generator of randomized calls not given a seed (RANSAC, FGR).</summary>
        public static class Random
        {
            /// <summary>Seed the global generator (without it, it starts from a random device).</summary>
            public static void Seed(ulong seed) { O3dNative.o3d_random_seed(seed); }
        }
    }

    public static partial class Registration
    {
        /// <summary>
        /// RANSAC over feature correspondences (registration_ransac_based_on_feature_matching): each hypothesis fits
        /// RansacN drawn pairs, must pass every checker, and is scored by the share of pairs within
        /// <paramref name="maxCorrespondenceDistance"/> after the move.
        /// </summary>
        public static RegistrationResult RegistrationRansacBasedOnFeatureMatching(
            PointCloud source, PointCloud target, Feature sourceFeature, Feature targetFeature, double maxCorrespondenceDistance,
            IList<CorrespondenceChecker> checkers = null, RansacOptions options = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            if (sourceFeature == null) throw new ArgumentNullException("sourceFeature");
            if (targetFeature == null) throw new ArgumentNullException("targetFeature");
            options = options ?? new RansacOptions();
            IntPtr r;
            using (var c = new NativeCheckers(checkers))
            using (var progress = new ProgressBridge(options.Progress))
            using (var o = options.ToNative(progress))
                O3dNative.o3d_register_ransac_based_on_feature_matching(out r, source.Handle, target.Handle, sourceFeature.Handle,
                                                                        targetFeature.Handle, maxCorrespondenceDistance,
                                                                        c.Array, c.Count, o);
            GC.KeepAlive(source); GC.KeepAlive(target); GC.KeepAlive(sourceFeature); GC.KeepAlive(targetFeature);
            return RegistrationResult.FromNative(r);
        }

        /// <summary>RANSAC over given flattened (source, target) pairs (registration_ransac_based_on_correspondence);
        /// options.MutualFilter is ignored.</summary>
        public static RegistrationResult RegistrationRansacBasedOnCorrespondence(
            PointCloud source, PointCloud target, int[] corres, double maxCorrespondenceDistance,
            IList<CorrespondenceChecker> checkers = null, RansacOptions options = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            ulong n = Checks.Pairs(corres, "corres");
            options = options ?? new RansacOptions();
            IntPtr r;
            using (var c = new NativeCheckers(checkers))
            using (var progress = new ProgressBridge(options.Progress))
            using (var o = options.ToNative(progress))
                O3dNative.o3d_register_ransac_based_on_correspondence(out r, source.Handle, target.Handle, corres, n,
                                                                      maxCorrespondenceDistance, c.Array, c.Count, o);
            GC.KeepAlive(source); GC.KeepAlive(target);
            return RegistrationResult.FromNative(r);
        }

        /// <summary>Fast Global Registration (Zhou, Park, Koltun 2016) on mutual feature matches
        /// (registration_fgr_based_on_feature_matching).</summary>
        public static RegistrationResult RegistrationFgrBasedOnFeatureMatching(
            PointCloud source, PointCloud target, Feature sourceFeature, Feature targetFeature, FgrOptions options = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            if (sourceFeature == null) throw new ArgumentNullException("sourceFeature");
            if (targetFeature == null) throw new ArgumentNullException("targetFeature");
            options = options ?? new FgrOptions();
            IntPtr r;
            using (var progress = new ProgressBridge(options.Progress))
            using (var o = options.ToNative(progress))
                O3dNative.o3d_register_fgr_based_on_feature_matching(out r, source.Handle, target.Handle, sourceFeature.Handle,
                                                                     targetFeature.Handle, o);
            GC.KeepAlive(source); GC.KeepAlive(target); GC.KeepAlive(sourceFeature); GC.KeepAlive(targetFeature);
            return RegistrationResult.FromNative(r);
        }

        /// <summary>Fast Global Registration on given flattened (source, target) pairs (registration_fgr_based_on_correspondence).</summary>
        public static RegistrationResult RegistrationFgrBasedOnCorrespondence(PointCloud source, PointCloud target, int[] corres,
                                                                              FgrOptions options = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            ulong n = Checks.Pairs(corres, "corres");
            options = options ?? new FgrOptions();
            IntPtr r;
            using (var progress = new ProgressBridge(options.Progress))
            using (var o = options.ToNative(progress))
                O3dNative.o3d_register_fgr_based_on_correspondence(out r, source.Handle, target.Handle, corres, n, o);
            GC.KeepAlive(source); GC.KeepAlive(target);
            return RegistrationResult.FromNative(r);
        }
    }
}
