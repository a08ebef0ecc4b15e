// SPDX-License-Identifier: MIT
#include "o3d/color_map/warping_field.h"

#include <algorithm>
#include <cmath>

namespace o3d::color_map::detail {

WarpingField::WarpingField(int width, int height, int vertical_anchors)
    : rows_(vertical_anchors), spacing_(double(height - 1) / double(vertical_anchors - 1)) {
    columns_ = int(std::ceil(double(width - 1) / spacing_ - 1e-9)) + 1;
    columns_ = std::max(columns_, 2);
    offsets_.assign(size_t(columns_) * size_t(rows_), Eigen::Vector2d::Zero());
}

WarpingField::Cell WarpingField::cell(double u, double v) const {
    const double gu = std::clamp(u / spacing_, 0.0, double(columns_ - 1));
    const double gv = std::clamp(v / spacing_, 0.0, double(rows_ - 1));
    const int i = std::min(int(gu), columns_ - 2);
    const int j = std::min(int(gv), rows_ - 2);
    const double a = gu - i, b = gv - j;
    Cell c;
    c.anchor = {j * columns_ + i, j * columns_ + i + 1, (j + 1) * columns_ + i, (j + 1) * columns_ + i + 1};
    c.weight = {(1 - a) * (1 - b), a * (1 - b), (1 - a) * b, a * b};
    return c;
}

Eigen::Vector2d WarpingField::displacement(const Cell& c) const {
    Eigen::Vector2d d = Eigen::Vector2d::Zero();
    for (int k = 0; k < 4; ++k) d += c.weight[size_t(k)] * offsets_[size_t(c.anchor[size_t(k)])];
    return d;
}

}  // namespace o3d::color_map::detail
