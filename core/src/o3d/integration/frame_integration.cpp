// SPDX-License-Identifier: MIT
// The voxel update is the hot loop of integration (millions of voxels a frame). Boxes of kCullBox^3 voxels are
// first tested against the frame's depth tiles, so voxels that cannot change cost nothing; the rest go in runs of
// four along z, one SIMD lane each: projection, tests and running averages are branch-free, and only the pixel
// reads go lane by lane.
#include "o3d/integration/frame_integration.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <utility>

#include "o3d/integration/simd4.h"
#include "o3d/utility/parallel.h"

namespace o3d::integration::detail {
namespace {

static_assert(kCullBox == 4, "a box's z runs are one SIMD vector of four lanes");

// Culling must never skip a voxel the update would touch: the box's corners and the voxel walk round differently,
// so a box is skipped as "behind" only when it is behind by this much more than sdf_trunc (0.1 mm).
constexpr float kCullMargin = 1e-4f;

struct CameraSteps {
    Eigen::Vector3f x, y, z;  ///< camera-space moves of one voxel along the block's axes
};

// Whether some voxel of the box [lo, lo + extent] (voxel centres; `first` is lo's, in camera space) may be updated:
// false when the whole box is behind the camera, projects outside the image or onto holes only, or lies more than
// sdf_trunc behind the farthest depth under it. When all 8 corners are in front of the camera, the image of the
// box is inside the hull of theirs. The corners go four to a vector: the near face (z offset 0), then the far one.
bool box_may_change(const Eigen::Vector3f& first, const Eigen::Vector3i& extent, const CameraSteps& step,
                    const FrameView& frame) {
    const Float4 ox{0.0f, float(extent.x()), 0.0f, float(extent.x())};
    const Float4 oy{0.0f, 0.0f, float(extent.y()), float(extent.y())};
    const float oz = float(extent.z());
    Float4 x[2], y[2], z[2];
    for (int face = 0; face < 2; ++face) {
        const Eigen::Vector3f base = first + step.z * (face ? oz : 0.0f);
        x[face] = splat(base.x()) + ox * splat(step.x.x()) + oy * splat(step.y.x());
        y[face] = splat(base.y()) + ox * splat(step.x.y()) + oy * splat(step.y.y());
        z[face] = splat(base.z()) + ox * splat(step.x.z()) + oy * splat(step.y.z());
    }
    const float z_min = lowest(min4(z[0], z[1])), z_max = highest(max4(z[0], z[1]));
    if (z_max <= 0.0f) return false;        // every voxel is behind the camera
    if (z_min <= kCullMargin) return true;  // straddles the camera plane: no bound on the footprint
    Float4 u[2], v[2];
    for (int face = 0; face < 2; ++face) {
        const Float4 inv_z = splat(1.0f) / z[face];
        u[face] = x[face] * splat(frame.fx) * inv_z;
        v[face] = y[face] * splat(frame.fy) * inv_z;
    }
    // Pixel u covers u_f in [u, u + 1) with u_f = x fx / z + cx + 0.5; one pixel of slack each way for rounding.
    const float u_lo = std::floor(lowest(min4(u[0], u[1])) + frame.cx + 0.5f) - 1.0f;
    const float u_hi = std::floor(highest(max4(u[0], u[1])) + frame.cx + 0.5f) + 1.0f;
    const float v_lo = std::floor(lowest(min4(v[0], v[1])) + frame.cy + 0.5f) - 1.0f;
    const float v_hi = std::floor(highest(max4(v[0], v[1])) + frame.cy + 0.5f) + 1.0f;
    if (!(u_hi >= 0.0f && v_hi >= 0.0f && u_lo < float(frame.width) && v_lo < float(frame.height))) return false;
    const DepthTiles::Span span = frame.tiles->query(int(std::max(u_lo, 0.0f)), int(std::max(v_lo, 0.0f)),
                                                     int(std::min(u_hi, float(frame.width - 1))),
                                                     int(std::min(v_hi, float(frame.height - 1))));
    if (span.farthest <= 0.0f) return false;  // only holes under the box
    // sdf = (depth - z) * f with f >= 1, so depth - z <= -sdf_trunc means sdf <= -sdf_trunc: skipped.
    return z_min - span.farthest < frame.sdf_trunc + kCullMargin;
}

// The colours of four pixels (FramePixel::color as bits) as the three vectors that line up with four consecutive RGB
// voxels: r0 g0 b0 r1 | g1 b1 r2 g2 | b2 r3 g3 b3.
PerChannel sample_colors(Int4 bits, FrameColor color) {
    if (color == FrameColor::Gray32) return per_channel(Float4(bits));
    constexpr float kByte = 1.0f / 255.0f;
    const Int4 byte = {255, 255, 255, 255};
    const Float4 r = __builtin_convertvector(bits & byte, Float4) * splat(kByte);
    const Float4 g = __builtin_convertvector((bits >> 8) & byte, Float4) * splat(kByte);
    const Float4 b = __builtin_convertvector((bits >> 16) & byte, Float4) * splat(kByte);
    const Float4 rg_low = __builtin_shufflevector(r, g, 0, 4, 1, 5), rg_high = __builtin_shufflevector(r, g, 2, 6, 3, 7);
    const Float4 g1_b1 = __builtin_shufflevector(rg_low, b, 3, 5, 3, 5);
    return {{__builtin_shufflevector(rg_low, b, 0, 1, 4, 2), __builtin_shufflevector(g1_b1, rg_high, 0, 1, 4, 5),
             __builtin_shufflevector(b, rg_high, 2, 6, 7, 3)}};
}

// Averages four samples into four consecutive RGB voxels, lanes outside `update` unchanged.
void average_colors(float* rgb, const PerChannel& sample, Int4 update, Float4 w, Float4 inv_w) {
    const PerChannel weight = per_channel(w), inv_weight = per_channel(inv_w);
    const PerChannel mask = per_channel(Float4(update));
    for (int i = 0; i < 3; ++i) {
        const Float4 old = load4(rgb + 4 * i);
        store4(rgb + 4 * i, select(Int4(mask.v[i]), (old * weight.v[i] + sample.v[i]) * inv_weight.v[i], old));
    }
}

// A frame's numbers as vectors, made once a block: update_run's stores into voxel arrays could alias the frame's
// floats, so the compiler would reload and re-splat them for every run.
struct RunConstants {
    Float4 fx, fy, cx, cy;              ///< cx, cy with the half pixel of nearest-pixel rounding added
    Float4 u_limit, v_limit;            ///< the image's width and height less Open3D's 0.0001 border
    Float4 trunc, minus_trunc, inv_trunc;
    Float4 lane_x, lane_y, lane_z;      ///< camera-space offsets of a run's four voxels from its first
    int width;
    FrameColor color;
};

const Float4 kLanes{0.0f, 1.0f, 2.0f, 3.0f};

Float4 load_pair(const FramePixel* a, const FramePixel* b) {
    static_assert(sizeof(FramePixel) == 8, "two pixels fill a vector");
    float out[4];
    std::memcpy(out, a, 8);
    std::memcpy(out + 2, b, 8);
    return load4(out);
}

RunConstants run_constants(const FrameView& frame, const Eigen::Vector3f& z_step) {
    return {splat(frame.fx), splat(frame.fy), splat(frame.cx + 0.5f), splat(frame.cy + 0.5f),
            splat(float(frame.width) - 0.0001f), splat(float(frame.height) - 0.0001f), splat(frame.sdf_trunc),
            splat(-frame.sdf_trunc), splat(1.0f / frame.sdf_trunc), kLanes * splat(z_step.x()),
            kLanes * splat(z_step.y()), kLanes * splat(z_step.z()), frame.width, frame.color};
}

// One run of `count` (<= 4) voxels along z from `first_voxel`, whose first centre is `start` in camera space.
void update_run(VoxelBlock& block, size_t first_voxel, int count, const Eigen::Vector3f& start,
                const RunConstants& k, const FrameView& frame) {
    const Float4 pz = splat(start.z()) + k.lane_z, px = splat(start.x()) + k.lane_x, py = splat(start.y()) + k.lane_y;
    const Float4 inv_z = splat(1.0f) / pz;  // lanes with pz <= 0 are masked out below
    // Pixel u covers u_f in [u, u + 1) with u_f = x fx / z + cx + 0.5; the 0.0001 borders are Open3D's.
    const Float4 u_f = px * k.fx * inv_z + k.cx, v_f = py * k.fy * inv_z + k.cy;
    const Float4 border = splat(0.0001f);
    const Int4 in_view = (pz > splat(0.0f)) & (kLanes < splat(float(count))) & (u_f >= border) & (u_f < k.u_limit) &
                         (v_f >= border) & (v_f < k.v_limit);
    if (!any(in_view)) return;
    const Int4 u = __builtin_convertvector(select(in_view, u_f, splat(0.0f)), Int4);
    const Int4 v = __builtin_convertvector(select(in_view, v_f, splat(0.0f)), Int4);
    int32_t index[4];  // lanes out of view read pixel 0 and are masked out
    const Int4 index4 = v * k.width + u;
    std::memcpy(index, &index4, sizeof index);
    // Two pixels (depth, colour) to a vector, then split: four depths, four colours.
    const Float4 p01 = load_pair(&frame.pixels[index[0]], &frame.pixels[index[1]]);
    const Float4 p23 = load_pair(&frame.pixels[index[2]], &frame.pixels[index[3]]);
    const Float4 depth = __builtin_shufflevector(p01, p23, 0, 2, 4, 6);
    const Int4 color_bits = Int4(__builtin_shufflevector(p01, p23, 1, 3, 5, 7));
    Int4 update = in_view & (depth > splat(0.0f)) & (depth <= splat(FLT_MAX));  // not holes, NaN or infinity
    const Float4 gap = depth - pz;
    // Free space at least sdf_trunc in front (most voxels) samples 1 and needs no depth-to-distance factor.
    Float4 sample = splat(1.0f);
    const Int4 near = update & (gap < k.trunc);
    if (any(near)) {
        const Float4 ray2{frame.ray_x2[u[0]] + frame.ray_y2[v[0]], frame.ray_x2[u[1]] + frame.ray_y2[v[1]],
                          frame.ray_x2[u[2]] + frame.ray_y2[v[2]], frame.ray_x2[u[3]] + frame.ray_y2[v[3]]};
        const Float4 sdf = gap * sqrt4(splat(1.0f) + ray2);
        sample = select(near, min4(splat(1.0f), sdf * k.inv_trunc), sample);
        update &= ~near | (sdf > k.minus_trunc);
    }
    if (!any(update)) return;
    float* tsdf = block.tsdf.data() + first_voxel;
    float* weight = block.weight.data() + first_voxel;
    float* rgb = block.color.empty() ? nullptr : block.color[first_voxel].data();
    Float4 old_tsdf{}, w{};
    if (count == 4) {
        old_tsdf = load4(tsdf), w = load4(weight);
    } else {
        for (int i = 0; i < count; ++i) old_tsdf[i] = tsdf[i], w[i] = weight[i];
    }
    const Float4 inv_w = splat(1.0f) / (w + splat(1.0f));
    const Float4 new_tsdf = select(update, (old_tsdf * w + sample) * inv_w, old_tsdf);
    const Float4 new_weight = w + select(update, splat(1.0f), splat(0.0f));
    if (count == 4) {
        store4(tsdf, new_tsdf), store4(weight, new_weight);
        if (rgb && k.color != FrameColor::None) average_colors(rgb, sample_colors(color_bits, k.color), update, w, inv_w);
        return;
    }
    for (int i = 0; i < count; ++i) {
        tsdf[i] = new_tsdf[i], weight[i] = new_weight[i];
        if (!rgb || k.color == FrameColor::None || !update[i]) continue;
        const PerChannel colors = sample_colors(color_bits, k.color);  // lane i's three channels: 3i .. 3i + 2
        for (int c = 0; c < 3; ++c)
            rgb[3 * i + c] = (rgb[3 * i + c] * w[i] + colors.v[(3 * i + c) / 4][(3 * i + c) % 4]) * inv_w[i];
    }
}

}  // namespace

void interleave_pixels(const float* depth, const uint8_t* rgb, const float* intensity, size_t count,
                       std::vector<FramePixel>& out) {
    out.resize(count);
#pragma omp parallel for schedule(static) num_threads(utility::resolve_num_threads())
    for (long i = 0; i < long(count); ++i) {
        FramePixel& pixel = out[size_t(i)];
        pixel.depth = depth[i];
        pixel.color = 0;
        if (rgb) pixel.color = uint32_t(rgb[3 * i]) | uint32_t(rgb[3 * i + 1]) << 8 | uint32_t(rgb[3 * i + 2]) << 16;
        if (intensity) std::memcpy(&pixel.color, &intensity[i], sizeof pixel.color);
    }
}

void order_by_footprint(std::vector<VoxelBlock*>& blocks, const BlockMap& map, const FrameView& frame) {
    constexpr int kTile = 32;  // pixels; about a block's footprint at room scale
    const int tiles_across = frame.width / kTile + 1;
    const double block_length = map.voxel_length() * double(map.side());
    std::vector<std::pair<int, VoxelBlock*>> keyed;
    keyed.reserve(blocks.size());
    for (VoxelBlock* block : blocks) {
        const Eigen::Vector3d centre =
            map.origin() + block_length * (block->key.cast<double>().array() + 0.5).matrix();
        const Eigen::Vector3f p = frame.rotation * centre.cast<float>() + frame.translation;
        int tile = INT32_MAX;  // behind the camera: last
        if (p.z() > 0.0f) {
            const float u = std::clamp(p.x() * frame.fx / p.z() + frame.cx, 0.0f, float(frame.width - 1));
            const float v = std::clamp(p.y() * frame.fy / p.z() + frame.cy, 0.0f, float(frame.height - 1));
            tile = int(v) / kTile * tiles_across + int(u) / kTile;
        }
        keyed.emplace_back(tile, block);
    }
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (size_t i = 0; i < blocks.size(); ++i) blocks[i] = keyed[i].second;
}

void integrate_block(VoxelBlock& block, const BlockMap& map, const FrameView& frame, int x_begin, int x_end) {
    const int side = map.side();
    const double voxel_length = map.voxel_length();
    const CameraSteps step{frame.rotation.col(0) * float(voxel_length), frame.rotation.col(1) * float(voxel_length),
                           frame.rotation.col(2) * float(voxel_length)};
    // Camera-space centre of voxel (x_begin, 0, 0); others are reached by steps (float rounding is far below mm).
    const Eigen::Vector3d origin = map.origin() + voxel_length * (double(side) * block.key.cast<double>() +
                                                                  Eigen::Vector3d(x_begin + 0.5, 0.5, 0.5));
    const Eigen::Vector3f first = frame.rotation * origin.cast<float>() + frame.translation;
    // Test every box first, then visit the live ones in memory order (x, y, then z): the voxel arrays are then read
    // as forward streams the hardware prefetches, where box order would jump between 16 columns.
    const int boxes_y = (side + kCullBox - 1) / kCullBox, boxes_z = boxes_y;
    const int boxes_x = (x_end - x_begin + kCullBox - 1) / kCullBox;
    thread_local std::vector<uint8_t> live;
    live.assign(size_t(boxes_x) * size_t(boxes_y) * size_t(boxes_z), 0);
    bool any_live = false;
    for (int bx = 0; bx < boxes_x; ++bx)
        for (int by = 0; by < boxes_y; ++by)
            for (int bz = 0; bz < boxes_z; ++bz) {
                const Eigen::Vector3i lo(bx * kCullBox, by * kCullBox, bz * kCullBox);
                const Eigen::Vector3i extent(std::min(kCullBox, x_end - x_begin - lo.x()) - 1,
                                             std::min(kCullBox, side - lo.y()) - 1,
                                             std::min(kCullBox, side - lo.z()) - 1);
                const Eigen::Vector3f corner =
                    first + step.x * float(lo.x()) + step.y * float(lo.y()) + step.z * float(lo.z());
                const bool box_live = box_may_change(corner, extent, step, frame);
                live[(size_t(bx) * size_t(boxes_y) + size_t(by)) * size_t(boxes_z) + size_t(bz)] = box_live;
                any_live |= box_live;
            }
    if (!any_live) return;
    const RunConstants constants = run_constants(frame, step.z);
    for (int x = x_begin; x < x_end; ++x)
        for (int y = 0; y < side; ++y) {
            const uint8_t* column_boxes =
                &live[(size_t((x - x_begin) / kCullBox) * size_t(boxes_y) + size_t(y / kCullBox)) * size_t(boxes_z)];
            const Eigen::Vector3f column_start = first + step.x * float(x - x_begin) + step.y * float(y);
            const size_t column = (size_t(x) * size_t(side) + size_t(y)) * size_t(side);
            for (int bz = 0; bz < boxes_z; ++bz) {
                if (!column_boxes[bz]) continue;
                const int z = bz * kCullBox;
                update_run(block, column + size_t(z), std::min(kCullBox, side - z), column_start + step.z * float(z),
                           constants, frame);
            }
        }
}

}  // namespace o3d::integration::detail
