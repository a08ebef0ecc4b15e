// SPDX-License-Identifier: MIT
// Image through the wrapper: creation, views, conversions, filters, PNG/PGM/JPEG round trips, errors.
#include <cstdio>
#include <cstdlib>

#include "test_util.hpp"

using o3dpp::Image;

TEST(Image, NewImagesAreZeroedAndDescribed) {
    const Image img(3, 2, 3, 1);
    EXPECT_EQ(img.width(), 3);
    EXPECT_EQ(img.height(), 2);
    EXPECT_EQ(img.num_channels(), 3);
    EXPECT_EQ(img.bytes_per_channel(), 1);
    EXPECT_EQ(img.to_bytes(), std::vector<uint8_t>(18, 0));
    EXPECT_EQ(img.data().size(), 18u);
}

TEST(Image, BadShapesThrow) {
    EXPECT_O3D_ERROR(Image(0, 2, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Image(2, 2, 2, 1), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Image(2, 2, 1, 3), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Image::from_values<uint8_t>(2, 2, {1, 2, 3}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Image(4, 4, 1, 1).filter(o3dpp::ImageFilter::Gaussian3), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Image(4, 4, 1, 1).to_values<float>(), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Image, MutableViewCloneAndFlips) {
    auto img = Image::from_values<uint8_t>(2, 2, {1, 2, 3, 4});
    const auto copy = img.clone();
    img.data_mutable()[0] = 9;
    EXPECT_EQ(img.to_bytes(), (std::vector<uint8_t>{9, 2, 3, 4}));
    EXPECT_EQ(copy.to_bytes(), (std::vector<uint8_t>{1, 2, 3, 4}));
    EXPECT_EQ(copy.flip_vertical().to_bytes(), (std::vector<uint8_t>{3, 4, 1, 2}));
    EXPECT_EQ(copy.flip_horizontal().to_bytes(), (std::vector<uint8_t>{2, 1, 4, 3}));
}

TEST(Image, FloatConversions) {
    const auto red = Image::from_values<uint8_t>(1, 1, {255, 0, 0}, 3);
    EXPECT_NEAR(red.create_float_image().to_values<float>()[0], 0.299, 1e-6);
    EXPECT_NEAR(red.create_float_image(o3dpp::ImageConvert::Equal).to_values<float>()[0], 1.0 / 3.0, 1e-6);
    const auto depth = Image::from_values<uint16_t>(4, 1, {1000, 5000, 0, 2500});
    EXPECT_EQ(depth.convert_depth_to_float(1000.0, 3.0).to_values<float>(), (std::vector<float>{1, 0, 0, 2.5}));
}

TEST(Image, FiltersOnARamp) {
    // f(u, v) = u with replicated borders: unnormalised Sobel x gives 8 inside, 4 on the border
    // columns; the 3-tap Gaussian keeps the interior and gives 0.25 / 3.75 at the borders
    // (the same as Open3D 0.20's Image.filter on this ramp).
    std::vector<float> ramp;
    for (int v = 0; v < 4; ++v)
        for (int u = 0; u < 5; ++u) ramp.push_back(static_cast<float>(u));
    const auto img = Image::from_values<float>(5, 4, ramp);
    const auto dx = img.filter(o3dpp::ImageFilter::Sobel3Dx).to_values<float>();
    const auto g = img.filter(o3dpp::ImageFilter::Gaussian3).to_values<float>();
    for (int v = 0; v < 4; ++v) {
        EXPECT_EQ(std::vector<float>(dx.begin() + 5 * v, dx.begin() + 5 * v + 5), (std::vector<float>{4, 8, 8, 8, 4}));
        EXPECT_EQ(std::vector<float>(g.begin() + 5 * v, g.begin() + 5 * v + 5),
                  (std::vector<float>{0.25f, 1, 2, 3, 3.75f}));
    }
    for (float d : img.filter(o3dpp::ImageFilter::Sobel3Dy).to_values<float>()) EXPECT_EQ(d, 0.0f);
    for (auto f : {o3dpp::ImageFilter::Gaussian5, o3dpp::ImageFilter::Gaussian7})
        for (float x : Image::from_values<float>(8, 8, std::vector<float>(64, 2.5f)).filter(f).to_values<float>())
            EXPECT_NEAR(x, 2.5f, 1e-5);
    std::vector<float> seq(16);
    for (int i = 0; i < 16; ++i) seq[i] = static_cast<float>(i);
    const auto half = Image::from_values<float>(4, 4, seq).downsample();
    EXPECT_EQ(half.width(), 2);
    EXPECT_EQ(half.to_values<float>(), (std::vector<float>{2.5f, 4.5f, 10.5f, 12.5f}));
}

TEST(Image, LosslessRoundTripsInMemory) {
    std::vector<uint8_t> rgb(5 * 3 * 3);
    for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i * 37 % 251);
    const auto img = Image::from_values<uint8_t>(5, 3, rgb, 3);
    for (const char* fmt : {"png", "ppm"}) {
        const auto back = o3dpp::read_image_from_memory(o3dpp::write_image_to_memory(img, fmt).to_vector(), fmt);
        EXPECT_EQ(back.num_channels(), 3) << fmt;
        EXPECT_EQ(back.to_bytes(), rgb) << fmt;
    }
    const std::vector<uint16_t> depth{0, 1, 1000, 4095, 40000, 65535};
    const auto d = Image::from_values<uint16_t>(3, 2, depth);
    for (const char* fmt : {"png", "pgm"}) {
        const auto back = o3dpp::read_image_from_memory(o3dpp::write_image_to_memory(d, fmt).to_vector(), fmt);
        EXPECT_EQ(back.to_values<uint16_t>(), depth) << fmt;
    }
}

TEST(Image, JpegIsCloseAndFilesWork) {
    std::vector<uint8_t> gray(16 * 16);
    for (int i = 0; i < 256; ++i) gray[i] = static_cast<uint8_t>((i % 16) * 8 + (i / 16) * 4);
    const auto img = Image::from_values<uint8_t>(16, 16, gray);
    const auto high = o3dpp::write_image_to_memory(img, "jpg", 100);
    const auto low = o3dpp::write_image_to_memory(img, "jpg", 5);
    EXPECT_LT(low.size(), high.size());
    const auto back = o3dpp::read_image_from_memory(high.to_vector(), "jpg").to_bytes();
    ASSERT_EQ(back.size(), gray.size());
    for (std::size_t i = 0; i < gray.size(); ++i) EXPECT_LE(std::abs(back[i] - gray[i]), 4);

    const std::string path = o3dpp_test::tmp_path("image_test.png");
    o3dpp::write_image(path, img);
    EXPECT_EQ(o3dpp::read_image(path).to_bytes(), gray);
    std::remove(path.c_str());
    EXPECT_O3D_ERROR(o3dpp::read_image("/nonexistent/x.png"), O3D_ERROR_IO);
    EXPECT_THROW(o3dpp::write_image_to_memory(Image(2, 2, 1, 4), "png"), o3dpp::Error);
    EXPECT_THROW(o3dpp::read_image_from_memory(std::vector<uint8_t>{0x89, 'P', 'N', 'G', 1, 2}, "png"), o3dpp::Error);
}

TEST(Image, CreatePyramidHalvesEachLevelAndKeepsAConstant) {
    const auto img = Image::from_values<float>(8, 4, std::vector<float>(32, 0.5f));
    const std::vector<Image> levels = img.create_pyramid(3);
    ASSERT_EQ(levels.size(), 3u);
    EXPECT_EQ(levels[1].width(), 4);
    EXPECT_EQ(levels[2].width(), 2);
    EXPECT_EQ(levels[2].height(), 1);
    for (const Image& level : levels)
        for (float v : level.to_values<float>()) EXPECT_EQ(v, 0.5f);
    const auto ramp = Image::from_values<float>(4, 2, {0, 1, 2, 3, 0, 1, 2, 3});
    EXPECT_EQ(ramp.create_pyramid(2, false)[1].to_values<float>(), (std::vector<float>{0.5f, 2.5f}));
    EXPECT_O3D_ERROR(Image(4, 4, 1, 1).create_pyramid(2), O3D_ERROR_INVALID_ARGUMENT);
}
