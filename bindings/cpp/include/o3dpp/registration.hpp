// SPDX-License-Identifier: MIT
#pragma once
/// @file registration.hpp
/// @brief ICP (point-to-point, point-to-plane, colored, generalized, symmetric, with robust kernels),
/// registration evaluation and the information matrix. Global registration: global_registration.hpp;
/// pose graphs: posegraph.hpp.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/registration.h"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/options.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

enum class Estimation : int32_t {
    PointToPoint = O3D_ESTIMATION_POINT_TO_POINT,
    PointToPlane = O3D_ESTIMATION_POINT_TO_PLANE,  ///< the target needs normals
    Colored = O3D_ESTIMATION_COLORED,              ///< both need colors, the target normals (Park et al. 2017)
    Generalized = O3D_ESTIMATION_GENERALIZED,      ///< Segal et al. 2009
    Symmetric = O3D_ESTIMATION_SYMMETRIC           ///< both need normals (Rusinkiewicz 2019)
};

/// @brief Robust kernel (M-estimator) weighting each residual r, with scale k (Open3D's L2Loss(),
/// TukeyLoss(k), ...). Used by point-to-plane, colored, generalized and symmetric ICP.
struct RobustKernel {
    enum class Type : int32_t {
        L2 = O3D_KERNEL_L2,          ///< w = 1
        L1 = O3D_KERNEL_L1,          ///< w = 1 / |r|
        Huber = O3D_KERNEL_HUBER,    ///< w = 1 if |r| <= k else k / |r|
        Cauchy = O3D_KERNEL_CAUCHY,  ///< w = 1 / (1 + (r / k)^2)
        GM = O3D_KERNEL_GM,          ///< w = k / (k + r^2)^2
        Tukey = O3D_KERNEL_TUKEY     ///< w = (1 - (r / k)^2)^2 if |r| <= k else 0
    };
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

/// @brief ICP options (estimation method + ICPConvergenceCriteria); defaults from o3d_icp_options_init.
struct IcpOptions : COptions<IcpOptions, o3d_icp_options_t, &o3d_icp_options_init> {
    Estimation estimation;
    bool with_scaling;
    double relative_fitness;
    double relative_rmse;
    int max_iteration;
    int num_threads;
    /// @brief Robust kernel of point-to-plane, colored, generalized and symmetric ICP.
    RobustKernel kernel;
    /// @brief Colored ICP: weight of the geometric term, in [0, 1].
    double lambda_geometric;
    /// @brief Generalized ICP: covariance regularisation (> 0).
    double epsilon;
    /// @brief Called after each iteration; return false to cancel (Error with O3D_ERROR_CANCELLED).
    /// An exception it throws cancels the call and is rethrown to the caller.
    ProgressCallback progress;

    IcpOptions() { load(library_defaults()); }
    template <typename S, typename C, typename F>
    static void fields(S& s, C& c, F f) {
        f(s.estimation, c.estimation);
        f(s.with_scaling, c.with_scaling);
        f(s.relative_fitness, c.relative_fitness);
        f(s.relative_rmse, c.relative_rmse);
        f(s.max_iteration, c.max_iteration);
        f(s.num_threads, c.num_threads);
        f(s.kernel.type, c.kernel);
        f(s.kernel.k, c.kernel_k);
        f(s.lambda_geometric, c.lambda_geometric);
        f(s.epsilon, c.epsilon);
    }
};

/// @brief Transformation, fitness, inlier RMSE and correspondences. Move-only.
class RegistrationResult
    : public Owner<RegistrationResult, o3d_registration_result_t, &o3d_registration_result_destroy> {
public:
    explicit RegistrationResult(o3d_registration_result_t* owned) : Owner(owned) {}

    Mat4 transformation() const {
        Mat4 t{};
        check(o3d_registration_result_get_transformation(t.data(), get()));
        return t;
    }
    double fitness() const { return query(&o3d_registration_result_get_fitness); }
    double inlier_rmse() const { return query(&o3d_registration_result_get_inlier_rmse); }
    /// @brief (source index, target index) pairs.
    std::vector<std::array<int32_t, 2>> correspondence_set() const {
        return copy_out<std::array<int32_t, 2>>(&o3d_registration_result_get_correspondence_set);
    }
};

namespace detail {
/// @brief Run `call(out, c_options)` with `options`' progress wired in, and own the result.
template <typename Options, typename Call>
RegistrationResult register_with(const Options& options, Call&& call) {
    return RegistrationResult::adopt([&](o3d_registration_result_t** out) {
        return with_progress(options.to_c(), options.progress, [&](const auto* c) { return call(out, c); });
    });
}
}  // namespace detail

/// @brief ICP of `source` onto `target` from `init`. @see o3d.pipelines.registration.registration_icp
inline RegistrationResult registration_icp(const PointCloud& source, const PointCloud& target,
                                           double max_correspondence_distance, const Mat4& init = identity4(),
                                           const IcpOptions& options = {}) {
    return detail::register_with(options, [&](o3d_registration_result_t** out, const o3d_icp_options_t* c) {
        return o3d_register_icp(out, source.get(), target.get(), max_correspondence_distance, init.data(), c);
    });
}

namespace detail {
inline RegistrationResult icp_as(Estimation estimation, const PointCloud& source, const PointCloud& target,
                                 double max_correspondence_distance, const Mat4& init, IcpOptions options) {
    options.estimation = estimation;
    return registration_icp(source, target, max_correspondence_distance, init, options);
}
}  // namespace detail

/// @brief Colored ICP (options.estimation is ignored). @see o3d.pipelines.registration.registration_colored_icp
inline RegistrationResult registration_colored_icp(const PointCloud& source, const PointCloud& target,
                                                   double max_correspondence_distance,
                                                   const Mat4& init = identity4(), const IcpOptions& options = {}) {
    return detail::icp_as(Estimation::Colored, source, target, max_correspondence_distance, init, options);
}
/// @brief Generalized ICP (options.estimation is ignored).
/// @see o3d.pipelines.registration.registration_generalized_icp
inline RegistrationResult registration_generalized_icp(const PointCloud& source, const PointCloud& target,
                                                       double max_correspondence_distance,
                                                       const Mat4& init = identity4(),
                                                       const IcpOptions& options = {}) {
    return detail::icp_as(Estimation::Generalized, source, target, max_correspondence_distance, init, options);
}
/// @brief Symmetric point-to-plane ICP (options.estimation is ignored).
/// @see o3d.pipelines.registration.registration_symmetric_icp
inline RegistrationResult registration_symmetric_icp(const PointCloud& source, const PointCloud& target,
                                                     double max_correspondence_distance,
                                                     const Mat4& init = identity4(), const IcpOptions& options = {}) {
    return detail::icp_as(Estimation::Symmetric, source, target, max_correspondence_distance, init, options);
}

/// @brief Fitness / RMSE / correspondences of `source` moved by `transformation`.
inline RegistrationResult evaluate_registration(const PointCloud& source, const PointCloud& target,
                                                double max_correspondence_distance,
                                                const Mat4& transformation = identity4()) {
    return RegistrationResult::adopt([&](o3d_registration_result_t** out) {
        return o3d_evaluate_registration(out, source.get(), target.get(), max_correspondence_distance,
                                         transformation.data());
    });
}

/// @brief 6x6 information matrix (row-major).
inline Mat6 get_information_matrix_from_point_clouds(const PointCloud& source, const PointCloud& target,
                                                     double max_correspondence_distance,
                                                     const Mat4& transformation = identity4()) {
    Mat6 out{};
    check(o3d_get_information_matrix_from_point_clouds(out.data(), source.get(), target.get(),
                                                       max_correspondence_distance, transformation.data()));
    return out;
}

}  // namespace o3dpp
