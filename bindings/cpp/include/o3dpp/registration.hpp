// SPDX-License-Identifier: MIT
#pragma once
/// @file registration.hpp
/// @brief ICP, registration evaluation and the information matrix.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/registration.h"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

enum class Estimation : int32_t {
    PointToPoint = O3D_ESTIMATION_POINT_TO_POINT,
    PointToPlane = O3D_ESTIMATION_POINT_TO_PLANE
};

/// @brief ICP options (estimation method + ICPConvergenceCriteria), Open3D defaults.
struct IcpOptions {
    Estimation estimation = Estimation::PointToPoint;
    bool with_scaling = false;
    double relative_fitness = 1e-6;
    double relative_rmse = 1e-6;
    int max_iteration = 30;
    int num_threads = 0;
    /// @brief Called after each iteration; return false to cancel (Error with O3D_ERROR_CANCELLED).
    /// An exception it throws cancels the call and is rethrown to the caller.
    ProgressCallback progress;

    /// @brief The C struct (without the callback, which registration_icp wires up).
    o3d_icp_options_t to_c() const {
        o3d_icp_options_t c;
        check(o3d_icp_options_init(&c, sizeof c));
        c.estimation = static_cast<int32_t>(estimation);
        c.with_scaling = with_scaling ? 1 : 0;
        c.relative_fitness = relative_fitness;
        c.relative_rmse = relative_rmse;
        c.max_iteration = max_iteration;
        c.num_threads = num_threads;
        return c;
    }
};

/// @brief Transformation, fitness, inlier RMSE and correspondences. Move-only.
class RegistrationResult {
public:
    explicit RegistrationResult(o3d_registration_result_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::RegistrationResult: NULL handle");
    }
    o3d_registration_result_t* get() const noexcept { return h_.get(); }
    o3d_registration_result_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    Mat4 transformation() const {
        Mat4 t{};
        check(o3d_registration_result_get_transformation(get(), t.data()));
        return t;
    }
    double fitness() const {
        double v = 0;
        check(o3d_registration_result_get_fitness(get(), &v));
        return v;
    }
    double inlier_rmse() const {
        double v = 0;
        check(o3d_registration_result_get_inlier_rmse(get(), &v));
        return v;
    }
    /// @brief (source index, target index) pairs.
    std::vector<std::array<int32_t, 2>> correspondence_set() const {
        size_t n = 0;
        check(o3d_registration_result_get_correspondence_set(get(), nullptr, 0, &n));
        std::vector<std::array<int32_t, 2>> out(n);
        check(o3d_registration_result_get_correspondence_set(get(), n ? out.front().data() : nullptr, n, &n));
        out.resize(n);
        return out;
    }

private:
    UniqueHandle<o3d_registration_result_t, &o3d_registration_result_destroy> h_;
};

/// @brief ICP of `source` onto `target` from `init`. @see o3d.pipelines.registration.registration_icp
inline RegistrationResult registration_icp(const PointCloud& source, const PointCloud& target,
                                           double max_correspondence_distance, const Mat4& init = identity4(),
                                           const IcpOptions& options = {}) {
    o3d_icp_options_t c = options.to_c();
    detail::ProgressContext ctx;
    if (options.progress) {
        ctx.callback = &options.progress;
        c.progress = &detail::progress_trampoline;
        c.user_data = &ctx;
    }
    o3d_registration_result_t* r = nullptr;
    detail::check_progress(
        o3d_register_icp(&r, source.get(), target.get(), max_correspondence_distance, init.data(), &c), ctx);
    return RegistrationResult(r);
}

/// @brief Fitness / RMSE / correspondences of `source` moved by `transformation`.
inline RegistrationResult evaluate_registration(const PointCloud& source, const PointCloud& target,
                                                double max_correspondence_distance,
                                                const Mat4& transformation = identity4()) {
    o3d_registration_result_t* r = nullptr;
    check(o3d_evaluate_registration(&r, source.get(), target.get(), max_correspondence_distance,
                                    transformation.data()));
    return RegistrationResult(r);
}

/// @brief 6x6 information matrix (row-major).
inline Mat6 get_information_matrix_from_point_clouds(const PointCloud& source, const PointCloud& target,
                                                     double max_correspondence_distance,
                                                     const Mat4& transformation = identity4()) {
    Mat6 out{};
    check(o3d_get_information_matrix_from_point_clouds(source.get(), target.get(), max_correspondence_distance,
                                                       transformation.data(), out.data()));
    return out;
}

}  // namespace o3dpp
