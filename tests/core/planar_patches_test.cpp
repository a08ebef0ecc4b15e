// SPDX-License-Identifier: MIT
// Planar patch detection (PointCloud.detect_planar_patches) on synthetic scenes with known planes. The scenes are
// built from a splitmix64 stream that tools/reference/record_planar_patches.py repeats, and the Open3D 0.20
// numbers quoted below are that script's output.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "o3d/geometry/oriented_bounding_box.h"
#include "o3d/geometry/planar_patches.h"
#include "o3d/utility/error.h"
#include "o3d/utility/random.h"

using namespace o3d::geometry;
using o3d::kdtree::SearchParam;

namespace {

/// o3d::utility::random::SplitMix64 (uniform: 53 bits in [0, 1)), repeated in
/// tools/reference/record_planar_patches.py so Open3D sees the same clouds.
using o3d::utility::random::SplitMix64;

/// Uniform in [-a, a].
double sym(SplitMix64& rng, double a) { return a * (2.0 * rng.uniform() - 1.0); }

/// Points c + a u + b v + e n with a, b, e uniform in [-hu, hu], [-hv, hv], [-noise, noise]; normals n, each
/// component perturbed by up to normal_noise and renormalised when normal_noise > 0.
void add_rectangle(SplitMix64& rng, PointCloud& cloud, const Eigen::Vector3d& c, const Eigen::Vector3d& u,
                   const Eigen::Vector3d& v, double hu, double hv, const Eigen::Vector3d& n, int count, double noise,
                   double normal_noise = 0.0) {
    for (int k = 0; k < count; ++k) {
        const double a = sym(rng, hu), b = sym(rng, hv), e = sym(rng, noise);
        cloud.points.push_back(c + a * u + b * v + e * n);
        Eigen::Vector3d m = n;
        if (normal_noise > 0.0) {
            const double x = sym(rng, normal_noise), y = sym(rng, normal_noise), z = sym(rng, normal_noise);
            m = (n + Eigen::Vector3d(x, y, z)).normalized();
        }
        cloud.normals.push_back(m);
    }
}

Eigen::Matrix3d rotation_zyx(double ax, double ay, double az) {
    Eigen::Matrix3d rx, ry, rz;
    rx << 1, 0, 0, 0, std::cos(ax), -std::sin(ax), 0, std::sin(ax), std::cos(ax);
    ry << std::cos(ay), 0, std::sin(ay), 0, 1, 0, -std::sin(ay), 0, std::cos(ay);
    rz << std::cos(az), -std::sin(az), 0, std::sin(az), std::cos(az), 0, 0, 0, 1;
    return rz * ry * rx;
}

const Eigen::Vector3d kBoxHalf(1.0, 0.75, 0.5);
const Eigen::Vector3d kBoxShift(0.3, -0.2, 0.1);
Eigen::Matrix3d box_rotation() { return rotation_zyx(0.3, -0.2, 0.5); }

/// Six faces of a box with half sizes kBoxHalf (1500 points per unit of half-size product), noise +-0.004
/// along the normal, exact outward normals, then rotated by box_rotation() and shifted by kBoxShift.
PointCloud box_scene() {
    SplitMix64 rng{11};
    PointCloud cloud;
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {-1.0, 1.0}) {
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            const Eigen::Vector3d n = sign * Eigen::Vector3d::Unit(axis);
            const int count = static_cast<int>(1500.0 * kBoxHalf[a1] * kBoxHalf[a2]);
            add_rectangle(rng, cloud, kBoxHalf[axis] * n, Eigen::Vector3d::Unit(a1), Eigen::Vector3d::Unit(a2),
                          kBoxHalf[a1], kBoxHalf[a2], n, count, 0.004);
        }
    }
    const Eigen::Matrix3d r = box_rotation();
    for (auto& p : cloud.points) p = r * p + kBoxShift;
    for (auto& n : cloud.normals) n = r * n;
    return cloud;
}

/// Floor z = 0 over [-1, 1]^2 (3000 points), wall x = -1 over y in [-1, 1], z in [0, 1.5] (2250), both with
/// noise +-0.003, and a sphere of radius 0.35 about (0.3, 0.2, 0.6) (2500, exact).
PointCloud planes_and_sphere_scene() {
    SplitMix64 rng{22};
    PointCloud cloud;
    add_rectangle(rng, cloud, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0, 1.0,
                  Eigen::Vector3d::UnitZ(), 3000, 0.003);
    add_rectangle(rng, cloud, Eigen::Vector3d(-1.0, 0.0, 0.75), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ(),
                  1.0, 0.75, Eigen::Vector3d::UnitX(), 2250, 0.003);
    for (int k = 0; k < 2500; ++k) {
        const double z = 2.0 * rng.uniform() - 1.0;
        const double phi = 2.0 * M_PI * rng.uniform();
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        const Eigen::Vector3d d(s * std::cos(phi), s * std::sin(phi), z);
        cloud.normals.push_back(d);
        cloud.points.push_back(Eigen::Vector3d(0.3, 0.2, 0.6) + 0.35 * d);
    }
    return cloud;
}

Eigen::Vector3d tilted_normal() { return Eigen::Vector3d(1.0, 2.0, 3.0).normalized(); }

/// A 2 x 1.2 rectangle about (0.5, -1, 2) on the plane of normal tilted_normal(), noise +-0.01 along the normal,
/// normals perturbed by up to 0.05 per component.
PointCloud noisy_plane_scene() {
    SplitMix64 rng{33};
    PointCloud cloud;
    const Eigen::Vector3d n = tilted_normal();
    const Eigen::Vector3d u = n.cross(Eigen::Vector3d::UnitZ()).normalized();
    const Eigen::Vector3d v = n.cross(u);
    add_rectangle(rng, cloud, Eigen::Vector3d(0.5, -1.0, 2.0), u, v, 1.0, 0.6, n, 3000, 0.01, 0.05);
    return cloud;
}

std::vector<PlanarPatch> detect(const PointCloud& cloud, double min_edge = 0.0, int threads = 0) {
    return detect_planar_patches_with_indices(cloud, 60, 75, 0.75, min_edge, 0, SearchParam::make_knn(30), threads);
}

/// A face of the box scene: its points are indices [begin, end) of box_scene(), in generation order.
struct Face {
    Eigen::Vector3d normal, center;
    double long_edge, short_edge;
    int64_t begin, end;
};

std::vector<Face> box_faces() {
    const Eigen::Matrix3d r = box_rotation();
    std::vector<Face> faces;
    int64_t begin = 0;
    for (int axis = 0; axis < 3; ++axis) {
        for (double sign : {-1.0, 1.0}) {
            const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
            const Eigen::Vector3d n = sign * Eigen::Vector3d::Unit(axis);
            const int64_t count = static_cast<int64_t>(1500.0 * kBoxHalf[a1] * kBoxHalf[a2]);
            const double e1 = 2.0 * kBoxHalf[a1], e2 = 2.0 * kBoxHalf[a2];
            faces.push_back({r * n, r * (kBoxHalf[axis] * n) + kBoxShift, std::max(e1, e2), std::min(e1, e2), begin,
                             begin + count});
            begin += count;
        }
    }
    return faces;
}

void expect_valid_box(const PointCloud& cloud, const PlanarPatch& patch) {
    EXPECT_NO_THROW(validate_obb(patch.box));
    EXPECT_NEAR(patch.box.R.determinant(), 1.0, 1e-9);
    EXPECT_GE(patch.box.extent.x(), patch.box.extent.y());
    EXPECT_GT(patch.box.extent.z(), 0.0);
    EXPECT_TRUE(std::is_sorted(patch.indices.begin(), patch.indices.end()));
    // The box holds every point of its patch.
    const std::vector<int64_t> inside = indices_in_obb(cloud.points, patch.box);
    EXPECT_TRUE(std::includes(inside.begin(), inside.end(), patch.indices.begin(), patch.indices.end()));
}

}  // namespace

// Open3D 0.20: 6 patches, normals the faces' outward normals, centres and extents the faces' (to about 0.02).
TEST(PlanarPatches, BoxGivesOnePatchPerFace) {
    const PointCloud cloud = box_scene();
    const std::vector<PlanarPatch> patches = detect(cloud);
    ASSERT_EQ(patches.size(), 6u);
    std::vector<bool> matched(6, false);
    for (const PlanarPatch& patch : patches) {
        expect_valid_box(cloud, patch);
        const Eigen::Vector3d n = patch.box.R.col(2);
        int face = -1;
        const std::vector<Face> faces = box_faces();
        for (int f = 0; f < 6; ++f)
            if (n.dot(faces[static_cast<size_t>(f)].normal) > 0.99) face = f;
        ASSERT_GE(face, 0) << "normal " << n.transpose() << " matches no face (outward)";
        EXPECT_FALSE(matched[static_cast<size_t>(face)]);
        matched[static_cast<size_t>(face)] = true;
        const Face& f = faces[static_cast<size_t>(face)];
        EXPECT_GT(n.dot(f.normal), 0.9999);
        EXPECT_LT((patch.box.center - f.center).norm(), 0.02);
        EXPECT_NEAR(patch.box.extent.x(), f.long_edge, 0.02);
        EXPECT_NEAR(patch.box.extent.y(), f.short_edge, 0.02);
        EXPECT_LT(patch.box.extent.z(), 0.009);  // noise +-0.004
        // Every point of the patch is on its face, and (almost) the whole face is in the patch.
        EXPECT_GE(patch.indices.front(), f.begin);
        EXPECT_LT(patch.indices.back(), f.end);
        EXPECT_GE(static_cast<double>(patch.indices.size()), 0.98 * static_cast<double>(f.end - f.begin));
    }
    // Largest first.
    for (size_t k = 1; k < patches.size(); ++k) EXPECT_GE(patches[k - 1].indices.size(), patches[k].indices.size());
}

// Open3D 0.20 gives 25 patches: the floor (2.02 x 2.04, 0.006 thick), the wall (2.03 x 1.52) and 23 small
// patches on the sphere (at most 0.33 across).
TEST(PlanarPatches, PlanesAndSphere) {
    const PointCloud cloud = planes_and_sphere_scene();
    const std::vector<PlanarPatch> patches = detect(cloud);
    ASSERT_GE(patches.size(), 2u);
    const PlanarPatch& floor = patches[0];
    const PlanarPatch& wall = patches[1];
    EXPECT_GT(floor.box.R.col(2).dot(Eigen::Vector3d::UnitZ()), 0.9999);
    EXPECT_LT(floor.box.center.norm(), 0.01);
    EXPECT_NEAR(floor.box.extent.x(), 2.0, 0.02);
    EXPECT_NEAR(floor.box.extent.y(), 2.0, 0.02);
    EXPECT_EQ(floor.indices.front(), 0);
    EXPECT_EQ(floor.indices.back(), 2999);
    EXPECT_GT(wall.box.R.col(2).dot(Eigen::Vector3d::UnitX()), 0.9999);
    EXPECT_LT((wall.box.center - Eigen::Vector3d(-1.0, 0.0, 0.75)).norm(), 0.01);
    EXPECT_NEAR(wall.box.extent.x(), 2.0, 0.02);
    EXPECT_NEAR(wall.box.extent.y(), 1.5, 0.02);
    EXPECT_EQ(wall.indices.front(), 3000);
    EXPECT_EQ(wall.indices.back(), 5249);

    // The sphere is cut into small patches, never one big plane; about as many as Open3D's 23.
    const size_t sphere_patches = patches.size() - 2;
    EXPECT_GE(sphere_patches, 12u);
    EXPECT_LE(sphere_patches, 46u);
    size_t covered = 0;
    for (size_t k = 2; k < patches.size(); ++k) {
        expect_valid_box(cloud, patches[k]);
        EXPECT_GE(patches[k].indices.front(), 5250);  // sphere points only
        EXPECT_LT(patches[k].indices.size(), 250u);   // at most a tenth of the sphere
        EXPECT_LT(patches[k].box.extent.x(), 0.4);
        // A patch is tangent to the sphere: its normal points away from the centre, through its own middle.
        const Eigen::Vector3d radial = (patches[k].box.center - Eigen::Vector3d(0.3, 0.2, 0.6)).normalized();
        EXPECT_GT(patches[k].box.R.col(2).dot(radial), 0.95);
        covered += patches[k].indices.size();
    }
    EXPECT_GT(covered, 1250u);  // most of the sphere's 2500 points
}

// Open3D 0.20: one patch, normal (0.2673, 0.5346, 0.8017), centre (0.4994, -0.9954, 2.0049), extents 2.0045 and
// 1.2158 (0.018 thick).
TEST(PlanarPatches, NoisyPlaneGivesOnePatch) {
    const PointCloud cloud = noisy_plane_scene();
    const std::vector<PlanarPatch> patches = detect(cloud);
    ASSERT_EQ(patches.size(), 1u);
    const PlanarPatch& patch = patches[0];
    expect_valid_box(cloud, patch);
    EXPECT_GT(patch.box.R.col(2).dot(tilted_normal()), 0.9999);
    EXPECT_LT((patch.box.center - Eigen::Vector3d(0.5, -1.0, 2.0)).norm(), 0.01);
    EXPECT_NEAR(patch.box.extent.x(), 2.0, 0.02);
    EXPECT_NEAR(patch.box.extent.y(), 1.2, 0.02);
    EXPECT_LT(patch.box.extent.z(), 0.021);  // noise +-0.01
    EXPECT_GE(patch.indices.size(), 2900u);

    // The boxes-only entry point returns the same boxes.
    const std::vector<OrientedBoundingBox> boxes = detect_planar_patches(cloud);
    ASSERT_EQ(boxes.size(), 1u);
    EXPECT_EQ(boxes[0].center, patch.box.center);
    EXPECT_EQ(boxes[0].R, patch.box.R);
    EXPECT_EQ(boxes[0].extent, patch.box.extent);
}

// Deliberate difference: Open3D 0.20 finds nothing in a noise-free plane (zero-spread statistics).
TEST(PlanarPatches, NoiseFreePlaneGivesOnePatch) {
    SplitMix64 rng{44};
    PointCloud cloud;
    add_rectangle(rng, cloud, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 1.0, 0.5,
                  -Eigen::Vector3d::UnitZ(), 2000, 0.0);
    const std::vector<PlanarPatch> patches = detect(cloud);
    ASSERT_EQ(patches.size(), 1u);
    EXPECT_EQ(patches[0].indices.size(), 2000u);
    EXPECT_GT(patches[0].box.R.col(2).dot(-Eigen::Vector3d::UnitZ()), 1.0 - 1e-12);  // the points' orientation
    EXPECT_NEAR(patches[0].box.extent.x(), 2.0, 0.01);
    EXPECT_GT(patches[0].box.extent.z(), 0.0);  // still a box with a volume
    expect_valid_box(cloud, patches[0]);
}

TEST(PlanarPatches, SameResultForAnyThreadCount) {
    const PointCloud cloud = planes_and_sphere_scene();
    const std::vector<PlanarPatch> one = detect(cloud, 0.0, 1);
    const std::vector<PlanarPatch> three = detect(cloud, 0.0, 3);
    ASSERT_EQ(one.size(), three.size());
    for (size_t k = 0; k < one.size(); ++k) {
        EXPECT_EQ(one[k].indices, three[k].indices);
        EXPECT_EQ(one[k].box.center, three[k].box.center);
        EXPECT_EQ(one[k].box.R, three[k].box.R);
        EXPECT_EQ(one[k].box.extent, three[k].box.extent);
    }
}

// Open3D 0.20 keeps the 4 faces whose long edge is 2 at min_plane_edge_length = 1.6, as here; here 2.1 drops every
// face (the long edge is below it), where Open3D still keeps the two 2 x 1.5 faces.
TEST(PlanarPatches, MinEdgeLengthDropsShortPatches) {
    const PointCloud cloud = box_scene();
    const std::vector<PlanarPatch> patches = detect(cloud, 1.6);
    ASSERT_EQ(patches.size(), 4u);
    for (const auto& p : patches) EXPECT_NEAR(p.box.extent.x(), 2.0, 0.02);
    EXPECT_TRUE(detect(cloud, 2.1).empty());
}

// Open3D 0.20 throws ("requires pre-computed normal vectors") without normals, an empty cloud included.
TEST(PlanarPatches, BadInputThrows) {
    using o3d::InvalidArgument;
    const PointCloud good = noisy_plane_scene();
    PointCloud no_normals = good;
    no_normals.normals.clear();
    EXPECT_THROW(detect_planar_patches(no_normals), InvalidArgument);
    EXPECT_THROW(detect_planar_patches(PointCloud{}), InvalidArgument);
    PointCloud bad_point = good;
    bad_point.points[7].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(detect_planar_patches(bad_point), InvalidArgument);
    PointCloud bad_normal = good;
    bad_normal.normals[7].x() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(detect_planar_patches(bad_normal), InvalidArgument);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (double deg : {0.0, -5.0, 90.5, nan}) {
        EXPECT_THROW(detect_planar_patches(good, deg), InvalidArgument) << deg;
        EXPECT_THROW(detect_planar_patches(good, 60, deg), InvalidArgument) << deg;
    }
    for (double ratio : {-0.1, 1.0, nan}) EXPECT_THROW(detect_planar_patches(good, 60, 75, ratio), InvalidArgument);
    for (double edge : {-1.0, std::numeric_limits<double>::infinity(), nan})
        EXPECT_THROW(detect_planar_patches(good, 60, 75, 0.75, edge), InvalidArgument);
    EXPECT_THROW(detect_planar_patches(good, 60, 75, 0.75, 0.0, 0, SearchParam::make_knn(0)), InvalidArgument);
    EXPECT_THROW(detect_planar_patches(good, 60, 75, 0.75, 0.0, 0, SearchParam::make_radius(-1.0)), InvalidArgument);
    // The limits themselves are accepted.
    EXPECT_NO_THROW(detect_planar_patches(good, 90, 90, 0.0, 0.0));
}
