// SPDX-License-Identifier: MIT
// Point-cloud smoothing filters: Open3D 0.20 references on synthetic clouds, analytic properties
// (MLS projects onto the fitted plane, Laplacian keeps a line, Taubin shrinks less, bilateral keeps an edge),
// attributes, edge cases, thread independence and bad input.
#include "o3d/geometry/point_cloud_smoothing.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "o3d/utility/error.h"
#include "o3d/utility/random.h"

using namespace o3d::geometry;
using o3d::InvalidArgument;
using o3d::kdtree::SearchParam;

namespace {

/// o3d::utility::random::SplitMix64 (uniform: 53 bits in [0, 1)): the same generator as
/// tools/reference/record_point_cloud_smoothing.py, so both sides smooth bit-identical clouds.
using o3d::utility::random::SplitMix64;

/// z = 0.1 x + 0.05 y + uniform noise of amplitude 0.01 (the recording script's noisy_plane).
PointCloud noisy_plane(size_t n, uint64_t seed) {
    SplitMix64 g{seed};
    PointCloud c;
    for (size_t i = 0; i < n; ++i) {
        const double x = -1.0 + 2.0 * g.uniform();
        const double y = -1.0 + 2.0 * g.uniform();
        const double z = 0.1 * x + 0.05 * y + 0.02 * (g.uniform() - 0.5);
        c.points.emplace_back(x, y, z);
    }
    return c;
}

/// Radius 1 + uniform noise of amplitude 0.02; normals radial (the recording script's noisy_sphere).
PointCloud noisy_sphere(size_t n, uint64_t seed) {
    SplitMix64 g{seed};
    PointCloud c;
    while (c.points.size() < n) {
        const double x = -1.0 + 2.0 * g.uniform();
        const double y = -1.0 + 2.0 * g.uniform();
        const double z = -1.0 + 2.0 * g.uniform();
        const double r = 1.0 + 0.04 * (g.uniform() - 0.5);
        const double length = std::sqrt(x * x + y * y + z * z);  // scalar, as numpy: same bits
        if (length < 0.1) continue;
        c.points.emplace_back(x / length * r, y / length * r, z / length * r);
        c.normals.emplace_back(x / length, y / length, z / length);
    }
    return c;
}

PointCloud without_normals(PointCloud c) {
    c.normals.clear();
    return c;
}

/// What the recording script prints for one case.
struct Reference {
    double mean_displacement, max_displacement;
    Eigen::Vector3d mean_point;
    Eigen::Vector3d p0, p137, p299;
};

void expect_matches(const PointCloud& before, const PointCloud& after, const Reference& ref, double tol) {
    ASSERT_EQ(after.size(), before.size());
    double sum = 0.0, worst = 0.0;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < after.size(); ++i) {
        const double d = (after.points[i] - before.points[i]).norm();
        sum += d;
        worst = std::max(worst, d);
        mean += after.points[i];
    }
    EXPECT_NEAR(sum / static_cast<double>(after.size()), ref.mean_displacement, tol);
    EXPECT_NEAR(worst, ref.max_displacement, tol);
    EXPECT_LT((mean / static_cast<double>(after.size()) - ref.mean_point).norm(), tol);
    EXPECT_LT((after.points[0] - ref.p0).norm(), tol) << after.points[0].transpose();
    EXPECT_LT((after.points[137] - ref.p137).norm(), tol) << after.points[137].transpose();
    EXPECT_LT((after.points[299] - ref.p299).norm(), tol) << after.points[299].transpose();
}

constexpr double kTol = 1e-12;  // the outputs agree with Open3D to ~1e-15
const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();

}  // namespace

// ---- Open3D 0.20.0 references: tools/reference/record_point_cloud_smoothing.py (plane 300 points seed 7,
// ---- sphere 400 points seed 11).

TEST(SmoothMls, PlaneHybridMatchesOpen3D) {
    const PointCloud in = noisy_plane(300, 7);
    expect_matches(in, smooth_mls(in, SearchParam::make_hybrid(0.3, 30)),
                   {0.0046353310326267974, 0.01247168383569879,
                    {-0.024996906402926899, -0.013155537012756015, -0.0032337094628957994},
                    {-0.21957367373351264, -0.96606843347827176, -0.069035258147364831},
                    {0.53023519547029319, -0.48734637985514923, 0.027614430592994763},
                    {-0.024956119207476004, 0.038813192034246449, -0.0010209315889887893}},
                   kTol);
}

TEST(SmoothMls, PlaneKnnUniformWeightsMatchesOpen3D) {
    const PointCloud in = noisy_plane(300, 7);
    expect_matches(in, smooth_mls(in, SearchParam::make_knn(20)),
                   {0.0049355131936634385, 0.012223598367200428,
                    {-0.02500454793998199, -0.013156076065230407, -0.0031878424970116733},
                    {-0.21956064416304014, -0.9660400085130777, -0.06965585647204578},
                    {0.53021089031110613, -0.48735810807578156, 0.027913008454012244},
                    {-0.024862049707798834, 0.038762854683330877, -0.0011130421655287052}},
                   kTol);
}

TEST(SmoothMls, SphereRadiusMatchesOpen3DAndAddsNoNormals) {
    const PointCloud in = without_normals(noisy_sphere(400, 11));
    const PointCloud out = smooth_mls(in, SearchParam::make_radius(0.25));
    expect_matches(in, out,
                   {0.0089572211224407221, 0.032644705484767854,
                    {0.010968893935114989, -0.0095432488363087452, -0.020002486851827362},
                    {-0.54975265741259272, -0.71221051357049636, 0.41307972618525068},
                    {-0.61190992055708238, 0.66828784773428707, -0.44012779078371017},
                    {-0.87802901580023751, -0.24613275753946143, 0.38979701111847398}},
                   kTol);
    EXPECT_FALSE(out.has_normals());
}

TEST(SmoothMls, SphereWithNormalsMatchesOpen3DIncludingOrientedNormals) {
    const PointCloud in = noisy_sphere(400, 11);
    const PointCloud out = smooth_mls(in, SearchParam::make_hybrid(0.3, 30));
    expect_matches(in, out,
                   {0.013624993689642215, 0.03921319953556094,
                    {0.011175715338091365, -0.0096538075764917644, -0.019865445533453187},
                    {-0.54775618871307175, -0.70923536103278839, 0.41125590289971808},
                    {-0.59623502953369811, 0.65192065839718061, -0.42803221879495096},
                    {-0.86860695885668049, -0.24379077931115992, 0.38537241748544926}},
                   kTol);
    ASSERT_TRUE(out.has_normals());
    // Open3D orients the PCA normals consistently (lowest point faces -z): outward on a sphere.
    EXPECT_LT((out.normals[0] - Eigen::Vector3d(-0.57576486882609379, -0.68330529182043309, 0.44898629600007156))
                  .norm(), kTol);
    EXPECT_LT((out.normals[137] - Eigen::Vector3d(-0.57941544232571041, 0.66529673527301147, -0.47080569158579016))
                  .norm(), kTol);
    EXPECT_LT((out.normals[299] - Eigen::Vector3d(-0.86073802138404976, -0.2910093684772872, 0.41766446581235717))
                  .norm(), kTol);
    for (size_t i = 0; i < out.size(); ++i) {
        EXPECT_NEAR(out.normals[i].norm(), 1.0, 1e-12);
        EXPECT_GT(out.normals[i].dot(out.points[i]), 0.0) << "normal " << i << " faces inward";
    }
}

TEST(SmoothLaplacian, SphereMatchesOpen3D) {
    const PointCloud in = without_normals(noisy_sphere(400, 11));
    expect_matches(in, smooth_laplacian(in, 10, 0.5, 20, false),
                   {0.30927134301013731, 0.76930328249911073,
                    {0.0029301079004097276, 0.005755185191955536, -0.028407403659841735},
                    {-0.62095528990628091, -0.39862401418972548, 0.5423850356834109},
                    {-0.29115851913666829, 0.59611879706394266, -0.68714287051636713},
                    {-0.66792752796200383, -0.2519672881239568, 0.60358289832557344}},
                   kTol);
}

TEST(SmoothLaplacian, SphereFixedNeighbourhoodsMatchesOpen3D) {
    const PointCloud in = without_normals(noisy_sphere(400, 11));
    expect_matches(in, smooth_laplacian(in, 10, 0.5, 20, true),
                   {0.23144265255873037, 0.47362925649638066,
                    {0.010716583845688325, -0.0087221326434941421, -0.024258075791751169},
                    {-0.55196393617228479, -0.5157575728877235, 0.39654498100369429},
                    {-0.41377095757720533, 0.49444885242524916, -0.50708568755865002},
                    {-0.62675251408176935, -0.29269309011156813, 0.49048279125136884}},
                   kTol);
}

TEST(SmoothTaubin, SphereMatchesOpen3D) {
    const PointCloud in = without_normals(noisy_sphere(400, 11));
    expect_matches(in, smooth_taubin(in, 10, 0.5, -0.53, 20, false),
                   {0.071138074279463573, 0.29771503645994585,
                    {0.01108357171028055, -0.0075253939413671631, -0.01684917220292911},
                    {-0.54555860186737726, -0.72556760609727611, 0.42005754424986974},
                    {-0.66084066435597233, 0.61354808981420228, -0.40685414153189553},
                    {-0.85083518083153864, -0.23784334071735377, 0.46455945557106565}},
                   kTol);
}

TEST(SmoothTaubin, SphereFixedNeighbourhoodsMatchesOpen3D) {
    const PointCloud in = without_normals(noisy_sphere(400, 11));
    expect_matches(in, smooth_taubin(in, 10, 0.5, -0.53, 20, true),
                   {0.072624959820207363, 0.234867076130202,
                    {0.011654746689891778, -0.010511041230854078, -0.019874460547346397},
                    {-0.57396524565524032, -0.67699097484853343, 0.46928800238223728},
                    {-0.5689217462601871, 0.59504860742135868, -0.54061679873281754},
                    {-0.80354997589780197, -0.27560475866156742, 0.52463758070884214}},
                   kTol);
}

TEST(SmoothBilateral, SphereWithNormalsMatchesOpen3D) {
    const PointCloud in = noisy_sphere(400, 11);
    const PointCloud out = smooth_bilateral(in, SearchParam::make_hybrid(0.3, 30), 0.1, 0.02);
    expect_matches(in, out,
                   {0.028894914303940613, 0.090847496092177266,
                    {0.011038421521099972, -0.00977756886178845, -0.020179007139974881},
                    {-0.57544117081120216, -0.70207883331746646, 0.40011870681007244},
                    {-0.61357306813673029, 0.68492667121222484, -0.41657310321069163},
                    {-0.88666703334262598, -0.21728579170276971, 0.3805047159994957}},
                   kTol);
    EXPECT_EQ(out.normals, in.normals);  // the input's normals are used and kept
}

TEST(SmoothBilateral, PlaneWithoutNormalsEstimatesKnn30NormalsLikeOpen3D) {
    const PointCloud in = noisy_plane(300, 7);
    const PointCloud out = smooth_bilateral(in, SearchParam::make_knn(15), 0.2, 0.01);
    expect_matches(in, out,
                   {0.044898446383933158, 0.18980108992127481,
                    {-0.026494904868124936, -0.013812458595605795, -0.0034147797169923038},
                    {-0.21920978989109435, -0.86936998160633472, -0.061984629159322846},
                    {0.56613189841636924, -0.51156015639951757, 0.029653743056919025},
                    {-0.036155817733783104, 0.0096269656749001977, -0.00031624068662595734}},
                   kTol);
    // The estimated normals stay on the output; their signs are arbitrary (in Open3D too), so compare |dot|.
    ASSERT_TRUE(out.has_normals());
    EXPECT_NEAR(std::abs(out.normals[0].dot(Eigen::Vector3d(0.10462138058350898, 0.054460361999746257,
                                                            -0.99301985664721593))), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(out.normals[137].dot(Eigen::Vector3d(-0.099206704056881936, -0.055965642605898452,
                                                              0.99349175976345117))), 1.0, 1e-12);
    EXPECT_NEAR(std::abs(out.normals[299].dot(Eigen::Vector3d(-0.088667881515468394, -0.056952655058157456,
                                                              0.99443169794078135))), 1.0, 1e-12);
}

// ---- Analytic properties.

TEST(SmoothMls, AllPointsNeighbourhoodProjectsOntoTheLeastSquaresPlane) {
    // With knn = N every neighbourhood is the whole cloud with uniform weights: one global PCA plane.
    const PointCloud in = noisy_plane(300, 7);
    const PointCloud out = smooth_mls(in, SearchParam::make_knn(300));
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (const auto& p : in.points) centroid += p;
    centroid /= 300.0;
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (const auto& p : in.points) scatter += (p - centroid) * (p - centroid).transpose();
    const Eigen::Vector3d normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(scatter).eigenvectors().col(0);
    double worst_before = 0.0, worst_after = 0.0;
    for (size_t i = 0; i < in.size(); ++i) {
        worst_before = std::max(worst_before, std::abs((in.points[i] - centroid).dot(normal)));
        worst_after = std::max(worst_after, std::abs((out.points[i] - centroid).dot(normal)));
        // Projection moves a point along the normal only.
        const Eigen::Vector3d moved = out.points[i] - in.points[i];
        EXPECT_LT((moved - moved.dot(normal) * normal).norm(), 1e-12);
    }
    EXPECT_GT(worst_before, 0.009);  // the noise (amplitude 0.01) is there ...
    EXPECT_LT(worst_after, 1e-12);   // ... and gone
}

TEST(SmoothMls, LocalPlanesReduceTheNoise) {
    const PointCloud in = noisy_plane(300, 7);
    const PointCloud out = smooth_mls(in, SearchParam::make_hybrid(0.3, 30));
    const Eigen::Vector3d normal = Eigen::Vector3d(-0.1, -0.05, 1.0).normalized();  // the true plane
    double before = 0.0, after = 0.0;
    for (size_t i = 0; i < in.size(); ++i) {
        before += std::pow(in.points[i].dot(normal), 2);
        after += std::pow(out.points[i].dot(normal), 2);
    }
    EXPECT_LT(after, 0.2 * before);  // RMS distance to the true plane at least halved
}

TEST(SmoothLaplacian, PointsOnALineStayOnTheLine) {
    const Eigen::Vector3d origin(1.0, -2.0, 0.5), dir = Eigen::Vector3d(0.3, 0.4, -0.2).normalized();
    SplitMix64 g{3};
    PointCloud in;
    for (int i = 0; i < 200; ++i) in.points.push_back(origin + (g.uniform() * 4.0 - 2.0) * dir);
    for (const bool fixed : {false, true}) {
        const PointCloud out = smooth_laplacian(in, 10, 0.5, 8, fixed);
        double moved = 0.0;
        for (size_t i = 0; i < out.size(); ++i) {
            const Eigen::Vector3d d = out.points[i] - origin;
            EXPECT_LT((d - d.dot(dir) * dir).norm(), 1e-12) << "point " << i;
            moved = std::max(moved, (out.points[i] - in.points[i]).norm());
        }
        EXPECT_GT(moved, 0.01);  // the points did move along the line
    }
}

double mean_radius(const PointCloud& c) {
    double sum = 0.0;
    for (const auto& p : c.points) sum += p.norm();
    return sum / static_cast<double>(c.size());
}

TEST(SmoothTaubin, ShrinksASphereLessThanLaplacian) {
    const PointCloud in = without_normals(noisy_sphere(400, 11));
    const double r0 = mean_radius(in);
    const double laplacian_loss = r0 - mean_radius(smooth_laplacian(in, 10, 0.5, 20, false));
    const double taubin_loss = r0 - mean_radius(smooth_taubin(in, 10, 0.5, -0.53, 20, false));
    // Open3D 0.20 on this cloud: 0.0784 (Laplacian) and 0.00137 (Taubin).
    EXPECT_GT(laplacian_loss, 0.05);
    EXPECT_LT(std::abs(taubin_loss), 0.05 * laplacian_loss);
}

TEST(SmoothBilateral, KeepsASharpEdgeBetterThanLaplacian) {
    // A roof z = |x| (a 90-degree crease along the y axis) with exact face normals, noise-free.
    SplitMix64 g{5};
    PointCloud in;
    for (int i = 0; i < 500; ++i) {
        const double x = -1.0 + 2.0 * g.uniform(), y = -1.0 + 2.0 * g.uniform();
        in.points.emplace_back(x, y, std::abs(x));
        in.normals.push_back(Eigen::Vector3d(x < 0 ? 1.0 : -1.0, 0.0, 1.0).normalized());
    }
    const PointCloud bilateral = smooth_bilateral(in, SearchParam::make_hybrid(0.15, 30), 0.1, 0.01);
    const PointCloud laplacian = smooth_laplacian(in, 1, 0.5, 20, false);
    auto crease_error = [](const PointCloud& c) {  // mean height off the roof near the crease
        double sum = 0.0;
        int count = 0;
        for (const auto& p : c.points)
            if (std::abs(p.x()) < 0.15 && std::abs(p.y()) < 0.8) sum += std::abs(p.z() - std::abs(p.x())), ++count;
        return sum / count;
    };
    const double e_bilateral = crease_error(bilateral), e_laplacian = crease_error(laplacian);
    EXPECT_GT(e_laplacian, 0.01);
    EXPECT_LT(e_bilateral, 0.1 * e_laplacian) << e_bilateral << " vs " << e_laplacian;
}

// ---- Attributes, edge cases, threads.

TEST(PointCloudSmoothing, AttributesAreKeptAsOpen3DKeepsThem) {
    PointCloud in = noisy_sphere(400, 11);
    in.colors.assign(in.size(), Eigen::Vector3d(0.1, 0.2, 0.3));
    in.covariances.assign(in.size(), Eigen::Matrix3d::Identity() * 2.0);
    for (const PointCloud& out : {smooth_laplacian(in, 2, 0.5, 10, false), smooth_taubin(in, 2, 0.5, -0.53, 10, true),
                                  smooth_bilateral(in, SearchParam::make_hybrid(0.3, 30), 0.1, 0.02)}) {
        EXPECT_EQ(out.normals, in.normals);  // not recomputed
        EXPECT_EQ(out.colors, in.colors);
        EXPECT_EQ(out.covariances, in.covariances);
    }
    const PointCloud mls = smooth_mls(in, SearchParam::make_hybrid(0.3, 30));
    EXPECT_EQ(mls.colors, in.colors);
    EXPECT_EQ(mls.covariances, in.covariances);  // stale, as Open3D
    EXPECT_NE(mls.normals, in.normals);          // the PCA normals
    // Normals that do not match the points do not count: MLS drops them.
    in.normals.pop_back();
    EXPECT_TRUE(smooth_mls(in, SearchParam::make_knn(10)).normals.empty());
}

TEST(PointCloudSmoothing, EmptyCloudGivesEmptyCloud) {
    const PointCloud empty;
    EXPECT_TRUE(smooth_mls(empty, SearchParam::make_knn(5)).points.empty());
    EXPECT_TRUE(smooth_laplacian(empty, 10, 0.5, 20, false).points.empty());
    EXPECT_TRUE(smooth_taubin(empty, 10, 0.5, -0.53, 20, true).points.empty());
    const PointCloud b = smooth_bilateral(empty, SearchParam::make_hybrid(0.05, 30), 0.05, 0.05);
    EXPECT_TRUE(b.points.empty());
    EXPECT_TRUE(b.normals.empty());
}

TEST(PointCloudSmoothing, ZeroIterationsAndTinyCloudsAreCopies) {
    const PointCloud in = without_normals(noisy_sphere(50, 2));
    EXPECT_EQ(smooth_laplacian(in, 0, 0.5, 10, false).points, in.points);
    EXPECT_EQ(smooth_taubin(in, 0, 0.5, -0.53, 10, true).points, in.points);
    PointCloud one;
    one.points.emplace_back(1.0, 2.0, 3.0);
    EXPECT_EQ(smooth_laplacian(one, 3, 0.5, 5, false).points, one.points);
    EXPECT_EQ(smooth_mls(one, SearchParam::make_knn(5)).points, one.points);  // < 3 neighbours
    EXPECT_EQ(smooth_bilateral(one, SearchParam::make_knn(5), 1.0, 1.0).points, one.points);
    // Two points, knn 3 (> N - 1): each moves half-way to the other (Open3D: both at 0.5).
    PointCloud two;
    two.points = {{0, 0, 0}, {1, 0, 0}};
    const PointCloud mid = smooth_laplacian(two, 1, 0.5, 3, false);
    EXPECT_EQ(mid.points[0], Eigen::Vector3d(0.5, 0, 0));
    EXPECT_EQ(mid.points[1], Eigen::Vector3d(0.5, 0, 0));
}

TEST(SmoothLaplacian, KnnBeyondTheCloudUsesAllOtherPoints) {
    const PointCloud in = without_normals(noisy_sphere(7, 4));
    Eigen::Vector3d total = Eigen::Vector3d::Zero();
    for (const auto& p : in.points) total += p;
    const PointCloud out = smooth_laplacian(in, 1, 0.3, 1000, false);
    for (size_t i = 0; i < in.size(); ++i) {
        const Eigen::Vector3d others = (total - in.points[i]) / 6.0;
        EXPECT_LT((out.points[i] - (in.points[i] + 0.3 * (others - in.points[i]))).norm(), 1e-14);
    }
}

TEST(SmoothLaplacian, OneIterationIsTheSameWithAndWithoutFixedNeighbourhoods) {
    const PointCloud in = without_normals(noisy_sphere(400, 11));
    EXPECT_EQ(smooth_laplacian(in, 1, 0.5, 20, true).points, smooth_laplacian(in, 1, 0.5, 20, false).points);
}

TEST(PointCloudSmoothing, ResultDoesNotDependOnThreadCount) {
    PointCloud in = noisy_sphere(400, 11);
    const auto hybrid = SearchParam::make_hybrid(0.3, 30);
    EXPECT_EQ(smooth_mls(in, hybrid, 1).points, smooth_mls(in, hybrid, 4).points);
    EXPECT_EQ(smooth_mls(in, hybrid, 1).normals, smooth_mls(in, hybrid, 4).normals);
    EXPECT_EQ(smooth_laplacian(in, 3, 0.5, 20, false, 1).points, smooth_laplacian(in, 3, 0.5, 20, false, 4).points);
    EXPECT_EQ(smooth_taubin(in, 3, 0.5, -0.53, 20, true, 1).points,
              smooth_taubin(in, 3, 0.5, -0.53, 20, true, 3).points);
    EXPECT_EQ(smooth_bilateral(in, hybrid, 0.1, 0.02, 1).points, smooth_bilateral(in, hybrid, 0.1, 0.02, 4).points);
    in.normals.clear();
    const PointCloud b1 = smooth_bilateral(in, hybrid, 0.1, 0.02, 1), b4 = smooth_bilateral(in, hybrid, 0.1, 0.02, 4);
    EXPECT_EQ(b1.points, b4.points);
    EXPECT_EQ(b1.normals, b4.normals);
}

TEST(PointCloudSmoothing, BadInputThrows) {
    const PointCloud in = noisy_sphere(20, 1);
    PointCloud nan_point = in;
    nan_point.points[3].y() = kNaN;
    const auto knn = SearchParam::make_knn(5);
    EXPECT_THROW(smooth_mls(nan_point, knn), InvalidArgument);
    EXPECT_THROW(smooth_laplacian(nan_point, 1, 0.5, 5, false), InvalidArgument);
    EXPECT_THROW(smooth_taubin(nan_point, 1, 0.5, -0.53, 5, true), InvalidArgument);
    EXPECT_THROW(smooth_bilateral(nan_point, knn, 1.0, 1.0), InvalidArgument);

    for (const SearchParam& bad : {SearchParam::make_knn(0), SearchParam::make_radius(0.0),
                                   SearchParam::make_radius(kNaN), SearchParam::make_hybrid(0.1, 0),
                                   SearchParam::make_hybrid(-1.0, 5)}) {
        EXPECT_THROW(smooth_mls(in, bad), InvalidArgument);
        EXPECT_THROW(smooth_bilateral(in, bad, 1.0, 1.0), InvalidArgument);
        EXPECT_THROW(smooth_mls(PointCloud{}, bad), InvalidArgument);  // validated even when empty
    }

    EXPECT_THROW(smooth_laplacian(in, -1, 0.5, 5, false), InvalidArgument);
    EXPECT_THROW(smooth_laplacian(in, 1, 0.5, 0, false), InvalidArgument);
    EXPECT_THROW(smooth_laplacian(in, 1, 0.5, -3, true), InvalidArgument);
    EXPECT_THROW(smooth_laplacian(in, 1, kNaN, 5, false), InvalidArgument);
    EXPECT_THROW(smooth_laplacian(in, 1, kInf, 5, false), InvalidArgument);
    EXPECT_THROW(smooth_taubin(in, -2, 0.5, -0.53, 5, false), InvalidArgument);
    EXPECT_THROW(smooth_taubin(in, 1, 0.5, 0.5, 0, false), InvalidArgument);
    EXPECT_THROW(smooth_taubin(in, 1, 0.5, kNaN, 5, false), InvalidArgument);
    EXPECT_THROW(smooth_taubin(in, 1, -kInf, -0.53, 5, false), InvalidArgument);
    EXPECT_THROW(smooth_laplacian(PointCloud{}, -1, 0.5, 5, false), InvalidArgument);

    for (const double sigma : {0.0, -1.0, kNaN, kInf}) {
        EXPECT_THROW(smooth_bilateral(in, knn, sigma, 1.0), InvalidArgument);
        EXPECT_THROW(smooth_bilateral(in, knn, 1.0, sigma), InvalidArgument);
    }
    PointCloud nan_normal = in;
    nan_normal.normals[2].x() = kNaN;
    EXPECT_THROW(smooth_bilateral(nan_normal, knn, 1.0, 1.0), InvalidArgument);
}

TEST(SmoothBilateral, TinySigmasKeepPointsInsteadOfNaN) {
    // 1 / (2 sigma^2) overflows to inf; the point's own weight must stay exp(0) = 1, not 0 * inf.
    const PointCloud in = noisy_sphere(50, 6);
    const PointCloud out = smooth_bilateral(in, SearchParam::make_knn(10), 1e-200, 1e-200);
    EXPECT_EQ(out.points, in.points);
}
