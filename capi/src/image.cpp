// SPDX-License-Identifier: MIT
// C API: images (o3d/image.h) and image I/O (the image part of o3d/io.h).
#include <memory>
#include <string>

#include "array_family.h"
#include "internal.h"
#include "o3d/geometry/image_ops.h"
#include "o3d/io/image_io.h"
#include "o3d/o3d.h"

namespace {

using o3d::geometry::Image;

/// Hand a new image to the caller through `out`.
void emit(o3d_image_t** out, Image image) {
    auto handle = std::make_unique<o3d_image>();
    handle->image = std::move(image);
    *out = handle.release();
}

/// Check `out` (and clear it, so that a failure leaves NULL) and the input handle.
const Image& begin_new(o3d_image_t** out, const o3d_image_t* image) {
    o3d::capi::require(out, "out");
    *out = nullptr;
    return o3d::capi::require(image, "image")->image;
}

std::string format_arg(const char* format) { return format ? std::string(format) : std::string(); }

o3d::geometry::ImageFilterType to_filter(int32_t type) {
    switch (type) {
        case O3D_IMAGE_FILTER_GAUSSIAN3: return o3d::geometry::ImageFilterType::Gaussian3;
        case O3D_IMAGE_FILTER_GAUSSIAN5: return o3d::geometry::ImageFilterType::Gaussian5;
        case O3D_IMAGE_FILTER_GAUSSIAN7: return o3d::geometry::ImageFilterType::Gaussian7;
        case O3D_IMAGE_FILTER_SOBEL3_DX: return o3d::geometry::ImageFilterType::Sobel3Dx;
        case O3D_IMAGE_FILTER_SOBEL3_DY: return o3d::geometry::ImageFilterType::Sobel3Dy;
        default: throw o3d::InvalidArgument("unknown filter_type " + std::to_string(type) + " (expected 0..4)");
    }
}

o3d::geometry::ImageConvertType to_convert(int32_t type) {
    switch (type) {
        case O3D_IMAGE_CONVERT_EQUAL: return o3d::geometry::ImageConvertType::Equal;
        case O3D_IMAGE_CONVERT_WEIGHTED: return o3d::geometry::ImageConvertType::Weighted;
        default: throw o3d::InvalidArgument("unknown convert_type " + std::to_string(type) + " (expected 0 or 1)");
    }
}

template <typename T>
o3d_status image_property(const char* function, const o3d_image_t* image, T* out, int32_t Image::*field) {
    return o3d::capi::guard(function, [&] {
        o3d::capi::require(image, "image");
        *o3d::capi::require(out, "out") = image->image.*field;
    });
}

}  // namespace

namespace {

/// @brief The pixel bytes as rows of one byte; replacing them keeps the image's shape.
o3d::capi::ArraySlot<uint8_t> image_slot(o3d_image_t* h, int32_t which) {
    Image& img = o3d::capi::require(h, "image")->image;
    if (which != O3D_IMAGE_DATA) o3d::capi::bad_which(which, "an image array (O3D_IMAGE_DATA)");
    o3d::capi::ArraySlot<uint8_t> s = o3d::capi::flat_slot(img.data, 1, !img.data.empty());
    s.assign = [&img](const uint8_t* src, size_t rows) {
        if (rows != img.data.size())
            throw o3d::InvalidArgument("image data needs " + std::to_string(img.data.size()) + " bytes, got " +
                                       std::to_string(rows));
        std::copy(src, src + rows, img.data.begin());
    };
    return s;
}

}  // namespace

extern "C" {

O3D_CAPI_ARRAYS(image, o3d_image_t, uint8_t, image_slot)
O3D_CAPI_ARRAY_QUERIES(image, o3d_image_t, image_slot, o3d::capi::no_index_slot)

O3D_API o3d_status o3d_image_create(o3d_image_t** out, int32_t width, int32_t height, int32_t num_channels,
                                    int32_t bytes_per_channel) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        emit(out, o3d::geometry::make_image(width, height, num_channels, bytes_per_channel));
    });
}

O3D_API o3d_status o3d_image_create_from_data(o3d_image_t** out, int32_t width, int32_t height,
                                              int32_t num_channels, int32_t bytes_per_channel, const uint8_t* data,
                                              size_t size) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(data, "data");
        Image image = o3d::geometry::make_image(width, height, num_channels, bytes_per_channel);
        if (size != image.byte_size())
            throw o3d::InvalidArgument("data holds " + std::to_string(size) + " bytes but a " + std::to_string(width) +
                                       " x " + std::to_string(height) + " x " + std::to_string(num_channels) +
                                       " x " + std::to_string(bytes_per_channel) + "-byte image needs " +
                                       std::to_string(image.byte_size()));
        std::memcpy(image.data.data(), data, size);
        emit(out, std::move(image));
    });
}

O3D_API void o3d_image_destroy(o3d_image_t* image) { delete image; }

O3D_API o3d_status o3d_image_clone(o3d_image_t** out, const o3d_image_t* src) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        emit(out, o3d::capi::require(src, "src")->image);
    });
}

O3D_API o3d_status o3d_image_width(int32_t* out, const o3d_image_t* image) {
    return image_property(__func__, image, out, &Image::width);
}
O3D_API o3d_status o3d_image_height(int32_t* out, const o3d_image_t* image) {
    return image_property(__func__, image, out, &Image::height);
}
O3D_API o3d_status o3d_image_num_channels(int32_t* out, const o3d_image_t* image) {
    return image_property(__func__, image, out, &Image::num_channels);
}
O3D_API o3d_status o3d_image_bytes_per_channel(int32_t* out, const o3d_image_t* image) {
    return image_property(__func__, image, out, &Image::bytes_per_channel);
}

O3D_API o3d_status o3d_image_filter(o3d_image_t** out, const o3d_image_t* image, int32_t filter_type) {
    return o3d::capi::guard(__func__, [&] {
        const Image& in = begin_new(out, image);
        emit(out, o3d::geometry::filter_image(in, to_filter(filter_type)));
    });
}

O3D_API o3d_status o3d_image_downsample(o3d_image_t** out, const o3d_image_t* image) {
    return o3d::capi::guard(__func__, [&] { emit(out, o3d::geometry::downsample_image(begin_new(out, image))); });
}

O3D_API o3d_status o3d_image_flip_vertical(o3d_image_t** out, const o3d_image_t* image) {
    return o3d::capi::guard(__func__, [&] { emit(out, o3d::geometry::flip_vertical(begin_new(out, image))); });
}

O3D_API o3d_status o3d_image_flip_horizontal(o3d_image_t** out, const o3d_image_t* image) {
    return o3d::capi::guard(__func__, [&] { emit(out, o3d::geometry::flip_horizontal(begin_new(out, image))); });
}

O3D_API o3d_status o3d_image_create_float_image(o3d_image_t** out, const o3d_image_t* image,
                                                int32_t convert_type) {
    return o3d::capi::guard(__func__, [&] {
        const Image& in = begin_new(out, image);
        emit(out, o3d::geometry::create_float_image(in, to_convert(convert_type)));
    });
}

O3D_API o3d_status o3d_image_convert_depth_to_float(o3d_image_t** out, const o3d_image_t* image,
                                                    double depth_scale, double depth_trunc) {
    return o3d::capi::guard(__func__, [&] {
        const Image& in = begin_new(out, image);
        emit(out, o3d::geometry::convert_depth_to_float(in, depth_scale, depth_trunc));
    });
}

O3D_API o3d_status o3d_io_read_image(o3d_image_t** out, const char* path, const char* format) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(path, "path");
        emit(out, o3d::io::read_image(path, format_arg(format)));
    });
}

O3D_API o3d_status o3d_io_write_image(const char* path, const o3d_image_t* image, const char* format,
                                      int32_t quality) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(path, "path");
        o3d::capi::require(image, "image");
        o3d::io::write_image(path, image->image, format_arg(format), quality);
    });
}

O3D_API o3d_status o3d_io_read_image_from_memory(o3d_image_t** out, const uint8_t* data, size_t size,
                                                 const char* format) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        if (!data && size) throw o3d::InvalidArgument("data is NULL but size is " + std::to_string(size));
        emit(out, o3d::io::read_image_from_memory(data, size, format_arg(format)));
    });
}

O3D_API o3d_status o3d_io_write_image_to_memory(o3d_buffer_t** out, const o3d_image_t* image, const char* format,
                                                int32_t quality) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(image, "image");
        auto buffer = std::make_unique<o3d_buffer>();
        buffer->bytes = o3d::io::write_image_to_memory(image->image, format_arg(format), quality);
        *out = buffer.release();
    });
}

}  // extern "C"
