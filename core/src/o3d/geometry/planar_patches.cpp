// SPDX-License-Identifier: MIT
// Planar patch detection: checks, defaults, neighbour graph, and the boxes of the final patches.
#include "o3d/geometry/planar_patches.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "o3d/geometry/planar_patches_detail.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

using planar_patches::Cloud;
using planar_patches::Patch;
using planar_patches::Settings;

/// Smallest thickness of a box, relative to its long edge: a noise-free patch still has a volume.
constexpr double kMinThicknessRatio = 1e-6;

void check_angle(double degrees, const char* name) {
    if (!(degrees > 0.0 && degrees <= 90.0))
        throw InvalidArgument(std::string(name) + " must be in (0, 90] degrees, got " + std::to_string(degrees));
}

Settings resolve_settings(const PointCloud& cloud, double normal_deg, double coplanarity_deg, double outlier_ratio,
                          double min_edge, size_t min_points) {
    check_angle(normal_deg, "normal_variance_threshold_deg");
    check_angle(coplanarity_deg, "coplanarity_deg");
    if (!(outlier_ratio >= 0.0 && outlier_ratio < 1.0))
        throw InvalidArgument("outlier_ratio must be in [0, 1), got " + std::to_string(outlier_ratio));
    if (!(min_edge >= 0.0) || !std::isfinite(min_edge))
        throw InvalidArgument("min_plane_edge_length must be finite and >= 0, got " + std::to_string(min_edge));

    Eigen::Vector3d lo = cloud.points[0], hi = cloud.points[0];
    double magnitude = 0.0;
    for (const auto& p : cloud.points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
        magnitude = std::max(magnitude, p.cwiseAbs().maxCoeff());
    }
    const double extent = (hi - lo).maxCoeff();
    constexpr double kRad = 3.14159265358979323846 / 180.0;
    Settings s;
    s.min_cos_normal = std::cos(normal_deg * kRad);
    s.cot_coplanarity = std::cos(coplanarity_deg * kRad) / std::sin(coplanarity_deg * kRad);
    s.outlier_ratio = outlier_ratio;
    s.min_edge_length = min_edge > 0.0 ? min_edge : 0.01 * extent;
    s.min_points = min_points > 0 ? min_points : std::max<size_t>(10, cloud.points.size() / 1000);
    s.min_points = std::max<size_t>(s.min_points, 3);
    // Rounding of |n . (p - c)| at the cloud's coordinates: far below any real noise.
    s.distance_floor = 1e-12 * (extent + magnitude);
    return s;
}

Cloud prepare_cloud(const PointCloud& cloud, const kdtree::SearchParam& param, int threads) {
    Cloud c;
    c.points = &cloud.points;
    c.normals.reserve(cloud.normals.size());
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        if (!cloud.points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
        const Eigen::Vector3d& n = cloud.normals[i];
        if (!n.allFinite()) throw InvalidArgument("normal " + std::to_string(i) + " has a non-finite entry");
        const double length = n.norm();
        c.normals.push_back(length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero());
    }
    const kdtree::KDTree tree(cloud.points);
    c.neighbours = tree.search_batch(cloud.points, param, threads);
    return c;
}

/// @brief The box of a final patch, or false when it is too small (points or long edge).
bool patch_box(const Cloud& cloud, const Settings& settings, const Patch& patch, PlanarPatch& out) {
    if (patch.members.size() < settings.min_points) return false;
    Eigen::Vector3d normal, center;
    if (!planar_patches::fit_plane(*cloud.points, patch.members, normal, center)) return false;
    double agreement = 0.0;
    for (int i : patch.members) agreement += normal.dot(cloud.normals[static_cast<size_t>(i)]);
    if (agreement < 0.0) normal = -normal;
    const planar_patches::Frame f = planar_patches::tight_frame(*cloud.points, patch.members, normal, center);
    const Eigen::Vector3d mid = 0.5 * (f.lo + f.hi);
    Eigen::Vector3d extent = f.hi - f.lo;
    const double long_edge = std::max(extent.x(), extent.y());
    if (long_edge < settings.min_edge_length) return false;
    extent.z() = std::max(extent.z(), kMinThicknessRatio * long_edge);
    out.box.center = center + mid.x() * f.u + mid.y() * f.v + mid.z() * normal;
    out.box.R.col(0) = f.u;
    out.box.R.col(1) = f.v;
    out.box.R.col(2) = normal;
    out.box.extent = extent;
    out.indices.assign(patch.members.begin(), patch.members.end());
    std::sort(out.indices.begin(), out.indices.end());
    return true;
}

}  // namespace

std::vector<PlanarPatch> detect_planar_patches_with_indices(const PointCloud& cloud,
                                                            double normal_variance_threshold_deg,
                                                            double coplanarity_deg, double outlier_ratio,
                                                            double min_plane_edge_length, size_t min_num_points,
                                                            const kdtree::SearchParam& search_param,
                                                            int num_threads) {
    if (!cloud.has_normals())
        throw InvalidArgument("detect_planar_patches needs a non-empty cloud with one normal per point "
                              "(call estimate_normals first)");
    if (cloud.points.size() > static_cast<size_t>(std::numeric_limits<int>::max()))
        throw InvalidArgument("detect_planar_patches supports at most 2^31 - 1 points");
    kdtree::validate(search_param);
    const Settings settings = resolve_settings(cloud, normal_variance_threshold_deg, coplanarity_deg, outlier_ratio,
                                               min_plane_edge_length, min_num_points);
    const int threads = utility::resolve_num_threads(num_threads);
    const Cloud prepared = prepare_cloud(cloud, search_param, threads);

    std::vector<int> plane_of;
    std::vector<Patch> patches = planar_patches::split_and_detect(prepared, settings, plane_of, threads);
    planar_patches::grow_and_merge(prepared, settings, patches, plane_of);

    std::vector<PlanarPatch> result;
    for (const Patch& patch : patches) {
        PlanarPatch out;
        if (patch.alive && patch_box(prepared, settings, patch, out)) result.push_back(std::move(out));
    }
    // Detection order is deterministic; the stable sort keeps it among patches of equal size.
    std::stable_sort(result.begin(), result.end(), [](const PlanarPatch& a, const PlanarPatch& b) {
        return a.indices.size() > b.indices.size();
    });
    return result;
}

std::vector<OrientedBoundingBox> detect_planar_patches(const PointCloud& cloud, double normal_variance_threshold_deg,
                                                       double coplanarity_deg, double outlier_ratio,
                                                       double min_plane_edge_length, size_t min_num_points,
                                                       const kdtree::SearchParam& search_param, int num_threads) {
    std::vector<OrientedBoundingBox> boxes;
    for (auto& patch :
         detect_planar_patches_with_indices(cloud, normal_variance_threshold_deg, coplanarity_deg, outlier_ratio,
                                            min_plane_edge_length, min_num_points, search_param, num_threads))
        boxes.push_back(patch.box);
    return boxes;
}

}  // namespace o3d::geometry
