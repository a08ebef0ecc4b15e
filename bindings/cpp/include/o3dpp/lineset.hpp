// SPDX-License-Identifier: MIT
#pragma once
/// @file lineset.hpp
/// @brief o3dpp::LineSet (move-only owner of an o3d_lineset_t): points, lines between them, per-line colors.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/lineset.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/lineset.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

using Line = std::array<int32_t, 2>;  ///< two point indices

namespace detail {
using LineSetArrayFns =
    ArrayFns<&o3d_lineset_has_array, &o3d_lineset_array_shape, &o3d_lineset_get_array, &o3d_lineset_array_view,
             &o3d_lineset_array_mutable_view, &o3d_lineset_set_array, &o3d_lineset_set_array_f32,
             &o3d_lineset_get_index_array, &o3d_lineset_index_array_view, &o3d_lineset_index_array_mutable_view,
             &o3d_lineset_set_index_array>;
}  // namespace detail

/// @brief o3d.geometry.LineSet. Line indices may hold any value; operations that follow them check them.
/// The methods that pass their arguments to one C function are generated (detail::LineSetCalls).
class LineSet : public Owner<LineSet, o3d_lineset_t, &o3d_lineset_destroy>,
                public Arrays<LineSet, LineSetArray, detail::LineSetArrayFns>,
                public detail::LineSetCalls<LineSet> {
    friend class detail::LineSetCalls<LineSet>;  // checks its calls with done
    using A = LineSetArray;

public:
    /// @brief New empty line set.
    LineSet() : Owner(make(&o3d_lineset_create)) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit LineSet(o3d_lineset_t* owned) : Owner(owned) {}
    LineSet(const std::vector<Vec3>& points, const std::vector<Line>& lines) : LineSet() {
        set_points(points);
        set_lines(lines);
    }

    /// @brief Deep copy.
    LineSet clone() const { return derive(&o3d_lineset_clone); }

    // --- named arrays (see Arrays for the generic accessor); views are borrowed until the next mutation ---
    void set_points(const std::vector<Vec3>& v) { set_array(A::Points, v); }
    /// @brief One color per line, RGB in [0, 1].
    void set_colors(const std::vector<Vec3>& v) { set_array(A::Colors, v); }
    void set_lines(const std::vector<Line>& lines) { set_array(A::Lines, lines); }
    std::vector<Vec3> get_points() const { return get_array(A::Points); }
    std::vector<Vec3> get_colors() const { return get_array(A::Colors); }
    std::vector<Line> get_lines() const { return get_array<Line>(A::Lines); }
    Rows3<const double> points() const { return array(A::Points); }
    Rows3<const double> colors() const { return array(A::Colors); }
    /// @brief Borrowed lines as 2 * num_lines() values.
    Span<const int32_t> lines() const { return array<int32_t>(A::Lines).flat(); }

    /// @brief cloud0's points then cloud1's, one line per {index into cloud0, index into cloud1}.
    static LineSet create_from_point_cloud_correspondences(const PointCloud& cloud0, const PointCloud& cloud1,
                                                           const std::vector<Line>& correspondences) {
        return adopt([&](o3d_lineset_t** o) {
            return o3d_lineset_create_from_point_cloud_correspondences(
                o, cloud0.get(), cloud1.get(), correspondences.empty() ? nullptr : correspondences.front().data(),
                correspondences.size());
        });
    }
    /// @brief The 12 edges of an oriented box (points in get_box_points order).
    static LineSet create_from_oriented_bounding_box(const OrientedBoundingBox& obb) {
        const o3d_obb_t c = obb.to_c();
        return create(&o3d_lineset_create_from_oriented_bounding_box, &c);
    }
};

}  // namespace o3dpp
