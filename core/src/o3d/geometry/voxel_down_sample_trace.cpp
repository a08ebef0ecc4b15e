// SPDX-License-Identifier: MIT
#include "o3d/geometry/voxel_down_sample_trace.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <string>
#include <tuple>

#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// @brief Open3D's approximate class of one voxel: the most frequent int(red); among equally frequent
/// classes the one whose first occurrence is latest.
double majority_class(const std::vector<Eigen::Vector3d>& colors, const std::vector<int>& members) {
    std::vector<std::pair<int, int>> seen;  // (class, count) in order of first occurrence
    for (int i : members) {
        const int k = static_cast<int>(colors[static_cast<size_t>(i)](0));
        auto it = std::find_if(seen.begin(), seen.end(), [k](const auto& s) { return s.first == k; });
        if (it == seen.end())
            seen.push_back({k, 1});
        else
            ++it->second;
    }
    auto best = seen.rbegin();
    for (auto it = seen.rbegin(); it != seen.rend(); ++it)
        if (it->second > best->second) best = it;
    return static_cast<double>(best->first);
}

}  // namespace

VoxelTrace voxel_down_sample_and_trace(const PointCloud& cloud, double voxel_size, const Eigen::Vector3d& min_bound,
                                       const Eigen::Vector3d& max_bound, bool approximate_class) {
    if (!std::isfinite(voxel_size) || voxel_size <= 0.0)
        throw InvalidArgument("voxel_size must be finite and > 0, got " + std::to_string(voxel_size));
    if (!min_bound.allFinite() || !max_bound.allFinite()) throw InvalidArgument("min_bound and max_bound must be finite");
    if ((max_bound - min_bound).minCoeff() < 0.0) throw InvalidArgument("min_bound > max_bound on an axis");
    // Open3D's own limit on the grid.
    if (voxel_size * static_cast<double>(INT_MAX) < (max_bound - min_bound).maxCoeff())
        throw InvalidArgument("voxel_size " + std::to_string(voxel_size) + " is too small for the bounds");
    const size_t n = cloud.points.size();
    if (n > static_cast<size_t>(INT_MAX)) throw InvalidArgument("the cloud has more points than an int can index");
    const bool with_normals = cloud.has_normals(), with_colors = cloud.has_colors();

    using Voxel = std::array<int, 3>;
    std::vector<Voxel> voxel(n);
    std::vector<int> octant(n);
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        if (!p.allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " is not finite (call remove_non_finite_points first)");
        const Eigen::Vector3d r = (p - min_bound) / voxel_size;
        int oct = 0;
        for (int a = 0; a < 3; ++a) {
            const double f = std::floor(r(a));
            if (!(f >= static_cast<double>(INT_MIN) && f <= static_cast<double>(INT_MAX)))
                throw InvalidArgument("point " + std::to_string(i) + " is too far from min_bound for an int voxel index");
            voxel[i][a] = static_cast<int>(f);
            if (r(a) - f >= 0.5) oct |= 1 << a;
        }
        octant[i] = oct;
        if (approximate_class && with_colors) {
            const double red = cloud.colors[i](0);
            if (!(red > static_cast<double>(INT_MIN) - 1.0 && red < static_cast<double>(INT_MAX) + 1.0))
                throw InvalidArgument("color " + std::to_string(i) + " has a red value that is no int class");
        }
    }

    // Group by voxel, (z, y, x) order; the stable sort keeps each voxel's points ascending.
    std::vector<int> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
        const Voxel& va = voxel[static_cast<size_t>(a)];
        const Voxel& vb = voxel[static_cast<size_t>(b)];
        return std::tie(va[2], va[1], va[0]) < std::tie(vb[2], vb[1], vb[0]);
    });

    VoxelTrace out;
    out.indices = order;
    out.offsets.push_back(0);
    for (size_t s = 0; s < n;) {
        size_t e = s + 1;
        while (e < n && voxel[static_cast<size_t>(order[e])] == voxel[static_cast<size_t>(order[s])]) ++e;
        const std::vector<int> members(order.begin() + static_cast<std::ptrdiff_t>(s),
                                       order.begin() + static_cast<std::ptrdiff_t>(e));
        const double count = static_cast<double>(members.size());
        Eigen::Vector3d point = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero(), color = Eigen::Vector3d::Zero();
        std::array<int, 8> cubic;
        cubic.fill(-1);
        for (int i : members) {
            const size_t k = static_cast<size_t>(i);
            point += cloud.points[k];
            if (with_normals) normal += cloud.normals[k];
            if (with_colors) color += cloud.colors[k];
            cubic[static_cast<size_t>(octant[k])] = i;  // ascending, so the largest index stays
        }
        out.cloud.points.push_back(point / count);
        if (with_normals) out.cloud.normals.push_back(normal / count);
        if (with_colors)
            out.cloud.colors.push_back(approximate_class ? Eigen::Vector3d::Constant(majority_class(cloud.colors, members))
                                                         : Eigen::Vector3d(color / count));
        out.cubic_ids.push_back(cubic);
        out.offsets.push_back(static_cast<int>(e));
        s = e;
    }
    return out;
}

}  // namespace o3d::geometry
