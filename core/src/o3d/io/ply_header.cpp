// SPDX-License-Identifier: MIT
// PLY header parsing, shared by the point-cloud and mesh readers.
#include <string>
#include <string_view>

#include "o3d/io/ply_format.h"

namespace o3d::io::detail {
namespace {

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

}  // namespace

PlyHeader parse_ply_header(const Input& in) {
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

}  // namespace o3d::io::detail
