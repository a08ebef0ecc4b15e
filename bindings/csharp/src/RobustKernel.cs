// SPDX-License-Identifier: MIT
namespace O3d
{
    /// <summary>The M-estimator of a <see cref="RobustKernel"/>.</summary>
    public enum RobustKernelKind
    {
        /// <summary>w = 1</summary>
        L2 = O3dNative.O3D_KERNEL_L2,
        /// <summary>w = 1 / |r|</summary>
        L1 = O3dNative.O3D_KERNEL_L1,
        /// <summary>w = 1 if |r| &lt;= k else k / |r|</summary>
        Huber = O3dNative.O3D_KERNEL_HUBER,
        /// <summary>w = 1 / (1 + (r / k)^2)</summary>
        Cauchy = O3dNative.O3D_KERNEL_CAUCHY,
        /// <summary>Geman-McClure: w = k / (k + r^2)^2</summary>
        GM = O3dNative.O3D_KERNEL_GM,
        /// <summary>w = (1 - (r / k)^2)^2 if |r| &lt;= k else 0</summary>
        Tukey = O3dNative.O3D_KERNEL_TUKEY,
    }

    /// <summary>
    /// A robust kernel weighting each ICP residual (o3d.pipelines.registration.L2Loss, L1Loss, HuberLoss(k),
    /// CauchyLoss(k), GMLoss(k), TukeyLoss(k)). Immutable; used by point-to-plane, colored, generalized and
    /// symmetric ICP through <see cref="IcpOptions.Kernel"/>.
    /// </summary>
    public sealed class RobustKernel
    {
        public RobustKernelKind Kind { get; private set; }
        /// <summary>The kernel's scale (unused by L2 and L1).</summary>
        public double K { get; private set; }

        public RobustKernel(RobustKernelKind kind, double k = 1.0) { Kind = kind; K = k; }

        public static RobustKernel L2Loss() { return new RobustKernel(RobustKernelKind.L2); }
        public static RobustKernel L1Loss() { return new RobustKernel(RobustKernelKind.L1); }
        public static RobustKernel HuberLoss(double k) { return new RobustKernel(RobustKernelKind.Huber, k); }
        public static RobustKernel CauchyLoss(double k) { return new RobustKernel(RobustKernelKind.Cauchy, k); }
        public static RobustKernel GMLoss(double k) { return new RobustKernel(RobustKernelKind.GM, k); }
        public static RobustKernel TukeyLoss(double k) { return new RobustKernel(RobustKernelKind.Tukey, k); }

        /// <summary>The weight this kernel gives to <paramref name="residual"/> (RobustKernel.weight).</summary>
        public double Weight(double residual)
        {
            double w;
            O3dNative.o3d_robust_kernel_weight(out w, (int)Kind, K, residual);
            return w;
        }

        public override string ToString() { return Kind + "Loss(k=" + K + ")"; }
    }
}
