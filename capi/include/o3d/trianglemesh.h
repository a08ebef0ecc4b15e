/* SPDX-License-Identifier: MIT */
/**
 * @file trianglemesh.h
 * @brief Triangle meshes: vertices, triangles and their attributes; normals, clean-up, topology
 * queries, processing (sampling, simplification, smoothing, subdivision) and primitives.
 *
 * Mirrors o3d.geometry.TriangleMesh. Arrays are row-major: vertices, vertex normals, vertex colors and
 * triangle normals are (N x 3) float64; triangle UVs are (3 * num_triangles x 2) float64, three rows per
 * triangle in corner order; triangles are (M x 3) int32 vertex indices; material ids are (M x 1) int32.
 * Counts are in rows. An attribute counts (has_array) only when its row count matches (Open3D semantics).
 *
 * Triangles may hold any int32 values; every operation that follows them checks them first and fails
 * with O3D_ERROR_INVALID_ARGUMENT on an index outside [0, num_vertices) instead of reading out of bounds.
 *
 * **Ownership:** handles written through `o3d_trianglemesh_t** out` belong to the caller
 * (o3d_trianglemesh_destroy). Views are borrowed: valid until the next mutating call on the mesh or
 * its destruction. On failure `*out` is left NULL. Clean-up functions edit the mesh in place;
 * processing functions write a new mesh.
 */
#ifndef O3D_TRIANGLEMESH_H
#define O3D_TRIANGLEMESH_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/boundingbox.h"
#include "o3d/image.h"
#include "o3d/pointcloud.h"

O3D_BEGIN_DECL


/* ---- Container ---- */

/** @brief New empty mesh. @see o3d.geometry.TriangleMesh() */
O3D_API o3d_status o3d_trianglemesh_create(o3d_trianglemesh_t** out);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_trianglemesh_destroy(o3d_trianglemesh_t* mesh);
/** @brief Deep copy (textures included). */
O3D_API o3d_status o3d_trianglemesh_clone(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* src);
/** @brief Remove everything (arrays and textures). */
O3D_API o3d_status o3d_trianglemesh_clear(o3d_trianglemesh_t* mesh);
/** @brief Number of vertices. */
O3D_API o3d_status o3d_trianglemesh_num_vertices(size_t* out_n, const o3d_trianglemesh_t* mesh);
/** @brief Number of triangles. */
O3D_API o3d_status o3d_trianglemesh_num_triangles(size_t* out_n, const o3d_trianglemesh_t* mesh);
/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a point, a line, a descriptor), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
#define O3D_MESH_VERTICES 0 /**< N x 3 float64 */
#define O3D_MESH_VERTEX_NORMALS 1 /**< N x 3 */
#define O3D_MESH_VERTEX_COLORS 2 /**< N x 3, RGB in [0,1] */
#define O3D_MESH_TRIANGLE_NORMALS 3 /**< M x 3 */
#define O3D_MESH_TRIANGLE_UVS 4 /**< 3M x 2, three rows per triangle in corner order */
#define O3D_MESH_TRIANGLES 100 /**< M x 3 int32 vertex indices */
#define O3D_MESH_TRIANGLE_MATERIAL_IDS 101 /**< M x 1 int32, index into the textures */

/**
 * @brief Whether array `which` counts (Open3D's has_*: present and of the matching size).
 * @param out receives 1 or 0. @param mesh the trianglemesh. @param which the array.
 * @return O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`. Thread-safe on a const handle.
 */
O3D_API o3d_status o3d_trianglemesh_has_array(int32_t* out, const o3d_trianglemesh_t* mesh, int32_t which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature. @return O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`. Thread-safe on a const handle.
 */
O3D_API o3d_status o3d_trianglemesh_array_shape(size_t* out_rows, size_t* out_cols, const o3d_trianglemesh_t* mesh, int32_t which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 * @return O3D_ERROR_INVALID_ARGUMENT on a NULL handle, NULL data with rows > 0 or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_set_array(o3d_trianglemesh_t* mesh, int32_t which, const double* data, size_t rows);
/** @brief As o3d_trianglemesh_set_array from float32 values, converted in the one copy. */
O3D_API o3d_status o3d_trianglemesh_set_array_f32(o3d_trianglemesh_t* mesh, int32_t which, const float* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them. @return O3D_ERROR_BUFFER_TOO_SMALL when capacity < rows,
 * O3D_ERROR_INVALID_ARGUMENT on a NULL handle or out_rows or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_trianglemesh_t* mesh,
                                              int32_t which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 * **Ownership:** the library's; valid until the next mutating call on `mesh` or its destruction.
 */
O3D_API o3d_status o3d_trianglemesh_array_view(const double** out_data, size_t* out_rows, const o3d_trianglemesh_t* mesh,
                                               int32_t which);
/** @brief Borrowed writable view of array `which`: as o3d_trianglemesh_array_view; writing through it is a mutating call. */
O3D_API o3d_status o3d_trianglemesh_array_mutable_view(double** out_data, size_t* out_rows, o3d_trianglemesh_t* mesh,
                                                       int32_t which);
/** @brief Replace int32 array `which` with `rows` rows of `data` (copied once), as o3d_trianglemesh_set_array. */
O3D_API o3d_status o3d_trianglemesh_set_index_array(o3d_trianglemesh_t* mesh, int32_t which, const int32_t* data, size_t rows);
/** @brief Copy int32 array `which` out, with the copy-out rules of o3d_trianglemesh_get_array. */
O3D_API o3d_status o3d_trianglemesh_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                                    const o3d_trianglemesh_t* mesh, int32_t which);
/** @brief Borrowed read-only view of int32 array `which` (ownership as o3d_trianglemesh_array_view). */
O3D_API o3d_status o3d_trianglemesh_index_array_view(const int32_t** out_data, size_t* out_rows,
                                                     const o3d_trianglemesh_t* mesh, int32_t which);
/** @brief Borrowed writable view of int32 array `which`; writing through it is a mutating call. */
O3D_API o3d_status o3d_trianglemesh_index_array_mutable_view(int32_t** out_data, size_t* out_rows,
                                                             o3d_trianglemesh_t* mesh, int32_t which);

/** @brief Number of texture images. */
O3D_API o3d_status o3d_trianglemesh_texture_count(size_t* out_n, const o3d_trianglemesh_t* mesh);
/** @brief Copy of texture `index` as a new image (caller destroys it). */
O3D_API o3d_status o3d_trianglemesh_get_texture(o3d_image_t** out, const o3d_trianglemesh_t* mesh, size_t index);
/** @brief Append a copy of `image` to the textures. */
O3D_API o3d_status o3d_trianglemesh_add_texture(o3d_trianglemesh_t* mesh, const o3d_image_t* image);
/** @brief Remove all textures. */
O3D_API o3d_status o3d_trianglemesh_clear_textures(o3d_trianglemesh_t* mesh);

/** @brief Concatenate `other` onto `mesh` (Open3D `mesh += other`), re-indexing its triangles. */
O3D_API o3d_status o3d_trianglemesh_append(o3d_trianglemesh_t* mesh, const o3d_trianglemesh_t* other);

/* ---- Normals, colors, transforms, bounds (as for point clouds) ---- */

/** @brief Area-weighted vertex normals from the triangle normals (unit length when normalized != 0). */
O3D_API o3d_status o3d_trianglemesh_compute_vertex_normals(o3d_trianglemesh_t* mesh, int32_t normalized);
/** @brief Triangle normals (b - a) x (c - a) (unit length when normalized != 0). */
O3D_API o3d_status o3d_trianglemesh_compute_triangle_normals(o3d_trianglemesh_t* mesh, int32_t normalized);
/** @brief Scale vertex and triangle normals to unit length. */
O3D_API o3d_status o3d_trianglemesh_normalize_normals(o3d_trianglemesh_t* mesh);
/** @brief Set every vertex color to `rgb`. */
O3D_API o3d_status o3d_trianglemesh_paint_uniform_color(o3d_trianglemesh_t* mesh, const double rgb[3]);
/** @brief Apply a row-major 4x4 transform to the vertices (normals rotated). */
O3D_API o3d_status o3d_trianglemesh_transform(o3d_trianglemesh_t* mesh, const double transform[16]);
/** @brief relative != 0: add `t`; relative == 0: move the center to `t`. */
O3D_API o3d_status o3d_trianglemesh_translate(o3d_trianglemesh_t* mesh, const double translation[3],
                                              int32_t relative);
/** @brief Rotate by row-major 3x3 `R` about `center` (NULL: the mesh's center). */
O3D_API o3d_status o3d_trianglemesh_rotate(o3d_trianglemesh_t* mesh, const double rotation[9],
                                           const double center[3]);
/** @brief Scale about `center` (NULL: the mesh's center). */
O3D_API o3d_status o3d_trianglemesh_scale(o3d_trianglemesh_t* mesh, double scale, const double center[3]);
/** @brief Component-wise minimum of the vertices ((0,0,0) when empty). */
O3D_API o3d_status o3d_trianglemesh_get_min_bound(double out[3], const o3d_trianglemesh_t* mesh);
O3D_API o3d_status o3d_trianglemesh_get_max_bound(double out[3], const o3d_trianglemesh_t* mesh);
/** @brief Mean of the vertices ((0,0,0) when empty). */
O3D_API o3d_status o3d_trianglemesh_get_center(double out[3], const o3d_trianglemesh_t* mesh);
O3D_API o3d_status o3d_trianglemesh_get_axis_aligned_bounding_box(double out_min[3], double out_max[3],
                                                                  const o3d_trianglemesh_t* mesh);

/* ---- Clean-up (in place; each keeps the attributes of what it keeps) ---- */

/** @brief Merge vertices with exactly equal coordinates, re-indexing the triangles. */
O3D_API o3d_status o3d_trianglemesh_remove_duplicated_vertices(o3d_trianglemesh_t* mesh);
/** @brief Remove triangles with the same three vertices (in any order). */
O3D_API o3d_status o3d_trianglemesh_remove_duplicated_triangles(o3d_trianglemesh_t* mesh);
/** @brief Remove triangles that repeat a vertex index. */
O3D_API o3d_status o3d_trianglemesh_remove_degenerate_triangles(o3d_trianglemesh_t* mesh);
/** @brief Remove vertices no triangle uses. */
O3D_API o3d_status o3d_trianglemesh_remove_unreferenced_vertices(o3d_trianglemesh_t* mesh);
/** @brief Remove the smallest-area triangles on each edge shared by more than two, until all are manifold. */
O3D_API o3d_status o3d_trianglemesh_remove_non_manifold_edges(o3d_trianglemesh_t* mesh);
/** @brief Merge vertices closer than `eps` (>= 0) into their mean (normals and colors averaged). */
O3D_API o3d_status o3d_trianglemesh_merge_close_vertices(o3d_trianglemesh_t* mesh, double eps);

/* ---- Queries ---- */

/** @brief Sum of the triangle areas. */
O3D_API o3d_status o3d_trianglemesh_get_surface_area(double* out, const o3d_trianglemesh_t* mesh);
/** @brief Enclosed volume; a mesh that is not watertight and orientable fails with INVALID_ARGUMENT. */
O3D_API o3d_status o3d_trianglemesh_get_volume(double* out, const o3d_trianglemesh_t* mesh);
/** @brief Edge- and vertex-manifold, no boundary edges, not self-intersecting. */
O3D_API o3d_status o3d_trianglemesh_is_watertight(int32_t* out, const o3d_trianglemesh_t* mesh);
/** @brief Every edge in one or two triangles (only two when allow_boundary_edges == 0). */
O3D_API o3d_status o3d_trianglemesh_is_edge_manifold(int32_t* out, const o3d_trianglemesh_t* mesh,
                                                     int32_t allow_boundary_edges);
/** @brief The triangles around every vertex form one fan. */
O3D_API o3d_status o3d_trianglemesh_is_vertex_manifold(int32_t* out, const o3d_trianglemesh_t* mesh);
/** @brief Some two triangles that share no vertex intersect. */
O3D_API o3d_status o3d_trianglemesh_is_self_intersecting(int32_t* out, const o3d_trianglemesh_t* mesh);
/** @brief The triangles can be oriented consistently. */
O3D_API o3d_status o3d_trianglemesh_is_orientable(int32_t* out, const o3d_trianglemesh_t* mesh);
/** @brief V - E + F. */
O3D_API o3d_status o3d_trianglemesh_euler_poincare_characteristic(int64_t* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief Edge-connected components. `out_triangle_clusters` gets each triangle's cluster (numbered by
 * lowest triangle index), `out_cluster_n_triangles` and `out_cluster_area` each cluster's size and area.
 * All three buffers hold `capacity` values (num_triangles always fits); any may be NULL to skip it.
 * `*out_num_triangles` and `*out_num_clusters` always get the counts.
 */
O3D_API o3d_status o3d_trianglemesh_cluster_connected_triangles(int32_t* out_triangle_clusters,
                                                                int32_t* out_cluster_n_triangles,
                                                                double* out_cluster_area, size_t capacity,
                                                                size_t* out_num_triangles, size_t* out_num_clusters,
                                                                const o3d_trianglemesh_t* mesh);

/* ---- Processing (each writes a new mesh or cloud) ---- */

/**
 * @brief `number_of_points` points uniformly on the surface (area-weighted). Normals from the triangle
 * normals (use_triangle_normal != 0) or interpolated vertex normals; colors interpolated. Same seed →
 * same output. @see sample_points_uniformly
 */
O3D_API o3d_status o3d_trianglemesh_sample_points_uniformly(o3d_pointcloud_t** out, const o3d_trianglemesh_t* mesh,
                                                            size_t number_of_points, int32_t use_triangle_normal,
                                                            uint64_t seed);
/**
 * @brief Poisson-disk samples by sample elimination (Yuksel 2015) from init_factor * number_of_points
 * uniform samples (init_factor >= 1; Open3D's default 5). @see sample_points_poisson_disk
 */
O3D_API o3d_status o3d_trianglemesh_sample_points_poisson_disk(o3d_pointcloud_t** out,
                                                               const o3d_trianglemesh_t* mesh,
                                                               size_t number_of_points, double init_factor,
                                                               int32_t use_triangle_normal, uint64_t seed);

#define O3D_SIMPLIFICATION_AVERAGE 0 /**< vertex clustering: cluster vertex = mean */
#define O3D_SIMPLIFICATION_QUADRIC 1 /**< vertex clustering: cluster vertex minimises the quadric error */
/** @brief Vertex clustering on a voxel grid of edge `voxel_size` > 0. @see simplify_vertex_clustering */
O3D_API o3d_status o3d_trianglemesh_simplify_vertex_clustering(o3d_trianglemesh_t** out,
                                                               const o3d_trianglemesh_t* mesh, double voxel_size,
                                                               int32_t contraction);
/**
 * @brief Quadric edge-collapse decimation (Garland & Heckbert 1997) down to `target_number_of_triangles`,
 * stopping early when the cheapest collapse costs more than `maximum_error` (INFINITY: no limit);
 * `boundary_weight` weights the boundary-preserving quadrics (Open3D default 1).
 */
O3D_API o3d_status o3d_trianglemesh_simplify_quadric_decimation(o3d_trianglemesh_t** out,
                                                                const o3d_trianglemesh_t* mesh,
                                                                size_t target_number_of_triangles,
                                                                double maximum_error, double boundary_weight);

#define O3D_FILTER_SCOPE_ALL 0    /**< positions, normals and colors */
#define O3D_FILTER_SCOPE_COLOR 1
#define O3D_FILTER_SCOPE_NORMAL 2
#define O3D_FILTER_SCOPE_VERTEX 3
/** @brief Average of each vertex and its neighbours, `number_of_iterations` times. */
O3D_API o3d_status o3d_trianglemesh_filter_smooth_simple(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                         int32_t number_of_iterations, int32_t filter_scope);
/**
 * @brief Laplacian smoothing v += lambda * (weighted mean of neighbours - v), neighbours weighted by inverse
 * distance as in Open3D (default lambda 0.5).
 */
O3D_API o3d_status o3d_trianglemesh_filter_smooth_laplacian(o3d_trianglemesh_t** out,
                                                            const o3d_trianglemesh_t* mesh,
                                                            int32_t number_of_iterations, double lambda_filter,
                                                            int32_t filter_scope);
/** @brief Taubin smoothing: alternating Laplacian steps with lambda and mu (defaults 0.5, -0.53). */
O3D_API o3d_status o3d_trianglemesh_filter_smooth_taubin(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                         int32_t number_of_iterations, double lambda_filter,
                                                         double mu, int32_t filter_scope);
/** @brief Split every triangle into four at its edge midpoints, `number_of_iterations` times. */
O3D_API o3d_status o3d_trianglemesh_subdivide_midpoint(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                       int32_t number_of_iterations);
/** @brief Loop subdivision (Loop 1987), `number_of_iterations` times. */
O3D_API o3d_status o3d_trianglemesh_subdivide_loop(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                   int32_t number_of_iterations);
/** @brief Triangles whose three vertices lie in [min_bound, max_bound] (unused vertices dropped). */
O3D_API o3d_status o3d_trianglemesh_crop_aabb(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                              const double min_bound[3], const double max_bound[3]);

/* ---- Primitives (Open3D's create_* with its defaults noted) ---- */

/** @brief Box [0,w] x [0,h] x [0,d] (defaults 1, 1, 1). */
O3D_API o3d_status o3d_trianglemesh_create_box(o3d_trianglemesh_t** out, double width, double height,
                                               double depth);
/** @brief UV sphere about the origin (defaults radius 1, resolution 20). */
O3D_API o3d_status o3d_trianglemesh_create_sphere(o3d_trianglemesh_t** out, double radius, int32_t resolution);
/** @brief Cylinder along z centred at the origin (defaults 1, 2, resolution 20, split 4). */
O3D_API o3d_status o3d_trianglemesh_create_cylinder(o3d_trianglemesh_t** out, double radius, double height,
                                                    int32_t resolution, int32_t split);
/** @brief Cone along z with its base at z = 0 (defaults 1, 2, resolution 20, split 1). */
O3D_API o3d_status o3d_trianglemesh_create_cone(o3d_trianglemesh_t** out, double radius, double height,
                                                int32_t resolution, int32_t split);
/** @brief Torus about z (defaults 1, 0.5, radial 30, tubular 20). */
O3D_API o3d_status o3d_trianglemesh_create_torus(o3d_trianglemesh_t** out, double torus_radius, double tube_radius,
                                                 int32_t radial_resolution, int32_t tubular_resolution);
/** @brief Arrow along z: a cylinder then a cone (defaults 1, 1.5, 5, 4, 20, 4, 1). */
O3D_API o3d_status o3d_trianglemesh_create_arrow(o3d_trianglemesh_t** out, double cylinder_radius,
                                                 double cone_radius, double cylinder_height, double cone_height,
                                                 int32_t resolution, int32_t cylinder_split, int32_t cone_split);
/** @brief Coloured axes (x red, y green, z blue) of length `size` at `origin` (NULL: 0,0,0). */
O3D_API o3d_status o3d_trianglemesh_create_coordinate_frame(o3d_trianglemesh_t** out, double size,
                                                            const double origin[3]);
/** TriangleMesh.create_mobius keyword arguments. */
typedef struct o3d_mobius_options {
    uint32_t struct_size; /**< sizeof(o3d_mobius_options_t) */
    int32_t length_split; /**< columns along the band, >= 3; default 70 */
    int32_t width_split;  /**< vertices across the band, >= 2; default 15 */
    int32_t twists;       /**< half turns along the band, >= 0 (odd: a Moebius strip); default 1 */
    double radius;        /**< radius of the band's centre circle, > 0; default 1 */
    double flatness;      /**< factor on z (0 flattens the band into the plane); default 1 */
    double width;         /**< width of the band, > 0; default 1 */
    double scale;         /**< factor on every coordinate, > 0; default 1 */
} o3d_mobius_options_t;

/**
 * @brief Fill `opts` with the defaults (Open3D's). @param opts the struct to fill.
 * @param struct_size sizeof(o3d_mobius_options_t) or a smaller, older size.
 * @return O3D_ERROR_INVALID_ARGUMENT on NULL or an unknown size. Thread-safe.
 */
O3D_API o3d_status o3d_mobius_options_init(o3d_mobius_options_t* opts, uint32_t struct_size);
/**
 * @brief A twisted band about the z axis: length_split columns of width_split vertices, two triangles per
 * cell; an odd `twists` closes it into a one-sided Moebius strip. @see TriangleMesh.create_mobius
 * @param out receives the new mesh. **Ownership:** the caller's (o3d_trianglemesh_destroy); NULL on failure.
 * @param opts the shape (NULL: defaults).
 * @return O3D_ERROR_INVALID_ARGUMENT on NULL `out`, a bad struct_size or an option out of range. Thread-safe.
 */
O3D_API o3d_status o3d_trianglemesh_create_mobius(o3d_trianglemesh_t** out, const o3d_mobius_options_t* opts);
/**
 * @brief Regular solids inscribed in a sphere of `radius` about the origin (default 1), as Open3D documents
 * them (Open3D 0.20's icosahedron actually puts its vertices at 1.902 * radius; ours are at radius).
 */
O3D_API o3d_status o3d_trianglemesh_create_tetrahedron(o3d_trianglemesh_t** out, double radius);
O3D_API o3d_status o3d_trianglemesh_create_octahedron(o3d_trianglemesh_t** out, double radius);
O3D_API o3d_status o3d_trianglemesh_create_icosahedron(o3d_trianglemesh_t** out, double radius);

/* ---- Convex hull (Qhull) ---- */

/** @brief Convex hull of a mesh's vertices. @see TriangleMesh.compute_convex_hull */
O3D_API o3d_status o3d_trianglemesh_compute_convex_hull(o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices,
                                                        size_t capacity, size_t* out_n,
                                                        const o3d_trianglemesh_t* mesh, int32_t joggle_inputs);

/* ---- Oriented bounding boxes ---- */

/** @brief Oriented box of a mesh's vertices. @see TriangleMesh.get_oriented_bounding_box(robust) */
O3D_API o3d_status o3d_trianglemesh_get_oriented_bounding_box(o3d_obb_t* out, const o3d_trianglemesh_t* mesh,
                                                              int32_t robust);
/** @brief Triangles whose three vertices lie inside `obb` (unused vertices dropped). @see TriangleMesh.crop */
O3D_API o3d_status o3d_trianglemesh_crop_obb(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                             const o3d_obb_t* obb);

O3D_END_DECL

#endif /* O3D_TRIANGLEMESH_H */
