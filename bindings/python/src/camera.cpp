// SPDX-License-Identifier: MIT
// o3d.camera: PinholeCameraIntrinsic (the C value struct), PinholeCameraIntrinsicParameters presets,
// PinholeCameraParameters (intrinsic + 4x4 world-to-camera extrinsic) and PinholeCameraTrajectory over
// o3d_camera_trajectory_t (camera.h), with Open3D 0.20's constructors and attribute names.
#include "geometry_types.h"

namespace o3dpy {

PyTrajectory::PyTrajectory() {
    o3d_camera_trajectory_t* raw = nullptr;
    check(o3d_camera_trajectory_create(&raw));
    h.reset(raw, &o3d_camera_trajectory_destroy);
}

namespace {

int32_t dimension(int64_t v, const char* what) {
    if (v < -1 || v > INT32_MAX) invalid(std::string(what) + " is out of range: " + std::to_string(v));
    return (int32_t)v;
}

PyIntrinsic from_values(int64_t width, int64_t height, double fx, double fy, double cx, double cy) {
    PyIntrinsic i;
    i.v.width = dimension(width, "width");
    i.v.height = dimension(height, "height");
    i.v.fx = fx;
    i.v.fy = fy;
    i.v.cx = cx;
    i.v.cy = cy;
    return i;
}

PyIntrinsic from_matrix(int64_t width, int64_t height, py::handle matrix) {
    auto k = as_mat3(matrix, "intrinsic_matrix");
    if (k[1] != 0.0) invalid("intrinsic_matrix: a non-zero skew (K[0, 1]) is not supported");
    return from_values(width, height, k[0], k[4], k[2], k[5]);
}

PyIntrinsic from_preset(IntrinsicPreset preset) {
    PyIntrinsic i;
    check(o3d_pinhole_intrinsic_set_preset(&i.v, (int32_t)preset));
    return i;
}

py::array intrinsic_matrix(const PyIntrinsic& i) {
    const double k[9] = {i.v.fx, 0.0, i.v.cx, 0.0, i.v.fy, i.v.cy, 0.0, 0.0, 1.0};
    return mat_to_array(k, 3, 3);
}

/// The extrinsic as a writable (4, 4) view into the parameters object (as Open3D's Eigen member).
py::array extrinsic_view(py::object self) {
    auto& p = self.cast<PyCameraParameters&>();
    return py::array(py::dtype::of<double>(), std::vector<py::ssize_t>{4, 4},
                     std::vector<py::ssize_t>{4 * sizeof(double), sizeof(double)}, p.extrinsic.data(), self);
}

py::list trajectory_parameters(const PyTrajectory& self) {
    size_t n = 0;
    check(o3d_camera_trajectory_size(&n, self.h.get()));
    py::list out;
    for (size_t i = 0; i < n; ++i) {
        PyCameraParameters p;
        check(o3d_camera_trajectory_get(&p.intrinsic.v, p.extrinsic.data(), self.h.get(), i));
        out.append(py::cast(p));
    }
    return out;
}

void set_trajectory_parameters(PyTrajectory& self, py::iterable params) {
    std::vector<PyCameraParameters> list;
    for (py::handle item : params) {
        if (!py::isinstance<PyCameraParameters>(item))
            throw py::type_error("parameters: expected a list of o3d.camera.PinholeCameraParameters");
        list.push_back(item.cast<PyCameraParameters>());
    }
    if (list.empty()) {
        check(o3d_camera_trajectory_clear(self.h.get()));
        return;
    }
    // Fill a fresh trajectory and swap it in only when every pose was accepted: a rejected list
    // leaves the old one as it was.
    PyTrajectory fresh;
    for (const auto& p : list) check(o3d_camera_trajectory_append(fresh.h.get(), &p.intrinsic.v, p.extrinsic.data()));
    self.h = std::move(fresh.h);
}

}  // namespace

void declare_camera(py::module_& m) {
    def_enum<IntrinsicPreset>(m);
    py::class_<PyIntrinsic>(m, "PinholeCameraIntrinsic", "Image size and pinhole intrinsics fx, fy, cx, cy (pixels).");
    py::class_<PyCameraParameters>(m, "PinholeCameraParameters", "An intrinsic and a 4x4 world-to-camera extrinsic.");
    py::class_<PyTrajectory>(m, "PinholeCameraTrajectory", "A list of PinholeCameraParameters.");
}

void define_camera(py::module_& m) {
    auto intr = static_cast<py::class_<PyIntrinsic>>(m.attr("PinholeCameraIntrinsic"));
    intr.def(py::init([]() { return from_values(-1, -1, 0, 0, 0, 0); }), "width = height = -1, all-zero matrix (as Open3D).")
        .def(py::init([](const PyIntrinsic& other) { return other; }), py::arg("intrinsic"))
        .def(py::init(&from_matrix), py::arg("width"), py::arg("height"), py::arg("intrinsic_matrix"))
        .def(py::init(&from_values), py::arg("width"), py::arg("height"), py::arg("fx"), py::arg("fy"), py::arg("cx"),
             py::arg("cy"))
        .def(py::init(&from_preset), py::arg("param"))
        .def("__copy__", [](const PyIntrinsic& self) { return self; })
        .def("__deepcopy__", [](const PyIntrinsic& self, py::handle) { return self; })
        .def_property(
            "width", [](const PyIntrinsic& self) { return self.v.width; },
            [](PyIntrinsic& self, int64_t w) { self.v.width = dimension(w, "width"); })
        .def_property(
            "height", [](const PyIntrinsic& self) { return self.v.height; },
            [](PyIntrinsic& self, int64_t h) { self.v.height = dimension(h, "height"); })
        .def_property(
            "intrinsic_matrix", &intrinsic_matrix,
            [](PyIntrinsic& self, py::handle k) { self = from_matrix(self.v.width, self.v.height, k); },
            "3x3 [[fx, 0, cx], [0, fy, cy], [0, 0, 1]] (a copy; assign a matrix to change it).")
        .def("get_focal_length", [](const PyIntrinsic& self) { return py::make_tuple(self.v.fx, self.v.fy); })
        .def("get_principal_point", [](const PyIntrinsic& self) { return py::make_tuple(self.v.cx, self.v.cy); })
        .def("get_skew", [](const PyIntrinsic&) { return 0.0; })
        .def("is_valid", [](const PyIntrinsic& self) { return self.v.width > 0 && self.v.height > 0; })
        .def(
            "set_intrinsics",
            [](PyIntrinsic& self, int64_t width, int64_t height, double fx, double fy, double cx, double cy) {
                self = from_values(width, height, fx, fy, cx, cy);
            },
            py::arg("width"), py::arg("height"), py::arg("fx"), py::arg("fy"), py::arg("cx"), py::arg("cy"))
        .def("__eq__",
             [](const PyIntrinsic& a, const PyIntrinsic& b) {
                 return a.v.width == b.v.width && a.v.height == b.v.height && a.v.fx == b.v.fx && a.v.fy == b.v.fy &&
                        a.v.cx == b.v.cx && a.v.cy == b.v.cy;
             })
        .def("__repr__", [](const PyIntrinsic& self) {
            return "PinholeCameraIntrinsic with width = " + std::to_string(self.v.width) +
                   " and height = " + std::to_string(self.v.height) + ".\nAccess intrinsics with intrinsic_matrix.";
        });

    auto params = static_cast<py::class_<PyCameraParameters>>(m.attr("PinholeCameraParameters"));
    params.def(py::init<>(), "Default intrinsic and an identity extrinsic.")
        .def(py::init([](const PyCameraParameters& other) { return other; }), py::arg("parameters"))
        .def("__copy__", [](const PyCameraParameters& self) { return self; })
        .def("__deepcopy__", [](const PyCameraParameters& self, py::handle) { return self; })
        .def_readwrite("intrinsic", &PyCameraParameters::intrinsic, "PinholeCameraIntrinsic.")
        .def_property(
            "extrinsic", &extrinsic_view,
            [](PyCameraParameters& self, py::handle e) { self.extrinsic = as_mat4(e, "extrinsic"); },
            "(4, 4) world-to-camera matrix (a writable view, as Open3D's).")
        .def("__repr__", [](const PyCameraParameters&) { return std::string("PinholeCameraParameters class."); });

    auto traj = static_cast<py::class_<PyTrajectory>>(m.attr("PinholeCameraTrajectory"));
    traj.def(py::init<>())
        .def(py::init([](const PyTrajectory& other) {
                 PyTrajectory copy;
                 set_trajectory_parameters(copy, trajectory_parameters(other));
                 return copy;
             }),
             py::arg("trajectory"))
        .def_property("parameters", &trajectory_parameters, &set_trajectory_parameters,
                      "List of PinholeCameraParameters (a copy, as Open3D's; assign a list to replace it). Each "
                      "extrinsic's last row must be (0, 0, 0, 1).")
        .def("__len__",
             [](const PyTrajectory& self) {
                 size_t n = 0;
                 check(o3d_camera_trajectory_size(&n, self.h.get()));
                 return n;
             })
        .def("__repr__", [](const PyTrajectory&) { return std::string("PinholeCameraTrajectory class."); });
}

}  // namespace o3dpy
