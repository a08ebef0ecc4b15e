/* SPDX-License-Identifier: MIT */
/**
 * @file o3d.h
 * @brief The whole o3d C API. Anything not declared in these headers is not API.
 */
#ifndef O3D_O3D_H
#define O3D_O3D_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/pointcloud.h"
#include "o3d/kdtree.h"
#include "o3d/indexlists.h"
#include "o3d/io.h"
#include "o3d/feature.h"
#include "o3d/registration.h"
#include "o3d/posegraph.h"
#include "o3d/image.h"
#include "o3d/camera.h"
#include "o3d/rgbd.h"
#include "o3d/trianglemesh.h"
#include "o3d/tetramesh.h"
#include "o3d/halfedgemesh.h"
#include "o3d/boundingbox.h"
#include "o3d/lineset.h"
#include "o3d/voxelgrid.h"
#include "o3d/octree.h"
#include "o3d/visualization.h"
#include "o3d/visualizer.h"
#include "o3d/selection.h"
#include "o3d/odometry.h"
#include "o3d/integration.h"
#include "o3d/color_map.h"
#include "o3d/reconstruction.h"

#endif /* O3D_O3D_H */
