// SPDX-License-Identifier: MIT
#include "o3d/reconstruction/pair_registration.h"

#include <Eigen/LU>  // Matrix4d::inverse
#include <algorithm>

#include "o3d/geometry/down_sample.h"
#include "o3d/geometry/normals.h"
#include "o3d/registration/fast_global_registration.h"
#include "o3d/registration/fpfh.h"
#include "o3d/registration/icp.h"
#include "o3d/registration/information_matrix.h"
#include "o3d/registration/ransac.h"

namespace o3d::reconstruction {
namespace {

void estimate_normals_at(geometry::PointCloud& cloud, double voxel_size) {
    geometry::estimate_normals(cloud, kdtree::SearchParam::make_hybrid(voxel_size * 2.0, 30));
}

registration::Estimation estimation_of(const std::string& icp_method) {
    if (icp_method == "point_to_point") return registration::Estimation::PointToPoint;
    if (icp_method == "point_to_plane") return registration::Estimation::PointToPlane;
    if (icp_method == "generalized") return registration::Estimation::Generalized;
    return registration::Estimation::Colored;
}

}  // namespace

PreparedCloud prepare_cloud(const geometry::PointCloud& cloud, double voxel_size) {
    PreparedCloud p;
    p.down = geometry::voxel_down_sample(cloud, voxel_size);
    estimate_normals_at(p.down, voxel_size);
    p.fpfh = registration::compute_fpfh_feature(p.down, kdtree::SearchParam::make_hybrid(voxel_size * 5.0, 100));
    return p;
}

PairResult register_by_features(const PreparedCloud& source, const PreparedCloud& target, const Config& config,
                                uint64_t seed) {
    const double distance = config.voxel_size * 1.4;
    registration::RegistrationResult result;
    if (config.global_registration == "fgr") {
        registration::FastGlobalRegistrationOption option;
        option.maximum_correspondence_distance = distance;
        option.seed = seed;
        result = registration::registration_fgr_based_on_feature_matching(source.down, target.down, source.fpfh,
                                                                           target.fpfh, option);
    } else {
        registration::RansacOptions options;
        options.ransac_n = 4;
        options.criteria = {1000000, 0.999};
        options.seed = seed;
        const std::vector<registration::CorrespondenceChecker> checkers{
            registration::CorrespondenceChecker::edge_length(0.9),
            registration::CorrespondenceChecker::distance(distance)};
        result = registration::registration_ransac_based_on_feature_matching(
            source.down, target.down, source.fpfh, target.fpfh, false, distance, checkers, options);
    }
    PairResult pair;
    if (result.transformation.trace() == 4.0) return pair;  // no hypothesis passed: Open3D's failure signal
    const registration::Matrix6d information = registration::get_information_matrix_from_point_clouds(
        source.down, target.down, distance, result.transformation);
    const auto smaller = static_cast<double>(std::min(source.down.points.size(), target.down.points.size()));
    if (information(5, 5) / smaller < 0.3) return pair;  // too little overlap to trust
    pair.success = true;
    pair.transformation = result.transformation;
    pair.information = information;
    return pair;
}

PairResult multiscale_icp(const geometry::PointCloud& source, const geometry::PointCloud& target,
                          const std::vector<double>& voxel_sizes, const std::vector<int>& max_iterations,
                          const Config& config, const Eigen::Matrix4d& init) {
    PairResult pair;
    pair.success = true;
    pair.transformation = init;
    const registration::Estimation estimation = estimation_of(config.icp_method);
    for (size_t scale = 0; scale < voxel_sizes.size(); ++scale) {
        const double voxel = voxel_sizes[scale];
        geometry::PointCloud source_down = geometry::voxel_down_sample(source, voxel);
        geometry::PointCloud target_down = geometry::voxel_down_sample(target, voxel);
        registration::IcpOptions options;
        options.estimation = estimation;
        options.criteria.max_iteration = max_iterations[scale];
        // Open3D: colored ICP searches within the scale's voxel; the other methods within 1.4 voxel_size.
        double distance = config.voxel_size * 1.4;
        if (estimation != registration::Estimation::PointToPoint) {
            estimate_normals_at(source_down, voxel);
            estimate_normals_at(target_down, voxel);
        }
        if (estimation == registration::Estimation::Colored) distance = voxel;
        const registration::RegistrationResult result =
            registration::registration_icp(source_down, target_down, distance, pair.transformation, options);
        pair.transformation = result.transformation;
        if (scale + 1 == voxel_sizes.size())
            pair.information = registration::get_information_matrix_from_point_clouds(
                source_down, target_down, voxel * 1.4, result.transformation);
    }
    return pair;
}

void add_scene_pair(int s, int t, const PairResult& pair, Eigen::Matrix4d& odometry, registration::PoseGraph& graph) {
    registration::PoseGraphEdge edge;
    edge.source_node_id = s;
    edge.target_node_id = t;
    edge.transformation = pair.transformation;
    edge.information = pair.information;
    if (t == s + 1) {
        odometry = pair.transformation * odometry;
        graph.nodes.push_back({odometry.inverse()});
    } else {
        edge.uncertain = true;
    }
    graph.edges.push_back(edge);
}

}  // namespace o3d::reconstruction
