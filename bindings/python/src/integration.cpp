// SPDX-License-Identifier: MIT
// o3d.pipelines.integration over integration.h: TSDFVolume and its uniform and scalable kinds under Open3D's names.
// Constructors, extraction and properties are generated (generated/integration_methods.h); here: integrate (an
// intrinsic value and a locked image) and the uniform volume's arrays.
#include "generated/integration_methods.h"

namespace o3dpy {
namespace {

struct PyTSDFVolume {
    std::shared_ptr<Handle<o3d_tsdf_volume_t, &o3d_tsdf_volume_destroy>> h;
    explicit PyTSDFVolume(o3d_tsdf_volume_t* raw) : h(std::make_shared<decltype(h)::element_type>(raw)) {}
};
struct PyUniformTSDFVolume : PyTSDFVolume {
    using PyTSDFVolume::PyTSDFVolume;
};
struct PyScalableTSDFVolume : PyTSDFVolume {
    using PyTSDFVolume::PyTSDFVolume;
};

/// extract_volume_tsdf / _color: an (N, cols) float32 array of a uniform volume.
template <o3d_status (*get)(float*, size_t, size_t*, const o3d_tsdf_volume_t*), py::ssize_t cols>
py::array_t<float> volume_array(const PyTSDFVolume& v) {
    size_t rows = 0;
    locked_const(v.h, [&](const o3d_tsdf_volume_t* p) { return get(nullptr, 0, &rows, p); });
    py::array_t<float> out(std::vector<py::ssize_t>{py::ssize_t(rows), cols});
    float* data = out.mutable_data();
    locked_const(v.h, [&](const o3d_tsdf_volume_t* p) { return get(data, rows, &rows, p); });
    return out;
}

}  // namespace

void define_integration(py::module_& m) {
    def_enum<TSDFVolumeColorType>(m);
    py::class_<PyTSDFVolume> base(m, "TSDFVolume", "A truncated signed distance volume: integrate RGB-D frames, "
                                                   "extract the surface.");
    def_tsdf_volume_methods(base);
    base.def(
        "integrate",
        [](PyTSDFVolume& self, const PyRGBDImage& image, const PyIntrinsic& intrinsic, py::handle extrinsic) {
            const std::array<double, 16> e = as_mat4(extrinsic, "extrinsic");
            RgbdPtr frame = image.h;
            locked_mut(self.h, [&](o3d_tsdf_volume_t* p) {
                std::shared_lock<std::shared_mutex> frame_lock(frame->mutex);
                return o3d_tsdf_volume_integrate(p, frame->p, &intrinsic.v, e.data());
            });
        },
        py::arg("image"), py::arg("intrinsic"), py::arg("extrinsic"),
        "Fuse an RGBDImage seen by `intrinsic` from `extrinsic` (4x4 world to camera). Depth is float metres; colour "
        "is 8-bit RGB for RGB8 (convert_rgb_to_intensity=False), float intensity for Gray32.");

    py::class_<PyUniformTSDFVolume, PyTSDFVolume> uniform(m, "UniformTSDFVolume",
                                                         "resolution^3 voxels of a cube of edge `length` from `origin`.");
    def_uniformtsdf_volume_methods(uniform);
    uniform.def("extract_volume_tsdf", &volume_array<&o3d_tsdf_volume_extract_volume_tsdf, 2>,
                "(resolution^3, 2) float32: tsdf and weight of voxel (x, y, z) at row (x * resolution + y) * resolution + z.");
    uniform.def("extract_volume_color", &volume_array<&o3d_tsdf_volume_extract_volume_color, 3>,
                "(resolution^3, 3) float32 colours in [0, 1], rows as extract_volume_tsdf.");
    py::class_<PyScalableTSDFVolume, PyTSDFVolume> scalable(
        m, "ScalableTSDFVolume", "Blocks of volume_unit_resolution^3 voxels, opened around the surface frames see.");
    def_scalabletsdf_volume_methods(scalable);
}

}  // namespace o3dpy
