// SPDX-License-Identifier: MIT
#pragma once
/// @file lineset.hpp
/// @brief o3dpp::LineSet (move-only owner of an o3d_lineset_t): points, lines between them, per-line colors.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/lineset.h"
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

using Line = std::array<int32_t, 2>;  ///< two point indices

/// @brief o3d.geometry.LineSet. Line indices may hold any value; operations that follow them check them.
class LineSet {
public:
    /// @brief New empty line set.
    LineSet() {
        o3d_lineset_t* p = nullptr;
        check(o3d_lineset_create(&p));
        h_.reset(p);
    }
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit LineSet(o3d_lineset_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::LineSet: NULL handle");
    }
    LineSet(const std::vector<Vec3>& points, const std::vector<Line>& lines) : LineSet() {
        set_points(points);
        set_lines(lines);
    }
    LineSet(LineSet&&) noexcept = default;
    LineSet& operator=(LineSet&&) noexcept = default;
    LineSet(const LineSet&) = delete;
    LineSet& operator=(const LineSet&) = delete;

    o3d_lineset_t* get() const noexcept { return h_.get(); }
    o3d_lineset_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Deep copy.
    LineSet clone() const { return adopt([&](o3d_lineset_t** o) { return o3d_lineset_clone(o, get()); }); }

    std::size_t num_points() const { return count(&o3d_lineset_num_points); }
    std::size_t num_lines() const { return count(&o3d_lineset_num_lines); }

    void set_points(const std::vector<Vec3>& v) { set_rows(O3D_LINESET_POINTS, v); }
    /// @brief One color per line, RGB in [0, 1].
    void set_colors(const std::vector<Vec3>& v) { set_rows(O3D_LINESET_COLORS, v); }
    std::vector<Vec3> get_points() const { return get_rows(O3D_LINESET_POINTS); }
    std::vector<Vec3> get_colors() const { return get_rows(O3D_LINESET_COLORS); }
    /// @brief Borrowed views, valid until the next mutating call or destruction.
    Rows3<const double> points() const { return view(O3D_LINESET_POINTS); }
    Rows3<const double> colors() const { return view(O3D_LINESET_COLORS); }

    void set_lines(const std::vector<Line>& lines) {
        check(o3d_lineset_set_index_array(get(), O3D_LINESET_LINES, lines.empty() ? nullptr : lines.front().data(), lines.size()));
    }
    std::vector<Line> get_lines() const {
        static_assert(sizeof(Line) == 2 * sizeof(int32_t), "Line must be 2 packed ints");
        size_t n = 0;
        check(o3d_lineset_get_index_array(nullptr, 0, &n, get(), O3D_LINESET_LINES));
        std::vector<Line> out(n);
        check(o3d_lineset_get_index_array(n ? out.front().data() : nullptr, n, &n, get(), O3D_LINESET_LINES));
        out.resize(n);
        return out;
    }
    /// @brief Borrowed lines as 2 * num_lines() values.
    Span<const int32_t> lines() const {
        const int32_t* d = nullptr;
        size_t n = 0;
        check(o3d_lineset_index_array_view(&d, &n, get(), O3D_LINESET_LINES));
        return {d, 2 * n};
    }

    LineSet& paint_uniform_color(const Vec3& rgb) {
        check(o3d_lineset_paint_uniform_color(get(), rgb.data()));
        return *this;
    }
    LineSet& transform(const Mat4& t) {
        check(o3d_lineset_transform(get(), t.data()));
        return *this;
    }

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
        return adopt([&](o3d_lineset_t** o) { return o3d_lineset_create_from_oriented_bounding_box(o, &c); });
    }
    /// @brief The 12 edges of [min_bound, max_bound].
    static LineSet create_from_axis_aligned_bounding_box(const Vec3& min_bound, const Vec3& max_bound) {
        return adopt([&](o3d_lineset_t** o) {
            return o3d_lineset_create_from_axis_aligned_bounding_box(o, min_bound.data(), max_bound.data());
        });
    }
    /// @brief The mesh's unique edges, on its vertices.
    static LineSet create_from_triangle_mesh(const TriangleMesh& mesh) {
        return adopt([&](o3d_lineset_t** o) { return o3d_lineset_create_from_triangle_mesh(o, mesh.get()); });
    }

    /// @brief Run `create(o3d_lineset_t**)` and own what it returns.
    template <typename F>
    static LineSet adopt(F&& create) {
        o3d_lineset_t* p = nullptr;
        check(create(&p));
        return LineSet(p);
    }

private:
    std::size_t count(o3d_status (*fn)(const o3d_lineset_t*, size_t*)) const {
        size_t n = 0;
        check(fn(get(), &n));
        return n;
    }
    void set_rows(int32_t which, const std::vector<Vec3>& v) {
        check(o3d_lineset_set_array(get(), which, v.empty() ? nullptr : v.front().data(), v.size()));
    }
    std::vector<Vec3> get_rows(int32_t which) const {
        size_t n = 0;
        check(o3d_lineset_get_array(nullptr, 0, &n, get(), which));
        std::vector<Vec3> out(n);
        check(o3d_lineset_get_array(n ? out.front().data() : nullptr, n, &n, get(), which));
        out.resize(n);
        return out;
    }
    Rows3<const double> view(int32_t which) const {
        const double* d = nullptr;
        size_t n = 0;
        check(o3d_lineset_array_view(&d, &n, get(), which));
        return {d, n};
    }

    UniqueHandle<o3d_lineset_t, &o3d_lineset_destroy> h_;
};

}  // namespace o3dpp
