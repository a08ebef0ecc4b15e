// SPDX-License-Identifier: MIT
// Steps 2-4 of planar patch detection: grow patches over the neighbour graph, merge coplanar neighbours, refit.
#include <algorithm>
#include <numeric>
#include <utility>

#include "o3d/geometry/planar_patches_detail.h"

namespace o3d::geometry::planar_patches {
namespace {

/// Bound on grow / merge / refit rounds; each round changes something, and in practice a few suffice.
constexpr int kMaxRounds = 100;

/// @brief Adds to patch p, breadth first, every unassigned neighbour its plane accepts. Returns the count.
size_t grow(const Cloud& cloud, std::vector<Patch>& patches, int p, std::vector<int>& plane_of) {
    Patch& patch = patches[static_cast<size_t>(p)];
    const auto& nb = cloud.neighbours;
    const size_t before = patch.members.size();
    // members doubles as the queue: the points appended are visited in turn.
    for (size_t k = 0; k < patch.members.size(); ++k) {
        const auto i = static_cast<size_t>(patch.members[k]);
        for (int64_t e = nb.offsets[i]; e < nb.offsets[i + 1]; ++e) {
            const auto j = static_cast<size_t>(nb.indices[static_cast<size_t>(e)]);
            if (plane_of[j] != -1 || !patch.plane.accepts((*cloud.points)[j], cloud.normals[j])) continue;
            plane_of[j] = p;
            patch.members.push_back(static_cast<int>(j));
        }
    }
    return patch.members.size() - before;
}

/// @brief Pairs (a < b) of live patches joined by a neighbour edge, ascending.
std::vector<std::pair<int, int>> adjacent_pairs(const Cloud& cloud, const std::vector<int>& plane_of) {
    std::vector<std::pair<int, int>> pairs;
    const auto& nb = cloud.neighbours;
    for (size_t i = 0; i < plane_of.size(); ++i) {
        const int a = plane_of[i];
        if (a < 0) continue;
        for (int64_t e = nb.offsets[i]; e < nb.offsets[i + 1]; ++e) {
            const int b = plane_of[static_cast<size_t>(nb.indices[static_cast<size_t>(e)])];
            if (b >= 0 && b != a) pairs.emplace_back(std::min(a, b), std::max(a, b));
        }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
}

/// @brief Merges patch `from` into `into` when at least half of the smaller one's points lie within the
/// larger one's bounds and the union passes the planarity test. Returns whether it merged.
bool try_merge(const Cloud& cloud, const Settings& settings, Patch& into, Patch& from) {
    const Patch& large = into.members.size() >= from.members.size() ? into : from;
    const Patch& small = &large == &into ? from : into;
    size_t within = 0;
    for (int i : small.members)
        if (large.plane.accepts((*cloud.points)[static_cast<size_t>(i)], cloud.normals[static_cast<size_t>(i)]))
            ++within;
    if (2 * within < small.members.size()) return false;

    std::vector<int> merged = into.members;
    merged.insert(merged.end(), from.members.begin(), from.members.end());
    Plane plane;
    std::vector<int> inliers;
    // The union is judged like a cell, but without the size floors (both parts already passed them).
    Settings union_settings = settings;
    union_settings.min_points = 3;
    if (!test_planarity(cloud, merged, union_settings, plane, inliers)) return false;
    into.plane = plane;
    into.members = std::move(merged);
    into.fitted_size = into.members.size();
    from.members.clear();
    from.alive = false;
    return true;
}

/// @brief One merge pass over the adjacent pairs in ascending order (union-find: a patch merged away is
/// represented by the one that absorbed it). The lower index survives. Returns whether anything merged.
bool merge_pass(const Cloud& cloud, const Settings& settings, std::vector<Patch>& patches,
                std::vector<int>& plane_of) {
    std::vector<int> parent(patches.size());
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&parent](int x) {
        while (parent[static_cast<size_t>(x)] != x) x = parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
        return x;
    };
    bool merged = false;
    for (const auto& [a0, b0] : adjacent_pairs(cloud, plane_of)) {
        const int a = find(a0), b = find(b0);
        if (a == b) continue;
        const int keep = std::min(a, b), drop = std::max(a, b);
        if (!try_merge(cloud, settings, patches[static_cast<size_t>(keep)], patches[static_cast<size_t>(drop)]))
            continue;
        parent[static_cast<size_t>(drop)] = keep;
        for (int i : patches[static_cast<size_t>(keep)].members) plane_of[static_cast<size_t>(i)] = keep;
        merged = true;
    }
    return merged;
}

/// @brief Refits the plane (not its bounds) of each patch that grew since its last fit. Returns whether any did.
bool refit_grown(const Cloud& cloud, std::vector<Patch>& patches) {
    bool refitted = false;
    for (Patch& patch : patches) {
        if (!patch.alive || patch.members.size() == patch.fitted_size) continue;
        fit_plane(*cloud.points, patch.members, patch.plane.normal, patch.plane.center);
        patch.fitted_size = patch.members.size();
        refitted = true;
    }
    return refitted;
}

}  // namespace

void grow_and_merge(const Cloud& cloud, const Settings& settings, std::vector<Patch>& patches,
                    std::vector<int>& plane_of) {
    for (int round = 0; round < kMaxRounds; ++round) {
        bool changed = false;
        for (size_t p = 0; p < patches.size(); ++p)
            if (patches[p].alive && grow(cloud, patches, static_cast<int>(p), plane_of) > 0) changed = true;
        if (merge_pass(cloud, settings, patches, plane_of)) changed = true;
        if (refit_grown(cloud, patches)) changed = true;
        if (!changed) break;
    }
}

}  // namespace o3d::geometry::planar_patches
