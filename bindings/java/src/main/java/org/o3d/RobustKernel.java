// SPDX-License-Identifier: MIT
package org.o3d;

/**
 * A robust kernel weighting each ICP residual (o3d.pipelines.registration.L2Loss, L1Loss, HuberLoss(k),
 * CauchyLoss(k), GMLoss(k), TukeyLoss(k)). Immutable; used by point-to-plane, colored, generalized and
 * symmetric ICP through {@link IcpOptions#kernel}.
 */
public final class RobustKernel {
    public enum Kind {
        /** w = 1 */
        L2(O3dNativeConstants.O3D_KERNEL_L2),
        /** w = 1 / |r| */
        L1(O3dNativeConstants.O3D_KERNEL_L1),
        /** w = 1 if |r| &lt;= k else k / |r| */
        HUBER(O3dNativeConstants.O3D_KERNEL_HUBER),
        /** w = 1 / (1 + (r / k)^2) */
        CAUCHY(O3dNativeConstants.O3D_KERNEL_CAUCHY),
        /** Geman-McClure: w = k / (k + r^2)^2 */
        GM(O3dNativeConstants.O3D_KERNEL_GM),
        /** w = (1 - (r / k)^2)^2 if |r| &lt;= k else 0 */
        TUKEY(O3dNativeConstants.O3D_KERNEL_TUKEY);

        final int code;

        Kind(int code) {
            this.code = code;
        }

        static Kind fromCode(int code) {
            for (Kind k : values()) {
                if (k.code == code) return k;
            }
            throw new IllegalArgumentException("unknown kernel " + code);
        }
    }

    private final Kind kind;
    private final double k;

    public RobustKernel(Kind kind, double k) {
        this.kind = java.util.Objects.requireNonNull(kind, "kind");
        this.k = k;
    }

    public static RobustKernel l2Loss() { return new RobustKernel(Kind.L2, 1.0); }
    public static RobustKernel l1Loss() { return new RobustKernel(Kind.L1, 1.0); }
    public static RobustKernel huberLoss(double k) { return new RobustKernel(Kind.HUBER, k); }
    public static RobustKernel cauchyLoss(double k) { return new RobustKernel(Kind.CAUCHY, k); }
    public static RobustKernel gmLoss(double k) { return new RobustKernel(Kind.GM, k); }
    public static RobustKernel tukeyLoss(double k) { return new RobustKernel(Kind.TUKEY, k); }

    public Kind kind() { return kind; }
    /** The kernel's scale (unused by L2 and L1). */
    public double k() { return k; }

    /** The weight this kernel gives to {@code residual} (RobustKernel.weight). */
    public double weight(double residual) {
        double[] w = new double[1];
        O3dNative.o3d_robust_kernel_weight(w, kind.code, k, residual);
        return w[0];
    }

    @Override
    public String toString() {
        return kind + "Loss(k=" + k + ")";
    }
}
