// SPDX-License-Identifier: MIT
#pragma once
/// @file gpu_geometry.h
/// @brief A geometry copied into OpenGL buffers (position, normal, color per vertex, as float32), ready to
/// draw. Uploads validate first (indices in range) and touch OpenGL only then.
#include <epoxy/gl.h>

#include "o3d/geometry/line_set.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/voxel_grid.h"
#include "o3d/visualization/render_option.h"
#include "o3d/visualization/view_camera.h"

namespace o3d::visualization {

enum class GeometryKind { PointCloud, TriangleMesh, LineSet, VoxelGrid };

struct VertexBuffer {
    GLuint vao = 0, vbo = 0, ebo = 0;
    GLsizei count = 0;  ///< vertices, or indices when ebo != 0
    void release();
};

struct GpuGeometry {
    GeometryKind kind = GeometryKind::PointCloud;
    bool has_normals = false;
    bool has_colors = false;
    SceneBox box;
    Material material;
    VertexBuffer main;          ///< points, lines, or triangles with one normal per face (flat shading)
    VertexBuffer smooth;        ///< meshes with vertex normals: shared vertices, indexed (smooth shading)
    VertexBuffer normal_lines;  ///< clouds with normals: each point twice, for point_show_normal
    void release();
};

// Each needs a current context.
GpuGeometry upload(const geometry::PointCloud& cloud, const Material& material);
GpuGeometry upload(const geometry::TriangleMesh& mesh, const Material& material);
GpuGeometry upload(const geometry::LineSet& lines, const Material& material);
GpuGeometry upload(const geometry::VoxelGrid& grid, const Material& material);

}  // namespace o3d::visualization
