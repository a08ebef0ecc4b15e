// SPDX-License-Identifier: MIT
// PoseGraph through the wrapper: nodes and edges, the shared JSON file round trip, a synthetic
// false loop closure pruned by global optimization, progress and cancellation, bad arguments.
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "test_util.hpp"

using o3dpp::Mat4;
using o3dpp::Mat6;
using o3dpp::PoseGraph;
using o3dpp::PoseGraphEdge;

namespace {
Mat4 mul(const Mat4& a, const Mat4& b) {
    Mat4 m{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) m[i * 4 + j] += a[i * 4 + k] * b[k * 4 + j];
    return m;
}
Mat4 inverse_rigid(const Mat4& m) {
    Mat4 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i * 4 + j] = m[j * 4 + i];
    for (int i = 0; i < 3; ++i) r[i * 4 + 3] = -(r[i * 4] * m[3] + r[i * 4 + 1] * m[7] + r[i * 4 + 2] * m[11]);
    r[15] = 1;
    return r;
}
// Rotation about z by `rad`, then translation t.
Mat4 pose_z(double rad, double tx, double ty, double tz) {
    const double c = std::cos(rad), s = std::sin(rad);
    return {c, -s, 0, tx, s, c, 0, ty, 0, 0, 1, tz, 0, 0, 0, 1};
}
Mat6 scaled_identity6(double s) {
    Mat6 m{};
    for (int i = 0; i < 6; ++i) m[i * 6 + i] = s;
    return m;
}
double max_abs_diff(const Mat4& a, const Mat4& b) {
    double d = 0;
    for (int i = 0; i < 16; ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
}

// Six poses along a curve, odometry between neighbours, a true loop closure 0 -> 5 and a false
// one 1 -> 4 (off by a metre); the start is the truth slightly disturbed (node 0 exact).
struct FalseLoop {
    PoseGraph graph;
    std::vector<Mat4> truth;
    FalseLoop() {
        for (int i = 0; i < 6; ++i) truth.push_back(pose_z(0.1 * i, i, 0.2 * i * i, 0.05 * i));
        for (int i = 0; i < 6; ++i) graph.add_node(mul(truth[i], pose_z(0.002 * i, 0.01 * i, -0.005 * i, 0)));
        for (int i = 0; i < 5; ++i) graph.add_edge(exact(i, i + 1, false));
        graph.add_edge(exact(0, 5, true));
        PoseGraphEdge wrong = exact(1, 4, true);
        wrong.transformation = mul(pose_z(0, 1.0, -0.5, 0.3), wrong.transformation);
        graph.add_edge(wrong);
    }
    PoseGraphEdge exact(int s, int t, bool uncertain) const {
        return PoseGraphEdge(s, t, mul(inverse_rigid(truth[t]), truth[s]), scaled_identity6(1000), uncertain);
    }
    double max_error() const {
        double e = 0;
        for (std::size_t i = 0; i < truth.size(); ++i) e = std::max(e, max_abs_diff(graph.node(i), truth[i]));
        return e;
    }
};
}  // namespace

TEST(PoseGraph, NodesAndEdges) {
    PoseGraph g;
    EXPECT_EQ(g.num_nodes(), 0u);
    const Mat4 pose = pose_z(0.3, 1, 2, 3);
    g.add_node();
    g.add_node(pose);
    EXPECT_EQ(g.node(0), o3dpp::identity4());
    EXPECT_EQ(g.node(1), pose);
    g.set_node(0, pose);
    EXPECT_EQ(g.nodes(), (std::vector<Mat4>{pose, pose}));

    PoseGraphEdge e(0, 1, pose, scaled_identity6(2), true, 0.5);
    g.add_edge(e);
    EXPECT_EQ(g.edge(0), e);
    PoseGraphEdge replaced = e;
    replaced.target_node_id = 0;
    replaced.uncertain = false;
    g.set_edge(0, replaced);
    EXPECT_EQ(g.edges(), std::vector<PoseGraphEdge>{replaced});

    PoseGraph copy = g.clone();
    g.clear();
    EXPECT_EQ(g.num_nodes() + g.num_edges(), 0u);
    EXPECT_EQ(copy.num_nodes(), 2u);
    EXPECT_EQ(copy.edge(0), replaced);
    EXPECT_EQ(PoseGraphEdge::library_default(), PoseGraphEdge());
}

TEST(PoseGraph, BadIndicesAndPoses) {
    PoseGraph g;
    g.add_node();
    EXPECT_O3D_ERROR(g.node(1), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(g.set_node(3, o3dpp::identity4()), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(g.edge(0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(g.set_edge(0, PoseGraphEdge()), O3D_ERROR_INVALID_ARGUMENT);
    Mat4 scaled = o3dpp::identity4();
    scaled[0] = 2;
    EXPECT_O3D_ERROR(g.add_node(scaled), O3D_ERROR_INVALID_ARGUMENT);
    Mat4 nan = o3dpp::identity4();
    nan[7] = NAN;
    EXPECT_O3D_ERROR(g.set_node(0, nan), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(g.num_nodes(), 1u);
    EXPECT_O3D_ERROR(PoseGraph(static_cast<o3d_pose_graph_t*>(nullptr)), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(PoseGraph, SharedJsonRoundTrip) {
    O3DPP_DATA_OR_SKIP(path, "open3d/test_pose_graph.json");
    const PoseGraph g = o3dpp::read_pose_graph(path);
    ASSERT_EQ(g.num_nodes(), 2u);
    ASSERT_EQ(g.num_edges(), 2u);
    // Column-major in the file: its first two "information" values are column 0's first two rows.
    const PoseGraphEdge first = g.edge(0);
    EXPECT_DOUBLE_EQ(first.information[0], -0.098422193060090923);
    EXPECT_DOUBLE_EQ(first.information[6], -0.29575487533188882);
    const std::string out = o3dpp_test::tmp_path("pose_graph_roundtrip.json");
    o3dpp::write_pose_graph(out, g);
    const PoseGraph back = o3dpp::read_pose_graph(out);
    EXPECT_EQ(back.nodes(), g.nodes());
    EXPECT_EQ(back.edges(), g.edges());

    EXPECT_O3D_ERROR(o3dpp::read_pose_graph(o3dpp_test::tmp_path("no_such_graph.json")), O3D_ERROR_IO);
    const std::string bad = o3dpp_test::tmp_path("bad_graph.json");
    std::ofstream(bad) << "{\"class_name\": \"PoseGraph\", \"nodes\": [";
    EXPECT_O3D_ERROR(o3dpp::read_pose_graph(bad), O3D_ERROR_PARSE);
}

TEST(PoseGraph, GlobalOptimizationPrunesTheFalseLoopClosure) {
    for (auto method : {o3dpp::GlobalOptimizationMethod::LevenbergMarquardt,
                        o3dpp::GlobalOptimizationMethod::GaussNewton}) {
        FalseLoop f;
        const double before = f.max_error();
        o3dpp::GlobalOptimizationOptions opts;
        opts.method = method;
        const auto summary = o3dpp::global_optimization(f.graph, opts);
        EXPECT_EQ(summary.pruned_edges, 1);
        EXPECT_GT(summary.iterations, 0);
        EXPECT_LT(summary.final_residual, summary.initial_residual);
        const auto edges = f.graph.edges();
        ASSERT_EQ(edges.size(), 6u);
        bool kept = false;
        for (const auto& e : edges) {
            EXPECT_FALSE(e.source_node_id == 1 && e.target_node_id == 4);
            if (e.source_node_id == 0 && e.target_node_id == 5) {
                kept = true;
                EXPECT_TRUE(e.uncertain);
                EXPECT_GT(e.confidence, 0.9);
            }
        }
        EXPECT_TRUE(kept);
        EXPECT_LT(f.max_error(), 1e-4);
        EXPECT_LT(f.max_error(), before);
    }
}

TEST(PoseGraph, ProgressCancelsAndLeavesTheGraphUnchanged) {
    FalseLoop f;
    const auto before = f.graph.nodes();
    o3dpp::GlobalOptimizationOptions opts;
    int calls = 0;
    opts.progress = [&](double) {
        ++calls;
        return false;
    };
    EXPECT_O3D_ERROR(o3dpp::global_optimization(f.graph, opts), O3D_ERROR_CANCELLED);
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(f.graph.nodes(), before);
    EXPECT_EQ(f.graph.num_edges(), 7u);
    opts.progress = [](double) -> bool { throw std::runtime_error("from optimization progress"); };
    EXPECT_THROW(o3dpp::global_optimization(f.graph, opts), std::runtime_error);
    EXPECT_EQ(f.graph.nodes(), before);
    std::vector<double> seen;
    opts.progress = [&](double x) {
        seen.push_back(x);
        return true;
    };
    o3dpp::global_optimization(f.graph, opts);
    ASSERT_FALSE(seen.empty());
    for (std::size_t i = 0; i < seen.size(); ++i) {
        EXPECT_GE(seen[i], 0.0);
        EXPECT_LE(seen[i], 1.0);
        if (i > 0) {
            EXPECT_LE(seen[i - 1], seen[i]);
        }
    }
}

TEST(PoseGraph, GlobalOptimizationRejectsBadGraphsAndOptions) {
    FalseLoop f;
    const auto before = f.graph.nodes();
    f.graph.add_edge(PoseGraphEdge(2, 9, o3dpp::identity4()));
    EXPECT_O3D_ERROR(o3dpp::global_optimization(f.graph), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(f.graph.nodes(), before);

    FalseLoop g;
    o3dpp::GlobalOptimizationOptions opts;
    opts.reference_node = 6;
    EXPECT_O3D_ERROR(o3dpp::global_optimization(g.graph, opts), O3D_ERROR_INVALID_ARGUMENT);
    opts = {};
    opts.max_correspondence_distance = NAN;
    EXPECT_O3D_ERROR(o3dpp::global_optimization(g.graph, opts), O3D_ERROR_INVALID_ARGUMENT);
    opts = {};
    opts.method = static_cast<o3dpp::GlobalOptimizationMethod>(7);
    EXPECT_O3D_ERROR(o3dpp::global_optimization(g.graph, opts), O3D_ERROR_INVALID_ARGUMENT);
    opts = {};
    opts.reference_node = 2;
    EXPECT_EQ(o3dpp::global_optimization(g.graph, opts).pruned_edges, 1);
}
