// SPDX-License-Identifier: MIT
// PCD writer, laid out like Open3D's: float x y z, normal_x normal_y normal_z, and rgb packed
// 0x00RRGGBB into a float's bits. DATA binary by default, ascii or binary_compressed on request.
#include <lzf.h>

#include <algorithm>
#include <climits>
#include <cstring>
#include <stdexcept>
#include <string>

#include "o3d/io/byte_reader.h"
#include "o3d/io/io_internal.h"
#include "o3d/io/text_writer.h"
#include "o3d/utility/error.h"

namespace o3d::io::detail {
namespace {

float packed_rgb(const Eigen::Vector3d& c) {
    const uint32_t v = (uint32_t{color_to_u8(c[0])} << 16) | (uint32_t{color_to_u8(c[1])} << 8) | color_to_u8(c[2]);
    float f;
    std::memcpy(&f, &v, 4);
    return f;
}

}  // namespace

std::vector<uint8_t> write_pcd(const geometry::PointCloud& cloud, const WriteOptions& options) {
    const size_t n = cloud.size();
    const bool normals = cloud.has_normals();
    const bool colors = cloud.has_colors();
    const size_t floats = 3 + (normals ? 3 : 0) + (colors ? 1 : 0);
    const char* data = options.write_ascii ? "ascii" : options.compressed ? "binary_compressed" : "binary";

    std::string fields = "x y z", sizes = "4 4 4", types = "F F F", counts = "1 1 1";
    if (normals) fields += " normal_x normal_y normal_z", sizes += " 4 4 4", types += " F F F", counts += " 1 1 1";
    if (colors) fields += " rgb", sizes += " 4", types += " F", counts += " 1";
    const std::string header = "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\nFIELDS " + fields +
                               "\nSIZE " + sizes + "\nTYPE " + types + "\nCOUNT " + counts + "\nWIDTH " +
                               std::to_string(n) + "\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS " + std::to_string(n) +
                               "\nDATA " + data + "\n";

    // One point's floats, in field order.
    auto point_floats = [&](size_t i, float* v) {
        int k = 0;
        for (int c = 0; c < 3; ++c) v[k++] = static_cast<float>(cloud.points[i][c]);
        if (normals)
            for (int c = 0; c < 3; ++c) v[k++] = static_cast<float>(cloud.normals[i][c]);
        if (colors) v[k++] = packed_rgb(cloud.colors[i]);
    };

    if (options.write_ascii) {
        ByteSink out(header.size() + n * floats * 14);
        out.put(header);
        float v[7];
        for (size_t i = 0; i < n; ++i) {
            point_floats(i, v);
            for (size_t k = 0; k < floats; ++k) {
                if (k) out.put(' ');
                out.put_number(v[k]);  // shortest text that reads back to the same float, rgb bits included
            }
            out.put('\n');
        }
        return out.finish();
    }

    const size_t record = floats * 4;
    if (!options.compressed) {
        std::vector<uint8_t> out = output_buffer(header.size() + n * record);
        std::memcpy(out.data(), header.data(), header.size());
        uint8_t* p = out.data() + header.size();
        float v[7];
        for (size_t i = 0; i < n; ++i, p += record) {
            point_floats(i, v);
            for (size_t k = 0; k < floats; ++k) store_le(p + 4 * k, v[k]);
        }
        return out;
    }

    // binary_compressed: field after field (as PCL stores it, so LZF finds runs), then LZF.
    const size_t raw_size = n * record;
    if (raw_size > UINT_MAX - 64)
        throw InvalidArgument("PCD binary_compressed holds at most 4 GiB of point data; " + std::to_string(n) +
                              " points need " + std::to_string(raw_size) + " bytes");
    std::vector<uint8_t> raw = output_buffer(raw_size);
    float v[7];
    for (size_t i = 0; i < n; ++i) {
        point_floats(i, v);
        for (size_t k = 0; k < floats; ++k) store_le(raw.data() + 4 * (k * n + i), v[k]);
    }
    // LZF adds at most one control byte per 32 literals, plus a little.
    const size_t bound = std::min<size_t>(raw_size + raw_size / 16 + 64, UINT_MAX);
    std::vector<uint8_t> out = output_buffer(header.size() + 8 + bound);
    std::memcpy(out.data(), header.data(), header.size());
    uint8_t* p = out.data() + header.size();
    unsigned packed = 0;
    if (raw_size) {
        packed = lzf_compress(raw.data(), static_cast<unsigned>(raw_size), p + 8, static_cast<unsigned>(bound));
        if (packed == 0) throw std::runtime_error("LZF compression failed");
    }
    store_le(p, static_cast<uint32_t>(packed));
    store_le(p + 4, static_cast<uint32_t>(raw_size));
    out.resize(header.size() + 8 + packed);
    return out;
}

}  // namespace o3d::io::detail
