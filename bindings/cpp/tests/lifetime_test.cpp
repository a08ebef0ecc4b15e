// SPDX-License-Identifier: MIT
// Move-only handles: moves transfer ownership, release() hands it out, destroy order is free.
#include <memory>
#include <type_traits>

#include "test_util.hpp"

using o3dpp::Vec3;

static_assert(!std::is_copy_constructible_v<o3dpp::PointCloud>);
static_assert(!std::is_copy_assignable_v<o3dpp::PointCloud>);
static_assert(std::is_nothrow_move_constructible_v<o3dpp::PointCloud>);
static_assert(std::is_nothrow_move_assignable_v<o3dpp::PointCloud>);
static_assert(!std::is_copy_constructible_v<o3dpp::KDTreeFlann>);
static_assert(std::is_nothrow_move_constructible_v<o3dpp::KDTreeFlann>);
static_assert(!std::is_copy_constructible_v<o3dpp::SearchResult>);
static_assert(std::is_nothrow_move_constructible_v<o3dpp::SearchResult>);
static_assert(!std::is_copy_constructible_v<o3dpp::RegistrationResult>);
static_assert(std::is_nothrow_move_constructible_v<o3dpp::RegistrationResult>);
static_assert(!std::is_copy_constructible_v<o3dpp::Buffer>);
static_assert(std::is_nothrow_move_assignable_v<o3dpp::Buffer>);

TEST(Lifetime, MoveTransfersTheHandle) {
    o3dpp::PointCloud a(std::vector<Vec3>{{1, 2, 3}});
    o3d_pointcloud_t* h = a.get();
    o3dpp::PointCloud b(std::move(a));
    EXPECT_EQ(b.get(), h);
    EXPECT_EQ(a.get(), nullptr);  // NOLINT(bugprone-use-after-move): moved-from state is specified
    EXPECT_FALSE(static_cast<bool>(a));
    EXPECT_EQ(b.size(), 1u);
    // A call on the moved-from object reaches the C API with NULL and throws, it does not crash.
    EXPECT_O3D_ERROR(a.size(), O3D_ERROR_INVALID_ARGUMENT);

    o3dpp::PointCloud c(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}});
    c = std::move(b);  // c's old cloud is destroyed, b's is taken over
    EXPECT_EQ(c.get(), h);
    EXPECT_EQ(c.size(), 1u);
    auto& alias = c;
    c = std::move(alias);  // self-move keeps the handle
    EXPECT_EQ(c.get(), h);
}

TEST(Lifetime, ReleaseHandsOwnershipToTheCaller) {
    o3dpp::PointCloud a(std::vector<Vec3>{{1, 2, 3}});
    o3d_pointcloud_t* raw = a.release();
    EXPECT_EQ(a.get(), nullptr);
    size_t n = 0;
    ASSERT_EQ(o3d_pointcloud_size(&n, raw), O3D_OK);
    EXPECT_EQ(n, 1u);
    o3dpp::PointCloud again(raw);  // adopt it back; destroyed once at scope end
    EXPECT_EQ(again.size(), 1u);
    EXPECT_O3D_ERROR(o3dpp::PointCloud(static_cast<o3d_pointcloud_t*>(nullptr)), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Lifetime, TreeAndResultOutliveTheirSources) {
    std::unique_ptr<o3dpp::SearchResult> result;
    {
        std::unique_ptr<o3dpp::KDTreeFlann> tree;
        {
            o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {5, 0, 0}});
            tree = std::make_unique<o3dpp::KDTreeFlann>(pc);
            pc.clear();  // the tree copied the points
        }  // cloud destroyed first
        result = std::make_unique<o3dpp::SearchResult>(tree->search_knn({{4.5, 0, 0}}, 2));
        EXPECT_EQ(tree->size(), 3u);
    }  // tree destroyed before the result
    EXPECT_EQ(result->get_indices(), (std::vector<int32_t>{2, 1}));
}

TEST(Lifetime, MovedResultsAndBuffersStayValid) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
    auto r1 = o3dpp::evaluate_registration(pc, pc, 0.1);
    o3dpp::RegistrationResult r2 = std::move(r1);
    EXPECT_EQ(r1.get(), nullptr);  // NOLINT(bugprone-use-after-move)
    EXPECT_DOUBLE_EQ(r2.fitness(), 1.0);
    auto b1 = o3dpp::write_point_cloud_to_memory(pc, "xyz");
    const auto bytes = b1.to_vector();
    o3dpp::Buffer b2;
    b2 = std::move(b1);
    EXPECT_FALSE(static_cast<bool>(b1));  // NOLINT(bugprone-use-after-move)
    EXPECT_EQ(b2.to_vector(), bytes);
}

TEST(Lifetime, HandlesInAVectorSurviveReallocation) {
    std::vector<o3dpp::PointCloud> clouds;
    std::vector<o3d_pointcloud_t*> handles;
    for (int i = 0; i < 20; ++i) {
        clouds.emplace_back(std::vector<Vec3>(static_cast<size_t>(i + 1), Vec3{double(i), 0, 0}));
        handles.push_back(clouds.back().get());
    }
    for (int i = 0; i < 20; ++i) {
        EXPECT_EQ(clouds[i].get(), handles[i]);
        EXPECT_EQ(clouds[i].size(), static_cast<size_t>(i + 1));
    }
}
