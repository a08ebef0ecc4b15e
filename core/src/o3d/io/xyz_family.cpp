// SPDX-License-Identifier: MIT
// The line-oriented text formats: XYZ (x y z), XYZN (+ nx ny nz), XYZRGB (+ r g b in [0,1]) and
// PTS (a point count line, then x y z [intensity] [r g b] with colours 0..255; Leica files may
// hold several such blocks one after another).
#include <string>
#include <string_view>

#include "o3d/io/byte_reader.h"
#include "o3d/io/io_internal.h"
#include "o3d/io/text_writer.h"
#include "o3d/utility/error.h"

namespace o3d::io::detail {
namespace {

enum class Extra { None, Normals, Colors };

bool skippable(std::string_view line) {
    TextCursor c(line);
    const std::string_view t = c.token();
    return t.empty() || t[0] == '#';
}

std::string quote(std::string_view s) { return "'" + std::string(s.substr(0, 40)) + (s.size() > 40 ? "...'" : "'"); }

/// @brief Read `want` numbers from the start of `line`; extra columns are ignored, as Open3D's
/// sscanf-based readers do.
bool parse_row(std::string_view line, int want, double* v) {
    TextCursor c(line);
    std::string_view tok;
    for (int k = 0; k < want; ++k)
        if (!c.number(v[k], tok)) return false;
    return true;
}

geometry::PointCloud read_columns(const Input& in, Extra extra, const char* format) {
    const int want = extra == Extra::None ? 3 : 6;
    geometry::PointCloud cloud;
    // Rows never outnumber lines: reserving by the line count is bounded by the input itself.
    const size_t max_rows = count_lines(in.chars(), in.chars_end()) + 1;
    cloud.points.reserve(max_rows);
    if (extra == Extra::Normals) cloud.normals.reserve(max_rows);
    if (extra == Extra::Colors) cloud.colors.reserve(max_rows);

    TextCursor cur(in.chars(), in.chars_end());
    size_t line_no = 0;
    double v[6];
    while (!cur.at_end()) {
        ++line_no;
        const std::string_view line = cur.line();
        if (skippable(line)) continue;
        if (!parse_row(line, want, v))
            parse_error(in, std::string(format) + ": line " + std::to_string(line_no) + ": expected " +
                                std::to_string(want) + " numbers, got " + quote(line));
        cloud.points.emplace_back(v[0], v[1], v[2]);
        if (extra == Extra::Normals) cloud.normals.emplace_back(v[3], v[4], v[5]);
        if (extra == Extra::Colors) cloud.colors.emplace_back(v[3], v[4], v[5]);
    }
    return cloud;
}

size_t count_tokens(std::string_view line) {
    TextCursor c(line);
    size_t n = 0;
    while (c.skip_token()) ++n;
    return n;
}

void put_triple(ByteSink& out, const Eigen::Vector3d& v) {
    out.put_number(v[0]);
    out.put(' ');
    out.put_number(v[1]);
    out.put(' ');
    out.put_number(v[2]);
}

std::vector<uint8_t> write_columns(const geometry::PointCloud& cloud, Extra extra, const char* format) {
    if (extra == Extra::Normals && !cloud.has_normals() && cloud.has_points())
        throw InvalidArgument(std::string(format) + " needs normals but the point cloud has none");
    if (extra == Extra::Colors && !cloud.has_colors() && cloud.has_points())
        throw InvalidArgument(std::string(format) + " needs colors but the point cloud has none");
    ByteSink out(cloud.size() * (extra == Extra::None ? 64 : 128));
    for (size_t i = 0; i < cloud.size(); ++i) {
        put_triple(out, cloud.points[i]);
        if (extra != Extra::None) {
            out.put(' ');
            put_triple(out, extra == Extra::Normals ? cloud.normals[i] : cloud.colors[i]);
        }
        out.put('\n');
    }
    return out.finish();
}

}  // namespace

geometry::PointCloud read_xyz(const Input& in) { return read_columns(in, Extra::None, "XYZ"); }
geometry::PointCloud read_xyzn(const Input& in) { return read_columns(in, Extra::Normals, "XYZN"); }
geometry::PointCloud read_xyzrgb(const Input& in) { return read_columns(in, Extra::Colors, "XYZRGB"); }

std::vector<uint8_t> write_xyz(const geometry::PointCloud& cloud) { return write_columns(cloud, Extra::None, "XYZ"); }
std::vector<uint8_t> write_xyzn(const geometry::PointCloud& cloud) {
    return write_columns(cloud, Extra::Normals, "XYZN");
}
std::vector<uint8_t> write_xyzrgb(const geometry::PointCloud& cloud) {
    return write_columns(cloud, Extra::Colors, "XYZRGB");
}

geometry::PointCloud read_pts(const Input& in) {
    TextCursor cur(in.chars(), in.chars_end());
    const size_t max_rows = count_lines(in.chars(), in.chars_end()) + 1;
    geometry::PointCloud cloud;
    size_t line_no = 0;
    size_t columns = 0;  // of the first row; fixes the layout for the whole file
    bool colors = false;
    bool any_block = false;

    auto next_line = [&](std::string_view& line) {
        while (!cur.at_end()) {
            ++line_no;
            line = cur.line();
            if (!skippable(line)) return true;
        }
        return false;
    };
    auto where = [&] { return "PTS: line " + std::to_string(line_no) + ": "; };

    std::string_view line;
    while (next_line(line)) {
        // A block: a point count, then that many rows.
        TextCursor lc(line);
        int64_t count = 0;
        const std::string_view tok = lc.token();
        if (!parse_int64(tok, count) || !lc.token().empty())
            parse_error(in, where() + (any_block ? "expected a point count to start the next block (more rows than "
                                                   "the count announced), got "
                                                 : "expected the point count, got ") +
                                quote(line));
        if (count < 0) parse_error(in, where() + "negative point count " + std::to_string(count));
        if (static_cast<uint64_t>(count) > max_rows)
            parse_error(in, where() + "the count " + std::to_string(count) + " exceeds the " +
                                std::to_string(max_rows) + " lines in the file");
        any_block = true;
        for (int64_t r = 0; r < count; ++r) {
            if (!next_line(line))
                parse_error(in, "PTS: the file ends after " + std::to_string(r) + " of the " + std::to_string(count) +
                                    " rows its count announced");
            if (columns == 0) {
                columns = count_tokens(line);
                if (columns != 3 && columns != 4 && columns != 6 && columns != 7)
                    parse_error(in, where() + "a row must be x y z [i] [r g b], got " + std::to_string(columns) +
                                        " columns");
                colors = columns >= 6;
                const size_t expect = cloud.points.size() + static_cast<size_t>(count);
                cloud.points.reserve(expect);
                if (colors) cloud.colors.reserve(expect);
            }
            double v[7];
            if (!parse_row(line, static_cast<int>(columns), v))
                parse_error(in, where() + "expected " + std::to_string(columns) + " numbers, got " + quote(line));
            cloud.points.emplace_back(v[0], v[1], v[2]);
            if (colors) {
                const double* c = v + (columns == 7 ? 4 : 3);
                cloud.colors.emplace_back(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
            }
        }
    }
    if (!any_block) parse_error(in, "PTS: no point count line");
    return cloud;
}

std::vector<uint8_t> write_pts(const geometry::PointCloud& cloud) {
    const bool colors = cloud.has_colors();
    ByteSink out(32 + cloud.size() * 80);
    out.put_number(cloud.size());
    out.put('\n');
    for (size_t i = 0; i < cloud.size(); ++i) {
        put_triple(out, cloud.points[i]);
        if (colors) {
            // x y z intensity r g b, as Open3D writes it: both of its readers take seven columns.
            out.put(" 0");
            for (int k = 0; k < 3; ++k) {
                out.put(' ');
                out.put_number(static_cast<unsigned>(color_to_u8(cloud.colors[i][k])));
            }
        }
        out.put('\n');
    }
    return out.finish();
}

}  // namespace o3d::io::detail
