// SPDX-License-Identifier: MIT
/// @file poisson_extraction.cpp
/// @brief Function evaluation on the sparse octree and surface-following marching cubes.
#include "o3d/geometry/poisson_extraction.h"

#include <algorithm>
#include <array>
#include <Eigen/Geometry>
#include <cmath>

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
    const int64_t idx = levels_[size_t(depth)].find(pack(x, y, z));
    if (idx >= 0) return levels_[size_t(depth)].y[size_t(idx)];
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
// Marching-cubes table, generated rather than typed in: on every cube face the iso-line segments cut off the
// inside corners (a rule that depends on the face alone, so both cells sharing a face agree); the segments
// chain into loops around the cube and each loop is fanned into triangles.

namespace {

// Corner k = (k&1, k>>1&1, k>>2&1). Edge id = axis*4 + j, j = bit of axis+1 + 2 * bit of axis+2.
int edge_id(int c0, int c1) {
    const int diff = c0 ^ c1;
    const int axis = diff == 1 ? 0 : (diff == 2 ? 1 : 2);
    const int b = (c0 >> ((axis + 1) % 3)) & 1, c = (c0 >> ((axis + 2) % 3)) & 1;
    return axis * 4 + b + 2 * c;
}
int edge_lower_corner(int e) {
    const int axis = e / 4, j = e % 4;
    return ((j & 1) << ((axis + 1) % 3)) | (((j >> 1) & 1) << ((axis + 2) % 3));
}

// Two cube edges lie on a common face when they are parallel and differ in one bit, or perpendicular and
// touch (share a corner).
bool share_face(int e0, int e1) {
    const int a0 = e0 / 4, a1 = e1 / 4;
    const int c0 = edge_lower_corner(e0), c1 = edge_lower_corner(e1);
    if (a0 == a1) {
        const int d = c0 ^ c1;
        return d != 0 && (d & (d - 1)) == 0;
    }
    const int c0b = c0 | (1 << a0), c1b = c1 | (1 << a1);
    return c0 == c1 || c0 == c1b || c0b == c1 || c0b == c1b;
}

struct CaseTable {
    std::array<std::vector<std::array<int8_t, 3>>, 256> tris;
    CaseTable() {
        for (int cs = 0; cs < 256; ++cs) {
            auto inside = [cs](int k) { return ((cs >> k) & 1) != 0; };
            std::array<int, 12> next;
            next.fill(-1);
            for (int axis = 0; axis < 3; ++axis)
                for (int side = 0; side < 2; ++side) {
                    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
                    // Counter-clockwise seen from outside the cube: (b,c) = 00,10,11,01 on the + side.
                    int p[4];
                    const int bc[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                    for (int i = 0; i < 4; ++i) {
                        const int q = side ? i : 3 - i;
                        p[i] = (side << axis) | (bc[q][0] << b) | (bc[q][1] << c);
                    }
                    for (int k = 0; k < 4; ++k) {
                        if (!(inside(p[k]) && !inside(p[(k + 1) % 4]))) continue;
                        // Exit edge: join it to the closest earlier crossing, keeping the inside on the left.
                        for (int m = k + 3; m > k; --m) {
                            const int a0 = p[m % 4], a1 = p[(m + 1) % 4];
                            if (inside(a0) != inside(a1)) {
                                next[size_t(edge_id(p[k], p[(k + 1) % 4]))] = edge_id(a0, a1);
                                break;
                            }
                        }
                    }
                }
            std::array<bool, 12> used{};
            for (int e0 = 0; e0 < 12; ++e0) {
                if (next[size_t(e0)] < 0 || used[size_t(e0)]) continue;
                std::vector<int> loop;
                for (int e = e0; !used[size_t(e)]; e = next[size_t(e)]) {
                    used[size_t(e)] = true;
                    loop.push_back(e);
                }
                // Fan from a vertex none of whose diagonals joins two crossings on one cube face: the cell
                // across that face could draw the same diagonal and the edge would carry four triangles.
                const size_t m = loop.size();
                size_t start = 0;
                for (size_t s0 = 0; s0 < m; ++s0) {
                    bool ok = true;
                    for (size_t i = 2; i + 1 < m && ok; ++i)
                        if (share_face(loop[s0], loop[(s0 + i) % m])) ok = false;
                    if (ok) {
                        start = s0;
                        break;
                    }
                }
                for (size_t i = 1; i + 1 < m; ++i)
                    tris[size_t(cs)].push_back({int8_t(loop[start]), int8_t(loop[(start + i) % m]),
                                                int8_t(loop[(start + i + 1) % m])});
            }
        }
        // Orientation: with only corner 0 inside the normal must point away from it.
        auto mid = [](int e) {
            const int c = edge_lower_corner(e);
            Eigen::Vector3d p(c & 1, (c >> 1) & 1, (c >> 2) & 1);
            p[e / 4] += 0.5;
            return p;
        };
        const auto& t = tris[1][0];
        const Eigen::Vector3d n = (mid(t[1]) - mid(t[0])).cross(mid(t[2]) - mid(t[0]));
        if (n.dot(Eigen::Vector3d(1, 1, 1)) < 0)
            for (auto& list : tris)
                for (auto& tri : list) std::swap(tri[1], tri[2]);
    }
};

const CaseTable& case_table() {
    static const CaseTable table;
    return table;
}

// Growable open-addressing map from keys to doubles (the memo of function values and the visited set).
class FlatMap {
public:
    FlatMap() { rehash(1 << 12); }
    const double* find(Key k) const {
        uint64_t h = KeyIndex::mix(k) & mask_;
        while (keys_[h] != kEmpty) {
            if (keys_[h] == k) return &vals_[h];
            h = (h + 1) & mask_;
        }
        return nullptr;
    }
    // Inserts (k, v) unless present; returns true when inserted.
    bool insert(Key k, double v) {
        if (2 * (size_ + 1) > keys_.size()) rehash(keys_.size() * 2);
        uint64_t h = KeyIndex::mix(k) & mask_;
        while (keys_[h] != kEmpty) {
            if (keys_[h] == k) return false;
            h = (h + 1) & mask_;
        }
        keys_[h] = k;
        vals_[h] = v;
        ++size_;
        return true;
    }

private:
    static constexpr Key kEmpty = ~Key(0);
    void rehash(size_t cap) {
        std::vector<Key> ok = std::move(keys_);
        std::vector<double> ov = std::move(vals_);
        keys_.assign(cap, kEmpty);
        vals_.assign(cap, 0.0);
        mask_ = cap - 1;
        size_ = 0;
        for (size_t i = 0; i < ok.size(); ++i)
            if (ok[i] != kEmpty) insert(ok[i], ov[i]);
    }
    std::vector<Key> keys_;
    std::vector<double> vals_;
    size_t size_ = 0;
    uint64_t mask_ = 0;
};

}  // namespace

bool extract_iso_surface(const std::vector<Level>& levels, const FunctionEvaluator& chi, double iso,
                         const std::vector<Key>& seed_cells, int seed_depth, IsoSurface& out,
                         const std::function<bool()>& keep_going, int threads, bool close_at_boundary) {
    const int depth = int(levels.size()) - 1;
    const int res = 1 << depth;
    const CaseTable& table = case_table();
    // The domain boundary is outside (chi grows outwards): this closes surfaces that would leave the cube.
    const double outside = iso + 1e-9 * std::max(1.0, std::abs(iso));
    FlatMap values;
    auto value = [&](int x, int y, int z) {
        const Key k = pack(x, y, z);
        if (const double* v = values.find(k)) return *v;
        double v = chi.at_vertex(x, y, z);
        if (close_at_boundary && (x == 0 || y == 0 || z == 0 || x == res || y == res || z == res))
            v = std::max(v, outside);
        values.insert(k, v);
        return v;
    };
    auto cell_case = [&](Key c) {
        const int x = key_x(c), y = key_y(c), z = key_z(c);
        int cs = 0;
        for (int k = 0; k < 8; ++k)
            if (value(x + (k & 1), y + ((k >> 1) & 1), z + ((k >> 2) & 1)) < iso) cs |= 1 << k;
        return cs;
    };

    std::vector<Key> queue(seed_cells.begin(), seed_cells.end());
    // Seeds away from the samples: sign changes along the edges of the complete coarse grid, located at
    // the finest depth by walking the edge.
    {
        const int sres = 1 << seed_depth, step = 1 << (depth - seed_depth);
        for (int x = 0; x <= sres; ++x)
            for (int y = 0; y <= sres; ++y)
                for (int z = 0; z <= sres; ++z) {
                    const int p[3] = {x * step, y * step, z * step};
                    const double v0 = value(p[0], p[1], p[2]);
                    for (int a = 0; a < 3; ++a) {
                        if ((a == 0 ? x : (a == 1 ? y : z)) == sres) continue;
                        int q[3] = {p[0], p[1], p[2]};
                        q[a] += step;
                        if ((value(q[0], q[1], q[2]) < iso) == (v0 < iso)) continue;
                        int r[3] = {p[0], p[1], p[2]};
                        bool prev = v0 < iso;
                        for (int s = 0; s < step; ++s) {
                            int t[3] = {r[0], r[1], r[2]};
                            t[a] += 1;
                            const bool cur = value(t[0], t[1], t[2]) < iso;
                            if (cur != prev) {
                                queue.push_back(pack(std::min(r[0], res - 1), std::min(r[1], res - 1),
                                                     std::min(r[2], res - 1)));
                                break;
                            }
                            r[a] += 1;
                        }
                    }
                }
    }
    sort_unique(queue);
    FlatMap visited;
    for (Key k : queue) visited.insert(k, 0.0);
    std::vector<Key> surface;
    for (size_t head = 0; head < queue.size(); ++head) {
        if ((head & 0xffff) == 0xffff && !keep_going()) return false;
        const Key c = queue[head];
        const int cs = cell_case(c);
        if (cs == 0 || cs == 255) continue;
        surface.push_back(c);
        const int x = key_x(c), y = key_y(c), z = key_z(c);
        for (int e = 0; e < 12; ++e) {
            const int a = e / 4, c0 = edge_lower_corner(e), c1 = c0 | (1 << a);
            if ((((cs >> c0) ^ (cs >> c1)) & 1) == 0) continue;
            // The four cells around this edge all see the crossing.
            const int b = (a + 1) % 3, cc = (a + 2) % 3;
            int v[3] = {x + (c0 & 1), y + ((c0 >> 1) & 1), z + ((c0 >> 2) & 1)};
            for (int j = 0; j < 4; ++j) {
                int m[3] = {v[0], v[1], v[2]};
                m[b] -= j & 1;
                m[cc] -= (j >> 1) & 1;
                if (m[0] < 0 || m[1] < 0 || m[2] < 0 || m[0] >= res || m[1] >= res || m[2] >= res) continue;
                const Key n = pack(m[0], m[1], m[2]);
                if (visited.insert(n, 0.0)) queue.push_back(n);
            }
        }
    }
    std::vector<Key>().swap(queue);
    sort_unique(surface);

    // Vertices: one per crossed edge, keyed (lower vertex, axis), numbered in key order.
    std::vector<Key> edges;
    std::vector<int> cases(surface.size());
    for (size_t i = 0; i < surface.size(); ++i) {
        const int cs = cell_case(surface[i]);
        cases[i] = cs;
        const Key c = surface[i];
        for (int e = 0; e < 12; ++e) {
            const int a = e / 4, c0 = edge_lower_corner(e), c1 = c0 | (1 << a);
            if ((((cs >> c0) ^ (cs >> c1)) & 1) == 0) continue;
            edges.push_back((pack(key_x(c) + (c0 & 1), key_y(c) + ((c0 >> 1) & 1), key_z(c) + ((c0 >> 2) & 1)) << 2) |
                            Key(a));
        }
    }
    sort_unique(edges, 3 * kKeyBits + 2);
    out.vertices.resize(edges.size());
    const int64_t ne = int64_t(edges.size());
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < ne; ++i) {
        const Key k = edges[size_t(i)] >> 2;
        const int a = int(edges[size_t(i)] & 3);
        const int x = key_x(k), y = key_y(k), z = key_z(k);
        const double v0 = *values.find(k);
        const double v1 = *values.find(pack(x + (a == 0), y + (a == 1), z + (a == 2)));
        // chi is trilinear on finest cells, hence linear along their edges: this root is exact.
        const double t = v1 != v0 ? std::min(std::max((iso - v0) / (v1 - v0), 0.0), 1.0) : 0.5;
        Eigen::Vector3d p(x, y, z);
        p[a] += t;
        out.vertices[size_t(i)] = p / res;
    }
    std::vector<size_t> offset(surface.size() + 1, 0);
    for (size_t i = 0; i < surface.size(); ++i) offset[i + 1] = offset[i] + table.tris[size_t(cases[i])].size();
    out.triangles.resize(offset.back());
    const int64_t ns = int64_t(surface.size());
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < ns; ++i) {
        const Key c = surface[size_t(i)];
        const auto& tris = table.tris[size_t(cases[size_t(i)])];
        for (size_t t = 0; t < tris.size(); ++t) {
            Eigen::Vector3i tri;
            for (int j = 0; j < 3; ++j) {
                const int e = tris[t][size_t(j)], a = e / 4, c0 = edge_lower_corner(e);
                const Key ek =
                    (pack(key_x(c) + (c0 & 1), key_y(c) + ((c0 >> 1) & 1), key_z(c) + ((c0 >> 2) & 1)) << 2) | Key(a);
                tri[j] = int(std::lower_bound(edges.begin(), edges.end(), ek) - edges.begin());
            }
            out.triangles[offset[size_t(i)] + t] = tri;
        }
    }
    return true;
}

}  // namespace o3d::geometry::poisson
