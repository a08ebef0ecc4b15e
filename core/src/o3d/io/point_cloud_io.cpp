// SPDX-License-Identifier: MIT
// Format dispatch, file <-> memory, and the read options that apply to every format.
#include "o3d/io/point_cloud_io.h"

#include <cmath>
#include <string_view>

#include "o3d/io/file_bytes.h"
#include "o3d/io/io_internal.h"
#include "o3d/utility/error.h"
#include "o3d/io/format_dispatch.h"

namespace o3d::io {
namespace detail {

void parse_error(const Input& in, const std::string& reason) { throw ParseError(in.name + ": " + reason); }

void allocate_cloud(geometry::PointCloud& cloud, size_t n, bool normals, bool colors) {
    auto one = [n](std::vector<Eigen::Vector3d>& v) {
        v.resize(n);
        prefault(v.data(), n * sizeof(Eigen::Vector3d));
    };
    one(cloud.points);
    if (normals) one(cloud.normals);
    if (colors) one(cloud.colors);
}

std::vector<uint8_t> output_buffer(size_t n) {
    std::vector<uint8_t> out;
    out.reserve(n);
    prefault(out.data(), n);
    out.resize(n);
    return out;
}

}  // namespace detail

namespace {

enum class Format { Ply, Pcd, Xyz, Xyzn, Xyzrgb, Pts };

constexpr detail::FormatName<Format> kFormats[] = {
    {"ply", Format::Ply}, {"pcd", Format::Pcd}, {"xyz", Format::Xyz}, {"xyzn", Format::Xyzn},
    {"xyzrgb", Format::Xyzrgb}, {"pts", Format::Pts}};

Format resolve(const std::string& format, const std::string* path) {
    return detail::resolve_format(kFormats, "point-cloud", format, path);
}

geometry::PointCloud parse(Format f, const detail::Input& in) {
    switch (f) {
        case Format::Ply: return detail::read_ply(in);
        case Format::Pcd: return detail::read_pcd(in);
        case Format::Xyz: return detail::read_xyz(in);
        case Format::Xyzn: return detail::read_xyzn(in);
        case Format::Xyzrgb: return detail::read_xyzrgb(in);
        case Format::Pts: return detail::read_pts(in);
    }
    throw Unsupported("unknown point-cloud format");
}

std::vector<uint8_t> encode(Format f, const geometry::PointCloud& cloud, const WriteOptions& options) {
    switch (f) {
        case Format::Ply: return detail::write_ply(cloud, options);
        case Format::Pcd: return detail::write_pcd(cloud, options);
        case Format::Xyz: return detail::write_xyz(cloud);
        case Format::Xyzn: return detail::write_xyzn(cloud);
        case Format::Xyzrgb: return detail::write_xyzrgb(cloud);
        case Format::Pts: return detail::write_pts(cloud);
    }
    throw Unsupported("unknown point-cloud format");
}

/// @brief Open3D's RemoveNonFinitePoints: drop a point (and its normal and colour) whose
/// coordinates hold a NaN or an infinity, as the options ask.
void remove_non_finite(geometry::PointCloud& cloud, const ReadOptions& options) {
    if (!options.remove_nan_points && !options.remove_infinite_points) return;
    const bool normals = cloud.has_normals();
    const bool colors = cloud.has_colors();
    size_t kept = 0;
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        const bool nan = std::isnan(p.x()) || std::isnan(p.y()) || std::isnan(p.z());
        const bool inf = std::isinf(p.x()) || std::isinf(p.y()) || std::isinf(p.z());
        if ((options.remove_nan_points && nan) || (options.remove_infinite_points && inf)) continue;
        if (kept != i) {
            cloud.points[kept] = p;
            if (normals) cloud.normals[kept] = cloud.normals[i];
            if (colors) cloud.colors[kept] = cloud.colors[i];
        }
        ++kept;
    }
    cloud.points.resize(kept);
    if (normals) cloud.normals.resize(kept);
    if (colors) cloud.colors.resize(kept);
}

}  // namespace

geometry::PointCloud read_point_cloud(const std::string& path, const std::string& format, const ReadOptions& options) {
    const Format f = resolve(format, &path);
    const detail::FileBytes bytes(path);
    static const uint8_t kEmpty = 0;
    const detail::Input in{bytes.size() ? bytes.data() : &kEmpty, bytes.size(), path};
    geometry::PointCloud cloud = parse(f, in);
    remove_non_finite(cloud, options);
    return cloud;
}

geometry::PointCloud read_point_cloud_from_memory(const uint8_t* data, size_t size, const std::string& format,
                                                  const ReadOptions& options) {
    const Format f = resolve(format, nullptr);
    if (!data && size) throw InvalidArgument("data is NULL but size is " + std::to_string(size));
    static const uint8_t kEmpty = 0;
    static const std::string kMemory = "<memory>";
    const detail::Input in{data ? data : &kEmpty, data ? size : 0, kMemory};
    geometry::PointCloud cloud = parse(f, in);
    remove_non_finite(cloud, options);
    return cloud;
}

void write_point_cloud(const std::string& path, const geometry::PointCloud& cloud, const std::string& format,
                       const WriteOptions& options) {
    const Format f = resolve(format, &path);
    detail::write_file(path, encode(f, cloud, options));
}

std::vector<uint8_t> write_point_cloud_to_memory(const geometry::PointCloud& cloud, const std::string& format,
                                                 const WriteOptions& options) {
    return encode(resolve(format, nullptr), cloud, options);
}

}  // namespace o3d::io
