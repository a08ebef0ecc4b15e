// SPDX-License-Identifier: MIT
// The extension module o3d._o3d. Registered in two passes, as Open3D's open3d_pybind.cpp: first
// every class is declared (so signatures can name each other), then methods are defined. The
// pure-Python package (bindings/python/o3d) sorts the names into Open3D's submodules.
#include "geometry_types.h"

namespace o3dpy {
// visualization.cpp: RenderOption and the offscreen renderer (o3d.visualization, .rendering).
void declare_visualization(py::module_& m);
void define_visualization(py::module_& m);
// visualizer.cpp: the viewer (Visualizer and its variants, ViewControl).
void declare_visualizer(py::module_& m);
void define_visualizer(py::module_& m);
void define_selection(py::module_& m);
void define_odometry(py::module_& m);
void define_integration(py::module_& m);
void define_color_map(py::module_& m);
void define_reconstruction(py::module_& m);
// tetramesh.cpp, surface_reconstruction.cpp (tetramesh_types.h) and keypoint.cpp.
void declare_tetramesh(py::module_& m);
void define_tetramesh(py::module_& m);
void define_surface_reconstruction(py::module_& m);
void define_keypoint(py::module_& m);
}  // namespace o3dpy

PYBIND11_MODULE(_o3d, m) {
    m.doc() = "o3d native extension (pybind11 over the o3d C API). Import o3d, not this module.";
    namespace o = o3dpy;
    o::declare_errors(m);
    o::declare_arrays(m);
    o::declare_utility(m);
    o::declare_pointcloud(m);
    o::declare_kdtree(m);
    o::declare_io(m);
    o::declare_registration(m);
    o::declare_image(m);
    o::declare_camera(m);
    o::declare_trianglemesh_enums(m);
    o::declare_trianglemesh(m);
    o::declare_tetramesh(m);
    o::declare_lineset(m);
    o::declare_voxelgrid(m);
    o::declare_octree(m);
    o::declare_halfedgemesh(m);
    o::declare_visualization(m);
    o::declare_visualizer(m);

    o::define_utility(m);
    o::define_pointcloud(m);
    o::define_pointcloud_tools(m);
    o::define_kdtree(m);
    o::define_io(m);
    o::define_registration(m);
    o::define_image(m);
    o::define_camera(m);
    o::define_trianglemesh(m);
    o::define_trianglemesh_processing(m);
    o::define_rgbd(m);
    o::define_io_geometry(m);
    o::define_boundingbox(m);
    o::define_hull(m);
    o::define_lineset(m);
    o::define_voxelgrid(m);
    o::define_octree(m);
    o::define_visualization(m);
    o::define_visualizer(m);
    o::define_selection(m);
    o::define_odometry(m);
    o::define_integration(m);
    o::define_color_map(m);
    o::define_reconstruction(m);
    o::define_tetramesh(m);
    o::define_surface_reconstruction(m);
    o::define_keypoint(m);
    o::define_geometry_algorithms(m);
    o::define_halfedgemesh(m);
}
