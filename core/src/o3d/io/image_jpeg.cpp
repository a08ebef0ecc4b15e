// SPDX-License-Identifier: MIT
// JPEG through libjpeg(-turbo) on memory: gray files read as 1 channel, colour (YCbCr/RGB) as 3; CMYK is
// refused. libjpeg reports errors by longjmp: every setjmp frame below holds only plain data, and the C++
// objects it fills are owned by the caller. A truncated file is an error here (libjpeg would pad it with
// gray and only warn), so a header that lies about the size fails at the first missing row.
#include <cstdio>
// jpeglib.h needs size_t and FILE declared first.
#include <jerror.h>
#include <jpeglib.h>

#include <csetjmp>
#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/io/image_io_internal.h"
#include "o3d/utility/error.h"

namespace o3d::io::detail {

namespace {

/// Cap on libjpeg's own working memory (progressive files keep every coefficient): past it libjpeg
/// fails cleanly instead of allocating what a corrupt header asks for.
constexpr long kMaxDecoderMemory = 1L << 30;

struct JpegErrors {
    jpeg_error_mgr mgr;
    jmp_buf jump;
    char text[JMSG_LENGTH_MAX] = "libjpeg error";
};

[[noreturn]] void on_error(j_common_ptr cinfo) {
    auto* errors = reinterpret_cast<JpegErrors*>(cinfo->err);
    cinfo->err->format_message(cinfo, errors->text);
    std::longjmp(errors->jump, 1);
}

void on_message(j_common_ptr cinfo, int level) {
    // Warnings are ignored, except premature end of data, which is an error for us.
    if (level < 0 && cinfo->err->msg_code == JWRN_JPEG_EOF) {
        auto* errors = reinterpret_cast<JpegErrors*>(cinfo->err);
        std::snprintf(errors->text, sizeof errors->text, "the JPEG data is truncated");
        std::longjmp(errors->jump, 1);
    }
}

void install_errors(JpegErrors& errors) {
    jpeg_std_error(&errors.mgr);
    errors.mgr.error_exit = on_error;
    errors.mgr.emit_message = on_message;
}

struct Header {
    uint32_t width = 0, height = 0;
    int channels = 0;
    bool cmyk = false;
};

/// Owns a jpeg_decompress_struct; each step returns false (message in `errors.text`) on a libjpeg error.
class JpegDecoder {
public:
    JpegDecoder() { install_errors(errors); }
    ~JpegDecoder() {
        if (created_) jpeg_destroy_decompress(&cinfo_);
    }
    JpegDecoder(const JpegDecoder&) = delete;
    JpegDecoder& operator=(const JpegDecoder&) = delete;

    bool start(const Input& in, Header& out) {
        if (setjmp(errors.jump)) return false;
        cinfo_.err = &errors.mgr;
        jpeg_create_decompress(&cinfo_);
        created_ = true;
        cinfo_.mem->max_memory_to_use = kMaxDecoderMemory;
        jpeg_mem_src(&cinfo_, in.data, static_cast<unsigned long>(in.size));
        jpeg_read_header(&cinfo_, TRUE);
        if (cinfo_.jpeg_color_space == JCS_CMYK || cinfo_.jpeg_color_space == JCS_YCCK) {
            out.cmyk = true;
            return true;
        }
        const bool gray = cinfo_.num_components == 1;
        cinfo_.out_color_space = gray ? JCS_GRAYSCALE : JCS_RGB;
        jpeg_start_decompress(&cinfo_);
        out.width = cinfo_.output_width;
        out.height = cinfo_.output_height;
        out.channels = cinfo_.output_components;
        return true;
    }

    /// Rows are appended as they are decoded, so memory follows the data actually present.
    bool read_rows(size_t row_bytes, std::vector<uint8_t>* pixels) {
        if (setjmp(errors.jump)) return false;
        while (cinfo_.output_scanline < cinfo_.output_height) {
            const size_t row = cinfo_.output_scanline;
            pixels->resize((row + 1) * row_bytes);
            JSAMPROW target = pixels->data() + row * row_bytes;
            jpeg_read_scanlines(&cinfo_, &target, 1);
        }
        jpeg_finish_decompress(&cinfo_);
        return true;
    }

    JpegErrors errors;

private:
    jpeg_decompress_struct cinfo_{};
    bool created_ = false;
};

}  // namespace

geometry::Image read_jpeg(const Input& in) {
    if (in.size < 3 || in.data[0] != 0xFF || in.data[1] != 0xD8) parse_error(in, "not a JPEG file (no SOI marker)");
    JpegDecoder decoder;
    Header header;
    if (!decoder.start(in, header)) parse_error(in, std::string("JPEG: ") + decoder.errors.text);
    if (header.cmyk) throw Unsupported(in.name + ": CMYK JPEG images are not supported");
    if (header.channels != 1 && header.channels != 3)
        parse_error(in, "JPEG decodes to " + std::to_string(header.channels) + " channels");
    const size_t row_bytes = size_t(header.width) * size_t(header.channels);
    if (header.width < 1 || header.height < 1 || uint64_t(row_bytes) * header.height > geometry::kMaxImageBytes)
        parse_error(in, "JPEG size " + std::to_string(header.width) + " x " + std::to_string(header.height) +
                            " is empty or exceeds the 4 GiB image limit");
    geometry::Image image;
    image.data.reserve(std::min<size_t>(row_bytes * header.height, size_t(64) << 20));
    if (!decoder.read_rows(row_bytes, &image.data)) parse_error(in, std::string("JPEG: ") + decoder.errors.text);
    image.width = int(header.width);
    image.height = int(header.height);
    image.num_channels = header.channels;
    image.bytes_per_channel = 1;
    return image;
}

namespace {

/// Owns a jpeg_compress_struct and the memory destination buffer libjpeg allocates.
class JpegEncoder {
public:
    JpegEncoder() { install_errors(errors); }
    ~JpegEncoder() {
        if (created_) jpeg_destroy_compress(&cinfo_);
        std::free(buffer_);
    }
    JpegEncoder(const JpegEncoder&) = delete;
    JpegEncoder& operator=(const JpegEncoder&) = delete;

    bool encode(const geometry::Image& image, int quality) {
        if (setjmp(errors.jump)) return false;
        cinfo_.err = &errors.mgr;
        jpeg_create_compress(&cinfo_);
        created_ = true;
        jpeg_mem_dest(&cinfo_, &buffer_, &size_);
        cinfo_.image_width = JDIMENSION(image.width);
        cinfo_.image_height = JDIMENSION(image.height);
        cinfo_.input_components = image.num_channels;
        cinfo_.in_color_space = image.num_channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
        jpeg_set_defaults(&cinfo_);
        jpeg_set_quality(&cinfo_, quality, TRUE);
        jpeg_start_compress(&cinfo_, TRUE);
        while (cinfo_.next_scanline < cinfo_.image_height) {
            // libjpeg's row type is non-const but it only reads the rows.
            const size_t offset = size_t(cinfo_.next_scanline) * image.bytes_per_line();
            JSAMPROW row = const_cast<JSAMPROW>(image.data.data() + offset);
            jpeg_write_scanlines(&cinfo_, &row, 1);
        }
        jpeg_finish_compress(&cinfo_);
        return true;
    }

    const uint8_t* data() const { return buffer_; }
    size_t size() const { return size_t(size_); }
    JpegErrors errors;

private:
    jpeg_compress_struct cinfo_{};
    bool created_ = false;
    unsigned char* buffer_ = nullptr;
    unsigned long size_ = 0;
};

}  // namespace

std::vector<uint8_t> write_jpeg(const geometry::Image& image, int quality) {
    if (image.width > 65500 || image.height > 65500)
        throw InvalidArgument("JPEG cannot store images wider or taller than 65500 pixels");
    JpegEncoder encoder;
    if (!encoder.encode(image, quality)) throw IoError(std::string("JPEG encoding failed: ") + encoder.errors.text);
    return std::vector<uint8_t>(encoder.data(), encoder.data() + encoder.size());
}

}  // namespace o3d::io::detail
