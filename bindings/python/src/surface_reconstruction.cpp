// SPDX-License-Identifier: MIT
// Surface reconstruction from point clouds (trianglemesh.h): Poisson, ball pivoting and alpha shapes, as the
// private calls under o3d/_surface_reconstruction.py (which adds Open3D's names, the progress bar and the
// callback). Each C call runs with the GIL released under the cloud's shared lock; its progress callback takes
// the GIL back to check Ctrl-C and call the Python callable, whose exception is re-raised after the call.
#include <memory>
#include <vector>

#include "registration_types.h"  // Progress, progress_trampoline, SharedLocks
#include "tetramesh_types.h"

namespace o3dpy {
namespace {

/// The fields of a C options struct as {name: value}, the keyword defaults of the Python wrappers.
template <typename C>
py::dict defaults_of(const C& o) {
    py::dict d;
    Fields<C>::each([&](const char* name, auto field, auto as, const char*) {
        using Py = typename decltype(as)::type;
        using F = std::remove_reference_t<decltype(std::declval<C&>().*field)>;
        if constexpr (!std::is_array_v<F>) d[name] = static_cast<Py>(o.*field);
    });
    return d;
}

/// Run `call(const o3d_pointcloud_t*)` (the extra locks taken by `lock_more`) with the GIL released, then
/// re-raise the progress callable's own exception (or KeyboardInterrupt) before the C status.
template <typename Lock, typename F>
void run_with_progress(const PyPointCloud& pcd, Progress& progress, Lock&& lock_more, F&& call) {
    CloudPtr cloud = pcd.h;
    o3d_status s;
    {
        py::gil_scoped_release release;
        SharedLocks locks;
        locks.add(cloud->mutex);
        lock_more(locks);
        s = call(static_cast<const o3d_pointcloud_t*>(cloud->p));
    }
    progress.rethrow();
    check(s);
}

/// o3d_progress_options_t for one call: `num_threads` and the trampoline over `progress` (always set, so Ctrl-C
/// cancels even without a Python callable).
o3d_progress_options_t progress_options(int32_t num_threads, Progress& progress) {
    o3d_progress_options_t o = init_of(&o3d_progress_options_init);
    o.num_threads = num_threads;
    o.progress = &progress_trampoline;
    o.user_data = &progress;
    return o;
}

/// A feature's values in order (the densities: one per mesh vertex).
py::array_t<double> feature_values(o3d_feature_t* f) {
    size_t rows = 0, cols = 0;
    check(o3d_feature_array_shape(&rows, &cols, f, O3D_FEATURE_DATA));
    py::array_t<double> out((py::ssize_t)(rows * cols));
    if (rows && cols) check(o3d_feature_get_array(out.mutable_data(), rows, &rows, f, O3D_FEATURE_DATA));
    return out;
}

py::tuple poisson(const PyPointCloud& pcd, int64_t depth, double width, double scale, bool linear_fit,
                  int64_t num_threads, py::object callback) {
    o3d_poisson_options_t o = init_of(&o3d_poisson_options_init);
    o.depth = int32_of(depth, "depth");
    o.width = width;
    o.scale = scale;
    o.linear_fit = linear_fit ? 1 : 0;
    o.num_threads = int32_of(num_threads, "n_threads");
    Progress progress(std::move(callback));
    o.progress = &progress_trampoline;
    o.user_data = &progress;
    o3d_trianglemesh_t* mesh = nullptr;
    o3d_feature_t* densities = nullptr;
    run_with_progress(pcd, progress, [](SharedLocks&) {}, [&](const o3d_pointcloud_t* pc) {
        return o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, &o);
    });
    std::unique_ptr<o3d_feature_t, void (*)(o3d_feature_t*)> owned(densities, &o3d_feature_destroy);
    PyTriangleMesh out(mesh);
    return py::make_tuple(std::move(out), feature_values(owned.get()));
}

PyTriangleMesh ball_pivoting(const PyPointCloud& pcd, py::handle radii, int64_t num_threads, py::object callback) {
    py::array_t<double> r = double_values(radii, "radii");
    Progress progress(std::move(callback));
    const o3d_progress_options_t o = progress_options(int32_of(num_threads, "num_threads"), progress);
    o3d_trianglemesh_t* mesh = nullptr;
    run_with_progress(pcd, progress, [](SharedLocks&) {}, [&](const o3d_pointcloud_t* pc) {
        return o3d_trianglemesh_create_from_point_cloud_ball_pivoting(&mesh, pc, r.size() ? r.data() : nullptr,
                                                                      (size_t)r.size(), &o);
    });
    return PyTriangleMesh(mesh);
}

PyTriangleMesh alpha_shape(const PyPointCloud& pcd, double alpha, py::handle tetra_mesh, py::handle pt_map,
                           int64_t num_threads, py::object callback) {
    std::shared_ptr<Geom<o3d_tetramesh_t>::H> tetras;  // kept alive (and locked) for the call
    std::vector<int32_t> map;
    if (!tetra_mesh.is_none()) {
        if (!py::isinstance<PyTetraMesh>(tetra_mesh))
            invalid("tetra_mesh: expected an o3d.geometry.TetraMesh or None");
        if (pt_map.is_none()) invalid("pt_map: required with tetra_mesh (TetraMesh.create_from_point_cloud's map)");
        tetras = tetra_mesh.cast<const PyTetraMesh&>().h;
        map = int32_values(pt_map, "pt_map");
    }
    Progress progress(std::move(callback));
    const o3d_progress_options_t o = progress_options(int32_of(num_threads, "num_threads"), progress);
    o3d_trianglemesh_t* mesh = nullptr;
    run_with_progress(
        pcd, progress, [&](SharedLocks& locks) { if (tetras) locks.add(tetras->mutex); },
        [&](const o3d_pointcloud_t* pc) {
            return o3d_trianglemesh_create_from_point_cloud_alpha_shape(&mesh, pc, alpha, tetras ? tetras->p : nullptr,
                                                                        map.data(), map.size(), &o);
        });
    return PyTriangleMesh(mesh);
}

}  // namespace

void define_surface_reconstruction(py::module_& m) {
    // Keyword defaults of the Python wrappers, from o3d_poisson_options_init and o3d_progress_options_init.
    m.attr("_poisson_defaults") = defaults_of(init_of(&o3d_poisson_options_init));
    m.attr("_progress_defaults") = defaults_of(init_of(&o3d_progress_options_init));
    m.def("_create_from_point_cloud_poisson", &poisson, py::arg("pcd"), py::arg("depth"), py::arg("width"),
          py::arg("scale"), py::arg("linear_fit"), py::arg("num_threads"), py::arg("progress"),
          "(TriangleMesh, densities as a float64 array) of o3d_trianglemesh_create_from_point_cloud_poisson.");
    m.def("_create_from_point_cloud_ball_pivoting", &ball_pivoting, py::arg("pcd"), py::arg("radii"),
          py::arg("num_threads"), py::arg("progress"), "o3d_trianglemesh_create_from_point_cloud_ball_pivoting.");
    m.def("_create_from_point_cloud_alpha_shape", &alpha_shape, py::arg("pcd"), py::arg("alpha"),
          py::arg("tetra_mesh"), py::arg("pt_map"), py::arg("num_threads"), py::arg("progress"),
          "o3d_trianglemesh_create_from_point_cloud_alpha_shape (tetra_mesh None: computed from pcd).");
}

}  // namespace o3dpy
