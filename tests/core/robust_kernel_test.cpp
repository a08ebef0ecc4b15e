// SPDX-License-Identifier: MIT
// Robust kernel weights against their closed forms, and the kernel argument checks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "o3d/registration/robust_kernel.h"
#include "o3d/utility/error.h"

namespace reg = o3d::registration;
using K = reg::RobustKernelType;

namespace {

constexpr double kResiduals[] = {0.0, 1e-3, -0.05, 0.2, -0.5, 0.5, 0.7, -1.3, 4.0};

}  // namespace

// Each weight is w(r) = rho'(r) / r of its loss; written out here independently of the library's switch.
TEST(RobustKernel, WeightsMatchClosedForms) {
    const double k = 0.5;
    for (double r : kResiduals) {
        SCOPED_TRACE(r);
        const double a = std::abs(r);
        EXPECT_EQ(reg::RobustKernel({K::L2, k}).weight(r), 1.0);
        if (r != 0.0) EXPECT_DOUBLE_EQ(reg::RobustKernel({K::L1, k}).weight(r), 1.0 / a);
        EXPECT_DOUBLE_EQ(reg::RobustKernel({K::Huber, k}).weight(r), a <= k ? 1.0 : k / a);
        EXPECT_DOUBLE_EQ(reg::RobustKernel({K::Cauchy, k}).weight(r), 1.0 / (1.0 + (r / k) * (r / k)));
        EXPECT_DOUBLE_EQ(reg::RobustKernel({K::GM, k}).weight(r), k / ((k + r * r) * (k + r * r)));
        const double t = 1.0 - (r / k) * (r / k);
        EXPECT_DOUBLE_EQ(reg::RobustKernel({K::Tukey, k}).weight(r), a <= k ? t * t : 0.0);
    }
}

// Open3D 0.20's HuberLoss(0.5).weight(r) etc. at r = 0, 0.2, -0.3, 0.5, 0.7, printed by
// tools/reference/record_icp_variants.py.
TEST(RobustKernel, MatchesOpen3DValues) {
    const double r[] = {0.0, 0.2, -0.3, 0.5, 0.7};
    const double huber[] = {1.0, 1.0, 1.0, 1.0, 0.7142857142857143};
    const double cauchy[] = {1.0, 0.8620689655172413, 0.7352941176470589, 0.5, 0.33783783783783783};
    const double gm[] = {2.0, 1.7146776406035664, 1.4363688595231257, 0.8888888888888888, 0.5101520253035404};
    const double tukey[] = {1.0, 0.7055999999999999, 0.4096, 0.0, 0.0};
    for (int i = 0; i < 5; ++i) {
        SCOPED_TRACE(r[i]);
        EXPECT_NEAR(reg::RobustKernel({K::Huber, 0.5}).weight(r[i]), huber[i], 1e-15);
        EXPECT_NEAR(reg::RobustKernel({K::Cauchy, 0.5}).weight(r[i]), cauchy[i], 1e-15);
        EXPECT_NEAR(reg::RobustKernel({K::GM, 0.5}).weight(r[i]), gm[i], 1e-15);
        EXPECT_NEAR(reg::RobustKernel({K::Tukey, 0.5}).weight(r[i]), tukey[i], 1e-15);
    }
}

TEST(RobustKernel, EdgeCases) {
    // L1 at an exact match is infinite (Open3D's L1Loss().weight(0) is inf too); the Gauss-Newton weight is capped.
    EXPECT_EQ(reg::RobustKernel({K::L1, 1.0}).weight(0.0), std::numeric_limits<double>::infinity());
    EXPECT_EQ(reg::RobustKernel({K::L1, 1.0}).irls_weight(0.0), reg::RobustKernel::kMaxWeight);
    EXPECT_DOUBLE_EQ(reg::RobustKernel({K::L1, 1.0}).irls_weight(0.25), 4.0);
    // Tukey is exactly zero beyond k and at k; Huber is continuous at k.
    EXPECT_EQ(reg::RobustKernel({K::Tukey, 0.1}).weight(0.1), 0.0);
    EXPECT_EQ(reg::RobustKernel({K::Tukey, 0.1}).weight(-3.0), 0.0);
    EXPECT_EQ(reg::RobustKernel({K::Huber, 0.1}).weight(0.1), 1.0);
    // Weights fall monotonically with |r| for every k-kernel.
    for (auto type : {K::Huber, K::Cauchy, K::GM, K::Tukey}) {
        const reg::RobustKernel kernel{type, 0.3};
        double previous = kernel.weight(0.0);
        for (double r = 0.01; r < 1.0; r += 0.01) {
            const double w = kernel.weight(r);
            EXPECT_LE(w, previous) << static_cast<int>(type) << " at " << r;
            EXPECT_EQ(w, kernel.weight(-r));
            previous = w;
        }
    }
}

TEST(RobustKernel, Validation) {
    EXPECT_NO_THROW(reg::check_robust_kernel({}));
    // L2 and L1 ignore k, so any k is fine for them.
    EXPECT_NO_THROW(reg::check_robust_kernel({K::L2, -1.0}));
    EXPECT_NO_THROW(reg::check_robust_kernel({K::L1, std::nan("")}));
    for (auto type : {K::Huber, K::Cauchy, K::GM, K::Tukey}) {
        EXPECT_NO_THROW(reg::check_robust_kernel({type, 1e-6}));
        for (double k : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
            EXPECT_THROW(reg::check_robust_kernel({type, k}), o3d::InvalidArgument)
                << static_cast<int>(type) << " " << k;
    }
    EXPECT_THROW(reg::check_robust_kernel({static_cast<K>(6), 1.0}), o3d::InvalidArgument);
    EXPECT_THROW(reg::check_robust_kernel({static_cast<K>(-1), 1.0}), o3d::InvalidArgument);
}
