// SPDX-License-Identifier: MIT
// C API: lineset.h (container, editing and the LineSet.create_from_* builders).
#include <Eigen/Core>
#include <memory>
#include <string>

#include "array_family.h"
#include "internal.h"
#include "o3d/geometry/line_set_ops.h"
#include "o3d/lineset.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::geometry::LineSet;

namespace {

LineSet& lines_of(o3d_lineset_t* l, const char* name = "lineset") { return require(l, name)->lineset; }
const LineSet& lines_of(const o3d_lineset_t* l, const char* name = "lineset") { return require(l, name)->lineset; }

o3d::capi::ArraySlot<double> lineset_slot(o3d_lineset_t* h, int32_t which) {
    LineSet& l = lines_of(h);
    switch (which) {
        case O3D_LINESET_POINTS: return o3d::capi::eigen_slot(l.points, l.has_points());
        case O3D_LINESET_COLORS: return o3d::capi::eigen_slot(l.colors, l.has_colors());
        default: o3d::capi::bad_which(which, "a float64 line-set array (O3D_LINESET_POINTS, O3D_LINESET_COLORS)");
    }
}

o3d::capi::ArraySlot<int32_t> lineset_index_slot(o3d_lineset_t* h, int32_t which) {
    LineSet& l = lines_of(h);
    if (which != O3D_LINESET_LINES) o3d::capi::bad_which(which, "an int32 line-set array (O3D_LINESET_LINES)");
    return o3d::capi::eigen_slot(l.lines, l.has_lines());
}

void check_input(const void* data, size_t rows, size_t row_bytes, const char* name) {
    if (rows > 0 && !data) throw o3d::InvalidArgument(std::string(name) + " is NULL but rows = " + std::to_string(rows));
    if (rows > SIZE_MAX / row_bytes || rows > static_cast<size_t>(INT32_MAX))
        throw o3d::InvalidArgument(std::string(name) + ": rows = " + std::to_string(rows) + " is too large");
}


o3d_lineset_t** require_out(o3d_lineset_t** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

void give(o3d_lineset_t** out, LineSet lines) {
    auto handle = std::make_unique<o3d_lineset>();
    handle->lineset = std::move(lines);
    *out = handle.release();
}

}  // namespace

extern "C" {

O3D_CAPI_ARRAYS_F64(lineset, o3d_lineset_t, lineset_slot)
O3D_CAPI_ARRAY_QUERIES(lineset, o3d_lineset_t, lineset_slot, lineset_index_slot)
O3D_CAPI_INDEX_ARRAYS(lineset, o3d_lineset_t, lineset_index_slot)

O3D_API o3d_status o3d_lineset_create(o3d_lineset_t** out) {
    return guard(__func__, [&] { give(require_out(out), LineSet{}); });
}

O3D_API void o3d_lineset_destroy(o3d_lineset_t* lineset) { delete lineset; }

O3D_API o3d_status o3d_lineset_clone(o3d_lineset_t** out, const o3d_lineset_t* src) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, lines_of(src, "src"));
    });
}

O3D_API o3d_status o3d_lineset_num_points(size_t* out_n, const o3d_lineset_t* lineset) {
    return guard(__func__, [&] { *require(out_n, "out_n") = lines_of(lineset).points.size(); });
}

O3D_API o3d_status o3d_lineset_num_lines(size_t* out_n, const o3d_lineset_t* lineset) {
    return guard(__func__, [&] { *require(out_n, "out_n") = lines_of(lineset).lines.size(); });
}

O3D_API o3d_status o3d_lineset_paint_uniform_color(o3d_lineset_t* lineset, const double rgb[3]) {
    return guard(__func__, [&] { o3d::geometry::paint_line_set(lines_of(lineset), vec3(rgb, "rgb")); });
}

O3D_API o3d_status o3d_lineset_transform(o3d_lineset_t* lineset, const double transform[16]) {
    return guard(__func__, [&] {
        LineSet& l = lines_of(lineset);
        require(transform, "transform");
        o3d::geometry::transform_line_set(l, Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(transform));
    });
}

O3D_API o3d_status o3d_lineset_create_from_point_cloud_correspondences(o3d_lineset_t** out,
                                                                       const o3d_pointcloud_t* cloud0,
                                                                       const o3d_pointcloud_t* cloud1,
                                                                       const int32_t* pairs, size_t n_pairs) {
    return guard(__func__, [&] {
        require_out(out);
        const auto& c0 = require(cloud0, "cloud0")->cloud;
        const auto& c1 = require(cloud1, "cloud1")->cloud;
        check_input(pairs, n_pairs, 2 * sizeof(int32_t), "pairs");
        std::vector<Eigen::Vector2i> list(n_pairs);
        for (size_t i = 0; i < n_pairs; ++i) list[i] = Eigen::Vector2i(pairs[2 * i], pairs[2 * i + 1]);
        give(out, o3d::geometry::line_set_from_correspondences(c0, c1, list));
    });
}

O3D_API o3d_status o3d_lineset_create_from_oriented_bounding_box(o3d_lineset_t** out, const o3d_obb_t* obb) {
    return guard(__func__, [&] {
        require_out(out);
        require(obb, "obb");
        const Eigen::Vector3d center(obb->center[0], obb->center[1], obb->center[2]);
        const Eigen::Matrix3d R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(obb->R);
        const Eigen::Vector3d extent(obb->extent[0], obb->extent[1], obb->extent[2]);
        if (!center.allFinite() || !R.allFinite() || !extent.allFinite())
            throw o3d::InvalidArgument("obb has a non-finite entry");
        if ((extent.array() < 0.0).any()) throw o3d::InvalidArgument("obb.extent has a negative entry");
        give(out, o3d::geometry::line_set_from_oriented_box(center, R, extent));
    });
}

O3D_API o3d_status o3d_lineset_create_from_axis_aligned_bounding_box(o3d_lineset_t** out, const double min_bound[3],
                                                                     const double max_bound[3]) {
    return guard(__func__, [&] {
        require_out(out);
        const Eigen::Vector3d lo = vec3(min_bound, "min_bound"), hi = vec3(max_bound, "max_bound");
        if (!lo.allFinite() || !hi.allFinite()) throw o3d::InvalidArgument("the bounds must be finite");
        if ((lo.array() > hi.array()).any()) throw o3d::InvalidArgument("min_bound exceeds max_bound");
        give(out, o3d::geometry::line_set_from_axis_aligned_box(lo, hi));
    });
}

O3D_API o3d_status o3d_lineset_create_from_triangle_mesh(o3d_lineset_t** out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, o3d::geometry::line_set_from_triangle_mesh(require(mesh, "mesh")->mesh));
    });
}

}  // extern "C"
