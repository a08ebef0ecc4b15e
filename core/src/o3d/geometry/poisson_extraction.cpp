// SPDX-License-Identifier: MIT
/// @file poisson_extraction.cpp
/// @brief Function evaluation on the sparse octree and surface-following marching cubes.
#include "o3d/geometry/poisson_extraction.h"

#include "o3d/geometry/poisson_cube_table.h"
#include "o3d/geometry/radix_sort.h"

#include <algorithm>
#include <array>
#include <Eigen/Geometry>
#include <cmath>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace o3d::geometry::poisson {

// ---------------------------------------------------------------------------------------------------------
// Evaluation

bool FunctionEvaluator::try_level(int d, const double g[3], double& out) const {
    const Level& L = levels_[size_t(d)];
    const double scale = std::ldexp(1.0, d - (int(levels_.size()) - 1));
    int c[3];
    double f[3];
    for (int a = 0; a < 3; ++a) {
        const double x = g[a] * scale;
        int ci = int(std::floor(x));
        ci = std::min(std::max(ci, 0), L.res - 1);
        c[a] = ci;
        f[a] = std::min(std::max(x - ci, 0.0), 1.0);
    }
    double v = 0;
    for (int k = 0; k < 8; ++k) {
        const int64_t idx = L.find(pack(c[0] + (k & 1), c[1] + ((k >> 1) & 1), c[2] + ((k >> 2) & 1)));
        if (idx < 0) return false;
        v += ((k & 1) ? f[0] : 1 - f[0]) * ((k & 2) ? f[1] : 1 - f[1]) * ((k & 4) ? f[2] : 1 - f[2]) *
             L.y[size_t(idx)];
    }
    out = v;
    return true;
}

double FunctionEvaluator::at_vertex(int x, int y, int z) const {
    const int depth = int(levels_.size()) - 1;
    // The deepest depth at which the point is a key carries every correction reaching it: a deeper hat is
    // non-zero at one of its own grid vertices only at its centre, which would be a key there too.
    for (int d = depth, s = 0; d >= 0 && ((x | y | z) & ((1 << s) - 1)) == 0; --d, ++s) {
        const int64_t idx = levels_[size_t(d)].find(pack(x >> s, y >> s, z >> s));
        if (idx >= 0) return levels_[size_t(d)].y[size_t(idx)];
    }
    const double g[3] = {double(x), double(y), double(z)};
    double v = 0;
    for (int d = depth - 1; d >= 0; --d)
        if (try_level(d, g, v)) return v;
    return v;
}

double FunctionEvaluator::at(const Eigen::Vector3d& u) const {
    const int depth = int(levels_.size()) - 1;
    const double s = std::ldexp(1.0, depth);
    const double g[3] = {u[0] * s, u[1] * s, u[2] * s};
    double v = 0;
    for (int d = depth; d >= 0; --d)
        if (try_level(d, g, v)) return v;
    return v;
}

// ---------------------------------------------------------------------------------------------------------
// Extraction

namespace {
// Growable open-addressing memo of function values at finest-grid points. clear() is O(1) (a generation
// stamp), because one memo serves thousands of small extraction tasks in turn.
class ValueMemo {
public:
    ValueMemo() { rehash(1 << 12); }
    void clear() {
        if (++gen_ == 0) std::fill(gens_.begin(), gens_.end(), gen_++);
        size_ = 0;
    }
    const double* find(Key k) const {
        uint64_t h = KeyIndex::mix(k) & mask_;
        while (gens_[h] == gen_) {
            if (keys_[h] == k) return &vals_[h];
            h = (h + 1) & mask_;
        }
        return nullptr;
    }
    void insert(Key k, double v) {
        if (2 * (size_ + 1) > keys_.size()) rehash(keys_.size() * 2);
        uint64_t h = KeyIndex::mix(k) & mask_;
        while (gens_[h] == gen_) {
            if (keys_[h] == k) return;
            h = (h + 1) & mask_;
        }
        keys_[h] = k, vals_[h] = v, gens_[h] = gen_;
        ++size_;
    }

private:
    void rehash(size_t cap) {
        std::vector<Key> ok = std::move(keys_);
        std::vector<double> ov = std::move(vals_);
        std::vector<uint32_t> og = std::move(gens_);
        keys_.assign(cap, 0);
        vals_.assign(cap, 0.0);
        gens_.assign(cap, gen_ - 1);
        mask_ = cap - 1;
        size_ = 0;
        for (size_t i = 0; i < ok.size(); ++i)
            if (og[i] == gen_) insert(ok[i], ov[i]);
    }
    std::vector<Key> keys_;
    std::vector<double> vals_;
    std::vector<uint32_t> gens_;
    uint32_t gen_ = 1;
    size_t size_ = 0;
    uint64_t mask_ = 0;
};

// Adaptive marching cubes on the octree's leaves. A cell of depth d is refined when an unknown of depth d+1
// lies in its closure; a leaf (an unrefined cell) therefore sees no finer correction, chi is exactly
// trilinear on it, and away from the samples the surface is extracted on coarse leaves. Cracks between leaf
// sizes are avoided topologically: an edge is subdivided wherever any of the four cells around it is
// refined, so every cell that touches an edge sees the same sub-edges and the same crossings (keyed by the
// sub-edge); a face is subdivided like the finer of its two cells, and each leaf face is marched as a polygon
// (its corners plus the sub-edge points on its sides) with a rule that depends on the face alone. The
// segments on a leaf's boundary then close into loops, shared segment by segment with the neighbours.
class LeafMesher {
public:
    struct Out {
        std::vector<std::pair<Key, Eigen::Vector3d>> crossings;  // (sub-edge key, position), repeats allowed
        std::vector<Eigen::Vector3d> centers;                     // extra loop-centre vertices
        std::vector<std::array<uint64_t, 3>> tris;                // crossing keys, or kCenter | local index
    };
    static constexpr uint64_t kCenter = uint64_t(1) << 63;

    LeafMesher(const std::vector<Level>& levels, const FunctionEvaluator& chi, double iso, bool close)
        : levels_(levels), chi_(chi), iso_(iso), depth_(int(levels.size()) - 1), res_(1 << depth_),
          close_(close), outside_(iso + 1e-9 * std::max(1.0, std::abs(iso))),
          margin_(1e-9 * std::max(1.0, std::abs(iso))), table_(case_table()) {}

    // Marches every leaf inside the cell (d, c) into `out`.
    void run(int d, const int c[3], Out& out) {
        memo_.clear();
        visit(d, c, out);
    }

private:
    // The centre of a depth-d cell is a vertex of depth d+1, and the level's keys are its unknowns grown by
    // one ring: the centre is a key exactly when an unknown lies in the cell's closure.
    bool touches_boundary(int d, const int c[3]) const {
        const int r = (1 << d) - 1;
        return c[0] == 0 || c[1] == 0 || c[2] == 0 || c[0] == r || c[1] == r || c[2] == r;
    }
    bool refined(int d, int x, int y, int z) const {
        if (d >= depth_) return false;
        const int r = 1 << d;
        if (x < 0 || y < 0 || z < 0 || x >= r || y >= r || z >= r) return false;
        return levels_[size_t(d) + 1].find(pack(2 * x + 1, 2 * y + 1, 2 * z + 1)) >= 0;
    }
    double value(const int p[3]) {
        const Key k = pack(p[0], p[1], p[2]);
        if (const double* v = memo_.find(k)) return *v;
        double v = chi_.at_vertex(p[0], p[1], p[2]);
        if (close_ && (p[0] == 0 || p[1] == 0 || p[2] == 0 || p[0] == res_ || p[1] == res_ || p[2] == res_))
            v = std::max(v, outside_);  // the domain boundary counts as outside: open surfaces close along it
        memo_.insert(k, v);
        return v;
    }
    // The crossing on the sub-edge p0-p1 (finest coordinates, along `axis`), recorded with its position.
    uint64_t crossing(const int p0[3], const int p1[3], int axis, Out& out) {
        const bool fwd = p0[axis] < p1[axis];
        const int* lo = fwd ? p0 : p1;
        const int* hi = fwd ? p1 : p0;
        const double v0 = value(lo), v1 = value(hi);
        // chi is linear along a leaf's edges, so this root is exact.
        const double t = v1 != v0 ? std::min(std::max((iso_ - v0) / (v1 - v0), 0.0), 1.0) : 0.5;
        Eigen::Vector3d p(lo[0], lo[1], lo[2]);
        p[axis] += t * (hi[axis] - lo[axis]);
        const Key key = (pack(lo[0], lo[1], lo[2]) << 2) | Key(axis);
        out.crossings.emplace_back(key, p / res_);
        last_ = p / res_;
        return key;
    }
    // Whether the depth-e edge from vertex q (depth-e coordinates) along `axis` is split by a refined cell.
    bool edge_split(int e, const int q[3], int axis) const {
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        for (int j = 0; j < 4; ++j) {
            int m[3] = {q[0], q[1], q[2]};
            m[b] -= j & 1;
            m[c] -= (j >> 1) & 1;
            if (refined(e, m[0], m[1], m[2])) return true;
        }
        return false;
    }
    // Appends the interior sub-edge points of that edge, in increasing coordinate, in finest coordinates.
    void edge_points(int e, const int q[3], int axis, std::vector<std::array<int, 3>>& pts) const {
        if (!edge_split(e, q, axis)) return;
        int lo[3] = {2 * q[0], 2 * q[1], 2 * q[2]};
        int hi[3] = {lo[0], lo[1], lo[2]};
        hi[axis] += 1;
        edge_points(e + 1, lo, axis, pts);
        const int s = depth_ - e - 1;
        pts.push_back({hi[0] << s, hi[1] << s, hi[2] << s});
        edge_points(e + 1, hi, axis, pts);
    }

    void visit(int d, const int c[3], Out& out) {
        if (refined(d, c[0], c[1], c[2])) {
            for (int k = 0; k < 8; ++k) {
                const int ch[3] = {2 * c[0] + (k & 1), 2 * c[1] + ((k >> 1) & 1), 2 * c[2] + ((k >> 2) & 1)};
                visit(d + 1, ch, out);
            }
            return;
        }
        // chi is trilinear on a leaf, so every point of it lies between its corner values: with all corners
        // clearly on one side (and no boundary override) no crossing can exist on it or its sub-edges.
        if (d < depth_ && !(close_ && touches_boundary(d, c))) {
            const int s = depth_ - d;
            bool below = false, above = false;
            for (int k = 0; k < 8; ++k) {
                const int p[3] = {(c[0] + (k & 1)) << s, (c[1] + ((k >> 1) & 1)) << s, (c[2] + ((k >> 2) & 1)) << s};
                const double v = value(p);
                below |= v < iso_ + margin_;
                above |= v >= iso_ - margin_;
            }
            if (!(below && above)) return;
        }
        bool plain = true;
        for (int e = 0; e < 12 && plain && d < depth_; ++e) {
            const int a = e / 4, c0 = edge_lower_corner(e);
            const int q[3] = {c[0] + (c0 & 1), c[1] + ((c0 >> 1) & 1), c[2] + ((c0 >> 2) & 1)};
            if (edge_split(d, q, a)) plain = false;
        }
        if (plain)
            plain_leaf(d, c, out);
        else
            split_leaf(d, c, out);
    }

    // A leaf whose faces and edges are whole: the case table.
    void plain_leaf(int d, const int c[3], Out& out) {
        const int s = depth_ - d, w = 1 << s;
        int cs = 0;
        for (int k = 0; k < 8; ++k) {
            const int p[3] = {(c[0] + (k & 1)) << s, (c[1] + ((k >> 1) & 1)) << s, (c[2] + ((k >> 2) & 1)) << s};
            if (value(p) < iso_) cs |= 1 << k;
        }
        for (const auto& t : table_.tris[size_t(cs)]) {
            std::array<uint64_t, 3> tri;
            for (int j = 0; j < 3; ++j) {
                const int e = t[size_t(j)], a = e / 4, c0 = edge_lower_corner(e);
                const int p0[3] = {(c[0] + (c0 & 1)) << s, (c[1] + ((c0 >> 1) & 1)) << s, (c[2] + ((c0 >> 2) & 1)) << s};
                int p1[3] = {p0[0], p0[1], p0[2]};
                p1[a] += w;
                tri[size_t(j)] = crossing(p0, p1, a, out);
            }
            out.tris.push_back(tri);
        }
    }

    // Polygon of a leaf face square (depth e, minimum corner m, normal `axis`, side + or -) seen
    // counter-clockwise from outside the leaf, as the case table walks cube faces; then its segments, each
    // from the crossing where an inside run of corners ends to the one where it begins.
    void face_segments(int e, const int m[3], int axis, int side, Out& out) {
        const int b = (axis + 1) % 3, c = (axis + 2) % 3, s = depth_ - e;
        const int bc[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        poly_.clear();
        for (int i = 0; i < 4; ++i) {
            const int* p = bc[side ? i : 3 - i];
            const int* n = bc[side ? (i + 1) % 4 : (6 - i) % 4];
            int q[3] = {m[0], m[1], m[2]};
            q[b] += p[0], q[c] += p[1];
            poly_.push_back({q[0] << s, q[1] << s, q[2] << s});
            // The side to the next corner, with its sub-edge points in walking order.
            const int ea = p[0] != n[0] ? b : c;
            const bool up = (ea == b ? n[0] - p[0] : n[1] - p[1]) > 0;
            int lo[3] = {q[0], q[1], q[2]};
            if (!up) lo[ea] -= 1;
            const size_t first = poly_.size();
            edge_points(e, lo, ea, poly_);
            if (!up) std::reverse(poly_.begin() + std::ptrdiff_t(first), poly_.end());
        }
        const size_t n = poly_.size();
        inside_.resize(n);
        for (size_t i = 0; i < n; ++i) inside_[i] = value(poly_[i].data()) < iso_;
        auto cross = [&](size_t i) {
            const size_t j = (i + 1) % n;
            const int a = poly_[i][0] != poly_[j][0] ? 0 : (poly_[i][1] != poly_[j][1] ? 1 : 2);
            const uint64_t key = crossing(poly_[i].data(), poly_[j].data(), a, out);
            pos_.emplace_back(key, last_);
            return key;
        };
        for (size_t k = 0; k < n; ++k) {
            if (!inside_[k] || inside_[(k + 1) % n]) continue;
            size_t j = (k + n - 1) % n;
            while (inside_[j]) j = (j + n - 1) % n;
            const uint64_t from = cross(k), to = cross(j);
            next_.emplace_back(from, to);
        }
    }
    // Leaf faces of the face of leaf (d, c) normal to `axis` on `side`: the squares of the finer neighbour.
    void face_tiles(int e, const int m[3], int axis, int side, Out& out) {
        int n[3] = {m[0], m[1], m[2]};
        if (!side) n[axis] -= 1;
        if (!refined(e, n[0], n[1], n[2])) {
            face_segments(e, m, axis, side, out);
            return;
        }
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        for (int j = 0; j < 4; ++j) {
            int q[3] = {2 * m[0], 2 * m[1], 2 * m[2]};
            q[b] += j & 1, q[c] += (j >> 1) & 1;
            face_tiles(e + 1, q, axis, side, out);
        }
    }
    // A leaf next to finer cells: its boundary polygons' segments chained into loops; a loop of more than
    // three crossings is fanned from its centre, so no diagonal can coincide with a neighbour's edge.
    void split_leaf(int d, const int c[3], Out& out) {
        next_.clear();
        pos_.clear();
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                int m[3] = {c[0], c[1], c[2]};
                m[axis] += side;
                face_tiles(d, m, axis, side, out);
            }
        if (next_.empty()) return;
        std::sort(next_.begin(), next_.end());
        std::sort(pos_.begin(), pos_.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        auto position = [&](uint64_t k) {
            return std::lower_bound(pos_.begin(), pos_.end(), k, [](const auto& x, uint64_t v) { return x.first < v; })
                ->second;
        };
        used_.assign(next_.size(), false);
        for (size_t s0 = 0; s0 < next_.size(); ++s0) {
            if (used_[s0]) continue;
            loop_.clear();
            for (size_t i = s0; !used_[i];) {
                used_[i] = true;
                loop_.push_back(next_[i].first);
                const auto it = std::lower_bound(next_.begin(), next_.end(), std::make_pair(next_[i].second, uint64_t(0)));
                if (it == next_.end() || it->first != next_[i].second) break;  // cannot happen: loops close
                i = size_t(it - next_.begin());
            }
            if (loop_.size() < 3) continue;
            auto emit = [&](uint64_t a, uint64_t b2, uint64_t c2) {
                out.tris.push_back(table_.flipped ? std::array<uint64_t, 3>{a, c2, b2} : std::array<uint64_t, 3>{a, b2, c2});
            };
            if (loop_.size() == 3) {
                emit(loop_[0], loop_[1], loop_[2]);
                continue;
            }
            Eigen::Vector3d centre = Eigen::Vector3d::Zero();
            for (uint64_t k : loop_) centre += position(k);
            out.centers.push_back(centre / double(loop_.size()));
            const uint64_t ci = kCenter | uint64_t(out.centers.size() - 1);
            for (size_t i = 0; i < loop_.size(); ++i) emit(ci, loop_[i], loop_[(i + 1) % loop_.size()]);
        }
    }

    const std::vector<Level>& levels_;
    const FunctionEvaluator& chi_;
    const double iso_;
    const int depth_, res_;
    const bool close_;
    const double outside_, margin_;
    const CaseTable& table_;
    ValueMemo memo_;
    Eigen::Vector3d last_;
    std::vector<std::array<int, 3>> poly_;
    std::vector<bool> inside_, used_;
    std::vector<std::pair<uint64_t, uint64_t>> next_;
    std::vector<std::pair<uint64_t, Eigen::Vector3d>> pos_;
    std::vector<uint64_t> loop_;
};

}  // namespace

bool extract_iso_surface(const std::vector<Level>& levels, const FunctionEvaluator& chi, double iso, int task_depth,
                         IsoSurface& out, const std::function<bool()>& keep_going, int threads,
                         bool close_at_boundary) {
    const int depth = int(levels.size()) - 1;
    task_depth = std::min(task_depth, depth);
    const int tres = 1 << task_depth;
    const int64_t ntasks = int64_t(tres) * tres * tres;
    std::vector<LeafMesher::Out> outs(static_cast<size_t>(ntasks));
    std::vector<LeafMesher> meshers(size_t(std::max(threads, 1)), LeafMesher(levels, chi, iso, close_at_boundary));
    // Tasks are the cells of a complete depth, run in batches between cancellation checks; each writes its
    // own output, merged in task order, so the mesh does not depend on the thread count.
    constexpr int64_t kBatch = 4096;
    for (int64_t b0 = 0; b0 < ntasks; b0 += kBatch) {
        if (b0 > 0 && !keep_going()) return false;
        const int64_t b1 = std::min(ntasks, b0 + kBatch);
#pragma omp parallel for num_threads(threads) schedule(dynamic, 16)
        for (int64_t t = b0; t < b1; ++t) {
            int tid = 0;
#ifdef _OPENMP
            tid = omp_get_thread_num();
#endif
            const int c[3] = {int(t / (int64_t(tres) * tres)), int((t / tres) % tres), int(t % tres)};
            meshers[size_t(tid)].run(task_depth, c, outs[size_t(t)]);
        }
    }
    // Vertices: the crossings numbered in key order, then the loop centres in task order.
    size_t total = 0;
    for (const auto& o : outs) total += o.crossings.size();
    std::vector<std::pair<uint64_t, size_t>> items;
    items.reserve(total);
    std::vector<std::pair<size_t, size_t>> where;  // (task, index) of each item
    where.reserve(total);
    for (size_t t = 0; t < outs.size(); ++t)
        for (size_t i = 0; i < outs[t].crossings.size(); ++i) {
            items.emplace_back(outs[t].crossings[i].first, where.size());
            where.emplace_back(t, i);
        }
    radix_sort_by_key(items, 3 * kKeyBits + 2);
    std::vector<Key> keys;
    keys.reserve(items.size() / 2);
    out.vertices.clear();
    for (size_t i = 0; i < items.size(); ++i) {
        if (i > 0 && items[i].first == items[i - 1].first) continue;
        keys.push_back(items[i].first);
        const auto& w = where[items[i].second];
        out.vertices.push_back(outs[w.first].crossings[w.second].second);
    }
    std::vector<std::pair<uint64_t, size_t>>().swap(items);
    std::vector<std::pair<size_t, size_t>>().swap(where);
    std::vector<size_t> center_base(outs.size() + 1, keys.size()), tri_base(outs.size() + 1, 0);
    for (size_t t = 0; t < outs.size(); ++t) {
        center_base[t + 1] = center_base[t] + outs[t].centers.size();
        tri_base[t + 1] = tri_base[t] + outs[t].tris.size();
        out.vertices.insert(out.vertices.end(), outs[t].centers.begin(), outs[t].centers.end());
    }
    out.triangles.resize(tri_base.back());
#pragma omp parallel for num_threads(threads) schedule(dynamic, 64)
    for (int64_t t = 0; t < ntasks; ++t) {
        const auto& o = outs[size_t(t)];
        for (size_t i = 0; i < o.tris.size(); ++i) {
            Eigen::Vector3i tri;
            for (int j = 0; j < 3; ++j) {
                const uint64_t k = o.tris[i][size_t(j)];
                tri[j] = (k & LeafMesher::kCenter)
                             ? int(center_base[size_t(t)] + (k & ~LeafMesher::kCenter))
                             : int(std::lower_bound(keys.begin(), keys.end(), k) - keys.begin());
            }
            out.triangles[tri_base[size_t(t)] + i] = tri;
        }
    }
    return true;
}

}  // namespace o3d::geometry::poisson
