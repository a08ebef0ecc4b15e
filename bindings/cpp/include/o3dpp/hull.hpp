// SPDX-License-Identifier: MIT
#pragma once
/// @file hull.hpp
/// @brief Convex hulls and hidden-point removal: now in trianglemesh.hpp (kept so that this include works).
#include "o3dpp/trianglemesh.hpp"
