// SPDX-License-Identifier: MIT
// o3d.pipelines.odometry over odometry.h: OdometryOption, the two Jacobian classes and compute_rgbd_odometry,
// under Open3D's names. The call releases the GIL.
#include "registration_types.h"

namespace o3dpy {
namespace {

/// OdometryOption: the C options plus the iterations per pyramid level (a parameter of the C call).
struct OdometryOption {
    o3d_odometry_options_t o{};
    std::vector<int32_t> iterations{20, 10, 5};
    OdometryOption() { check(o3d_odometry_options_init(&o, sizeof(o))); }
};

/// RGBDOdometryJacobian and its two kinds.
struct Jacobian {
    o3d_odometry_jacobian kind;
};
struct ColorTerm : Jacobian {
    ColorTerm() : Jacobian{O3D_ODOMETRY_JACOBIAN_COLOR_TERM} {}
};
struct HybridTerm : Jacobian {
    HybridTerm() : Jacobian{O3D_ODOMETRY_JACOBIAN_HYBRID_TERM} {}
};

std::vector<int32_t> as_iterations(py::handle levels) {
    if (levels.is_none()) return {20, 10, 5};  // Open3D's default
    std::vector<int32_t> out;
    for (py::handle n : py::iter(levels)) out.push_back(int32_of(py::cast<int64_t>(n), "iteration_number_per_pyramid_level"));
    if (out.empty()) invalid("iteration_number_per_pyramid_level is empty");
    return out;
}

}  // namespace

void define_odometry(py::module_& m) {
    py::class_<OdometryOption> option(m, "OdometryOption", "Open3D's OdometryOption.");
    option
        .def(py::init([](py::handle levels, double depth_diff_max, double depth_min, double depth_max) {
                 OdometryOption o;
                 o.iterations = as_iterations(levels);
                 o.o.depth_diff_max = depth_diff_max;
                 o.o.depth_min = depth_min;
                 o.o.depth_max = depth_max;
                 return o;
             }),
             py::arg("iteration_number_per_pyramid_level") = py::none(),
             py::arg("depth_diff_max") = 0.03, py::arg("depth_min") = 0.0, py::arg("depth_max") = 4.0)
        .def_property(
            "iteration_number_per_pyramid_level",
            [](const OdometryOption& o) {
                py::list levels;
                for (int32_t n : o.iterations) levels.append(n);
                return py::module_::import("o3d.utility").attr("IntVector")(levels);
            },
            [](OdometryOption& o, py::handle levels) { o.iterations = as_iterations(levels); },
            "Iterations per pyramid level, coarsest first; its length is the number of levels.")
        .def("__repr__", [](const OdometryOption& o) {
            std::string levels;
            for (int32_t n : o.iterations) levels += (levels.empty() ? "" : ", ") + std::to_string(n);
            return "OdometryOption\n> iteration_number_per_pyramid_level : [" + levels +
                   "]\n> depth_diff_max : " + std::to_string(o.o.depth_diff_max) +
                   "\n> depth_min : " + std::to_string(o.o.depth_min) + "\n> depth_max : " + std::to_string(o.o.depth_max);
        });
    def_fields(option);

    py::class_<Jacobian>(m, "RGBDOdometryJacobian", "The error terms odometry minimizes.");
    py::class_<ColorTerm, Jacobian>(m, "RGBDOdometryJacobianFromColorTerm",
                                    "Intensity only (Steinbruecker et al. 2011).")
        .def(py::init<>());
    py::class_<HybridTerm, Jacobian>(m, "RGBDOdometryJacobianFromHybridTerm",
                                     "Intensity and depth (Park et al. 2017).")
        .def(py::init<>());

    m.def(
        "compute_rgbd_odometry",
        [](const PyRGBDImage& source, const PyRGBDImage& target, const PyIntrinsic& intrinsic, py::handle odo_init,
           const Jacobian& jacobian, const OdometryOption& option) {
            const std::array<double, 16> init = mat4_or_identity(odo_init, "odo_init");
            o3d_bool success = 0;
            py::array_t<double> t(std::vector<py::ssize_t>{4, 4}), info(std::vector<py::ssize_t>{6, 6});
            double *tp = t.mutable_data(), *ip = info.mutable_data();  // taken with the GIL held
            RgbdPtr a = source.h, b = target.h;
            o3d_status s;
            {
                py::gil_scoped_release release;
                SharedLocks locks;
                locks.add(a->mutex);
                locks.add(b->mutex);
                s = o3d_odometry_compute_rgbd(&success, tp, ip, a->p, b->p, &intrinsic.v, init.data(), jacobian.kind,
                                              option.iterations.data(), option.iterations.size(), &option.o);
            }
            check(s);
            return py::make_tuple(success != 0, t, info);
        },
        py::arg("source"), py::arg("target"), py::arg("pinhole_camera_intrinsic"), py::arg("odo_init") = py::none(),
        py::arg("jacobian") = ColorTerm(), py::arg("option") = OdometryOption(),
        "(success, 4x4 transformation, 6x6 information) taking source onto target, from odo_init (None: "
        "identity). The images are float intensity and depth in metres (RGBDImage.create_from_color_and_depth's "
        "default). A pair that cannot be aligned gives success False with the identity.");
}

}  // namespace o3dpy
