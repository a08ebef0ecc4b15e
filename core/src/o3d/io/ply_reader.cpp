// SPDX-License-Identifier: MIT
// PLY reader: ascii, binary_little_endian, binary_big_endian. Only the vertex element's x y z,
// nx ny nz and red green blue are kept; every other property and element is walked and skipped,
// so a truncated or inconsistent file is caught wherever the damage is.
#include <string>
#include <string_view>
#include <vector>

#include "o3d/io/byte_reader.h"
#include "o3d/io/io_internal.h"

namespace o3d::io::detail {
namespace {

enum class PlyEncoding { Ascii, BinaryLittle, BinaryBig };

struct PlyProperty {
    std::string name;
    bool is_list = false;
    ScalarType type = ScalarType::Float32;  // the scalar's type, or the list items' type
    ScalarType count_type = ScalarType::UInt8;
};

struct PlyElement {
    std::string name;
    uint64_t count = 0;
    std::vector<PlyProperty> props;

    bool has_list() const {
        for (const auto& p : props)
            if (p.is_list) return true;
        return false;
    }
    /// @brief Bytes of one record when every list is empty (exact when there are no lists).
    size_t min_record_size() const {
        size_t s = 0;
        for (const auto& p : props) s += scalar_size(p.is_list ? p.count_type : p.type);
        return s;
    }
};

struct PlyHeader {
    PlyEncoding encoding = PlyEncoding::Ascii;
    std::vector<PlyElement> elements;
    size_t data_offset = 0;
};

// The attributes read into the cloud, in PointCloud order.
enum Slot { kX, kY, kZ, kNx, kNy, kNz, kRed, kGreen, kBlue, kSlotCount };
constexpr const char* kSlotNames[kSlotCount] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"};

int slot_of(const std::string& name) {
    for (int s = 0; s < kSlotCount; ++s)
        if (name == kSlotNames[s]) return s;
    return -1;
}

bool parse_type(std::string_view s, ScalarType& t) {
    struct Name {
        const char* name;
        ScalarType type;
    };
    static const Name kNames[] = {
        {"char", ScalarType::Int8},      {"int8", ScalarType::Int8},       {"uchar", ScalarType::UInt8},
        {"uint8", ScalarType::UInt8},    {"short", ScalarType::Int16},     {"int16", ScalarType::Int16},
        {"ushort", ScalarType::UInt16},  {"uint16", ScalarType::UInt16},   {"int", ScalarType::Int32},
        {"int32", ScalarType::Int32},    {"uint", ScalarType::UInt32},     {"uint32", ScalarType::UInt32},
        {"float", ScalarType::Float32},  {"float32", ScalarType::Float32}, {"double", ScalarType::Float64},
        {"float64", ScalarType::Float64}, {"int64", ScalarType::Int64},    {"uint64", ScalarType::UInt64},
    };
    for (const auto& n : kNames)
        if (s == n.name) {
            t = n.type;
            return true;
        }
    return false;
}

/// @brief Colour channels stored as integers are scaled to [0,1] by their type's range.
double color_divisor(ScalarType t) {
    switch (t) {
        case ScalarType::Float32:
        case ScalarType::Float64: return 1.0;
        case ScalarType::Int16:
        case ScalarType::UInt16: return 65535.0;
        default: return 255.0;
    }
}

PlyHeader parse_header(const Input& in) {
    TextCursor cur(in.chars(), in.chars_end());
    if (cur.line() != "ply") parse_error(in, "PLY: the first line is not 'ply'");
    PlyHeader h;
    bool have_format = false;
    bool ended = false;
    size_t line_no = 1;
    while (!cur.at_end()) {
        ++line_no;
        const std::string_view line = cur.line();
        const std::string where = "PLY header line " + std::to_string(line_no) + ": ";
        TextCursor lc(line);
        const std::string_view kw = lc.token();
        if (kw.empty() || kw == "comment" || kw == "obj_info") continue;
        if (kw == "end_header") {
            ended = true;
            break;
        }
        if (kw == "format") {
            const std::string_view enc = lc.token();
            if (enc == "ascii") h.encoding = PlyEncoding::Ascii;
            else if (enc == "binary_little_endian") h.encoding = PlyEncoding::BinaryLittle;
            else if (enc == "binary_big_endian") h.encoding = PlyEncoding::BinaryBig;
            else parse_error(in, where + "unknown format '" + std::string(enc) + "'");
            have_format = true;
        } else if (kw == "element") {
            PlyElement e;
            e.name = std::string(lc.token());
            const std::string_view count = lc.token();
            int64_t n = 0;
            if (e.name.empty() || !parse_int64(count, n))
                parse_error(in, where + "expected 'element <name> <count>'");
            if (n < 0) parse_error(in, where + "element '" + e.name + "' has a negative count " + std::to_string(n));
            e.count = static_cast<uint64_t>(n);
            h.elements.push_back(std::move(e));
        } else if (kw == "property") {
            if (h.elements.empty()) parse_error(in, where + "property before any element");
            PlyProperty p;
            std::string_view t = lc.token();
            if (t == "list") {
                p.is_list = true;
                if (!parse_type(lc.token(), p.count_type) || !is_integer(p.count_type))
                    parse_error(in, where + "a list's length type must be an integer type");
                t = lc.token();
            }
            if (!parse_type(t, p.type)) parse_error(in, where + "unknown property type '" + std::string(t) + "'");
            p.name = std::string(lc.token());
            if (p.name.empty()) parse_error(in, where + "property without a name");
            h.elements.back().props.push_back(std::move(p));
        } else {
            parse_error(in, where + "unknown keyword '" + std::string(kw) + "'");
        }
    }
    if (!ended) parse_error(in, "PLY: the header has no end_header line");
    if (!have_format) parse_error(in, "PLY: the header has no format line");
    h.data_offset = static_cast<size_t>(cur.pos() - in.chars());
    return h;
}

/// @brief Where the kept attributes are, and how to hold them.
struct VertexPlan {
    int slot_prop[kSlotCount];   // property index per slot, -1 when absent
    std::vector<int> prop_slot;  // slot per property, -1 for the skipped ones
    bool normals = false;
    bool colors = false;

    VertexPlan(const Input& in, const PlyElement& v) {
        for (int& s : slot_prop) s = -1;
        prop_slot.assign(v.props.size(), -1);
        for (size_t i = 0; i < v.props.size(); ++i) {
            const int s = slot_of(v.props[i].name);
            if (s < 0 || slot_prop[s] >= 0) continue;
            if (v.props[i].is_list)
                parse_error(in, "PLY: vertex property '" + v.props[i].name + "' is a list, not a scalar");
            slot_prop[s] = static_cast<int>(i);
            prop_slot[i] = s;
        }
        if (slot_prop[kX] < 0 || slot_prop[kY] < 0 || slot_prop[kZ] < 0)
            parse_error(in, "PLY: the vertex element lacks an x, y or z property");
        normals = slot_prop[kNx] >= 0 && slot_prop[kNy] >= 0 && slot_prop[kNz] >= 0;
        colors = slot_prop[kRed] >= 0 && slot_prop[kGreen] >= 0 && slot_prop[kBlue] >= 0;
    }

    void allocate(geometry::PointCloud& cloud, size_t n) const {
        allocate_cloud(cloud, n, normals, colors);
    }

    /// @brief Store one vertex whose kept values are in `v` (colours already scaled).
    void store(geometry::PointCloud& cloud, size_t i, const double* v) const {
        cloud.points[i] = Eigen::Vector3d(v[kX], v[kY], v[kZ]);
        if (normals) cloud.normals[i] = Eigen::Vector3d(v[kNx], v[kNy], v[kNz]);
        if (colors) cloud.colors[i] = Eigen::Vector3d(v[kRed], v[kGreen], v[kBlue]);
    }
};

std::string count_text(uint64_t n, const std::string& what) { return std::to_string(n) + " " + what; }

class BinaryReader {
public:
    BinaryReader(const Input& in, size_t offset, bool swap) : in_(in), pos_(in.data + offset), swap_(swap) {}

    size_t remaining() const { return static_cast<size_t>(in_.data + in_.size - pos_); }

    void skip_element(const PlyElement& e) {
        if (e.props.empty() || e.count == 0) return;
        if (!e.has_list()) {
            const size_t stride = e.min_record_size();
            if (e.count > remaining() / stride) truncated(e, stride);
            pos_ += e.count * stride;
            return;
        }
        for (uint64_t r = 0; r < e.count; ++r) walk_record(e, r, nullptr, nullptr);
    }

    void read_vertices(const PlyElement& e, const VertexPlan& plan, geometry::PointCloud& cloud) {
        const size_t min_size = e.min_record_size();
        if (e.count > remaining() / min_size) truncated(e, min_size);
        const size_t n = static_cast<size_t>(e.count);
        plan.allocate(cloud, n);
        if (e.has_list()) {
            double values[kSlotCount];
            for (size_t i = 0; i < n; ++i) {
                walk_record(e, i, &plan, values);
                plan.store(cloud, i, values);
            }
            return;
        }
        // Fixed-size records: decode each attribute with one tight loop over the records.
        size_t offset[kSlotCount] = {};
        for (size_t p = 0, off = 0; p < e.props.size(); off += scalar_size(e.props[p].type), ++p) {
            const int s = plan.prop_slot[p];
            if (s >= 0) offset[s] = off;
        }
        auto decode = [&](int first, std::vector<Eigen::Vector3d>& out) {
            TripleLayout l{};
            for (int k = 0; k < 3; ++k) {
                l.base[k] = pos_ + offset[first + k];
                l.stride[k] = min_size;
                l.type[k] = e.props[static_cast<size_t>(plan.slot_prop[first + k])].type;
            }
            decode_triples(l, n, first == kRed ? color_divisor(l.type[0]) : 1.0, swap_, out.data());
        };
        decode(kX, cloud.points);
        if (plan.normals) decode(kNx, cloud.normals);
        if (plan.colors) decode(kRed, cloud.colors);
        pos_ += n * min_size;
    }

private:
    /// @brief Walk one record with lists; with a plan, collect the kept values into `values`.
    void walk_record(const PlyElement& e, uint64_t r, const VertexPlan* plan, double* values) {
        for (size_t p = 0; p < e.props.size(); ++p) {
            const PlyProperty& prop = e.props[p];
            if (!prop.is_list) {
                const size_t size = scalar_size(prop.type);
                if (remaining() < size) truncated_at(e, r);
                if (plan) {
                    const int s = plan->prop_slot[p];
                    if (s >= 0) {
                        const double v = load_as_double(pos_, prop.type, swap_);
                        values[s] = s >= kRed ? v / color_divisor(prop.type) : v;
                    }
                }
                pos_ += size;
                continue;
            }
            const size_t count_size = scalar_size(prop.count_type);
            if (remaining() < count_size) truncated_at(e, r);
            const int64_t len = load_as_int64(pos_, prop.count_type, swap_);
            pos_ += count_size;
            if (len < 0)
                parse_error(in_, "PLY: " + e.name + " " + std::to_string(r) + " has a negative length for list '" +
                                     prop.name + "'");
            const size_t item = scalar_size(prop.type);
            if (static_cast<uint64_t>(len) > remaining() / item) truncated_at(e, r);
            pos_ += static_cast<size_t>(len) * item;
        }
    }

    [[noreturn]] void truncated(const PlyElement& e, size_t record) {
        parse_error(in_, "PLY: element '" + e.name + "' declares " + count_text(e.count, "records") + " of at least " +
                             std::to_string(record) + " bytes but only " + std::to_string(remaining()) +
                             " bytes of data are left (truncated file or wrong count)");
    }
    [[noreturn]] void truncated_at(const PlyElement& e, uint64_t r) {
        parse_error(in_, "PLY: data ends inside " + e.name + " " + std::to_string(r) + " of " + std::to_string(e.count) +
                             " (truncated file or wrong count)");
    }

    const Input& in_;
    const uint8_t* pos_;
    bool swap_;
};

class AsciiReader {
public:
    AsciiReader(const Input& in, size_t offset) : in_(in), cur_(in.chars() + offset, in.chars_end()) {}

    void skip_element(const PlyElement& e) {
        if (e.props.empty()) return;
        for (uint64_t r = 0; r < e.count; ++r) walk_record(e, r, nullptr, nullptr);
    }

    void read_vertices(const PlyElement& e, const VertexPlan& plan, geometry::PointCloud& cloud) {
        // Each value needs at least one character and one separator: bound the count by the
        // bytes left before allocating anything for it.
        const size_t max_tokens = (cur_.remaining() + 1) / 2;
        if (e.count > max_tokens / e.props.size())
            parse_error(in_, "PLY: the vertex element declares " + count_text(e.count, "vertices") + " of " +
                                 std::to_string(e.props.size()) + " values but only " +
                                 std::to_string(cur_.remaining()) + " bytes of text are left");
        const size_t n = static_cast<size_t>(e.count);
        plan.allocate(cloud, n);
        double values[kSlotCount];
        for (size_t i = 0; i < n; ++i) {
            walk_record(e, i, &plan, values);
            plan.store(cloud, i, values);
        }
    }

    void finish() {
        if (!cur_.only_whitespace_left())
            parse_error(in_, "PLY: text follows the last element (the header's counts are too small)");
    }

private:
    void walk_record(const PlyElement& e, uint64_t r, const VertexPlan* plan, double* values) {
        for (size_t p = 0; p < e.props.size(); ++p) {
            const PlyProperty& prop = e.props[p];
            if (!prop.is_list && plan && plan->prop_slot[p] >= 0) {
                const int s = plan->prop_slot[p];
                double v;
                std::string_view tok;
                if (!cur_.number(v, tok)) {
                    if (tok.empty()) truncated_at(e, r);
                    bad_number(e, r, prop, tok);
                }
                values[s] = s >= kRed ? v / color_divisor(prop.type) : v;
                continue;
            }
            const std::string_view tok = cur_.token();
            if (tok.empty()) truncated_at(e, r);
            if (!prop.is_list) continue;
            int64_t len;
            if (!parse_int64(tok, len)) bad_number(e, r, prop, tok);
            if (len < 0)
                parse_error(in_, "PLY: " + e.name + " " + std::to_string(r) + " has a negative length for list '" +
                                     prop.name + "'");
            for (int64_t k = 0; k < len; ++k)
                if (!cur_.skip_token()) truncated_at(e, r);
        }
    }

    [[noreturn]] void truncated_at(const PlyElement& e, uint64_t r) {
        parse_error(in_, "PLY: the text ends inside " + e.name + " " + std::to_string(r) + " of " +
                             std::to_string(e.count) + " (truncated file or wrong count)");
    }
    [[noreturn]] void bad_number(const PlyElement& e, uint64_t r, const PlyProperty& p, std::string_view tok) {
        parse_error(in_, "PLY: " + e.name + " " + std::to_string(r) + ", property '" + p.name + "': '" +
                             std::string(tok.substr(0, 32)) + "' is not a number");
    }

    const Input& in_;
    TextCursor cur_;
};

}  // namespace

geometry::PointCloud read_ply(const Input& in) {
    const PlyHeader h = parse_header(in);
    const PlyElement* vertex = nullptr;
    for (const auto& e : h.elements)
        if (e.name == "vertex") {
            vertex = &e;
            break;
        }
    if (!vertex) parse_error(in, "PLY: the header declares no vertex element");
    const VertexPlan plan(in, *vertex);

    geometry::PointCloud cloud;
    if (h.encoding == PlyEncoding::Ascii) {
        AsciiReader r(in, h.data_offset);
        for (const auto& e : h.elements) {
            if (&e == vertex) r.read_vertices(e, plan, cloud);
            else r.skip_element(e);
        }
        r.finish();
    } else {
        const bool file_little = h.encoding == PlyEncoding::BinaryLittle;
        BinaryReader r(in, h.data_offset, file_little != kHostLittleEndian);
        for (const auto& e : h.elements) {
            if (&e == vertex) r.read_vertices(e, plan, cloud);
            else r.skip_element(e);
        }
    }
    return cloud;
}

}  // namespace o3d::io::detail
