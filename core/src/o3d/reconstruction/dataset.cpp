// SPDX-License-Identifier: MIT
#include "o3d/reconstruction/dataset.h"

#include <algorithm>
#include <filesystem>

#include "o3d/camera/camera_io.h"
#include "o3d/camera/intrinsic_presets.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/io/image_io.h"
#include "o3d/reconstruction/stage_runner.h"
#include "o3d/utility/error.h"

namespace o3d::reconstruction {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> files_with_extension(const fs::path& folder, const char* extension) {
    std::vector<std::string> files;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
        if (it->is_regular_file(ec) && it->path().extension() == extension) files.push_back(it->path().string());
    if (ec) throw IoError(folder.string() + ": cannot list: " + ec.message());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

Dataset open_dataset(const Config& config) {
    const fs::path root(config.path_dataset);
    std::error_code ec;
    if (!fs::is_directory(root, ec)) throw IoError(config.path_dataset + ": no such dataset folder");
    fs::path color_folder;
    for (const char* name : {"image", "rgb", "color"})
        if (fs::is_directory(root / name, ec)) {
            color_folder = root / name;
            break;
        }
    if (color_folder.empty()) throw IoError(config.path_dataset + ": no image/, rgb/ or color/ folder");
    if (!fs::is_directory(root / "depth", ec)) throw IoError(config.path_dataset + ": no depth/ folder");

    Dataset d;
    d.color_files = files_with_extension(color_folder, ".jpg");
    for (std::string& png : files_with_extension(color_folder, ".png")) d.color_files.push_back(std::move(png));
    d.depth_files = files_with_extension(root / "depth", ".png");
    if (d.color_files.empty()) throw InvalidArgument(color_folder.string() + ": no .jpg or .png images");
    if (d.color_files.size() != d.depth_files.size())
        throw InvalidArgument(config.path_dataset + ": " + std::to_string(d.color_files.size()) +
                              " colour images but " + std::to_string(d.depth_files.size()) + " depth images");
    d.intrinsic = config.path_intrinsic.empty()
                      ? camera::intrinsic_preset(camera::IntrinsicPreset::PrimeSenseDefault)
                      : camera::read_pinhole_camera_intrinsic(config.path_intrinsic);
    d.frames_per_fragment = config.n_frames_per_fragment;
    return d;
}

geometry::RGBDImage read_frame(const Config& config, const Dataset& dataset, int frame, bool convert_rgb_to_intensity) {
    const auto i = static_cast<size_t>(frame);
    return with_context("frame " + std::to_string(frame) + " (" + dataset.color_files[i] + ", " +
                            dataset.depth_files[i] + ")",
                        [&] {
                            const geometry::Image color = io::read_image(dataset.color_files[i]);
                            const geometry::Image depth = io::read_image(dataset.depth_files[i]);
                            geometry::RGBDOptions options;
                            options.depth_scale = config.depth_scale;
                            options.depth_trunc = config.depth_max;
                            options.convert_rgb_to_intensity = convert_rgb_to_intensity;
                            return geometry::create_rgbd_from_color_and_depth(color, depth, options);
                        });
}

}  // namespace o3d::reconstruction
