/* SPDX-License-Identifier: MIT */
/**
 * @file halfedgemesh.h
 * @brief Half-edge triangle meshes (o3d.geometry.HalfEdgeTriangleMesh): a cleaned, manifold copy of a triangle
 * mesh with its half-edges, for walking one-rings and boundary loops.
 *
 * Half-edge 3t + k is side k of triangle t, from triangles[t][k] to triangles[t][(k + 1) % 3]. A half-edge mesh
 * never changes after it is made; its arrays are copied out.
 *
 * **Ownership:** handles written through `o3d_halfedgemesh_t** out` belong to the caller
 * (o3d_halfedgemesh_destroy); index lists to the caller too (o3d_index_lists_destroy).
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_HALFEDGEMESH_H
#define O3D_HALFEDGEMESH_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** The float64 arrays of a half-edge mesh (O3D_HALFEDGEMESH_*), N x 3 each. */
typedef int32_t o3d_halfedgemesh_array;
#define O3D_HALFEDGEMESH_VERTICES 0         /**< vertex positions */
#define O3D_HALFEDGEMESH_VERTEX_NORMALS 1   /**< unit, area-weighted vertex normals */
#define O3D_HALFEDGEMESH_VERTEX_COLORS 2    /**< vertex colors (empty when the mesh had none) */
#define O3D_HALFEDGEMESH_TRIANGLE_NORMALS 3 /**< unit triangle normals */

/**
 * @brief Open3D's HalfEdgeTriangleMesh.create_from_triangle_mesh. The mesh is cleaned first, as Open3D does:
 * equal vertices merged, triangles equal up to rotation dropped, triangles repeating a vertex dropped,
 * unreferenced vertices dropped; normals are computed afresh and colors kept. A mesh without triangles gives an
 * empty half-edge mesh.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_halfedgemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh (manifold: no directed edge used twice, no two fans touching at a boundary vertex)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a triangle index out of range, or a non-manifold
 *   mesh (the message says where).
 */
O3D_API o3d_status o3d_halfedgemesh_create_from_triangle_mesh(o3d_halfedgemesh_t** out, const o3d_trianglemesh_t* mesh);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `mesh`: no other call may use it during or after.
 * @param mesh the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_halfedgemesh_destroy(o3d_halfedgemesh_t* mesh);
/**
 * @brief Copy a float64 array (rows of 3) into `out`; `*out_rows` always gets its rows. `out` NULL only reports
 * them.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows of 3 (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_rows receives the number of rows (always, also when the buffer is NULL or too small)
 * @param mesh the half-edge mesh
 * @param which O3D_HALFEDGEMESH_VERTICES, _VERTEX_NORMALS, _VERTEX_COLORS or _TRIANGLE_NORMALS
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_halfedgemesh_get_array(double* out, size_t capacity, size_t* out_rows,
                                              const o3d_halfedgemesh_t* mesh, o3d_halfedgemesh_array which);
/**
 * @brief Copy the triangles (rows of 3 vertex indices) into `out`; `*out_rows` always gets their number.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows of 3 (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_rows receives the number of rows (always, also when the buffer is NULL or too small)
 * @param mesh the half-edge mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_halfedgemesh_get_triangles(int32_t* out, size_t capacity, size_t* out_rows,
                                                  const o3d_halfedgemesh_t* mesh);
/**
 * @brief Copy the half-edges, one row of 5 int32 each: next, twin (-1 on a boundary), from vertex, to vertex,
 * triangle (Open3D's HalfEdge.next, twin, vertex_indices, triangle_index). `*out_rows` always gets their number.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows of 5 (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_rows receives the number of rows (always, also when the buffer is NULL or too small)
 * @param mesh the half-edge mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_halfedgemesh_get_half_edges(int32_t* out, size_t capacity, size_t* out_rows,
                                                   const o3d_halfedgemesh_t* mesh);
/**
 * @brief Per vertex, its outgoing half-edges in fan order (Open3D's ordered_half_edge_from_vertex): from its
 * boundary half-edge when it has one, else from its lowest-numbered one.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_index_lists_destroy(); left NULL on failure.
 * @param out receives one list per vertex (NULL on failure)
 * @param mesh the half-edge mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_halfedgemesh_get_ordered_half_edge_from_vertex(o3d_index_lists_t** out,
                                                                      const o3d_halfedgemesh_t* mesh);
/**
 * @brief The boundary loop through `vertex_index` as half-edge indices, from the vertex's outgoing boundary
 * half-edge along the half-edges' directions; empty when the vertex is not on a boundary.
 * @see HalfEdgeTriangleMesh.boundary_half_edges_from_vertex
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param mesh the half-edge mesh
 * @param vertex_index the vertex (in range)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a vertex out of range;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_halfedgemesh_boundary_half_edges_from_vertex(int32_t* out, size_t capacity, size_t* out_n,
                                                                    const o3d_halfedgemesh_t* mesh,
                                                                    int32_t vertex_index);
/**
 * @brief The same loop as vertex indices, starting with `vertex_index`.
 * @see HalfEdgeTriangleMesh.boundary_vertices_from_vertex
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param mesh the half-edge mesh
 * @param vertex_index the vertex (in range)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a vertex out of range;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_halfedgemesh_boundary_vertices_from_vertex(int32_t* out, size_t capacity, size_t* out_n,
                                                                  const o3d_halfedgemesh_t* mesh,
                                                                  int32_t vertex_index);
/**
 * @brief Every boundary loop once, as vertex indices (Open3D's get_boundaries): vertices are visited in ascending
 * order and each not yet on a found loop starts its loop.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_index_lists_destroy(); left NULL on failure.
 * @param out receives one list per loop (NULL on failure)
 * @param mesh the half-edge mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_halfedgemesh_get_boundaries(o3d_index_lists_t** out, const o3d_halfedgemesh_t* mesh);

O3D_END_DECL

#endif /* O3D_HALFEDGEMESH_H */
