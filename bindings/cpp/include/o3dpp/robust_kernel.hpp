// SPDX-License-Identifier: MIT
#pragma once
/// @file robust_kernel.hpp
/// @brief o3dpp::RobustKernel: a robust kernel (O3D_KERNEL_*) and its scale, one value of the ICP options.
#include "o3d/registration.h"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"

namespace o3dpp {

/// @brief Robust kernel (M-estimator) weighting each residual r, with scale k (Open3D's L2Loss(),
/// TukeyLoss(k), ...). Used by point-to-plane, colored, generalized and symmetric ICP.
struct RobustKernel {
    using Type = RobustKernelType;
    Type type = Type::L2;
    double k = 1.0;  ///< unused by L2 and L1

    static RobustKernel L2() { return {Type::L2, 1.0}; }
    static RobustKernel L1() { return {Type::L1, 1.0}; }
    static RobustKernel Huber(double k) { return {Type::Huber, k}; }
    static RobustKernel Cauchy(double k) { return {Type::Cauchy, k}; }
    static RobustKernel GM(double k) { return {Type::GM, k}; }
    static RobustKernel Tukey(double k) { return {Type::Tukey, k}; }

    /// @brief The weight given to `residual`. @see RobustKernel.weight
    double weight(double residual) const {
        double w = 0;
        check(o3d_robust_kernel_weight(&w, static_cast<int32_t>(type), k, residual));
        return w;
    }
};

}  // namespace o3dpp
