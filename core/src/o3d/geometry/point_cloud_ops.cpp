// SPDX-License-Identifier: MIT
#include "o3d/geometry/point_cloud_ops.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

template <typename T>
void append_attribute(std::vector<T>& target, bool keep, const std::vector<T>& source, size_t new_size) {
    if (!keep) {
        target.clear();
        return;
    }
    target.reserve(new_size);
    target.insert(target.end(), source.begin(), source.end());
}

}  // namespace

void append(PointCloud& target, const PointCloud& source) {
    if (source.points.empty()) return;
    const size_t new_size = target.points.size() + source.points.size();
    const bool target_empty = !target.has_points();
    append_attribute(target.normals, (target_empty || target.has_normals()) && source.has_normals(), source.normals,
                     new_size);
    append_attribute(target.colors, (target_empty || target.has_colors()) && source.has_colors(), source.colors,
                     new_size);
    append_attribute(target.covariances, (target_empty || target.has_covariances()) && source.has_covariances(),
                     source.covariances, new_size);
    target.points.reserve(new_size);
    target.points.insert(target.points.end(), source.points.begin(), source.points.end());
}

Eigen::Vector3d min_bound(const PointCloud& cloud) {
    if (cloud.points.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d lo = cloud.points[0];
    for (const auto& p : cloud.points) lo = lo.cwiseMin(p);
    return lo;
}

Eigen::Vector3d max_bound(const PointCloud& cloud) {
    if (cloud.points.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d hi = cloud.points[0];
    for (const auto& p : cloud.points) hi = hi.cwiseMax(p);
    return hi;
}

Eigen::Vector3d center(const PointCloud& cloud) {
    if (cloud.points.empty()) return Eigen::Vector3d::Zero();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& p : cloud.points) sum += p;
    return sum / static_cast<double>(cloud.points.size());
}

void transform(PointCloud& cloud, const Eigen::Matrix4d& transformation) {
    if (!transformation.allFinite()) throw InvalidArgument("transformation has a non-finite entry");
    for (auto& p : cloud.points) {
        const Eigen::Vector4d h = transformation * p.homogeneous();
        p = h.head<3>() / h(3);
    }
    const Eigen::Matrix3d linear = transformation.topLeftCorner<3, 3>();
    if (cloud.has_covariances())
        for (auto& c : cloud.covariances) c = linear * c * linear.transpose();
    if (!cloud.has_normals()) return;
    for (auto& n : cloud.normals) n = linear * n;
}

void translate(PointCloud& cloud, const Eigen::Vector3d& translation, bool relative) {
    if (!translation.allFinite()) throw InvalidArgument("translation has a non-finite entry");
    const Eigen::Vector3d shift = relative ? translation : Eigen::Vector3d(translation - center(cloud));
    for (auto& p : cloud.points) p += shift;
}

void rotate(PointCloud& cloud, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& c) {
    if (!rotation.allFinite()) throw InvalidArgument("rotation has a non-finite entry");
    if (!c.allFinite()) throw InvalidArgument("center has a non-finite entry");
    for (auto& p : cloud.points) p = rotation * (p - c) + c;
    if (cloud.has_covariances())
        for (auto& cov : cloud.covariances) cov = rotation * cov * rotation.transpose();
    if (!cloud.has_normals()) return;
    for (auto& n : cloud.normals) n = rotation * n;
}

void scale(PointCloud& cloud, double factor, const Eigen::Vector3d& c) {
    if (!std::isfinite(factor)) throw InvalidArgument("scale is not finite");
    if (!c.allFinite()) throw InvalidArgument("center has a non-finite entry");
    for (auto& p : cloud.points) p = (p - c) * factor + c;
}

void paint_uniform_color(PointCloud& cloud, const Eigen::Vector3d& rgb) {
    if (!rgb.allFinite()) throw InvalidArgument("color has a non-finite entry");
    cloud.colors.assign(cloud.points.size(), rgb.cwiseMax(0.0).cwiseMin(1.0));
}

PointCloud select_by_mask(const PointCloud& cloud, const std::vector<uint8_t>& keep) {
    PointCloud out;
    const bool normals = cloud.has_normals(), colors = cloud.has_colors(), covariances = cloud.has_covariances();
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        if (!keep[i]) continue;
        out.points.push_back(cloud.points[i]);
        if (normals) out.normals.push_back(cloud.normals[i]);
        if (colors) out.colors.push_back(cloud.colors[i]);
        if (covariances) out.covariances.push_back(cloud.covariances[i]);
    }
    return out;
}

PointCloud select_by_index(const PointCloud& cloud, const std::vector<int64_t>& indices, bool invert) {
    const size_t n = cloud.points.size();
    std::vector<uint8_t> keep(n, invert ? 1 : 0);
    for (const int64_t i : indices) {
        if (i < 0 || static_cast<uint64_t>(i) >= n)
            throw InvalidArgument("index " + std::to_string(i) + " is out of range for a cloud of " +
                                  std::to_string(n) + " points");
        keep[static_cast<size_t>(i)] = invert ? 0 : 1;
    }
    return select_by_mask(cloud, keep);
}

void remove_non_finite_points(PointCloud& cloud, bool remove_nan, bool remove_infinite) {
    if (!remove_nan && !remove_infinite) return;
    std::vector<uint8_t> keep(cloud.points.size(), 1);
    bool any_removed = false;
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        const bool has_nan = p.array().isNaN().any();
        const bool has_inf = p.array().isInf().any();
        if ((remove_nan && has_nan) || (remove_infinite && has_inf)) {
            keep[i] = 0;
            any_removed = true;
        }
    }
    if (any_removed) cloud = select_by_mask(cloud, keep);
}

void normalize_normals(PointCloud& cloud) {
    for (auto& n : cloud.normals) {
        const double norm = n.norm();
        if (norm > 0.0) n /= norm;
    }
}

void check_attribute_sizes(const PointCloud& cloud) {
    const size_t n = cloud.points.size();
    if (!cloud.normals.empty() && cloud.normals.size() != n)
        throw InvalidArgument("the cloud has " + std::to_string(n) + " points but " +
                              std::to_string(cloud.normals.size()) + " normals");
    if (!cloud.colors.empty() && cloud.colors.size() != n)
        throw InvalidArgument("the cloud has " + std::to_string(n) + " points but " +
                              std::to_string(cloud.colors.size()) + " colors");
}

}  // namespace o3d::geometry
