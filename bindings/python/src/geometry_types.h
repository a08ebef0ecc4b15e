// SPDX-License-Identifier: MIT
// Python-side holders of the mesh, image, RGB-D and camera handles (trianglemesh.h, image.h, rgbd.h,
// camera.h). Each owns its C handle through a shared_ptr so numpy views can keep it alive.
#pragma once

#include <functional>

#include "common.h"

namespace o3dpy {

using MeshHandle = Handle<o3d_trianglemesh_t, &o3d_trianglemesh_destroy>;
using MeshPtr = std::shared_ptr<MeshHandle>;
using ImageHandle = Handle<o3d_image_t, &o3d_image_destroy>;
using ImagePtr = std::shared_ptr<ImageHandle>;
using RgbdHandle = Handle<o3d_rgbd_image_t, &o3d_rgbd_image_destroy>;
using RgbdPtr = std::shared_ptr<RgbdHandle>;
using LineSetHandle = Handle<o3d_lineset_t, &o3d_lineset_destroy>;
using LineSetPtr = std::shared_ptr<LineSetHandle>;
using VoxelGridHandle = Handle<o3d_voxelgrid_t, &o3d_voxelgrid_destroy>;
using VoxelGridPtr = std::shared_ptr<VoxelGridHandle>;
using OctreeHandle = Handle<o3d_octree_t, &o3d_octree_destroy>;
using OctreePtr = std::shared_ptr<OctreeHandle>;

/// o3d.geometry.TriangleMesh; copy-on-write before resizing calls, as PyPointCloud.
struct PyTriangleMesh : Geom<o3d_trianglemesh_t> {
    using Geom::Geom;
    PyTriangleMesh();
    /// Open3D's adjacency_list (compute_adjacency_list fills it): per vertex its neighbours, ascending. Held by the
    /// Python object, not the C mesh, as Open3D holds it beside the arrays.
    std::vector<std::vector<int32_t>> adjacency;
};

/// o3d.geometry.Image. No C call resizes an image in place, so the pixel memory is fixed for the
/// handle's life and numpy views (buffer protocol) can point at it directly.
struct PyImage {
    ImagePtr h;
    bool readonly = false;  // parts of an RGBDImage are snapshots: writing them would change nothing
    explicit PyImage(o3d_image_t* raw) : h(std::make_shared<ImageHandle>(raw)) {}
    const o3d_image_t* get() const { return h->p; }
};

/// o3d.geometry.RGBDImage: the C handle plus read-only snapshots of its two images.
struct PyRGBDImage {
    RgbdPtr h;
    py::object color;
    py::object depth;
};

/// o3d.camera.PinholeCameraIntrinsic (a plain C value).
struct PyIntrinsic {
    o3d_pinhole_intrinsic_t v{};
};

/// o3d.camera.PinholeCameraParameters.
struct PyCameraParameters {
    PyIntrinsic intrinsic;
    std::array<double, 16> extrinsic{1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
};

/// The owner of a live RenderOption (an OffscreenRenderer, a Visualizer): an OptionEdit reads the owner's
/// option, applies `change` and, when `write`, sets the result, in one step (called with the GIL held;
/// it releases it for the C calls).
using OptionChange = std::function<o3d_status(o3d_render_option_t&)>;
using OptionEdit = std::function<o3d_status(const OptionChange& change, bool write)>;
/// An o3d.visualization.RenderOption whose fields read and write its owner's option (visualization.cpp).
py::object live_render_option(OptionEdit edit);
/// The read-change-write step of an OptionEdit over an owner's get/set_render_option pair.
template <typename T>
o3d_status edit_option(T* owner, o3d_status (*get)(o3d_render_option_t*, T*),
                       o3d_status (*set)(T*, const o3d_render_option_t*), const OptionChange& change, bool write) {
    o3d_render_option_t o{};
    o3d_status s = o3d_render_option_init(&o, (uint32_t)sizeof o);
    if (s == O3D_OK) s = get(&o, owner);
    if (s == O3D_OK) s = change(o);
    return s == O3D_OK && write ? set(owner, &o) : s;
}

/// o3d.camera.PinholeCameraTrajectory over o3d_camera_trajectory_t.
struct PyTrajectory {
    std::shared_ptr<o3d_camera_trajectory_t> h;
    PyTrajectory();
    explicit PyTrajectory(o3d_camera_trajectory_t* raw) : h(raw, &o3d_camera_trajectory_destroy) {}
};

/// Shared conversions of the new bindings.
std::string path_of(py::handle filename);
uint64_t seed_or_random(py::handle seed);
/// Non-negative int32 indices from a 1-D integer sequence (ValueError names `what`).
std::vector<int32_t> int32_indices(py::handle obj, const char* what);
/// One byte per entry (0 or 1) from a 1-D sequence of booleans or integers (ValueError names `what`).
std::vector<uint8_t> byte_mask(py::handle obj, const char* what);
py::array vec3_to_array(const double* v);
py::array mat_to_array(const double* v, size_t rows, size_t cols);
std::pair<std::array<double, 3>, std::array<double, 3>> aabb_bounds(py::handle box);
py::object make_aabb(const double* lo, const double* hi);
PyImage image_from_array(py::handle obj);

/// get_axis_aligned_bounding_box over `aabb` (the other spatial methods are generated: generated/*_methods.h).
template <typename G, typename T = typename G::C>
void def_aabb(py::class_<G>& cls, o3d_status (*aabb)(double*, double*, const T*)) {
    cls.def(
        "get_axis_aligned_bounding_box",
        [aabb](const G& self) {
            std::array<double, 3> lo{}, hi{};
            locked_const(self.h, [&](const T* p) { return aabb(lo.data(), hi.data(), p); });
            return make_aabb(lo.data(), hi.data());
        },
        "The axis-aligned bounding box (o3d.geometry.AxisAlignedBoundingBox).");
}

/// o3d.geometry.LineSet; copy-on-write before resizing calls, as PyPointCloud.
struct PyLineSet : Geom<o3d_lineset_t> {
    using Geom::Geom;
    PyLineSet();
};

/// o3d.geometry.VoxelGrid. Its arrays are only copied out (no views), so editing calls need no copy-on-write.
struct PyVoxelGrid {
    VoxelGridPtr h;
    explicit PyVoxelGrid(o3d_voxelgrid_t* raw) : h(std::make_shared<VoxelGridHandle>(raw)) {}
};

/// o3d.geometry.Octree.
struct PyOctree {
    OctreePtr h;
    explicit PyOctree(o3d_octree_t* raw) : h(std::make_shared<OctreeHandle>(raw)) {}
};

/// Oriented boxes are the pure-Python o3d.geometry.OrientedBoundingBox (center, R, extent).
bool is_obb(py::handle box);
o3d_obb_t obb_of(py::handle box);
py::object make_obb(const o3d_obb_t& obb);
/// An (N,3) float64 C-contiguous copy-free (when possible) view of any (N,3) array-like.
py::array_t<double> rows3_f64(py::handle obj, const char* what);
/// Python list of int from int32 values.
py::list int_list(const int32_t* v, size_t n);

/// An o3d_index_lists_t the binding owns (destroyed with it).
using IndexLists = std::unique_ptr<o3d_index_lists_t, void (*)(o3d_index_lists_t*)>;
inline IndexLists own_lists(o3d_index_lists_t* lists) { return IndexLists(lists, &o3d_index_lists_destroy); }
/// The rows of index lists, copied out (call without the GIL): offsets (num_lists + 1) and values.
struct IndexRows {
    std::vector<int64_t> offsets{0};
    std::vector<int32_t> values;
    size_t size() const { return offsets.size() - 1; }
};
o3d_status read_index_lists(IndexRows& out, const o3d_index_lists_t* lists);
/// Index lists as Open3D's Python shows them: a list of sets of int (adjacency_list), or a list of (n_i,) int32
/// numpy arrays (Open3D's List[IntVector]).
py::list index_rows_to_python(const IndexRows& rows, bool as_sets);
/// read_index_lists + index_rows_to_python of an owned handle (raises on failure).
py::list index_lists_to_python(const IndexLists& lists, bool as_sets);
/// Rows of `cols` values a C call copies out (`f(out, capacity, &count, handle)`, capacity and count in rows), under
/// the handle's shared lock with the GIL released: first into `guess` rows, again at the reported size when short.
template <typename T, typename H, typename F>
std::vector<T> read_rows(const std::shared_ptr<H>& h, size_t cols, size_t guess, F&& f) {
    std::vector<T> buf(guess * cols);
    size_t n = 0;
    locked_const(h, [&](auto p) {
        o3d_status s = f(buf.empty() ? nullptr : buf.data(), guess, &n, p);
        if (s == O3D_ERROR_BUFFER_TOO_SMALL || (s == O3D_OK && n > guess)) {
            o3d_clear_error();
            buf.resize(n * cols);
            s = f(buf.empty() ? nullptr : buf.data(), n, &n, p);
        }
        return s;
    });
    buf.resize(n * cols);
    return buf;
}
/// A numpy array of `shape` holding a copy of `v` (its size must be the shape's); read-only unless `writable`.
template <typename T>
py::array to_numpy(const std::vector<T>& v, std::vector<py::ssize_t> shape, bool writable = true) {
    py::array_t<T> a(shape);
    if (!v.empty()) std::memcpy(a.mutable_data(), v.data(), v.size() * sizeof(T));
    if (!writable) a.attr("setflags")(py::arg("write") = false);
    return std::move(a);
}
/// Ellipsoids are the pure-Python o3d.geometry.OrientedBoundingEllipsoid (center, R, radii).
o3d_obe_t obe_of(py::handle ellipsoid);
py::object make_obe(const o3d_obe_t& obe);

void declare_trianglemesh(py::module_& m);
void declare_trianglemesh_enums(py::module_& m);
void declare_image(py::module_& m);
void declare_camera(py::module_& m);
void define_trianglemesh(py::module_& m);
void define_trianglemesh_processing(py::module_& m);
void define_image(py::module_& m);
void define_rgbd(py::module_& m);
void define_camera(py::module_& m);
void define_io_geometry(py::module_& m);
void declare_lineset(py::module_& m);
void declare_voxelgrid(py::module_& m);
void declare_octree(py::module_& m);
void define_boundingbox(py::module_& m);
void define_hull(py::module_& m);
void define_lineset(py::module_& m);
void define_voxelgrid(py::module_& m);
void define_octree(py::module_& m);
void declare_halfedgemesh(py::module_& m);
void define_halfedgemesh(py::module_& m);
void define_geometry_algorithms(py::module_& m);

}  // namespace o3dpy
