// SPDX-License-Identifier: MIT
// Replays the committed seed corpus and deterministic mutations of every seed through the
// point-cloud, triangle-mesh, image and feature readers. Passing means: no crash, no sanitizer report,
// and no exception but o3d::ParseError. Seeds live in corpus/<format>/ (point clouds),
// corpus/mesh_<format>/, corpus/image_<format>/ and corpus/feature_bin/ (Open3D's binary feature files).
// `io_fuzz_replay --write-seeds DIR` regenerates the writer-made seeds.
#include <dirent.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstring>
#include <algorithm>
#include <exception>
#include <stdexcept>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "o3d/io/feature_io.h"
#include "o3d/io/image_io.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"

namespace {

using Bytes = std::vector<uint8_t>;
const char* const kFormats[] = {"ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts"};
const char* const kMeshFormats[] = {"ply", "obj", "stl", "off", "glb", "gltf"};
const char* const kImageFormats[] = {"png", "jpg", "ppm", "pgm"};
const char* const kFeatureFormats[] = {"bin"};
constexpr int kMutationsPerSeed = 3000;

struct Rng {
    uint64_t s;
    uint64_t next() {  // splitmix64: tiny, and the same sequence on every platform
        uint64_t z = (s += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    size_t below(size_t n) { return n ? static_cast<size_t>(next() % n) : 0; }
};

/// @brief One random edit of the kinds that break parsers: bit flips, boundary bytes, cuts,
/// deleted and duplicated spans, and header numbers swapped for extreme ones.
void mutate(Bytes& b, Rng& rng) {
    static const char* const kNumbers[] = {"-1", "0", "4294967295", "4294967296", "18446744073709551615",
                                           "9223372036854775807", "99999999999999999999", "1e400", "nan", "-0"};
    static const uint8_t kBytes[] = {0, 0xff, '\n', '\r', ' ', '-', '9', '.', 'e', 0x80, 0x7f};
    const size_t n = b.size();
    switch (rng.below(7)) {
        case 0:
            if (n) b[rng.below(n)] ^= static_cast<uint8_t>(1u << rng.below(8));
            break;
        case 1:
            if (n) b[rng.below(n)] = kBytes[rng.below(sizeof kBytes)];
            break;
        case 2: b.resize(rng.below(n + 1)); break;
        case 3: {
            const size_t at = rng.below(n + 1), len = rng.below(std::min<size_t>(n - at, 64) + 1);
            b.erase(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + len));
            break;
        }
        case 4: {
            const size_t at = rng.below(n + 1), len = rng.below(std::min<size_t>(n - at, 64) + 1);
            const Bytes span(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(at + len));
            b.insert(b.begin() + static_cast<long>(rng.below(n + 1)), span.begin(), span.end());
            break;
        }
        case 5: {
            const size_t at = rng.below(n + 1), len = rng.below(9);
            for (size_t k = 0; k < len; ++k) b.insert(b.begin() + static_cast<long>(at), static_cast<uint8_t>(rng.next()));
            break;
        }
        default: {
            // Replace the k-th run of digits (header counts, sizes) with an extreme number.
            std::vector<size_t> starts;
            for (size_t i = 0; i < n; ++i)
                if (b[i] >= '0' && b[i] <= '9' && (i == 0 || b[i - 1] < '0' || b[i - 1] > '9')) starts.push_back(i);
            if (starts.empty()) break;
            const size_t at = starts[rng.below(std::min<size_t>(starts.size(), 40))];
            size_t end = at;
            while (end < n && b[end] >= '0' && b[end] <= '9') ++end;
            const char* num = kNumbers[rng.below(sizeof kNumbers / sizeof *kNumbers)];
            b.erase(b.begin() + static_cast<long>(at), b.begin() + static_cast<long>(end));
            b.insert(b.begin() + static_cast<long>(at), num, num + std::strlen(num));
        }
    }
}

uint64_t fnv1a(const std::string& s) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
    return h;
}

int failures = 0;

/// @brief Read `b` as a cloud in `format`, write it back and re-read it.
void read_cloud(const Bytes& b, const char* format) {
    o3d::io::ReadOptions options;
    options.remove_nan_points = b.size() % 2 == 1;
    const auto cloud = o3d::io::read_point_cloud_from_memory(b.data(), b.size(), format, options);
    const auto again = o3d::io::write_point_cloud_to_memory(cloud, format);
    if (o3d::io::read_point_cloud_from_memory(again.data(), again.size(), format).size() != cloud.size())
        throw std::runtime_error("re-reading the written cloud changed its size");
}

/// @brief Read `b` as a mesh in `format` (post-processed for odd sizes), write it back and re-read it.
void read_mesh(const Bytes& b, const char* format) {
    o3d::io::MeshReadOptions options;
    options.enable_post_processing = b.size() % 2 == 1;
    const auto mesh = o3d::io::read_triangle_mesh_from_memory(b.data(), b.size(), format, options);
    o3d::io::MeshWriteOptions w;
    w.write_ascii = b.size() % 3 == 0;
    const auto again = o3d::io::write_triangle_mesh_to_memory(mesh, format, w);
    if (o3d::io::read_triangle_mesh_from_memory(again.data(), again.size(), format).triangles.size() !=
        mesh.triangles.size())
        throw std::runtime_error("re-reading the written mesh changed its triangle count");
}

/// @brief Read `b` as an image in `format`, write it back and re-read it: as PNG (which holds every
/// 8/16-bit image a reader returns), or for PNM as the PGM or PPM its channel count asks for (a PNM
/// reader takes either kind).
void read_image(const Bytes& b, const char* format) {
    const auto image = o3d::io::read_image_from_memory(b.data(), b.size(), format);
    const bool pnm = std::strcmp(format, "ppm") == 0 || std::strcmp(format, "pgm") == 0;
    const char* out = pnm ? (image.num_channels == 1 ? "pgm" : "ppm") : "png";
    const auto again = o3d::io::write_image_to_memory(image, out);
    const auto back = o3d::io::read_image_from_memory(again.data(), again.size(), out);
    if (back.width != image.width || back.height != image.height || back.num_channels != image.num_channels)
        throw std::runtime_error("re-reading the written image changed its shape");
}

/// @brief Read `b` as a feature file, write it back and re-read it.
void read_feature(const Bytes& b, const char*) {
    const auto feature = o3d::io::read_feature_from_memory(b.data(), b.size());
    const auto again = o3d::io::write_feature_to_memory(feature);
    if (o3d::io::read_feature_from_memory(again.data(), again.size()).data != feature.data)
        throw std::runtime_error("re-reading the written feature changed it");
}

using Reader = void (*)(const Bytes&, const char*);

/// @brief Run `read` on `b`; anything but success or a ParseError naming "<memory>" is reported
/// (images may also be o3d::Unsupported: a valid variant the reader does not take, such as ASCII PNM).
void read_one(Reader read, const Bytes& b, const char* format, const std::string& what) {
    try {
        try {
            read(b, format);
        } catch (const o3d::Unsupported& e) {
            if (read != read_image) throw;
            throw o3d::ParseError(e.what());
        }
    } catch (const o3d::ParseError& e) {
        if (std::strstr(e.what(), "<memory>: ") != e.what()) {
            ++failures;
            std::fprintf(stderr, "FAIL %s as %s: ParseError without the source name: %s\n", what.c_str(), format,
                         e.what());
        }
    } catch (const std::exception& e) {
        ++failures;
        std::fprintf(stderr, "FAIL %s as %s: %s\n", what.c_str(), format, e.what());
    }
}

Bytes slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    const std::string s = ss.str();
    return Bytes(s.begin(), s.end());
}

std::vector<std::string> list_files(const std::string& dir) {
    std::vector<std::string> out;
    if (DIR* d = opendir(dir.c_str())) {
        while (const dirent* e = readdir(d))
            if (e->d_name[0] != '.') out.push_back(dir + "/" + e->d_name);
        closedir(d);
    }
    return out;
}

o3d::geometry::PointCloud tiny_cloud(bool normals, bool colors) {
    o3d::geometry::PointCloud pc;
    const double xyz[3][3] = {{0.5, -1.25, 3}, {1e-3, 2.5e4, -7}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i) {
        pc.points.emplace_back(xyz[i][0], xyz[i][1], xyz[i][2]);
        if (normals) pc.normals.emplace_back(0, i == 1 ? 1 : 0, i == 1 ? 0 : 1);
        if (colors) pc.colors.emplace_back(i / 2.0, 1.0, 0.2);
    }
    return pc;
}

void save(const std::string& dir, const std::string& sub, const std::string& name, const Bytes& b) {
    const std::string folder = dir + "/" + sub;
    mkdir(folder.c_str(), 0755);
    const std::string path = folder + "/" + name;
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), static_cast<long>(b.size()));
    std::printf("wrote %s (%zu bytes)\n", path.c_str(), b.size());
}

/// @brief A square pyramid (a quad base, four sides) with normals, colours and UVs.
o3d::geometry::TriangleMesh tiny_mesh() {
    o3d::geometry::TriangleMesh m;
    const double xyz[5][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 0.75}};
    for (int i = 0; i < 5; ++i) {
        m.vertices.emplace_back(xyz[i][0], xyz[i][1], xyz[i][2]);
        m.vertex_normals.emplace_back(xyz[i][0] - 0.5, xyz[i][1] - 0.5, xyz[i][2] - 0.25);
        m.vertex_colors.emplace_back(i / 4.0, 1.0, 0.2);
    }
    const int tris[6][3] = {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    for (const auto& t : tris) {
        m.triangles.emplace_back(t[0], t[1], t[2]);
        for (int k = 0; k < 3; ++k) m.triangle_uvs.emplace_back(xyz[t[k]][0], xyz[t[k]][1]);
    }
    return m;
}

o3d::geometry::Image tiny_image(int channels, int bytes) {
    o3d::geometry::Image im;
    im.width = 5;
    im.height = 3;
    im.num_channels = channels;
    im.bytes_per_channel = bytes;
    im.data.resize(im.byte_size());
    for (size_t i = 0; i < im.data.size(); ++i) im.data[i] = static_cast<uint8_t>(i * 37 + 11);
    return im;
}

int write_seeds(const std::string& dir) {
    struct Seed {
        const char* format;
        bool ascii, compressed, normals, colors;
    };
    const Seed seeds[] = {{"ply", false, false, true, true}, {"ply", true, false, true, true},
                          {"ply", false, false, false, false}, {"pcd", false, false, true, true},
                          {"pcd", true, false, true, true},   {"pcd", false, true, true, true},
                          {"xyz", false, false, false, false}, {"xyzn", false, false, true, false},
                          {"xyzrgb", false, false, false, true}, {"pts", false, false, false, true},
                          {"pts", false, false, false, false}};
    for (const Seed& s : seeds) {
        o3d::io::WriteOptions w;
        w.write_ascii = s.ascii;
        w.compressed = s.compressed;
        const Bytes b = o3d::io::write_point_cloud_to_memory(tiny_cloud(s.normals, s.colors), s.format, w);
        save(dir, s.format,
             std::string("written") + (s.ascii ? "_ascii" : "") + (s.compressed ? "_compressed" : "") +
                 (s.normals ? "_normals" : "") + (s.colors ? "_colors" : "") + "." + s.format,
             b);
    }
    for (const char* f : kMeshFormats)
        for (bool ascii : {false, true}) {
            const std::string fmt = f;
            if (ascii && fmt != "ply" && fmt != "stl") continue;
            o3d::io::MeshWriteOptions w;
            w.write_ascii = ascii;
            save(dir, "mesh_" + fmt, std::string("written") + (ascii ? "_ascii" : "") + "." + fmt,
                 o3d::io::write_triangle_mesh_to_memory(tiny_mesh(), fmt, w));
        }
    const struct {
        const char* format;
        int channels, bytes;
    } images[] = {{"png", 3, 1}, {"png", 1, 2}, {"png", 4, 1}, {"jpg", 3, 1}, {"jpg", 1, 1},
                  {"ppm", 3, 1}, {"ppm", 3, 2}, {"pgm", 1, 1}, {"pgm", 1, 2}};
    for (const auto& im : images)
        save(dir, std::string("image_") + im.format,
             "written_" + std::to_string(im.channels) + "x" + std::to_string(8 * im.bytes) + "." + im.format,
             o3d::io::write_image_to_memory(tiny_image(im.channels, im.bytes), im.format));
    for (const int num : {0, 2, 5}) {
        o3d::registration::Feature f;
        f.data.resize(3, num);
        for (int i = 0; i < 3 * num; ++i) f.data(i % 3, i / 3) = 0.5 * i - 1.0;
        save(dir, "feature_bin", "written_3x" + std::to_string(num) + ".bin", o3d::io::write_feature_to_memory(f));
    }
    return 0;
}

/// @brief The seeds of one family under root/<prefix><format>/: each must read as its own format, and
/// neither it nor thousands of mutations of it may crash any reader of the family.
template <size_t N>
void replay(const std::string& root, const std::string& prefix, const char* const (&formats)[N], Reader read,
            size_t& seeds, size_t& inputs) {
    for (const char* format : formats) {
        for (const std::string& path : list_files(root + "/" + prefix + format)) {
            const Bytes seed = slurp(path);
            ++seeds;
            try {
                read(seed, format);
            } catch (const std::exception& e) {
                ++failures;
                std::fprintf(stderr, "FAIL seed %s does not read: %s\n", path.c_str(), e.what());
            }
            for (const char* other : formats) read_one(read, seed, other, path);
            Rng rng{fnv1a(path.substr(root.size()))};
            for (int m = 0; m < kMutationsPerSeed; ++m) {
                Bytes b = seed;
                const size_t edits = 1 + rng.below(4);
                for (size_t e = 0; e < edits; ++e) mutate(b, rng);
                read_one(read, b, format, path + " mutation " + std::to_string(m));
                ++inputs;
            }
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 3 && std::strcmp(argv[1], "--write-seeds") == 0) return write_seeds(argv[2]);
    const std::string root = argc > 1 ? argv[1] : O3D_FUZZ_CORPUS;
    size_t seeds = 0, inputs = 0;
    replay(root, "", kFormats, read_cloud, seeds, inputs);
    const size_t cloud_seeds = seeds;
    replay(root, "mesh_", kMeshFormats, read_mesh, seeds, inputs);
    const size_t mesh_seeds = seeds - cloud_seeds;
    replay(root, "image_", kImageFormats, read_image, seeds, inputs);
    const size_t image_seeds = seeds - cloud_seeds - mesh_seeds;
    replay(root, "feature_", kFeatureFormats, read_feature, seeds, inputs);
    const size_t feature_seeds = seeds - cloud_seeds - mesh_seeds - image_seeds;
    std::printf("%zu seeds (%zu clouds, %zu meshes, %zu images, %zu features), %zu mutated inputs, %d failures\n",
                seeds, cloud_seeds, mesh_seeds, image_seeds, feature_seeds, inputs, failures);
    if (cloud_seeds < 6 || mesh_seeds < 6 || image_seeds < 4 || feature_seeds < 2) {
        std::fprintf(stderr,
                     "FAIL: expected seeds under %s/<format>/, mesh_<format>/, image_<format>/ and feature_bin/\n",
                     root.c_str());
        return 1;
    }
    return failures ? 1 : 0;
}
