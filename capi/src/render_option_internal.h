// SPDX-License-Identifier: MIT
#pragma once
/// @file render_option_internal.h
/// @brief The C RenderOption and the core's, shared by the renderer's and the visualizer's C API.
#include "internal.h"
#include "o3d/visualization.h"
#include "o3d/visualization/render_option.h"

namespace o3d::capi {

/// @brief The core option for a C one (NULL: defaults), checked: flags 0 or 1, enums known, ranges.
visualization::RenderOption render_option_to_core(const o3d_render_option_t* user);
/// @brief Fill `*out` with `option`, as far as the caller's `out->struct_size` goes (checked).
void write_render_option(o3d_render_option_t* out, const visualization::RenderOption& option);
/// @brief A new image handle owning `image`.
o3d_image_t* new_image(geometry::Image&& image);

}  // namespace o3d::capi
