// SPDX-License-Identifier: MIT
// smooth_mls and smooth_bilateral: one pass, each point from the input's neighbourhood of that point.
// The Laplacian and Taubin filters live in point_cloud_smoothing_laplacian.cpp.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/normal_orientation.h"
#include "o3d/geometry/normals.h"
#include "o3d/geometry/point_cloud_smoothing.h"
#include "o3d/geometry/symmetric_eigen3.h"
#include "o3d/kdtree/query_order.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

void require_finite_points(const PointCloud& cloud) {
    for (size_t i = 0; i < cloud.points.size(); ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
}

void require_positive_sigma(double sigma, const char* name) {
    if (!std::isfinite(sigma) || sigma <= 0.0)
        throw InvalidArgument(std::string(name) + " must be finite and > 0, got " + std::to_string(sigma));
}

/// @brief exp(-d2 * inv_scale) with exp(0) = 1 for d2 = 0 even when inv_scale overflowed to +inf (a tiny
/// sigma or radius), where the plain product would be 0 * inf = NaN.
double gaussian(double d2, double inv_scale) { return d2 == 0.0 ? 1.0 : std::exp(-d2 * inv_scale); }

/// @brief Weighted centroid of the listed points and their weighted scatter about it (not divided by the
/// weight sum: only its eigenvectors are used). Two passes, mean first, so clouds far from the origin keep
/// their precision.
void weighted_plane(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices,
                    const std::vector<double>& weights, Eigen::Vector3d& centroid, Eigen::Matrix3d& scatter) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    double total = 0.0;
    for (size_t k = 0; k < indices.size(); ++k) {
        sum += weights[k] * points[static_cast<size_t>(indices[k])];
        total += weights[k];
    }
    centroid = sum / total;  // total > 0: every weight is >= exp(-1) (d <= h) or 1 (Knn)
    scatter.setZero();
    for (size_t k = 0; k < indices.size(); ++k) {
        const Eigen::Vector3d d = points[static_cast<size_t>(indices[k])] - centroid;
        scatter.noalias() += weights[k] * d * d.transpose();
    }
}

}  // namespace

PointCloud smooth_mls(const PointCloud& cloud, const kdtree::SearchParam& param, int num_threads) {
    kdtree::validate(param);
    require_finite_points(cloud);
    PointCloud out = cloud;
    const bool had_normals = cloud.has_normals();
    if (!had_normals) out.normals.clear();  // Open3D drops normals that do not match the points
    if (cloud.points.empty()) return out;

    const size_t n = cloud.points.size();
    const kdtree::KDTree tree(cloud.points);
    // Gaussian weights need a length scale; a pure kNN search has none, so its weights are uniform.
    const double inv_h2 = param.kind == kdtree::SearchParam::Kind::Knn ? 0.0 : 1.0 / (param.radius * param.radius);
    const int threads = utility::resolve_num_threads(num_threads);
    const std::vector<uint32_t> order = kdtree::spatial_order(cloud.points);
#pragma omp parallel num_threads(threads)
    {
        std::vector<int> idx;
        std::vector<double> d2, w;
#pragma omp for schedule(dynamic, 256)
        for (int64_t s = 0; s < static_cast<int64_t>(n); ++s) {
            const size_t i = order[static_cast<size_t>(s)];
            const Eigen::Vector3d& p = cloud.points[i];
            if (tree.search(p, param, idx, d2) < 3) {
                if (had_normals) out.normals[i] = cloud.normals[i].normalized();
                continue;
            }
            w.resize(idx.size());
            for (size_t k = 0; k < idx.size(); ++k) w[k] = gaussian(d2[k], inv_h2);
            Eigen::Vector3d centroid;
            Eigen::Matrix3d scatter;
            weighted_plane(cloud.points, idx, w, centroid, scatter);
            const Eigen::Vector3d normal = smallest_eigenvector(scatter);  // zero when all neighbours coincide
            out.points[i] = p - normal * (p - centroid).dot(normal);
            if (had_normals) out.normals[i] = normal.squaredNorm() > 0.0 ? normal : cloud.normals[i].normalized();
        }
    }
    // The PCA normals have arbitrary signs; Open3D makes them agree with this exact call.
    if (had_normals) orient_normals_consistent_tangent_plane(out, 30, 0.0, 1.0, num_threads);
    return out;
}

PointCloud smooth_bilateral(const PointCloud& cloud, const kdtree::SearchParam& param, double sigma_s,
                            double sigma_r, int num_threads) {
    kdtree::validate(param);
    require_positive_sigma(sigma_s, "sigma_s");
    require_positive_sigma(sigma_r, "sigma_r");
    require_finite_points(cloud);
    if (cloud.has_normals())
        for (size_t i = 0; i < cloud.normals.size(); ++i)
            if (!cloud.normals[i].allFinite())
                throw InvalidArgument("normal " + std::to_string(i) + " has a non-finite coordinate");
    PointCloud out = cloud;
    if (cloud.points.empty()) return out;

    const size_t n = cloud.points.size();
    const kdtree::KDTree tree(cloud.points);
    // Open3D's estimate_normals() default: kNN 30. The estimated normals stay on the output, as Open3D's.
    if (!cloud.has_normals()) estimate_normals(out, tree, kdtree::SearchParam::make_knn(30), num_threads);
    const std::vector<Eigen::Vector3d>& normals = out.normals;
    const double inv_s = 1.0 / (2.0 * sigma_s * sigma_s);
    const double inv_r = 1.0 / (2.0 * sigma_r * sigma_r);
    const int threads = utility::resolve_num_threads(num_threads);
    const std::vector<uint32_t> order = kdtree::spatial_order(cloud.points);
#pragma omp parallel num_threads(threads)
    {
        std::vector<int> idx;
        std::vector<double> d2;
#pragma omp for schedule(dynamic, 256)
        for (int64_t s = 0; s < static_cast<int64_t>(n); ++s) {
            const size_t i = order[static_cast<size_t>(s)];
            const double normal_norm = normals[i].norm();
            if (normal_norm == 0.0 || tree.search(cloud.points[i], param, idx, d2) < 2) continue;
            const Eigen::Vector3d& p = cloud.points[i];
            const Eigen::Vector3d unit_normal = normals[i] / normal_norm;
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            double total = 0.0;
            for (size_t k = 0; k < idx.size(); ++k) {
                const Eigen::Vector3d& q = cloud.points[static_cast<size_t>(idx[k])];
                const double height = (p - q).dot(unit_normal);
                const double w = gaussian(d2[k], inv_s) * gaussian(height * height, inv_r);
                sum += w * q;
                total += w;
            }
            // The point itself (or a duplicate of it) has weight 1, so total >= 1 in practice.
            if (total > 0.0) out.points[i] = sum / total;
        }
    }
    return out;
}

}  // namespace o3d::geometry
