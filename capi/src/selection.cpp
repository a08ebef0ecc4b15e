// SPDX-License-Identifier: MIT
// C API of SelectionPolygonVolume (selection.h).
#include "o3d/selection.h"

#include "internal.h"
#include "o3d/io/file_bytes.h"
#include "o3d/visualization/selection_polygon_volume.h"

struct o3d_selection_polygon_volume {
    o3d::visualization::SelectionPolygonVolume volume;
};

namespace {

using o3d::capi::guard;
using o3d::capi::require;
using Volume = o3d::visualization::SelectionPolygonVolume;

const Volume& of(const o3d_selection_polygon_volume_t* v) { return require(v, "volume")->volume; }
Volume& of(o3d_selection_polygon_volume_t* v) { return require(v, "volume")->volume; }

}  // namespace

O3D_API o3d_status o3d_selection_polygon_volume_create(o3d_selection_polygon_volume_t** out) {
    return guard(__func__, [&] {
        require(out, "out");  // first: in `*require(out) = new ...` the allocation would come before the check
        *out = new o3d_selection_polygon_volume();
    });
}

O3D_API void o3d_selection_polygon_volume_destroy(o3d_selection_polygon_volume_t* volume) { delete volume; }

O3D_API o3d_status o3d_selection_polygon_volume_read_json(o3d_selection_polygon_volume_t** out, const char* path) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const o3d::io::detail::FileBytes bytes(require(path, "path"));
        const std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
        *out = new o3d_selection_polygon_volume{o3d::visualization::selection_polygon_volume_from_json(text)};
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_get_orthogonal_axis(o3d_axis* out,
                                                                    const o3d_selection_polygon_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = of(volume).orthogonal_axis; });
}

O3D_API o3d_status o3d_selection_polygon_volume_set_orthogonal_axis(o3d_selection_polygon_volume_t* volume,
                                                                    o3d_axis axis) {
    return guard(__func__, [&] {
        Volume& v = of(volume);
        if (axis != O3D_AXIS_X && axis != O3D_AXIS_Y && axis != O3D_AXIS_Z)
            throw o3d::InvalidArgument("axis must be O3D_AXIS_X, _Y or _Z, got " + std::to_string(axis));
        v.orthogonal_axis = axis;
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_get_axis_min(double* out, const o3d_selection_polygon_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = of(volume).axis_min; });
}

O3D_API o3d_status o3d_selection_polygon_volume_set_axis_min(o3d_selection_polygon_volume_t* volume, double value) {
    return guard(__func__, [&] {
        Volume& v = of(volume);
        o3d::capi::require_finite(value, "axis_min");
        v.axis_min = value;
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_get_axis_max(double* out, const o3d_selection_polygon_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = of(volume).axis_max; });
}

O3D_API o3d_status o3d_selection_polygon_volume_set_axis_max(o3d_selection_polygon_volume_t* volume, double value) {
    return guard(__func__, [&] {
        Volume& v = of(volume);
        o3d::capi::require_finite(value, "axis_max");
        v.axis_max = value;
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_get_bounding_polygon(double* out, size_t capacity, size_t* out_rows,
                                                                     const o3d_selection_polygon_volume_t* volume) {
    return guard(__func__, [&] {
        require(out_rows, "out_rows");
        const std::vector<Eigen::Vector3d>& corners = of(volume).bounding_polygon;
        o3d::capi::copy_out(corners.empty() ? nullptr : corners.front().data(), corners.size(), out, capacity, out_rows, 3);
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_set_bounding_polygon(o3d_selection_polygon_volume_t* volume,
                                                                     const double* corners, size_t rows) {
    return guard(__func__, [&] {
        Volume& v = of(volume);
        if (rows > 0) require(corners, "corners");
        std::vector<Eigen::Vector3d> polygon(rows);
        for (size_t i = 0; i < rows; ++i) {
            polygon[i] = Eigen::Vector3d(corners[3 * i], corners[3 * i + 1], corners[3 * i + 2]);
            if (!polygon[i].allFinite())
                throw o3d::InvalidArgument("corner " + std::to_string(i) + " is not finite");
        }
        v.bounding_polygon = std::move(polygon);
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_crop_in_polygon(int32_t* out, size_t capacity, size_t* out_n,
                                                                const o3d_selection_polygon_volume_t* volume,
                                                                const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const std::vector<int64_t> inside =
            o3d::visualization::crop_in_polygon(of(volume), require(pc, "pc")->cloud.points);
        if (inside.size() > size_t(INT32_MAX)) throw o3d::InvalidArgument("more points inside than int32 can index");
        const std::vector<int32_t> narrow(inside.begin(), inside.end());
        o3d::capi::copy_out(narrow.data(), narrow.size(), out, capacity, out_n);
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_crop_point_cloud(o3d_pointcloud_t** out,
                                                                 const o3d_selection_polygon_volume_t* volume,
                                                                 const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        *out = new o3d_pointcloud{o3d::visualization::crop_point_cloud(of(volume), require(pc, "pc")->cloud)};
    });
}

O3D_API o3d_status o3d_selection_polygon_volume_crop_triangle_mesh(o3d_trianglemesh_t** out,
                                                                   const o3d_selection_polygon_volume_t* volume,
                                                                   const o3d_trianglemesh_t* input) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        *out = new o3d_trianglemesh{o3d::visualization::crop_triangle_mesh(of(volume), require(input, "input")->mesh)};
    });
}
