// SPDX-License-Identifier: MIT
#pragma once
/// @file o3dpp.hpp
/// @brief The whole header-only C++17 wrapper over the o3d C API (namespace o3dpp).
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/camera.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/feature.hpp"
#include "o3dpp/global_registration.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/hull.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/io.hpp"
#include "o3dpp/kdtree.hpp"
#include "o3dpp/lineset.hpp"
#include "o3dpp/octree.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/posegraph.hpp"
#include "o3dpp/registration.hpp"
#include "o3dpp/rgbd.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"
#include "o3dpp/voxelgrid.hpp"
