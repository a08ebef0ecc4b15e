// SPDX-License-Identifier: MIT
// o3d.geometry.RGBDImage over o3d_rgbd_image_t (rgbd.h) and PointCloud.create_from_depth_image /
// create_from_rgbd_image. .color and .depth are read-only snapshots taken once at creation: the C
// handle owns the images the back-projection uses, so an edit through numpy could never reach it.
#include "geometry_types.h"

namespace o3dpy {
namespace {

const o3d_image_t* image_arg(const PyImage& img, const char* what) {
    if (!img.get()) invalid(std::string(what) + ": the image is empty");
    return img.get();
}

PyRGBDImage wrap(o3d_rgbd_image_t* raw) {
    PyRGBDImage r;
    r.h = std::make_shared<RgbdHandle>(raw);
    o3d_image_t* color = nullptr;
    o3d_image_t* depth = nullptr;
    check(o3d_rgbd_image_get_color(&color, raw));
    PyImage c(color);
    check(o3d_rgbd_image_get_depth(&depth, raw));
    PyImage d(depth);
    c.readonly = d.readonly = true;
    r.color = py::cast(std::move(c));
    r.depth = py::cast(std::move(d));
    return r;
}

PyRGBDImage from_dataset(int32_t format, const PyImage& color, const PyImage& depth, bool convert) {
    const o3d_image_t* c = image_arg(color, "color");
    const o3d_image_t* d = image_arg(depth, "depth");
    o3d_rgbd_image_t* out = nullptr;
    check(nogil([&] { return o3d_rgbd_image_create_from_dataset_format(&out, format, c, d, convert ? 1 : 0); }));
    return wrap(out);
}

const o3d_rgbd_image_t* rgbd_arg(const PyRGBDImage& r) {
    if (!r.h || !r.h->p) invalid("image: the RGBDImage is empty");
    return r.h->p;
}

/// extrinsic None -> NULL (identity in the C API), else a 4x4 matrix.
bool extrinsic_arg(py::handle extrinsic, std::array<double, 16>& out) {
    if (extrinsic.is_none()) return false;
    out = as_mat4(extrinsic, "extrinsic");
    return true;
}

void define_rgbd_class(py::module_& m) {
    const o3d_rgbd_options_t ro = init_of(&o3d_rgbd_options_init);
    py::class_<PyRGBDImage>(m, "RGBDImage",
                            "A color (or intensity) image and a float32 depth image in metres, of the same size.")
        .def(py::init([]() {
                 PyRGBDImage r;
                 r.color = py::cast(PyImage(nullptr));
                 r.depth = py::cast(PyImage(nullptr));
                 return r;
             }),
             "An empty RGB-D image.")
        .def_property_readonly(
            "color", [](const PyRGBDImage& self) { return self.color; },
            "The color (or 1-channel float intensity) image; a read-only snapshot.")
        .def_property_readonly(
            "depth", [](const PyRGBDImage& self) { return self.depth; },
            "The 1-channel float32 depth image in metres; a read-only snapshot.")
        .def("is_empty", [](const PyRGBDImage& self) { return !self.h || !self.h->p; })
        .def("__repr__",
             [](const PyRGBDImage& self) {
                 return "RGBDImage of size \nColor image : " + std::string(py::str(self.color)) +
                        "\nDepth image : " + std::string(py::str(self.depth));
             })
        .def_static(
            "create_from_color_and_depth",
            [](const PyImage& color, const PyImage& depth, double depth_scale, double depth_trunc,
               bool convert_rgb_to_intensity) {
                o3d_rgbd_options_t o = init_of(&o3d_rgbd_options_init);
                o.depth_scale = depth_scale;
                o.depth_trunc = depth_trunc;
                o.convert_rgb_to_intensity = convert_rgb_to_intensity ? 1 : 0;
                const o3d_image_t* c = image_arg(color, "color");
                const o3d_image_t* d = image_arg(depth, "depth");
                o3d_rgbd_image_t* out = nullptr;
                check(nogil([&] { return o3d_rgbd_image_create_from_color_and_depth(&out, c, d, &o); }));
                return wrap(out);
            },
            py::arg("color"), py::arg("depth"), py::arg("depth_scale") = ro.depth_scale, py::arg("depth_trunc") = ro.depth_trunc,
            py::arg("convert_rgb_to_intensity") = ro.convert_rgb_to_intensity != 0)
        .def_static(
            "create_from_redwood_format",
            [](const PyImage& c, const PyImage& d, bool convert) { return from_dataset(O3D_RGBD_FORMAT_REDWOOD, c, d, convert); },
            py::arg("color"), py::arg("depth"), py::arg("convert_rgb_to_intensity") = true)
        .def_static(
            "create_from_tum_format",
            [](const PyImage& c, const PyImage& d, bool convert) { return from_dataset(O3D_RGBD_FORMAT_TUM, c, d, convert); },
            py::arg("color"), py::arg("depth"), py::arg("convert_rgb_to_intensity") = true)
        .def_static(
            "create_from_sun_format",
            [](const PyImage& c, const PyImage& d, bool convert) { return from_dataset(O3D_RGBD_FORMAT_SUN, c, d, convert); },
            py::arg("color"), py::arg("depth"), py::arg("convert_rgb_to_intensity") = true)
        .def_static(
            "create_from_nyu_format",
            [](const PyImage& c, const PyImage& d, bool convert) { return from_dataset(O3D_RGBD_FORMAT_NYU, c, d, convert); },
            py::arg("color"), py::arg("depth"), py::arg("convert_rgb_to_intensity") = true);
}

}  // namespace

void define_rgbd(py::module_& m) {
    const o3d_depth_to_cloud_options_t dc = init_of(&o3d_depth_to_cloud_options_init);
    define_rgbd_class(m);
    auto cloud = static_cast<py::class_<PyPointCloud>>(m.attr("PointCloud"));
    cloud
        .def_static(
            "create_from_depth_image",
            [](const PyImage& depth, const PyIntrinsic& intrinsic, py::handle extrinsic, double depth_scale,
               double depth_trunc, int64_t stride, bool project_valid_depth_only) {
                if (stride < 1 || stride > INT32_MAX) invalid("stride must be >= 1");
                o3d_depth_to_cloud_options_t o = init_of(&o3d_depth_to_cloud_options_init);
                o.depth_scale = depth_scale;
                o.depth_trunc = depth_trunc;
                o.stride = (int32_t)stride;
                o.project_valid_depth_only = project_valid_depth_only ? 1 : 0;
                std::array<double, 16> e{};
                const bool has_e = extrinsic_arg(extrinsic, e);
                const o3d_image_t* d = image_arg(depth, "depth");
                const o3d_pinhole_intrinsic_t k = intrinsic.v;
                o3d_pointcloud_t* out = nullptr;
                check(nogil([&] {
                    return o3d_pointcloud_create_from_depth_image(&out, d, &k, has_e ? e.data() : nullptr, &o);
                }));
                return PyPointCloud(adopt(out));
            },
            py::arg("depth"), py::arg("intrinsic"), py::arg("extrinsic") = py::none(), py::arg("depth_scale") = dc.depth_scale,
            py::arg("depth_trunc") = dc.depth_trunc, py::arg("stride") = dc.stride,
            py::arg("project_valid_depth_only") = dc.project_valid_depth_only != 0,
            "Back-project a depth image (uint16 raw or float32 metres) through intrinsic, then to world "
            "coordinates with the inverse of extrinsic (world-to-camera; None: identity).")
        .def_static(
            "create_from_rgbd_image",
            [](const PyRGBDImage& image, const PyIntrinsic& intrinsic, py::handle extrinsic,
               bool project_valid_depth_only) {
                std::array<double, 16> e{};
                const bool has_e = extrinsic_arg(extrinsic, e);
                const o3d_rgbd_image_t* r = rgbd_arg(image);
                RgbdPtr keep = image.h;
                const o3d_pinhole_intrinsic_t k = intrinsic.v;
                o3d_pointcloud_t* out = nullptr;
                check(nogil([&] {
                    return o3d_pointcloud_create_from_rgbd_image(&out, r, &k, has_e ? e.data() : nullptr,
                                                                 project_valid_depth_only ? 1 : 0);
                }));
                return PyPointCloud(adopt(out));
            },
            py::arg("image"), py::arg("intrinsic"), py::arg("extrinsic") = py::none(),
            py::arg("project_valid_depth_only") = true, "As create_from_depth_image, with per-point colors.");
}

}  // namespace o3dpy
