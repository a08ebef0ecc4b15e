// SPDX-License-Identifier: MIT
// Image format dispatch, file <-> memory, and the format checks every writer shares.
#include "o3d/io/image_io.h"

#include <string_view>

#include "o3d/geometry/image_ops.h"
#include "o3d/io/file_bytes.h"
#include "o3d/io/image_io_internal.h"
#include "o3d/utility/error.h"
#include "o3d/io/format_dispatch.h"

namespace o3d::io {

namespace {

enum class Format { Png, Jpeg, Ppm, Pgm };

constexpr detail::FormatName<Format> kFormats[] = {
    {"png", Format::Png}, {"jpg", Format::Jpeg}, {"jpeg", Format::Jpeg}, {"ppm", Format::Ppm}, {"pgm", Format::Pgm}};

Format resolve(const std::string& format, const std::string* path) {
    return detail::resolve_format(kFormats, "image", format, path);
}

geometry::Image parse(Format f, const detail::Input& in) {
    if (in.size == 0) detail::parse_error(in, "the image data is empty");
    switch (f) {
        case Format::Png: return detail::read_png(in);
        case Format::Jpeg: return detail::read_jpeg(in);
        case Format::Ppm:
        case Format::Pgm: return detail::read_pnm(in);
    }
    throw Unsupported("unknown image format");
}

std::string describe(const geometry::Image& image) {
    return std::to_string(image.num_channels) + "-channel " +
           (image.bytes_per_channel == 4 ? std::string("float32")
                                         : std::to_string(8 * image.bytes_per_channel) + "-bit");
}

/// Which channel counts and depths each format stores (the header's table).
void require_writable(Format f, const geometry::Image& image) {
    geometry::require_valid_image(image, "write_image");
    const int c = image.num_channels, b = image.bytes_per_channel;
    bool ok = false;
    const char* name = "";
    switch (f) {
        case Format::Png: ok = b != 4; name = "PNG (8/16-bit, 1, 3 or 4 channels)"; break;
        case Format::Jpeg: ok = b == 1 && c != 4; name = "JPEG (8-bit, 1 or 3 channels)"; break;
        case Format::Ppm: ok = b != 4 && c == 3; name = "PPM (8/16-bit, 3 channels)"; break;
        case Format::Pgm: ok = b != 4 && c == 1; name = "PGM (8/16-bit, 1 channel)"; break;
    }
    if (!ok)
        throw InvalidArgument("a " + describe(image) + " image cannot be written as " + name +
                              (b == 4 ? "; convert float images to 8 or 16 bit first" : ""));
}

std::vector<uint8_t> encode(Format f, const geometry::Image& image, int quality) {
    require_writable(f, image);
    // Only JPEG has a quality; the other formats ignore the argument.
    if (f == Format::Jpeg && quality != -1 && (quality < 1 || quality > 100))
        throw InvalidArgument("JPEG quality " + std::to_string(quality) + " is not in 1..100 (or -1 for 90)");
    switch (f) {
        case Format::Png: return detail::write_png(image);
        case Format::Jpeg: return detail::write_jpeg(image, quality == -1 ? 90 : quality);
        case Format::Ppm:
        case Format::Pgm: return detail::write_pnm(image);
    }
    throw Unsupported("unknown image format");
}

}  // namespace

geometry::Image read_image(const std::string& path, const std::string& format) {
    const Format f = resolve(format, &path);
    const detail::FileBytes bytes(path);
    return parse(f, detail::Input{bytes.data(), bytes.size(), path});
}

geometry::Image read_image_from_memory(const uint8_t* data, size_t size, const std::string& format) {
    const Format f = resolve(format, nullptr);
    if (!data && size) throw InvalidArgument("data is NULL");
    static const std::string kName = "<memory>";
    return parse(f, detail::Input{data, size, kName});
}

void write_image(const std::string& path, const geometry::Image& image, const std::string& format, int quality) {
    const Format f = resolve(format, &path);
    detail::write_file(path, encode(f, image, quality));
}

std::vector<uint8_t> write_image_to_memory(const geometry::Image& image, const std::string& format, int quality) {
    return encode(resolve(format, nullptr), image, quality);
}

}  // namespace o3d::io
