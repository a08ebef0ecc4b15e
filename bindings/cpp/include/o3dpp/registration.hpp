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
#include "o3dpp/generated/options.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

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
