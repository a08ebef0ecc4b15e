// SPDX-License-Identifier: MIT
// Image operations: analytic answers (constants survive smoothing, Sobel of a ramp is its slope times the
// kernel gain, 2x2 means, flips), Open3D's conversion rules, argument checks, and numbers recorded from
// Open3D 0.20 on the shared RGB-D frame by tools/reference/record_image.py.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "o3d/geometry/image_ops.h"
#include "o3d/io/image_io.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "test_data.h"

namespace {

using o3d::geometry::Image;
using o3d::geometry::ImageConvertType;
using o3d::geometry::ImageFilterType;
using o3d::geometry::make_image;

constexpr ImageFilterType kAllFilters[] = {ImageFilterType::Gaussian3, ImageFilterType::Gaussian5,
                                          ImageFilterType::Gaussian7, ImageFilterType::Sobel3Dx,
                                          ImageFilterType::Sobel3Dy};

Image float_image(int w, int h, float (*f)(int u, int v)) {
    Image im = make_image(w, h, 1, 4);
    for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u) *im.pixel<float>(u, v) = f(u, v);
    return im;
}

float at(const Image& im, int u, int v) { return *im.pixel<float>(u, v); }

TEST(imageOps, MakeImageValidates) {
    const Image im = make_image(5, 3, 3, 2);
    EXPECT_EQ(im.byte_size(), 5u * 3 * 3 * 2);
    EXPECT_EQ(im.data.size(), im.byte_size());
    for (uint8_t b : im.data) ASSERT_EQ(b, 0);
    EXPECT_THROW(make_image(0, 3, 1, 1), o3d::InvalidArgument);
    EXPECT_THROW(make_image(3, -1, 1, 1), o3d::InvalidArgument);
    EXPECT_THROW(make_image(3, 3, 2, 1), o3d::InvalidArgument);
    EXPECT_THROW(make_image(3, 3, 1, 3), o3d::InvalidArgument);
    EXPECT_THROW(make_image(3, 3, 1, 8), o3d::InvalidArgument);
    // 2^31-1 squared: no overflow, a clear error instead of an allocation.
    EXPECT_THROW(make_image(2147483647, 2147483647, 4, 4), o3d::InvalidArgument);
    EXPECT_THROW(make_image(70000, 70000, 1, 1), o3d::InvalidArgument);
}

TEST(imageOps, FilterOfConstantIsConstant) {
    for (float c : {2.0f, 0.3f, -7.25f}) {
        Image im = make_image(9, 6, 1, 4);
        for (int v = 0; v < 6; ++v)
            for (int u = 0; u < 9; ++u) *im.pixel<float>(u, v) = c;
        for (ImageFilterType t : kAllFilters) {
            const Image out = o3d::geometry::filter_image(im, t);
            ASSERT_EQ(out.width, 9);
            ASSERT_EQ(out.height, 6);
            const bool sobel = t == ImageFilterType::Sobel3Dx || t == ImageFilterType::Sobel3Dy;
            for (int v = 0; v < 6; ++v)
                for (int u = 0; u < 9; ++u) {
                    if (sobel)
                        ASSERT_EQ(at(out, u, v), 0.0f);
                    else if (c == 2.0f || c == -7.25f)  // products with the dyadic weights are exact
                        ASSERT_EQ(at(out, u, v), c);
                    else
                        ASSERT_NEAR(at(out, u, v), c, 1e-6f);
                }
        }
    }
}

TEST(imageOps, SobelOfRampIsSlopeTimesGain) {
    // f = 0.5 u + 0.25 v. Sobel 3: difference (-1, 0, 1) spans 2 pixels, smoothing (1, 2, 1) sums to 4,
    // so the interior response is 8 x slope; on a replicated border the difference spans 1 pixel (4 x slope).
    const Image ramp = float_image(16, 12, [](int u, int v) { return 0.5f * float(u) + 0.25f * float(v); });
    const Image dx = o3d::geometry::filter_image(ramp, ImageFilterType::Sobel3Dx);
    const Image dy = o3d::geometry::filter_image(ramp, ImageFilterType::Sobel3Dy);
    for (int v = 0; v < 12; ++v)
        for (int u = 0; u < 16; ++u) {
            const float ex = (u == 0 || u == 15) ? 4 * 0.5f : 8 * 0.5f;
            const float ey = (v == 0 || v == 11) ? 4 * 0.25f : 8 * 0.25f;
            ASSERT_EQ(at(dx, u, v), ex) << u << "," << v;
            ASSERT_EQ(at(dy, u, v), ey) << u << "," << v;
        }
    // Symmetric Gaussians keep a linear ramp away from the border.
    for (ImageFilterType t : {ImageFilterType::Gaussian3, ImageFilterType::Gaussian5, ImageFilterType::Gaussian7}) {
        const Image g = o3d::geometry::filter_image(ramp, t);
        for (int v = 3; v < 9; ++v)
            for (int u = 3; u < 13; ++u) ASSERT_EQ(at(g, u, v), at(ramp, u, v)) << u << "," << v;
    }
    // Gaussian3 at the left edge: the replicated pixel gives 0.75 f(0, v) + 0.25 f(1, v) = f(0, v) + 0.125
    // horizontally; vertically v = 2 is interior, so (0, 2) -> 0.25 * 2 + 0.125.
    const Image g3 = o3d::geometry::filter_image(ramp, ImageFilterType::Gaussian3);
    EXPECT_EQ(at(g3, 0, 2), 0.625f);
}

TEST(imageOps, FilterNeedsFloatGray) {
    EXPECT_THROW(o3d::geometry::filter_image(make_image(4, 4, 1, 1), ImageFilterType::Gaussian3), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::filter_image(make_image(4, 4, 1, 2), ImageFilterType::Gaussian3), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::filter_image(make_image(4, 4, 3, 4), ImageFilterType::Sobel3Dx), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::filter_image(Image{}, ImageFilterType::Gaussian3), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::downsample_image(make_image(4, 4, 1, 1)), o3d::InvalidArgument);
    Image broken = make_image(4, 4, 1, 4);
    broken.data.resize(10);  // data not matching the size
    EXPECT_THROW(o3d::geometry::filter_image(broken, ImageFilterType::Gaussian3), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::flip_vertical(broken), o3d::InvalidArgument);
    // A 1-pixel image is fine: every tap replicates the pixel.
    Image one = make_image(1, 1, 1, 4);
    *one.pixel<float>(0, 0) = 3.0f;
    EXPECT_EQ(at(o3d::geometry::filter_image(one, ImageFilterType::Gaussian7), 0, 0), 3.0f);
    EXPECT_EQ(at(o3d::geometry::filter_image(one, ImageFilterType::Sobel3Dy), 0, 0), 0.0f);
}

TEST(imageOps, SameBitsForAnyThreadCount) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> d(0.0f, 4.0f);
    Image im = make_image(640, 480, 1, 4);
    for (int v = 0; v < 480; ++v)
        for (int u = 0; u < 640; ++u) *im.pixel<float>(u, v) = d(rng);
    for (ImageFilterType t : kAllFilters) {
        o3d::utility::set_default_num_threads(1);
        const Image serial = o3d::geometry::filter_image(im, t);
        o3d::utility::set_default_num_threads(4);
        const Image parallel = o3d::geometry::filter_image(im, t);
        o3d::utility::set_default_num_threads(0);
        ASSERT_EQ(serial.data, parallel.data);
    }
}

TEST(imageOps, DownsampleMeansTwoByTwoBlocks) {
    // Each 2x2 block holds {b, b+1, b+2, b+3} with b = 10 * block index: the mean is b + 1.5.
    Image im = make_image(4, 4, 1, 4);
    for (int v = 0; v < 4; ++v)
        for (int u = 0; u < 4; ++u) {
            const int block = (v / 2) * 2 + u / 2;
            *im.pixel<float>(u, v) = float(10 * block + (v % 2) * 2 + u % 2);
        }
    const Image half = o3d::geometry::downsample_image(im);
    ASSERT_EQ(half.width, 2);
    ASSERT_EQ(half.height, 2);
    EXPECT_EQ(at(half, 0, 0), 1.5f);
    EXPECT_EQ(at(half, 1, 0), 11.5f);
    EXPECT_EQ(at(half, 0, 1), 21.5f);
    EXPECT_EQ(at(half, 1, 1), 31.5f);
    // Odd sizes keep floor(size / 2): Open3D's create_pyramid on arange(35) as 5 rows x 7 columns gives
    // [[4, 6, 8], [18, 20, 22]] (record_image.py).
    const Image odd = o3d::geometry::downsample_image(float_image(7, 5, [](int u, int v) { return float(v * 7 + u); }));
    ASSERT_EQ(odd.width, 3);
    ASSERT_EQ(odd.height, 2);
    const float expected[2][3] = {{4, 6, 8}, {18, 20, 22}};
    for (int v = 0; v < 2; ++v)
        for (int u = 0; u < 3; ++u) EXPECT_EQ(at(odd, u, v), expected[v][u]);
    EXPECT_THROW(o3d::geometry::downsample_image(make_image(1, 8, 1, 4)), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::downsample_image(make_image(8, 1, 1, 4)), o3d::InvalidArgument);
}

TEST(imageOps, Flips) {
    // 3 x 2 RGB, 8-bit: pixel (u, v) = (u, v, 7).
    Image rgb = make_image(3, 2, 3, 1);
    for (int v = 0; v < 2; ++v)
        for (int u = 0; u < 3; ++u) {
            uint8_t* p = rgb.pixel<uint8_t>(u, v);
            p[0] = uint8_t(u), p[1] = uint8_t(v), p[2] = 7;
        }
    const Image fv = o3d::geometry::flip_vertical(rgb);
    const Image fh = o3d::geometry::flip_horizontal(rgb);
    for (int v = 0; v < 2; ++v)
        for (int u = 0; u < 3; ++u) {
            EXPECT_EQ(fv.pixel<uint8_t>(u, v)[0], u);
            EXPECT_EQ(fv.pixel<uint8_t>(u, v)[1], 1 - v);
            EXPECT_EQ(fh.pixel<uint8_t>(u, v)[0], 2 - u);
            EXPECT_EQ(fh.pixel<uint8_t>(u, v)[1], v);
            EXPECT_EQ(fh.pixel<uint8_t>(u, v)[2], 7);
        }
    // Every format, odd sizes: flipping twice is the identity, once is not.
    std::mt19937 rng(5);
    for (int channels : {1, 3, 4})
        for (int bytes : {1, 2, 4}) {
            Image im = make_image(5, 3, channels, bytes);
            for (uint8_t& b : im.data) b = uint8_t(rng());
            EXPECT_EQ(o3d::geometry::flip_vertical(o3d::geometry::flip_vertical(im)).data, im.data);
            EXPECT_EQ(o3d::geometry::flip_horizontal(o3d::geometry::flip_horizontal(im)).data, im.data);
            EXPECT_NE(o3d::geometry::flip_horizontal(im).data, im.data);
            const Image h = o3d::geometry::flip_horizontal(im);
            const size_t px = size_t(channels) * size_t(bytes);
            EXPECT_EQ(std::memcmp(h.pixel<uint8_t>(4, 2), im.pixel<uint8_t>(0, 2), px), 0);
        }
}

TEST(imageOps, CreateFloatImage) {
    Image gray8 = make_image(2, 1, 1, 1);
    gray8.data = {0, 51};
    Image f = o3d::geometry::create_float_image(gray8, ImageConvertType::Weighted);
    EXPECT_EQ(f.num_channels, 1);
    EXPECT_EQ(f.bytes_per_channel, 4);
    EXPECT_EQ(at(f, 0, 0), 0.0f);
    EXPECT_EQ(at(f, 1, 0), 51.0f / 255.0f);

    Image gray16 = make_image(1, 1, 1, 2);
    *gray16.pixel<uint16_t>(0, 0) = 4321;
    EXPECT_EQ(at(o3d::geometry::create_float_image(gray16, ImageConvertType::Equal), 0, 0), 4321.0f);

    for (int channels : {3, 4}) {
        Image rgb = make_image(1, 1, channels, 1);
        uint8_t* p = rgb.pixel<uint8_t>(0, 0);
        p[0] = 30, p[1] = 60, p[2] = 90;
        if (channels == 4) p[3] = 255;  // alpha does not count
        EXPECT_FLOAT_EQ(at(o3d::geometry::create_float_image(rgb, ImageConvertType::Equal), 0, 0), 60.0f / 255.0f);
        EXPECT_FLOAT_EQ(at(o3d::geometry::create_float_image(rgb, ImageConvertType::Weighted), 0, 0),
                        (0.299f * 30 + 0.587f * 60 + 0.114f * 90) / 255.0f);
        Image rgb16 = make_image(1, 1, channels, 2);
        uint16_t* q = rgb16.pixel<uint16_t>(0, 0);
        q[0] = 1000, q[1] = 2000, q[2] = 6000;
        EXPECT_FLOAT_EQ(at(o3d::geometry::create_float_image(rgb16, ImageConvertType::Equal), 0, 0), 3000.0f);
        Image rgbf = make_image(1, 1, channels, 4);
        float* r = rgbf.pixel<float>(0, 0);
        r[0] = 1.0f, r[1] = 0.0f, r[2] = 0.0f;
        EXPECT_FLOAT_EQ(at(o3d::geometry::create_float_image(rgbf, ImageConvertType::Weighted), 0, 0), 0.299f);
    }
    EXPECT_THROW(o3d::geometry::create_float_image(Image{}, ImageConvertType::Equal), o3d::InvalidArgument);
}

TEST(imageOps, ConvertDepthToFloat) {
    // Open3D 0.20 (record_image.py), depth_scale 1000, depth_trunc 3: depths at or beyond 3 m become 0.
    const uint16_t raw[8] = {0, 1, 2999, 3000, 3001, 65535, 1234, 777};
    const float expected[8] = {0.0f, 0.00100000005f, 2.99900007f, 0.0f, 0.0f, 0.0f, 1.23399997f, 0.77700001f};
    Image depth = make_image(8, 1, 1, 2);
    std::memcpy(depth.data.data(), raw, sizeof raw);
    const Image m = o3d::geometry::convert_depth_to_float(depth, 1000.0, 3.0);
    for (int u = 0; u < 8; ++u) EXPECT_EQ(at(m, u, 0), expected[u]) << u;
    // An infinite truncation keeps everything.
    EXPECT_EQ(at(o3d::geometry::convert_depth_to_float(depth, 1000.0, INFINITY), 5, 0), 65.535f);

    // Float depth: non-finite values are invalid depths (0).
    const float inf = std::numeric_limits<float>::infinity();
    const float values[5] = {2.0f, std::nanf(""), inf, -inf, 8.0f};
    Image fd = make_image(5, 1, 1, 4);
    std::memcpy(fd.data.data(), values, sizeof values);
    const Image fm = o3d::geometry::convert_depth_to_float(fd, 2.0, 3.5);
    const float fexp[5] = {1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
    for (int u = 0; u < 5; ++u) EXPECT_EQ(at(fm, u, 0), fexp[u]) << u;
    // The input is unchanged.
    EXPECT_EQ(at(fd, 0, 0), 2.0f);

    EXPECT_THROW(o3d::geometry::convert_depth_to_float(depth, 0.0, 3.0), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::convert_depth_to_float(depth, -1.0, 3.0), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::convert_depth_to_float(depth, NAN, 3.0), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::convert_depth_to_float(depth, INFINITY, 3.0), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::convert_depth_to_float(depth, 1000.0, NAN), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::convert_depth_to_float(make_image(2, 2, 1, 1), 1000.0, 3.0), o3d::InvalidArgument);
    EXPECT_THROW(o3d::geometry::convert_depth_to_float(make_image(2, 2, 3, 2), 1000.0, 3.0), o3d::InvalidArgument);
}

// ---- Open3D 0.20 on open3d/RGBD frame 0 (tools/reference/record_image.py) ----

struct Pixel {
    int u, v;
};
constexpr Pixel kPixels[8] = {{0, 0}, {639, 0}, {0, 479}, {639, 479}, {320, 240}, {100, 200}, {1, 1}, {600, 30}};

struct FilterReference {
    ImageFilterType type;
    float values[8];
    double sum;
};

void expect_reference(const Image& im, const float (&values)[8], double sum, const char* what) {
    ASSERT_EQ(im.width, 640) << what;
    ASSERT_EQ(im.height, 480) << what;
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(at(im, kPixels[i].u, kPixels[i].v), values[i])
            << what << " at " << kPixels[i].u << "," << kPixels[i].v;
    double s = 0.0;
    for (int v = 0; v < im.height; ++v)
        for (int u = 0; u < im.width; ++u) s += double(at(im, u, v));
    EXPECT_NEAR(s, sum, 1e-9 * std::max(1.0, std::abs(sum))) << what;
}

TEST(imageOpsReference, DepthFrame) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/RGBD/depth/00000.png");
    const Image depth = o3d::io::read_image(path);
    const Image m = o3d::geometry::convert_depth_to_float(depth, 1000.0, 3.0);
    expect_reference(m, {0, 0, 0, 0, 2.19499993f, 1.37699997f, 0, 1.87300003f}, 479199.33029168844, "depth metres");
    const FilterReference refs[] = {
        {ImageFilterType::Gaussian3, {0, 0, 0, 0, 2.19924998f, 1.37393749f, 0, 1.87549996f}, 479199.3305182494},
        {ImageFilterType::Gaussian5, {0, 0, 0, 0, 2.19924998f, 1.37382817f, 0, 1.87579691f}, 479199.33010772546},
        {ImageFilterType::Gaussian7, {0, 0, 0, 0, 2.1990757f, 1.37385213f, 0, 1.8764503f}, 479199.33004911925},
        {ImageFilterType::Sobel3Dx,
         {0, 0, 0, 0, -0.0679998398f, -0.0209999084f, 0, -0.0880000591f},
         5.519390106201172e-05},
        {ImageFilterType::Sobel3Dy, {0, 0, 0, 0, 0, -0.00699996948f, 0, -0.0360002518f}, 0.0},
    };
    for (const FilterReference& r : refs)
        expect_reference(o3d::geometry::filter_image(m, r.type), r.values, r.sum, "depth filter");
    const Image half = o3d::geometry::downsample_image(m);
    ASSERT_EQ(half.width, 320);
    ASSERT_EQ(half.height, 240);
    EXPECT_EQ(at(half, 160, 120), 2.19499993f);
    EXPECT_EQ(at(half, 50, 100), 1.37175f);
    double s = 0.0;
    for (float x : std::vector<float>(reinterpret_cast<const float*>(half.data.data()),
                                      reinterpret_cast<const float*>(half.data.data()) + 320 * 240))
        s += x;
    EXPECT_NEAR(s, 119799.83272725344, 1e-6);
}

TEST(imageOpsReference, ColorFrameIntensity) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/RGBD/color/00000.jpg");
    const Image color = o3d::io::read_image(path);
    const Image gray = o3d::geometry::create_float_image(color, ImageConvertType::Weighted);
    expect_reference(gray,
                     {0.851631403f, 0.690462768f, 0.640341163f, 0.384239197f, 1.0f, 0.787388206f, 0.851631403f,
                      0.716462731f},
                     236960.86209215224, "intensity");
    const FilterReference refs[] = {
        {ImageFilterType::Gaussian3,
         {0.851631403f, 0.689482391f, 0.6379022f, 0.378601968f, 0.999568403f, 0.793025494f, 0.851631403f, 0.714747071f},
         236960.8621260263},
        {ImageFilterType::Gaussian5,
         {0.851631403f, 0.688762367f, 0.641773522f, 0.3762528f, 0.999468446f, 0.793010116f, 0.851631403f, 0.712978959f},
         236960.83655267954},
        {ImageFilterType::Gaussian7,
         {0.851631403f, 0.687817395f, 0.648569286f, 0.374422252f, 0.999018967f, 0.791996241f, 0.851596117f,
          0.711209118f},
         236960.77998229116},
        {ImageFilterType::Sobel3Dx,
         {0, 0.0156862736f, -0.0362314582f, 0.0117647052f, 0.00690597296f, -0.0745097995f, 0, -0.00392132998f},
         -1014.8356784768403},
        {ImageFilterType::Sobel3Dy,
         {0, 0, -0.00803542137f, 0.0745097399f, -0.00230193138f, -0.00392150879f, 0, 0.0117647648f},
         -824.0772594511509},
    };
    for (const FilterReference& r : refs)
        expect_reference(o3d::geometry::filter_image(gray, r.type), r.values, r.sum, "intensity filter");
    const Image half = o3d::geometry::downsample_image(gray);
    EXPECT_EQ(at(half, 0, 0), 0.851631403f);
    EXPECT_EQ(at(half, 319, 239), 0.373454899f);
    EXPECT_EQ(at(half, 160, 120), 1.0f);
    EXPECT_EQ(at(half, 50, 100), 0.787388206f);
}

}  // namespace
