// SPDX-License-Identifier: MIT
// Binary Netpbm: PGM (P5, gray) and PPM (P6, RGB). Samples are 1 byte when maxval < 256, else 2 bytes
// big-endian (the Netpbm specification); values are kept as stored, not rescaled to the full range.
#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/io/image_io_internal.h"
#include "o3d/utility/error.h"

namespace o3d::io::detail {

namespace {

/// Header cursor: whitespace and '#' comments (to the end of the line) separate the fields.
class PnmHeader {
public:
    explicit PnmHeader(const Input& in) : in_(in) {}

    /// The next decimal field, which must lie in [lo, hi].
    uint32_t field(const char* name, uint32_t lo, uint32_t hi) {
        skip_separators();
        if (pos_ >= in_.size || !is_digit(in_.data[pos_])) parse_error(in_, std::string("PNM header: missing ") + name);
        uint64_t v = 0;
        while (pos_ < in_.size && is_digit(in_.data[pos_])) {
            v = v * 10 + uint64_t(in_.data[pos_++] - '0');
            if (v > hi) break;
        }
        if (v < lo || v > hi)
            parse_error(in_, std::string("PNM header: ") + name + " is not in " + std::to_string(lo) + ".." +
                                 std::to_string(hi));
        return static_cast<uint32_t>(v);
    }
    /// After maxval comes exactly one whitespace byte, then the raster.
    size_t raster_start() {
        if (pos_ >= in_.size || !is_space(in_.data[pos_]))
            parse_error(in_, "PNM header: no whitespace between maxval and the pixel data");
        return pos_ + 1;
    }
    void skip(size_t n) { pos_ += n; }

private:
    static bool is_digit(uint8_t c) { return c >= '0' && c <= '9'; }
    static bool is_space(uint8_t c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
    }
    void skip_separators() {
        while (pos_ < in_.size) {
            if (is_space(in_.data[pos_])) {
                ++pos_;
            } else if (in_.data[pos_] == '#') {
                while (pos_ < in_.size && in_.data[pos_] != '\n' && in_.data[pos_] != '\r') ++pos_;
            } else {
                break;
            }
        }
    }
    const Input& in_;
    size_t pos_ = 0;
};

[[noreturn]] void above_maxval(const Input& in, uint32_t sample, uint32_t maxval) {
    parse_error(in, "PNM sample " + std::to_string(sample) + " exceeds maxval " + std::to_string(maxval));
}

}  // namespace

geometry::Image read_pnm(const Input& in) {
    if (in.size < 2 || in.data[0] != 'P') parse_error(in, "not a PNM file (no 'P' magic number)");
    const char kind = static_cast<char>(in.data[1]);
    if (kind != '5' && kind != '6') {
        if (kind >= '1' && kind <= '7')
            throw Unsupported(in.name + ": PNM type P" + std::string(1, kind) +
                              " is not supported (only binary P5 gray and P6 RGB)");
        parse_error(in, "not a PNM file (unknown magic number)");
    }
    PnmHeader header(in);
    header.skip(2);
    const uint32_t width = header.field("width", 1, kMaxImageDimension);
    const uint32_t height = header.field("height", 1, kMaxImageDimension);
    const uint32_t maxval = header.field("maxval", 1, 65535);
    const size_t start = header.raster_start();
    const int channels = kind == '5' ? 1 : 3;
    const int bytes = maxval < 256 ? 1 : 2;
    // Check the data is there before allocating, so that a lying header cannot ask for gigabytes.
    const uint64_t samples = uint64_t(width) * height * uint64_t(channels);
    if (samples * uint64_t(bytes) > in.size - start)
        parse_error(in, "PNM pixel data is truncated: " + std::to_string(width) + " x " + std::to_string(height) +
                            " needs " + std::to_string(samples * bytes) + " bytes, the file has " +
                            std::to_string(in.size - start));
    geometry::Image image = geometry::make_image(int(width), int(height), channels, bytes);
    const uint8_t* src = in.data + start;
    if (bytes == 1) {
        for (size_t i = 0; i < samples; ++i)
            if (src[i] > maxval) above_maxval(in, src[i], maxval);
        std::memcpy(image.data.data(), src, samples);
    } else {
        uint16_t* dst = reinterpret_cast<uint16_t*>(image.data.data());
        for (size_t i = 0; i < samples; ++i) {
            const uint16_t v = uint16_t(uint16_t(src[2 * i]) << 8 | src[2 * i + 1]);
            if (v > maxval) above_maxval(in, v, maxval);
            dst[i] = v;
        }
    }
    return image;
}

std::vector<uint8_t> write_pnm(const geometry::Image& image) {
    const bool wide = image.bytes_per_channel == 2;
    const std::string header = std::string(image.num_channels == 1 ? "P5\n" : "P6\n") + std::to_string(image.width) +
                               " " + std::to_string(image.height) + "\n" + (wide ? "65535" : "255") + "\n";
    std::vector<uint8_t> out = output_buffer(header.size() + image.byte_size());
    std::memcpy(out.data(), header.data(), header.size());
    uint8_t* dst = out.data() + header.size();
    if (!wide) {
        std::memcpy(dst, image.data.data(), image.byte_size());
    } else {
        const size_t samples = image.byte_size() / 2;
        const uint16_t* src = reinterpret_cast<const uint16_t*>(image.data.data());
        for (size_t i = 0; i < samples; ++i) {
            dst[2 * i] = uint8_t(src[i] >> 8);
            dst[2 * i + 1] = uint8_t(src[i] & 0xff);
        }
    }
    return out;
}

}  // namespace o3d::io::detail
