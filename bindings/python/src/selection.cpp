// SPDX-License-Identifier: MIT
// o3d.visualization.SelectionPolygonVolume and read_selection_polygon_volume over selection.h. Open3D names
// the orthogonal axis by a string ("X", "Y", "Z"); the C API by O3D_AXIS_*.
#include "generated/selection_methods.h"

namespace o3dpy {
namespace {

using VolumeHandle = Handle<o3d_selection_polygon_volume_t, &o3d_selection_polygon_volume_destroy>;

struct PyVolume {
    std::shared_ptr<VolumeHandle> h;
    explicit PyVolume(o3d_selection_polygon_volume_t* raw) : h(std::make_shared<VolumeHandle>(raw)) {}
};

PyVolume new_volume() {
    o3d_selection_polygon_volume_t* raw = nullptr;
    check(o3d_selection_polygon_volume_create(&raw));
    return PyVolume(raw);
}

std::string axis_name(const PyVolume& v) {
    o3d_axis axis = O3D_AXIS_Y;
    locked_const(v.h, [&](const o3d_selection_polygon_volume_t* p) {
        return o3d_selection_polygon_volume_get_orthogonal_axis(&axis, p);
    });
    return std::string(1, char('X' + axis));
}

void set_axis(PyVolume& v, const std::string& name) {
    if (name.size() != 1 || !std::strchr("XYZxyz", name[0]))
        invalid("orthogonal_axis must be \"X\", \"Y\" or \"Z\", got \"" + name + "\"");
    const o3d_axis axis = (name[0] | 0x20) - 'x';
    locked_mut(v.h, [&](o3d_selection_polygon_volume_t* p) { return o3d_selection_polygon_volume_set_orthogonal_axis(p, axis); });
}

py::object polygon(const PyVolume& v) {
    std::vector<double> corners;
    locked_const(v.h, [&](const o3d_selection_polygon_volume_t* p) {
        size_t n = 0;
        o3d_status s = o3d_selection_polygon_volume_get_bounding_polygon(nullptr, 0, &n, p);
        if (s != O3D_OK) return s;
        corners.resize(3 * n);
        return o3d_selection_polygon_volume_get_bounding_polygon(corners.data(), n, &n, p);
    });
    py::array_t<double> rows({py::ssize_t(corners.size() / 3), py::ssize_t(3)});
    if (!corners.empty()) std::memcpy(rows.mutable_data(), corners.data(), corners.size() * sizeof(double));
    return py::module_::import("o3d.utility").attr("Vector3dVector")(rows);
}

void set_polygon(PyVolume& v, py::handle corners) {
    const py::array_t<double> rows = rows3_f64(corners, "bounding_polygon");
    locked_mut(v.h, [&](o3d_selection_polygon_volume_t* p) {
        return o3d_selection_polygon_volume_set_bounding_polygon(p, rows.size() ? rows.data() : nullptr, size_t(rows.shape(0)));
    });
}

/// `f(volume, cloud)` with both locked for reading (the GIL released).
template <typename F>
void with_cloud(const PyVolume& v, const PyPointCloud& cloud, F&& f) {
    std::shared_lock<std::shared_mutex> volume_lock(v.h->mutex);
    locked_const(cloud.h, [&](const o3d_pointcloud_t* pc) { return f(v.h->p, pc); });
}

}  // namespace

void define_selection(py::module_& m) {
    py::class_<PyVolume> cls(m, "SelectionPolygonVolume",
                         "A prism: a polygon (bounding_polygon) across one axis (orthogonal_axis: \"X\", \"Y\" or "
                         "\"Z\"), from axis_min to axis_max along it. Cropping keeps what lies inside.");
    def_selection_polygon_volume_methods(cls);
    cls.def(py::init(&new_volume), "An empty volume (axis Y, range [0, 0], no polygon).")
        .def_property("orthogonal_axis", &axis_name, &set_axis, "\"X\", \"Y\" or \"Z\".")
        .def_property("bounding_polygon", &polygon, &set_polygon,
                      "The corners (Vector3dVector); the coordinate along the orthogonal axis is ignored.")
        .def(
            "crop_in_polygon",
            [](const PyVolume& v, const PyPointCloud& cloud) {
                std::vector<int32_t> indices;
                with_cloud(v, cloud, [&](const o3d_selection_polygon_volume_t* p, const o3d_pointcloud_t* pc) {
                    size_t n = 0;
                    o3d_status s = o3d_selection_polygon_volume_crop_in_polygon(nullptr, 0, &n, p, pc);
                    if (s != O3D_OK) return s;
                    indices.resize(n);
                    return o3d_selection_polygon_volume_crop_in_polygon(indices.data(), n, &n, p, pc);
                });
                return int_list(indices.data(), indices.size());
            },
            py::arg("input"), "Indices of the points inside, ascending.");
    m.def(
        "read_selection_polygon_volume",
        [](py::handle filename) {
            const std::string path = path_of(filename);
            o3d_selection_polygon_volume_t* out = nullptr;
            check(nogil([&] { return o3d_selection_polygon_volume_read_json(&out, path.c_str()); }), path);
            return PyVolume(out);
        },
        py::arg("filename"), "A SelectionPolygonVolume from Open3D's JSON file.");
}

}  // namespace o3dpy
