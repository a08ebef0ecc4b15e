// SPDX-License-Identifier: MIT
#pragma once
/// @file delaunay_test_points.h
/// @brief Point sets shared by the TetraMesh and alpha-shape tests.
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace o3d::test {

/// @brief A torus (R = 1, r = 0.35 with a 5% radial jitter) sampled by golden-ratio sequences: fully
/// deterministic, and the same formula as torus_points() in tools/reference/record_alpha_shape.py.
inline std::vector<Eigen::Vector3d> torus_points(int n) {
    std::vector<Eigen::Vector3d> pts;
    const double two_pi = 2.0 * M_PI;
    for (int i = 0; i < n; ++i) {
        const double fu = i * 0.6180339887498949, fv = i * 0.7548776662466927, fs = i * 0.5698402909980532;
        const double u = two_pi * (fu - std::floor(fu)), v = two_pi * (fv - std::floor(fv));
        const double r = 0.35 * (1.0 + 0.05 * ((fs - std::floor(fs)) - 0.5));
        pts.emplace_back((1.0 + r * std::cos(v)) * std::cos(u), (1.0 + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
    return pts;
}

/// @brief `n` uniform random points in the ball of radius `radius` about the origin.
inline std::vector<Eigen::Vector3d> ball_points(size_t n, double radius, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Eigen::Vector3d> pts;
    while (pts.size() < n) {
        const Eigen::Vector3d p(u(rng), u(rng), u(rng));
        if (p.squaredNorm() <= 1.0) pts.push_back(radius * p);
    }
    return pts;
}

/// @brief `n` random points on the sphere of radius `radius` (radii jittered by +-`jitter` so that the set
/// is not exactly cospherical).
inline std::vector<Eigen::Vector3d> sphere_points(size_t n, double radius, double jitter, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(-jitter, jitter);
    std::vector<Eigen::Vector3d> pts;
    for (size_t i = 0; i < n; ++i) pts.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * (radius + u(rng)));
    return pts;
}

}  // namespace o3d::test
