// SPDX-License-Identifier: MIT
#pragma once
/// @file parallel.h
/// @brief Thread-count policy shared by every OpenMP kernel.
namespace o3d::utility {

/// @brief Library-wide default used when a call asks for 0 threads (0 = OpenMP's default).
void set_default_num_threads(int num_threads);
/// @brief Threads a call asking for `requested` (0 = default) should use; always >= 1.
/// In a process forked after this library ran parallel code, returns 1: GCC's libgomp thread pool
/// does not survive fork(), and a parallel region there would hang (Open3D issue #1552).
int resolve_num_threads(int requested = 0);

}  // namespace o3d::utility
