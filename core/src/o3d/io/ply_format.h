// SPDX-License-Identifier: MIT
#pragma once
/// @file ply_format.h
/// @brief The PLY header model shared by the point-cloud and mesh readers, and the element walker that
/// reads a vertex element into attribute arrays and a face element into triangles.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "o3d/io/byte_reader.h"
#include "o3d/io/io_internal.h"

namespace o3d::io::detail {

enum class PlyEncoding { Ascii, BinaryLittle, BinaryBig };

struct PlyProperty {
    std::string name;
    bool is_list = false;
    ScalarType type = ScalarType::Float32;  // the scalar's type, or the list items' type
    ScalarType count_type = ScalarType::UInt8;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> props;

    bool has_list() const {
        for (const auto& p : props)
            if (p.is_list) return true;
        return false;
    }
    /// @brief Bytes of one record when every list is empty (exact when there are no lists).
    size_t min_record_size() const {
        size_t s = 0;
        for (const auto& p : props) s += scalar_size(p.is_list ? p.count_type : p.type);
        return s;
    }
};

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    size_t data_offset = 0;
};

/// @brief Parse the header; ParseError on anything malformed.
PlyHeader parse_ply_header(const Input& in);

/// @brief Where the vertex element's attributes go. Null members are not wanted; a wanted attribute the
/// file lacks is left empty. uvs are per-vertex texture coordinates (u/v, s/t or texture_u/texture_v).
struct PlyVertexSink {
    std::vector<Eigen::Vector3d>* points = nullptr;
    std::vector<Eigen::Vector3d>* normals = nullptr;
    std::vector<Eigen::Vector3d>* colors = nullptr;
    std::vector<Eigen::Vector2d>* uvs = nullptr;
};

/// @brief Where the face element goes: polygons fan-triangulated; per-corner texture coordinates from a
/// "texcoord" list (two values per corner), three per triangle, left empty when the file has none.
struct PlyFaceSink {
    std::vector<Eigen::Vector3i>* triangles = nullptr;
    std::vector<Eigen::Vector2d>* corner_uvs = nullptr;
};

/// @brief Read every element of the file: the "vertex" one into `vertices` (it must exist), the "face" one
/// into `faces` when given, and walk past the rest, so damage anywhere is caught. Face indices are checked
/// to be in [0, INT32_MAX] here, not against the vertex count.
void read_ply_elements(const Input& in, const PlyVertexSink& vertices, const PlyFaceSink* faces);

/// @brief The binary little-endian vertex records shared by the point-cloud and mesh PLY writers:
/// x y z as doubles, then nx ny nz as doubles when `normals`, then red green blue as uchar when `colors`
/// (either may be NULL). Returns the end of what was written.
inline uint8_t* write_ply_vertex_records(uint8_t* p, const std::vector<Eigen::Vector3d>& xyz,
                                         const std::vector<Eigen::Vector3d>* normals,
                                         const std::vector<Eigen::Vector3d>* colors) {
    for (size_t i = 0; i < xyz.size(); ++i) {
        for (int k = 0; k < 3; ++k) store_le(p + 8 * k, xyz[i][k]);
        p += 24;
        if (normals) {
            for (int k = 0; k < 3; ++k) store_le(p + 8 * k, (*normals)[i][k]);
            p += 24;
        }
        if (colors) {
            for (int k = 0; k < 3; ++k) p[k] = color_to_u8((*colors)[i][k]);
            p += 3;
        }
    }
    return p;
}

}  // namespace o3d::io::detail
