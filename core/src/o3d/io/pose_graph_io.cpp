// SPDX-License-Identifier: MIT
// JSON goes through nlohmann_json; this file only maps Open3D's field names and layouts.
#include "o3d/io/pose_graph_io.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "o3d/io/file_bytes.h"
#include "o3d/utility/error.h"

namespace o3d::io {
namespace {

using nlohmann::json;
using registration::PoseGraph;
using registration::PoseGraphEdge;
using registration::PoseGraphNode;

/// @brief Names the source and where in it a problem is ("edges[3].information").
struct Where {
    const std::string& name;
    std::string path;

    [[noreturn]] void fail(const std::string& reason) const {
        throw ParseError(name + ": " + (path.empty() ? "" : path + ": ") + reason);
    }
    Where at(const std::string& key) const { return {name, path.empty() ? key : path + "." + key}; }
};

const json* find(const json& object, const char* key) {
    const auto it = object.find(key);
    return it == object.end() ? nullptr : &*it;
}

const json& member(const json& object, const char* key, const Where& where) {
    const json* v = find(object, key);
    if (!v) where.fail(std::string("missing \"") + key + "\"");
    return *v;
}

/// @brief An int32 member, or `fallback` when it is absent (Open3D's Json::Value::get defaults).
int read_int(const json& object, const char* key, int fallback, const Where& where) {
    const json* v = find(object, key);
    if (!v) return fallback;
    if (!v->is_number_integer()) where.at(key).fail("expected an integer");
    if (v->is_number_unsigned() ? v->get<uint64_t>() > static_cast<uint64_t>(std::numeric_limits<int>::max())
                                : (v->get<int64_t>() < std::numeric_limits<int>::min() ||
                                   v->get<int64_t>() > std::numeric_limits<int>::max()))
        where.at(key).fail("integer out of range");
    return static_cast<int>(v->get<int64_t>());
}

double read_finite(const json& v, const Where& where) {
    if (!v.is_number()) where.fail("expected a number");
    const double x = v.get<double>();
    if (!std::isfinite(x)) where.fail("number is not finite");
    return x;
}

/// @brief `count` finite numbers; the JSON array holds them in column-major order, as Eigen stores them.
void read_matrix(const json& object, const char* key, int count, double* out, const Where& where) {
    const json& v = member(object, key, where);
    if (!v.is_array() || v.size() != static_cast<size_t>(count))
        where.at(key).fail("expected an array of " + std::to_string(count) + " numbers");
    for (int k = 0; k < count; ++k)
        out[k] = read_finite(v[static_cast<size_t>(k)], where.at(std::string(key) + "[" + std::to_string(k) + "]"));
}

void check_class(const json& object, const char* class_name, const Where& where) {
    if (!object.is_object()) where.fail("expected a JSON object");
    const json* cls = find(object, "class_name");
    if (!cls || !cls->is_string() || cls->get<std::string>() != class_name)
        where.fail(std::string("\"class_name\" is not \"") + class_name + "\"");
    const int major = read_int(object, "version_major", 1, where);
    const int minor = read_int(object, "version_minor", 0, where);
    if (major != 1 || minor != 0)
        where.fail("unsupported version " + std::to_string(major) + "." + std::to_string(minor) + " (expected 1.0)");
}

PoseGraphNode node_from(const json& object, const Where& where) {
    check_class(object, "PoseGraphNode", where);
    PoseGraphNode node;
    read_matrix(object, "pose", 16, node.pose.data(), where);
    return node;
}

PoseGraphEdge edge_from(const json& object, const Where& where) {
    check_class(object, "PoseGraphEdge", where);
    PoseGraphEdge edge;
    edge.source_node_id = read_int(object, "source_node_id", -1, where);
    edge.target_node_id = read_int(object, "target_node_id", -1, where);
    if (const json* u = find(object, "uncertain")) {
        if (u->is_boolean())
            edge.uncertain = u->get<bool>();
        else if (u->is_number_integer() && (u->get<int64_t>() == 0 || u->get<int64_t>() == 1))
            edge.uncertain = u->get<int64_t>() == 1;
        else
            where.at("uncertain").fail("expected true or false");
    }
    if (const json* c = find(object, "confidence")) edge.confidence = read_finite(*c, where.at("confidence"));
    read_matrix(object, "transformation", 16, edge.transformation.data(), where);
    read_matrix(object, "information", 36, edge.information.data(), where);
    return edge;
}

/// @brief The array under `key`; Open3D writes an empty list as null.
template <typename T, typename From>
std::vector<T> list_from(const json& root, const char* key, const Where& where, From from) {
    const json& list = member(root, key, where);
    std::vector<T> out;
    if (list.is_null()) return out;
    if (!list.is_array()) where.at(key).fail("expected an array");
    out.reserve(list.size());
    for (size_t k = 0; k < list.size(); ++k)
        out.push_back(from(list[k], where.at(std::string(key) + "[" + std::to_string(k) + "]")));
    return out;
}

template <int Count>
json matrix_to(const double* m, const char* what) {
    json out = json::array();
    for (int k = 0; k < Count; ++k) {
        if (!std::isfinite(m[k])) throw InvalidArgument(std::string(what) + " has a NaN or infinite entry");
        out.push_back(m[k]);
    }
    return out;
}

}  // namespace

PoseGraph parse_pose_graph_json(std::string_view text, const std::string& name) {
    json root;
    try {
        root = json::parse(text.begin(), text.end());
    } catch (const json::exception& e) {
        throw ParseError(name + ": invalid JSON: " + e.what());
    }
    const Where where{name, ""};
    check_class(root, "PoseGraph", where);
    PoseGraph graph;
    graph.nodes = list_from<PoseGraphNode>(root, "nodes", where, node_from);
    graph.edges = list_from<PoseGraphEdge>(root, "edges", where, edge_from);
    return graph;
}

std::string format_pose_graph_json(const PoseGraph& graph) {
    json nodes = json::array();
    for (size_t i = 0; i < graph.nodes.size(); ++i) {
        const std::string what = "nodes[" + std::to_string(i) + "].pose";
        nodes.push_back(json{{"class_name", "PoseGraphNode"},
                             {"pose", matrix_to<16>(graph.nodes[i].pose.data(), what.c_str())},
                             {"version_major", 1},
                             {"version_minor", 0}});
    }
    json edges = json::array();
    for (size_t i = 0; i < graph.edges.size(); ++i) {
        const PoseGraphEdge& e = graph.edges[i];
        const std::string what = "edges[" + std::to_string(i) + "]";
        if (!std::isfinite(e.confidence)) throw InvalidArgument(what + ".confidence is not finite");
        edges.push_back(json{{"class_name", "PoseGraphEdge"},
                             {"confidence", e.confidence},
                             {"information", matrix_to<36>(e.information.data(), (what + ".information").c_str())},
                             {"source_node_id", e.source_node_id},
                             {"target_node_id", e.target_node_id},
                             {"transformation",
                              matrix_to<16>(e.transformation.data(), (what + ".transformation").c_str())},
                             {"uncertain", e.uncertain},
                             {"version_major", 1},
                             {"version_minor", 0}});
    }
    const json root{{"class_name", "PoseGraph"},
                    {"edges", std::move(edges)},
                    {"nodes", std::move(nodes)},
                    {"version_major", 1},
                    {"version_minor", 0}};
    return root.dump(1, '\t') + "\n";
}

PoseGraph read_pose_graph(const std::string& path) {
    const detail::FileBytes bytes(path);
    return parse_pose_graph_json(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path);
}

void write_pose_graph(const std::string& path, const PoseGraph& graph) {
    const std::string text = format_pose_graph_json(graph);  // validate before touching the file
    detail::write_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

}  // namespace o3d::io
