// SPDX-License-Identifier: MIT
#pragma once
/// @file ball_pivoting_front.h
/// @brief Ball-pivoting internals: the growing mesh and its front (the edges used by one triangle).
#include <Eigen/Core>
#include <cstdint>
#include <deque>
#include <vector>

namespace o3d::geometry::ball_pivoting {

/// @brief Active: on the front, waiting to be pivoted. Boundary: pivoting found no valid triangle
/// (it may be re-pivoted with a larger ball, or glued by a later triangle). Inner: used by two triangles.
enum class EdgeState : uint8_t { Active, Boundary, Inner };

/// @brief An undirected mesh edge, stored with the direction its first triangle walks it.
struct Edge {
    int32_t source;
    int32_t target;
    int32_t opposite;  ///< the first triangle's third vertex
    int32_t triangle;  ///< the first triangle
    int32_t next_at_source = -1;  ///< next edge in source's incidence list
    int32_t next_at_target = -1;  ///< next edge in target's incidence list
    EdgeState state = EdgeState::Active;
};

/// @brief The triangles found so far and their edges. The paper's front is a set of loops of edges; here
/// the loops are implicit (the edges with one triangle), and the join and glue operations reduce to
/// adding a triangle whose edges either are new (join) or close an edge already on the front (glue).
/// Active edges are pivoted in first-in first-out order, which makes the surface grow as a wave.
class Front {
public:
    explicit Front(size_t num_vertices);

    /// @brief True when no triangle uses `v`.
    bool is_orphan(int v) const { return head_[v] < 0; }
    /// @brief Number of vertices some triangle uses.
    size_t num_used() const { return num_used_; }
    /// @brief True when `v` lies on the front (an edge with a single triangle, active or boundary).
    bool on_front(int v) const { return open_edges_[v] > 0; }
    /// @brief The edge joining a and b, or -1.
    int find_edge(int a, int b) const;
    /// @brief Whether triangle (a, b, c) keeps the mesh edge manifold and consistently oriented: each of
    /// its directed edges a->b, b->c, c->a is new or used once by a triangle walking it the other way.
    bool can_add(int a, int b, int c) const;
    /// @brief Add triangle (a, b, c) (can_add must hold) resting under a ball centred at `center`.
    /// Its new edges become active; the edges it shares with the front become inner.
    void add_triangle(int a, int b, int c, const Eigen::Vector3d& center);

    /// @brief Next active edge, or -1 when the front has none.
    int pop_active();
    /// @brief Pivoting `e` failed: mark it boundary.
    void set_boundary(int e) { edges_[e].state = EdgeState::Boundary; }
    /// @brief Re-activate boundary edge `e` (its triangle's ball centre already updated).
    void reactivate(int e);

    const Edge& edge(int e) const { return edges_[e]; }
    size_t num_edges() const { return edges_.size(); }
    const std::vector<Eigen::Vector3i>& triangles() const { return triangles_; }
    std::vector<Eigen::Vector3i>& triangles() { return triangles_; }
    /// @brief Centre of the ball resting on each triangle (for the radius it was last pivoted with).
    std::vector<Eigen::Vector3d>& centers() { return centers_; }
    const std::vector<Eigen::Vector3d>& centers() const { return centers_; }

private:
    int add_or_close_edge(int source, int target, int opposite, int triangle);

    std::vector<int32_t> head_;        ///< first edge of each vertex's incidence list
    std::vector<int32_t> open_edges_;  ///< number of single-triangle edges at each vertex
    std::vector<Edge> edges_;
    std::vector<Eigen::Vector3i> triangles_;
    std::vector<Eigen::Vector3d> centers_;
    std::deque<int32_t> queue_;
    size_t num_used_ = 0;
};

}  // namespace o3d::geometry::ball_pivoting
