// SPDX-License-Identifier: MIT
// libFuzzer target: bytes -> read_triangle_mesh_from_memory(O3D_FUZZ_FORMAT). Anything but a mesh or
// o3d::ParseError (another exception, a crash, a sanitizer report, a leak) is a finding.
#include <cstddef>
#include <cstdint>

#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    o3d::geometry::TriangleMesh mesh;
    try {
        o3d::io::MeshReadOptions options;
        options.enable_post_processing = size % 2 == 1;  // exercise the vertex merging too
        mesh = o3d::io::read_triangle_mesh_from_memory(data, size, O3D_FUZZ_FORMAT, options);
    } catch (const o3d::ParseError&) {
        return 0;
    }
    // Whatever the reader accepts, the writer must encode and the reader take back whole.
    o3d::io::MeshWriteOptions w;
    w.write_ascii = size % 3 == 0;
    const auto bytes = o3d::io::write_triangle_mesh_to_memory(mesh, O3D_FUZZ_FORMAT, w);
    const auto again = o3d::io::read_triangle_mesh_from_memory(bytes.data(), bytes.size(), O3D_FUZZ_FORMAT);
    if (again.triangles.size() != mesh.triangles.size()) __builtin_trap();
    return 0;
}
