// SPDX-License-Identifier: MIT
// The reconstruction system through the wrapper: the generated stage enum and options, a stage run on a small
// dataset written here (three frames of a textured plane 1 m away, the camera sliding 1 cm a frame), progress
// that rises to 1 and cancels when the callback returns false, and errors that name the stage to run first.
// (The known-trajectory run is tests/capi/test_reconstruction.c; the living-room run is the Python test.)
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "test_util.hpp"

namespace fs = std::filesystem;
using o3dpp::ReconstructionOptions;
using o3dpp::ReconstructionStage;

namespace {

constexpr int W = 96, H = 72, kFrames = 3;

/// A dataset folder with colour/ and depth/ PNGs and a config that writes below `folder`/out.
std::string write_dataset(const std::string& folder) {
    fs::remove_all(folder);
    fs::create_directories(folder + "/data/color");
    fs::create_directories(folder + "/data/depth");
    for (int k = 0; k < kFrames; ++k) {
        std::vector<uint8_t> rgb(3 * W * H);
        std::vector<uint16_t> depth(W * H, 1000);  // 1 m in millimetres
        for (int v = 0; v < H; ++v)
            for (int u = 0; u < W; ++u) {
                const double x = (u - W / 2.0) / 80.0 + 0.01 * k;  // the plane point this pixel sees, metres
                const double y = (v - H / 2.0) / 80.0;
                for (int c = 0; c < 3; ++c)
                    rgb[3 * (v * W + u) + c] =
                        static_cast<uint8_t>(128 + 100 * std::sin(9.0 * x + 2.0 * c) * std::cos(7.0 * y - c));
            }
        char name[32];
        std::snprintf(name, sizeof name, "/%05d.png", k);
        o3dpp::write_image(folder + "/data/color" + name, o3dpp::Image::from_data(W, H, 3, 1, rgb.data(), rgb.size()));
        o3dpp::write_image(folder + "/data/depth" + name,
                           o3dpp::Image::from_data(W, H, 1, 2, depth.data(), depth.size() * sizeof(uint16_t)));
    }
    o3dpp::write_pinhole_camera_intrinsic(folder + "/intrinsic.json", o3dpp::PinholeIntrinsic(W, H, 80.0, 80.0, 47.5, 35.5));
    const std::string config = folder + "/config.json";
    std::ofstream(config) << "{\"path_dataset\": \"" << folder << "/data\", \"path_intrinsic\": \"" << folder
                          << "/intrinsic.json\", \"path_output\": \"" << folder << "/out\", \"n_frames_per_fragment\": 3,"
                          << " \"n_keyframes_per_n_frame\": 1, \"tsdf_cubic_size\": 4.0}";
    return config;
}

}  // namespace

TEST(Reconstruction, OptionsComeFromTheCHeader) {
    const ReconstructionOptions o;
    EXPECT_TRUE(o.resume);
    EXPECT_EQ(o.num_threads, 0);
    EXPECT_EQ(static_cast<int>(ReconstructionStage::IntegrateScene), O3D_RECONSTRUCTION_STAGE_INTEGRATE_SCENE);
}

TEST(Reconstruction, MakeFragmentsReportsProgressAndCancels) {
    const std::string folder = o3dpp_test::tmp_path("reconstruction_cpp");
    const std::string config = write_dataset(folder);
    ReconstructionOptions o;
    std::vector<double> seen;
    o.progress = [&](double f) {
        seen.push_back(f);
        return true;
    };
    o3dpp::run_reconstruction_stage(config, ReconstructionStage::MakeFragments, o);
    ASSERT_FALSE(seen.empty());
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
    for (size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);
    EXPECT_TRUE(fs::exists(folder + "/out/fragments/fragment_000.ply"));
    EXPECT_TRUE(fs::exists(folder + "/out/fragments/fragment_optimized_000.json"));

    o.resume = false;
    o.progress = [](double) { return false; };
    try {
        o3dpp::run_reconstruction_stage(config, ReconstructionStage::MakeFragments, o);
        FAIL() << "expected a cancel";
    } catch (const o3dpp::Error& e) {
        EXPECT_EQ(e.code(), O3D_ERROR_CANCELLED);
    }
    EXPECT_TRUE(fs::exists(folder + "/out/fragments/fragment_000.ply"));  // finished outputs stay
    fs::remove_all(folder);
}

TEST(Reconstruction, ErrorsNameTheStageToRunFirst) {
    const std::string folder = o3dpp_test::tmp_path("reconstruction_cpp_errors");
    const std::string config = write_dataset(folder);
    try {
        o3dpp::run_reconstruction_stage(config, ReconstructionStage::RefineRegistration);
        FAIL() << "expected an error";
    } catch (const o3dpp::Error& e) {
        EXPECT_EQ(e.code(), O3D_ERROR_IO);
        EXPECT_NE(std::string(e.what()).find("run the \"register fragments\" stage first"), std::string::npos);
    }
    EXPECT_THROW(o3dpp::run_reconstruction_stage(folder + "/nothing.json", ReconstructionStage::MakeFragments),
                 o3dpp::Error);
    fs::remove_all(folder);
}
