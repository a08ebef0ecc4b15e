// SPDX-License-Identifier: MIT
#include "o3d/io/feature_io.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "o3d/io/file_bytes.h"
#include "o3d/io/io_internal.h"
#include "o3d/utility/error.h"

namespace o3d::io {
namespace {

constexpr size_t kHeaderBytes = 2 * sizeof(int32_t);

// The files are little-endian; so is every platform o3d builds for, which lets the values be
// copied as they lie (checked here rather than byte-swapped at run time).
static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "feature files are little-endian");

registration::Feature parse(const detail::Input& in) {
    if (in.size < kHeaderBytes)
        detail::parse_error(in, "a feature file starts with two int32 sizes, but it has only " +
                                    std::to_string(in.size) + " bytes");
    int32_t header[2];
    std::memcpy(header, in.data, sizeof header);
    const int32_t dimension = header[0], num = header[1];
    if (dimension < 0 || num < 0)
        detail::parse_error(in, "negative feature size " + std::to_string(dimension) + " x " + std::to_string(num));
    const size_t body = in.size - kHeaderBytes;
    // 64-bit products cannot overflow: both factors are below 2^31.
    const uint64_t values = static_cast<uint64_t>(dimension) * static_cast<uint64_t>(num);
    if (values > body / sizeof(double) || values * sizeof(double) != body)
        detail::parse_error(in, "a " + std::to_string(dimension) + " x " + std::to_string(num) + " feature needs " +
                                    std::to_string(values * sizeof(double)) + " bytes of values, the file has " +
                                    std::to_string(body));
    registration::Feature feature;
    feature.data.resize(dimension, num);
    if (values) std::memcpy(feature.data.data(), in.data + kHeaderBytes, body);
    const double* v = feature.data.data();
    for (uint64_t i = 0; i < values; ++i)
        if (!std::isfinite(v[i]))
            detail::parse_error(in, "value " + std::to_string(i % static_cast<uint64_t>(dimension)) +
                                        " of descriptor " + std::to_string(i / static_cast<uint64_t>(dimension)) +
                                        " is not finite");
    return feature;
}

}  // namespace

registration::Feature read_feature(const std::string& path) {
    const detail::FileBytes bytes(path);
    static const uint8_t kEmpty = 0;
    const detail::Input in{bytes.size() ? bytes.data() : &kEmpty, bytes.size(), path};
    return parse(in);
}

registration::Feature read_feature_from_memory(const uint8_t* data, size_t size) {
    if (!data && size) throw InvalidArgument("data is NULL but size is " + std::to_string(size));
    static const uint8_t kEmpty = 0;
    static const std::string kMemory = "<memory>";
    const detail::Input in{data ? data : &kEmpty, data ? size : 0, kMemory};
    return parse(in);
}

std::vector<uint8_t> write_feature_to_memory(const registration::Feature& feature) {
    constexpr size_t kMax = static_cast<size_t>(std::numeric_limits<int32_t>::max());
    if (feature.dimension() > kMax || feature.num() > kMax)
        throw InvalidArgument("a feature file holds at most 2^31 - 1 descriptors of at most 2^31 - 1 values, got " +
                              std::to_string(feature.dimension()) + " x " + std::to_string(feature.num()));
    // The reader rejects non-finite values, so the writer does not produce them.
    if (!feature.data.allFinite()) throw InvalidArgument("the feature holds a non-finite value");
    const int32_t header[2] = {static_cast<int32_t>(feature.dimension()), static_cast<int32_t>(feature.num())};
    const size_t body = feature.dimension() * feature.num() * sizeof(double);
    std::vector<uint8_t> bytes(kHeaderBytes + body);
    std::memcpy(bytes.data(), header, sizeof header);
    if (body) std::memcpy(bytes.data() + kHeaderBytes, feature.data.data(), body);
    return bytes;
}

void write_feature(const std::string& path, const registration::Feature& feature) {
    detail::write_file(path, write_feature_to_memory(feature));
}

}  // namespace o3d::io
