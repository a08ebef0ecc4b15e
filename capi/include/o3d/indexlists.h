/* SPDX-License-Identifier: MIT */
/**
 * @file indexlists.h
 * @brief Lists of indices of varying length (Open3D's `List[IntVector]` / `List[Set[int]]`): a mesh's
 * adjacency list, the points each down-sampled point came from, the boundary loops of a half-edge mesh.
 *
 * Stored flat, as compressed rows: list i holds `values[offsets[i] .. offsets[i + 1])`, with
 * `offsets[0] == 0` and num_lists + 1 offsets. What the values are, and their order inside a list, is
 * said by the function that made the lists.
 *
 * **Ownership:** handles written through `o3d_index_lists_t** out` belong to the caller
 * (o3d_index_lists_destroy). A list set never changes after it is made.
 */
#ifndef O3D_INDEXLISTS_H
#define O3D_INDEXLISTS_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `lists`: no other call may use it during or after.
 * @param lists the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_index_lists_destroy(o3d_index_lists_t* lists);
/**
 * @brief Number of lists.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the number of lists
 * @param lists the lists
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_index_lists_num_lists(size_t* out, const o3d_index_lists_t* lists);
/**
 * @brief Total number of values over all lists.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the number of values
 * @param lists the lists
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_index_lists_num_values(size_t* out, const o3d_index_lists_t* lists);
/**
 * @brief Copy the offsets (num_lists + 1 values, the first 0) into `out`, which holds `capacity` values;
 * `*out_n` always gets the count. `out` NULL only reports it.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param lists the lists
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_index_lists_get_offsets(int64_t* out, size_t capacity, size_t* out_n,
                                               const o3d_index_lists_t* lists);
/**
 * @brief Copy the values of every list, list after list (total values), into `out`, which holds `capacity`
 * values; `*out_n` always gets the count. `out` NULL only reports it.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param lists the lists
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_index_lists_get_values(int32_t* out, size_t capacity, size_t* out_n,
                                              const o3d_index_lists_t* lists);

O3D_END_DECL

#endif /* O3D_INDEXLISTS_H */
