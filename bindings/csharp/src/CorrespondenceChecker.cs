// SPDX-License-Identifier: MIT
using System;
using System.Collections.Generic;

namespace O3d
{
    public enum CorrespondenceCheckerKind
    {
        /// <summary>CorrespondenceCheckerBasedOnEdgeLength(similarity_threshold in (0, 1]).</summary>
        EdgeLength = O3dNative.O3D_CHECKER_EDGE_LENGTH,
        /// <summary>CorrespondenceCheckerBasedOnDistance(distance_threshold).</summary>
        Distance = O3dNative.O3D_CHECKER_DISTANCE,
        /// <summary>CorrespondenceCheckerBasedOnNormal(normal_angle_threshold, radians): both clouds need normals.</summary>
        Normal = O3dNative.O3D_CHECKER_NORMAL,
    }

    /// <summary>
    /// Prunes RANSAC hypotheses early (Open3D's CorrespondenceCheckerBasedOnEdgeLength / Distance / Normal).
    /// Immutable; a null threshold in the factories takes the library's default (0.9, 0.075, 30 degrees).
    /// </summary>
    public sealed class CorrespondenceChecker
    {
        public CorrespondenceCheckerKind Kind { get; private set; }
        /// <summary>Similarity, distance or angle in radians, by kind.</summary>
        public double Threshold { get; private set; }

        public CorrespondenceChecker(CorrespondenceCheckerKind kind, double threshold) { Kind = kind; Threshold = threshold; }

        static CorrespondenceChecker Make(CorrespondenceCheckerKind kind, double? threshold)
        {
            if (threshold.HasValue) return new CorrespondenceChecker(kind, threshold.Value);
            using (var c = NewNative(kind)) return new CorrespondenceChecker(kind, c.threshold);
        }

        public static CorrespondenceChecker EdgeLength(double? similarityThreshold = null) { return Make(CorrespondenceCheckerKind.EdgeLength, similarityThreshold); }
        public static CorrespondenceChecker Distance(double? distanceThreshold = null) { return Make(CorrespondenceCheckerKind.Distance, distanceThreshold); }
        public static CorrespondenceChecker Normal(double? normalAngleThreshold = null) { return Make(CorrespondenceCheckerKind.Normal, normalAngleThreshold); }

        static o3d_correspondence_checker_t NewNative(CorrespondenceCheckerKind kind)
        {
            var c = new o3d_correspondence_checker_t();
            try
            {
                O3dNative.o3d_correspondence_checker_init(c, O3dNative.o3dx_sizeof_correspondence_checker(), (int)kind);
            }
            catch
            {
                c.Dispose();
                throw;
            }
            return c;
        }

        internal o3d_correspondence_checker_t ToNative()
        {
            var c = NewNative(Kind);
            c.threshold = Threshold;
            return c;
        }

        /// <summary>
        /// Does the hypothesis pass (CorrespondenceChecker.Check)? <paramref name="corres"/> holds flattened (source, target)
        /// index pairs; <paramref name="transformation"/> (null: identity) moves the source.
        /// </summary>
        public bool Check(PointCloud source, PointCloud target, int[] corres, double[] transformation = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            ulong n = Checks.Pairs(corres, "corres");
            int passed;
            using (var c = ToNative())
                O3dNative.o3d_correspondence_checker_check(out passed, c, source.Handle, target.Handle, corres, n,
                                                           Checks.Fixed(transformation, 16, "transformation", true));
            GC.KeepAlive(source); GC.KeepAlive(target);
            return passed != 0;
        }

        public override string ToString() { return "CorrespondenceChecker(" + Kind + ", " + Threshold + ")"; }
    }

    /// <summary>A native C array of checkers for one call (the `checkers, num_checkers` pair); Dispose frees it.</summary>
    internal sealed class NativeCheckers : IDisposable
    {
        /// <summary>The array (null when there are no checkers).</summary>
        public o3d_correspondence_checker_t Array { get; private set; }
        public ulong Count { get; private set; }

        public NativeCheckers(IList<CorrespondenceChecker> checkers)
        {
            if (checkers == null || checkers.Count == 0) return;
            ulong n = (ulong)checkers.Count;
            var array = O3dNative.o3dx_checkers_new(n);
            if (array == null) throw new OutOfMemoryException("checkers");
            Array = array;
            try
            {
                for (int i = 0; i < checkers.Count; i++)
                {
                    if (checkers[i] == null) throw new ArgumentNullException("checkers[" + i + "]");
                    using (var c = checkers[i].ToNative()) O3dNative.o3dx_checkers_set(array, n, (ulong)i, c);
                }
            }
            catch
            {
                Dispose();
                throw;
            }
            Count = n;
        }

        public void Dispose()
        {
            if (Array != null) O3dNative.o3dx_checkers_delete(Array);
            Array = null;
            Count = 0;
        }
    }
}
