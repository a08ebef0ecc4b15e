// SPDX-License-Identifier: MIT
// libFuzzer target: bytes -> read_image_from_memory(O3D_FUZZ_FORMAT). Anything but an image,
// o3d::ParseError or o3d::Unsupported (a valid variant not taken, e.g. ASCII PNM) is a finding.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "o3d/io/image_io.h"
#include "o3d/utility/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    o3d::geometry::Image image;
    try {
        image = o3d::io::read_image_from_memory(data, size, O3D_FUZZ_FORMAT);
    } catch (const o3d::ParseError&) {
        return 0;
    } catch (const o3d::Unsupported&) {
        return 0;
    }
    // PNG holds every 8/16-bit image a reader returns; PNM goes back to the PGM or PPM it fits.
    const bool pnm = std::strcmp(O3D_FUZZ_FORMAT, "ppm") == 0 || std::strcmp(O3D_FUZZ_FORMAT, "pgm") == 0;
    const char* out = pnm ? (image.num_channels == 1 ? "pgm" : "ppm") : "png";
    const auto bytes = o3d::io::write_image_to_memory(image, out);
    const auto again = o3d::io::read_image_from_memory(bytes.data(), bytes.size(), out);
    if (again.width != image.width || again.height != image.height) __builtin_trap();
    return 0;
}
