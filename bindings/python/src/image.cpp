// SPDX-License-Identifier: MIT
// o3d.geometry.Image over o3d_image_t (image.h). np.asarray(image) is a zero-copy view through the
// buffer protocol: its base keeps the Image (and so the C handle) alive, and no C call resizes an image.
#include "generated/image_methods.h"

namespace o3dpy {
namespace {

struct Format {
    int32_t width = 0, height = 0, channels = 0, bytes = 0;
};

Format format_of(const PyImage& img) {
    Format f;
    if (!img.get()) return f;  // Image(): empty
    check(o3d_image_width(&f.width, img.get()));
    check(o3d_image_height(&f.height, img.get()));
    check(o3d_image_num_channels(&f.channels, img.get()));
    check(o3d_image_bytes_per_channel(&f.bytes, img.get()));
    return f;
}

const char* buffer_format(int32_t bytes) {
    return bytes == 2 ? "H" : bytes == 4 ? "f" : "B";  // uint16, float32, uint8 (also the empty image)
}

const o3d_image_t* require(const PyImage& img, const char* what) {
    if (!img.get()) invalid(std::string(what) + ": the image is empty");
    return img.get();
}

py::buffer_info buffer_of(PyImage& self) {
    const Format f = format_of(self);
    std::vector<py::ssize_t> shape{f.height, f.width};
    if (f.channels > 1) shape.push_back(f.channels);
    const py::ssize_t item = f.bytes ? f.bytes : 1;
    std::vector<py::ssize_t> strides{(py::ssize_t)f.width * f.channels * item, (py::ssize_t)f.channels * item};
    if (f.channels > 1) strides.push_back(item);
    void* data = nullptr;
    if (self.get()) {
        size_t size = 0;
        if (self.readonly) {
            const uint8_t* p = nullptr;
            check(o3d_image_array_view(&p, &size, self.get(), O3D_IMAGE_DATA));
            data = const_cast<uint8_t*>(p);
        } else {
            uint8_t* p = nullptr;
            check(o3d_image_array_mutable_view(&p, &size, self.h->p, O3D_IMAGE_DATA));
            data = p;
        }
    }
    return py::buffer_info(data, item, buffer_format(f.bytes), (py::ssize_t)shape.size(), shape, strides, self.readonly);
}

PyImage clone_image(const PyImage& self) {
    o3d_image_t* out = nullptr;
    if (self.get()) check(o3d_image_clone(&out, self.get()));
    return PyImage(out);
}

}  // namespace

PyImage image_from_array(py::handle obj) {
    py::array a = py::array::ensure(obj);
    if (!a) invalid("Image: expected a numpy array (or buffer) of uint8, uint16 or float32");
    // Compare kind and size, not dtype identity: arrays made from buffers carry their own dtype objects.
    const char kind = a.dtype().kind();
    const py::ssize_t item = a.dtype().itemsize();
    int32_t bytes = 0;
    if (kind == 'u' && (item == 1 || item == 2)) bytes = (int32_t)item;
    else if (kind == 'f' && item == 4) bytes = 4;
    if (bytes == 0 || !a.dtype().attr("isnative").cast<bool>())
        invalid("Image: dtype must be uint8, uint16 or float32 (native byte order), got " + std::string(py::str(a.dtype())));
    if (a.ndim() != 2 && a.ndim() != 3)
        invalid("Image: expected an (H, W) or (H, W, C) array, got " + std::to_string(a.ndim()) + " dimensions");
    const py::ssize_t c = a.ndim() == 3 ? a.shape(2) : 1;
    if (a.shape(0) > INT32_MAX || a.shape(1) > INT32_MAX) invalid("Image: too large");
    py::array contiguous = py::array::ensure(a, py::array::c_style);
    if (!contiguous) throw py::error_already_set();
    const auto* data = static_cast<const uint8_t*>(contiguous.data());
    const size_t size = (size_t)contiguous.nbytes();
    const int32_t w = (int32_t)a.shape(1), h = (int32_t)a.shape(0), ch = (int32_t)c;
    o3d_image_t* out = nullptr;
    check(nogil([&] { return o3d_image_create_from_data(&out, w, h, ch, bytes, data, size); }));
    return PyImage(out);
}

void declare_image(py::module_& m) {
    def_enum<ImageFilterType>(m);
    def_enum<ColorToIntensityConversionType>(m);
    py::class_<PyImage>(m, "Image", py::buffer_protocol(),
                        "A 2D image: 1, 3 or 4 channels of uint8, uint16 or float32. ``Image(array)`` copies an "
                        "(H, W) or (H, W, C) array; ``np.asarray(image)`` is a zero-copy view of its pixels.");
}

void define_image(py::module_& m) {
    auto cls = static_cast<py::class_<PyImage>>(m.attr("Image"));
    def_image_methods(cls);  // create, filter, downsample, flip_*, create_float_image, convert_depth_to_float_image
    cls.attr("FilterType") = m.attr("ImageFilterType");
    cls.attr("ColorToIntensityConversionType") = m.attr("ColorToIntensityConversionType");
    cls.def(py::init([]() { return PyImage(nullptr); }), "An empty image.")
        .def(py::init(&clone_image),
             py::arg("image"), "Deep copy.")
        .def(py::init([](py::handle array) { return image_from_array(array); }), py::arg("data"),
             "Copy of an (H, W) or (H, W, C) uint8 / uint16 / float32 array (C in 1, 3, 4).")
        .def_buffer(&buffer_of)
        .def("__copy__", &clone_image)
        .def("__deepcopy__", [](const PyImage& self, py::handle) { return clone_image(self); })
        .def_property_readonly("width", [](const PyImage& self) { return format_of(self).width; })
        .def_property_readonly("height", [](const PyImage& self) { return format_of(self).height; })
        .def_property_readonly("num_of_channels", [](const PyImage& self) { return format_of(self).channels; })
        .def_property_readonly("channels", [](const PyImage& self) { return format_of(self).channels; })
        .def_property_readonly("bytes_per_channel", [](const PyImage& self) { return format_of(self).bytes; })
        .def("is_empty",
             [](const PyImage& self) {
                 int32_t has = 0;
                 if (self.get()) check(o3d_image_has_array(&has, self.get(), O3D_IMAGE_DATA));
                 return has == 0;
             })
        .def("dimension", [](const PyImage&) { return 2; })
        .def("get_min_bound", [](const PyImage&) {
            const double z[2] = {0.0, 0.0};
            return mat_to_array(z, 2, 0);
        })
        .def("get_max_bound", [](const PyImage& self) {
            const Format f = format_of(self);
            const double v[2] = {(double)f.width, (double)f.height};
            return mat_to_array(v, 2, 0);
        })
        .def("__repr__",
             [](const PyImage& self) {
                 const Format f = format_of(self);
                 return "Image of size " + std::to_string(f.width) + "x" + std::to_string(f.height) + ", with " +
                        std::to_string(f.channels) + " channels.\nUse numpy.asarray to access buffer data.";
             })
        .def(
            "create_pyramid",
            [](const PyImage& self, int64_t num_of_levels, bool with_gaussian_filter) {
                if (num_of_levels < 0) invalid("create_pyramid: num_of_levels must be >= 0");
                Format f = format_of(self);
                if (f.channels != 1 || f.bytes != 4)
                    invalid("create_pyramid: expected a 1-channel float32 image (use create_float_image)");
                // Open3D's layout: level 0 is a copy; each next level is the previous one (Gaussian3
                // filtered when asked) downsampled by 2.
                py::list out;
                if (num_of_levels == 0) return out;
                out.append(py::cast(clone_image(self)));
                for (int64_t i = 1; i < num_of_levels; ++i) {  // the generated filter and downsample
                    py::object prev = out[(size_t)(i - 1)];
                    out.append((with_gaussian_filter ? prev.attr("filter")(ImageFilterType::Gaussian3) : prev)
                                   .attr("downsample")());
                }
                return out;
            },
            py::arg("num_of_levels"), py::arg("with_gaussian_filter"),
            "List of num_of_levels images, each half the size of the previous (1-channel float32 input).")
        .def_static(
            "filter_pyramid",
            [](py::iterable image_pyramid, ImageFilterType filter_type) {
                py::list out;
                for (py::handle level : image_pyramid) out.append(py::cast(level.cast<PyImage>()).attr("filter")(filter_type));
                return out;
            },
            py::arg("image_pyramid"), py::arg("filter_type"), "Each level filtered.")
        .def(
            "_data_copy",
            [](const PyImage& self) {
                const o3d_image_t* img = require(self, "_data_copy");
                size_t size = 0, cols = 0;
                check(o3d_image_array_shape(&size, &cols, img, O3D_IMAGE_DATA));
                PyObject* raw = PyBytes_FromStringAndSize(nullptr, (py::ssize_t)size);
                if (!raw) throw py::error_already_set();
                py::bytes out = py::reinterpret_steal<py::bytes>(raw);
                check(o3d_image_get_array(reinterpret_cast<uint8_t*>(PyBytes_AS_STRING(raw)), size, &size, img, O3D_IMAGE_DATA));
                return out;
            },
            "The pixel bytes, copied (o3d_image_get_array).")
        .def(
            "_set_data",
            [](PyImage& self, py::bytes data) {
                std::string_view bytes = data;
                o3d_image_t* img = const_cast<o3d_image_t*>(require(self, "_set_data"));
                check(o3d_image_set_array(img, O3D_IMAGE_DATA, reinterpret_cast<const uint8_t*>(bytes.data()),
                                          bytes.size()));
            },
            py::arg("data"), "Replace the pixel bytes (exactly width * height * channels * bytes_per_channel).");
}

}  // namespace o3dpy
