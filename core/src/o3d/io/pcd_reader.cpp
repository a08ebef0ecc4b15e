// SPDX-License-Identifier: MIT
// PCD reader (v0.5-v0.7): DATA ascii, binary and binary_compressed (LZF). Keeps x y z,
// normal_x normal_y normal_z and rgb/rgba (packed 0x00RRGGBB as F, U or I of 4 bytes); every other
// field of any SIZE, TYPE and COUNT is skipped. Organized clouds keep their width x height order.
#include <lzf.h>

#include <climits>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "o3d/io/byte_reader.h"
#include "o3d/io/io_internal.h"

namespace o3d::io::detail {
namespace {

enum class PcdData { Ascii, Binary, Compressed };

struct PcdField {
    std::string name;
    size_t size = 4;
    char type = 'F';
    size_t count = 1;
    size_t offset = 0;  // in a binary point record
    ScalarType scalar = ScalarType::Float32;
};

struct PcdHeader {
    std::vector<PcdField> fields;
    uint64_t points = 0;
    PcdData data = PcdData::Ascii;
    size_t point_size = 0;
    size_t data_offset = 0;
};

// A field's COUNT beyond this is a corrupt header, not an array anyone stores per point.
constexpr uint64_t kMaxFieldCount = 1u << 20;
// LZF emits at most 264 bytes per 3-byte back-reference: a larger claimed ratio is a lie.
constexpr uint64_t kMaxLzfRatio = 88;

bool to_scalar(char type, size_t size, ScalarType& out) {
    switch (type) {
        case 'I':
            out = size == 1 ? ScalarType::Int8 : size == 2 ? ScalarType::Int16 : size == 4 ? ScalarType::Int32
                                                                                           : ScalarType::Int64;
            return size == 1 || size == 2 || size == 4 || size == 8;
        case 'U':
            out = size == 1 ? ScalarType::UInt8 : size == 2 ? ScalarType::UInt16 : size == 4 ? ScalarType::UInt32
                                                                                             : ScalarType::UInt64;
            return size == 1 || size == 2 || size == 4 || size == 8;
        case 'F':
            out = size == 4 ? ScalarType::Float32 : ScalarType::Float64;
            return size == 4 || size == 8;
        default: return false;
    }
}

std::vector<std::string_view> rest_tokens(TextCursor& c) {
    std::vector<std::string_view> out;
    for (std::string_view t = c.token(); !t.empty(); t = c.token()) out.push_back(t);
    return out;
}

uint64_t parse_count(const Input& in, const std::string& where, const char* key, std::string_view tok) {
    int64_t v = 0;
    if (!parse_int64(tok, v)) parse_error(in, where + key + " '" + std::string(tok.substr(0, 32)) + "' is not an integer");
    if (v < 0) parse_error(in, where + key + " is negative (" + std::to_string(v) + ")");
    return static_cast<uint64_t>(v);
}

PcdHeader parse_header(const Input& in) {
    TextCursor cur(in.chars(), in.chars_end());
    PcdHeader h;
    std::vector<std::string_view> names, sizes, types, counts;
    bool have_width = false, have_height = false, have_points = false, have_data = false;
    uint64_t width = 0, height = 1, points = 0;
    size_t line_no = 0;
    while (!cur.at_end() && !have_data) {
        ++line_no;
        const std::string_view line = cur.line();
        const std::string where = "PCD header line " + std::to_string(line_no) + ": ";
        TextCursor lc(line);
        const std::string_view kw = lc.token();
        if (kw.empty() || kw[0] == '#') continue;
        if (kw == "FIELDS" || kw == "COLUMNS") names = rest_tokens(lc);
        else if (kw == "SIZE") sizes = rest_tokens(lc);
        else if (kw == "TYPE") types = rest_tokens(lc);
        else if (kw == "COUNT") counts = rest_tokens(lc);
        else if (kw == "WIDTH") width = parse_count(in, where, "WIDTH", lc.token()), have_width = true;
        else if (kw == "HEIGHT") height = parse_count(in, where, "HEIGHT", lc.token()), have_height = true;
        else if (kw == "POINTS") points = parse_count(in, where, "POINTS", lc.token()), have_points = true;
        else if (kw == "DATA") {
            const std::string_view d = lc.token();
            if (d == "ascii") h.data = PcdData::Ascii;
            else if (d == "binary") h.data = PcdData::Binary;
            else if (d == "binary_compressed") h.data = PcdData::Compressed;
            else parse_error(in, where + "unknown DATA '" + std::string(d.substr(0, 32)) + "'");
            have_data = true;
        }
        // VERSION, VIEWPOINT and keywords of later versions carry nothing a point cloud keeps.
    }
    if (!have_data) parse_error(in, "PCD: the header has no DATA line (not a PCD file, or truncated)");
    if (names.empty()) parse_error(in, "PCD: the header has no FIELDS");
    if (sizes.size() != names.size() || types.size() != names.size() || (!counts.empty() && counts.size() != names.size()))
        parse_error(in, "PCD: FIELDS, SIZE, TYPE and COUNT list different numbers of entries (" +
                            std::to_string(names.size()) + ", " + std::to_string(sizes.size()) + ", " +
                            std::to_string(types.size()) + ", " + std::to_string(counts.size()) + ")");
    h.fields.resize(names.size());
    for (size_t i = 0; i < names.size(); ++i) {
        PcdField& f = h.fields[i];
        f.name = std::string(names[i]);
        const std::string where = "PCD: field '" + f.name + "': ";
        const uint64_t size = parse_count(in, where, "SIZE", sizes[i]);
        f.count = counts.empty() ? 1 : parse_count(in, where, "COUNT", counts[i]);
        f.type = types[i].size() == 1 ? types[i][0] : '?';
        if (!to_scalar(f.type, size, f.scalar))
            parse_error(in, where + "unsupported TYPE '" + std::string(types[i].substr(0, 8)) + "' with SIZE " +
                                std::to_string(size));
        if (f.count == 0 || f.count > kMaxFieldCount)
            parse_error(in, where + "COUNT " + std::to_string(f.count) + " is out of range");
        f.size = static_cast<size_t>(size);
        f.offset = h.point_size;
        h.point_size += f.size * f.count;  // <= 2^23 per field, and fields are bounded by the header's length
    }
    if (!have_width && !have_points) parse_error(in, "PCD: the header has neither WIDTH nor POINTS");
    if (!have_width) width = points, height = 1;
    uint64_t wh = 0;
    if (__builtin_mul_overflow(width, height, &wh))
        parse_error(in, "PCD: WIDTH x HEIGHT overflows (" + std::to_string(width) + " x " + std::to_string(height) + ")");
    if (have_points && have_width && wh != points)
        parse_error(in, "PCD: POINTS " + std::to_string(points) + " differs from WIDTH x HEIGHT = " + std::to_string(width) +
                            " x " + std::to_string(height));
    (void)have_height;
    h.points = wh;
    h.data_offset = static_cast<size_t>(cur.pos() - in.chars());
    return h;
}

/// @brief Which fields become which attribute.
struct PcdPlan {
    int xyz[3] = {-1, -1, -1};
    int normal[3] = {-1, -1, -1};
    int rgb = -1;
    bool normals = false;

    PcdPlan(const Input& in, const std::vector<PcdField>& fields) {
        static const char* kXyz[3] = {"x", "y", "z"};
        static const char* kNormal[3] = {"normal_x", "normal_y", "normal_z"};
        for (size_t i = 0; i < fields.size(); ++i) {
            const std::string& n = fields[i].name;
            const int idx = static_cast<int>(i);
            for (int k = 0; k < 3; ++k) {
                if (n == kXyz[k] && xyz[k] < 0) xyz[k] = idx;
                if (n == kNormal[k] && normal[k] < 0) normal[k] = idx;
            }
            if ((n == "rgb" || n == "rgba") && rgb < 0 && fields[i].size == 4) rgb = idx;
        }
        if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0) parse_error(in, "PCD: the FIELDS lack x, y or z");
        normals = normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0;
        for (int k = 0; k < 3; ++k) {
            check_scalar(in, fields, xyz[k]);
            if (normals) check_scalar(in, fields, normal[k]);
        }
        if (rgb >= 0) check_scalar(in, fields, rgb);
    }

    static void check_scalar(const Input& in, const std::vector<PcdField>& fields, int i) {
        const PcdField& f = fields[static_cast<size_t>(i)];
        if (f.count != 1)
            parse_error(in, "PCD: field '" + f.name + "' has COUNT " + std::to_string(f.count) + ", expected 1");
    }

    void allocate(geometry::PointCloud& cloud, size_t n) const {
        allocate_cloud(cloud, n, normals, rgb >= 0);
    }
};

inline Eigen::Vector3d unpack_rgb(uint32_t v) {
    return Eigen::Vector3d(((v >> 16) & 0xff) / 255.0, ((v >> 8) & 0xff) / 255.0, (v & 0xff) / 255.0);
}

/// @brief Decode binary records. `base(f)` is where field f of point 0 lies and `stride(f)` the
/// distance between points: the record size (binary) or the field's size (compressed, which
/// stores field after field).
template <typename Base, typename Stride>
void decode_binary(const std::vector<PcdField>& fields, const PcdPlan& plan, size_t n, Base base, Stride stride,
                   geometry::PointCloud& cloud) {
    plan.allocate(cloud, n);
    auto triple = [&](const int* idx, std::vector<Eigen::Vector3d>& out) {
        TripleLayout l{};
        for (int k = 0; k < 3; ++k) {
            const size_t f = static_cast<size_t>(idx[k]);
            l.base[k] = base(f);
            l.stride[k] = stride(f);
            l.type[k] = fields[f].scalar;
        }
        decode_triples(l, n, 1.0, false, out.data());
    };
    triple(plan.xyz, cloud.points);
    if (plan.normals) triple(plan.normal, cloud.normals);
    if (plan.rgb >= 0) {
        const size_t f = static_cast<size_t>(plan.rgb);
        const uint8_t* b = base(f);
        const size_t s = stride(f);
        for (size_t i = 0; i < n; ++i) cloud.colors[i] = unpack_rgb(load<uint32_t, !kHostLittleEndian>(b + i * s));
    }
}

void read_ascii(const Input& in, const PcdHeader& h, const PcdPlan& plan, geometry::PointCloud& cloud) {
    TextCursor cur(in.chars() + h.data_offset, in.chars_end());
    size_t per_point = 0;
    for (const auto& f : h.fields) per_point += f.count;
    // Every value takes at least one character and a separator.
    const size_t max_values = (cur.remaining() + 1) / 2;
    if (h.points > max_values / per_point)
        parse_error(in, "PCD: the header declares " + std::to_string(h.points) + " points of " +
                            std::to_string(per_point) + " values but only " + std::to_string(cur.remaining()) +
                            " bytes of text follow");
    const size_t n = static_cast<size_t>(h.points);
    plan.allocate(cloud, n);

    // Per field: 0 skip, 1..3 point component, 4..6 normal component, 7 rgb.
    std::vector<int> role(h.fields.size(), 0);
    for (int k = 0; k < 3; ++k) {
        role[static_cast<size_t>(plan.xyz[k])] = 1 + k;
        if (plan.normals) role[static_cast<size_t>(plan.normal[k])] = 4 + k;
    }
    if (plan.rgb >= 0) role[static_cast<size_t>(plan.rgb)] = 7;

    for (size_t i = 0; i < n; ++i) {
        for (size_t f = 0; f < h.fields.size(); ++f) {
            const PcdField& field = h.fields[f];
            if (role[f] == 0) {
                for (size_t c = 0; c < field.count; ++c)
                    if (!cur.skip_token())
                        parse_error(in, "PCD: the text ends inside point " + std::to_string(i) + " of " +
                                            std::to_string(n) + " (truncated file or wrong POINTS)");
                continue;
            }
            if (role[f] != 7) {
                double v;
                std::string_view tok;
                if (cur.number(v, tok)) {
                    if (role[f] <= 3) cloud.points[i][role[f] - 1] = v;
                    else cloud.normals[i][role[f] - 4] = v;
                    continue;
                }
                if (tok.empty())
                    parse_error(in, "PCD: the text ends inside point " + std::to_string(i) + " of " +
                                        std::to_string(n) + " (truncated file or wrong POINTS)");
                parse_error(in, "PCD: point " + std::to_string(i) + ", field '" + field.name + "': '" +
                                    std::string(tok.substr(0, 32)) + "' is not a number");
            }
            const std::string_view tok = cur.token();
            if (tok.empty())
                parse_error(in, "PCD: the text ends inside point " + std::to_string(i) + " of " + std::to_string(n) +
                                    " (truncated file or wrong POINTS)");
            bool ok = true;
            {
                // The packed colour's bits, written as the float, unsigned or signed number they form.
                uint32_t bits = 0;
                if (field.type == 'F') {
                    float v = 0;
                    ok = parse_float(tok, v);
                    std::memcpy(&bits, &v, 4);
                } else {
                    int64_t v = 0;
                    ok = parse_int64(tok, v) && v >= INT32_MIN && v <= static_cast<int64_t>(UINT32_MAX);
                    bits = static_cast<uint32_t>(v);
                }
                if (ok) cloud.colors[i] = unpack_rgb(bits);
            }
            if (!ok)
                parse_error(in, "PCD: point " + std::to_string(i) + ", field '" + field.name + "': '" +
                                    std::string(tok.substr(0, 32)) + "' is not a number");
        }
    }
    if (!cur.only_whitespace_left())
        parse_error(in, "PCD: text follows the last of the " + std::to_string(n) + " points the header declares");
}

void read_binary(const Input& in, const PcdHeader& h, const PcdPlan& plan, geometry::PointCloud& cloud) {
    const size_t available = in.size - h.data_offset;
    if (h.points > available / h.point_size)
        parse_error(in, "PCD: the header declares " + std::to_string(h.points) + " points of " +
                            std::to_string(h.point_size) + " bytes but only " + std::to_string(available) +
                            " bytes of data follow (truncated file or wrong POINTS)");
    const uint8_t* data = in.data + h.data_offset;
    const size_t ps = h.point_size;
    decode_binary(
        h.fields, plan, static_cast<size_t>(h.points), [&](size_t f) { return data + h.fields[f].offset; },
        [&](size_t) { return ps; }, cloud);
}

void read_compressed(const Input& in, const PcdHeader& h, const PcdPlan& plan, geometry::PointCloud& cloud) {
    const size_t available = in.size - h.data_offset;
    if (available < 8) parse_error(in, "PCD: binary_compressed data lacks its 8-byte size prefix");
    const uint8_t* p = in.data + h.data_offset;
    const uint32_t compressed = load<uint32_t, !kHostLittleEndian>(p);
    const uint32_t uncompressed = load<uint32_t, !kHostLittleEndian>(p + 4);
    uint64_t expected = 0;
    if (__builtin_mul_overflow(static_cast<uint64_t>(h.points), static_cast<uint64_t>(h.point_size), &expected) ||
        expected != uncompressed)
        parse_error(in, "PCD: binary_compressed data unpacks to " + std::to_string(uncompressed) + " bytes but " +
                            std::to_string(h.points) + " points of " + std::to_string(h.point_size) + " bytes need " +
                            std::to_string(h.points) + " x " + std::to_string(h.point_size));
    if (compressed > available - 8)
        parse_error(in, "PCD: binary_compressed data claims " + std::to_string(compressed) + " bytes but only " +
                            std::to_string(available - 8) + " follow (truncated file)");
    if (uncompressed == 0) {
        plan.allocate(cloud, 0);
        return;
    }
    if (static_cast<uint64_t>(uncompressed) > static_cast<uint64_t>(compressed) * kMaxLzfRatio)
        parse_error(in, "PCD: " + std::to_string(compressed) + " compressed bytes cannot unpack to " +
                            std::to_string(uncompressed) + " (corrupt size prefix)");
    std::unique_ptr<uint8_t[]> raw(new uint8_t[uncompressed]);
    const unsigned got = lzf_decompress(p + 8, compressed, raw.get(), uncompressed);
    if (got != uncompressed)
        parse_error(in, "PCD: the LZF data is corrupt (unpacked " + std::to_string(got) + " of " +
                            std::to_string(uncompressed) + " bytes)");
    // Field-major layout: all points' first field, then all points' second field, ...
    const size_t n = static_cast<size_t>(h.points);
    const uint8_t* u = raw.get();
    decode_binary(
        h.fields, plan, n, [&](size_t f) { return u + n * h.fields[f].offset; },
        [&](size_t f) { return h.fields[f].size * h.fields[f].count; }, cloud);
}

}  // namespace

geometry::PointCloud read_pcd(const Input& in) {
    const PcdHeader h = parse_header(in);
    const PcdPlan plan(in, h.fields);
    geometry::PointCloud cloud;
    switch (h.data) {
        case PcdData::Ascii: read_ascii(in, h, plan, cloud); break;
        case PcdData::Binary: read_binary(in, h, plan, cloud); break;
        case PcdData::Compressed: read_compressed(in, h, plan, cloud); break;
    }
    return cloud;
}

}  // namespace o3d::io::detail
