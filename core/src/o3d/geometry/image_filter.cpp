// SPDX-License-Identifier: MIT
// Separable filters on 1-channel float images (Open3D's Image::Filter): a horizontal pass, then a vertical
// one, each tap's product rounded to float and the taps summed in double from the left/top, borders
// replicating the edge pixel, each pass stored as float. Following that arithmetic exactly makes the
// results bitwise equal to Open3D's. Every output pixel is computed on its own, so the row-parallel
// passes give the same bits for any thread count.
#include <algorithm>
#include <array>
#include <vector>

#include "o3d/geometry/image_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

namespace {

// Open3D's kernels: binomial Gaussians (sum 1) and the Sobel difference / smoothing pair.
constexpr std::array<float, 3> kGaussian3 = {0.25f, 0.5f, 0.25f};
constexpr std::array<float, 5> kGaussian5 = {0.0625f, 0.25f, 0.375f, 0.25f, 0.0625f};
constexpr std::array<float, 7> kGaussian7 = {0.03125f, 0.109375f, 0.21875f, 0.28125f,
                                             0.21875f, 0.109375f, 0.03125f};
constexpr std::array<float, 3> kSobelDiff = {-1.0f, 0.0f, 1.0f};
constexpr std::array<float, 3> kSobelSmooth = {1.0f, 2.0f, 1.0f};

/// Below this many pixels a pass is cheaper than waking the thread team.
constexpr size_t kParallelPixels = 1 << 15;

template <size_t K>
void horizontal_pass(const float* in, float* out, int width, int height, const std::array<float, K>& k,
                     int threads) {
    constexpr int h = int(K / 2);
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
        std::vector<float> padded(size_t(width) + 2 * h);
#pragma omp for schedule(static)
        for (int y = 0; y < height; ++y) {
            const float* row = in + size_t(y) * size_t(width);
            for (int i = 0; i < h; ++i) {
                padded[size_t(i)] = row[0];
                padded[size_t(width + h + i)] = row[width - 1];
            }
            std::copy(row, row + width, padded.begin() + h);
            const float* p = padded.data();
            float* o = out + size_t(y) * size_t(width);
            for (int x = 0; x < width; ++x) {
                double acc = 0.0;
                for (size_t i = 0; i < K; ++i) acc += double(p[size_t(x) + i] * k[i]);
                o[x] = float(acc);
            }
        }
    }
}

template <size_t K>
void vertical_pass(const float* in, float* out, int width, int height, const std::array<float, K>& k, int threads) {
    constexpr int h = int(K / 2);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (int y = 0; y < height; ++y) {
        std::array<const float*, K> rows;
        for (size_t i = 0; i < K; ++i)
            rows[i] = in + size_t(std::clamp(y + int(i) - h, 0, height - 1)) * size_t(width);
        float* o = out + size_t(y) * size_t(width);
        for (int x = 0; x < width; ++x) {
            double acc = 0.0;
            for (size_t i = 0; i < K; ++i) acc += double(rows[i][x] * k[i]);
            o[x] = float(acc);
        }
    }
}

template <size_t K>
Image separable(const Image& image, const std::array<float, K>& kx, const std::array<float, K>& ky) {
    const size_t pixels = size_t(image.width) * size_t(image.height);
    const int threads = pixels >= kParallelPixels ? utility::resolve_num_threads() : 1;
    Image temp = make_image(image.width, image.height, 1, 4);
    Image out = make_image(image.width, image.height, 1, 4);
    horizontal_pass(reinterpret_cast<const float*>(image.data.data()), reinterpret_cast<float*>(temp.data.data()),
                    image.width, image.height, kx, threads);
    vertical_pass(reinterpret_cast<const float*>(temp.data.data()), reinterpret_cast<float*>(out.data.data()),
                  image.width, image.height, ky, threads);
    return out;
}

}  // namespace

Image filter_image(const Image& image, ImageFilterType type) {
    require_float_gray(image, "filter_image");
    switch (type) {
        case ImageFilterType::Gaussian3: return separable(image, kGaussian3, kGaussian3);
        case ImageFilterType::Gaussian5: return separable(image, kGaussian5, kGaussian5);
        case ImageFilterType::Gaussian7: return separable(image, kGaussian7, kGaussian7);
        case ImageFilterType::Sobel3Dx: return separable(image, kSobelDiff, kSobelSmooth);
        case ImageFilterType::Sobel3Dy: return separable(image, kSobelSmooth, kSobelDiff);
    }
    throw InvalidArgument("filter_image: unknown filter type");
}

}  // namespace o3d::geometry
