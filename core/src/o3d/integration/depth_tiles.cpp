// SPDX-License-Identifier: MIT
#include "o3d/integration/depth_tiles.h"

#include <algorithm>
#include <cfloat>

#include "o3d/utility/parallel.h"

namespace o3d::integration::detail {
namespace {

constexpr int kTileShift = 3;  // 8 x 8 pixel tiles at the finest level
constexpr int kMostTilesPerAxis = 4;

DepthTiles::Span merge(DepthTiles::Span a, DepthTiles::Span b) {
    return {std::min(a.nearest, b.nearest), std::max(a.farthest, b.farthest)};
}

}  // namespace

void DepthTiles::build(const float* depth, int width, int height) {
    // Levels are resized, not rebuilt, so that a summary built for every frame reuses its memory.
    size_t count = 1;
    for (int w = (width + (1 << kTileShift) - 1) >> kTileShift, h = (height + (1 << kTileShift) - 1) >> kTileShift;
         w > 1 || h > 1; w = (w + 1) / 2, h = (h + 1) / 2)
        ++count;
    levels_.resize(count);
    Level& finest = levels_[0];
    finest.width = (width + (1 << kTileShift) - 1) >> kTileShift;
    finest.height = (height + (1 << kTileShift) - 1) >> kTileShift;
    finest.tiles.assign(size_t(finest.width) * size_t(finest.height), Span{FLT_MAX, 0.0f});
    // Tile rows are independent: threads take them whole.
#pragma omp parallel for schedule(static) num_threads(utility::resolve_num_threads())
    for (int tile_row = 0; tile_row < finest.height; ++tile_row) {
        Span* row = finest.tiles.data() + size_t(tile_row) * size_t(finest.width);
        for (int v = tile_row << kTileShift; v < std::min(height, (tile_row + 1) << kTileShift); ++v) {
            const float* pixels = depth + size_t(v) * size_t(width);
            for (int u = 0; u < width; ++u) {
                const float d = pixels[u];
                Span& tile = row[u >> kTileShift];
                if (d > 0.0f && d <= FLT_MAX) {
                    tile.nearest = std::min(tile.nearest, d);
                    tile.farthest = std::max(tile.farthest, d);
                } else {
                    tile.nearest = 0.0f;
                }
            }
        }
    }
    for (size_t level = 1; level < levels_.size(); ++level) {
        const Level& fine = levels_[level - 1];
        Level& coarse = levels_[level];
        coarse.width = (fine.width + 1) / 2;
        coarse.height = (fine.height + 1) / 2;
        coarse.tiles.assign(size_t(coarse.width) * size_t(coarse.height), Span{FLT_MAX, 0.0f});
        for (int y = 0; y < fine.height; ++y)
            for (int x = 0; x < fine.width; ++x) {
                Span& tile = coarse.tiles[size_t(y / 2) * size_t(coarse.width) + size_t(x / 2)];
                tile = merge(tile, fine.tiles[size_t(y) * size_t(fine.width) + size_t(x)]);
            }
    }
}

DepthTiles::Span DepthTiles::query(int u0, int v0, int u1, int v1) const {
    int x0 = u0 >> kTileShift, y0 = v0 >> kTileShift, x1 = u1 >> kTileShift, y1 = v1 >> kTileShift;
    size_t level = 0;
    while (level + 1 < levels_.size() && (x1 - x0 >= kMostTilesPerAxis || y1 - y0 >= kMostTilesPerAxis)) {
        x0 >>= 1, y0 >>= 1, x1 >>= 1, y1 >>= 1;
        ++level;
    }
    const Level& tiles = levels_[level];
    Span out{FLT_MAX, 0.0f};
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) out = merge(out, tiles.tiles[size_t(y) * size_t(tiles.width) + size_t(x)]);
    return out;
}

}  // namespace o3d::integration::detail
