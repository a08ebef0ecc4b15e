// SPDX-License-Identifier: MIT
#include "o3d/geometry/ball_pivoting_front.h"

namespace o3d::geometry::ball_pivoting {

Front::Front(size_t num_vertices) : head_(num_vertices, -1), open_edges_(num_vertices, 0) {}

int Front::find_edge(int a, int b) const {
    // Incidence lists are short (the vertex degree), so a walk beats any hash map.
    for (int e = head_[a]; e >= 0;) {
        const Edge& edge = edges_[e];
        if (edge.source == a) {
            if (edge.target == b) return e;
            e = edge.next_at_source;
        } else {
            if (edge.source == b) return e;
            e = edge.next_at_target;
        }
    }
    return -1;
}

bool Front::can_add(int a, int b, int c) const {
    const int corners[3] = {a, b, c};
    for (int k = 0; k < 3; ++k) {
        const int s = corners[k], t = corners[(k + 1) % 3];
        const int e = find_edge(s, t);
        if (e < 0) continue;
        const Edge& edge = edges_[e];
        // A third triangle on an edge breaks manifoldness; the same direction twice breaks orientation.
        if (edge.state == EdgeState::Inner || edge.source == s) return false;
    }
    return true;
}

int Front::add_or_close_edge(int source, int target, int opposite, int triangle) {
    const int e = find_edge(source, target);
    if (e >= 0) {
        // Glue: the front edge target -> source is now shared by two triangles.
        edges_[e].state = EdgeState::Inner;
        --open_edges_[source];
        --open_edges_[target];
        return e;
    }
    Edge edge;
    edge.source = source;
    edge.target = target;
    edge.opposite = opposite;
    edge.triangle = triangle;
    edge.next_at_source = head_[source];
    edge.next_at_target = head_[target];
    const int id = static_cast<int>(edges_.size());
    edges_.push_back(edge);
    head_[source] = id;
    head_[target] = id;
    ++open_edges_[source];
    ++open_edges_[target];
    queue_.push_back(id);
    return id;
}

void Front::add_triangle(int a, int b, int c, const Eigen::Vector3d& center) {
    const int t = static_cast<int>(triangles_.size());
    triangles_.emplace_back(a, b, c);
    centers_.push_back(center);
    num_used_ += (head_[a] < 0) + (head_[b] < 0) + (head_[c] < 0);
    add_or_close_edge(a, b, c, t);
    add_or_close_edge(b, c, a, t);
    add_or_close_edge(c, a, b, t);
}

int Front::pop_active() {
    // Edges glued after they were queued stay in the queue; they are skipped here.
    while (!queue_.empty()) {
        const int e = queue_.front();
        queue_.pop_front();
        if (edges_[e].state == EdgeState::Active) return e;
    }
    return -1;
}

void Front::reactivate(int e) {
    edges_[e].state = EdgeState::Active;
    queue_.push_back(e);
}

}  // namespace o3d::geometry::ball_pivoting
