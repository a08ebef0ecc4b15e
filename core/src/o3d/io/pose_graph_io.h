// SPDX-License-Identifier: MIT
#pragma once
/// @file pose_graph_io.h
/// @brief Open3D's JSON layout for pose graphs (o3d.io.read_pose_graph / write_pose_graph):
/// {"class_name": "PoseGraph", "version_major": 1, "version_minor": 0, "nodes": [...], "edges": [...]},
/// each node {"class_name": "PoseGraphNode", "pose": 16 numbers}, each edge {"class_name": "PoseGraphEdge",
/// "source_node_id", "target_node_id", "uncertain", "confidence", "transformation": 16 numbers,
/// "information": 36 numbers}. Matrices are stored column-major. As in Open3D, a missing version reads
/// as 1.0, missing node ids as -1, a missing "uncertain" as false and a missing "confidence" as 1.
#include <string>
#include <string_view>

#include "o3d/registration/pose_graph.h"

namespace o3d::io {

/// @brief Read a pose graph file (UTF-8 path).
/// @throws o3d::IoError when the file cannot be read; o3d::ParseError ("<path>: <where>: <reason>") on
/// malformed JSON, a wrong "class_name" or version, a matrix of the wrong size, a non-finite number or
/// an id that is not a 32-bit integer.
registration::PoseGraph read_pose_graph(const std::string& path);
/// @brief Write `graph` (UTF-8 path), numbers in their shortest exact form, so a read gives it back exactly.
/// @throws o3d::InvalidArgument on a non-finite entry (JSON cannot hold it); o3d::IoError when the file
/// cannot be written.
void write_pose_graph(const std::string& path, const registration::PoseGraph& graph);

/// @brief read_pose_graph on text in memory; `name` prefixes error messages.
registration::PoseGraph parse_pose_graph_json(std::string_view text, const std::string& name);
/// @brief write_pose_graph to a string.
std::string format_pose_graph_json(const registration::PoseGraph& graph);

}  // namespace o3d::io
