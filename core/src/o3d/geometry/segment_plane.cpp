// SPDX-License-Identifier: MIT
#include "o3d/geometry/segment_plane.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_set>

#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

namespace {

/// SplitMix64: a tiny, high-quality generator; its state is seeded per iteration.
struct SplitMix64 {
    uint64_t state;
    uint64_t next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// Uniform in [0, n) (Lemire's multiply-shift; the bias is below 2^-32 for n < 2^31).
    uint64_t below(uint64_t n) { return static_cast<uint64_t>((static_cast<unsigned __int128>(next()) * n) >> 64); }
};

/// The distinct indices of iteration `iteration`: a function of (seed, iteration) only.
void draw_sample(uint64_t seed, int iteration, size_t n, int count, std::vector<int64_t>& sample) {
    SplitMix64 rng{seed};
    rng.state = rng.next() ^ (static_cast<uint64_t>(iteration) * 0xD1B54A32D192ED03ull);
    sample.clear();
    if (count <= 16) {
        while (static_cast<int>(sample.size()) < count) {
            const int64_t idx = static_cast<int64_t>(rng.below(n));
            if (std::find(sample.begin(), sample.end(), idx) == sample.end()) sample.push_back(idx);
        }
    } else {
        std::unordered_set<int64_t> seen;
        while (static_cast<int>(sample.size()) < count) {
            const int64_t idx = static_cast<int64_t>(rng.below(n));
            if (seen.insert(idx).second) sample.push_back(idx);
        }
    }
}

Eigen::Vector4d triangle_plane(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2) {
    Eigen::Vector3d abc = (p1 - p0).cross(p2 - p0);
    const double norm = abc.norm();
    if (norm == 0.0 || !std::isfinite(norm)) return Eigen::Vector4d::Zero();
    abc /= norm;
    return Eigen::Vector4d(abc.x(), abc.y(), abc.z(), -abc.dot(p0));
}

struct Candidate {
    bool valid = false;
    Eigen::Vector4d plane = Eigen::Vector4d::Zero();
    double fitness = 0.0;
    double rmse = 0.0;
};

/// Open3D's EvaluateRANSACBasedOnDistance (without materialising the inliers).
Candidate evaluate(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector4d& plane, double threshold) {
    Candidate c;
    c.valid = true;
    c.plane = plane;
    double error = 0.0;
    size_t inliers = 0;
    for (const auto& p : points) {
        const double d = std::abs(plane.head<3>().dot(p) + plane[3]);
        if (d <= threshold) {
            error += d;
            ++inliers;
        }
    }
    if (inliers > 0) {
        c.fitness = static_cast<double>(inliers) / static_cast<double>(points.size());
        c.rmse = error / std::sqrt(static_cast<double>(inliers));
    }
    return c;
}

}  // namespace

Eigen::Vector4d fit_plane(const std::vector<Eigen::Vector3d>& points, const std::vector<int64_t>& indices) {
    if (indices.empty()) return Eigen::Vector4d::Zero();
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for (int64_t i : indices) centroid += points[i];
    centroid /= static_cast<double>(indices.size());
    double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
    for (int64_t i : indices) {
        const Eigen::Vector3d r = points[i] - centroid;
        xx += r.x() * r.x();
        xy += r.x() * r.y();
        xz += r.x() * r.z();
        yy += r.y() * r.y();
        yz += r.y() * r.z();
        zz += r.z() * r.z();
    }
    const double det_x = yy * zz - yz * yz;
    const double det_y = xx * zz - xz * xz;
    const double det_z = xx * yy - xy * xy;
    Eigen::Vector3d abc;
    if (det_x > det_y && det_x > det_z)
        abc = Eigen::Vector3d(det_x, xz * yz - xy * zz, xy * yz - xz * yy);
    else if (det_y > det_z)
        abc = Eigen::Vector3d(xz * yz - xy * zz, det_y, xy * xz - yz * xx);
    else
        abc = Eigen::Vector3d(xy * yz - xz * yy, xy * xz - yz * xx, det_z);
    const double norm = abc.norm();
    if (norm == 0.0 || !std::isfinite(norm)) return Eigen::Vector4d::Zero();
    abc /= norm;
    return Eigen::Vector4d(abc.x(), abc.y(), abc.z(), -abc.dot(centroid));
}

PlaneSegmentation segment_plane(const PointCloud& cloud, double distance_threshold, int ransac_n, int num_iterations,
                                double probability, uint64_t seed, int num_threads) {
    if (!std::isfinite(distance_threshold) || distance_threshold < 0.0)
        throw InvalidArgument("distance_threshold must be finite and >= 0, got " + std::to_string(distance_threshold));
    if (ransac_n < 3) throw InvalidArgument("ransac_n must be >= 3, got " + std::to_string(ransac_n));
    if (num_iterations < 1)
        throw InvalidArgument("num_iterations must be >= 1, got " + std::to_string(num_iterations));
    if (!(probability > 0.0 && probability <= 1.0))
        throw InvalidArgument("probability must be in (0, 1], got " + std::to_string(probability));
    const std::vector<Eigen::Vector3d>& points = cloud.points;
    if (points.size() < static_cast<size_t>(ransac_n))
        throw InvalidArgument("segment_plane needs at least ransac_n = " + std::to_string(ransac_n) +
                              " points, the cloud has " + std::to_string(points.size()));

    const int threads = utility::resolve_num_threads(num_threads);
    // Blocks of iterations are evaluated in parallel, then reduced in iteration order. The block size is
    // fixed, so only the wasted work past an early exit depends on the thread count, never the result.
    constexpr int kBlock = 64;
    std::vector<Candidate> block(kBlock);
    Candidate best;
    double break_iteration = std::numeric_limits<double>::infinity();
    double iteration_count = 0;  // models evaluated (degenerate samples do not count, as Open3D)
    bool done = false;
    for (int start = 0; start < num_iterations && !done; start += kBlock) {
        const int count = std::min(kBlock, num_iterations - start);
#pragma omp parallel num_threads(threads) if (threads > 1 && points.size() * count > 20000)
        {
            std::vector<int64_t> sample;
#pragma omp for schedule(dynamic, 1)
            for (int k = 0; k < count; ++k) {
                draw_sample(seed, start + k, points.size(), ransac_n, sample);
                const Eigen::Vector4d plane = ransac_n == 3
                                                  ? triangle_plane(points[sample[0]], points[sample[1]], points[sample[2]])
                                                  : fit_plane(points, sample);
                block[k] = plane.isZero(0) ? Candidate{} : evaluate(points, plane, distance_threshold);
            }
        }
        for (int k = 0; k < count; ++k) {
            if (iteration_count > break_iteration) {
                done = true;
                break;
            }
            const Candidate& c = block[k];
            if (!c.valid) continue;
            if (c.fitness > best.fitness || (c.fitness == best.fitness && c.rmse < best.rmse) || !best.valid) {
                // !best.valid: Open3D starts from fitness 0 / rmse 0 and keeps the zero plane when no sample has
                // an inlier; here the first valid model is kept instead (it is then refitted below).
                const bool improved = c.fitness > best.fitness || (c.fitness == best.fitness && c.rmse < best.rmse);
                best = c;
                if (improved) {
                    if (c.fitness < 1.0) {
                        // Open3D's formula; a denominator that rounds to 0 (tiny fitness) leaves the budget alone.
                        const double den = std::log(1.0 - std::pow(c.fitness, ransac_n));
                        if (den < 0.0) {
                            const double b = std::log(1.0 - probability) / den;
                            if (!std::isnan(b)) break_iteration = std::min(break_iteration, std::floor(b));
                        }
                    } else {
                        break_iteration = 0;
                    }
                }
            }
            iteration_count += 1;
        }
    }
    if (!best.valid)
        throw NotConverged("segment_plane: every RANSAC sample was degenerate (are the points collinear?)");

    PlaneSegmentation out;
    const Eigen::Vector4d& model = best.plane;
    for (size_t i = 0; i < points.size(); ++i)
        if (std::abs(model.head<3>().dot(points[i]) + model[3]) <= distance_threshold)
            out.inliers.push_back(static_cast<int64_t>(i));
    const Eigen::Vector4d refit = fit_plane(points, out.inliers);
    out.plane = refit.isZero(0) ? model : refit;
    return out;
}

}  // namespace o3d::geometry
