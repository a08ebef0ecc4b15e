// SPDX-License-Identifier: MIT
// C API: registration.h, global registration (correspondence checkers, RANSAC, FGR, the random seed).
#include <cmath>
#include <cstddef>
#include <cstring>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/registration.h"
#include "o3d/registration/correspondence_checker.h"
#include "o3d/registration/fast_global_registration.h"
#include "o3d/registration/ransac.h"
#include "o3d/utility/random.h"

namespace {

namespace reg = o3d::registration;

const o3d_ransac_options_t kRansacDefaults = {
    sizeof(o3d_ransac_options_t), O3D_ESTIMATION_POINT_TO_POINT, 0, 3, 100000, 0.999, 0, 0, 0, 0, nullptr, nullptr,
};

const o3d_fgr_options_t kFgrDefaults = {
    sizeof(o3d_fgr_options_t), 1.4, 0, 1, 0.025, 64, 0.95, 1000, 1, 0, 0, 0, nullptr, nullptr,
};

double default_threshold(int32_t kind) {
    switch (kind) {
        case O3D_CHECKER_EDGE_LENGTH: return 0.9;
        case O3D_CHECKER_DISTANCE: return 0.075;
        case O3D_CHECKER_NORMAL: return 0.5236;  // 30 degrees
        default: throw o3d::InvalidArgument("checker kind " + std::to_string(kind) + " is not an O3D_CHECKER_*");
    }
}

/// One checker of the caller's array; `name` locates it in messages. A struct too short to hold the
/// threshold gets its kind's default.
reg::CorrespondenceChecker to_core(const o3d_correspondence_checker_t& user, const std::string& name) {
    const uint32_t size = user.struct_size;
    if (size < offsetof(o3d_correspondence_checker_t, threshold) || size > sizeof(o3d_correspondence_checker_t))
        throw o3d::InvalidArgument(name + ".struct_size " + std::to_string(size) +
                                   " is not a size this library knows (expected " +
                                   std::to_string(sizeof(o3d_correspondence_checker_t)) +
                                   "); call o3d_correspondence_checker_init()");
    const bool has_threshold = size >= offsetof(o3d_correspondence_checker_t, threshold) + sizeof(double);
    const double threshold = has_threshold ? user.threshold : default_threshold(user.kind);
    switch (user.kind) {
        case O3D_CHECKER_EDGE_LENGTH: return reg::CorrespondenceChecker::edge_length(threshold);
        case O3D_CHECKER_DISTANCE: return reg::CorrespondenceChecker::distance(threshold);
        case O3D_CHECKER_NORMAL: return reg::CorrespondenceChecker::normal(threshold);
        default:
            throw o3d::InvalidArgument(name + ".kind " + std::to_string(user.kind) + " is not an O3D_CHECKER_*");
    }
}

/// The caller's checker array. Entries are `checkers[0].struct_size` bytes apart, so an array built
/// against an older, shorter struct keeps working.
std::vector<reg::CorrespondenceChecker> to_core(const o3d_correspondence_checker_t* checkers, size_t n) {
    std::vector<reg::CorrespondenceChecker> out;
    if (n == 0) return out;
    o3d::capi::require(checkers, "checkers");
    const size_t stride = checkers[0].struct_size;
    if (stride < offsetof(o3d_correspondence_checker_t, threshold) || stride > sizeof(o3d_correspondence_checker_t))
        throw o3d::InvalidArgument("checkers[0].struct_size " + std::to_string(stride) +
                                   " is not a size this library knows (expected " +
                                   std::to_string(sizeof(o3d_correspondence_checker_t)) +
                                   "); call o3d_correspondence_checker_init()");
    const auto* bytes = reinterpret_cast<const unsigned char*>(checkers);
    out.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const std::string name = "checkers[" + std::to_string(i) + "]";
        o3d_correspondence_checker_t entry{};
        // Read the size field alone first: an entry may be shorter than this library's struct.
        std::memcpy(&entry.struct_size, bytes + i * stride, sizeof(uint32_t));
        if (entry.struct_size != stride)
            throw o3d::InvalidArgument(name + ".struct_size " + std::to_string(entry.struct_size) +
                                       " differs from checkers[0].struct_size " + std::to_string(stride));
        std::memcpy(&entry, bytes + i * stride, stride);
        out.push_back(to_core(entry, name));
    }
    return out;
}

reg::CorrespondenceSet to_corres(const int32_t* corres, size_t n) {
    if (n && !corres) throw o3d::InvalidArgument("corres is NULL but num_corres is " + std::to_string(n));
    reg::CorrespondenceSet out(n);
    for (size_t i = 0; i < n; ++i) out[i] = Eigen::Vector2i(corres[2 * i], corres[2 * i + 1]);
    return out;
}


reg::RansacOptions to_core(const o3d_ransac_options_t& o) {
    reg::RansacOptions out;
    if (o.estimation == O3D_ESTIMATION_POINT_TO_POINT)
        out.estimation = reg::Estimation::PointToPoint;
    else if (o.estimation == O3D_ESTIMATION_POINT_TO_PLANE)
        out.estimation = reg::Estimation::PointToPlane;
    else
        throw o3d::InvalidArgument("opts.estimation " + std::to_string(o.estimation) +
                                   " is not O3D_ESTIMATION_POINT_TO_POINT or O3D_ESTIMATION_POINT_TO_PLANE");
    out.with_scaling = o.with_scaling != 0;
    out.ransac_n = o.ransac_n;
    out.criteria.max_iteration = o.max_iteration;
    out.criteria.confidence = o.confidence;
    if (o.use_seed) out.seed = o.seed;
    out.num_threads = o3d::capi::to_num_threads(o.num_threads);
    out.progress = o3d::capi::to_progress(o.progress, o.user_data);
    return out;
}

reg::FastGlobalRegistrationOption to_core(const o3d_fgr_options_t& o) {
    reg::FastGlobalRegistrationOption out;
    out.division_factor = o.division_factor;
    out.use_absolute_scale = o.use_absolute_scale != 0;
    out.decrease_mu = o.decrease_mu != 0;
    out.maximum_correspondence_distance = o.maximum_correspondence_distance;
    out.iteration_number = o.iteration_number;
    out.tuple_scale = o.tuple_scale;
    out.maximum_tuple_count = o.maximum_tuple_count;
    out.tuple_test = o.tuple_test != 0;
    if (o.use_seed) out.seed = o.seed;
    out.num_threads = o3d::capi::to_num_threads(o.num_threads);
    out.progress = o3d::capi::to_progress(o.progress, o.user_data);
    return out;
}

o3d_registration_result_t* wrap(reg::RegistrationResult&& r) {
    auto handle = std::make_unique<o3d_registration_result>();
    handle->result = std::move(r);
    return handle.release();
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_correspondence_checker_init(o3d_correspondence_checker_t* checker, uint32_t struct_size,
                                                   int32_t kind) {
    return o3d::capi::guard(__func__, [&] {
        const o3d_correspondence_checker_t defaults = {sizeof(o3d_correspondence_checker_t), kind,
                                                       default_threshold(kind)};
        o3d::capi::init_options(checker, struct_size, defaults, "checker");
    });
}

O3D_API o3d_status o3d_correspondence_checker_check(int32_t* out_passed, const o3d_correspondence_checker_t* checker,
                                                    const o3d_pointcloud_t* source, const o3d_pointcloud_t* target,
                                                    const int32_t* corres, size_t num_corres,
                                                    const double transformation[16]) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out_passed, "out_passed");
        const auto core = to_core(o3d::capi::require(checker, "checker"), 1);
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        const Eigen::Matrix4d t = o3d::capi::read_transform(transformation, "transformation");
        *out_passed = core[0].check(source->cloud, target->cloud, to_corres(corres, num_corres), t) ? 1 : 0;
    });
}

O3D_API o3d_status o3d_ransac_options_init(o3d_ransac_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kRansacDefaults, "opts"); });
}

O3D_API o3d_status o3d_random_seed(uint64_t seed) {
    return o3d::capi::guard(__func__, [&] { o3d::utility::random::seed(seed); });
}

O3D_API o3d_status o3d_register_ransac_based_on_feature_matching(
    o3d_registration_result_t** out, const o3d_pointcloud_t* source, const o3d_pointcloud_t* target,
    const o3d_feature_t* source_feature, const o3d_feature_t* target_feature, double max_correspondence_distance,
    const o3d_correspondence_checker_t* checkers, size_t num_checkers, const o3d_ransac_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        o3d::capi::require(source_feature, "source_feature");
        o3d::capi::require(target_feature, "target_feature");
        const o3d_ransac_options_t user = o3d::capi::read_options(opts, kRansacDefaults, "opts");
        const reg::RansacOptions options = to_core(user);
        *out = wrap(reg::registration_ransac_based_on_feature_matching(
            source->cloud, target->cloud, source_feature->feature, target_feature->feature, user.mutual_filter != 0,
            max_correspondence_distance, to_core(checkers, num_checkers), options));
    });
}

O3D_API o3d_status o3d_register_ransac_based_on_correspondence(
    o3d_registration_result_t** out, const o3d_pointcloud_t* source, const o3d_pointcloud_t* target,
    const int32_t* corres, size_t num_corres, double max_correspondence_distance,
    const o3d_correspondence_checker_t* checkers, size_t num_checkers, const o3d_ransac_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        const reg::RansacOptions options = to_core(o3d::capi::read_options(opts, kRansacDefaults, "opts"));
        *out = wrap(reg::registration_ransac_based_on_correspondence(
            source->cloud, target->cloud, to_corres(corres, num_corres), max_correspondence_distance,
            to_core(checkers, num_checkers), options));
    });
}

O3D_API o3d_status o3d_fgr_options_init(o3d_fgr_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kFgrDefaults, "opts"); });
}

O3D_API o3d_status o3d_register_fgr_based_on_feature_matching(o3d_registration_result_t** out,
                                                              const o3d_pointcloud_t* source,
                                                              const o3d_pointcloud_t* target,
                                                              const o3d_feature_t* source_feature,
                                                              const o3d_feature_t* target_feature,
                                                              const o3d_fgr_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        o3d::capi::require(source_feature, "source_feature");
        o3d::capi::require(target_feature, "target_feature");
        const reg::FastGlobalRegistrationOption options = to_core(o3d::capi::read_options(opts, kFgrDefaults, "opts"));
        *out = wrap(reg::registration_fgr_based_on_feature_matching(source->cloud, target->cloud,
                                                                    source_feature->feature, target_feature->feature,
                                                                    options));
    });
}

O3D_API o3d_status o3d_register_fgr_based_on_correspondence(o3d_registration_result_t** out,
                                                            const o3d_pointcloud_t* source,
                                                            const o3d_pointcloud_t* target, const int32_t* corres,
                                                            size_t num_corres, const o3d_fgr_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(source, "source");
        o3d::capi::require(target, "target");
        const reg::FastGlobalRegistrationOption options = to_core(o3d::capi::read_options(opts, kFgrDefaults, "opts"));
        *out = wrap(reg::registration_fgr_based_on_correspondence(source->cloud, target->cloud,
                                                                  to_corres(corres, num_corres), options));
    });
}

}  // extern "C"
