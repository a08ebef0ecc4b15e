// SPDX-License-Identifier: MIT
#pragma once
/// @file selection.hpp
/// @brief o3dpp::SelectionPolygonVolume (move-only owner of an o3d_selection_polygon_volume_t): a prism over a
/// polygon that crops clouds and meshes (o3d.visualization.SelectionPolygonVolume).
#include <cstdint>
#include <vector>

#include "o3d/selection.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/selection.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"

namespace o3dpp {

/// @brief The polygon lies across get_orthogonal_axis(), the prism runs along it over
/// [get_axis_min(), get_axis_max()]. read_json, the axis and range accessors and the crops are generated
/// (detail::SelectionPolygonVolumeCalls); what is written here returns the enum or variable-length arrays.
class SelectionPolygonVolume
    : public Owner<SelectionPolygonVolume, o3d_selection_polygon_volume_t, &o3d_selection_polygon_volume_destroy>,
      public detail::SelectionPolygonVolumeCalls<SelectionPolygonVolume> {
    friend class detail::SelectionPolygonVolumeCalls<SelectionPolygonVolume>;  // checks its calls with done

public:
    /// @brief Empty: orthogonal axis Y, range [0, 0], no polygon (set one before cropping).
    SelectionPolygonVolume() : Owner(make(&o3d_selection_polygon_volume_create)) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit SelectionPolygonVolume(o3d_selection_polygon_volume_t* owned) : Owner(owned) {}

    /// @brief The corners in order; their coordinate along the orthogonal axis is ignored.
    std::vector<Vec3> get_bounding_polygon() const {
        return copy_out<Vec3>(&o3d_selection_polygon_volume_get_bounding_polygon);
    }
    SelectionPolygonVolume& set_bounding_polygon(const std::vector<Vec3>& corners) {
        return done(o3d_selection_polygon_volume_set_bounding_polygon(
            get(), corners.empty() ? nullptr : corners.front().data(), corners.size()));
    }
    /// @brief Indices of the points of `pc` inside, ascending.
    std::vector<int32_t> crop_in_polygon(const PointCloud& pc) const {
        return copy_out<int32_t>(&o3d_selection_polygon_volume_crop_in_polygon, pc.get());
    }
};

}  // namespace o3dpp
