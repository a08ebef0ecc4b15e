// SPDX-License-Identifier: MIT
#pragma once
// Shared by ransac_test.cpp and fgr_test.cpp: synthetic clouds with known answers, the shared scans,
// and the stored FPFH features (Open3D's binary layout, read by a tiny local reader so that these tests
// do not depend on the feature I/O under test elsewhere).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "o3d/geometry/down_sample.h"
#include "o3d/geometry/normals.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/feature.h"
#include "o3d/registration/registration_result.h"
#include "o3d/utility/random.h"

namespace o3d::test {

/// A smooth, asymmetric height field sampled by the R2 sequence, with exact normals.
inline geometry::PointCloud height_field(int n) {
    geometry::PointCloud pc;
    for (int k = 0; k < n; ++k) {
        const double u = std::fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double v = std::fmod(0.5 + k * 0.5698402909980532, 1.0);
        const double x = -1.0 + 2.0 * u;
        const double y = -0.7 + 1.9 * v;
        const double z = 0.3 * std::sin(2.0 * x) + 0.2 * std::cos(3.0 * y) + 0.15 * x * y + 0.1 * x * x;
        const double fx = 0.6 * std::cos(2.0 * x) + 0.15 * y + 0.2 * x;
        const double fy = -0.6 * std::sin(3.0 * y) + 0.15 * x;
        pc.points.emplace_back(x, y, z);
        pc.normals.push_back(Eigen::Vector3d(-fx, -fy, 1.0).normalized());
    }
    return pc;
}

inline Eigen::Matrix4d rigid(double degrees, const Eigen::Vector3d& axis, const Eigen::Vector3d& t,
                             double scale = 1.0) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = scale * Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
    m.topRightCorner<3, 1>() = t;
    return m;
}

/// `pc` moved by `m` (normals turned by its rotation).
inline geometry::PointCloud transformed(const geometry::PointCloud& pc, const Eigen::Matrix4d& m) {
    geometry::PointCloud out = pc;
    const Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
    const Eigen::Matrix3d rotation = linear / std::cbrt(linear.determinant());
    for (auto& p : out.points) p = linear * p + m.topRightCorner<3, 1>();
    for (auto& n : out.normals) n = rotation * n;
    return out;
}

/// (i, i) for a fraction 1 - outlier_share of the points, (i, random other) for the rest; shuffled.
inline registration::CorrespondenceSet pairs_with_outliers(size_t n, double outlier_share, uint64_t seed) {
    auto rng = utility::random::stream(seed, 0);
    registration::CorrespondenceSet corres;
    for (size_t i = 0; i < n; ++i) {
        int j = static_cast<int>(i);
        if (rng.uniform() < outlier_share) {
            do j = static_cast<int>(rng.below(n));
            while (j == static_cast<int>(i));
        }
        corres.emplace_back(static_cast<int>(i), j);
    }
    return corres;
}

/// Rotation angle (degrees) between the linear parts of two transformations.
inline double angle_between_degrees(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) {
    const Eigen::Matrix3d d = a.topLeftCorner<3, 3>().transpose() * b.topLeftCorner<3, 3>();
    return Eigen::AngleAxisd(d).angle() * 180.0 / M_PI;
}

/// Mean distance that `m` moves the points of `pc` (0 for the identity).
inline double mean_displacement(const geometry::PointCloud& pc, const Eigen::Matrix4d& m) {
    double sum = 0.0;
    for (const auto& p : pc.points) sum += (m.topLeftCorner<3, 3>() * p + m.topRightCorner<3, 1>() - p).norm();
    return sum / static_cast<double>(pc.size());
}

inline bool bitwise_equal(const registration::RegistrationResult& a, const registration::RegistrationResult& b) {
    return std::memcmp(a.transformation.data(), b.transformation.data(), sizeof(double) * 16) == 0 &&
           std::memcmp(&a.fitness, &b.fitness, sizeof(double)) == 0 &&
           std::memcmp(&a.inlier_rmse, &b.inlier_rmse, sizeof(double)) == 0 &&
           a.correspondence_set == b.correspondence_set;
}

/// Open3D's feature file: int32 dimension, int32 count, then count x dimension float64.
inline registration::Feature read_stored_feature(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    int32_t header[2] = {0, 0};
    in.read(reinterpret_cast<char*>(header), sizeof header);
    registration::Feature f;
    if (!in || header[0] <= 0 || header[1] <= 0) return f;
    f.data.resize(header[0], header[1]);
    in.read(reinterpret_cast<char*>(f.data.data()), static_cast<std::streamsize>(sizeof(double) * f.data.size()));
    if (!in) f.data.resize(0, 0);
    return f;
}

/// The large known motion of the shared-scan tests: 75 degrees about a tilted axis through the
/// scan's centroid, then half a metre. cloud_bin_0 moved by it must come back by about its inverse.
inline Eigen::Matrix4d large_motion_about_centroid(const geometry::PointCloud& pc) {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& p : pc.points) centroid += p;
    centroid /= static_cast<double>(pc.size());
    Eigen::Matrix4d m = rigid(75.0, {0.3, -1.0, 0.5}, Eigen::Vector3d::Zero());
    m.topRightCorner<3, 1>() = centroid - m.topLeftCorner<3, 3>() * centroid + Eigen::Vector3d(0.4, -0.2, 0.3);
    return m;
}

/// The paper's preprocessing: voxel 0.05, then normals from radius 0.1 / at most 30 neighbours.
inline geometry::PointCloud paper_preprocess(const geometry::PointCloud& pc) {
    geometry::PointCloud down = geometry::voxel_down_sample(pc, 0.05);
    geometry::estimate_normals(down, kdtree::SearchParam::make_hybrid(0.1, 30));
    return down;
}

}  // namespace o3d::test
