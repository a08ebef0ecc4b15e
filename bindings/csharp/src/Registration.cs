// SPDX-License-Identifier: MIT
using System;
using System.Runtime.InteropServices;

namespace O3d
{
    /// <summary>Transformation estimation method of ICP.</summary>
    public enum EstimationMethod
    {
        PointToPoint = O3dNative.O3D_ESTIMATION_POINT_TO_POINT,
        /// <summary>The target needs normals.</summary>
        PointToPlane = O3dNative.O3D_ESTIMATION_POINT_TO_PLANE,
    }

    /// <summary>ICP options: estimation method plus ICPConvergenceCriteria (Open3D defaults).</summary>
    public sealed class IcpOptions
    {
        public EstimationMethod Estimation { get; set; }
        /// <summary>Point-to-point only: also estimate a scale.</summary>
        public bool WithScaling { get; set; }
        public double RelativeFitness { get; set; }
        public double RelativeRmse { get; set; }
        public int MaxIteration { get; set; }
        /// <summary>0 = library default.</summary>
        public int NumThreads { get; set; }
        /// <summary>
        /// Called on the calling thread after each iteration with iteration/max_iteration; return false to
        /// cancel (the call then throws O3dException with Status.Cancelled). May be null.
        /// </summary>
        public Func<double, bool> Progress { get; set; }

        public IcpOptions()
        {
            using (var o = NewNative())
            {
                Estimation = (EstimationMethod)o.estimation;
                WithScaling = o.with_scaling != 0;
                RelativeFitness = o.relative_fitness;
                RelativeRmse = o.relative_rmse;
                MaxIteration = o.max_iteration;
                NumThreads = o.num_threads;
            }
        }

        static o3d_icp_options_t NewNative()
        {
            var o = new o3d_icp_options_t();
            O3dNative.o3d_icp_options_init(o, O3dNative.o3dx_sizeof_icp_options());
            return o;
        }

        [UnmanagedFunctionPointer(CallingConvention.Cdecl)]
        internal delegate int ProgressCallbackNative(double fraction, IntPtr userData);

        static readonly ProgressCallbackNative progressTrampoline = ProgressTrampoline;

        [MonoPInvokeCallback(typeof(ProgressCallbackNative))]
        static int ProgressTrampoline(double fraction, IntPtr userData)
        {
            try
            {
                var f = (Func<double, bool>)GCHandle.FromIntPtr(userData).Target;
                return f(fraction) ? 0 : 1;
            }
            catch (Exception) { return 1; } // a throwing callback cancels
        }

        /// <summary>The native options; <paramref name="pin"/> must be freed after the call when allocated.</summary>
        internal o3d_icp_options_t ToNative(out GCHandle pin)
        {
            var o = NewNative();
            o.estimation = (int)Estimation;
            o.with_scaling = WithScaling ? 1 : 0;
            o.relative_fitness = RelativeFitness;
            o.relative_rmse = RelativeRmse;
            o.max_iteration = MaxIteration;
            o.num_threads = NumThreads;
            pin = default(GCHandle);
            if (Progress != null)
            {
                pin = GCHandle.Alloc(Progress);
                o.progress = Marshal.GetFunctionPointerForDelegate(progressTrampoline);
                o.user_data = GCHandle.ToIntPtr(pin);
            }
            return o;
        }
    }

    /// <summary>Result of a registration, copied out of the native result.</summary>
    public sealed class RegistrationResult
    {
        /// <summary>Row-major 4x4 transformation (16 values).</summary>
        public double[] Transformation { get; private set; }
        /// <summary>Inlier count / number of source points.</summary>
        public double Fitness { get; private set; }
        /// <summary>RMS distance of the inlier pairs.</summary>
        public double InlierRmse { get; private set; }
        /// <summary>(source, target) index pairs, flattened: 2 values per pair.</summary>
        public int[] CorrespondenceSet { get; private set; }

        /// <summary>Copies everything out of a native o3d_registration_result_t and destroys it.</summary>
        internal static RegistrationResult FromNative(IntPtr r)
        {
            try
            {
                var res = new RegistrationResult();
                var t = new double[16];
                O3dNative.o3d_registration_result_get_transformation(r, t);
                double fitness, rmse;
                O3dNative.o3d_registration_result_get_fitness(r, out fitness);
                O3dNative.o3d_registration_result_get_inlier_rmse(r, out rmse);
                ulong n;
                O3dNative.o3d_registration_result_get_correspondence_set(r, null, 0, out n);
                var pairs = new int[checked((long)n * 2)];
                O3dNative.o3d_registration_result_get_correspondence_set(r, pairs, n, out n);
                res.Transformation = t;
                res.Fitness = fitness;
                res.InlierRmse = rmse;
                res.CorrespondenceSet = pairs;
                return res;
            }
            finally
            {
                O3dNative.o3d_registration_result_destroy(r);
            }
        }
    }

    /// <summary>o3d.pipelines.registration.</summary>
    public static class Registration
    {
        /// <summary>ICP from <paramref name="source"/> onto <paramref name="target"/>, starting at <paramref name="init"/> (null: identity).</summary>
        public static RegistrationResult RegistrationIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                         double[] init = null, IcpOptions options = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            GCHandle pin;
            IntPtr r;
            using (var o = (options ?? new IcpOptions()).ToNative(out pin))
            {
                try
                {
                    O3dNative.o3d_register_icp(out r, source.Handle, target.Handle, maxCorrespondenceDistance,
                                               Checks.Fixed(init, 16, "init", true), o);
                }
                finally
                {
                    if (pin.IsAllocated) pin.Free();
                }
            }
            GC.KeepAlive(source); GC.KeepAlive(target);
            return RegistrationResult.FromNative(r);
        }

        /// <summary>Fitness, inlier RMSE and correspondences of source moved by transformation (null: identity).</summary>
        public static RegistrationResult EvaluateRegistration(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                              double[] transformation = null)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            IntPtr r;
            O3dNative.o3d_evaluate_registration(out r, source.Handle, target.Handle, maxCorrespondenceDistance,
                                                Checks.Fixed(transformation, 16, "transformation", true));
            GC.KeepAlive(source); GC.KeepAlive(target);
            return RegistrationResult.FromNative(r);
        }

        /// <summary>The 6x6 information matrix (row-major, 36 values).</summary>
        public static double[] GetInformationMatrixFromPointClouds(PointCloud source, PointCloud target,
                                                                   double maxCorrespondenceDistance, double[] transformation)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            var m = new double[36];
            O3dNative.o3d_get_information_matrix_from_point_clouds(source.Handle, target.Handle, maxCorrespondenceDistance,
                                                                   Checks.Fixed(transformation, 16, "transformation", false), m);
            GC.KeepAlive(source); GC.KeepAlive(target);
            return m;
        }
    }
}
