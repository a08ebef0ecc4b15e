// SPDX-License-Identifier: MIT
// The PCL side of the C++ benchmark (one translation unit: PCL headers compile slowly).
#include "bench.h"

#include <pcl/common/io.h>
#include <pcl/features/fpfh_omp.h>
#include <pcl/features/normal_3d_omp.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/pcl_config.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/icp.h>
#include <pcl/search/kdtree.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace bench {

namespace {

using PointFull = pcl::PointXYZRGBNormal;

template <class P>
void fill_xyz(const Cloud& c, pcl::PointCloud<P>& out) {
    out.resize(c.size());
    for (size_t i = 0; i < c.size(); ++i) {
        out[i].x = static_cast<float>(c.pts[3 * i]);
        out[i].y = static_cast<float>(c.pts[3 * i + 1]);
        out[i].z = static_cast<float>(c.pts[3 * i + 2]);
    }
    out.width = static_cast<std::uint32_t>(c.size());
    out.height = 1;
    out.is_dense = true;
}

template <class P>
void fill_normals(const Cloud& c, pcl::PointCloud<P>& out) {
    for (size_t i = 0; i < c.size(); ++i) {
        const bool has = !c.nrm.empty();
        out[i].normal_x = has ? static_cast<float>(c.nrm[3 * i]) : 0.f;
        out[i].normal_y = has ? static_cast<float>(c.nrm[3 * i + 1]) : 0.f;
        out[i].normal_z = has ? static_cast<float>(c.nrm[3 * i + 2]) : 0.f;
        out[i].curvature = 0.f;
    }
}

pcl::PointCloud<PointFull>::Ptr full_cloud(const Cloud& c) {
    pcl::PointCloud<PointFull>::Ptr out(new pcl::PointCloud<PointFull>);
    fill_xyz(c, *out);
    fill_normals(c, *out);
    for (size_t i = 0; i < c.size(); ++i) {
        auto ch = [&](int k) {
            return c.col.empty() ? std::uint8_t(0)
                                 : static_cast<std::uint8_t>(std::lround(std::fmin(1.0, std::fmax(0.0, c.col[3 * i + k])) * 255.0));
        };
        (*out)[i].r = ch(0);
        (*out)[i].g = ch(1);
        (*out)[i].b = ch(2);
        (*out)[i].a = 255;
    }
    return out;
}

std::string file_size_mb(const std::string& path) {
    std::ifstream f(path, std::ios::binary | std::ios::ate);
    char b[32];
    std::snprintf(b, sizeof b, "%.1f MB", f ? static_cast<double>(f.tellg()) / 1e6 : 0.0);
    return b;
}

template <class P>
void check_loaded(const pcl::PointCloud<P>& c, const std::string& path) {
    if (c.empty()) throw std::runtime_error("PCL read an empty cloud from " + path);
    // A PLY with double coordinates does not map onto float fields: PCL then leaves them 0.
    bool any = false;
    for (size_t i = 0; i < c.size() && i < 1000; ++i)
        if (c[i].x != 0.f || c[i].y != 0.f || c[i].z != 0.f) any = true;
    if (!any) throw std::runtime_error("PCL read no coordinates (field types not mappable to float?)");
}

void to_row_major(const Eigen::Matrix4f& m, double out[16]) {
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out[4 * i + j] = m(i, j);
}

}  // namespace

std::string pcl_version() { return PCL_VERSION_PRETTY; }

bool pcl_load(const std::string& path, Cloud& out) {
    pcl::PointCloud<PointFull> c;
    const bool ply = path.size() > 4 && path.substr(path.size() - 4) == ".ply";
    if ((ply ? pcl::io::loadPLYFile(path, c) : pcl::io::loadPCDFile(path, c)) != 0 || c.empty()) return false;
    out.pts.resize(3 * c.size());
    out.nrm.resize(3 * c.size());
    out.col.resize(3 * c.size());
    for (size_t i = 0; i < c.size(); ++i) {
        out.pts[3 * i] = c[i].x, out.pts[3 * i + 1] = c[i].y, out.pts[3 * i + 2] = c[i].z;
        out.nrm[3 * i] = c[i].normal_x, out.nrm[3 * i + 1] = c[i].normal_y, out.nrm[3 * i + 2] = c[i].normal_z;
        out.col[3 * i] = c[i].r / 255.0, out.col[3 * i + 1] = c[i].g / 255.0, out.col[3 * i + 2] = c[i].b / 255.0;
    }
    return true;
}

bool pcl_write(const std::string& path, const Cloud& c) {
    auto pc = full_cloud(c);
    const bool ply = path.size() > 4 && path.substr(path.size() - 4) == ".ply";
    return (ply ? pcl::io::savePLYFileBinary(path, *pc) : pcl::io::savePCDFileBinary(path, *pc)) == 0;
}

void run_pcl(const Config& cfg, const std::map<std::string, Cloud>& clouds, const std::vector<IcpCase>& icp,
             Results& out) {
    const std::map<std::string, std::string> labels = {
        {"fragment", "fragment"}, {"synthetic", "synthetic " + std::to_string(cfg.synthetic_points / 1000) + "k"}};
    for (const auto& src : {std::string("fragment"), std::string("synthetic")}) {
        for (const auto& ext : {std::string("ply"), std::string("pcd")}) {
            const std::string up = ext == "ply" ? "PLY" : "PCD";
            const std::string path = cfg.files.at(src + "." + ext);
            out[row_read(up, labels.at(src))] = guarded([&] {
                pcl::PointCloud<PointFull> c;
                bool typed_ok = true;
                try {
                    if (ext == "ply") pcl::io::loadPLYFile(path, c);
                    else pcl::io::loadPCDFile(path, c);
                    check_loaded(c, path);
                } catch (const std::exception&) {
                    typed_ok = false;
                }
                if (!typed_ok) {
                    // PCL cannot map double x/y/z (as o3d and Open3D write PLY) onto a float point type: time
                    // its untyped reader instead, which parses every property into a PCLPointCloud2 blob.
                    pcl::PCLPointCloud2 blob;
                    return measure(
                        cfg, nullptr,
                        [&] {
                            const int rc = ext == "ply" ? pcl::io::loadPLYFile(path, blob) : pcl::io::loadPCDFile(path, blob);
                            if (rc != 0) throw std::runtime_error("PCL could not read " + path);
                        },
                        [&] {
                            return std::to_string(std::size_t(blob.width) * blob.height) +
                                   " pts (PCLPointCloud2: typed read cannot map double x/y/z)";
                        });
                }
                return measure(
                    cfg, nullptr,
                    [&] {
                        c.clear();
                        const int rc = ext == "ply" ? pcl::io::loadPLYFile(path, c) : pcl::io::loadPCDFile(path, c);
                        if (rc != 0) throw std::runtime_error("PCL could not read " + path);
                    },
                    [&] {
                        check_loaded(c, path);
                        return std::to_string(c.size()) + " pts";
                    });
            });
            const std::string outp = cfg.tmp_dir + "/out_pcl_" + src + "." + ext;
            out[row_write(up, labels.at(src))] = guarded([&] {
                auto pc = full_cloud(clouds.at(src));
                return measure(
                    cfg, nullptr,
                    [&] {
                        const int rc = ext == "ply" ? pcl::io::savePLYFileBinary(outp, *pc)
                                                    : pcl::io::savePCDFileBinary(outp, *pc);
                        if (rc != 0) throw std::runtime_error("PCL could not write " + outp);
                    },
                    [&] { return file_size_mb(outp); });
            });
        }
    }

    const std::pair<std::string, double> voxels[3] = {{"fragment", 0.01}, {"fragment", 0.05}, {"synthetic", 0.05}};
    for (const auto& [src, v] : voxels) {
        out[row_voxel(v, labels.at(src))] = guarded([&, src = src, v = v] {
            auto pc = full_cloud(clouds.at(src));
            pcl::PointCloud<PointFull> res;
            return measure(
                cfg, nullptr,
                [&] {
                    pcl::VoxelGrid<PointFull> vg;
                    vg.setInputCloud(pc);
                    vg.setLeafSize(static_cast<float>(v), static_cast<float>(v), static_cast<float>(v));
                    vg.filter(res);
                },
                [&] { return std::to_string(res.size()) + " pts"; });
        });
    }

    out[row_knn(labels.at("synthetic"))] = guarded([&] {
        pcl::PointCloud<pcl::PointXYZ>::Ptr pc(new pcl::PointCloud<pcl::PointXYZ>);
        fill_xyz(clouds.at("synthetic"), *pc);
        const size_t n = pc->size();
        std::vector<int> indices(n * kKnn);
        std::vector<float> d2(n * kKnn);
        return measure(
            cfg, nullptr,
            [&] {
                pcl::KdTreeFLANN<pcl::PointXYZ> tree;
                tree.setInputCloud(pc);
#pragma omp parallel num_threads(cfg.threads)
                {
                    std::vector<int> idx(kKnn);
                    std::vector<float> dd(kKnn);
#pragma omp for schedule(static)
                    for (long long i = 0; i < static_cast<long long>(n); ++i) {
                        tree.nearestKSearch((*pc)[i], kKnn, idx, dd);
                        std::copy(idx.begin(), idx.end(), indices.begin() + i * kKnn);
                        std::copy(dd.begin(), dd.end(), d2.begin() + i * kKnn);
                    }
                }
            },
            [&] { return std::to_string(n * kKnn) + " nbrs"; });
    });

    out[row_normals_knn()] = guarded([&] {
        pcl::PointCloud<pcl::PointXYZ>::Ptr pc(new pcl::PointCloud<pcl::PointXYZ>);
        fill_xyz(clouds.at("fragment"), *pc);
        pcl::PointCloud<pcl::Normal> normals;
        return measure(
            cfg, nullptr,
            [&] {
                pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne(static_cast<unsigned>(cfg.threads));
                ne.setInputCloud(pc);  // builds its own search tree inside compute()
                ne.setKSearch(kKnn);
                ne.compute(normals);
            },
            [&] { return std::to_string(normals.size()) + " normals"; });
    });

    for (const IcpCase& ic : icp) {
        Eigen::Matrix4f init;
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) init(i, j) = static_cast<float>(ic.init[4 * i + j]);
        out[row_icp(false, ic.label)] = guarded([&] {
            pcl::PointCloud<pcl::PointXYZ>::Ptr s(new pcl::PointCloud<pcl::PointXYZ>), t(new pcl::PointCloud<pcl::PointXYZ>);
            fill_xyz(ic.source, *s);
            fill_xyz(ic.target, *t);
            pcl::PointCloud<pcl::PointXYZ> aligned;
            double T[16];
            return measure(
                cfg, nullptr,
                [&] {
                    pcl::IterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> reg;
                    reg.setInputSource(s);
                    reg.setInputTarget(t);  // the target KD-tree is built inside align(), as o3d builds its own
                    reg.setMaxCorrespondenceDistance(ic.max_distance);
                    reg.setMaximumIterations(kIcpMaxIteration);
                    reg.align(aligned, init);
                    to_row_major(reg.getFinalTransformation(), T);
                },
                [&] { return icp_summary(ic, T); });
        });
        out[row_icp(true, ic.label)] = guarded([&] {
            if (ic.target.nrm.empty()) throw std::runtime_error("target has no normals");
            pcl::PointCloud<pcl::PointNormal>::Ptr s(new pcl::PointCloud<pcl::PointNormal>),
                t(new pcl::PointCloud<pcl::PointNormal>);
            fill_xyz(ic.source, *s);
            fill_normals(ic.source, *s);
            fill_xyz(ic.target, *t);
            fill_normals(ic.target, *t);
            pcl::PointCloud<pcl::PointNormal> aligned;
            double T[16];
            return measure(
                cfg, nullptr,
                [&] {
                    pcl::IterativeClosestPointWithNormals<pcl::PointNormal, pcl::PointNormal> reg;
                    reg.setInputSource(s);
                    reg.setInputTarget(t);
                    reg.setMaxCorrespondenceDistance(ic.max_distance);
                    reg.setMaximumIterations(kIcpMaxIteration);
                    reg.align(aligned, init);
                    to_row_major(reg.getFinalTransformation(), T);
                },
                [&] { return icp_summary(ic, T); });
        });
    }
    out[row_fpfh()] = guarded([&] {
        const Cloud& in = clouds.at("fpfh_input");
        pcl::PointCloud<pcl::PointNormal>::Ptr c(new pcl::PointCloud<pcl::PointNormal>);
        fill_xyz(in, *c);
        fill_normals(in, *c);
        pcl::PointCloud<pcl::FPFHSignature33> features;
        return measure(
            cfg, nullptr,
            [&] {
                // The search tree is built inside the timed call, as o3d builds its own.
                pcl::search::KdTree<pcl::PointNormal>::Ptr tree(new pcl::search::KdTree<pcl::PointNormal>);
                pcl::FPFHEstimationOMP<pcl::PointNormal, pcl::PointNormal, pcl::FPFHSignature33> est;
                est.setNumberOfThreads(static_cast<unsigned>(cfg.threads));
                est.setInputCloud(c);
                est.setInputNormals(c);
                est.setSearchMethod(tree);
                est.setRadiusSearch(kFpfhRadius);
                est.compute(features);
            },
            [&] { return "33x" + std::to_string(features.size()) + " (radius only)"; });
    });
}

}  // namespace bench
