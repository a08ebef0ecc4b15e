// SPDX-License-Identifier: MIT
// Malformed, truncated and lying inputs give o3d::ParseError with the source's name and the
// reason; never a crash, never an allocation sized by an unchecked header count.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "io_test_util.h"

namespace {

using o3d::test::bytes_of;
using o3d::test::parse_error_of;

/// @brief Expect a ParseError from <memory> whose message contains `reason`.
void expect_parse_error(const std::string& text, const std::string& format, const std::string& reason) {
    const std::string msg = parse_error_of(bytes_of(text), format);
    ASSERT_FALSE(msg.empty()) << format << " accepted:\n" << text.substr(0, 300);
    EXPECT_EQ(msg.rfind("<memory>: ", 0), 0u) << msg;
    EXPECT_NE(msg.find(reason), std::string::npos) << "message: " << msg << "\nexpected to contain: " << reason;
}

const std::string kPlyHead = "ply\nformat binary_little_endian 1.0\n";
const std::string kXyz = "property float x\nproperty float y\nproperty float z\n";

TEST(ioMalformed, PlyHeaders) {
    expect_parse_error("", "ply", "first line");
    expect_parse_error("plx\nformat ascii 1.0\nend_header\n", "ply", "first line");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz, "ply", "end_header");
    expect_parse_error("ply\nelement vertex 1\n" + kXyz + "end_header\n0 0 0\n", "ply", "no format");
    expect_parse_error("ply\nformat binary_middle_endian 1.0\nend_header\n", "ply", "unknown format");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex -3\n" + kXyz + "end_header\n", "ply", "negative count");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex many\n" + kXyz + "end_header\n", "ply",
                       "element <name> <count>");
    expect_parse_error("ply\nformat ascii 1.0\nproperty float x\nend_header\n", "ply", "before any element");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n", "ply",
                       "unknown property type 'quad'");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty list float int x\nend_header\n", "ply",
                       "integer type");
    expect_parse_error("ply\nformat ascii 1.0\nbogus line\nend_header\n", "ply", "unknown keyword 'bogus'");
    expect_parse_error("ply\nformat ascii 1.0\nelement face 1\nproperty int a\nend_header\n1\n", "ply",
                       "no vertex element");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n",
                       "ply", "lacks an x, y or z");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty list uchar float x\nproperty float y\n"
                       "property float z\nend_header\n1 1 2 3\n",
                       "ply", "is a list");
}

TEST(ioMalformed, PlyCountsThatLie) {
    // Four billion vertices announced, twelve bytes present: refused before any allocation.
    expect_parse_error(kPlyHead + "element vertex 4000000000\n" + kXyz + "end_header\n" + std::string(12, '\0'), "ply",
                       "declares 4000000000 records");
    expect_parse_error(kPlyHead + "element vertex 9223372036854775807\n" + kXyz + "end_header\n", "ply",
                       "declares 9223372036854775807");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1000000000\n" + kXyz + "end_header\n1 2 3\n", "ply",
                       "declares 1000000000 vertices");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 2\n" + kXyz + "end_header\n10.5 20.5 30.5\n4 5\n", "ply",
                       "ends inside vertex 1");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz + "end_header\n1 2 3\n4 5 6\n", "ply",
                       "counts are too small");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\n" + kXyz + "end_header\n1 2 x\n", "ply",
                       "'x' is not a number");
    // A face list claiming 2^31 indices in a few bytes.
    std::string faces = kPlyHead + "element vertex 0\n" + kXyz +
                        "element face 1\nproperty list int int vertex_indices\nend_header\n";
    const int32_t huge = 0x7fffffff;
    faces.append(reinterpret_cast<const char*>(&huge), 4);
    expect_parse_error(faces, "ply", "ends inside face 0");
    std::string negative = faces.substr(0, faces.size() - 4);
    const int32_t minus = -2;
    negative.append(reinterpret_cast<const char*>(&minus), 4);
    expect_parse_error(negative, "ply", "negative length");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 0\n" + kXyz +
                           "element face 1\nproperty list uchar int v\nend_header\n-1\n",
                       "ply", "negative length");
}

TEST(ioMalformed, PcdHeaders) {
    expect_parse_error("", "pcd", "no DATA line");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS 1\n", "pcd", "no DATA line");
    expect_parse_error("SIZE 4\nTYPE F\nPOINTS 1\nDATA ascii\n", "pcd", "no FIELDS");
    expect_parse_error("FIELDS x y z\nSIZE 4 4\nTYPE F F F\nPOINTS 1\nDATA ascii\n1 2 3", "pcd", "different numbers");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 3\nTYPE F F F\nPOINTS 1\nDATA ascii\n1 2 3", "pcd", "SIZE 3");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\nPOINTS 1\nDATA ascii\n1 2 3", "pcd", "TYPE 'Q'");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 0\nPOINTS 1\nDATA ascii\n1 2 3", "pcd",
                       "COUNT 0");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 99999999999\nPOINTS 1\nDATA ascii\n", "pcd",
                       "out of range");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 3\nPOINTS 1\nDATA ascii\n1 2 3 3 3", "pcd",
                       "field 'z' has COUNT 3");
    expect_parse_error("FIELDS x y\nSIZE 4 4\nTYPE F F\nPOINTS 1\nDATA ascii\n1 2", "pcd", "lack x, y or z");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS -1\nDATA ascii\n", "pcd", "negative");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 2\nPOINTS 3\nDATA ascii\n", "pcd",
                       "differs from WIDTH x HEIGHT");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 4294967296\nHEIGHT 4294967296\nDATA ascii\n",
                       "pcd", "overflows");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nHEIGHT 1\nDATA ascii\n", "pcd", "neither WIDTH nor POINTS");
    expect_parse_error("FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nPOINTS 1\nDATA zipped\n", "pcd", "unknown DATA");
}

const std::string kPcdHead = "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";

TEST(ioMalformed, PcdCountsThatLie) {
    expect_parse_error(kPcdHead + "POINTS 4000000000\nDATA binary\n" + std::string(24, '\0'), "pcd",
                       "declares 4000000000 points of 12 bytes but only 24");
    expect_parse_error(kPcdHead + "POINTS 4000000000\nDATA ascii\n1 2 3\n", "pcd", "declares 4000000000 points");
    expect_parse_error(kPcdHead + "POINTS 2\nDATA ascii\n10.5 20.5 30.5\n4 5\n", "pcd", "ends inside point 1");
    expect_parse_error(kPcdHead + "POINTS 1\nDATA ascii\n1 2 3\n4 5 6\n", "pcd", "text follows the last");
    expect_parse_error(kPcdHead + "POINTS 1\nDATA ascii\n1 2 zz\n", "pcd", "'zz' is not a number");
    expect_parse_error(kPcdHead + "POINTS 1\nDATA binary_compressed\n\x01\x00", "pcd", "8-byte size prefix");

    auto compressed = [](uint32_t packed, uint32_t raw, const std::string& payload) {
        std::string s = kPcdHead + "POINTS 1000\nDATA binary_compressed\n";
        s.append(reinterpret_cast<const char*>(&packed), 4);
        s.append(reinterpret_cast<const char*>(&raw), 4);
        return s + payload;
    };
    expect_parse_error(compressed(10, 12000, std::string(10, 'a')), "pcd", "cannot unpack to 12000");
    expect_parse_error(compressed(100, 12000, std::string(10, 'a')), "pcd", "claims 100 bytes but only 10");
    expect_parse_error(compressed(10, 4000000000u, std::string(10, 'a')), "pcd", "unpacks to 4000000000 bytes");
    expect_parse_error(compressed(200, 12000, std::string(200, '\xff')), "pcd", "LZF data is corrupt");
}

TEST(ioMalformed, TextFormats) {
    expect_parse_error("1 2 3\n4 5\n", "xyz", "line 2: expected 3 numbers");
    expect_parse_error("1 2 3 4 5 6\n1 2 3\n", "xyzn", "line 2: expected 6 numbers");
    expect_parse_error("1 2 3 0.1 0.2 abc\n", "xyzrgb", "expected 6 numbers");
    expect_parse_error("", "pts", "no point count");
    expect_parse_error("-5\n", "pts", "negative point count");
    expect_parse_error("abc\n", "pts", "expected the point count");
    expect_parse_error("3\n1 2 3\n4 5 6\n", "pts", "ends after 2 of the 3 rows");
    expect_parse_error("1\n1 2 3\n4 5 6\n", "pts", "more rows than the count");
    expect_parse_error("1000000\n1 2 3\n", "pts", "exceeds the");
    expect_parse_error("1\n1 2 3 4 5\n", "pts", "got 5 columns");
}

// Cutting a valid file anywhere must raise ParseError for the binary formats (every byte
// counts); text formats may legitimately end at a line boundary, so they must merely not crash.
TEST(ioMalformed, TruncatedAtEveryOffset) {
    const auto cloud = o3d::test::make_cloud(20, true, true);
    struct Variant {
        const char* format;
        bool ascii, compressed;
    };
    for (const Variant v : {Variant{"ply", false, false}, Variant{"pcd", false, false}, Variant{"pcd", false, true},
                            Variant{"ply", true, false}, Variant{"pcd", true, false}, Variant{"pts", false, false},
                            Variant{"xyzn", false, false}}) {
        o3d::io::WriteOptions w;
        w.write_ascii = v.ascii;
        w.compressed = v.compressed;
        const auto full = o3d::io::write_point_cloud_to_memory(cloud, v.format, w);
        const bool binary = !v.ascii && (std::string(v.format) == "ply" || std::string(v.format) == "pcd");
        for (size_t cut = 0; cut < full.size(); ++cut) {
            const std::vector<uint8_t> part(full.begin(), full.begin() + static_cast<long>(cut));
            try {
                const auto pc = o3d::io::read_point_cloud_from_memory(part.data(), part.size(), v.format);
                EXPECT_FALSE(binary) << v.format << " accepted a cut at " << cut << " of " << full.size();
                EXPECT_LE(pc.size(), cloud.size());
            } catch (const o3d::ParseError& e) {
                EXPECT_NE(std::string(e.what()).find("<memory>"), std::string::npos);
            }
        }
    }
}

// Random bytes, and random bytes behind a plausible header, never escape as anything but ParseError.
TEST(ioMalformed, RandomGarbage) {
    std::mt19937 rng(1234);
    const std::string prefixes[] = {"", "ply\nformat binary_little_endian 1.0\nelement vertex 5\n" + kXyz + "end_header\n",
                                    "ply\nformat ascii 1.0\nelement vertex 5\n" + kXyz + "end_header\n",
                                    kPcdHead + "POINTS 5\nDATA binary\n", kPcdHead + "POINTS 5\nDATA binary_compressed\n",
                                    kPcdHead + "POINTS 5\nDATA ascii\n", "5\n"};
    int parse_errors = 0;
    for (int round = 0; round < 300; ++round) {
        std::string s = prefixes[round % 7];
        const int n = static_cast<int>(rng() % 200);
        for (int i = 0; i < n; ++i) s.push_back(static_cast<char>(rng()));
        for (const char* format : {"ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts"}) {
            try {
                o3d::test::read_text(s, format);
            } catch (const o3d::ParseError&) {
                ++parse_errors;
            }
        }
    }
    EXPECT_GT(parse_errors, 1500);
}

}  // namespace
