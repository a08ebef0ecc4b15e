// SPDX-License-Identifier: MIT
// o3d.io for triangle meshes, images and camera models (the mesh/image/camera part of io.h): files and
// in-memory bytes. Unlike Open3D, failures raise (O3DFileNotFoundError, O3DIOError, ParseError,
// UnsupportedError) instead of printing a warning and returning an empty object.
#include "geometry_types.h"

namespace o3dpy {
namespace {

std::string format_of(py::handle format) { return format.is_none() ? std::string("auto") : format.cast<std::string>(); }

o3d_mesh_read_options_t mesh_read_opts(bool enable_post_processing) {
    o3d_mesh_read_options_t o = init_of(&o3d_mesh_read_options_init);
    o.enable_post_processing = enable_post_processing ? 1 : 0;
    return o;
}

o3d_mesh_write_options_t mesh_write_opts(bool write_ascii, bool compressed, bool normals, bool colors, bool uvs) {
    o3d_mesh_write_options_t o = init_of(&o3d_mesh_write_options_init);
    o.write_ascii = write_ascii ? 1 : 0;
    o.compressed = compressed ? 1 : 0;
    o.write_vertex_normals = normals ? 1 : 0;
    o.write_vertex_colors = colors ? 1 : 0;
    o.write_triangle_uvs = uvs ? 1 : 0;
    return o;
}

struct Bytes {
    const uint8_t* data;
    size_t size;
};

Bytes bytes_of(py::buffer& data) {
    py::buffer_info info = data.request();
    if (info.ndim > 1 && info.strides.back() != info.itemsize) invalid("data: expected a contiguous bytes-like object");
    return {static_cast<const uint8_t*>(info.ptr), (size_t)(info.size * info.itemsize)};
}

/// Copy a library buffer into Python bytes, then free it.
py::bytes to_bytes(o3d_buffer_t* raw) {
    std::unique_ptr<o3d_buffer_t, void (*)(o3d_buffer_t*)> buf(raw, &o3d_buffer_destroy);
    const uint8_t* data = nullptr;
    size_t size = 0;
    check(o3d_buffer_view(&data, &size, buf.get()));
    return py::bytes(reinterpret_cast<const char*>(data), size);
}

const o3d_image_t* image_arg(const PyImage& img) {
    if (!img.get()) invalid("image: the image is empty");
    return img.get();
}

void define_mesh_io(py::module_& m) {
    const o3d_mesh_read_options_t rd = init_of(&o3d_mesh_read_options_init);
    const o3d_mesh_write_options_t wd = init_of(&o3d_mesh_write_options_init);
    m.def(
        "read_triangle_mesh",
        [](py::handle filename, bool enable_post_processing, bool /*print_progress*/, py::handle format) {
            const std::string path = path_of(filename), fmt = format_of(format);
            const o3d_mesh_read_options_t o = mesh_read_opts(enable_post_processing);
            o3d_trianglemesh_t* out = nullptr;
            check(nogil([&] { return o3d_io_read_triangle_mesh(&out, path.c_str(), fmt.c_str(), &o); }), path);
            return PyTriangleMesh(out);
        },
        py::arg("filename"), py::arg("enable_post_processing") = rd.enable_post_processing != 0,
        py::arg("print_progress") = false, py::arg("format") = "auto",
        "Read a mesh (ply, obj with its .mtl and textures, stl, off, gltf, glb; format 'auto' = from the "
        "extension). Failures raise. print_progress is accepted for Open3D compatibility.");
    m.def(
        "write_triangle_mesh",
        [](py::handle filename, const PyTriangleMesh& mesh, bool write_ascii, bool compressed, bool normals, bool colors,
           bool uvs, bool /*print_progress*/, py::handle format) {
            const std::string path = path_of(filename), fmt = format_of(format);
            const o3d_mesh_write_options_t o = mesh_write_opts(write_ascii, compressed, normals, colors, uvs);
            MeshPtr h = mesh.h;
            o3d_status s;
            {
                py::gil_scoped_release release;
                std::shared_lock<std::shared_mutex> lock(h->mutex);
                s = o3d_io_write_triangle_mesh(path.c_str(), h->p, fmt.c_str(), &o);
            }
            check(s, path);
            return true;
        },
        py::arg("filename"), py::arg("mesh"), py::arg("write_ascii") = wd.write_ascii != 0,
        py::arg("compressed") = wd.compressed != 0, py::arg("write_vertex_normals") = wd.write_vertex_normals != 0,
        py::arg("write_vertex_colors") = wd.write_vertex_colors != 0,
        py::arg("write_triangle_uvs") = wd.write_triangle_uvs != 0, py::arg("print_progress") = false,
        py::arg("format") = "auto",
        "Write a mesh (OBJ also writes its .mtl and PNG textures); returns True, failures raise.");
    m.def(
        "read_triangle_mesh_from_bytes",
        [](py::buffer data, const std::string& format, bool enable_post_processing) {
            const Bytes b = bytes_of(data);
            const o3d_mesh_read_options_t o = mesh_read_opts(enable_post_processing);
            o3d_trianglemesh_t* out = nullptr;
            check(nogil([&] { return o3d_io_read_triangle_mesh_from_memory(&out, b.data, b.size, format.c_str(), &o); }));
            return PyTriangleMesh(out);
        },
        py::arg("data"), py::arg("format"), py::arg("enable_post_processing") = rd.enable_post_processing != 0,
        "Decode a mesh from bytes: 'ply', 'stl', 'off', 'obj' (no materials) or 'glb'.");
    m.def(
        "write_triangle_mesh_to_bytes",
        [](const PyTriangleMesh& mesh, const std::string& format, bool write_ascii, bool compressed, bool normals,
           bool colors, bool uvs) {
            const o3d_mesh_write_options_t o = mesh_write_opts(write_ascii, compressed, normals, colors, uvs);
            o3d_buffer_t* buf = nullptr;
            locked_const(mesh.h, [&](const o3d_trianglemesh_t* m) {
                return o3d_io_write_triangle_mesh_to_memory(&buf, m, format.c_str(), &o);
            });
            return to_bytes(buf);
        },
        py::arg("mesh"), py::arg("format"), py::arg("write_ascii") = wd.write_ascii != 0,
        py::arg("compressed") = wd.compressed != 0, py::arg("write_vertex_normals") = wd.write_vertex_normals != 0,
        py::arg("write_vertex_colors") = wd.write_vertex_colors != 0,
        py::arg("write_triangle_uvs") = wd.write_triangle_uvs != 0, "Encode a mesh in the given format into bytes.");
}

void define_image_io(py::module_& m) {
    m.def(
        "read_image",
        [](py::handle filename, py::handle format) {
            const std::string path = path_of(filename), fmt = format_of(format);
            o3d_image_t* out = nullptr;
            check(nogil([&] { return o3d_io_read_image(&out, path.c_str(), fmt.c_str()); }), path);
            return PyImage(out);
        },
        py::arg("filename"), py::arg("format") = "auto", "Read a PNG, JPEG, PPM or PGM image. Failures raise.");
    m.def(
        "write_image",
        [](py::handle filename, const PyImage& image, int32_t quality, py::handle format) {
            const std::string path = path_of(filename), fmt = format_of(format);
            const o3d_image_t* img = image_arg(image);
            ImagePtr keep = image.h;
            check(nogil([&] { return o3d_io_write_image(path.c_str(), img, fmt.c_str(), quality); }), path);
            return true;
        },
        py::arg("filename"), py::arg("image"), py::arg("quality") = -1, py::arg("format") = "auto",
        "Write an image (quality: JPEG 1..100, -1 = default 90). Float images raise: convert first.");
    m.def(
        "read_image_from_bytes",
        [](py::buffer data, const std::string& format) {
            const Bytes b = bytes_of(data);
            o3d_image_t* out = nullptr;
            check(nogil([&] { return o3d_io_read_image_from_memory(&out, b.data, b.size, format.c_str()); }));
            return PyImage(out);
        },
        py::arg("data"), py::arg("format"), "Decode an image from bytes ('png', 'jpg', 'ppm', 'pgm').");
    m.def(
        "write_image_to_bytes",
        [](const PyImage& image, const std::string& format, int32_t quality) {
            const o3d_image_t* img = image_arg(image);
            ImagePtr keep = image.h;
            o3d_buffer_t* buf = nullptr;
            check(nogil([&] { return o3d_io_write_image_to_memory(&buf, img, format.c_str(), quality); }));
            return to_bytes(buf);
        },
        py::arg("image"), py::arg("format"), py::arg("quality") = -1, "Encode an image into bytes.");
}

void define_camera_io(py::module_& m) {
    m.def(
        "read_pinhole_camera_intrinsic",
        [](py::handle filename) {
            const std::string path = path_of(filename);
            PyIntrinsic out;
            check(nogil([&] { return o3d_io_read_pinhole_camera_intrinsic(&out.v, path.c_str()); }), path);
            return out;
        },
        py::arg("filename"), "Read a PinholeCameraIntrinsic JSON file (Open3D's layout).");
    m.def(
        "write_pinhole_camera_intrinsic",
        [](py::handle filename, const PyIntrinsic& intrinsic) {
            const std::string path = path_of(filename);
            const o3d_pinhole_intrinsic_t k = intrinsic.v;
            check(nogil([&] { return o3d_io_write_pinhole_camera_intrinsic(path.c_str(), &k); }), path);
            return true;
        },
        py::arg("filename"), py::arg("intrinsic"));
    m.def(
        "read_pinhole_camera_parameters",
        [](py::handle filename) {
            const std::string path = path_of(filename);
            PyCameraParameters out;
            check(nogil([&] {
                      return o3d_io_read_pinhole_camera_parameters(&out.intrinsic.v, out.extrinsic.data(), path.c_str());
                  }),
                  path);
            return out;
        },
        py::arg("filename"), "Read a PinholeCameraParameters JSON file.");
    m.def(
        "write_pinhole_camera_parameters",
        [](py::handle filename, const PyCameraParameters& parameters) {
            const std::string path = path_of(filename);
            const PyCameraParameters p = parameters;
            check(nogil([&] {
                      return o3d_io_write_pinhole_camera_parameters(path.c_str(), &p.intrinsic.v, p.extrinsic.data());
                  }),
                  path);
            return true;
        },
        py::arg("filename"), py::arg("parameters"));
    m.def(
        "read_pinhole_camera_trajectory",
        [](py::handle filename, py::handle format) {
            const std::string path = path_of(filename), fmt = format_of(format);
            o3d_camera_trajectory_t* out = nullptr;
            check(nogil([&] { return o3d_io_read_pinhole_camera_trajectory(&out, path.c_str(), fmt.c_str()); }), path);
            return PyTrajectory(out);
        },
        py::arg("filename"), py::arg("format") = "auto",
        "Read a trajectory: 'json' (PinholeCameraTrajectory) or 'log' (camera-to-world poses, PrimeSense "
        "intrinsics); 'auto' = from the extension.");
    m.def(
        "write_pinhole_camera_trajectory",
        [](py::handle filename, const PyTrajectory& trajectory, py::handle format) {
            const std::string path = path_of(filename), fmt = format_of(format);
            auto keep = trajectory.h;
            check(nogil([&] {
                      return o3d_io_write_pinhole_camera_trajectory(path.c_str(), keep.get(), fmt.c_str());
                  }),
                  path);
            return true;
        },
        py::arg("filename"), py::arg("trajectory"), py::arg("format") = "auto");
}

}  // namespace

void define_io_geometry(py::module_& m) {
    define_mesh_io(m);
    define_image_io(m);
    define_camera_io(m);
}

}  // namespace o3dpy
