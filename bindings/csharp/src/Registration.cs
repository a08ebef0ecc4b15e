// SPDX-License-Identifier: MIT
using System;

namespace O3d
{
    /// <summary>Transformation estimation method of ICP.</summary>
    public enum EstimationMethod
    {
        PointToPoint = O3dNative.O3D_ESTIMATION_POINT_TO_POINT,
        /// <summary>The target needs normals.</summary>
        PointToPlane = O3dNative.O3D_ESTIMATION_POINT_TO_PLANE,
        /// <summary>TransformationEstimationForColoredICP: both clouds need colors, the target normals.</summary>
        Colored = O3dNative.O3D_ESTIMATION_COLORED,
        /// <summary>TransformationEstimationForGeneralizedICP (covariances from the clouds, their normals, or estimated).</summary>
        Generalized = O3dNative.O3D_ESTIMATION_GENERALIZED,
        /// <summary>TransformationEstimationSymmetric: both clouds need normals.</summary>
        Symmetric = O3dNative.O3D_ESTIMATION_SYMMETRIC,
    }

    /// <summary>ICP options: estimation method, its parameters and ICPConvergenceCriteria (Open3D defaults).</summary>
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
        /// <summary>Robust kernel of point-to-plane, colored, generalized and symmetric ICP (default L2Loss).</summary>
        public RobustKernel Kernel { get; set; }
        /// <summary>Colored ICP: weight of the geometric term, in [0, 1] (default 0.968).</summary>
        public double LambdaGeometric { get; set; }
        /// <summary>Generalized ICP: covariance regularisation, &gt; 0 (default 1e-3).</summary>
        public double Epsilon { get; set; }
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
                Kernel = new RobustKernel((RobustKernelKind)o.kernel, o.kernel_k);
                LambdaGeometric = o.lambda_geometric;
                Epsilon = o.epsilon;
            }
        }

        static o3d_icp_options_t NewNative()
        {
            var o = new o3d_icp_options_t();
            O3dNative.o3d_icp_options_init(o, O3dNative.o3dx_sizeof_icp_options());
            return o;
        }

        /// <summary>The native options; <paramref name="progress"/> must outlive the native call.</summary>
        internal o3d_icp_options_t ToNative(ProgressBridge progress)
        {
            var o = NewNative();
            o.estimation = (int)Estimation;
            o.with_scaling = WithScaling ? 1 : 0;
            o.relative_fitness = RelativeFitness;
            o.relative_rmse = RelativeRmse;
            o.max_iteration = MaxIteration;
            o.num_threads = NumThreads;
            var kernel = Kernel ?? RobustKernel.L2Loss();
            o.kernel = (int)kernel.Kind;
            o.kernel_k = kernel.K;
            o.lambda_geometric = LambdaGeometric;
            o.epsilon = Epsilon;
            o.progress = progress.Function;
            o.user_data = progress.UserData;
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
                O3dNative.o3d_registration_result_get_transformation(t, r);
                double fitness, rmse;
                O3dNative.o3d_registration_result_get_fitness(out fitness, r);
                O3dNative.o3d_registration_result_get_inlier_rmse(out rmse, r);
                ulong n;
                O3dNative.o3d_registration_result_get_correspondence_set(null, 0, out n, r);
                var pairs = new int[checked((long)n * 2)];
                O3dNative.o3d_registration_result_get_correspondence_set(pairs, n, out n, r);
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

    /// <summary>o3d.pipelines.registration (local refinement here; features, global registration and pose graphs in
    /// Feature.cs, RegistrationGlobal.cs and PoseGraph.cs).</summary>
    public static partial class Registration
    {
        /// <summary>ICP from <paramref name="source"/> onto <paramref name="target"/>, starting at <paramref name="init"/> (null: identity),
        /// with any estimation (<see cref="IcpOptions.Estimation"/>).</summary>
        public static RegistrationResult RegistrationIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                         double[] init = null, IcpOptions options = null)
        {
            return Icp(source, target, maxCorrespondenceDistance, init, options, null);
        }

        /// <summary>Colored ICP (Park et al. 2017): RegistrationIcp with EstimationMethod.Colored, whatever options.Estimation says.</summary>
        public static RegistrationResult RegistrationColoredIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                                double[] init = null, IcpOptions options = null)
        {
            return Icp(source, target, maxCorrespondenceDistance, init, options, EstimationMethod.Colored);
        }

        /// <summary>Generalized ICP (Segal et al. 2009): RegistrationIcp with EstimationMethod.Generalized.</summary>
        public static RegistrationResult RegistrationGeneralizedIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                                    double[] init = null, IcpOptions options = null)
        {
            return Icp(source, target, maxCorrespondenceDistance, init, options, EstimationMethod.Generalized);
        }

        /// <summary>Symmetric point-to-plane ICP (Rusinkiewicz 2019): RegistrationIcp with EstimationMethod.Symmetric.</summary>
        public static RegistrationResult RegistrationSymmetricIcp(PointCloud source, PointCloud target, double maxCorrespondenceDistance,
                                                                  double[] init = null, IcpOptions options = null)
        {
            return Icp(source, target, maxCorrespondenceDistance, init, options, EstimationMethod.Symmetric);
        }

        static RegistrationResult Icp(PointCloud source, PointCloud target, double maxCorrespondenceDistance, double[] init,
                                      IcpOptions options, EstimationMethod? estimation)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (target == null) throw new ArgumentNullException("target");
            options = options ?? new IcpOptions();
            IntPtr r;
            using (var progress = new ProgressBridge(options.Progress))
            using (var o = options.ToNative(progress))
            {
                if (estimation.HasValue) o.estimation = (int)estimation.Value;
                O3dNative.o3d_register_icp(out r, source.Handle, target.Handle, maxCorrespondenceDistance,
                                           Checks.Fixed(init, 16, "init", true), o);
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
            O3dNative.o3d_get_information_matrix_from_point_clouds(m, source.Handle, target.Handle,
                                                                   maxCorrespondenceDistance,
                                                                   Checks.Fixed(transformation, 16, "transformation", false));
            GC.KeepAlive(source); GC.KeepAlive(target);
            return m;
        }
    }
}
