// SPDX-License-Identifier: MIT
#pragma once
/// @file array_family.h
/// @brief The one way every geometry's arrays are read and written through the C API.
///
/// Each geometry exports the same functions, differing only in the noun: has_array, set_array,
/// set_array_f32, get_array, array_view, array_mutable_view for its float64 (or, for images, byte)
/// arrays, and set_index_array, get_index_array, index_array_view, index_array_mutable_view for its
/// int32 arrays. A geometry only says where array `which` lives (an ArraySlot); the checks, the single
/// copy and the copy-out convention are written once, here.
#include <functional>
#include <string>

#include "internal.h"

namespace o3d::capi {

/// @brief Where one array of a geometry lives: `rows` rows of `cols` values at `data`, whether the
/// geometry counts it as present, and how to replace it (one copy, converting float32 when asked).
template <typename T>
struct ArraySlot {
    T* data = nullptr;
    size_t rows = 0;
    size_t cols = 0;
    bool present = false;
    std::function<void(const T*, size_t)> assign;
    std::function<void(const float*, size_t)> assign_f32;  ///< empty when the array takes no float32
};

/// @brief A slot over a std::vector of fixed-size Eigen vectors (points, normals, colors, ...).
template <typename Vec>
ArraySlot<typename Vec::Scalar> eigen_slot(std::vector<Vec>& v, bool present) {
    using T = typename Vec::Scalar;
    constexpr int cols = Vec::RowsAtCompileTime;
    ArraySlot<T> s;
    s.data = v.empty() ? nullptr : v[0].data();
    s.rows = v.size();
    s.cols = cols;
    s.present = present;
    auto fill = [&v](auto* src, size_t rows) {
        std::vector<Vec> out(rows);
        for (size_t i = 0; i < rows; ++i)
            for (int k = 0; k < cols; ++k) out[i](k) = static_cast<T>(src[cols * i + k]);
        v = std::move(out);
    };
    s.assign = [fill](const T* src, size_t rows) { fill(src, rows); };
    if constexpr (std::is_same_v<T, double>) s.assign_f32 = [fill](const float* src, size_t rows) { fill(src, rows); };
    return s;
}

/// @brief A slot over a flat std::vector (one value per row unless `cols` says otherwise).
template <typename T>
ArraySlot<T> flat_slot(std::vector<T>& v, size_t cols, bool present) {
    ArraySlot<T> s;
    s.data = v.empty() ? nullptr : v.data();
    s.rows = cols ? v.size() / cols : 0;
    s.cols = cols;
    s.present = present;
    s.assign = [&v, cols](const T* src, size_t rows) { v.assign(src, src + rows * cols); };
    return s;
}

[[noreturn]] inline void bad_which(int32_t which, const char* what) {
    throw o3d::InvalidArgument("which " + std::to_string(which) + " is not " + what);
}

template <typename T>
void check_rows(const void* data, size_t rows, size_t cols) {
    if (rows > 0 && !data) throw o3d::InvalidArgument("data is NULL but rows = " + std::to_string(rows));
    if (cols && rows > SIZE_MAX / (cols * sizeof(T)))
        throw o3d::InvalidArgument("rows = " + std::to_string(rows) + " is too large");
}

template <typename T, typename In>
void set_array(const ArraySlot<T>& s, const In* data, size_t rows) {
    check_rows<T>(data, rows, s.cols);
    if constexpr (std::is_same_v<In, float> && !std::is_same_v<T, float>) {
        if (!s.assign_f32) throw o3d::InvalidArgument("this array takes no float32 input");
        s.assign_f32(data, rows);
    } else {
        s.assign(data, rows);
    }
}

template <typename T>
void get_array(const ArraySlot<T>& s, T* out, size_t capacity, size_t* out_rows) {
    require(out_rows, "out_rows");
    copy_out<T>(s.data, s.rows, out, capacity, out_rows, s.cols);
}

template <typename T, typename Ptr>
void view_array(const ArraySlot<T>& s, Ptr* out_data, size_t* out_rows) {
    *require(out_data, "out_data") = s.data;
    *require(out_rows, "out_rows") = s.rows;
}

/// For geometries without int32 arrays.
template <typename H>
ArraySlot<int32_t> no_index_slot(H*, int32_t which) {
    bad_which(which, "an array of this geometry");
}

}  // namespace o3d::capi


/// Defines the float64 (or byte, with T = uint8_t) array functions of one geometry. `SLOT(geometry&, which)`
/// returns its ArraySlot; `GEOM(handle)` its geometry (throwing on NULL).
#define O3D_CAPI_ARRAYS(NOUN, HANDLE, T, SLOT)                                                          \
    O3D_API o3d_status o3d_##NOUN##_set_array(HANDLE* h, int32_t which, const T* data, size_t rows) {        \
        return o3d::capi::guard(__func__, [&] { o3d::capi::set_array(SLOT(h, which), data, rows); });     \
    }                                                                                                     \
    O3D_API o3d_status o3d_##NOUN##_get_array(T* out, size_t capacity, size_t* out_rows, const HANDLE* h,   \
                                              int32_t which) {                                            \
        return o3d::capi::guard(__func__, [&] {                                                           \
            o3d::capi::get_array(SLOT(const_cast<HANDLE*>(h), which), out, capacity, out_rows);           \
        });                                                                                               \
    }                                                                                                     \
    O3D_API o3d_status o3d_##NOUN##_array_view(const T** out_data, size_t* out_rows, const HANDLE* h,       \
                                               int32_t which) {                                           \
        return o3d::capi::guard(__func__, [&] {                                                           \
            o3d::capi::view_array(SLOT(const_cast<HANDLE*>(h), which), out_data, out_rows);               \
        });                                                                                               \
    }                                                                                                     \
    O3D_API o3d_status o3d_##NOUN##_array_mutable_view(T** out_data, size_t* out_rows, HANDLE* h,           \
                                                       int32_t which) {                                   \
        return o3d::capi::guard(__func__, [&] { o3d::capi::view_array(SLOT(h, which), out_data, out_rows); }); \
    }

/// has_array and array_shape for one geometry: `which` below 100 names a float64 (or byte) array, from 100
/// on an int32 one.
#define O3D_CAPI_ARRAY_QUERIES(NOUN, HANDLE, SLOT, INDEX_SLOT)                                             \
    O3D_API o3d_status o3d_##NOUN##_has_array(int32_t* out, const HANDLE* h, int32_t which) {              \
        return o3d::capi::guard(__func__, [&] {                                                           \
            HANDLE* g = const_cast<HANDLE*>(h);                                                           \
            *o3d::capi::require(out, "out") =                                                             \
                (which >= O3D_INDEX_ARRAY_FIRST ? INDEX_SLOT(g, which).present : SLOT(g, which).present) ? 1 : 0; \
        });                                                                                               \
    }                                                                                                     \
    O3D_API o3d_status o3d_##NOUN##_array_shape(size_t* out_rows, size_t* out_cols, const HANDLE* h,        \
                                                int32_t which) {                                          \
        return o3d::capi::guard(__func__, [&] {                                                           \
            HANDLE* g = const_cast<HANDLE*>(h);                                                           \
            o3d::capi::require(out_rows, "out_rows");                                                     \
            o3d::capi::require(out_cols, "out_cols");                                                     \
            if (which >= O3D_INDEX_ARRAY_FIRST) {                                                          \
                const auto s = INDEX_SLOT(g, which);                                                      \
                *out_rows = s.rows;                                                                       \
                *out_cols = s.cols;                                                                       \
            } else {                                                                                      \
                const auto s = SLOT(g, which);                                                            \
                *out_rows = s.rows;                                                                       \
                *out_cols = s.cols;                                                                       \
            }                                                                                             \
        });                                                                                               \
    }

/// As O3D_CAPI_ARRAYS, plus set_array_f32 (float32 input converted in the one copy).
#define O3D_CAPI_ARRAYS_F64(NOUN, HANDLE, SLOT)                                                         \
    O3D_CAPI_ARRAYS(NOUN, HANDLE, double, SLOT)                                                       \
    O3D_API o3d_status o3d_##NOUN##_set_array_f32(HANDLE* h, int32_t which, const float* data, size_t rows) { \
        return o3d::capi::guard(__func__, [&] { o3d::capi::set_array(SLOT(h, which), data, rows); });     \
    }

/// The int32 array functions of one geometry; `SLOT(handle, which)` returns an ArraySlot<int32_t>.
#define O3D_CAPI_INDEX_ARRAYS(NOUN, HANDLE, SLOT)                                                             \
    O3D_API o3d_status o3d_##NOUN##_set_index_array(HANDLE* h, int32_t which, const int32_t* data,          \
                                                    size_t rows) {                                        \
        return o3d::capi::guard(__func__, [&] { o3d::capi::set_array(SLOT(h, which), data, rows); });     \
    }                                                                                                     \
    O3D_API o3d_status o3d_##NOUN##_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,        \
                                                    const HANDLE* h, int32_t which) {                     \
        return o3d::capi::guard(__func__, [&] {                                                           \
            o3d::capi::get_array(SLOT(const_cast<HANDLE*>(h), which), out, capacity, out_rows);           \
        });                                                                                               \
    }                                                                                                     \
    O3D_API o3d_status o3d_##NOUN##_index_array_view(const int32_t** out_data, size_t* out_rows,            \
                                                     const HANDLE* h, int32_t which) {                    \
        return o3d::capi::guard(__func__, [&] {                                                           \
            o3d::capi::view_array(SLOT(const_cast<HANDLE*>(h), which), out_data, out_rows);               \
        });                                                                                               \
    }                                                                                                     \
    O3D_API o3d_status o3d_##NOUN##_index_array_mutable_view(int32_t** out_data, size_t* out_rows,          \
                                                             HANDLE* h, int32_t which) {                  \
        return o3d::capi::guard(__func__, [&] { o3d::capi::view_array(SLOT(h, which), out_data, out_rows); }); \
    }
