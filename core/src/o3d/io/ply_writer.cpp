// SPDX-License-Identifier: MIT
// PLY writer, laid out like Open3D's: double x y z and nx ny nz, uchar red green blue;
// binary_little_endian unless write_ascii.
#include <cstring>
#include <string>

#include "o3d/io/byte_reader.h"
#include "o3d/io/io_internal.h"
#include "o3d/io/ply_format.h"
#include "o3d/io/text_writer.h"

namespace o3d::io::detail {

std::vector<uint8_t> write_ply(const geometry::PointCloud& cloud, const WriteOptions& options) {
    const size_t n = cloud.size();
    const bool normals = cloud.has_normals();
    const bool colors = cloud.has_colors();

    std::string header = "ply\nformat ";
    header += options.write_ascii ? "ascii" : "binary_little_endian";
    header += " 1.0\ncomment Created by o3d\nelement vertex " + std::to_string(n) +
              "\nproperty double x\nproperty double y\nproperty double z\n";
    if (normals) header += "property double nx\nproperty double ny\nproperty double nz\n";
    if (colors) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    header += "end_header\n";

    if (options.write_ascii) {
        ByteSink out(header.size() + n * (normals ? 128 : 64));
        out.put(header);
        for (size_t i = 0; i < n; ++i) {
            const Eigen::Vector3d& p = cloud.points[i];
            for (int k = 0; k < 3; ++k) {
                if (k) out.put(' ');
                out.put_number(p[k]);
            }
            if (normals)
                for (int k = 0; k < 3; ++k) {
                    out.put(' ');
                    out.put_number(cloud.normals[i][k]);
                }
            if (colors)
                for (int k = 0; k < 3; ++k) {
                    out.put(' ');
                    out.put_number(static_cast<unsigned>(color_to_u8(cloud.colors[i][k])));
                }
            out.put('\n');
        }
        return out.finish();
    }

    const size_t record = 24 + (normals ? 24 : 0) + (colors ? 3 : 0);
    std::vector<uint8_t> out = output_buffer(header.size() + n * record);
    std::memcpy(out.data(), header.data(), header.size());
    uint8_t* p = out.data() + header.size();
    write_ply_vertex_records(p, cloud.points, normals ? &cloud.normals : nullptr, colors ? &cloud.colors : nullptr);
    return out;
}

}  // namespace o3d::io::detail
