// SPDX-License-Identifier: MIT
#include "o3d/reconstruction/fragment_clouds.h"

#include "o3d/io/point_cloud_io.h"

namespace o3d::reconstruction {

std::vector<geometry::PointCloud> read_fragment_clouds(const Config& config, int n, int num_threads,
                                                       StageProgress& progress, const char* stage) {
    std::vector<geometry::PointCloud> clouds(static_cast<size_t>(n));
    parallel_for(clouds.size(), num_threads, progress, stage, [&](size_t i) {
        const std::string path = config.fragment_output(config.template_fragment_pointcloud, static_cast<int>(i));
        if (!file_exists(path)) throw IoError(path + ": missing; run the \"make fragments\" stage first");
        clouds[i] = io::read_point_cloud(path);
        if (clouds[i].points.empty()) throw InvalidArgument(path + ": the fragment cloud is empty");
    });
    return clouds;
}

}  // namespace o3d::reconstruction
