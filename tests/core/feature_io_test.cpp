// SPDX-License-Identifier: MIT
// Open3D's binary feature files: the shared Feature/cloud_bin_{0,1}.fpfh.bin read with recorded values,
// file and memory round trips (UTF-8 paths too), and every way a file can lie about its size.
#include "o3d/io/feature_io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "o3d/utility/error.h"
#include "test_data.h"

using o3d::registration::Feature;

namespace {

// tools/reference/record_fpfh.py: stored0_column_0, stored1_column_3457 (Open3D 0.20 read_feature).
constexpr std::array<double, 33> kStored0Column0 = {
    6.711965560913086, 2.783480167388916, 4.1213698387146, 8.917947769165039, 14.481118202209473, 32.13579177856445,
    7.065032005310059, 12.435261726379395, 1.4537322521209717, 2.373115062713623, 7.521194934844971,
    12.972970008850098, 10.049040794372559, 5.605851650238037, 6.487475395202637, 9.624201774597168,
    18.492616653442383, 12.744392395019531, 8.532476425170898, 3.8701062202453613, 5.76608943939209,
    5.8547844886779785, 8.182937622070312, 7.382133483886719, 5.317745685577393, 7.258790493011475,
    6.279788970947266, 11.157909393310547, 19.702133178710938, 8.078969955444336, 9.228659629821777,
    9.761730194091797, 7.649205207824707
};
constexpr std::array<double, 33> kStored1Column3457 = {
    4.57197380065918, 3.088332176208496, 10.728137969970703, 10.123797416687012, 14.70786190032959,
    40.879920959472656, 4.696052074432373, 2.6089210510253906, 2.5119082927703857, 2.260016679763794,
    3.8230645656585693, 9.481978416442871, 6.484823703765869, 5.426222324371338, 7.003264427185059,
    10.410881996154785, 26.70120620727539, 9.712754249572754, 7.77863883972168, 5.676891326904297, 4.559263229370117,
    6.764081001281738, 7.030186653137207, 6.866293907165527, 3.864675998687744, 3.05531644821167, 5.138452053070068,
    12.697052955627441, 7.479024410247803, 7.49285888671875, 9.824458122253418, 19.91148567199707, 16.640207290649414
};

std::filesystem::path temp_dir() {
    const auto dir = std::filesystem::temp_directory_path() / ("o3d_feature_io_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return dir;
}

Feature sample() {
    Feature f;
    f.data.resize(4, 3);
    for (int i = 0; i < 12; ++i) f.data(i % 4, i / 4) = 0.25 * i - 1.0 + 1e-9 * i * i;
    return f;
}

std::vector<uint8_t> file_bytes(int32_t dim, int32_t num, size_t values) {
    std::vector<uint8_t> b(8 + 8 * values);
    std::memcpy(b.data(), &dim, 4);
    std::memcpy(b.data() + 4, &num, 4);
    for (size_t i = 0; i < values; ++i) {
        const double v = static_cast<double>(i);
        std::memcpy(b.data() + 8 + 8 * i, &v, 8);
    }
    return b;
}

Feature parse(const std::vector<uint8_t>& b) { return o3d::io::read_feature_from_memory(b.data(), b.size()); }

}  // namespace

TEST(FeatureIo, ReadsTheStoredFeatures) {
    O3D_TEST_DATA_OR_SKIP(path0, "open3d/Feature/cloud_bin_0.fpfh.bin");
    O3D_TEST_DATA_OR_SKIP(path1, "open3d/Feature/cloud_bin_1.fpfh.bin");
    const Feature f0 = o3d::io::read_feature(path0);
    const Feature f1 = o3d::io::read_feature(path1);
    ASSERT_EQ(f0.dimension(), 33u);
    ASSERT_EQ(f0.num(), 3903u);
    ASSERT_EQ(f1.dimension(), 33u);
    ASSERT_EQ(f1.num(), 3458u);
    for (int b = 0; b < 33; ++b) {
        EXPECT_EQ(f0.data(b, 0), kStored0Column0[b]) << b;
        EXPECT_EQ(f1.data(b, 3457), kStored1Column3457[b]) << b;
    }
    // record_fpfh.py: stored0_total = 1170899.9981996166; stored1_total = 1037399.998354264 (each
    // descriptor's three sub-histograms sum to 100, in float32 precision).
    EXPECT_NEAR(f0.data.sum(), 1170899.9981996166, 1e-6);
    EXPECT_NEAR(f1.data.sum(), 1037399.998354264, 1e-6);
}

TEST(FeatureIo, RoundTripsThroughFilesAndMemory) {
    const Feature f = sample();
    const auto bytes = o3d::io::write_feature_to_memory(f);
    ASSERT_EQ(bytes.size(), 8u + 12u * 8u);
    int32_t header[2];
    std::memcpy(header, bytes.data(), 8);
    EXPECT_EQ(header[0], 4);
    EXPECT_EQ(header[1], 3);
    double first_of_second;  // descriptor by descriptor: value 0 of descriptor 1 follows descriptor 0
    std::memcpy(&first_of_second, bytes.data() + 8 + 4 * 8, 8);
    EXPECT_EQ(first_of_second, f.data(0, 1));
    EXPECT_EQ(parse(bytes).data, f.data);

    const std::string path = (temp_dir() / "特徴_feature_ü.bin").string();
    o3d::io::write_feature(path, f);
    EXPECT_TRUE(std::filesystem::exists(std::filesystem::u8path(path)));
    EXPECT_EQ(o3d::io::read_feature(path).data, f.data);

    Feature empty;
    empty.data.resize(33, 0);
    const Feature back = parse(o3d::io::write_feature_to_memory(empty));
    EXPECT_EQ(back.dimension(), 33u);
    EXPECT_EQ(back.num(), 0u);
}

TEST(FeatureIo, RejectsMalformedData) {
    EXPECT_NO_THROW(parse(file_bytes(3, 2, 6)));
    EXPECT_THROW(parse({}), o3d::ParseError);                                  // no header
    EXPECT_THROW(parse({1, 0, 0, 0, 1}), o3d::ParseError);                     // half a header
    EXPECT_THROW(parse(file_bytes(3, 2, 5)), o3d::ParseError);                 // truncated
    auto cut = file_bytes(3, 2, 6);
    cut.pop_back();
    EXPECT_THROW(parse(cut), o3d::ParseError);                                 // a partial value
    EXPECT_THROW(parse(file_bytes(3, 2, 7)), o3d::ParseError);                 // trailing values
    EXPECT_THROW(parse(file_bytes(-3, 2, 6)), o3d::ParseError);                // negative dimension
    EXPECT_THROW(parse(file_bytes(3, -2, 6)), o3d::ParseError);                // negative count
    const int32_t big = std::numeric_limits<int32_t>::max();
    EXPECT_THROW(parse(file_bytes(big, big, 4)), o3d::ParseError);             // 2^62 values claimed
    auto nan = file_bytes(2, 2, 4);
    const double bad = std::numeric_limits<double>::quiet_NaN();
    std::memcpy(nan.data() + 8 + 8 * 3, &bad, 8);
    EXPECT_THROW(parse(nan), o3d::ParseError);
    try {
        parse(file_bytes(3, 2, 5));
    } catch (const o3d::ParseError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("<memory>: ", 0), 0u) << e.what();
    }
    EXPECT_THROW(o3d::io::read_feature_from_memory(nullptr, 8), o3d::InvalidArgument);
}

TEST(FeatureIo, FileErrors) {
    EXPECT_THROW(o3d::io::read_feature((temp_dir() / "missing.bin").string()), o3d::IoError);
    EXPECT_THROW(o3d::io::write_feature((temp_dir() / "no_such_dir" / "f.bin").string(), sample()), o3d::IoError);
    const auto path = temp_dir() / "truncated.bin";
    const auto bytes = file_bytes(33, 10, 100);
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    try {
        o3d::io::read_feature(path.string());
        FAIL() << "a truncated file was read";
    } catch (const o3d::ParseError& e) {
        EXPECT_NE(std::string(e.what()).find("truncated.bin"), std::string::npos) << e.what();
    }
    Feature nan = sample();
    nan.data(1, 1) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(o3d::io::write_feature_to_memory(nan), o3d::InvalidArgument);
}
