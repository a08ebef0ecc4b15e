// SPDX-License-Identifier: MIT
#include "o3d/geometry/normals.h"

#include <string>
#include <vector>

#include "o3d/geometry/point_cloud_covariances.h"
#include "o3d/geometry/symmetric_eigen3.h"
#include "o3d/kdtree/query_order.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

void require_normals(const PointCloud& cloud) {
    if (!cloud.has_normals()) throw InvalidArgument("the cloud has no normals (call estimate_normals first)");
}

}  // namespace

void estimate_normals(PointCloud& cloud, const kdtree::SearchParam& param, int num_threads) {
    const kdtree::KDTree tree(cloud.points);
    estimate_normals(cloud, tree, param, num_threads);
}

void estimate_normals(PointCloud& cloud, const kdtree::KDTree& tree, const kdtree::SearchParam& param,
                      int num_threads) {
    if (tree.size() != cloud.points.size())
        throw InvalidArgument("the tree indexes " + std::to_string(tree.size()) + " points but the cloud has " +
                              std::to_string(cloud.points.size()));
    // Validate once here so that no exception can start inside the parallel region.
    std::vector<int> probe_idx;
    std::vector<double> probe_d2;
    tree.search(Eigen::Vector3d::Zero(), param, probe_idx, probe_d2);

    const size_t n = cloud.points.size();
    const bool had_normals = cloud.has_normals();
    std::vector<Eigen::Vector3d> normals(n);
    const int threads = utility::resolve_num_threads(num_threads);
    // Neighbouring points share tree nodes: visiting them together keeps those nodes in cache.
    const std::vector<uint32_t> order = kdtree::spatial_order(cloud.points);
#pragma omp parallel num_threads(threads)
    {
        std::vector<int> idx;
        std::vector<double> d2;
#pragma omp for schedule(dynamic, 512)
        for (int64_t s = 0; s < static_cast<int64_t>(n); ++s) {
            const size_t i = order[static_cast<size_t>(s)];
            Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
            if (tree.search(cloud.points[i], param, idx, d2) >= 3) {
                normal = smallest_eigenvector(neighbourhood_covariance(cloud.points, idx));
                if (normal.squaredNorm() == 0.0) normal = had_normals ? cloud.normals[i] : Eigen::Vector3d::UnitZ();
            }
            if (had_normals && normal.dot(cloud.normals[i]) < 0.0) normal = -normal;
            normals[i] = normal;
        }
    }
    cloud.normals = std::move(normals);
}

void orient_normals_to_align_with_direction(PointCloud& cloud, const Eigen::Vector3d& direction) {
    if (!direction.allFinite()) throw InvalidArgument("direction has a non-finite entry");
    require_normals(cloud);
    for (auto& normal : cloud.normals) {
        if (normal.norm() == 0.0)
            normal = direction;
        else if (normal.dot(direction) < 0.0)
            normal = -normal;
    }
}

void orient_normals_towards_camera_location(PointCloud& cloud, const Eigen::Vector3d& camera_location) {
    if (!camera_location.allFinite()) throw InvalidArgument("camera_location has a non-finite entry");
    require_normals(cloud);
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        const Eigen::Vector3d towards = camera_location - cloud.points[i];
        Eigen::Vector3d& normal = cloud.normals[i];
        if (normal.norm() == 0.0) {
            normal = towards.norm() == 0.0 ? Eigen::Vector3d::UnitZ() : towards.normalized();
        } else if (normal.dot(towards) < 0.0) {
            normal = -normal;
        }
    }
}

}  // namespace o3d::geometry
