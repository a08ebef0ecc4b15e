// SPDX-License-Identifier: MIT
// libFuzzer target: bytes -> read_point_cloud_from_memory(O3D_FUZZ_FORMAT). Anything but a cloud
// or o3d::ParseError (another exception, a crash, a sanitizer report, a leak) is a finding.
#include <cstddef>
#include <cstdint>

#include "o3d/io/point_cloud_io.h"
#include "o3d/utility/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    o3d::geometry::PointCloud cloud;
    try {
        o3d::io::ReadOptions options;
        options.remove_nan_points = size % 2 == 1;  // exercise the compaction too
        cloud = o3d::io::read_point_cloud_from_memory(data, size, O3D_FUZZ_FORMAT, options);
    } catch (const o3d::ParseError&) {
        return 0;
    }
    // Whatever a reader accepts, the writer must encode and the reader take back whole; an
    // exception escaping here is a finding too.
    const auto bytes = o3d::io::write_point_cloud_to_memory(cloud, O3D_FUZZ_FORMAT);
    const auto again = o3d::io::read_point_cloud_from_memory(bytes.data(), bytes.size(), O3D_FUZZ_FORMAT);
    if (again.size() != cloud.size()) __builtin_trap();
    return 0;
}
