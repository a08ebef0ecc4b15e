// SPDX-License-Identifier: MIT
// Shared declarations of the C++ benchmark: o3d (C API, bench_main.cpp) against PCL (bench_pcl.cpp).
#pragma once

#include <array>
#include <exception>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace bench {

struct Config {
    int threads = 1;
    int repeat = 5;
    int warmup = 1;
    double budget_s = 20.0;
    size_t synthetic_points = 1000000;
    unsigned long long seed = 20240601ULL;
    std::string fragment_pcd, bin0_pcd, bin1_pcd, tmp_dir;
    std::map<std::string, std::string> files;  // "fragment.ply", "synthetic.pcd", ... -> shared input file
};

/// One library's result on one row. skipped: the library lacks the op ('-').
struct Cell {
    bool skipped = true;
    double seconds = -1.0;
    int runs = 0;
    std::string info;
    std::string error;
};

/// Plain arrays (N x 3 row-major doubles); nrm / col empty when absent.
struct Cloud {
    std::vector<double> pts, nrm, col;
    size_t size() const { return pts.size() / 3; }
};

/// An ICP problem: source, target (target normals needed for point-to-plane), max distance, init, truth.
struct IcpCase {
    std::string label;
    Cloud source, target;
    double max_distance = 0.05;
    std::array<double, 16> init{};
    bool has_truth = false;
    std::array<double, 16> truth{};
};

constexpr int kIcpMaxIteration = 30;
constexpr int kKnn = 30;

/// Median of timed runs of run() (each preceded by an untimed setup()), after cfg.warmup warm-ups.
/// Exceptions from setup/run propagate. info() is called once after the last run.
Cell measure(const Config& cfg, const std::function<void()>& setup, const std::function<void()>& run,
             const std::function<std::string()>& info);

/// Runs f() and returns its cell; an exception becomes a cell that reports the (shortened) error,
/// so one failing row never stops the run.
template <class F>
Cell guarded(F&& f) {
    try {
        return f();
    } catch (const std::exception& e) {
        Cell c;
        c.skipped = false;
        c.error = e.what();
        if (c.error.size() > 100) c.error = c.error.substr(0, 97) + "...";
        return c;
    }
}

/// "fit F rmse R [err Adeg/Bmm]" of a final source->target transform, with one common evaluator (o3d's).
std::string icp_summary(const IcpCase& c, const double transform[16]);

// Row names, shared by both sides so the cells line up.
std::string row_read(const std::string& ext, const std::string& label);
std::string row_write(const std::string& ext, const std::string& label);
std::string row_voxel(double voxel, const std::string& label);
std::string row_knn(const std::string& label);
std::string row_normals_knn();
std::string row_normals_hybrid();
std::string row_icp(bool plane, const std::string& label);
std::string row_fpfh();

/// FPFH row: cloud_bin_0 voxel-downsampled at 0.05 with hybrid(0.1, 30) normals (made once by o3d, so both
/// libraries see the same points and normals), features with radius 0.25.
constexpr double kFpfhRadius = 0.25;
constexpr int kFpfhMaxNn = 100;

using Results = std::map<std::string, Cell>;  // row name -> cell

#ifdef O3D_BENCH_HAVE_PCL
/// Run every PCL row into `out`.
void run_pcl(const Config& cfg, const std::map<std::string, Cloud>& clouds, const std::vector<IcpCase>& icp,
             Results& out);
/// Fallbacks when o3d cannot read or write yet: load xyz/normals/colors, or write binary PLY/PCD.
bool pcl_load(const std::string& path, Cloud& out);
bool pcl_write(const std::string& path, const Cloud& c);
std::string pcl_version();
#endif

}  // namespace bench
