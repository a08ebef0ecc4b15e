// SPDX-License-Identifier: MIT
// o3d.pipelines.color_map over color_map.h: RigidOptimizerOption, NonRigidOptimizerOption and the two optimizers,
// under Open3D's names. The options' fields come from the header (def_fields); each call runs with the GIL released
// and the mesh and images locked shared.
#include "registration_types.h"

namespace o3dpy {
namespace {

template <typename C, o3d_status (*Init)(C*, uint32_t)>
struct Option {
    C o = init_of(Init);
};
using RigidOption = Option<o3d_color_map_rigid_options_t, &o3d_color_map_rigid_options_init>;
using NonRigidOption = Option<o3d_color_map_non_rigid_options_t, &o3d_color_map_non_rigid_options_init>;

/// run_rigid_optimizer / run_non_rigid_optimizer: (coloured mesh, refined trajectory).
template <typename O, auto Run>
py::tuple run(const PyTriangleMesh& mesh, py::iterable images, const PyTrajectory& trajectory,
              const O& option) {
    auto m = mesh.h;
    auto t = trajectory.h;  // kept alive while the GIL is released
    std::vector<RgbdPtr> held;
    std::vector<const o3d_rgbd_image_t*> raw;
    for (py::handle image : images) {
        if (!py::isinstance<PyRGBDImage>(image)) throw py::type_error("imgs_rgbd: expected a list of o3d.geometry.RGBDImage");
        held.push_back(image.cast<const PyRGBDImage&>().h);
        raw.push_back(held.back()->p);
    }
    o3d_trianglemesh_t* out_mesh = nullptr;
    o3d_camera_trajectory_t* out_trajectory = nullptr;
    o3d_status s;
    {
        py::gil_scoped_release release;
        SharedLocks locks;
        locks.add(m->mutex);
        for (const auto& image : held) locks.add(image->mutex);
        s = Run(&out_mesh, &out_trajectory, m->p, raw.data(), raw.size(), t.get(), &option.o);
    }
    check(s);
    return py::make_tuple(PyTriangleMesh(out_mesh), PyTrajectory(out_trajectory));
}

template <typename O>
py::class_<O> def_option(py::module_& m, const char* name, const char* doc) {
    py::class_<O> cls(m, name, doc);
    def_fields(cls);
    def_fields_init(cls, "The fields in Open3D's order, by position or keyword; the rest keep the defaults.");
    return cls;
}

}  // namespace

void define_color_map(py::module_& m) {
    def_option<RigidOption>(m, "RigidOptimizerOption", "Open3D's RigidOptimizerOption (its C++ defaults).");
    def_option<NonRigidOption>(m, "NonRigidOptimizerOption", "Open3D's NonRigidOptimizerOption (its C++ defaults).");
    const char* doc = "(colored mesh, refined trajectory): imgs_rgbd[i] was taken from camera_trajectory's pose i; "
                      "colour 8-bit RGB (convert_rgb_to_intensity=False) or float intensity, depth float metres.";
    m.def("run_rigid_optimizer", &run<RigidOption, &o3d_color_map_run_rigid_optimizer>, py::arg("mesh"),
          py::arg("imgs_rgbd"), py::arg("camera_trajectory"), py::arg("option") = RigidOption(), doc);
    m.def("run_non_rigid_optimizer", &run<NonRigidOption, &o3d_color_map_run_non_rigid_optimizer>, py::arg("mesh"),
          py::arg("imgs_rgbd"), py::arg("camera_trajectory"), py::arg("option") = NonRigidOption(), doc);
}

}  // namespace o3dpy
