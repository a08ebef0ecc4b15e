// SPDX-License-Identifier: MIT
// PNG through libpng's progressive-free (whole image) API, on memory. Palette images become RGB (RGBA
// with a tRNS chunk), gray+alpha becomes RGBA, low bit depths become 8 bit; 16-bit samples, big-endian
// in the file, are native in memory. libpng reports errors by longjmp: every setjmp frame below holds
// only plain data, and C++ objects (the pixel buffer) are made outside them.
#include <png.h>

#include <csetjmp>
#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/io/image_io_internal.h"
#include "o3d/utility/error.h"

namespace o3d::io::detail {

namespace {

constexpr bool kLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

/// deflate cannot expand data by more than 1032:1, so a header promising more raw bytes than that
/// ratio allows from the whole file is a lie; rejecting it avoids allocating for it.
constexpr uint64_t kMaxDeflateRatio = 1032;

/// libpng's error and warning hooks: keep the message, return to the setjmp point, never print.
struct PngMessage {
    char text[200] = "libpng error";
};

void on_error(png_structp png, png_const_charp message) {
    auto* m = static_cast<PngMessage*>(png_get_error_ptr(png));
    std::snprintf(m->text, sizeof m->text, "%s", message ? message : "libpng error");
    png_longjmp(png, 1);
}
void on_warning(png_structp, png_const_charp) {}

struct MemorySource {
    const uint8_t* data;
    size_t size;
    size_t pos;
};

void read_from_memory(png_structp png, png_bytep out, png_size_t n) {
    auto* src = static_cast<MemorySource*>(png_get_io_ptr(png));
    if (n > src->size - src->pos) png_error(png, "truncated PNG data");
    std::memcpy(out, src->data + src->pos, n);
    src->pos += n;
}

struct Layout {
    uint32_t width = 0, height = 0;
    int channels = 0, bytes = 0;
    uint64_t raw_bytes = 0;  // the decompressed stream: rows with their filter bytes
    size_t row_bytes = 0;    // one output row after the transformations
};

/// Owns libpng's read structures; each step returns false (message in `message`) on a libpng error.
class PngReader {
public:
    explicit PngReader(const Input& in) : source_{in.data, in.size, 0} {
        png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
        if (png_) info_ = png_create_info_struct(png_);
        if (!png_ || !info_) throw std::bad_alloc();
    }
    ~PngReader() { png_destroy_read_struct(&png_, &info_, nullptr); }
    PngReader(const PngReader&) = delete;
    PngReader& operator=(const PngReader&) = delete;

    bool read_header(Layout& out) {
        if (setjmp(png_jmpbuf(png_))) return false;
        png_set_read_fn(png_, &source_, read_from_memory);
        png_set_user_limits(png_, kMaxImageDimension, kMaxImageDimension);
        png_read_info(png_, info_);
        out.width = png_get_image_width(png_, info_);
        out.height = png_get_image_height(png_, info_);
        const int color = png_get_color_type(png_, info_);
        const int depth = png_get_bit_depth(png_, info_);
        const int passes = png_get_interlace_type(png_, info_) == PNG_INTERLACE_NONE ? 1 : 7;
        out.raw_bytes = (uint64_t(png_get_rowbytes(png_, info_)) + uint64_t(passes)) * out.height;
        if (color == PNG_COLOR_TYPE_PALETTE) {
            png_set_palette_to_rgb(png_);
            const bool alpha = png_get_valid(png_, info_, PNG_INFO_tRNS) != 0;
            if (alpha) png_set_tRNS_to_alpha(png_);
            out.channels = alpha ? 4 : 3;
        } else if (color == PNG_COLOR_TYPE_GRAY) {
            if (depth < 8) png_set_expand_gray_1_2_4_to_8(png_);
            out.channels = 1;
        } else if (color == PNG_COLOR_TYPE_GRAY_ALPHA) {
            png_set_gray_to_rgb(png_);  // o3d images have no 2-channel format
            out.channels = 4;
        } else if (color == PNG_COLOR_TYPE_RGB) {
            out.channels = 3;
        } else {
            out.channels = 4;
        }
        out.bytes = depth == 16 ? 2 : 1;
        if (depth == 16 && kLittleEndian) png_set_swap(png_);
        png_set_interlace_handling(png_);
        png_read_update_info(png_, info_);
        out.row_bytes = png_get_rowbytes(png_, info_);
        return true;
    }

    bool read_rows(png_bytepp rows) {
        if (setjmp(png_jmpbuf(png_))) return false;
        png_read_image(png_, rows);
        return true;
    }

    PngMessage message;

private:
    MemorySource source_;
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
};

}  // namespace

geometry::Image read_png(const Input& in) {
    if (in.size < 8 || png_sig_cmp(in.data, 0, 8) != 0) parse_error(in, "not a PNG file (bad signature)");
    PngReader reader(in);
    Layout layout;
    if (!reader.read_header(layout)) parse_error(in, std::string("PNG: ") + reader.message.text);
    if (layout.raw_bytes > kMaxDeflateRatio * uint64_t(in.size) + 4096)
        parse_error(in, "PNG header claims " + std::to_string(layout.width) + " x " + std::to_string(layout.height) +
                            " pixels, more than " + std::to_string(in.size) + " bytes of compressed data can hold");
    geometry::Image image = geometry::make_image(int(layout.width), int(layout.height), layout.channels, layout.bytes);
    if (layout.row_bytes != image.bytes_per_line())
        parse_error(in, "PNG: unexpected row layout after conversion");
    std::vector<png_bytep> rows(layout.height);
    for (uint32_t v = 0; v < layout.height; ++v) rows[v] = image.data.data() + size_t(v) * layout.row_bytes;
    if (!reader.read_rows(rows.data())) parse_error(in, std::string("PNG: ") + reader.message.text);
    return image;
}

namespace {

void write_to_vector(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<uint8_t>*>(png_get_io_ptr(png));
    bool ok = true;
    try {
        out->insert(out->end(), data, data + n);
    } catch (...) {
        ok = false;
    }
    if (!ok) png_error(png, "out of memory");
}
void flush_nothing(png_structp) {}

/// Owns libpng's write structures; encode() returns false (message in `message`) on a libpng error.
class PngWriter {
public:
    PngWriter() {
        png_ = png_create_write_struct(PNG_LIBPNG_VER_STRING, &message, on_error, on_warning);
        if (png_) info_ = png_create_info_struct(png_);
        if (!png_ || !info_) throw std::bad_alloc();
    }
    ~PngWriter() { png_destroy_write_struct(&png_, &info_); }
    PngWriter(const PngWriter&) = delete;
    PngWriter& operator=(const PngWriter&) = delete;

    bool encode(const geometry::Image& image, png_bytepp rows, std::vector<uint8_t>* out) {
        if (setjmp(png_jmpbuf(png_))) return false;
        png_set_write_fn(png_, out, write_to_vector, flush_nothing);
        const int color = image.num_channels == 1   ? PNG_COLOR_TYPE_GRAY
                          : image.num_channels == 3 ? PNG_COLOR_TYPE_RGB
                                                    : PNG_COLOR_TYPE_RGB_ALPHA;
        png_set_IHDR(png_, info_, png_uint_32(image.width), png_uint_32(image.height), 8 * image.bytes_per_channel,
                     color, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
        png_write_info(png_, info_);
        if (image.bytes_per_channel == 2 && kLittleEndian) png_set_swap(png_);
        png_write_image(png_, rows);
        png_write_end(png_, nullptr);
        return true;
    }

    PngMessage message;

private:
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
};

}  // namespace

std::vector<uint8_t> write_png(const geometry::Image& image) {
    // png_write_image takes non-const rows but does not modify them.
    std::vector<png_bytep> rows(size_t(image.height));
    for (int v = 0; v < image.height; ++v)
        rows[size_t(v)] = const_cast<png_bytep>(image.data.data() + size_t(v) * image.bytes_per_line());
    std::vector<uint8_t> out;
    out.reserve(image.byte_size() / 2 + 1024);
    PngWriter writer;
    if (!writer.encode(image, rows.data(), &out))
        throw IoError(std::string("PNG encoding failed: ") + writer.message.text);
    return out;
}

}  // namespace o3d::io::detail
