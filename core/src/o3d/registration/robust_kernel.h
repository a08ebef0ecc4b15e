// SPDX-License-Identifier: MIT
#pragma once
/// @file robust_kernel.h
/// @brief Robust kernels (M-estimators) for iteratively reweighted least squares, as Open3D's
/// RobustKernel family (after Babin et al., "Analysis of Robust Functions for Registration
/// Algorithms", 2019): each residual r of a Gauss-Newton step is weighted by w(r) = rho'(r) / r.
#include <algorithm>
#include <cmath>

namespace o3d::registration {

/// @brief The kernels Open3D offers (L2Loss, L1Loss, HuberLoss, CauchyLoss, GMLoss, TukeyLoss).
enum class RobustKernelType { L2, L1, Huber, Cauchy, GM, Tukey };

/// @brief A kernel and its scale `k` (ignored by L2 and L1).
struct RobustKernel {
    RobustKernelType type = RobustKernelType::L2;
    double k = 1.0;

    /// @brief The weight of residual `r`:
    /// L2: 1; L1: 1 / |r|; Huber: 1 if |r| <= k else k / |r|; Cauchy: 1 / (1 + (r / k)^2);
    /// GM: k / (k + r^2)^2; Tukey: (1 - (r / k)^2)^2 if |r| <= k else 0.
    /// L1 at r = 0 is +inf, as the formula says. @see o3d.pipelines.registration.RobustKernel.weight
    double weight(double r) const {
        switch (type) {
            case RobustKernelType::L2:
                return 1.0;
            case RobustKernelType::L1:
                return 1.0 / std::abs(r);
            case RobustKernelType::Huber:
                return std::abs(r) <= k ? 1.0 : k / std::abs(r);
            case RobustKernelType::Cauchy: {
                const double q = r / k;
                return 1.0 / (1.0 + q * q);
            }
            case RobustKernelType::GM: {
                const double d = k + r * r;
                return k / (d * d);
            }
            case RobustKernelType::Tukey: {
                if (!(std::abs(r) <= k)) return 0.0;
                const double q = r / k;
                const double s = 1.0 - q * q;
                return s * s;
            }
        }
        return 1.0;
    }

    /// @brief The weight a Gauss-Newton sum uses: weight(r) capped at kMaxWeight, so that an exactly
    /// matched pair under L1 (weight +inf) cannot turn the normal equations into inf * 0 = NaN.
    double irls_weight(double r) const { return std::min(weight(r), kMaxWeight); }

    /// @brief Does the kernel read `k`?
    bool uses_k() const { return type != RobustKernelType::L2 && type != RobustKernelType::L1; }

    static constexpr double kMaxWeight = 1e12;
};

/// @brief Throw o3d::InvalidArgument unless `kernel` has a known type and, when it uses k, a finite k > 0.
void check_robust_kernel(const RobustKernel& kernel);

}  // namespace o3d::registration
