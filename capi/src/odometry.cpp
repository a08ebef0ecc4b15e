// SPDX-License-Identifier: MIT
// C API of RGB-D odometry (odometry.h).
#include "o3d/odometry.h"

#include <cstring>

#include "camera_internal.h"
#include "internal.h"
#include "o3d/odometry/odometry.h"

namespace {

constexpr o3d_odometry_options_t kDefaults = {sizeof(o3d_odometry_options_t), 0.03, 0.0, 4.0};
constexpr size_t kMaxLevels = 8;

}  // namespace

O3D_API o3d_status o3d_odometry_options_init(o3d_odometry_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kDefaults, "opts"); });
}

O3D_API o3d_status o3d_odometry_compute_rgbd(o3d_bool* out_success, double out_transformation[16],
                                             double out_information[36], const o3d_rgbd_image_t* source,
                                             const o3d_rgbd_image_t* target, const o3d_pinhole_intrinsic_t* intrinsic,
                                             const double odo_init[16], o3d_odometry_jacobian jacobian,
                                             const int32_t* iterations_per_level, size_t num_levels,
                                             const o3d_odometry_options_t* opts) {
    using o3d::capi::require;
    return o3d::capi::guard(__func__, [&] {
        require(out_success, "out_success");
        require(out_transformation, "out_transformation");
        require(out_information, "out_information");
        require(source, "source");
        require(target, "target");
        require(intrinsic, "intrinsic");
        if (jacobian != O3D_ODOMETRY_JACOBIAN_COLOR_TERM && jacobian != O3D_ODOMETRY_JACOBIAN_HYBRID_TERM)
            throw o3d::InvalidArgument("jacobian must be O3D_ODOMETRY_JACOBIAN_COLOR_TERM or _HYBRID_TERM");
        const o3d_odometry_options_t o = o3d::capi::read_options(opts, kDefaults, "opts");
        o3d::odometry::OdometryOption option;
        option.depth_diff_max = o.depth_diff_max;
        option.depth_min = o.depth_min;
        option.depth_max = o.depth_max;
        if (iterations_per_level) {
            if (num_levels < 1 || num_levels > kMaxLevels)
                throw o3d::InvalidArgument("num_levels must be 1..8, got " + std::to_string(num_levels));
            option.iteration_number_per_pyramid_level.assign(iterations_per_level, iterations_per_level + num_levels);
        }
        const Eigen::Matrix4d init =
            odo_init ? o3d::capi::matrix_from_row_major(odo_init) : Eigen::Matrix4d::Identity();
        const auto result = o3d::odometry::compute_rgbd_odometry(
            source->rgbd, target->rgbd, o3d::capi::to_core(*intrinsic), init,
            jacobian == O3D_ODOMETRY_JACOBIAN_HYBRID_TERM ? o3d::odometry::Jacobian::HybridTerm
                                                          : o3d::odometry::Jacobian::ColorTerm,
            option);
        *out_success = result.success ? 1 : 0;
        o3d::capi::matrix_to_row_major(result.transformation, out_transformation);
        for (int r = 0; r < 6; ++r)
            for (int c = 0; c < 6; ++c) out_information[6 * r + c] = result.information(r, c);
    });
}
