// SPDX-License-Identifier: MIT
// PLY element reading: ascii, binary_little_endian, binary_big_endian. The vertex element's x y z,
// nx ny nz, red green blue (and for meshes u v) and the face element's vertex index and texcoord lists are
// kept; every other property and element is walked and skipped, so a truncated or inconsistent file is
// caught wherever the damage is.
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "o3d/io/file_bytes.h"
#include "o3d/io/mesh_io_internal.h"
#include "o3d/io/ply_format.h"

namespace o3d::io::detail {
namespace {

// The vertex attributes read, in sink order.
enum Slot { kX, kY, kZ, kNx, kNy, kNz, kRed, kGreen, kBlue, kU, kV, kSlotCount };

int slot_of(const std::string& n) {
    static const char* const kNames[kRed + 3] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue"};
    for (int s = 0; s < kRed + 3; ++s)
        if (n == kNames[s]) return s;
    if (n == "u" || n == "s" || n == "texture_u") return kU;
    if (n == "v" || n == "t" || n == "texture_v") return kV;
    return -1;
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

template <typename T>
void allocate(std::vector<T>* v, size_t n) {
    v->resize(n);
    prefault(v->data(), n * sizeof(T));
}

/// @brief Where the kept vertex attributes are, and where they go.
struct VertexPlan {
    int slot_prop[kSlotCount];   // property index per slot, -1 when absent or not wanted
    std::vector<int> prop_slot;  // slot per property, -1 for the skipped ones
    bool normals = false;
    bool colors = false;
    bool uvs = false;
    const PlyVertexSink& sink;

    VertexPlan(const Input& in, const PlyElement& v, const PlyVertexSink& s) : sink(s) {
        for (int& p : slot_prop) p = -1;
        prop_slot.assign(v.props.size(), -1);
        for (size_t i = 0; i < v.props.size(); ++i) {
            const int slot = slot_of(v.props[i].name);
            if (slot < 0 || slot_prop[slot] >= 0 || !wanted(slot)) continue;
            if (v.props[i].is_list)
                parse_error(in, "PLY: vertex property '" + v.props[i].name + "' is a list, not a scalar");
            slot_prop[slot] = static_cast<int>(i);
            prop_slot[i] = slot;
        }
        if (slot_prop[kX] < 0 || slot_prop[kY] < 0 || slot_prop[kZ] < 0)
            parse_error(in, "PLY: the vertex element lacks an x, y or z property");
        normals = slot_prop[kNx] >= 0 && slot_prop[kNy] >= 0 && slot_prop[kNz] >= 0;
        colors = slot_prop[kRed] >= 0 && slot_prop[kGreen] >= 0 && slot_prop[kBlue] >= 0;
        uvs = slot_prop[kU] >= 0 && slot_prop[kV] >= 0;
    }

    bool wanted(int slot) const {
        if (slot <= kZ) return true;
        if (slot <= kNz) return sink.normals != nullptr;
        if (slot <= kBlue) return sink.colors != nullptr;
        return sink.uvs != nullptr;
    }

    /// @brief The value of property p as stored (colours scaled to [0,1]).
    static double scaled(int slot, double v, ScalarType t) { return slot >= kRed && slot <= kBlue ? v / color_divisor(t) : v; }

    void allocate_all(size_t n) const {
        allocate(sink.points, n);
        if (normals) allocate(sink.normals, n);
        if (colors) allocate(sink.colors, n);
        if (uvs) allocate(sink.uvs, n);
    }

    /// @brief Store one vertex whose kept values are in `v` (colours already scaled).
    void store(size_t i, const double* v) const {
        (*sink.points)[i] = Eigen::Vector3d(v[kX], v[kY], v[kZ]);
        if (normals) (*sink.normals)[i] = Eigen::Vector3d(v[kNx], v[kNy], v[kNz]);
        if (colors) (*sink.colors)[i] = Eigen::Vector3d(v[kRed], v[kGreen], v[kBlue]);
        if (uvs) (*sink.uvs)[i] = Eigen::Vector2d(v[kU], v[kV]);
    }
};

/// @brief Which lists of the face element are kept, and the polygon being assembled.
struct FacePlan {
    int index_prop = -1;
    int uv_prop = -1;
    const PlyFaceSink& sink;
    std::vector<int64_t> corners;
    std::vector<double> corner_uvs;

    FacePlan(const Input& in, const PlyElement& f, const PlyFaceSink& s) : sink(s) {
        for (size_t i = 0; i < f.props.size(); ++i) {
            const PlyProperty& p = f.props[i];
            if (!p.is_list) continue;
            if (index_prop < 0 && (p.name == "vertex_indices" || p.name == "vertex_index")) {
                if (!is_integer(p.type)) parse_error(in, "PLY: the face list '" + p.name + "' must hold integers");
                index_prop = static_cast<int>(i);
            } else if (uv_prop < 0 && p.name == "texcoord" && s.corner_uvs) {
                uv_prop = static_cast<int>(i);
            }
        }
        if (index_prop < 0 && f.count > 0)
            parse_error(in, "PLY: the face element has no vertex_indices (or vertex_index) list");
    }

    void begin() {
        corners.clear();
        corner_uvs.clear();
    }

    /// @brief Emit the polygon just read as triangles (a fan, as Open3D does).
    void finish(const Input& in, uint64_t r) {
        const size_t n = corners.size();
        if (n < 3) parse_error(in, "PLY: face " + std::to_string(r) + " has " + std::to_string(n) + " corners (< 3)");
        for (int64_t c : corners)
            if (c < 0 || c > INT32_MAX)
                parse_error(in, "PLY: face " + std::to_string(r) + " has the vertex index " + std::to_string(c) +
                                    ", out of range");
        if (uv_prop >= 0 && !corner_uvs.empty() && corner_uvs.size() != 2 * n)
            parse_error(in, "PLY: face " + std::to_string(r) + " has " + std::to_string(corner_uvs.size()) +
                                " texcoord values for " + std::to_string(n) + " corners");
        fan_triangulate(n, [&](size_t a, size_t b, size_t c) {
            sink.triangles->emplace_back(static_cast<int>(corners[a]), static_cast<int>(corners[b]),
                                         static_cast<int>(corners[c]));
            if (uv_prop < 0) return;
            for (size_t k : {a, b, c})
                sink.corner_uvs->emplace_back(corner_uvs.empty() ? 0.0 : corner_uvs[2 * k],
                                              corner_uvs.empty() ? 0.0 : corner_uvs[2 * k + 1]);
        });
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
        for (uint64_t r = 0; r < e.count; ++r) walk_record(e, r, nullptr, nullptr, nullptr);
    }

    void read_vertices(const PlyElement& e, const VertexPlan& plan) {
        const size_t min_size = e.min_record_size();
        if (min_size == 0 || e.count > remaining() / min_size) truncated(e, min_size);
        const size_t n = static_cast<size_t>(e.count);
        plan.allocate_all(n);
        if (e.has_list()) {
            double values[kSlotCount];
            for (size_t i = 0; i < n; ++i) {
                walk_record(e, i, &plan, values, nullptr);
                plan.store(i, values);
            }
            return;
        }
        // Fixed-size records: decode each attribute with one tight loop over the records.
        size_t offset[kSlotCount] = {};
        for (size_t p = 0, off = 0; p < e.props.size(); off += scalar_size(e.props[p].type), ++p) {
            const int s = plan.prop_slot[p];
            if (s >= 0) offset[s] = off;
        }
        auto type_of = [&](int slot) { return e.props[static_cast<size_t>(plan.slot_prop[slot])].type; };
        auto decode = [&](int first, std::vector<Eigen::Vector3d>& out) {
            TripleLayout l{};
            for (int k = 0; k < 3; ++k) {
                l.base[k] = pos_ + offset[first + k];
                l.stride[k] = min_size;
                l.type[k] = type_of(first + k);
            }
            decode_triples(l, n, first == kRed ? color_divisor(l.type[0]) : 1.0, swap_, out.data());
        };
        decode(kX, *plan.sink.points);
        if (plan.normals) decode(kNx, *plan.sink.normals);
        if (plan.colors) decode(kRed, *plan.sink.colors);
        if (plan.uvs) {
            auto& uv = *plan.sink.uvs;
            for (size_t i = 0; i < n; ++i) {
                uv[i][0] = load_as_double(pos_ + i * min_size + offset[kU], type_of(kU), swap_);
                uv[i][1] = load_as_double(pos_ + i * min_size + offset[kV], type_of(kV), swap_);
            }
        }
        pos_ += n * min_size;
    }

    void read_faces(const PlyElement& e, FacePlan& plan) {
        const size_t min_size = e.min_record_size();
        if (e.count > remaining() / (min_size ? min_size : 1)) truncated(e, min_size);
        plan.sink.triangles->reserve(plan.sink.triangles->size() + static_cast<size_t>(e.count));
        if (e.props.size() == 1 && !swap_ && e.props[0].count_type == ScalarType::UInt8 &&
            (e.props[0].type == ScalarType::Int32 || e.props[0].type == ScalarType::UInt32)) {
            // The layout nearly every writer uses: one uchar-counted list of 32-bit indices, mostly triangles.
            for (uint64_t r = 0; r < e.count; ++r) {
                if (remaining() >= 13 && pos_[0] == 3) {
                    int32_t t[3];
                    std::memcpy(t, pos_ + 1, 12);
                    if (t[0] >= 0 && t[1] >= 0 && t[2] >= 0) {  // UInt32 above INT32_MAX: the general path rejects it
                        plan.sink.triangles->emplace_back(t[0], t[1], t[2]);
                        pos_ += 13;
                        continue;
                    }
                }
                plan.begin();
                walk_record(e, r, nullptr, nullptr, &plan);
                plan.finish(in_, r);
            }
            return;
        }
        for (uint64_t r = 0; r < e.count; ++r) {
            plan.begin();
            walk_record(e, r, nullptr, nullptr, &plan);
            plan.finish(in_, r);
        }
    }

private:
    /// @brief Walk one record; with a vertex plan, collect the kept scalars into `values`; with a face
    /// plan, collect its index and texcoord lists.
    void walk_record(const PlyElement& e, uint64_t r, const VertexPlan* plan, double* values, FacePlan* face) {
        for (size_t p = 0; p < e.props.size(); ++p) {
            const PlyProperty& prop = e.props[p];
            if (!prop.is_list) {
                const size_t size = scalar_size(prop.type);
                if (remaining() < size) truncated_at(e, r);
                if (plan) {
                    const int s = plan->prop_slot[p];
                    if (s >= 0) values[s] = VertexPlan::scaled(s, load_as_double(pos_, prop.type, swap_), prop.type);
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
            const int p_int = static_cast<int>(p);
            if (face && p_int == face->index_prop) {
                for (int64_t k = 0; k < len; ++k) face->corners.push_back(load_as_int64(pos_ + k * item, prop.type, swap_));
            } else if (face && p_int == face->uv_prop) {
                for (int64_t k = 0; k < len; ++k)
                    face->corner_uvs.push_back(load_as_double(pos_ + k * item, prop.type, swap_));
            }
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
        for (uint64_t r = 0; r < e.count; ++r) walk_record(e, r, nullptr, nullptr, nullptr);
    }

    void read_vertices(const PlyElement& e, const VertexPlan& plan) {
        bound_count(e);
        const size_t n = static_cast<size_t>(e.count);
        plan.allocate_all(n);
        double values[kSlotCount];
        for (size_t i = 0; i < n; ++i) {
            walk_record(e, i, &plan, values, nullptr);
            plan.store(i, values);
        }
    }

    void read_faces(const PlyElement& e, FacePlan& plan) {
        bound_count(e);
        plan.sink.triangles->reserve(plan.sink.triangles->size() + static_cast<size_t>(e.count));
        for (uint64_t r = 0; r < e.count; ++r) {
            plan.begin();
            walk_record(e, r, nullptr, nullptr, &plan);
            plan.finish(in_, r);
        }
    }

    void finish() {
        if (!cur_.only_whitespace_left())
            parse_error(in_, "PLY: text follows the last element (the header's counts are too small)");
    }

private:
    /// @brief Each value needs at least one character and one separator: bound the count by the bytes
    /// left before allocating anything for it.
    void bound_count(const PlyElement& e) {
        const size_t max_tokens = (cur_.remaining() + 1) / 2;
        if (!e.props.empty() && e.count > max_tokens / e.props.size())
            parse_error(in_, "PLY: the " + e.name + " element declares " +
                                 count_text(e.count, e.name == "vertex" ? "vertices" : e.name == "face" ? "faces" : "records") + " of " +
                                 std::to_string(e.props.size()) + " values but only " +
                                 std::to_string(cur_.remaining()) + " bytes of text are left");
    }

    double number(const PlyElement& e, uint64_t r, const PlyProperty& prop) {
        double v;
        std::string_view tok;
        if (!cur_.number(v, tok)) {
            if (tok.empty()) truncated_at(e, r);
            bad_number(e, r, prop, tok);
        }
        return v;
    }

    void walk_record(const PlyElement& e, uint64_t r, const VertexPlan* plan, double* values, FacePlan* face) {
        for (size_t p = 0; p < e.props.size(); ++p) {
            const PlyProperty& prop = e.props[p];
            if (!prop.is_list && plan && plan->prop_slot[p] >= 0) {
                const int s = plan->prop_slot[p];
                values[s] = VertexPlan::scaled(s, number(e, r, prop), prop.type);
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
            const int p_int = static_cast<int>(p);
            if (face && p_int == face->index_prop) {
                for (int64_t k = 0; k < len; ++k) {
                    const std::string_view t = cur_.token();
                    if (t.empty()) truncated_at(e, r);
                    int64_t v;
                    if (!parse_int64(t, v)) bad_number(e, r, prop, t);
                    face->corners.push_back(v);
                }
            } else if (face && p_int == face->uv_prop) {
                for (int64_t k = 0; k < len; ++k) face->corner_uvs.push_back(number(e, r, prop));
            } else {
                for (int64_t k = 0; k < len; ++k)
                    if (!cur_.skip_token()) truncated_at(e, r);
            }
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

template <typename Reader>
void read_all(Reader& r, const PlyHeader& h, const PlyElement* vertex, const VertexPlan& vplan, const PlyElement* face,
              FacePlan* fplan) {
    for (const auto& e : h.elements) {
        if (&e == vertex) r.read_vertices(e, vplan);
        else if (&e == face && fplan) r.read_faces(e, *fplan);
        else r.skip_element(e);
    }
}

}  // namespace

void read_ply_elements(const Input& in, const PlyVertexSink& vertices, const PlyFaceSink* faces) {
    const PlyHeader h = parse_ply_header(in);
    const PlyElement* vertex = nullptr;
    const PlyElement* face = nullptr;
    for (const auto& e : h.elements) {
        if (!vertex && e.name == "vertex") vertex = &e;
        if (!face && e.name == "face") face = &e;
    }
    if (!vertex) parse_error(in, "PLY: the header declares no vertex element");
    const VertexPlan vplan(in, *vertex, vertices);
    std::optional<FacePlan> fplan;
    if (faces && face) fplan.emplace(in, *face, *faces);
    FacePlan* fp = fplan ? &*fplan : nullptr;

    if (h.encoding == PlyEncoding::Ascii) {
        AsciiReader r(in, h.data_offset);
        read_all(r, h, vertex, vplan, face, fp);
        r.finish();
    } else {
        const bool file_little = h.encoding == PlyEncoding::BinaryLittle;
        BinaryReader r(in, h.data_offset, file_little != kHostLittleEndian);
        read_all(r, h, vertex, vplan, face, fp);
    }
}

geometry::PointCloud read_ply(const Input& in) {
    geometry::PointCloud cloud;
    PlyVertexSink sink;
    sink.points = &cloud.points;
    sink.normals = &cloud.normals;
    sink.colors = &cloud.colors;
    read_ply_elements(in, sink, nullptr);
    return cloud;
}

}  // namespace o3d::io::detail
