// SPDX-License-Identifier: MIT
// The Python-side holder of o3d_tetramesh_t (tetramesh.h), shared by tetramesh.cpp (the class) and
// surface_reconstruction.cpp (alpha shapes reuse a tetra mesh). Kept out of geometry_types.h so that only
// the two files that use it see it.
#pragma once

#include "geometry_types.h"

namespace o3dpy {

O3DPY_ARRAY_API(tetramesh, true, -1);
O3DPY_INDEX_API(tetramesh);

/// o3d.geometry.TetraMesh; copy-on-write before resizing calls, as PyPointCloud.
struct PyTetraMesh : Geom<o3d_tetramesh_t> {
    using Geom::Geom;
    PyTetraMesh();
};

/// A 1-D array-like of integers (list, IntVector, ndarray) as int32 values, each checked against the int32
/// range (the C calls check what they accept beyond that).
std::vector<int32_t> int32_values(py::handle obj, const char* what);
/// A 1-D array-like of numbers (list, DoubleVector, ndarray) as C-contiguous float64.
py::array_t<double> double_values(py::handle obj, const char* what);

void declare_tetramesh(py::module_& m);
void define_tetramesh(py::module_& m);
void define_surface_reconstruction(py::module_& m);

}  // namespace o3dpy
