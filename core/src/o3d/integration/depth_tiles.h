// SPDX-License-Identifier: MIT
#pragma once
/// @file depth_tiles.h
/// @brief A depth image summarised over square tiles at every scale (a min/max pyramid), so that integration can
/// tell from a box of voxels' footprint on the image that none of them can be updated and skip the whole box.
#include <vector>

namespace o3d::integration::detail {

class DepthTiles {
public:
    /// @brief What a rectangle of pixels holds: `nearest` is the smallest depth, 0 when any pixel is a hole;
    /// `farthest` is the largest valid depth, 0 when none is valid. Holes are 0, negative, NaN or infinite.
    struct Span {
        float nearest = 0.0f;
        float farthest = 0.0f;
    };

    /// @brief Summarises `depth` (metres, row-major, width x height); the image is not kept.
    void build(const float* depth, int width, int height);
    /// @brief A span covering at least the pixels [u0, u1] x [v0, v1] (inclusive, inside the image): the tiles
    /// that hold them, taken at the scale where a few tiles suffice, so the span may cover a few more pixels.
    Span query(int u0, int v0, int u1, int v1) const;

private:
    struct Level {
        int width = 0, height = 0;
        std::vector<Span> tiles;
    };
    std::vector<Level> levels_;  ///< level k: tiles of kTile << k pixels a side, down to one tile
};

}  // namespace o3d::integration::detail
