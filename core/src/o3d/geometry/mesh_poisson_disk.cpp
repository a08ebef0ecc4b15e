// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_poisson_disk.h"

#include <Eigen/Geometry>  // cross(), used by triangle_cross
#include <climits>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "o3d/geometry/mesh_sampling.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

/// @brief Max-heap of sample indices by (weight, index), with each sample's position tracked so that a
/// lowered weight sifts down in place (Yuksel's elimination heap).
class EliminationHeap {
public:
    explicit EliminationHeap(const std::vector<double>& weight)
        : weight_(weight), heap_(weight.size()), pos_(weight.size()) {
        for (size_t i = 0; i < heap_.size(); ++i) heap_[i] = pos_[i] = i;
        for (size_t i = heap_.size() / 2; i-- > 0;) sift_down(i);
    }
    /// @brief Remove and return the heaviest sample (the higher index on a tie).
    size_t pop() {
        const size_t top = heap_[0];
        place(0, heap_.back());
        heap_.pop_back();
        if (!heap_.empty()) sift_down(0);
        return top;
    }
    /// @brief Restore the order after sample i's weight dropped.
    void lowered(size_t i) { sift_down(pos_[i]); }

private:
    bool heavier(size_t a, size_t b) const { return weight_[a] > weight_[b] || (weight_[a] == weight_[b] && a > b); }
    void place(size_t slot, size_t sample) {
        heap_[slot] = sample;
        pos_[sample] = slot;
    }
    void sift_down(size_t slot) {
        const size_t n = heap_.size(), sample = heap_[slot];
        for (;;) {
            size_t child = 2 * slot + 1;
            if (child >= n) break;
            if (child + 1 < n && heavier(heap_[child + 1], heap_[child])) ++child;
            if (!heavier(heap_[child], sample)) break;
            place(slot, heap_[child]);
            slot = child;
        }
        place(slot, sample);
    }

    const std::vector<double>& weight_;
    std::vector<size_t> heap_, pos_;
};

}  // namespace

PointCloud sample_points_poisson_disk(const TriangleMesh& mesh, size_t number_of_points, double init_factor,
                                      bool use_triangle_normal, uint64_t seed, int num_threads) {
    validate_triangles(mesh);
    if (!std::isfinite(init_factor) || init_factor < 1.0)
        throw InvalidArgument("init_factor must be finite and >= 1, got " + std::to_string(init_factor));
    if (number_of_points == 0) throw InvalidArgument("number_of_points must be > 0");
    const double initial = std::floor(init_factor * static_cast<double>(number_of_points));
    if (initial > static_cast<double>(INT_MAX))
        throw InvalidArgument("init_factor * number_of_points = " + std::to_string(initial) +
                              " initial samples is more than the 2^31 - 1 supported");
    PointCloud cloud =
        sample_points_uniformly(mesh, static_cast<size_t>(initial), use_triangle_normal, seed, num_threads);
    const size_t count = cloud.points.size();
    if (count <= number_of_points) return cloud;

    double area = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) area += triangle_area(mesh, t);
    const double n = static_cast<double>(number_of_points);
    const double r_max = 2 * std::sqrt(area / n / (2 * std::sqrt(3.0)));
    const double r_min = r_max * 0.5 * (1 - std::pow(n / static_cast<double>(count), 1.5));

    // The samples never move, so each one's neighbours within r_max, and what each contributes to the
    // other's weight, are found once.
    const kdtree::KDTree tree(cloud.points);
    const kdtree::SearchResult near =
        tree.search_batch(cloud.points, kdtree::SearchParam::make_radius(r_max), num_threads);
    std::vector<double> contribution(near.indices.size());
    const int threads = utility::resolve_num_threads(num_threads);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t k = 0; k < static_cast<int64_t>(contribution.size()); ++k) {
        const double d = std::max(std::sqrt(near.distances2[static_cast<size_t>(k)]), r_min);
        const double x = std::max(0.0, 1 - d / r_max), x2 = x * x, x4 = x2 * x2;
        contribution[static_cast<size_t>(k)] = x4 * x4;  // Yuksel's alpha = 8
    }
    // Weights only ever drop (a deletion subtracts what the deleted sample contributed to each neighbour,
    // the distance being symmetric), so an indexed max-heap with sift-down serves, with no stale entries.
    std::vector<double> weight(count, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t ii = 0; ii < static_cast<int64_t>(count); ++ii) {
        const size_t i = static_cast<size_t>(ii);
        double w = 0;
        for (int64_t k = near.offsets[i]; k < near.offsets[i + 1]; ++k) {
            const size_t slot = static_cast<size_t>(k);
            if (static_cast<size_t>(near.indices[slot]) != i) w += contribution[slot];
        }
        weight[i] = w;
    }
    EliminationHeap heap(weight);
    std::vector<uint8_t> deleted(count, 0);
    size_t live = count;
    while (live > number_of_points) {
        const size_t i = heap.pop();
        deleted[i] = 1;
        --live;
        for (int64_t k = near.offsets[i]; k < near.offsets[i + 1]; ++k) {
            const size_t j = static_cast<size_t>(near.indices[static_cast<size_t>(k)]);
            if (j == i || deleted[j]) continue;
            weight[j] -= contribution[static_cast<size_t>(k)];
            heap.lowered(j);
        }
    }

    PointCloud out;
    const bool normals = cloud.has_normals(), colors = cloud.has_colors();
    out.points.reserve(live);
    for (size_t i = 0; i < count; ++i) {
        if (deleted[i]) continue;
        out.points.push_back(cloud.points[i]);
        if (normals) out.normals.push_back(cloud.normals[i]);
        if (colors) out.colors.push_back(cloud.colors[i]);
    }
    return out;
}

}  // namespace o3d::geometry
