// SPDX-License-Identifier: MIT
// compute_fpfh_feature: analytic values on a plane, Open3D's normalisation (each sub-histogram of a
// point with neighbours sums to 100 + 100), agreement with a literal transcription of Open3D's
// ComputePairFeatures / ComputeSPFHFeature / ComputeFPFHFeature on clouds made of the degenerate cases
// (ties, coincident points, normals along the joining line, flipped and unnormalised normals),
// invariance to a rigid motion, indices = matching columns, thread-count independence, bad input.
#include "o3d/registration/fpfh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <utility>

#include "o3d/utility/error.h"

using o3d::geometry::PointCloud;
using o3d::kdtree::SearchParam;
using o3d::registration::compute_fpfh_feature;
using o3d::registration::Feature;

namespace {

constexpr double kPi = 3.14159265358979323846;

// ---- A literal transcription of Open3D 0.20's Feature.cpp, the oracle for the fast implementation ----

Eigen::Vector4d open3d_pair_features(const Eigen::Vector3d& p1, const Eigen::Vector3d& n1, const Eigen::Vector3d& p2,
                                     const Eigen::Vector3d& n2) {
    Eigen::Vector4d result;
    Eigen::Vector3d dp2p1 = p2 - p1;
    result(3) = dp2p1.norm();
    if (result(3) == 0.0) return Eigen::Vector4d::Zero();
    Eigen::Vector3d n1_copy = n1, n2_copy = n2;
    const double angle1 = n1_copy.dot(dp2p1) / result(3);
    const double angle2 = n2_copy.dot(dp2p1) / result(3);
    if (std::acos(std::fabs(angle1)) > std::acos(std::fabs(angle2))) {
        n1_copy = n2;
        n2_copy = n1;
        dp2p1 *= -1.0;
        result(2) = -angle2;
    } else {
        result(2) = angle1;
    }
    Eigen::Vector3d v = dp2p1.cross(n1_copy);
    const double v_norm = v.norm();
    if (v_norm == 0.0) return Eigen::Vector4d::Zero();
    v /= v_norm;
    const Eigen::Vector3d w = n1_copy.cross(v);
    result(1) = v.dot(n2_copy);
    result(0) = std::atan2(w.dot(n2_copy), n1_copy.dot(n2_copy));
    return result;
}

int open3d_bin(double position) {
    int h = static_cast<int>(std::floor(position));
    return h < 0 ? 0 : (h >= 11 ? 10 : h);
}

/// Open3D's neighbourhood of point i: KNN from the KD-tree; radius and hybrid by brute force, sorted by
/// (distance, index). Open3D breaks ties at the max_nn cut by tree traversal order, i.e. arbitrarily;
/// o3d breaks them by index.
class Neighbours {
public:
    Neighbours(const PointCloud& cloud, const SearchParam& param) : cloud_(cloud), param_(param), tree_(cloud.points) {}

    int search(int i, std::vector<int>& idx, std::vector<double>& d2) const {
        if (param_.kind == SearchParam::Kind::Knn) return tree_.search(cloud_.points[i], param_, idx, d2);
        std::vector<std::pair<double, int>> all;
        for (size_t j = 0; j < cloud_.size(); ++j) {
            const Eigen::Vector3d d = cloud_.points[i] - cloud_.points[j];
            const double dist = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            if (dist < param_.radius * param_.radius) all.emplace_back(dist, static_cast<int>(j));
        }
        std::sort(all.begin(), all.end());
        if (param_.kind == SearchParam::Kind::Hybrid && all.size() > static_cast<size_t>(param_.knn))
            all.resize(static_cast<size_t>(param_.knn));
        idx.clear();
        d2.clear();
        for (const auto& [dist, j] : all) {
            idx.push_back(j);
            d2.push_back(dist);
        }
        return static_cast<int>(idx.size());
    }

private:
    const PointCloud& cloud_;
    SearchParam param_;
    o3d::kdtree::KDTree tree_;
};

Feature open3d_fpfh(const PointCloud& cloud, const SearchParam& param) {
    const Neighbours tree(cloud, param);
    const int n = static_cast<int>(cloud.size());
    Eigen::MatrixXd spfh = Eigen::MatrixXd::Zero(33, n);
    std::vector<int> idx;
    std::vector<double> d2;
    for (int i = 0; i < n; ++i) {
        if (tree.search(i, idx, d2) <= 1) continue;
        const double incr = 100.0 / static_cast<double>(idx.size() - 1);
        for (size_t k = 1; k < idx.size(); ++k) {
            const Eigen::Vector4d pf =
                open3d_pair_features(cloud.points[i], cloud.normals[i], cloud.points[idx[k]], cloud.normals[idx[k]]);
            spfh(open3d_bin(11 * (pf(0) + kPi) / (2.0 * kPi)), i) += incr;
            spfh(open3d_bin(11 * (pf(1) + 1.0) * 0.5) + 11, i) += incr;
            spfh(open3d_bin(11 * (pf(2) + 1.0) * 0.5) + 22, i) += incr;
        }
    }
    Feature out;
    out.data = Eigen::MatrixXd::Zero(33, n);
    for (int i = 0; i < n; ++i) {
        if (tree.search(i, idx, d2) <= 1) continue;
        double sum[3] = {0.0, 0.0, 0.0};
        for (size_t k = 1; k < idx.size(); ++k) {
            if (d2[k] == 0.0) continue;
            for (int j = 0; j < 33; ++j) {
                const double val = spfh(j, idx[k]) / d2[k];
                sum[j / 11] += val;
                out.data(j, i) += val;
            }
        }
        for (double& s : sum)
            if (s != 0.0) s = 100.0 / s;
        for (int j = 0; j < 33; ++j) out.data(j, i) = out.data(j, i) * sum[j / 11] + spfh(j, i);
    }
    return out;
}

// ---- Clouds ----

/// Random points on a unit sphere with outward normals: every pair is an exact tie of the two normals'
/// angles to the joining line (|a1| = |a2| = d / 2).
PointCloud sphere(int n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    PointCloud pc;
    for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d p = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
        pc.points.push_back(p);
        pc.normals.push_back(p);
    }
    return pc;
}

/// A 0.1-spaced grid in z = 0, normals +z or (every third point) -z: opposite normals give angles of
/// exactly +-pi, where the sign of a zero decides between the end bins.
PointCloud flipped_plane(int side) {
    PointCloud pc;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            pc.points.emplace_back(0.1 * x, 0.1 * y, 0.0);
            pc.normals.emplace_back(0.0, 0.0, (x + 2 * y) % 3 == 0 ? -1.0 : 1.0);
        }
    return pc;
}

/// The awkward cases together: coincident points, points on a line with normals along it (a zero
/// cross product), unnormalised normals (cosines beyond 1, where Open3D's acos is NaN), a far-away
/// isolated point, and random noise around them.
PointCloud awkward(uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    PointCloud pc;
    for (int i = 0; i < 300; ++i) {
        pc.points.emplace_back(u(rng), u(rng), 0.2 * u(rng));
        pc.normals.push_back(Eigen::Vector3d(u(rng), u(rng), 1.0).normalized());
    }
    for (int i = 0; i < 20; ++i) {  // duplicates of earlier points, with other normals
        pc.points.push_back(pc.points[i * 7]);
        pc.normals.push_back(Eigen::Vector3d(0.0, 1.0, 0.0));
    }
    for (int i = 0; i < 15; ++i) {  // a line along x with normals along x
        pc.points.emplace_back(-0.5 + 0.07 * i, 0.3, 0.0);
        pc.normals.emplace_back(1.0, 0.0, 0.0);
    }
    for (int i = 0; i < 15; ++i) {  // normals of length 3
        pc.points.emplace_back(0.4, -0.6 + 0.08 * i, 0.05);
        pc.normals.emplace_back(0.0, 0.0, 3.0);
    }
    for (int i = 0; i < 70; ++i) {  // more coincident points than a hybrid search keeps
        pc.points.emplace_back(0.7, 0.7, 0.0);
        pc.normals.push_back(Eigen::Vector3d(0.1 * (i % 5), 1.0, 0.0).normalized());
    }
    pc.points.emplace_back(50.0, 50.0, 50.0);  // isolated
    pc.normals.emplace_back(0.0, 0.0, 1.0);
    return pc;
}

/// Two points whose pair feature has the angle atan2(-0, -0.8) = -pi (bin 0; +0 would give pi, bin 10),
/// without a tie of the two normals' angles: the zeros' signs are traced through the cross products.
PointCloud signed_zero_pair() {
    PointCloud pc;
    pc.points = {Eigen::Vector3d(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, -0.0, 1.0)};
    pc.normals = {Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(-0.0, 0.6, -0.8)};
    return pc;
}

/// Random points on the surface z = 0.3 sin(2x) cos(3y) with its normals: generic, no exact ties.
PointCloud wavy_surface(int n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    PointCloud pc;
    for (int i = 0; i < n; ++i) {
        const double x = u(rng), y = u(rng);
        pc.points.emplace_back(x, y, 0.3 * std::sin(2 * x) * std::cos(3 * y));
        const Eigen::Vector3d gradient(0.6 * std::cos(2 * x) * std::cos(3 * y),
                                       -0.9 * std::sin(2 * x) * std::sin(3 * y), -1.0);
        pc.normals.push_back(-gradient.normalized());
    }
    return pc;
}

void expect_equal_features(const Feature& a, const Feature& b, double tolerance) {
    ASSERT_EQ(a.dimension(), b.dimension());
    ASSERT_EQ(a.num(), b.num());
    for (size_t i = 0; i < a.num(); ++i)
        for (int j = 0; j < 33; ++j)
            ASSERT_NEAR(a.data(j, i), b.data(j, i), tolerance * (1.0 + std::fabs(b.data(j, i))))
                << "point " << i << " bin " << j;
}

}  // namespace

// On a plane with one normal every pair feature is (angle 0, cosines 0): bins 5, 16 and 27.
TEST(Fpfh, PlaneHasAnalyticHistogram) {
    PointCloud pc;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 12; ++x) {
            pc.points.emplace_back(0.1 * x, 0.1 * y, 1.0);
            pc.normals.emplace_back(0.0, 0.0, 1.0);
        }
    const Feature f = compute_fpfh_feature(pc, SearchParam::make_hybrid(0.25, 30));
    ASSERT_EQ(f.num(), pc.size());
    for (size_t i = 0; i < f.num(); ++i)
        for (int b = 0; b < 33; ++b)
            EXPECT_NEAR(f.data(b, i), (b == 5 || b == 16 || b == 27) ? 200.0 : 0.0, 1e-9) << i << " " << b;
}

TEST(Fpfh, SubHistogramsSumTo200) {
    const PointCloud pc = sphere(2000, 1);
    const Feature f = compute_fpfh_feature(pc, SearchParam::make_knn(20));
    for (size_t i = 0; i < f.num(); ++i)
        for (int h = 0; h < 3; ++h) EXPECT_NEAR(f.data.col(i).segment(11 * h, 11).sum(), 200.0, 1e-9);
    EXPECT_GT(f.data.minCoeff(), -1e-12);
}

TEST(Fpfh, EqualsOpen3dTranscription) {
    const PointCloud clouds[] = {sphere(1500, 2), flipped_plane(15), awkward(3), wavy_surface(1500, 9),
                                 signed_zero_pair()};
    // Hybrid 12 mostly takes the KD-tree path (the radius spans many more points), hybrid 60 the grid.
    const SearchParam params[] = {SearchParam::make_knn(30), SearchParam::make_radius(0.3),
                                  SearchParam::make_hybrid(0.25, 12), SearchParam::make_hybrid(0.3, 60)};
    for (size_t c = 0; c < std::size(clouds); ++c)
        for (const SearchParam& param : params) {
            SCOPED_TRACE("cloud " + std::to_string(c) + ", search kind " +
                         std::to_string(static_cast<int>(param.kind)));
            expect_equal_features(compute_fpfh_feature(clouds[c], param), open3d_fpfh(clouds[c], param), 1e-12);
        }
}

TEST(Fpfh, SignOfZeroAnglePicksTheEndBin) {
    const Feature f = compute_fpfh_feature(signed_zero_pair(), SearchParam::make_knn(2));
    // Point 0's own SPFH puts its one pair in angle bin 0; point 1's pair (frame on point 1) elsewhere.
    EXPECT_GE(f.data(0, 0), 100.0);
    EXPECT_EQ(f.data(10, 0), open3d_fpfh(signed_zero_pair(), SearchParam::make_knn(2)).data(10, 0));
}

TEST(Fpfh, FewerThanTwoNeighboursGiveZero) {
    const PointCloud pc = awkward(4);
    const Feature f = compute_fpfh_feature(pc, SearchParam::make_radius(0.5));
    EXPECT_EQ(f.data.col(static_cast<Eigen::Index>(pc.size() - 1)).norm(), 0.0);  // the isolated point
    EXPECT_GT(f.data.col(0).norm(), 0.0);
}

// Exact degeneracies (ties, zero cross products) do not survive the rounding of a rotation, so this
// uses a generic surface.
TEST(Fpfh, InvariantToRigidMotion) {
    const PointCloud pc = wavy_surface(2500, 5);
    const Eigen::Matrix3d r =
        (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized())).toRotationMatrix();
    const Eigen::Vector3d t(3.0, -1.5, 0.25);
    PointCloud moved = pc;
    for (size_t i = 0; i < pc.size(); ++i) {
        moved.points[i] = r * pc.points[i] + t;
        moved.normals[i] = r * pc.normals[i];
    }
    const auto param = SearchParam::make_hybrid(0.4, 40);
    expect_equal_features(compute_fpfh_feature(moved, param), compute_fpfh_feature(pc, param), 1e-9);
}

TEST(Fpfh, IndicesGiveTheMatchingColumns) {
    const PointCloud pc = sphere(1200, 6);
    const auto param = SearchParam::make_hybrid(0.2, 25);
    const Feature full = compute_fpfh_feature(pc, param);
    const std::vector<int64_t> indices = {900, 3, 3, 1199, 0, 450};
    const Feature subset = compute_fpfh_feature(pc, param, indices, 2);
    const std::vector<int64_t> expected = {0, 3, 450, 900, 1199};  // unique, ascending
    ASSERT_EQ(subset.num(), expected.size());
    for (size_t c = 0; c < expected.size(); ++c)
        EXPECT_EQ(subset.data.col(static_cast<Eigen::Index>(c)), full.data.col(expected[c])) << c;
    EXPECT_EQ(compute_fpfh_feature(pc, param, std::vector<int64_t>{}).num(), 0u);
}

TEST(Fpfh, SameResultForAnyThreadCount) {
    const PointCloud pc = awkward(7);
    for (const SearchParam& param : {SearchParam::make_knn(30), SearchParam::make_hybrid(0.3, 50)}) {
        const Feature one = compute_fpfh_feature(pc, param, std::nullopt, 1);
        const Feature two = compute_fpfh_feature(pc, param, std::nullopt, 2);
        const Feature three = compute_fpfh_feature(pc, param, std::nullopt, 3);
        EXPECT_EQ(one.data, two.data);
        EXPECT_EQ(one.data, three.data);
    }
}

TEST(Fpfh, RejectsBadInput) {
    PointCloud pc = sphere(50, 8);
    PointCloud bare = pc;
    bare.normals.clear();
    EXPECT_THROW(compute_fpfh_feature(bare), o3d::InvalidArgument);
    EXPECT_THROW(compute_fpfh_feature(PointCloud{}), o3d::InvalidArgument);
    EXPECT_THROW(compute_fpfh_feature(pc, SearchParam::make_knn(0)), o3d::InvalidArgument);
    EXPECT_THROW(compute_fpfh_feature(pc, SearchParam::make_radius(std::nan(""))), o3d::InvalidArgument);
    EXPECT_THROW(compute_fpfh_feature(pc, SearchParam::make_knn(5), std::nullopt, -1), o3d::InvalidArgument);
    EXPECT_THROW(compute_fpfh_feature(pc, SearchParam::make_knn(5), std::vector<int64_t>{3, 50}), o3d::InvalidArgument);
    EXPECT_THROW(compute_fpfh_feature(pc, SearchParam::make_knn(5), std::vector<int64_t>{-1}), o3d::InvalidArgument);
    PointCloud bad_normal = pc;
    bad_normal.normals[4].x() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(compute_fpfh_feature(bad_normal), o3d::InvalidArgument);
    PointCloud bad_point = pc;
    bad_point.points[9].z() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(compute_fpfh_feature(bad_point), o3d::InvalidArgument);
}
