// SPDX-License-Identifier: MIT
#pragma once
/// @file internal.h
/// @brief Plumbing shared by every C API translation unit: the exception guard, the thread-local
/// error, argument checks, versioned options structs, and the handle structs shared across modules.
/// Nothing here is exported.
#include <cstring>
#include <functional>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "o3d/common.h"
#include "o3d/pointcloud.h"
#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/half_edge_mesh.h"
#include "o3d/geometry/image.h"
#include "o3d/geometry/line_set.h"
#include "o3d/geometry/octree.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/rgbd_image.h"
#include "o3d/geometry/tetra_mesh.h"
#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/voxel_grid.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/feature.h"
#include "o3d/registration/registration_result.h"
#include "o3d/utility/error.h"

struct o3d_pointcloud {
    o3d::geometry::PointCloud cloud;
};

struct o3d_trianglemesh {
    o3d::geometry::TriangleMesh mesh;
};

struct o3d_halfedgemesh {
    o3d::geometry::HalfEdgeTriangleMesh mesh;
};
struct o3d_tetramesh {
    o3d::geometry::TetraMesh mesh;
};

struct o3d_image {
    o3d::geometry::Image image;
};

struct o3d_rgbd_image {
    o3d::geometry::RGBDImage rgbd;
};

struct o3d_camera_trajectory {
    o3d::camera::PinholeCameraTrajectory trajectory;
};

struct o3d_lineset {
    o3d::geometry::LineSet lineset;
};

struct o3d_voxelgrid {
    o3d::geometry::VoxelGrid grid;
};

struct o3d_octree {
    o3d::geometry::Octree octree;
};

struct o3d_registration_result {
    o3d::registration::RegistrationResult result;
};

struct o3d_feature {
    o3d::registration::Feature feature;
};

/// Compressed rows: list i is values[offsets[i] .. offsets[i + 1]).
struct o3d_index_lists {
    std::vector<int64_t> offsets{0};
    std::vector<int32_t> values;
};
struct o3d_buffer {
    std::vector<uint8_t> bytes;
};

namespace o3d::capi {

/// @brief Record a failure for this thread and return `status`.
o3d_status fail(o3d_status status, const std::string& message);
/// @brief Forget the previous failure (called on entry of every guarded call).
void reset_error();

/// @brief Run `body` (returning o3d_status or void), translating every exception into a status
/// with a message. No exception ever leaves the library.
template <typename F>
o3d_status guard(const char* function, F&& body) noexcept {
    try {
        reset_error();
        if constexpr (std::is_void_v<decltype(body())>) {
            body();
            return O3D_OK;
        } else {
            return body();
        }
    } catch (const o3d::InvalidArgument& e) {
        return fail(O3D_ERROR_INVALID_ARGUMENT, std::string(function) + ": " + e.what());
    } catch (const o3d::IoError& e) {
        return fail(O3D_ERROR_IO, std::string(function) + ": " + e.what());
    } catch (const o3d::ParseError& e) {
        return fail(O3D_ERROR_PARSE, std::string(function) + ": " + e.what());
    } catch (const o3d::Unsupported& e) {
        return fail(O3D_ERROR_UNSUPPORTED, std::string(function) + ": " + e.what());
    } catch (const o3d::BufferTooSmall& e) {
        return fail(O3D_ERROR_BUFFER_TOO_SMALL, std::string(function) + ": " + e.what());
    } catch (const o3d::NotConverged& e) {
        return fail(O3D_ERROR_NOT_CONVERGED, std::string(function) + ": " + e.what());
    } catch (const o3d::Cancelled& e) {
        return fail(O3D_ERROR_CANCELLED, std::string(function) + ": " + e.what());
    } catch (const std::bad_alloc&) {
        return fail(O3D_ERROR_OUT_OF_MEMORY, std::string(function) + ": out of memory");
    } catch (const std::length_error& e) {
        return fail(O3D_ERROR_OUT_OF_MEMORY, std::string(function) + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        return fail(O3D_ERROR_INVALID_ARGUMENT, std::string(function) + ": " + e.what());
    } catch (const std::exception& e) {
        return fail(O3D_ERROR_INTERNAL, std::string(function) + ": " + e.what());
    } catch (...) {
        return fail(O3D_ERROR_INTERNAL, std::string(function) + ": unknown error");
    }
}

/// @brief Throw InvalidArgument("<name> is NULL") when `p` is NULL.
template <typename T>
T* require(T* p, const char* name) {
    if (!p) throw o3d::InvalidArgument(std::string(name) + " is NULL");
    return p;
}

/// @brief Read a versioned options struct: start from `defaults`, then take the first
/// `user->struct_size` bytes the caller provided (older, shorter structs keep working).
/// NULL `user` means defaults. A struct_size smaller than the size field or larger than
/// the library knows is rejected.
template <typename T>
T read_options(const T* user, const T& defaults, const char* name) {
    T out = defaults;
    if (!user) return out;
    const uint32_t size = user->struct_size;
    if (size < sizeof(uint32_t) || size > sizeof(T))
        throw o3d::InvalidArgument(std::string(name) + ".struct_size " + std::to_string(size) +
                                   " is not a size this library knows (expected " + std::to_string(sizeof(T)) +
                                   "); call the matching *_init()");
    std::memcpy(&out, user, size);
    out.struct_size = sizeof(T);
    return out;
}

/// @brief Shared body of every `*_init(opts, struct_size)`: write the defaults' first struct_size bytes.
template <typename T>
void init_options(T* opts, uint32_t struct_size, const T& defaults, const char* name) {
    require(opts, name);
    if (struct_size < sizeof(uint32_t) || struct_size > sizeof(T))
        throw o3d::InvalidArgument(std::string(name) + ": struct_size " + std::to_string(struct_size) +
                                   " is not a size this library knows (expected " + std::to_string(sizeof(T)) + ")");
    T filled = defaults;
    filled.struct_size = struct_size;
    std::memcpy(opts, &filled, struct_size);
}

/// @brief Copy-out convention: report `count` in `*out_n`; copy when `out` is non-NULL and
/// `capacity` suffices, else BufferTooSmall (when `out` is non-NULL).
template <typename T>
void copy_out(const T* src, size_t count, T* out, size_t capacity, size_t* out_n, size_t elements_per_item = 1) {
    if (out_n) *out_n = count;
    if (!out) return;
    if (capacity < count)
        throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " items but " + std::to_string(count) +
                                  " are needed");
    if (count) std::memcpy(out, src, count * elements_per_item * sizeof(T));
}

/// @brief The 3 doubles at `v` as a vector; throws InvalidArgument("<name> is NULL") for NULL.
inline Eigen::Vector3d vec3(const double* v, const char* name) {
    require(v, name);
    return Eigen::Vector3d(v[0], v[1], v[2]);
}

/// @brief Write `v` to the 3 doubles at `out`; throws InvalidArgument("<name> is NULL") for NULL.
inline void write3(double* out, const char* name, const Eigen::Vector3d& v) {
    require(out, name);
    out[0] = v.x();
    out[1] = v.y();
    out[2] = v.z();
}

/// @brief Throw InvalidArgument unless `x` is finite.
void require_finite(double x, const char* name);

/// @brief The core search parameter for a C one (NULL: KNN 30); validates kind, knn and radius.
o3d::kdtree::SearchParam to_search_param(const o3d_search_param_t* param);
/// @brief Validate a per-call thread count (0 = library default, negative is invalid).
int to_num_threads(int32_t num_threads);

/// @brief A core progress function over a C callback (non-zero return = cancel); empty when `callback` is NULL.
inline std::function<bool(double)> to_progress(o3d_progress_callback callback, void* user_data) {
    if (!callback) return {};
    return [callback, user_data](double fraction) { return callback(fraction, user_data) == 0; };
}
/// @brief A row-major 4x4 (16 doubles) as a matrix; NULL means identity. Non-finite entries are
/// rejected with InvalidArgument naming `name`. (Defined in registration.cpp.)
Eigen::Matrix4d read_transform(const double* m, const char* name);

/// @brief Check a new-handle out-parameter and clear it, so a failing call leaves `*out == NULL`.
template <typename Handle>
Handle** require_out_handle(Handle** out, const char* name = "out") {
    require(out, name);
    *out = nullptr;
    return out;
}

/// @brief Hand `value` to the caller as a new handle of type Handle (whose one member it becomes).
template <typename Handle, typename Value>
void emit_handle(Handle** out, Value&& value) {
    *out = new Handle{std::forward<Value>(value)};
}

/// @brief Index lists from per-list vectors (each list as given).
o3d_index_lists_t* make_index_lists(const std::vector<std::vector<int>>& lists);
/// @brief Index lists from compressed rows (offsets of num_lists + 1, the first 0).
o3d_index_lists_t* make_index_lists(const std::vector<int>& offsets, const std::vector<int>& values);

}  // namespace o3d::capi
