// SPDX-License-Identifier: MIT
// RGB-D images: create_from_color_and_depth and the dataset readers (Redwood, TUM, SUN, NYU).
// Reference numbers: Open3D 0.20.0 (pip wheel), printed by tools/reference/record_rgbd.py (sections
// "dataset readers" and "SUN / NYU on raw samples"); the pixel list below is its PIXELS.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "o3d/geometry/image_ops.h"
#include "o3d/geometry/rgbd_dataset_formats.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/io/image_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace {

using namespace o3d::geometry;

float depth_at(const Image& depth, int u, int v) {
    float z;
    std::memcpy(&z, depth.pixel<uint8_t>(u, v), sizeof z);
    return z;
}

Image depth16(int width, int height, const std::vector<uint16_t>& values) {
    Image image = make_image(width, height, 1, 2);
    std::memcpy(image.data.data(), values.data(), values.size() * 2);
    return image;
}

Image rgb8(int width, int height) {
    Image image = make_image(width, height, 3, 1);
    for (size_t i = 0; i < image.data.size(); ++i) image.data[i] = static_cast<uint8_t>(37 * i + 11);
    return image;
}

TEST(rgbdImage, ConvertsDepthAndColor) {
    const Image depth = depth16(3, 2, {0, 1000, 2999, 3000, 65535, 1500});
    const Image color = rgb8(3, 2);
    const RGBDImage gray = create_rgbd_from_color_and_depth(color, depth);  // Open3D's defaults: 1000, 3 m
    ASSERT_EQ(gray.depth.num_channels, 1);
    ASSERT_EQ(gray.depth.bytes_per_channel, 4);
    const float expected[] = {0.0f, 1.0f, 2999.0f / 1000.0f, 0.0f, 0.0f, 1.5f};  // 3000 mm = 3 m is truncated
    for (int i = 0; i < 6; ++i) EXPECT_EQ(depth_at(gray.depth, i % 3, i / 3), expected[i]) << i;
    ASSERT_EQ(gray.color.num_channels, 1);
    ASSERT_EQ(gray.color.bytes_per_channel, 4);
    for (int i = 0; i < 6; ++i) {
        const uint8_t* p = color.pixel<uint8_t>(i % 3, i / 3);
        EXPECT_NEAR(depth_at(gray.color, i % 3, i / 3), (0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 255.0, 1e-6);
    }

    RGBDOptions keep;
    keep.convert_rgb_to_intensity = false;
    keep.depth_scale = 500.0;
    keep.depth_trunc = 10.0;
    const RGBDImage rgb = create_rgbd_from_color_and_depth(color, depth, keep);
    EXPECT_EQ(rgb.color.num_channels, 3);
    EXPECT_EQ(rgb.color.bytes_per_channel, 1);
    EXPECT_EQ(rgb.color.data, color.data);
    EXPECT_EQ(depth_at(rgb.depth, 0, 1), 6.0f);
    EXPECT_EQ(depth_at(rgb.depth, 1, 1), 0.0f);  // 131 m > 10 m
}

TEST(rgbdImage, RejectsBadInput) {
    const Image depth = depth16(3, 2, {1, 2, 3, 4, 5, 6});
    EXPECT_THROW(create_rgbd_from_color_and_depth(rgb8(2, 3), depth), o3d::InvalidArgument);   // size mismatch
    EXPECT_THROW(create_rgbd_from_color_and_depth(rgb8(3, 2), Image{}), o3d::InvalidArgument); // empty depth
    EXPECT_THROW(create_rgbd_from_color_and_depth(make_image(3, 2, 3, 2), depth), o3d::InvalidArgument);
    EXPECT_THROW(create_rgbd_from_color_and_depth(rgb8(3, 2), make_image(3, 2, 3, 2)), o3d::InvalidArgument);
    RGBDOptions bad;
    bad.depth_scale = 0.0;
    EXPECT_THROW(create_rgbd_from_color_and_depth(rgb8(3, 2), depth, bad), o3d::InvalidArgument);
    bad.depth_scale = 1000.0;
    bad.depth_trunc = NAN;
    EXPECT_THROW(create_rgbd_from_color_and_depth(rgb8(3, 2), depth, bad), o3d::InvalidArgument);
    Image lying = rgb8(3, 2);
    lying.data.resize(5);
    EXPECT_THROW(create_rgbd_from_color_and_depth(lying, depth), o3d::InvalidArgument);
    // The dataset readers take raw uint16 depth only.
    EXPECT_THROW(create_rgbd_from_dataset_format(RGBDDatasetFormat::TUM, rgb8(3, 2), make_image(3, 2, 1, 4), true),
                 o3d::InvalidArgument);
    EXPECT_THROW(create_rgbd_from_dataset_format(static_cast<RGBDDatasetFormat>(9), rgb8(3, 2), depth, true),
                 o3d::InvalidArgument);
    EXPECT_THROW(create_rgbd_from_dataset_format(RGBDDatasetFormat::NYU, rgb8(2, 3), depth, true),
                 o3d::InvalidArgument);
}

// Open3D: record_rgbd.py "SUN / NYU on raw samples" (RAW_SAMPLES).
const std::vector<uint16_t> kRawSamples = {0,      1,      8,      1000,   8000,   55992,  56000,  0x0400, 0x0401,
                                           0x4400, 0x1204, 0x1904, 0x1a04, 0x0444, 0x8000, 0xff03, 0xffff};
const std::vector<double> kSunRawDepth = {0.0, 0.0, 0.0010000000474974513, 0.125, 1.0, 6.999000072479248, 0.0,
                                          0.12800000607967377, 0.0, 2.1760001182556152, 0.0, 0.0, 0.0, 0.0,
                                          4.0960001945495605, 0.0, 0.0};
const std::vector<double> kNyuRawDepth = {0.32199999690055847, 0.41999998688697815, 0.0, 0.0, 0.0, 0.0, 0.0,
                                          0.3230000138282776, 0.421999990940094, 0.34299999475479126,
                                          6.955999851226807, 0.0, 0.0, 0.0, 0.36399999260902405, 5.054999828338623,
                                          0.0};

TEST(rgbdDatasets, SunAndNyuDecodeRawSamplesAsOpen3D) {
    const int n = static_cast<int>(kRawSamples.size());
    const Image depth = depth16(n, 1, kRawSamples);
    const Image before = depth;
    const Image color = rgb8(n, 1);
    const RGBDImage sun = create_rgbd_from_dataset_format(RGBDDatasetFormat::SUN, color, depth, true);
    const RGBDImage nyu = create_rgbd_from_dataset_format(RGBDDatasetFormat::NYU, color, depth, false);
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(depth_at(sun.depth, i, 0), float(kSunRawDepth[size_t(i)])) << "SUN raw " << kRawSamples[size_t(i)];
        EXPECT_EQ(depth_at(nyu.depth, i, 0), float(kNyuRawDepth[size_t(i)])) << "NYU raw " << kRawSamples[size_t(i)];
    }
    EXPECT_EQ(depth.data, before.data) << "the caller's depth image was modified";
    EXPECT_EQ(nyu.color.data, color.data);
}

TEST(rgbdDatasets, RedwoodAndTumScales) {
    const Image depth = depth16(4, 1, {3999, 4000, 19995, 20000});
    const Image color = rgb8(4, 1);
    const RGBDImage redwood = create_rgbd_from_dataset_format(RGBDDatasetFormat::Redwood, color, depth, true);
    EXPECT_EQ(depth_at(redwood.depth, 0, 0), 3.999f);
    EXPECT_EQ(depth_at(redwood.depth, 1, 0), 0.0f);  // truncated at 4 m
    const RGBDImage tum = create_rgbd_from_dataset_format(RGBDDatasetFormat::TUM, color, depth, true);
    EXPECT_EQ(depth_at(tum.depth, 0, 0), 3999.0f / 5000.0f);
    EXPECT_EQ(depth_at(tum.depth, 2, 0), 19995.0f / 5000.0f);
    EXPECT_EQ(depth_at(tum.depth, 3, 0), 0.0f);
}

// record_rgbd.py PIXELS as (u, v).
const int kPixels[6][2] = {{320, 240}, {100, 50}, {600, 400}, {10, 470}, {400, 100}, {213, 377}};

struct DatasetReference {
    double depth[6];
    double intensity[6];
    double depth_sum;
    size_t nonzero;
};

void expect_matches(const RGBDImage& rgbd, const DatasetReference& ref) {
    ASSERT_EQ(rgbd.depth.width, 640);
    ASSERT_EQ(rgbd.depth.height, 480);
    ASSERT_EQ(rgbd.color.bytes_per_channel, 4);
    for (int i = 0; i < 6; ++i) {
        const int u = kPixels[i][0], v = kPixels[i][1];
        EXPECT_EQ(depth_at(rgbd.depth, u, v), float(ref.depth[i])) << "depth at (" << u << "," << v << ")";
        EXPECT_NEAR(depth_at(rgbd.color, u, v), ref.intensity[i], 1e-6) << "intensity at (" << u << "," << v << ")";
    }
    double sum = 0;
    size_t nonzero = 0;
    for (int v = 0; v < 480; ++v)
        for (int u = 0; u < 640; ++u) {
            const float z = depth_at(rgbd.depth, u, v);
            sum += z;
            nonzero += z > 0;
        }
    EXPECT_EQ(nonzero, ref.nonzero);
    EXPECT_NEAR(sum, ref.depth_sum, 1e-9 * ref.depth_sum);
}

TEST(rgbdDatasets, TumSample) {
    O3D_TEST_DATA_OR_SKIP(color, "open3d/RGBD/other_formats/TUM_color.png");
    O3D_TEST_DATA_OR_SKIP(depth, "open3d/RGBD/other_formats/TUM_depth.png");
    const DatasetReference ref = {
        {2.184000015258789, 2.1029999256134033, 2.365000009536743, 2.115999937057495, 2.6589999198913574,
         2.4670000076293945},
        {0.9873411655426025, 0.4024352729320526, 0.5134392380714417, 0.4679725468158722, 0.39204317331314087,
         0.34589022397994995},
        585524.5596835613,
        244280};
    expect_matches(create_rgbd_from_dataset_format(RGBDDatasetFormat::TUM, o3d::io::read_image(color),
                                                   o3d::io::read_image(depth), true),
                   ref);
}

TEST(rgbdDatasets, SunSample) {
    O3D_TEST_DATA_OR_SKIP(color, "open3d/RGBD/other_formats/SUN_color.jpg");
    O3D_TEST_DATA_OR_SKIP(depth, "open3d/RGBD/other_formats/SUN_depth.png");
    const DatasetReference ref = {
        {0.0, 2.2709999084472656, 0.0, 1.2970000505447388, 2.9579999446868896, 3.5390000343322754},
        {0.28755685687065125, 0.14239215850830078, 0.24428626894950867, 0.39258432388305664, 0.5086078643798828,
         0.2436862736940384},
        679479.086156249,
        236957};
    const Image raw = o3d::io::read_image(depth);
    const Image before = raw;
    expect_matches(create_rgbd_from_dataset_format(RGBDDatasetFormat::SUN, o3d::io::read_image(color), raw, true), ref);
    EXPECT_EQ(raw.data, before.data);
}

TEST(rgbdDatasets, NyuSample) {
    // Open3D's tutorial reads the PGM as big-endian 16-bit samples (its read_nyu_pgm), as a PGM reader does.
    O3D_TEST_DATA_OR_SKIP(color, "open3d/RGBD/other_formats/NYU_color.ppm");
    O3D_TEST_DATA_OR_SKIP(depth, "open3d/RGBD/other_formats/NYU_depth.pgm");
    const DatasetReference ref = {
        {3.0420000553131104, 4.1570000648498535, 2.7339999675750732, 2.3499999046325684, 3.23799991607666,
         3.178999900817871},
        {0.39978039264678955, 0.19072158634662628, 0.32692158222198486, 0.3918784260749817, 0.1887921541929245,
         0.5744470953941345},
        1017788.1883063316,
        285001};
    const Image raw = o3d::io::read_image(depth);
    ASSERT_EQ(raw.bytes_per_channel, 2);
    const Image before = raw;
    expect_matches(create_rgbd_from_dataset_format(RGBDDatasetFormat::NYU, o3d::io::read_image(color), raw, true), ref);
    EXPECT_EQ(raw.data, before.data);
}

TEST(rgbdDatasets, RedwoodSampleAndDefaults) {
    O3D_TEST_DATA_OR_SKIP(color_path, "open3d/RGBD/color/00000.jpg");
    O3D_TEST_DATA_OR_SKIP(depth_path, "open3d/RGBD/depth/00000.png");
    const DatasetReference ref = {
        {2.194999933242798, 1.3639999628067017, 1.3309999704360962, 0.0, 2.0969998836517334, 1.5609999895095825},
        {1.0, 1.0, 0.5171999931335449, 0.8458941578865051, 0.7806156277656555, 0.7014470100402832},
        479199.33029168844,
        267129};
    const Image color = o3d::io::read_image(color_path);
    const Image depth = o3d::io::read_image(depth_path);
    expect_matches(create_rgbd_from_dataset_format(RGBDDatasetFormat::Redwood, color, depth, true), ref);
    expect_matches(create_rgbd_from_color_and_depth(color, depth), ref);  // no depth in [3 m, 4 m) here
}

}  // namespace
