// SPDX-License-Identifier: MIT
#include "o3d/registration/fpfh.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "o3d/registration/fpfh_neighbourhoods.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace {

constexpr int kFpfhBins = 11;
constexpr int kFpfhDim = 3 * kFpfhBins;
constexpr double kPi = 3.14159265358979323846;

/// @brief Bins of one pair feature: the angle (atan2 in [-pi, pi]) and the two cosines in [-1, 1].
struct PairBins {
    int angle, cos_v, cos_n;
};

// A zero pair feature (coincident points, or a normal along the line joining them) lands in the
// middle bin of each histogram, as Open3D's zero vector does.
constexpr PairBins kZeroPairBins{5, 5, 5};

/// @brief floor(t) clamped to [0, 10]; NaN gives 0.
inline int clamp_bin(double t) {
    if (!(t >= 0.0)) return 0;
    if (t >= kFpfhBins - 1) return kFpfhBins - 1;
    return static_cast<int>(t);
}

// Open3D's arithmetic for the bin positions (in bins, before the floor) of the angle and a cosine.
inline double angle_position(double angle) { return kFpfhBins * (angle + kPi) / (2.0 * kPi); }
inline double cosine_position(double c) { return kFpfhBins * (c + 1.0) * 0.5; }

inline double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline void cross3(const double* a, const double* b, double* out) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/// @brief Bins of the Darboux-frame pair feature of (p1, n1) and (p2, n2) (Rusu et al. 2009), literally
/// with Open3D's conventions: the frame sits on the point whose normal makes the smaller angle with
/// the joining line (acos(|a1|) > acos(|a2|) swaps, which NaN never does), the angle is
/// atan2(w.n2, u.n2). The reference the fast path below falls back to.
PairBins exact_pair_feature_bins(const Eigen::Vector3d& p1, const Eigen::Vector3d& n1, const Eigen::Vector3d& p2,
                                 const Eigen::Vector3d& n2) {
    double dp[3] = {p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]};
    const double distance = std::sqrt(dot3(dp, dp));
    if (distance == 0.0) return kZeroPairBins;
    const double a1 = dot3(n1.data(), dp) / distance;
    const double a2 = dot3(n2.data(), dp) / distance;
    const double* u = n1.data();  // the frame's normal
    const double* t = n2.data();  // the other normal
    double cos_n = a1;
    if (std::acos(std::fabs(a1)) > std::acos(std::fabs(a2))) {
        std::swap(u, t);
        for (double& c : dp) c = -c;
        cos_n = -a2;
    }
    double v[3], w[3];
    cross3(dp, u, v);
    const double v_norm = std::sqrt(dot3(v, v));
    if (v_norm == 0.0) return kZeroPairBins;
    for (double& c : v) c /= v_norm;
    cross3(u, v, w);
    return {clamp_bin(angle_position(std::atan2(dot3(w, t), dot3(u, t)))), clamp_bin(cosine_position(dot3(v, t))),
            clamp_bin(cosine_position(cos_n))};
}

// ---- The fast path: kLanes pairs at a time -----------------------------------------------------
// GCC/Clang vector extensions (plain SSE2 pairs on x86-64, NEON on ARM, scalar code elsewhere): the
// auto-vectoriser gives up on a loop this long, and one pair at a time is a ~300-cycle dependency chain.

constexpr int kLanes = 2;  // one SSE2 / NEON register; wider types change the vector ABI
typedef double Doubles __attribute__((vector_size(kLanes * sizeof(double))));
typedef int64_t Mask __attribute__((vector_size(kLanes * sizeof(int64_t))));  // lanes all ones or zero
typedef uint64_t Bits __attribute__((vector_size(kLanes * sizeof(uint64_t))));
typedef int32_t Ints __attribute__((vector_size(kLanes * sizeof(int32_t))));

inline Doubles load(const double* p) {
    Doubles v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

/// @brief Every lane x, signed zeros included (0 + -0 would be +0, and the sign of a zero picks bins).
inline Doubles splat(double x) {
    Doubles v;
    for (int i = 0; i < kLanes; ++i) v[i] = x;
    return v;
}

// Casts between vector types of one size reinterpret the bits (GCC and Clang vector semantics).
inline Doubles select(Mask m, Doubles yes, Doubles no) {
    return (Doubles)(((Bits)yes & (Bits)m) | ((Bits)no & ~(Bits)m));
}

inline Doubles abs_of(Doubles x) { return (Doubles)((Bits)x & 0x7FFFFFFFFFFFFFFFull); }

inline Doubles min_of(Doubles a, Doubles b) { return select(b < a, b, a); }
inline Doubles max_of(Doubles a, Doubles b) { return select(a < b, b, a); }  // NaN in b yields a

/// @brief 1 / sqrt(x) to a relative 5e-10 for normal x > 0: the classic exponent-halving guess and
/// three Newton steps (vector code has no portable square root).
inline Doubles approximate_inverse_sqrt(Doubles x) {
    Doubles y = (Doubles)(0x5FE6EB50C7B537A9ull - ((Bits)x >> 1));
    const Doubles half = 0.5 * x;
    y = y * (1.5 - half * y * y);
    y = y * (1.5 - half * y * y);
    y = y * (1.5 - half * y * y);
    return y;
}

/// @brief atan2(y, x) within 6e-9 rad (1e-8 bins, a hundredth of the edge margin): atan of
/// r = min/max in [0, 1] by an odd polynomial of degree 17 (a least-squares minimax fit of
/// atan(r) / r in r^2 made for this file), evaluated by Estrin's scheme for a short dependency chain,
/// then the octant. NaN for (0, 0).
inline Doubles approximate_atan2(Doubles y, Doubles x) {
    constexpr double c0 = 0.9999998863828069, c1 = -0.3333259702641036, c2 = 0.1998590673399105,
                     c3 = -0.14161228944671142, c4 = 0.1049894510002812, c5 = -0.07234855251399674,
                     c6 = 0.03978119794217279, c7 = -0.014401341684025418, c8 = 0.002456720396586648;
    const Doubles ax = abs_of(x), ay = abs_of(y);
    const Mask steep = ax < ay;
    const Doubles r = select(steep, ax, ay) / select(steep, ay, ax);
    const Doubles s1 = r * r, s2 = s1 * s1, s4 = s2 * s2;
    const Doubles low = (c0 + c1 * s1) + (c2 + c3 * s1) * s2;
    const Doubles high = (c4 + c5 * s1) + (c6 + c7 * s1) * s2;
    const Doubles series = low + (high + c8 * s4) * s4;
    Doubles a = r * series;
    a = select(steep, kPi / 2.0 - a, a);
    a = select(x < 0.0, kPi - a, a);
    // The sign of y, -0 included, as atan2's: atan2(-0, x < 0) is -pi (bin 0), atan2(+0, x < 0) is pi (bin 10).
    return (Doubles)((Bits)a | ((Bits)y & 0x8000000000000000ull));
}

/// @brief Position clamped into [0.5, 10.5], where only the integers 1..10 are bin edges (positions
/// 0 and 11 clamp into the end bins anyway); NaN becomes 0.5.
inline Doubles clamp_position(Doubles position) { return min_of(splat(10.5), max_of(splat(0.5), position)); }

/// @brief The bins of positions (floor, clamped to 0..10), and into `unsure` the lanes within 1e-6
/// bins of an edge or NaN.
inline Ints bins_of(Doubles position, Mask& unsure) {
    const Doubles clamped = clamp_position(position);
    const Ints bins = __builtin_convertvector(clamped, Ints);
    const Doubles fraction = clamped - __builtin_convertvector(bins, Doubles);
    unsure |= (fraction <= 1e-6) | (fraction >= 1.0 - 1e-6) | (position != position);
    return bins;
}

/// @brief Structure-of-arrays scratch for the pair features of one point with its neighbours, reused
/// from point to point (no allocation once grown); padded to whole vectors.
struct PairScratch {
    std::vector<double> px, py, pz, nx, ny, nz;
    std::vector<int32_t> angle, cos_v, cos_n;
    std::vector<int64_t> exact;  // non-zero: the fast path is not sure, use exact_pair_feature_bins

    /// @brief Room for m pairs, rounded up to whole vectors; returns the padded count.
    size_t resize(size_t m) {
        const size_t padded = (m + kLanes - 1) / kLanes * kLanes;
        for (auto* a : {&px, &py, &pz, &nx, &ny, &nz}) a->resize(padded);
        for (auto* a : {&angle, &cos_v, &cos_n}) a->resize(padded);
        exact.resize(padded);
        return padded;
    }
};

inline void store(int32_t* out, Ints v) { std::memcpy(out, &v, sizeof v); }
inline void store(int64_t* out, Mask v) { std::memcpy(out, &v, sizeof v); }

/// @brief The bins of the pairs (p1, n1)-(scratch point k, normal k) for k < padded, into the scratch.
/// Equal to exact_pair_feature_bins wherever `exact[k]` is 0: no branches, square roots, acos or
/// atan2; its approximations stay far below 1e-6 bins, and it flags whatever they could decide
/// differently: coincident points or a normal along the joining line, a near tie of the two normals'
/// angles to that line or a cosine near 1, and any of the three positions within 1e-6 bins of an edge.
void fast_pair_feature_bins(const Eigen::Vector3d& p1, const Eigen::Vector3d& n1, PairScratch& s, size_t padded) {
    constexpr double kTiny = 1e-200;  // below this the inverse-sqrt guess is not accurate (subnormals)
    constexpr double kTie = 1e-8;     // far above the 5e-10 relative error of the approximations
    const Doubles x1 = splat(p1[0]), y1 = splat(p1[1]), z1 = splat(p1[2]);
    const Doubles u1 = splat(n1[0]), v1 = splat(n1[1]), w1 = splat(n1[2]);
    for (size_t k = 0; k < padded; k += kLanes) {
        const Doubles nx = load(&s.nx[k]), ny = load(&s.ny[k]), nz = load(&s.nz[k]);
        Doubles dx = load(&s.px[k]) - x1, dy = load(&s.py[k]) - y1, dz = load(&s.pz[k]) - z1;
        const Doubles d2 = dx * dx + dy * dy + dz * dz;
        const Doubles inverse_distance = approximate_inverse_sqrt(d2);
        const Doubles a1 = (u1 * dx + v1 * dy + w1 * dz) * inverse_distance;
        const Doubles a2 = (nx * dx + ny * dy + nz * dz) * inverse_distance;
        const Doubles c1 = abs_of(a1), c2 = abs_of(a2);
        // Open3D swaps when acos(c1) > acos(c2), never when either is beyond 1 (acos is NaN there).
        // acos decreases with slope <= -1, so a gap well above the approximation error decides it.
        const Mask swap = (c1 <= 1.0) & (c2 <= 1.0) & (c2 - c1 > kTie);
        Mask unsure = (abs_of(c2 - c1) <= kTie) | (abs_of(c1 - 1.0) <= kTie) | (abs_of(c2 - 1.0) <= kTie) |
                      ~(d2 > kTiny);
        const Doubles ux = select(swap, nx, u1), uy = select(swap, ny, v1), uz = select(swap, nz, w1);
        const Doubles tx = select(swap, u1, nx), ty = select(swap, v1, ny), tz = select(swap, w1, nz);
        dx = select(swap, -dx, dx);
        dy = select(swap, -dy, dy);
        dz = select(swap, -dz, dz);
        const Doubles cn = select(swap, -a2, a1);
        Doubles vx = dy * uz - dz * uy, vy = dz * ux - dx * uz, vz = dx * uy - dy * ux;
        const Doubles v2 = vx * vx + vy * vy + vz * vz;
        unsure |= ~(v2 > kTiny);
        const Doubles inverse_v_norm = approximate_inverse_sqrt(v2);
        vx *= inverse_v_norm;
        vy *= inverse_v_norm;
        vz *= inverse_v_norm;
        const Doubles wx = uy * vz - uz * vy, wy = uz * vx - ux * vz, wz = ux * vy - uy * vx;
        const Doubles cv = vx * tx + vy * ty + vz * tz;
        const Doubles theta = approximate_atan2(wx * tx + wy * ty + wz * tz, ux * tx + uy * ty + uz * tz);
        store(&s.angle[k], bins_of(kFpfhBins * (theta + kPi) / (2.0 * kPi), unsure));
        store(&s.cos_v[k], bins_of(kFpfhBins * (cv + 1.0) * 0.5, unsure));
        store(&s.cos_n[k], bins_of(kFpfhBins * (cn + 1.0) * 0.5, unsure));
        store(&s.exact[k], unsure);
    }
}

/// @brief Neighbour lists of the points whose SPFH is needed ("slots"): slot s is cloud point
/// point_of[s]; its neighbours are result row s. The points that get an FPFH come first, in order.
struct Neighbourhoods {
    std::vector<int64_t> point_of;
    std::vector<int32_t> slot_of;  // cloud point -> slot, -1 when its SPFH is not needed
    kdtree::SearchResult result;
    size_t num_fpfh = 0;

    size_t count(size_t s) const { return static_cast<size_t>(result.offsets[s + 1] - result.offsets[s]); }
    const int32_t* indices(size_t s) const { return result.indices.data() + result.offsets[s]; }
    const double* distances2(size_t s) const { return result.distances2.data() + result.offsets[s]; }
};

/// @brief Append `more` (rows after those of `into`) to `into`.
void append_rows(kdtree::SearchResult& into, const kdtree::SearchResult& more) {
    const int64_t base = into.offsets.back();
    into.offsets.reserve(into.offsets.size() + more.offsets.size() - 1);
    for (size_t q = 1; q < more.offsets.size(); ++q) into.offsets.push_back(base + more.offsets[q]);
    into.indices.insert(into.indices.end(), more.indices.begin(), more.indices.end());
    into.distances2.insert(into.distances2.end(), more.distances2.begin(), more.distances2.end());
}

/// @brief One batch search for the selected points, a second one for the neighbours they pull in.
Neighbourhoods find_neighbourhoods(size_t n, const detail::FpfhNeighbourhoods& search,
                                   const std::optional<std::vector<int64_t>>& indices, int num_threads) {
    Neighbourhoods nb;
    nb.slot_of.assign(n, -1);
    if (!indices) {
        nb.point_of.resize(n);
        for (size_t i = 0; i < n; ++i) {
            nb.point_of[i] = static_cast<int64_t>(i);
            nb.slot_of[i] = static_cast<int32_t>(i);
        }
        nb.num_fpfh = n;
        nb.result = search.search(nb.point_of, num_threads);
        return nb;
    }
    for (size_t j = 0; j < indices->size(); ++j) {
        const int64_t i = (*indices)[j];
        if (i < 0 || static_cast<size_t>(i) >= n)
            throw InvalidArgument("indices[" + std::to_string(j) + "] = " + std::to_string(i) +
                                  " is out of range for a cloud of " + std::to_string(n) + " points");
        nb.slot_of[static_cast<size_t>(i)] = 0;  // selected; slots are numbered below
    }
    for (size_t i = 0; i < n; ++i)
        if (nb.slot_of[i] == 0) {
            nb.slot_of[i] = static_cast<int32_t>(nb.point_of.size());
            nb.point_of.push_back(static_cast<int64_t>(i));
        }
    nb.num_fpfh = nb.point_of.size();
    nb.result = search.search(nb.point_of, num_threads);
    // The neighbours of the selected points need their SPFH too, so their neighbourhoods as well.
    for (int32_t j : nb.result.indices)
        if (nb.slot_of[static_cast<size_t>(j)] < 0) nb.slot_of[static_cast<size_t>(j)] = -2;
    std::vector<int64_t> pulled_in;
    for (size_t i = 0; i < n; ++i)
        if (nb.slot_of[i] == -2) {
            nb.slot_of[i] = static_cast<int32_t>(nb.point_of.size());
            nb.point_of.push_back(static_cast<int64_t>(i));
            pulled_in.push_back(static_cast<int64_t>(i));
        }
    if (!pulled_in.empty()) append_rows(nb.result, search.search(pulled_in, num_threads));
    return nb;
}

/// @brief SPFH of slot s into `column` (kFpfhDim values, zero on entry): the histograms of its pair
/// features with every neighbour after the first (the point itself), each summing to 100.
void compute_one_spfh(const Eigen::Vector3d* points, const Eigen::Vector3d* normals, const Neighbourhoods& nb,
                      int64_t s, PairScratch& scratch, double* column) {
    const size_t m = nb.count(static_cast<size_t>(s));
    if (m < 2) return;
    const size_t i = static_cast<size_t>(nb.point_of[static_cast<size_t>(s)]);
    const int32_t* nbrs = nb.indices(static_cast<size_t>(s));
    int counts[kFpfhDim] = {};
    // Neighbour 0 is the point itself (or a coincident one, which gives the same zero pair feature).
    const size_t pairs = m - 1;
    const size_t padded = scratch.resize(pairs);
    for (size_t k = 0; k < padded; ++k) {
        // The padding repeats the last pair; its bins are computed and ignored.
        const size_t j = static_cast<size_t>(nbrs[std::min(k, pairs - 1) + 1]);
        const Eigen::Vector3d& p = points[j];
        const Eigen::Vector3d& q = normals[j];
        scratch.px[k] = p[0];
        scratch.py[k] = p[1];
        scratch.pz[k] = p[2];
        scratch.nx[k] = q[0];
        scratch.ny[k] = q[1];
        scratch.nz[k] = q[2];
    }
    fast_pair_feature_bins(points[i], normals[i], scratch, padded);
    for (size_t k = 0; k < pairs; ++k) {
        PairBins b{scratch.angle[k], scratch.cos_v[k], scratch.cos_n[k]};
        if (scratch.exact[k] != 0) {
            const size_t j = static_cast<size_t>(nbrs[k + 1]);
            b = exact_pair_feature_bins(points[i], normals[i], points[j], normals[j]);
        }
        ++counts[b.angle];
        ++counts[kFpfhBins + b.cos_v];
        ++counts[2 * kFpfhBins + b.cos_n];
    }
    const double increment = 100.0 / static_cast<double>(m - 1);
    for (int b = 0; b < kFpfhDim; ++b) column[b] = counts[b] * increment;
}

/// @brief SPFH of every slot (kFpfhDim x slots): the first neighbour is the point itself and is skipped.
Eigen::MatrixXd compute_spfh(const geometry::PointCloud& cloud, const Neighbourhoods& nb, int threads) {
    const int64_t slots = static_cast<int64_t>(nb.point_of.size());
    Eigen::MatrixXd spfh = Eigen::MatrixXd::Zero(kFpfhDim, slots);
    const Eigen::Vector3d* points = cloud.points.data();
    const Eigen::Vector3d* normals = cloud.normals.data();
#pragma omp parallel num_threads(threads)
    {
        PairScratch scratch;  // per thread, reused from point to point
#pragma omp for schedule(dynamic, 64)
        for (int64_t s = 0; s < slots; ++s) compute_one_spfh(points, normals, nb, s, scratch, spfh.col(s).data());
    }
    return spfh;
}
/// @brief FPFH of the first num_fpfh slots into `out`: the neighbours' SPFHs weighted by 1 / squared
/// distance, each sub-histogram rescaled to sum to 100, plus the point's own SPFH (Open3D's
/// ComputeFPFHFeature). Points with fewer than 2 neighbours keep their zero column.
void weigh_neighbours(const Neighbourhoods& nb, const Eigen::MatrixXd& spfh, Eigen::MatrixXd& out, int threads) {
    const int64_t num_fpfh = static_cast<int64_t>(nb.num_fpfh);
#pragma omp parallel for schedule(dynamic, 64) num_threads(threads)
    for (int64_t s = 0; s < num_fpfh; ++s) {
        const size_t m = nb.count(static_cast<size_t>(s));
        if (m < 2) continue;
        const int32_t* nbrs = nb.indices(static_cast<size_t>(s));
        const double* d2 = nb.distances2(static_cast<size_t>(s));
        double acc[kFpfhDim] = {};
        for (size_t k = 1; k < m; ++k) {
            if (d2[k] == 0.0) continue;  // a coincident point has no direction (Open3D skips it)
            const double weight = 1.0 / d2[k];
            const double* other = spfh.col(nb.slot_of[static_cast<size_t>(nbrs[k])]).data();
            for (int b = 0; b < kFpfhDim; ++b) acc[b] += other[b] * weight;
        }
        const double* own = spfh.col(s).data();
        double* column = out.col(s).data();
        for (int h = 0; h < 3; ++h) {
            double sum = 0.0;
            for (int b = h * kFpfhBins; b < (h + 1) * kFpfhBins; ++b) sum += acc[b];
            const double scale = sum != 0.0 ? 100.0 / sum : 1.0;
            for (int b = h * kFpfhBins; b < (h + 1) * kFpfhBins; ++b) column[b] = acc[b] * scale + own[b];
        }
    }
}

}  // namespace

Feature compute_fpfh_feature(const geometry::PointCloud& cloud, const kdtree::SearchParam& param,
                             const std::optional<std::vector<int64_t>>& indices, int num_threads) {
    if (cloud.points.empty()) throw InvalidArgument("compute_fpfh_feature: the cloud is empty");
    if (!cloud.has_normals()) throw InvalidArgument("compute_fpfh_feature: the cloud has no normals");
    if (num_threads < 0) throw InvalidArgument("num_threads must be >= 0, got " + std::to_string(num_threads));
    for (size_t i = 0; i < cloud.size(); ++i)
        if (!cloud.normals[i].allFinite())
            throw InvalidArgument("normal " + std::to_string(i) + " has a non-finite coordinate");
    const int threads = utility::resolve_num_threads(num_threads);

    const detail::FpfhNeighbourhoods search(cloud.points, param);  // checks the points and the parameter
    const Neighbourhoods nb = find_neighbourhoods(cloud.size(), search, indices, threads);
    const Eigen::MatrixXd spfh = compute_spfh(cloud, nb, threads);

    Feature feature;
    feature.data = Eigen::MatrixXd::Zero(kFpfhDim, static_cast<Eigen::Index>(nb.num_fpfh));
    weigh_neighbours(nb, spfh, feature.data, threads);
    return feature;
}

}  // namespace o3d::registration
