// SPDX-License-Identifier: MIT
#pragma once
/// @file gpu_geometry.h
/// @brief A geometry copied into OpenGL buffers (position, normal, color per vertex, as float32), ready to
/// draw. Uploads validate first (indices in range) and touch OpenGL only then.
#include <epoxy/gl.h>

#include "o3d/geometry/image.h"
#include "o3d/geometry/line_set.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/voxel_grid.h"
#include "o3d/visualization/render_option.h"
#include "o3d/visualization/view_camera.h"

namespace o3d::visualization {

enum class GeometryKind { PointCloud, TriangleMesh, LineSet, VoxelGrid, Image };

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
    GLuint texture = 0;         ///< images: RGB8, drawn on a quad given in normalized device coordinates
    void release();
};

// Each needs a current context.
GpuGeometry upload(const geometry::PointCloud& cloud, const Material& material);
GpuGeometry upload(const geometry::TriangleMesh& mesh, const Material& material);
GpuGeometry upload(const geometry::LineSet& lines, const Material& material);
GpuGeometry upload(const geometry::VoxelGrid& grid, const Material& material);
/// @brief An image shown flat in a `width` x `height` frame as Open3D's legacy viewer does (scaled to fit,
/// keeping its aspect ratio, centred). 1, 3 or 4 channels of uint8; one channel of uint16 or float32 is
/// shown as gray scaled to its largest value; 3 channels of float32 are clamped to [0, 1].
GpuGeometry upload(const geometry::Image& image, int width, int height);
/// @brief A closed outline through window pixels (x right, y down) of a `width` x `height` frame, in normalized
/// device coordinates: drawn over the scene as is (VisualizerWithEditing's selection).
GpuGeometry upload_outline(const std::vector<Eigen::Vector2d>& pixels, int width, int height);

}  // namespace o3d::visualization
