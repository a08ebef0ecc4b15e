// SPDX-License-Identifier: MIT
// Global optimization on synthetic graphs with a known answer: false loop closures pruned and the poses
// recovered, a consistent graph left alone, the reference node kept, both methods, thread-count
// independence, progress and cancellation, and every invalid input rejected with the graph unchanged.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

#include "o3d/registration/global_optimization.h"
#include "o3d/utility/error.h"

namespace reg = o3d::registration;
using Method = reg::GlobalOptimizationMethod;

namespace {

constexpr Method kMethods[] = {Method::GaussNewton, Method::LevenbergMarquardt};

Eigen::Matrix4d rigid(const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = r;
    m.topRightCorner<3, 1>() = t;
    return m;
}

Eigen::Matrix4d rigid_inverse(const Eigen::Matrix4d& m) {
    const Eigen::Matrix3d r = m.topLeftCorner<3, 3>().transpose();
    return rigid(r, -r * m.topRightCorner<3, 1>());
}

/// A reproducible value in [-1, 1] (splitmix64), the same on every platform.
double unit(uint64_t& state) {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) / static_cast<double>(1ull << 52) - 1.0;
}

Eigen::Matrix4d perturbation(double amplitude, uint64_t& state) {
    const Eigen::Vector3d w(unit(state), unit(state), unit(state));
    const Eigen::Vector3d t(unit(state), unit(state), unit(state));
    return rigid(Eigen::AngleAxisd(amplitude * w.norm(), w.normalized()).toRotationMatrix(), amplitude * t);
}

/// Open3D's information matrix for point pairs at `count` points of a small block: Lambda(5, 5) = count.
reg::Matrix6d information(int count) {
    reg::Matrix6d info = reg::Matrix6d::Zero();
    for (int k = 0; k < count; ++k) {
        const double x = 0.4 * (k % 5) - 0.8, y = 0.4 * ((k / 5) % 5) - 0.8, z = 0.3 * (k / 25) - 0.15;
        Eigen::Matrix<double, 6, 3> g;
        g << 0, -z, y, z, 0, -x, -y, x, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
        info += g * g.transpose();
    }
    return info;
}

struct Synthetic {
    reg::PoseGraph graph;
    std::vector<Eigen::Matrix4d> truth;
    std::vector<size_t> false_edges;  // indices of the false loop closures
};

/// n poses on a rising helix; odometry i -> i + 1 (certain), true loop closures i + 4 -> i for even i
/// (uncertain), `false_closures` wrong ones (i + 6 -> i + 1, off by 0.6 rad and ~0.6 m), every measurement
/// perturbed by `noise` (radians / metres). Nodes start from the chained odometry, or, with `start_noise`
/// > 0, at the truth moved by that much; node 0 starts at the truth.
Synthetic helix(int n, double noise, int false_closures, double start_noise = 0.0) {
    Synthetic s;
    for (int i = 0; i < n; ++i)
        s.truth.push_back(rigid((Eigen::AngleAxisd(0.45 * i, Eigen::Vector3d::UnitZ()) *
                                 Eigen::AngleAxisd(0.05 * std::sin(i), Eigen::Vector3d::UnitX()))
                                    .toRotationMatrix(),
                                {3.0 * std::cos(0.45 * i), 3.0 * std::sin(0.45 * i), 0.08 * i}));
    const reg::Matrix6d info = information(50);
    uint64_t state = 42;
    const auto add = [&](int source, int target, bool uncertain, const Eigen::Matrix4d& error) {
        const Eigen::Matrix4d relative =
            rigid_inverse(s.truth[static_cast<size_t>(target)]) * s.truth[static_cast<size_t>(source)];
        s.graph.edges.push_back({source, target, error * perturbation(noise, state) * relative, info, uncertain, 1.0});
    };
    for (int i = 0; i + 1 < n; ++i) add(i, i + 1, false, Eigen::Matrix4d::Identity());
    for (int i = 0; i + 4 < n; i += 2) add(i + 4, i, true, Eigen::Matrix4d::Identity());
    const Eigen::Matrix4d wrong =
        rigid(Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix(), {0.5, -0.3, 0.2});
    for (int f = 0; f < false_closures; ++f) {
        const int i = (3 * f + 1) % (n - 6);
        s.false_edges.push_back(s.graph.edges.size());
        add(i + 6, i + 1, true, wrong);
    }
    Eigen::Matrix4d pose = s.truth[0];
    s.graph.nodes.push_back({pose});
    for (int i = 0; i + 1 < n; ++i) {
        pose = start_noise > 0.0 ? s.truth[static_cast<size_t>(i + 1)] * perturbation(start_noise, state)
                                 : pose * rigid_inverse(s.graph.edges[static_cast<size_t>(i)].transformation);
        s.graph.nodes.push_back({pose});
    }
    return s;
}

reg::GlobalOptimizationOptions with(Method method, int reference_node = -1, int threads = 0) {
    reg::GlobalOptimizationOptions options;
    options.method = method;
    options.option.reference_node = reference_node;
    options.num_threads = threads;
    return options;
}

double max_translation_error(const reg::PoseGraph& g, const std::vector<Eigen::Matrix4d>& truth) {
    double worst = 0.0;
    for (size_t i = 0; i < truth.size(); ++i)
        worst = std::max(worst, (g.nodes[i].pose.topRightCorner<3, 1>() - truth[i].topRightCorner<3, 1>()).norm());
    return worst;
}

double max_rotation_error(const reg::PoseGraph& g, const std::vector<Eigen::Matrix4d>& truth) {
    double worst = 0.0;
    for (size_t i = 0; i < truth.size(); ++i) {
        const Eigen::Matrix3d d = g.nodes[i].pose.topLeftCorner<3, 3>().transpose() * truth[i].topLeftCorner<3, 3>();
        worst = std::max(worst, Eigen::AngleAxisd(d).angle());
    }
    return worst;
}

template <typename T>
bool same_bits(const T& a, const T& b) {
    return std::memcmp(&a, &b, sizeof(T)) == 0;
}

/// Bitwise equality of everything a graph holds (NaN included).
void expect_identical(const reg::PoseGraph& a, const reg::PoseGraph& b) {
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (size_t i = 0; i < a.nodes.size(); ++i)
        EXPECT_TRUE(same_bits(a.nodes[i].pose, b.nodes[i].pose)) << "node " << i;
    for (size_t k = 0; k < a.edges.size(); ++k) {
        const reg::PoseGraphEdge &x = a.edges[k], &y = b.edges[k];
        EXPECT_EQ(x.source_node_id, y.source_node_id) << "edge " << k;
        EXPECT_EQ(x.target_node_id, y.target_node_id) << "edge " << k;
        EXPECT_TRUE(same_bits(x.transformation, y.transformation)) << "edge " << k;
        EXPECT_TRUE(same_bits(x.information, y.information)) << "edge " << k;
        EXPECT_EQ(x.uncertain, y.uncertain) << "edge " << k;
        EXPECT_TRUE(same_bits(x.confidence, y.confidence)) << "edge " << k;
    }
}

/// The poses in node 0's frame: what does not depend on where the whole graph sits.
double max_relative_difference(const reg::PoseGraph& a, const reg::PoseGraph& b) {
    const Eigen::Matrix4d a0 = rigid_inverse(a.nodes[0].pose), b0 = rigid_inverse(b.nodes[0].pose);
    double worst = 0.0;
    for (size_t i = 0; i < a.nodes.size(); ++i)
        worst = std::max(worst, (a0 * a.nodes[i].pose - b0 * b.nodes[i].pose).cwiseAbs().maxCoeff());
    return worst;
}

}  // namespace

/// The edges left are `original` without `removed`, in order; true closures keep a confidence above `floor`.
void expect_pruned_exactly(const reg::PoseGraph& g, const Synthetic& s, double floor) {
    ASSERT_EQ(g.edges.size(), s.graph.edges.size() - s.false_edges.size());
    size_t k = 0;
    for (size_t i = 0; i < s.graph.edges.size(); ++i) {
        if (std::find(s.false_edges.begin(), s.false_edges.end(), i) != s.false_edges.end()) continue;
        EXPECT_EQ(g.edges[k].source_node_id, s.graph.edges[i].source_node_id) << i;
        EXPECT_EQ(g.edges[k].target_node_id, s.graph.edges[i].target_node_id) << i;
        if (g.edges[k].uncertain)
            EXPECT_GT(g.edges[k].confidence, floor) << "true closure " << i;
        else
            EXPECT_EQ(g.edges[k].confidence, 1.0) << i;
        ++k;
    }
}

// Exact measurements but two false closures, poses started 5 cm / 0.05 rad off: the false closures go,
// and what the true edges then say is the truth itself.
TEST(GlobalOptimization, FalseLoopClosuresArePrunedAndPosesRecovered) {
    for (Method method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        const Synthetic s = helix(16, 0.0, 2, 0.05);
        reg::PoseGraph g = s.graph;
        EXPECT_GT(max_translation_error(g, s.truth), 0.05);
        const auto summary = reg::global_optimization(g, with(method));
        EXPECT_EQ(summary.pruned_edges, 2);
        expect_pruned_exactly(g, s, 1.0 - 1e-6);
        EXPECT_LT(max_translation_error(g, s.truth), 1e-6);
        EXPECT_LT(max_rotation_error(g, s.truth), 1e-6);
        EXPECT_EQ(g.nodes[0].pose, s.truth[0]);  // the reference node
        EXPECT_LT(summary.final_residual, 1e-9 * summary.initial_residual);
    }
}

// Noisy measurements (1 cm / 0.01 rad per axis), poses chained from the odometry: the false closures go,
// the true ones stay, and the loop closures take out most of the odometry's drift.
TEST(GlobalOptimization, NoisyGraphLosesItsFalseClosuresAndMostOfItsDrift) {
    for (Method method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        const Synthetic s = helix(16, 0.01, 2);
        reg::PoseGraph g = s.graph;
        const double drift = max_translation_error(g, s.truth);
        EXPECT_GT(drift, 0.15);
        const auto summary = reg::global_optimization(g, with(method));
        EXPECT_EQ(summary.pruned_edges, 2);
        expect_pruned_exactly(g, s, 0.5);
        EXPECT_LT(max_translation_error(g, s.truth), 0.5 * drift);
        EXPECT_LT(max_rotation_error(g, s.truth), 0.03);
        EXPECT_LT(summary.final_residual, summary.initial_residual);
    }
}

TEST(GlobalOptimization, WithoutTheLineProcessAFalseClosureWouldBend) {
    // The same graph with the false closure marked certain: it cannot be pruned and drags the poses away
    // (and, with them, true closures below the threshold), which is what the line process prevents.
    Synthetic s = helix(16, 0.0, 1, 0.05);
    s.graph.edges[s.false_edges[0]].uncertain = false;
    reg::PoseGraph g = s.graph;
    reg::global_optimization(g, with(Method::LevenbergMarquardt));
    EXPECT_GT(max_translation_error(g, s.truth), 0.1);
}

TEST(GlobalOptimization, ConsistentGraphStaysPut) {
    for (Method method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        Synthetic s = helix(10, 0.0, 0);
        for (size_t i = 0; i < s.truth.size(); ++i) s.graph.nodes[i].pose = s.truth[i];
        reg::PoseGraph g = s.graph;
        const auto summary = reg::global_optimization(g, with(method));
        EXPECT_EQ(summary.iterations, 0);
        EXPECT_EQ(summary.pruned_edges, 0);
        EXPECT_LT(summary.initial_residual, 1e-20);
        for (size_t i = 0; i < g.nodes.size(); ++i) EXPECT_EQ(g.nodes[i].pose, s.truth[i]) << i;
        for (const auto& e : g.edges) EXPECT_GT(e.confidence, 1.0 - 1e-12);
    }
}

TEST(GlobalOptimization, ReferenceNodeIsKeptExactlyAndOnlyFixesTheFrame) {
    for (Method method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        const Synthetic s = helix(12, 0.01, 1);
        reg::PoseGraph first = s.graph, fifth = s.graph;
        reg::global_optimization(first, with(method, -1));
        reg::global_optimization(fifth, with(method, 5));
        EXPECT_EQ(first.nodes[0].pose, s.graph.nodes[0].pose);
        EXPECT_EQ(fifth.nodes[5].pose, s.graph.nodes[5].pose);
        EXPECT_NE(fifth.nodes[0].pose, s.graph.nodes[0].pose);
        EXPECT_EQ(first.edges.size(), fifth.edges.size());
        // Gauss-Newton's path depends on the fixed node (to the 1e-6 convergence tolerance); LM's only by rounding.
        EXPECT_LT(max_relative_difference(first, fifth), method == Method::GaussNewton ? 1e-5 : 1e-9);
    }
}

TEST(GlobalOptimization, GaussNewtonAndLevenbergMarquardtReachTheSameOptimum) {
    const Synthetic s = helix(16, 0.01, 2);
    reg::PoseGraph gn = s.graph, lm = s.graph;
    reg::global_optimization(gn, with(Method::GaussNewton));
    reg::global_optimization(lm, with(Method::LevenbergMarquardt));
    ASSERT_EQ(gn.edges.size(), lm.edges.size());
    EXPECT_LT(max_relative_difference(gn, lm), 1e-5);
    for (size_t k = 0; k < gn.edges.size(); ++k) EXPECT_NEAR(gn.edges[k].confidence, lm.edges[k].confidence, 1e-5);
}

TEST(GlobalOptimization, ThreadCountDoesNotChangeTheResult) {
    // 720 nodes, 1082 edges: above the 1024 where the per-edge work runs in parallel.
    const Synthetic s = helix(720, 0.01, 5);
    ASSERT_GT(s.graph.edges.size(), 1024u);
    for (Method method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        reg::PoseGraph one = s.graph;
        const auto summary = reg::global_optimization(one, with(method, -1, 1));
        EXPECT_EQ(summary.pruned_edges, 5);
        for (int threads : {2, 3}) {
            SCOPED_TRACE(threads);
            reg::PoseGraph many = s.graph;
            const auto other = reg::global_optimization(many, with(method, -1, threads));
            expect_identical(one, many);
            EXPECT_EQ(other.iterations, summary.iterations);
            EXPECT_EQ(other.final_residual, summary.final_residual);
        }
    }
}

TEST(GlobalOptimization, LargeGraphIsSolvedSparsely) {
    // 2000 nodes: 12000 unknowns, far beyond a dense solve's reach in test time.
    const Synthetic s = helix(2000, 0.005, 20);
    reg::PoseGraph g = s.graph;
    const auto summary = reg::global_optimization(g, with(Method::LevenbergMarquardt));
    EXPECT_EQ(summary.pruned_edges, 20);
    EXPECT_LT(summary.final_residual, summary.initial_residual);
}

TEST(GlobalOptimization, ProgressRunsOnTheCallingThreadAndReachesOne) {
    for (Method method : kMethods) {
        SCOPED_TRACE(static_cast<int>(method));
        reg::PoseGraph g = helix(12, 0.01, 1).graph;
        std::vector<double> fractions;
        bool other_thread = false;
        const auto caller = std::this_thread::get_id();
        auto options = with(method, -1, 4);
        options.progress = [&](double f) {
            other_thread = other_thread || std::this_thread::get_id() != caller;
            fractions.push_back(f);
            return true;
        };
        const auto summary = reg::global_optimization(g, options);
        EXPECT_FALSE(other_thread);
        ASSERT_GE(fractions.size(), static_cast<size_t>(summary.iterations));
        for (size_t i = 0; i < fractions.size(); ++i) {
            EXPECT_GT(fractions[i], 0.0);
            EXPECT_LE(fractions[i], 1.0);
            if (i) EXPECT_GE(fractions[i], fractions[i - 1]);
        }
        EXPECT_EQ(fractions.back(), 1.0);
    }
}

TEST(GlobalOptimization, CancelLeavesTheGraphUnchanged) {
    for (Method method : kMethods) {
        for (int stop_at : {1, 3}) {
            SCOPED_TRACE(std::to_string(static_cast<int>(method)) + " stop at call " + std::to_string(stop_at));
            const reg::PoseGraph before = helix(12, 0.01, 1).graph;
            reg::PoseGraph g = before;
            int calls = 0;
            auto options = with(method);
            options.progress = [&](double) { return ++calls < stop_at; };
            EXPECT_THROW(reg::global_optimization(g, options), o3d::Cancelled);
            EXPECT_EQ(calls, stop_at);
            expect_identical(g, before);
        }
    }
}

TEST(GlobalOptimization, MaxIterationZeroRunsOneIterationPerPass) {
    // Open3D tests the iteration count after an iteration, so max_iteration = k allows k + 1 of them.
    reg::PoseGraph g = helix(12, 0.01, 1).graph;
    auto options = with(Method::GaussNewton);
    options.criteria.max_iteration = 0;
    EXPECT_EQ(reg::global_optimization(g, options).iterations, 2);
}

TEST(GlobalOptimization, TrivialGraphs) {
    reg::PoseGraph empty;
    const auto summary = reg::global_optimization(empty);
    EXPECT_EQ(summary.iterations, 0);
    EXPECT_TRUE(empty.nodes.empty());

    reg::PoseGraph single;
    single.nodes.push_back({rigid(Eigen::Matrix3d::Identity(), {1, 2, 3})});
    const reg::PoseGraph before = single;
    EXPECT_EQ(reg::global_optimization(single).iterations, 0);
    expect_identical(single, before);

    // A self-edge constrains nothing: the pose stays, for both methods.
    single.edges.push_back({0, 0, rigid(Eigen::Matrix3d::Identity(), {0.1, 0, 0}), information(10), false, 1.0});
    for (Method method : kMethods) {
        reg::PoseGraph g = single;
        reg::global_optimization(g, with(method));
        EXPECT_EQ(g.nodes[0].pose, single.nodes[0].pose);
    }
}

TEST(GlobalOptimization, InvalidInputIsRejectedAndLeavesTheGraphUnchanged) {
    const Synthetic s = helix(8, 0.01, 1);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    using Graph = reg::PoseGraph;
    using Options = reg::GlobalOptimizationOptions;
    struct Case {
        const char* what;
        void (*graph)(Graph&);
        void (*options)(Options&);
    };
    static double bad_value;
    const Case cases[] = {
        {"source id -1", [](Graph& g) { g.edges[2].source_node_id = -1; }, nullptr},
        {"target id past the end", [](Graph& g) { g.edges[2].target_node_id = static_cast<int>(g.nodes.size()); },
         nullptr},
        {"NaN pose", [](Graph& g) { g.nodes[3].pose(0, 3) = bad_value; }, nullptr},
        {"singular pose", [](Graph& g) { g.nodes[3].pose.col(1).setZero(); }, nullptr},
        {"NaN transformation", [](Graph& g) { g.edges[1].transformation(1, 1) = bad_value; }, nullptr},
        {"singular transformation", [](Graph& g) { g.edges[1].transformation.row(2).setZero(); }, nullptr},
        {"NaN information", [](Graph& g) { g.edges[0].information(4, 2) = bad_value; }, nullptr},
        {"certain edge with confidence 0.5", [](Graph& g) { g.edges[0].confidence = 0.5; }, nullptr},
        {"uncertain edge with confidence 1.5", [](Graph& g) { g.edges.back().confidence = 1.5; }, nullptr},
        {"uncertain edge with NaN confidence", [](Graph& g) { g.edges.back().confidence = bad_value; }, nullptr},
        {"disconnected", [](Graph& g) { g.nodes.push_back({Eigen::Matrix4d::Identity()}); }, nullptr},
        {"no point pairs behind the edges (mu = 0)",
         [](Graph& g) {
             for (auto& e : g.edges) e.information(5, 5) = 0.0;
         },
         nullptr},
        {"max_iteration < 0", nullptr, [](Options& o) { o.criteria.max_iteration = -1; }},
        {"max_iteration_lm < 1", nullptr, [](Options& o) { o.criteria.max_iteration_lm = 0; }},
        {"min_relative_increment NaN", nullptr, [](Options& o) { o.criteria.min_relative_increment = bad_value; }},
        {"min_relative_residual_increment < 0", nullptr,
         [](Options& o) { o.criteria.min_relative_residual_increment = -1e-6; }},
        {"min_right_term NaN", nullptr, [](Options& o) { o.criteria.min_right_term = bad_value; }},
        {"min_residual < 0", nullptr, [](Options& o) { o.criteria.min_residual = -1.0; }},
        {"lower_scale_factor 0", nullptr, [](Options& o) { o.criteria.lower_scale_factor = 0.0; }},
        {"lower > upper", nullptr, [](Options& o) { o.criteria.lower_scale_factor = 0.9; }},
        {"upper_scale_factor inf", nullptr, [](Options& o) { o.criteria.upper_scale_factor = bad_value; }},
        {"max_correspondence_distance 0", nullptr, [](Options& o) { o.option.max_correspondence_distance = 0.0; }},
        {"max_correspondence_distance NaN", nullptr,
         [](Options& o) { o.option.max_correspondence_distance = bad_value; }},
        {"preference_loop_closure < 0", nullptr, [](Options& o) { o.option.preference_loop_closure = -1.0; }},
        {"edge_prune_threshold > 1", nullptr, [](Options& o) { o.option.edge_prune_threshold = 1.5; }},
        {"edge_prune_threshold NaN", nullptr, [](Options& o) { o.option.edge_prune_threshold = bad_value; }},
        {"reference_node -2", nullptr, [](Options& o) { o.option.reference_node = -2; }},
        {"reference_node past the end", nullptr, [](Options& o) { o.option.reference_node = 8; }},
        {"num_threads < 0", nullptr, [](Options& o) { o.num_threads = -1; }},
        {"unknown method", nullptr, [](Options& o) { o.method = static_cast<Method>(7); }},
    };
    for (double value : {nan, inf}) {
        bad_value = value;
        for (const Case& c : cases) {
            SCOPED_TRACE(std::string(c.what) + (value == inf ? " (inf)" : ""));
            Graph g = s.graph;
            if (c.graph) c.graph(g);
            const Graph before = g;
            Options options;
            if (c.options) c.options(options);
            EXPECT_THROW(reg::global_optimization(g, options), o3d::InvalidArgument);
            expect_identical(g, before);
        }
    }
}
