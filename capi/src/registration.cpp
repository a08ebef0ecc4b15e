// SPDX-License-Identifier: MIT
// C API: registration.h.
#include <cmath>
#include <memory>
#include <string>

#include "internal.h"
#include "o3d/registration.h"
#include "o3d/registration/evaluation.h"
#include "o3d/registration/icp.h"
#include "o3d/registration/information_matrix.h"
#include "o3d/registration/robust_kernel.h"

namespace {

namespace reg = o3d::registration;

const o3d_icp_options_t kIcpDefaults = {
    sizeof(o3d_icp_options_t), O3D_ESTIMATION_POINT_TO_POINT, 0, 1e-6, 1e-6, 30, 0, nullptr, nullptr,
    O3D_KERNEL_L2, 1.0, 0.968, 1e-3,
};

/// O3D_KERNEL_* and its k -> core kernel, validated (k must be finite and > 0 where the kernel reads it).
reg::RobustKernel to_kernel(int32_t kernel, double k, const char* name) {
    reg::RobustKernel out;
    out.k = k;
    switch (kernel) {
        case O3D_KERNEL_L2: out.type = reg::RobustKernelType::L2; break;
        case O3D_KERNEL_L1: out.type = reg::RobustKernelType::L1; break;
        case O3D_KERNEL_HUBER: out.type = reg::RobustKernelType::Huber; break;
        case O3D_KERNEL_CAUCHY: out.type = reg::RobustKernelType::Cauchy; break;
        case O3D_KERNEL_GM: out.type = reg::RobustKernelType::GM; break;
        case O3D_KERNEL_TUKEY: out.type = reg::RobustKernelType::Tukey; break;
        default:
            throw o3d::InvalidArgument(std::string(name) + " " + std::to_string(kernel) + " is not an O3D_KERNEL_*");
    }
    reg::check_robust_kernel(out);
    return out;
}

reg::IcpOptions to_core(const o3d_icp_options_t& o) {
    reg::IcpOptions out;
    switch (o.estimation) {
        case O3D_ESTIMATION_POINT_TO_POINT: out.estimation = reg::Estimation::PointToPoint; break;
        case O3D_ESTIMATION_POINT_TO_PLANE: out.estimation = reg::Estimation::PointToPlane; break;
        case O3D_ESTIMATION_COLORED: out.estimation = reg::Estimation::Colored; break;
        case O3D_ESTIMATION_GENERALIZED: out.estimation = reg::Estimation::Generalized; break;
        case O3D_ESTIMATION_SYMMETRIC: out.estimation = reg::Estimation::Symmetric; break;
        default:
            throw o3d::InvalidArgument("opts.estimation " + std::to_string(o.estimation) +
                                       " is not an O3D_ESTIMATION_*");
    }
    out.kernel = to_kernel(o.kernel, o.kernel_k, "opts.kernel");
    if (!(o.lambda_geometric >= 0.0 && o.lambda_geometric <= 1.0))
        throw o3d::InvalidArgument("opts.lambda_geometric must be in [0, 1], got " +
                                   std::to_string(o.lambda_geometric));
    if (!(std::isfinite(o.epsilon) && o.epsilon > 0.0))
        throw o3d::InvalidArgument("opts.epsilon must be finite and > 0, got " + std::to_string(o.epsilon));
    out.lambda_geometric = o.lambda_geometric;
    out.epsilon = o.epsilon;
    out.with_scaling = o.with_scaling != 0;
    out.criteria.relative_fitness = o.relative_fitness;
    out.criteria.relative_rmse = o.relative_rmse;
    out.criteria.max_iteration = o.max_iteration;
    out.num_threads = o.num_threads;
    out.progress = o3d::capi::to_progress(o.progress, o.user_data);
    return out;
}

o3d_registration_result_t* wrap(reg::RegistrationResult&& r) {
    auto handle = std::make_unique<o3d_registration_result>();
    handle->result = std::move(r);
    return handle.release();
}

}  // namespace

namespace o3d::capi {

Eigen::Matrix4d read_transform(const double* m, const char* name) {
    Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
    if (!m) return t;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            if (!std::isfinite(m[4 * r + c]))
                throw o3d::InvalidArgument(std::string(name) + "[" + std::to_string(4 * r + c) + "] is not finite");
            t(r, c) = m[4 * r + c];
        }
    return t;
}

}  // namespace o3d::capi

extern "C" {

O3D_API o3d_status o3d_icp_options_init(o3d_icp_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kIcpDefaults, "opts"); });
}

O3D_API o3d_status o3d_robust_kernel_weight(double* out, int32_t kernel, double k, double residual) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        const reg::RobustKernel core = to_kernel(kernel, k, "kernel");
        if (std::isnan(residual)) throw o3d::InvalidArgument("residual is NaN");
        *out = core.weight(residual);
    });
}

O3D_API o3d_status o3d_register_icp(o3d_registration_result_t** out, const o3d_pointcloud_t* source,
                                    const o3d_pointcloud_t* target, double max_correspondence_distance,
                                    const double init[16], const o3d_icp_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        const Eigen::Matrix4d t0 = o3d::capi::read_transform(init, "init");
        const reg::IcpOptions options = to_core(o3d::capi::read_options(opts, kIcpDefaults, "opts"));
        *out = wrap(reg::registration_icp(source->cloud, target->cloud, max_correspondence_distance, t0, options));
    });
}

O3D_API o3d_status o3d_evaluate_registration(o3d_registration_result_t** out, const o3d_pointcloud_t* source,
                                             const o3d_pointcloud_t* target, double max_correspondence_distance,
                                             const double transformation[16]) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        const Eigen::Matrix4d t = o3d::capi::read_transform(transformation, "transformation");
        *out = wrap(reg::evaluate_registration(source->cloud, target->cloud, max_correspondence_distance, t));
    });
}

O3D_API o3d_status o3d_get_information_matrix_from_point_clouds(double out[36], const o3d_pointcloud_t* source,
                                                                const o3d_pointcloud_t* target,
                                                                double max_correspondence_distance,
                                                                const double transformation[16]) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        const Eigen::Matrix4d t = o3d::capi::read_transform(transformation, "transformation");
        const Eigen::Matrix<double, 6, 6> info =
            reg::get_information_matrix_from_point_clouds(source->cloud, target->cloud, max_correspondence_distance, t);
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c) out[6 * r + c] = info(r, c);
    });
}

O3D_API void o3d_registration_result_destroy(o3d_registration_result_t* result) { delete result; }

O3D_API o3d_status o3d_registration_result_get_transformation(double out[16], const o3d_registration_result_t* result) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(result, "result");
        o3d::capi::require(out, "out");
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) out[4 * r + c] = result->result.transformation(r, c);
    });
}

O3D_API o3d_status o3d_registration_result_get_fitness(double* out, const o3d_registration_result_t* result) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(result, "result");
        *o3d::capi::require(out, "out") = result->result.fitness;
    });
}

O3D_API o3d_status o3d_registration_result_get_inlier_rmse(double* out, const o3d_registration_result_t* result) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(result, "result");
        *o3d::capi::require(out, "out") = result->result.inlier_rmse;
    });
}

O3D_API o3d_status o3d_registration_result_get_correspondence_set(int32_t* out, size_t capacity, size_t* out_n,
                                                                  const o3d_registration_result_t* result) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(result, "result");
        if (!out && !out_n) throw o3d::InvalidArgument("out and out_n are both NULL");
        const auto& set = result->result.correspondence_set;
        static_assert(sizeof(Eigen::Vector2i) == 2 * sizeof(int32_t), "pairs must be two packed int32");
        const int32_t* data = set.empty() ? nullptr : set.front().data();
        o3d::capi::copy_out(data, set.size(), out, capacity, out_n, 2);
    });
}

}  // extern "C"
