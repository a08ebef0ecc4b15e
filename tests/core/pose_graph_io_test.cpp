// SPDX-License-Identifier: MIT
// Pose graph JSON (Open3D's layout): exact round trips, the field names and column-major order, Open3D's
// defaults, malformed input, file errors and UTF-8 paths.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <regex>
#include <string>

#include "o3d/io/pose_graph_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace reg = o3d::registration;
using o3d::io::format_pose_graph_json;
using o3d::io::parse_pose_graph_json;

namespace {

std::filesystem::path temp_dir() {
    const auto dir = std::filesystem::temp_directory_path() / ("o3d_pose_graph_io_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

/// Numbers that only survive in their shortest exact form: thirds, tiny, huge and negative values.
reg::PoseGraph awkward_graph() {
    reg::PoseGraph g;
    for (int i = 0; i < 3; ++i) {
        reg::PoseGraphNode n;
        for (int k = 0; k < 16; ++k) n.pose.data()[k] = (k + 1.0 + i) / 3.0 * (k % 2 ? -1.0 : 1.0);
        n.pose(3, 0) = 1e-300;
        g.nodes.push_back(n);
    }
    for (int i = 0; i < 2; ++i) {
        reg::PoseGraphEdge e;
        e.source_node_id = i + 1;
        e.target_node_id = i;
        for (int k = 0; k < 16; ++k) e.transformation.data()[k] = std::sqrt(2.0 + k + i);
        for (int k = 0; k < 36; ++k) e.information.data()[k] = 1e10 / (k + 7.0) - i;
        e.uncertain = i == 1;
        e.confidence = i == 1 ? 0.1 + 0.2 : 1.0;
        g.edges.push_back(e);
    }
    return g;
}

void expect_same(const reg::PoseGraph& a, const reg::PoseGraph& b) {
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (size_t i = 0; i < a.nodes.size(); ++i) EXPECT_EQ(a.nodes[i].pose, b.nodes[i].pose) << "node " << i;
    for (size_t k = 0; k < a.edges.size(); ++k) {
        SCOPED_TRACE("edge " + std::to_string(k));
        EXPECT_EQ(a.edges[k].source_node_id, b.edges[k].source_node_id);
        EXPECT_EQ(a.edges[k].target_node_id, b.edges[k].target_node_id);
        EXPECT_EQ(a.edges[k].transformation, b.edges[k].transformation);
        EXPECT_EQ(a.edges[k].information, b.edges[k].information);
        EXPECT_EQ(a.edges[k].uncertain, b.edges[k].uncertain);
        EXPECT_EQ(a.edges[k].confidence, b.edges[k].confidence);
    }
}

std::string parse_error_of(const std::string& text) {
    try {
        parse_pose_graph_json(text, "<memory>");
    } catch (const o3d::ParseError& e) {
        return e.what();
    }
    return "";
}

const char* const kNode = R"({"class_name": "PoseGraphNode", "pose": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]})";

/// A one-node, one-edge graph with `edge` as the edge's JSON and `node` as the node's.
std::string graph_text(const std::string& edge, const std::string& node = kNode) {
    return R"({"class_name": "PoseGraph", "version_major": 1, "version_minor": 0, "nodes": [)" + node +
           R"(], "edges": [)" + edge + "]}";
}

std::string edge_text(const std::string& extra, const std::string& transformation = "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1",
                      const std::string& information = "1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,0,0,0,0,0,1,0,"
                                                       "0,0,0,0,0,1") {
    return R"({"class_name": "PoseGraphEdge", "transformation": [)" + transformation + R"(], "information": [)" +
           information + "]" + extra + "}";
}

}  // namespace

TEST(PoseGraphIo, RoundTripIsExactInMemoryAndOnDisk) {
    const reg::PoseGraph g = awkward_graph();
    expect_same(parse_pose_graph_json(format_pose_graph_json(g), "<memory>"), g);
    const std::string path = (temp_dir() / "graph.json").string();
    o3d::io::write_pose_graph(path, g);
    expect_same(o3d::io::read_pose_graph(path), g);
}

TEST(PoseGraphIo, EmptyGraphRoundTrips) {
    const reg::PoseGraph back = parse_pose_graph_json(format_pose_graph_json({}), "<memory>");
    EXPECT_TRUE(back.nodes.empty());
    EXPECT_TRUE(back.edges.empty());
    // Open3D writes an empty list as null.
    const reg::PoseGraph null_lists =
        parse_pose_graph_json(R"({"class_name": "PoseGraph", "nodes": null, "edges": null})", "<memory>");
    EXPECT_TRUE(null_lists.nodes.empty());
    EXPECT_TRUE(null_lists.edges.empty());
}

TEST(PoseGraphIo, WritesOpen3DFieldNamesAndColumnMajorMatrices) {
    reg::PoseGraph g;
    reg::PoseGraphNode n;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) n.pose(r, c) = 10 * r + c;
    g.nodes.push_back(n);
    reg::PoseGraphEdge e;
    e.source_node_id = 0;
    e.target_node_id = 0;
    e.uncertain = true;
    e.confidence = 0.5;
    g.edges.push_back(e);
    const std::string text = format_pose_graph_json(g);
    for (const char* field : {"\"class_name\": \"PoseGraph\"", "\"class_name\": \"PoseGraphNode\"",
                              "\"class_name\": \"PoseGraphEdge\"", "\"version_major\": 1", "\"version_minor\": 0",
                              "\"source_node_id\": 0", "\"target_node_id\": 0", "\"uncertain\": true",
                              "\"confidence\": 0.5", "\"transformation\"", "\"information\"", "\"nodes\"", "\"edges\""})
        EXPECT_NE(text.find(field), std::string::npos) << field << " in\n" << text;
    // Column-major: the pose's numbers run down the columns.
    std::smatch m;
    ASSERT_TRUE(std::regex_search(text, m, std::regex(R"("pose":\s*\[([^\]]*)\])")));
    const std::string numbers = std::regex_replace(m[1].str(), std::regex(R"(\s)"), "");
    EXPECT_EQ(numbers, "0.0,10.0,20.0,30.0,1.0,11.0,21.0,31.0,2.0,12.0,22.0,32.0,3.0,13.0,23.0,33.0");
}

TEST(PoseGraphIo, ReadsOpen3DDefaults) {
    // No ids, no "uncertain", no "confidence", no versions: Open3D reads -1, -1, false, 1.
    const reg::PoseGraph g = parse_pose_graph_json(graph_text(edge_text("")), "<memory>");
    ASSERT_EQ(g.edges.size(), 1u);
    EXPECT_EQ(g.edges[0].source_node_id, -1);
    EXPECT_EQ(g.edges[0].target_node_id, -1);
    EXPECT_FALSE(g.edges[0].uncertain);
    EXPECT_EQ(g.edges[0].confidence, 1.0);
    const reg::PoseGraph u =
        parse_pose_graph_json(graph_text(edge_text(R"(, "uncertain": 1, "source_node_id": 7)")), "<memory>");
    EXPECT_TRUE(u.edges[0].uncertain);
    EXPECT_EQ(u.edges[0].source_node_id, 7);
}

TEST(PoseGraphIo, SharedTestFileRoundTrips) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/test_pose_graph.json");
    const reg::PoseGraph g = o3d::io::read_pose_graph(path);
    ASSERT_EQ(g.nodes.size(), 2u);
    ASSERT_EQ(g.edges.size(), 2u);
    EXPECT_EQ(g.edges[0].source_node_id, 1);
    EXPECT_EQ(g.edges[0].target_node_id, 0);
    expect_same(parse_pose_graph_json(format_pose_graph_json(g), "<memory>"), g);
}

TEST(PoseGraphIo, MalformedInputIsAParseError) {
    const std::string fifteen = "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0";
    const std::string cases[] = {
        "",
        "{",
        "[]",
        "not json",
        graph_text(edge_text("")).substr(0, 60),                                        // truncated
        R"({"class_name": "PoseGraf", "nodes": [], "edges": []})",                     // wrong class
        R"({"nodes": [], "edges": []})",                                               // no class
        R"({"class_name": "PoseGraph", "version_major": 2, "nodes": [], "edges": []})",  // version
        R"({"class_name": "PoseGraph", "version_minor": 1, "nodes": [], "edges": []})",
        R"({"class_name": "PoseGraph", "edges": []})",                                   // no nodes
        R"({"class_name": "PoseGraph", "nodes": []})",                                   // no edges
        R"({"class_name": "PoseGraph", "nodes": {}, "edges": []})",                      // not an array
        R"({"class_name": "PoseGraph", "nodes": [1], "edges": []})",                     // node not an object
        graph_text(edge_text(""), R"({"class_name": "PoseGraphEdge", "pose": [1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]})"),
        graph_text(edge_text(""), R"({"class_name": "PoseGraphNode"})"),                 // no pose
        graph_text(edge_text(""), R"({"class_name": "PoseGraphNode", "pose": [)" + fifteen + "]}"),
        graph_text(edge_text(""), R"({"class_name": "PoseGraphNode", "pose": [)" + fifteen + R"(, "x"]})"),
        graph_text(edge_text(""), R"({"class_name": "PoseGraphNode", "pose": [)" + fifteen + ", 1e999]}"),
        graph_text(edge_text("", fifteen)),                                              // 15 numbers
        graph_text(edge_text("", fifteen + ",1,1")),                                     // 17
        graph_text(edge_text("", "1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1", "1,2,3")),           // information 3
        graph_text(edge_text(R"(, "class_name": "PoseGraphNode")")),                     // duplicate key, wrong class
        graph_text(R"({"class_name": "PoseGraphEdge", "information": [])" + std::string("1") + "]}"),
        graph_text(edge_text(R"(, "source_node_id": 1.5)")),
        graph_text(edge_text(R"(, "target_node_id": "0")")),
        graph_text(edge_text(R"(, "source_node_id": 4294967296)")),
        graph_text(edge_text(R"(, "target_node_id": -2147483649)")),
        graph_text(edge_text(R"(, "uncertain": "yes")")),
        graph_text(edge_text(R"(, "uncertain": 2)")),
        graph_text(edge_text(R"(, "confidence": "high")")),
        graph_text(edge_text(R"(, "confidence": -1e400)")),
        graph_text(edge_text(R"(, "version_major": 3)")),
    };
    for (const std::string& text : cases) {
        SCOPED_TRACE(text);
        const std::string message = parse_error_of(text);
        EXPECT_NE(message, "");
        EXPECT_EQ(message.rfind("<memory>: ", 0), 0u) << message;
    }
    // The message says where: the edge and the field.
    EXPECT_NE(parse_error_of(graph_text(edge_text("", fifteen))).find("edges[0].transformation"), std::string::npos);
}

TEST(PoseGraphIo, FileErrors) {
    const auto dir = temp_dir();
    EXPECT_THROW(o3d::io::read_pose_graph((dir / "missing.json").string()), o3d::IoError);
    EXPECT_THROW(o3d::io::read_pose_graph(dir.string()), o3d::IoError);  // a directory
    EXPECT_THROW(o3d::io::write_pose_graph((dir / "no" / "such" / "dir.json").string(), awkward_graph()),
                 o3d::IoError);
}

TEST(PoseGraphIo, NonFiniteValuesAreNotWritten) {
    const auto path = temp_dir() / "nan.json";
    std::filesystem::remove(path);
    for (int which = 0; which < 4; ++which) {
        reg::PoseGraph g = awkward_graph();
        const double nan = std::numeric_limits<double>::quiet_NaN();
        if (which == 0) g.nodes[1].pose(2, 1) = nan;
        if (which == 1) g.edges[0].transformation(0, 3) = std::numeric_limits<double>::infinity();
        if (which == 2) g.edges[1].information(5, 5) = nan;
        if (which == 3) g.edges[1].confidence = nan;
        EXPECT_THROW(o3d::io::write_pose_graph(path.string(), g), o3d::InvalidArgument) << which;
        EXPECT_FALSE(std::filesystem::exists(path)) << which;
    }
}

TEST(PoseGraphIo, Utf8Path) {
    const std::string path = (temp_dir() / "位姿图_pose_gräph.json").string();
    o3d::io::write_pose_graph(path, awkward_graph());
    expect_same(o3d::io::read_pose_graph(path), awkward_graph());
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::u8path(path)));
}
