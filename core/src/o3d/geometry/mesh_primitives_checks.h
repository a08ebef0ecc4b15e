// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_primitives_checks.h
/// @brief Argument checks shared by the primitive factories.
#include <cmath>
#include <cstdint>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry::detail {

inline void require_positive(double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
        throw InvalidArgument(std::string(name) + " must be positive and finite, got " + std::to_string(v));
}

inline void require_at_least(int v, int least, const char* name) {
    if (v < least)
        throw InvalidArgument(std::string(name) + " must be >= " + std::to_string(least) + ", got " + std::to_string(v));
}

/// @brief Vertex counts beyond int32 cannot be indexed by the triangles.
inline void require_indexable(int64_t vertices, const char* what) {
    if (vertices > INT32_MAX)
        throw InvalidArgument(std::string(what) + ": the resolution asks for " + std::to_string(vertices) +
                              " vertices, more than int32 triangle indices reach");
}

}  // namespace o3d::geometry::detail
