// SPDX-License-Identifier: MIT
#include "o3d/geometry/normal_orientation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

// Neighbours (self included) searched for the Euclidean tree even when k is smaller: on sampled
// surfaces the EMST edges are almost all among the 8 nearest neighbours, so the kNN-graph tree then
// needs few Boruvka bridges.
constexpr int kEuclideanNeighbours = 9;
constexpr int kLeafSize = 8;

struct Edge {
    double w;
    uint32_t a, b;
};

// Ties broken by the vertex pair so the tree, hence the result, does not depend on the input order
// of equal-weight edges (or on the thread that produced them).
bool edge_less(const Edge& x, const Edge& y) {
    if (x.w != y.w) return x.w < y.w;
    if (x.a != y.a) return x.a < y.a;
    return x.b < y.b;
}

struct DisjointSet {
    std::vector<uint32_t> parent, rank;
    explicit DisjointSet(size_t n) : parent(n), rank(n, 0) { std::iota(parent.begin(), parent.end(), 0u); }
    uint32_t find(uint32_t x) {
        while (parent[x] != x) {
            parent[x] = parent[parent[x]];  // path halving
            x = parent[x];
        }
        return x;
    }
    bool unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (rank[a] < rank[b]) std::swap(a, b);
        parent[b] = a;
        if (rank[a] == rank[b]) ++rank[a];
        return true;
    }
};

// Kruskal: the edges of `edges` that join two sets of `ds`, lightest first (ds is updated).
std::vector<Edge> kruskal(std::vector<Edge>& edges, DisjointSet& ds) {
    std::sort(edges.begin(), edges.end(), edge_less);
    std::vector<Edge> tree;
    for (const Edge& e : edges)
        if (ds.unite(e.a, e.b)) tree.push_back(e);
    return tree;
}

// Filters of an edge seen from point i towards point j, as Open3D applies them.
struct EdgeRules {
    const std::vector<Eigen::Vector3d>& p;
    const std::vector<Eigen::Vector3d>& n;
    double cos_alpha_tol;
    double lambda;

    double plane_distance(uint32_t i, uint32_t j) const { return std::abs(n[i].dot(p[j] - p[i])); }
    // In the cone of half-angle alpha around n_i: the edge leaves the surface rather than following it.
    // A zero-length edge (duplicate points) has no direction and is kept.
    bool excluded(uint32_t i, uint32_t j) const {
        if (cos_alpha_tol >= 1.0) return false;
        const double len = (p[j] - p[i]).norm();
        return len > 0.0 && plane_distance(i, j) / len > cos_alpha_tol;
    }
    double euclidean_weight(uint32_t i, uint32_t j) const {
        const double d2 = (p[j] - p[i]).squaredNorm();
        return lambda == 0.0 ? d2 : d2 + lambda * plane_distance(i, j);
    }
    double normal_weight(uint32_t i, uint32_t j) const { return 1.0 - std::abs(n[i].dot(n[j])); }
};

// Quartile by linear interpolation between order statistics (sorted input).
double quantile(const std::vector<double>& sorted, double q) {
    const double pos = q * static_cast<double>(sorted.size() - 1);
    const size_t lo = static_cast<size_t>(std::floor(pos));
    const size_t hi = std::min(lo + 1, sorted.size() - 1);
    return sorted[lo] + (pos - static_cast<double>(lo)) * (sorted[hi] - sorted[lo]);
}

// KD-tree whose nodes know whether all their points lie in one component: the nearest point of another
// component is then found without entering the subtrees of the query's own component (Boruvka step).
class ComponentTree {
public:
    explicit ComponentTree(const std::vector<Eigen::Vector3d>& pts) : pts_(pts), order_(pts.size()) {
        std::iota(order_.begin(), order_.end(), 0u);
        nodes_.reserve(2 * pts.size() / kLeafSize + 2);
        build(0, static_cast<uint32_t>(pts.size()));
    }

    void set_labels(const std::vector<uint32_t>& label) {
        for (size_t i = nodes_.size(); i-- > 0;) {
            Node& nd = nodes_[i];
            if (nd.left < 0) {
                nd.label = label[order_[nd.begin]];
                for (uint32_t s = nd.begin + 1; s < nd.end; ++s)
                    if (label[order_[s]] != nd.label) nd.label = kMixed;
            } else {
                const uint32_t l = nodes_[static_cast<size_t>(nd.left)].label;
                nd.label = l == nodes_[static_cast<size_t>(nd.right)].label ? l : kMixed;
            }
        }
    }

    // Nearest j with label[j] != label[i] that `accept(i, j)` allows; ties go to the smaller j.
    template <class Accept>
    void nearest_other(uint32_t i, const std::vector<uint32_t>& label, const Accept& accept, double& best_d2,
                       int64_t& best_j) const {
        search(0, i, label, accept, best_d2, best_j);
    }

private:
    static constexpr uint32_t kMixed = std::numeric_limits<uint32_t>::max();
    struct Node {
        Eigen::Vector3d lo, hi;
        uint32_t begin, end;
        int32_t left = -1, right = -1;
        uint32_t label = kMixed;
    };

    int32_t build(uint32_t begin, uint32_t end) {
        Eigen::Vector3d lo = pts_[order_[begin]], hi = lo;
        for (uint32_t s = begin; s < end; ++s) {
            lo = lo.cwiseMin(pts_[order_[s]]);
            hi = hi.cwiseMax(pts_[order_[s]]);
        }
        const int32_t id = static_cast<int32_t>(nodes_.size());
        nodes_.push_back(Node{lo, hi, begin, end, -1, -1, kMixed});
        if (end - begin > static_cast<uint32_t>(kLeafSize)) {
            int axis = 0;
            (hi - lo).maxCoeff(&axis);
            const uint32_t mid = begin + (end - begin) / 2;
            std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                             [&](uint32_t a, uint32_t b) {
                                 const double va = pts_[a][axis], vb = pts_[b][axis];
                                 return va < vb || (va == vb && a < b);
                             });
            const int32_t l = build(begin, mid);
            const int32_t r = build(mid, end);
            nodes_[static_cast<size_t>(id)].left = l;
            nodes_[static_cast<size_t>(id)].right = r;
        }
        return id;
    }

    double box_d2(const Node& nd, const Eigen::Vector3d& q) const {
        const Eigen::Vector3d d = (nd.lo - q).cwiseMax(q - nd.hi).cwiseMax(0.0);
        return d.squaredNorm();
    }

    template <class Accept>
    void search(int32_t id, uint32_t i, const std::vector<uint32_t>& label, const Accept& accept, double& best_d2,
                int64_t& best_j) const {
        const Node& nd = nodes_[static_cast<size_t>(id)];
        if (nd.label == label[i]) return;
        // Strictly farther only: an equally distant point may still win the index tie-break.
        if (box_d2(nd, pts_[i]) > best_d2) return;
        if (nd.left < 0) {
            for (uint32_t s = nd.begin; s < nd.end; ++s) {
                const uint32_t j = order_[s];
                if (label[j] == label[i]) continue;
                const double d2 = (pts_[j] - pts_[i]).squaredNorm();
                if ((d2 < best_d2 || (d2 == best_d2 && static_cast<int64_t>(j) < best_j)) && accept(i, j)) {
                    best_d2 = d2;
                    best_j = j;
                }
            }
            return;
        }
        const int32_t a = nd.left, b = nd.right;
        const bool a_first =
            box_d2(nodes_[static_cast<size_t>(a)], pts_[i]) <= box_d2(nodes_[static_cast<size_t>(b)], pts_[i]);
        search(a_first ? a : b, i, label, accept, best_d2, best_j);
        search(a_first ? b : a, i, label, accept, best_d2, best_j);
    }

    const std::vector<Eigen::Vector3d>& pts_;
    std::vector<uint32_t> order_;
    std::vector<Node> nodes_;
};

// Boruvka over the components of `ds`: each component but the largest takes its nearest allowed edge to
// another component until one component is left or no allowed edge joins two. Each such edge is the
// lightest one leaving its component, so it belongs to a minimum spanning tree (cut property).
void bridge_components(const std::vector<Eigen::Vector3d>& pts, const EdgeRules& rules, DisjointSet& ds,
                       std::vector<Edge>& tree, int threads) {
    const size_t n = pts.size();
    std::vector<uint32_t> label(n);
    auto relabel = [&]() {
        size_t count = 0;
        for (uint32_t i = 0; i < n; ++i) {
            label[i] = ds.find(i);
            if (label[i] == i) ++count;
        }
        return count;
    };
    if (relabel() <= 1) return;
    ComponentTree ctree(pts);
    const auto accept = [&](uint32_t i, uint32_t j) { return !rules.excluded(i, j) || !rules.excluded(j, i); };
    for (;;) {
        ctree.set_labels(label);
        std::vector<uint32_t> size(n, 0);
        for (uint32_t i = 0; i < n; ++i) ++size[label[i]];
        const uint32_t largest =
            static_cast<uint32_t>(std::max_element(size.begin(), size.end()) - size.begin());
        std::vector<uint32_t> queries;
        for (uint32_t i = 0; i < n; ++i)
            if (label[i] != largest) queries.push_back(i);
        std::vector<double> d2(queries.size());
        std::vector<int64_t> to(queries.size());
#pragma omp parallel for schedule(dynamic, 256) num_threads(threads)
        for (int64_t q = 0; q < static_cast<int64_t>(queries.size()); ++q) {
            double best = std::numeric_limits<double>::infinity();
            int64_t j = -1;
            ctree.nearest_other(queries[static_cast<size_t>(q)], label, accept, best, j);
            d2[static_cast<size_t>(q)] = best;
            to[static_cast<size_t>(q)] = j;
        }
        // Lightest edge per component, ties by vertex pair: independent of the thread schedule.
        std::vector<Edge> best_of(n, Edge{std::numeric_limits<double>::infinity(), 0, 0});
        std::vector<uint8_t> has(n, 0);
        for (size_t q = 0; q < queries.size(); ++q) {
            if (to[q] < 0) continue;
            const uint32_t i = queries[q], j = static_cast<uint32_t>(to[q]);
            const Edge e{d2[q], std::min(i, j), std::max(i, j)};
            Edge& cur = best_of[label[i]];
            if (!has[label[i]] || edge_less(e, cur)) {
                cur = e;
                has[label[i]] = 1;
            }
        }
        std::vector<Edge> found;
        for (uint32_t c = 0; c < n; ++c)
            if (has[c]) found.push_back(best_of[c]);
        if (found.empty()) return;  // the remaining components cannot be joined by an allowed edge
        std::sort(found.begin(), found.end(), edge_less);
        for (const Edge& e : found)
            if (ds.unite(e.a, e.b)) tree.push_back(e);
        if (relabel() <= 1) return;
    }
}

}  // namespace

void orient_normals_consistent_tangent_plane(PointCloud& cloud, int k, double lambda, double cos_alpha_tol,
                                             int num_threads) {
    if (!cloud.has_normals())
        throw InvalidArgument("the cloud has no normals (call estimate_normals first)");
    if (k < 1) throw InvalidArgument("k must be >= 1, got " + std::to_string(k));
    if (!std::isfinite(lambda) || lambda < 0.0)
        throw InvalidArgument("lambda must be finite and >= 0, got " + std::to_string(lambda));
    if (!std::isfinite(cos_alpha_tol))
        throw InvalidArgument("cos_alpha_tol must be finite, got " + std::to_string(cos_alpha_tol));
    const size_t n = cloud.points.size();
    if (n >= std::numeric_limits<uint32_t>::max())
        throw InvalidArgument("too many points for normal orientation: " + std::to_string(n));
    for (size_t i = 0; i < n; ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
    const int threads = utility::resolve_num_threads(num_threads);
    const auto& pts = cloud.points;
    auto& normals = cloud.normals;
    const EdgeRules rules{pts, normals, cos_alpha_tol, lambda};

    // One kNN search serves both graphs: the Euclidean tree uses all `kk` neighbours, the Riemannian
    // graph the first k (self included, as Open3D's SearchKNN(k)).
    const int knn_graph = static_cast<int>(std::min<size_t>(static_cast<size_t>(k), n));
    const int kk = static_cast<int>(std::min<size_t>(static_cast<size_t>(std::max(k, kEuclideanNeighbours)), n));
    const kdtree::KDTree tree(pts);
    const kdtree::SearchResult nn = tree.search_batch(pts, kdtree::SearchParam::make_knn(kk), threads);

    // Edges of each point, in per-point slots so the parallel fill is deterministic; unused slots keep
    // an infinite weight and are dropped afterwards.
    const size_t kk_s = static_cast<size_t>(kk), kg_s = static_cast<size_t>(knn_graph);
    constexpr Edge kNone{std::numeric_limits<double>::infinity(), 0, 0};
    std::vector<Edge> euclid(n * kk_s, kNone);
    std::vector<Edge> riemann(n * kg_s, kNone);
#pragma omp parallel num_threads(threads)
    {
        std::vector<double> dist;
#pragma omp for schedule(dynamic, 1024)
        for (int64_t si = 0; si < static_cast<int64_t>(n); ++si) {
            const uint32_t i = static_cast<uint32_t>(si);
            const size_t b = static_cast<size_t>(nn.offsets[i]), e = static_cast<size_t>(nn.offsets[i + 1]);
            const size_t e_graph = std::min(e, b + kg_s);
            double outlier_limit = std::numeric_limits<double>::infinity();
            if (lambda != 0.0) {
                // Open3D drops, for lambda != 0, kNN neighbours far off the tangent plane (Tukey fence).
                dist.clear();
                for (size_t s = b; s < e_graph; ++s) {
                    const uint32_t j = static_cast<uint32_t>(nn.indices[s]);
                    if (j != i) dist.push_back(rules.plane_distance(i, j));
                }
                if (!dist.empty()) {
                    std::sort(dist.begin(), dist.end());
                    const double q1 = quantile(dist, 0.25), q3 = quantile(dist, 0.75);
                    outlier_limit = q3 + 1.5 * (q3 - q1);
                }
            }
            for (size_t s = b; s < e; ++s) {
                const uint32_t j = static_cast<uint32_t>(nn.indices[s]);
                if (j == i || rules.excluded(i, j)) continue;
                const uint32_t a = std::min(i, j), c = std::max(i, j);
                euclid[i * kk_s + (s - b)] = Edge{rules.euclidean_weight(i, j), a, c};
                if (s < e_graph && (lambda == 0.0 || rules.plane_distance(i, j) <= outlier_limit))
                    riemann[i * kg_s + (s - b)] = Edge{rules.normal_weight(i, j), a, c};
            }
        }
    }
    const auto drop_none = [](std::vector<Edge>& v) {
        v.erase(std::remove_if(v.begin(), v.end(), [](const Edge& e) { return std::isinf(e.w); }), v.end());
    };
    drop_none(euclid);
    drop_none(riemann);

    // Euclidean minimum spanning tree (of the kNN graph, then bridged), reweighted by normal agreement.
    DisjointSet euclid_sets(n);
    std::vector<Edge> emst = kruskal(euclid, euclid_sets);
    std::vector<Edge>().swap(euclid);
    bridge_components(pts, rules, euclid_sets, emst, threads);
    for (Edge& e : emst) e.w = rules.normal_weight(e.a, e.b);
    riemann.insert(riemann.end(), emst.begin(), emst.end());

    // Minimum spanning forest of the Riemannian graph, as adjacency lists.
    DisjointSet sets(n);
    const std::vector<Edge> mst = kruskal(riemann, sets);
    std::vector<Edge>().swap(riemann);
    std::vector<uint32_t> start(n + 1, 0), adj(2 * mst.size());
    for (const Edge& e : mst) {
        ++start[e.a + 1];
        ++start[e.b + 1];
    }
    for (size_t i = 0; i < n; ++i) start[i + 1] += start[i];
    {
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (const Edge& e : mst) {
            adj[fill[e.a]++] = e.b;
            adj[fill[e.b]++] = e.a;
        }
    }

    // Root of each tree: its lowest point (first index on ties), normal turned to face -z.
    std::vector<uint32_t> root_of(n, std::numeric_limits<uint32_t>::max());
    for (uint32_t i = 0; i < n; ++i) {
        uint32_t& r = root_of[sets.find(i)];
        if (r == std::numeric_limits<uint32_t>::max() || pts[i].z() < pts[r].z()) r = i;
    }
    // Breadth-first walk: each child agrees with its parent. A child's final sign depends only on its
    // tree path, never on the visiting order.
    std::vector<uint8_t> visited(n, 0);
    std::vector<uint32_t> queue;
    queue.reserve(n);
    for (uint32_t c = 0; c < n; ++c) {
        const uint32_t r = root_of[c];
        if (r == std::numeric_limits<uint32_t>::max()) continue;
        if (normals[r].z() > 0.0) normals[r] = -normals[r];  // Open3D: flip when n . (0,0,-1) < 0
        queue.clear();
        queue.push_back(r);
        visited[r] = 1;
        for (size_t head = 0; head < queue.size(); ++head) {
            const uint32_t u = queue[head];
            for (uint32_t s = start[u]; s < start[u + 1]; ++s) {
                const uint32_t v = adj[s];
                if (visited[v]) continue;
                visited[v] = 1;
                if (normals[u].dot(normals[v]) < 0.0) normals[v] = -normals[v];
                queue.push_back(v);
            }
        }
    }
}

}  // namespace o3d::geometry
