// SPDX-License-Identifier: MIT
#include "o3d/geometry/point_cloud_covariances.h"

#include <string>
#include <vector>

#include "o3d/kdtree/query_order.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

Eigen::Matrix3d neighbourhood_covariance(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int i : indices) mean += points[static_cast<size_t>(i)];
    mean /= static_cast<double>(indices.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int i : indices) {
        const Eigen::Vector3d d = points[static_cast<size_t>(i)] - mean;
        cov.noalias() += d * d.transpose();
    }
    return cov / static_cast<double>(indices.size());
}

void estimate_covariances(PointCloud& cloud, const kdtree::SearchParam& param, int num_threads) {
    const kdtree::KDTree tree(cloud.points);
    estimate_covariances(cloud, tree, param, num_threads);
}

void estimate_covariances(PointCloud& cloud, const kdtree::KDTree& tree, const kdtree::SearchParam& param,
                          int num_threads) {
    if (tree.size() != cloud.points.size())
        throw InvalidArgument("the tree indexes " + std::to_string(tree.size()) + " points but the cloud has " +
                              std::to_string(cloud.points.size()));
    // Validate the parameter once here so that no exception can start inside the parallel region.
    std::vector<int> probe_idx;
    std::vector<double> probe_d2;
    tree.search(Eigen::Vector3d::Zero(), param, probe_idx, probe_d2);

    const size_t n = cloud.points.size();
    std::vector<Eigen::Matrix3d> covariances(n);
    const int threads = utility::resolve_num_threads(num_threads);
    // Each point's result depends only on its own neighbourhood, so any schedule gives the same output;
    // the spatial order keeps shared tree nodes in cache.
    const std::vector<uint32_t> order = kdtree::spatial_order(cloud.points);
#pragma omp parallel num_threads(threads)
    {
        std::vector<int> idx;
        std::vector<double> d2;
#pragma omp for schedule(dynamic, 512)
        for (int64_t s = 0; s < static_cast<int64_t>(n); ++s) {
            const size_t i = order[static_cast<size_t>(s)];
            covariances[i] = tree.search(cloud.points[i], param, idx, d2) >= 3
                                 ? neighbourhood_covariance(cloud.points, idx)
                                 : Eigen::Matrix3d::Identity().eval();
        }
    }
    cloud.covariances = std::move(covariances);
}

}  // namespace o3d::geometry
