// SPDX-License-Identifier: MIT
// Image files: every PNG/JPEG of the shared RGB-D data read as Open3D 0.20 reads it (sizes, formats and
// byte sums recorded by tools/reference/record_image.py), round trips of every format and bit depth
// through memory and files, and malformed, truncated and lying files rejected with a clear error.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "o3d/geometry/image_ops.h"
#include "o3d/io/image_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace {

using o3d::geometry::Image;
using o3d::geometry::make_image;
using o3d::io::read_image_from_memory;
using o3d::io::write_image_to_memory;

std::vector<uint8_t> bytes_of(const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); }

Image read_mem(const std::vector<uint8_t>& bytes, const std::string& format) {
    return read_image_from_memory(bytes.data(), bytes.size(), format);
}

/// "" when reading succeeds, else the ParseError's message; any other exception fails the test.
std::string parse_error_of(const std::vector<uint8_t>& bytes, const std::string& format) {
    try {
        read_mem(bytes, format);
    } catch (const o3d::ParseError& e) {
        return e.what();
    }
    return "";
}

Image random_image(int w, int h, int channels, int bytes, uint32_t seed) {
    Image im = make_image(w, h, channels, bytes);
    std::mt19937 rng(seed);
    for (uint8_t& b : im.data) b = uint8_t(rng());
    return im;
}

/// A smooth RGB or gray image (JPEG's friend): a diagonal gradient, below 256 for sizes up to 96 x 64.
Image smooth_image(int w, int h, int channels) {
    Image im = make_image(w, h, channels, 1);
    for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u)
            for (int c = 0; c < channels; ++c) im.pixel<uint8_t>(u, v)[c] = uint8_t(u + v + c * 40);
    return im;
}

void expect_same(const Image& a, const Image& b, const std::string& what) {
    EXPECT_EQ(a.width, b.width) << what;
    EXPECT_EQ(a.height, b.height) << what;
    EXPECT_EQ(a.num_channels, b.num_channels) << what;
    EXPECT_EQ(a.bytes_per_channel, b.bytes_per_channel) << what;
    EXPECT_TRUE(a.data == b.data) << what;
}

// ---- The shared data, as Open3D 0.20 reads it ----

struct DataImage {
    const char* path;
    int width, height, channels, bytes;
    int64_t sum;  // sum of every sample
};

constexpr DataImage kDataImages[] = {
    {"color/00000.jpg", 640, 480, 3, 1, 179914237},
    {"color/00001.jpg", 640, 480, 3, 1, 179476677},
    {"color/00002.jpg", 640, 480, 3, 1, 178940705},
    {"color/00003.jpg", 640, 480, 3, 1, 178388746},
    {"color/00004.jpg", 640, 480, 3, 1, 177794026},
    {"depth/00000.png", 640, 480, 1, 2, 479199333},
    {"depth/00001.png", 640, 480, 1, 2, 481105956},
    {"depth/00002.png", 640, 480, 1, 2, 483024348},
    {"depth/00003.png", 640, 480, 1, 2, 484862011},
    {"depth/00004.png", 640, 480, 1, 2, 486794419},
    {"other_formats/SUN_color.jpg", 640, 480, 3, 1, 70797444},
    {"other_formats/SUN_depth.png", 640, 480, 1, 2, 5891375813},
    {"other_formats/TUM_color.png", 640, 480, 3, 1, 101558687},
    {"other_formats/TUM_depth.png", 640, 480, 1, 2, 3074716315},
};

int64_t sample_sum(const Image& im) {
    int64_t s = 0;
    if (im.bytes_per_channel == 1)
        for (uint8_t b : im.data) s += b;
    else
        for (size_t i = 0; i < im.data.size() / 2; ++i) s += reinterpret_cast<const uint16_t*>(im.data.data())[i];
    return s;
}

TEST(imageIoData, EveryRgbdImageAsOpen3dReadsIt) {
    for (const DataImage& d : kDataImages) {
        O3D_TEST_DATA_OR_SKIP(path, std::string("open3d/RGBD/") + d.path);
        const Image im = o3d::io::read_image(path);
        EXPECT_EQ(im.width, d.width) << d.path;
        EXPECT_EQ(im.height, d.height) << d.path;
        EXPECT_EQ(im.num_channels, d.channels) << d.path;
        EXPECT_EQ(im.bytes_per_channel, d.bytes) << d.path;
        EXPECT_EQ(sample_sum(im), d.sum) << d.path;
    }
}

TEST(imageIoData, PixelsOfFrameZero) {
    O3D_TEST_DATA_OR_SKIP(depth_path, "open3d/RGBD/depth/00000.png");
    O3D_TEST_DATA_OR_SKIP(color_path, "open3d/RGBD/color/00000.jpg");
    // record_image.py: depth (16-bit, big-endian in the file) and colour at (320, 240), (100, 200), (600, 30).
    const Image depth = o3d::io::read_image(depth_path);
    EXPECT_EQ(*depth.pixel<uint16_t>(320, 240), 2195);
    EXPECT_EQ(*depth.pixel<uint16_t>(100, 200), 1377);
    EXPECT_EQ(*depth.pixel<uint16_t>(600, 30), 1873);
    const Image color = o3d::io::read_image(color_path, "jpeg");
    const uint8_t* p = color.pixel<uint8_t>(100, 200);
    EXPECT_EQ(p[0], 212);
    EXPECT_EQ(p[1], 196);
    EXPECT_EQ(p[2], 196);
    p = color.pixel<uint8_t>(639, 479);
    EXPECT_EQ(p[0], 132);
    EXPECT_EQ(p[1], 89);
    EXPECT_EQ(p[2], 55);
}

TEST(imageIoData, NetpbmFiles) {
    O3D_TEST_DATA_OR_SKIP(pgm, "open3d/RGBD/other_formats/NYU_depth.pgm");
    O3D_TEST_DATA_OR_SKIP(ppm, "open3d/RGBD/other_formats/NYU_color.ppm");
    // NYU_depth.pgm is "P5 640 480 65535" then big-endian samples ff 07 ...; NYU_color.ppm "P6 640 480 255",
    // first pixel dc f8 eb.
    const Image depth = o3d::io::read_image(pgm);
    EXPECT_EQ(depth.width, 640);
    EXPECT_EQ(depth.height, 480);
    EXPECT_EQ(depth.num_channels, 1);
    EXPECT_EQ(depth.bytes_per_channel, 2);
    EXPECT_EQ(*depth.pixel<uint16_t>(0, 0), 0xff07);
    const Image color = o3d::io::read_image(ppm);
    EXPECT_EQ(color.num_channels, 3);
    EXPECT_EQ(color.bytes_per_channel, 1);
    EXPECT_EQ(color.pixel<uint8_t>(0, 0)[0], 0xdc);
    EXPECT_EQ(color.pixel<uint8_t>(0, 0)[1], 0xf8);
    EXPECT_EQ(color.pixel<uint8_t>(0, 0)[2], 0xeb);
    // Written back and read again, bit for bit.
    expect_same(read_mem(write_image_to_memory(depth, "pgm"), "pgm"), depth, "NYU pgm");
    expect_same(read_mem(write_image_to_memory(color, "ppm"), "ppm"), color, "NYU ppm");
}

// ---- Round trips ----

TEST(imageIo, LosslessRoundTrips) {
    struct Case {
        const char* format;
        int channels, bytes;
    };
    const Case cases[] = {{"png", 1, 1}, {"png", 1, 2}, {"png", 3, 1}, {"png", 3, 2}, {"png", 4, 1},
                          {"png", 4, 2}, {"pgm", 1, 1}, {"pgm", 1, 2}, {"ppm", 3, 1}, {"ppm", 3, 2}};
    const auto dir = std::filesystem::temp_directory_path() / ("o3d_image_io_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    uint32_t seed = 1;
    for (const Case& c : cases) {
        for (auto [w, h] : {std::pair{1, 1}, std::pair{7, 5}, std::pair{64, 33}}) {
            const Image im = random_image(w, h, c.channels, c.bytes, seed++);
            const std::string what = std::string(c.format) + " " + std::to_string(c.channels) + "x" +
                                     std::to_string(8 * c.bytes) + " " + std::to_string(w) + "x" + std::to_string(h);
            expect_same(read_mem(write_image_to_memory(im, c.format), c.format), im, what + " (memory)");
            const std::string path = (dir / (std::string("image.") + c.format)).string();
            o3d::io::write_image(path, im);  // format from the extension
            expect_same(o3d::io::read_image(path), im, what + " (file)");
        }
    }
    std::filesystem::remove_all(dir);
}

TEST(imageIo, HighlyCompressibleImagesAreNotMistakenForLies) {
    // A constant image compresses close to deflate's 1032:1 limit, which the PNG reader's size check uses.
    for (int bytes : {1, 2}) {
        const Image zero = make_image(1500, 1000, 4, bytes);
        const std::vector<uint8_t> png = write_image_to_memory(zero, "png");
        EXPECT_LT(png.size() * 200, zero.byte_size());
        expect_same(read_mem(png, "png"), zero, "constant png");
    }
}

TEST(imageIo, SixteenBitByteOrder) {
    Image im = make_image(2, 1, 1, 2);
    *im.pixel<uint16_t>(0, 0) = 0x0102;
    *im.pixel<uint16_t>(1, 0) = 0xA0B0;
    const std::vector<uint8_t> pgm = write_image_to_memory(im, "pgm");
    const std::string header = "P5\n2 1\n65535\n";
    ASSERT_EQ(pgm.size(), header.size() + 4);
    EXPECT_EQ(std::string(pgm.begin(), pgm.begin() + long(header.size())), header);
    EXPECT_EQ(pgm[header.size()], 0x01);  // big-endian in the file
    EXPECT_EQ(pgm[header.size() + 1], 0x02);
    EXPECT_EQ(pgm[header.size() + 2], 0xA0);
    // PNG: bit depth 16 in IHDR (byte 24), and the value survives.
    const std::vector<uint8_t> png = write_image_to_memory(im, "png");
    EXPECT_EQ(png[24], 16);
    EXPECT_EQ(*read_mem(png, "png").pixel<uint16_t>(0, 0), 0x0102);
}

double mean_abs_error(const Image& a, const Image& b) {
    double s = 0;
    for (size_t i = 0; i < a.data.size(); ++i) s += std::abs(int(a.data[i]) - int(b.data[i]));
    return s / double(a.data.size());
}

TEST(imageIo, JpegRoundTripsWithQuality) {
    for (int channels : {1, 3}) {
        const Image im = smooth_image(96, 64, channels);
        const std::vector<uint8_t> best = write_image_to_memory(im, "jpg", 100);
        const std::vector<uint8_t> low = write_image_to_memory(im, "jpeg", 10);
        const std::vector<uint8_t> dflt = write_image_to_memory(im, "jpg");
        EXPECT_LT(low.size(), dflt.size());
        EXPECT_LT(dflt.size(), best.size());
        const Image back = read_mem(best, "jpg");
        ASSERT_EQ(back.width, 96);
        ASSERT_EQ(back.height, 64);
        ASSERT_EQ(back.num_channels, channels);
        ASSERT_EQ(back.bytes_per_channel, 1);
        EXPECT_LT(mean_abs_error(back, im), 2.0);
        const Image rough = read_mem(low, "jpg");
        EXPECT_GT(mean_abs_error(rough, im), mean_abs_error(back, im));
        // The default is quality 90, exactly.
        EXPECT_EQ(dflt, write_image_to_memory(im, "jpg", 90));
    }
}

TEST(imageIo, WriteChecksFormatAndArguments) {
    const Image f = make_image(4, 4, 1, 4);
    for (const char* fmt : {"png", "jpg", "pgm", "ppm"})
        EXPECT_THROW(write_image_to_memory(f, fmt), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 4, 1), "jpg"), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 1, 2), "jpg"), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 3, 1), "pgm"), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 1, 1), "ppm"), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 4, 1), "ppm"), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 3, 1), "jpg", 0), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 3, 1), "jpg", 101), o3d::InvalidArgument);
    EXPECT_NO_THROW(write_image_to_memory(make_image(4, 4, 3, 1), "png", 101));  // ignored by PNG
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 3, 1), "bmp"), o3d::Unsupported);
    EXPECT_THROW(write_image_to_memory(make_image(4, 4, 3, 1), ""), o3d::InvalidArgument);
    EXPECT_THROW(write_image_to_memory(Image{}, "png"), o3d::InvalidArgument);
    Image broken = make_image(4, 4, 3, 1);
    broken.data.resize(5);
    EXPECT_THROW(write_image_to_memory(broken, "png"), o3d::InvalidArgument);
    EXPECT_THROW(o3d::io::write_image("/nonexistent-dir/x.png", make_image(2, 2, 1, 1)), o3d::IoError);
    EXPECT_THROW(o3d::io::write_image("/tmp/x.tiff", make_image(2, 2, 1, 1)), o3d::Unsupported);
    EXPECT_THROW(o3d::io::read_image("/nonexistent-dir/x.png"), o3d::IoError);
    EXPECT_THROW(o3d::io::read_image("/tmp/noextension"), o3d::Unsupported);
    EXPECT_THROW(read_image_from_memory(nullptr, 4, "png"), o3d::InvalidArgument);
    EXPECT_THROW(read_image_from_memory(nullptr, 0, "png"), o3d::ParseError);
}

// ---- Malformed files ----

uint32_t crc32(const uint8_t* p, size_t n) {
    uint32_t c = 0xffffffffu;
    for (size_t i = 0; i < n; ++i) {
        c ^= p[i];
        for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
    }
    return ~c;
}

void put_be32(uint8_t* p, uint32_t v) {
    p[0] = uint8_t(v >> 24), p[1] = uint8_t(v >> 16), p[2] = uint8_t(v >> 8), p[3] = uint8_t(v);
}

TEST(imageIoMalformed, Png) {
    const std::vector<uint8_t> good = write_image_to_memory(random_image(40, 30, 3, 1, 9), "png");
    EXPECT_NE(parse_error_of(bytes_of("not a png at all"), "png").find("signature"), std::string::npos);
    EXPECT_NE(parse_error_of(std::vector<uint8_t>(good.begin(), good.begin() + 8), "png"), "");
    for (size_t cut : {size_t(20), size_t(33), size_t(60), good.size() / 2, good.size() - 13})
        EXPECT_NE(parse_error_of(std::vector<uint8_t>(good.begin(), good.begin() + long(cut)), "png"), "") << cut;
    // A wrong CRC on IHDR.
    std::vector<uint8_t> bad_crc = good;
    bad_crc[29] ^= 0xff;
    EXPECT_NE(parse_error_of(bad_crc, "png"), "");
    // A header claiming 60000 x 60000 pixels (valid CRC) over a few hundred bytes: refused before allocating.
    std::vector<uint8_t> lying = good;
    put_be32(&lying[16], 60000);
    put_be32(&lying[20], 60000);
    put_be32(&lying[29], crc32(&lying[12], 17));
    const std::string msg = parse_error_of(lying, "png");
    EXPECT_NE(msg.find("compressed data"), std::string::npos) << msg;
    // Beyond the dimension limit.
    put_be32(&lying[16], 1u << 30);
    put_be32(&lying[29], crc32(&lying[12], 17));
    EXPECT_NE(parse_error_of(lying, "png"), "");
}

TEST(imageIoMalformed, Jpeg) {
    const std::vector<uint8_t> good = write_image_to_memory(smooth_image(64, 48, 3), "jpg", 90);
    EXPECT_NE(parse_error_of(bytes_of("GIF89a"), "jpg").find("SOI"), std::string::npos);
    EXPECT_NE(parse_error_of(std::vector<uint8_t>{0xFF, 0xD8, 0xFF, 0x00, 0x12}, "jpg"), "");
    for (size_t cut : {size_t(4), size_t(100), good.size() / 2, good.size() - 3}) {
        const std::string msg = parse_error_of(std::vector<uint8_t>(good.begin(), good.begin() + long(cut)), "jpg");
        EXPECT_NE(msg, "") << cut;
    }
    // A SOF0 claiming 65000 x 65000: fails at the first missing row, not by allocating 12 GB.
    std::vector<uint8_t> lying = good;
    for (size_t i = 2; i + 9 < lying.size(); ++i)
        if (lying[i] == 0xFF && lying[i + 1] == 0xC0) {
            lying[i + 5] = 0xFD, lying[i + 6] = 0xE8;  // height 65000
            lying[i + 7] = 0xFD, lying[i + 8] = 0xE8;  // width 65000
            break;
        }
    EXPECT_NE(parse_error_of(lying, "jpg"), "");
}

TEST(imageIoMalformed, Netpbm) {
    EXPECT_NE(parse_error_of(bytes_of("P5\n2 2\n255\n\x01\x02\x03"), "pgm").find("truncated"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P6\n2 2\n255\n123456789"), "ppm").find("truncated"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P5\n0 2\n255\n"), "pgm").find("width"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P5\n2 2\n0\n\x01\x01\x01\x01"), "pgm").find("maxval"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P5\n2 2\n65536\n"), "pgm").find("maxval"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P5\n2 2"), "pgm").find("maxval"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P5\n2 x\n255\n"), "pgm").find("height"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P5\n2 1\n255"), "pgm").find("whitespace"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("Q5\n"), "pgm").find("magic"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P9\n"), "pgm").find("magic"), std::string::npos);
    EXPECT_THROW(read_mem(bytes_of("P2\n1 1\n255\n7\n"), "pgm"), o3d::Unsupported);
    EXPECT_THROW(read_mem(bytes_of("P3\n1 1\n255\n7 7 7\n"), "ppm"), o3d::Unsupported);
    // A lying header: 60000 x 60000 16-bit over 4 bytes of data.
    EXPECT_NE(parse_error_of(bytes_of("P5 60000 60000 65535\n\x01\x02\x03\x04"), "pgm").find("truncated"),
              std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of("P5 99999999999999999999 1 255\n"), "pgm").find("width"), std::string::npos);
    // Samples above maxval break the format.
    EXPECT_NE(parse_error_of(bytes_of("P5\n2 1\n100\n\x64\x65"), "pgm").find("exceeds maxval"), std::string::npos);
    EXPECT_NE(parse_error_of(bytes_of(std::string("P5\n1 1\n1000\n\x03\xe9", 14)), "pgm").find("exceeds maxval"),
              std::string::npos);
}

TEST(imageIo, NetpbmMaxvalAndComments) {
    // maxval < 256: 1 byte per sample, values kept as stored; comments anywhere in the header.
    const Image a = read_mem(bytes_of(std::string("P5 # gray\n# size\n3 1 # w h\n100\n\x00\x32\x64", 34)), "pgm");
    ASSERT_EQ(a.bytes_per_channel, 1);
    EXPECT_EQ(a.data, (std::vector<uint8_t>{0, 50, 100}));
    // 255 < maxval: 2 bytes, big-endian.
    const Image b = read_mem(bytes_of(std::string("P6 1 1 1000\n\x03\xe8\x00\x01\x01\x00", 18)), "ppm");
    ASSERT_EQ(b.bytes_per_channel, 2);
    EXPECT_EQ(b.pixel<uint16_t>(0, 0)[0], 1000);
    EXPECT_EQ(b.pixel<uint16_t>(0, 0)[1], 1);
    EXPECT_EQ(b.pixel<uint16_t>(0, 0)[2], 256);
    // Trailing data after the raster is ignored; a P6 file read as "pgm" is still RGB.
    EXPECT_EQ(read_mem(bytes_of("P6 1 1 255\nabcXYZ"), "pgm").num_channels, 3);
}

TEST(imageIoMalformed, RandomCorruptionNeverCrashes) {
    const std::vector<std::pair<std::string, std::vector<uint8_t>>> seeds = {
        {"png", write_image_to_memory(random_image(16, 12, 3, 1, 2), "png")},
        {"png", write_image_to_memory(random_image(9, 7, 1, 2, 3), "png")},
        {"jpg", write_image_to_memory(smooth_image(32, 24, 3), "jpg")},
        {"pgm", write_image_to_memory(random_image(8, 8, 1, 2, 4), "pgm")},
    };
    std::mt19937 rng(11);
    for (const auto& [format, good] : seeds)
        for (int trial = 0; trial < 300; ++trial) {
            std::vector<uint8_t> bytes = good;
            const int flips = 1 + int(rng() % 4);
            for (int k = 0; k < flips; ++k) bytes[rng() % bytes.size()] = uint8_t(rng());
            if (trial % 3 == 0) bytes.resize(rng() % bytes.size());
            try {
                const Image im = read_mem(bytes, format);
                EXPECT_EQ(im.data.size(), im.byte_size());
            } catch (const o3d::ParseError&) {
            } catch (const o3d::Unsupported&) {
            }
        }
}

}  // namespace
