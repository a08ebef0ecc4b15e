/* SPDX-License-Identifier: MIT */
/* libo3d.so through dlopen/dlsym only (this test does not link libo3d; the headers give typedefs):
 * every public function resolves, the list below matches the headers, a small pipeline runs through
 * function pointers, the version matches, and internal C++ symbols are not resolvable. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "o3d/o3d.h"

#ifndef O3D_LIB_PATH
#error "O3D_LIB_PATH must name the built libo3d.so"
#endif

static void* g_lib = NULL;

/* Every function declared in capi/include/o3d/\*.h. test_list_matches_headers keeps it honest. */
static const char* const k_api[] = {
    "o3d_version",
    "o3d_version_major",
    "o3d_version_minor",
    "o3d_version_patch",
    "o3d_last_error_message",
    "o3d_last_error_code",
    "o3d_clear_error",
    "o3d_status_string",
    "o3d_set_verbosity_level",
    "o3d_get_verbosity_level",
    "o3d_set_log_callback",
    "o3d_set_num_threads",
    "o3d_get_num_threads",
    "o3d_buffer_destroy",
    "o3d_buffer_view",
    "o3d_buffer_get_data",
    "o3d_pointcloud_create",
    "o3d_pointcloud_destroy",
    "o3d_pointcloud_clone",
    "o3d_pointcloud_size",
    "o3d_pointcloud_has_points",
    "o3d_pointcloud_has_normals",
    "o3d_pointcloud_has_colors",
    "o3d_pointcloud_clear",
    "o3d_pointcloud_set_points",
    "o3d_pointcloud_set_points_f32",
    "o3d_pointcloud_set_normals",
    "o3d_pointcloud_set_normals_f32",
    "o3d_pointcloud_set_colors",
    "o3d_pointcloud_set_colors_f32",
    "o3d_pointcloud_get_points",
    "o3d_pointcloud_get_normals",
    "o3d_pointcloud_get_colors",
    "o3d_pointcloud_points_view",
    "o3d_pointcloud_normals_view",
    "o3d_pointcloud_colors_view",
    "o3d_pointcloud_points_mutable_view",
    "o3d_pointcloud_normals_mutable_view",
    "o3d_pointcloud_colors_mutable_view",
    "o3d_pointcloud_append",
    "o3d_pointcloud_transform",
    "o3d_pointcloud_translate",
    "o3d_pointcloud_rotate",
    "o3d_pointcloud_scale",
    "o3d_pointcloud_get_min_bound",
    "o3d_pointcloud_get_max_bound",
    "o3d_pointcloud_get_center",
    "o3d_pointcloud_get_axis_aligned_bounding_box",
    "o3d_pointcloud_paint_uniform_color",
    "o3d_pointcloud_select_by_index",
    "o3d_pointcloud_remove_non_finite_points",
    "o3d_pointcloud_normalize_normals",
    "o3d_pointcloud_voxel_down_sample",
    "o3d_pointcloud_uniform_down_sample",
    "o3d_pointcloud_random_down_sample",
    "o3d_pointcloud_farthest_point_down_sample",
    "o3d_search_param_init",
    "o3d_pointcloud_estimate_normals",
    "o3d_pointcloud_orient_normals_to_align_with_direction",
    "o3d_pointcloud_orient_normals_towards_camera_location",
    "o3d_pointcloud_compute_nearest_neighbor_distance",
    "o3d_pointcloud_compute_point_cloud_distance",
    "o3d_pointcloud_remove_statistical_outlier",
    "o3d_pointcloud_remove_radius_outlier",
    "o3d_pointcloud_crop_aabb",
    "o3d_pointcloud_segment_plane",
    "o3d_pointcloud_cluster_dbscan",
    "o3d_pointcloud_compute_mean_and_covariance",
    "o3d_pointcloud_compute_mahalanobis_distance",
    "o3d_kdtree_create_from_pointcloud",
    "o3d_kdtree_create_from_points",
    "o3d_kdtree_destroy",
    "o3d_kdtree_size",
    "o3d_kdtree_search",
    "o3d_kdtree_search_f32",
    "o3d_search_result_destroy",
    "o3d_search_result_counts",
    "o3d_search_result_view",
    "o3d_search_result_get_offsets",
    "o3d_search_result_get_indices",
    "o3d_search_result_get_distances2",
    "o3d_read_options_init",
    "o3d_write_options_init",
    "o3d_io_read_point_cloud",
    "o3d_io_write_point_cloud",
    "o3d_io_read_point_cloud_from_memory",
    "o3d_io_write_point_cloud_to_memory",
    "o3d_icp_options_init",
    "o3d_register_icp",
    "o3d_evaluate_registration",
    "o3d_get_information_matrix_from_point_clouds",
    "o3d_registration_result_destroy",
    "o3d_registration_result_get_transformation",
    "o3d_registration_result_get_fitness",
    "o3d_registration_result_get_inlier_rmse",
    "o3d_registration_result_get_correspondence_set",
    "o3d_feature_create",
    "o3d_feature_create_from_data",
    "o3d_feature_destroy",
    "o3d_feature_clone",
    "o3d_feature_dimension",
    "o3d_feature_num",
    "o3d_feature_resize",
    "o3d_feature_data",
    "o3d_feature_get_data",
    "o3d_feature_select_by_index",
    "o3d_compute_fpfh_feature",
    "o3d_correspondences_from_features",
    "o3d_io_read_feature",
    "o3d_io_write_feature",
    "o3d_kdtree_create_from_feature",
    "o3d_kdtree_create_from_points_xd",
    "o3d_kdtree_dimension",
    "o3d_kdtree_search_xd",
    "o3d_robust_kernel_weight",
    "o3d_correspondence_checker_init",
    "o3d_correspondence_checker_check",
    "o3d_ransac_options_init",
    "o3d_random_seed",
    "o3d_register_ransac_based_on_feature_matching",
    "o3d_register_ransac_based_on_correspondence",
    "o3d_fgr_options_init",
    "o3d_register_fgr_based_on_feature_matching",
    "o3d_register_fgr_based_on_correspondence",
    "o3d_pose_graph_edge_init",
    "o3d_pose_graph_create",
    "o3d_pose_graph_destroy",
    "o3d_pose_graph_clone",
    "o3d_pose_graph_num_nodes",
    "o3d_pose_graph_num_edges",
    "o3d_pose_graph_add_node",
    "o3d_pose_graph_get_node",
    "o3d_pose_graph_set_node",
    "o3d_pose_graph_add_edge",
    "o3d_pose_graph_get_edge",
    "o3d_pose_graph_set_edge",
    "o3d_pose_graph_clear",
    "o3d_io_read_pose_graph",
    "o3d_io_write_pose_graph",
    "o3d_global_optimization_options_init",
    "o3d_global_optimization",
    "o3d_pinhole_intrinsic_set_preset",
    "o3d_camera_trajectory_create",
    "o3d_camera_trajectory_destroy",
    "o3d_camera_trajectory_size",
    "o3d_camera_trajectory_get",
    "o3d_camera_trajectory_append",
    "o3d_camera_trajectory_clear",
    "o3d_image_create",
    "o3d_image_create_from_data",
    "o3d_image_destroy",
    "o3d_image_clone",
    "o3d_image_width",
    "o3d_image_height",
    "o3d_image_num_channels",
    "o3d_image_bytes_per_channel",
    "o3d_image_data_view",
    "o3d_image_data_mutable_view",
    "o3d_image_get_data",
    "o3d_image_filter",
    "o3d_image_downsample",
    "o3d_image_flip_vertical",
    "o3d_image_flip_horizontal",
    "o3d_image_create_float_image",
    "o3d_image_convert_depth_to_float",
    "o3d_mesh_read_options_init",
    "o3d_mesh_write_options_init",
    "o3d_io_read_triangle_mesh",
    "o3d_io_write_triangle_mesh",
    "o3d_io_read_triangle_mesh_from_memory",
    "o3d_io_write_triangle_mesh_to_memory",
    "o3d_io_read_image",
    "o3d_io_write_image",
    "o3d_io_read_image_from_memory",
    "o3d_io_write_image_to_memory",
    "o3d_io_read_pinhole_camera_intrinsic",
    "o3d_io_write_pinhole_camera_intrinsic",
    "o3d_io_read_pinhole_camera_parameters",
    "o3d_io_write_pinhole_camera_parameters",
    "o3d_io_read_pinhole_camera_trajectory",
    "o3d_io_write_pinhole_camera_trajectory",
    "o3d_rgbd_options_init",
    "o3d_rgbd_image_create_from_color_and_depth",
    "o3d_rgbd_image_create_from_dataset_format",
    "o3d_rgbd_image_destroy",
    "o3d_rgbd_image_get_color",
    "o3d_rgbd_image_get_depth",
    "o3d_depth_to_cloud_options_init",
    "o3d_pointcloud_create_from_depth_image",
    "o3d_pointcloud_create_from_rgbd_image",
    "o3d_trianglemesh_create",
    "o3d_trianglemesh_destroy",
    "o3d_trianglemesh_clone",
    "o3d_trianglemesh_clear",
    "o3d_trianglemesh_num_vertices",
    "o3d_trianglemesh_num_triangles",
    "o3d_trianglemesh_has_array",
    "o3d_trianglemesh_set_array",
    "o3d_trianglemesh_get_array",
    "o3d_trianglemesh_array_view",
    "o3d_trianglemesh_array_mutable_view",
    "o3d_trianglemesh_set_index_array",
    "o3d_trianglemesh_get_index_array",
    "o3d_trianglemesh_index_array_view",
    "o3d_trianglemesh_index_array_mutable_view",
    "o3d_trianglemesh_texture_count",
    "o3d_trianglemesh_get_texture",
    "o3d_trianglemesh_add_texture",
    "o3d_trianglemesh_clear_textures",
    "o3d_trianglemesh_append",
    "o3d_trianglemesh_compute_vertex_normals",
    "o3d_trianglemesh_compute_triangle_normals",
    "o3d_trianglemesh_normalize_normals",
    "o3d_trianglemesh_paint_uniform_color",
    "o3d_trianglemesh_transform",
    "o3d_trianglemesh_translate",
    "o3d_trianglemesh_rotate",
    "o3d_trianglemesh_scale",
    "o3d_trianglemesh_get_min_bound",
    "o3d_trianglemesh_get_max_bound",
    "o3d_trianglemesh_get_center",
    "o3d_trianglemesh_get_axis_aligned_bounding_box",
    "o3d_trianglemesh_remove_duplicated_vertices",
    "o3d_trianglemesh_remove_duplicated_triangles",
    "o3d_trianglemesh_remove_degenerate_triangles",
    "o3d_trianglemesh_remove_unreferenced_vertices",
    "o3d_trianglemesh_remove_non_manifold_edges",
    "o3d_trianglemesh_merge_close_vertices",
    "o3d_trianglemesh_get_surface_area",
    "o3d_trianglemesh_get_volume",
    "o3d_trianglemesh_is_watertight",
    "o3d_trianglemesh_is_edge_manifold",
    "o3d_trianglemesh_is_vertex_manifold",
    "o3d_trianglemesh_is_self_intersecting",
    "o3d_trianglemesh_is_orientable",
    "o3d_trianglemesh_euler_poincare_characteristic",
    "o3d_trianglemesh_cluster_connected_triangles",
    "o3d_trianglemesh_sample_points_uniformly",
    "o3d_trianglemesh_sample_points_poisson_disk",
    "o3d_trianglemesh_simplify_vertex_clustering",
    "o3d_trianglemesh_simplify_quadric_decimation",
    "o3d_trianglemesh_filter_smooth_simple",
    "o3d_trianglemesh_filter_smooth_laplacian",
    "o3d_trianglemesh_filter_smooth_taubin",
    "o3d_trianglemesh_subdivide_midpoint",
    "o3d_trianglemesh_subdivide_loop",
    "o3d_trianglemesh_crop_aabb",
    "o3d_trianglemesh_create_box",
    "o3d_trianglemesh_create_sphere",
    "o3d_trianglemesh_create_cylinder",
    "o3d_trianglemesh_create_cone",
    "o3d_trianglemesh_create_torus",
    "o3d_trianglemesh_create_arrow",
    "o3d_trianglemesh_create_coordinate_frame",
    "o3d_trianglemesh_create_tetrahedron",
    "o3d_trianglemesh_create_octahedron",
    "o3d_trianglemesh_create_icosahedron",
    "o3d_obb_create_from_points",
    "o3d_obb_create_from_axis_aligned_bounding_box",
    "o3d_obb_get_box_points",
    "o3d_obb_get_point_indices_within",
    "o3d_pointcloud_get_oriented_bounding_box",
    "o3d_trianglemesh_get_oriented_bounding_box",
    "o3d_pointcloud_crop_obb",
    "o3d_trianglemesh_crop_obb",
    "o3d_pointcloud_compute_convex_hull",
    "o3d_trianglemesh_compute_convex_hull",
    "o3d_pointcloud_hidden_point_removal",
    "o3d_lineset_create",
    "o3d_lineset_destroy",
    "o3d_lineset_clone",
    "o3d_lineset_num_points",
    "o3d_lineset_num_lines",
    "o3d_lineset_set_array",
    "o3d_lineset_get_array",
    "o3d_lineset_array_view",
    "o3d_lineset_set_lines",
    "o3d_lineset_get_lines",
    "o3d_lineset_lines_view",
    "o3d_lineset_paint_uniform_color",
    "o3d_lineset_transform",
    "o3d_lineset_create_from_point_cloud_correspondences",
    "o3d_lineset_create_from_oriented_bounding_box",
    "o3d_lineset_create_from_axis_aligned_bounding_box",
    "o3d_lineset_create_from_triangle_mesh",
    "o3d_octree_create",
    "o3d_octree_destroy",
    "o3d_octree_convert_from_point_cloud",
    "o3d_octree_get_root",
    "o3d_octree_num_leaf_nodes",
    "o3d_octree_locate_leaf_node",
    "o3d_pointcloud_has_covariances",
    "o3d_pointcloud_set_covariances",
    "o3d_pointcloud_get_covariances",
    "o3d_pointcloud_covariances_view",
    "o3d_pointcloud_estimate_covariances",
    "o3d_voxelgrid_create_from_point_cloud",
    "o3d_voxelgrid_create_from_point_cloud_within_bounds",
    "o3d_voxelgrid_create_from_triangle_mesh",
    "o3d_voxelgrid_destroy",
    "o3d_voxelgrid_get_voxel_size",
    "o3d_voxelgrid_get_origin",
    "o3d_voxelgrid_num_voxels",
    "o3d_voxelgrid_get_voxels",
    "o3d_voxelgrid_get_voxel",
    "o3d_voxelgrid_check_if_included",
};
#define API_COUNT (sizeof k_api / sizeof k_api[0])

static int group_setup(void** state) {
    (void)state;
    /* Only dlclose-safe because libo3d is linked with -z nodelete (libgomp workers); we never close it. */
    g_lib = dlopen(O3D_LIB_PATH, RTLD_NOW | RTLD_LOCAL);
    if (!g_lib) fprintf(stderr, "dlopen(%s): %s\n", O3D_LIB_PATH, dlerror());
    return g_lib ? 0 : -1;
}

static void* sym(const char* name) {
    void* p;
    dlerror();
    p = dlsym(g_lib, name);
    if (!p) fail_msg("dlsym(%s): %s", name, dlerror());
    return p;
}

/* Convert a dlsym'd object pointer to a function pointer (POSIX guarantees this works). */
#define LOAD(var, name) memcpy(&(var), &(void*){sym(name)}, sizeof(var))

static void test_every_public_function_resolves(void** state) {
    size_t i;
    (void)state;
    for (i = 0; i < API_COUNT; ++i) assert_non_null(sym(k_api[i]));
}

/* ---- the static list equals the O3D_API declarations in the headers ---- */

static int in_list(const char* name) {
    size_t i;
    for (i = 0; i < API_COUNT; ++i)
        if (strcmp(k_api[i], name) == 0) return 1;
    return 0;
}

/* Append the name of every `O3D_API ... name(` declaration in `text` to names[]. */
static size_t scan_declarations(const char* text, char names[][96], size_t count, size_t max) {
    const char* p = text;
    while ((p = strstr(p, "O3D_API")) != NULL) {
        const char* line = p;
        const char *paren, *end, *begin;
        while (line > text && line[-1] != '\n') --line;
        p += 7;
        if (strstr(line, "#define") && strstr(line, "#define") < p) continue; /* the macro itself */
        if (*line == '#') continue;
        paren = strchr(p, '(');
        if (!paren) break;
        end = paren;
        while (end > p && (end[-1] == ' ' || end[-1] == '\n')) --end;
        begin = end;
        while (begin > p && (begin[-1] == '_' || (begin[-1] >= 'a' && begin[-1] <= 'z') ||
                             (begin[-1] >= 'A' && begin[-1] <= 'Z') || (begin[-1] >= '0' && begin[-1] <= '9')))
            --begin;
        if (count < max && end > begin && (size_t)(end - begin) < 96) {
            memcpy(names[count], begin, (size_t)(end - begin));
            names[count][end - begin] = '\0';
            ++count;
        }
        p = paren;
    }
    return count;
}

static void test_list_matches_headers(void** state) {
    /* Every function declared in the public headers (O3D_PUBLIC_HEADER_DIR) is in k_api. */
    static char names[512][96];
    char dir[4096], path[4200];
    DIR* d;
    struct dirent* e;
    size_t count = 0, i, j, headers = 0;
    (void)state;
    /* An absolute path from CMake: __FILE__ may be relative (ccache base_dir, out-of-tree builds). */
    snprintf(dir, sizeof dir, "%s", O3D_PUBLIC_HEADER_DIR);
    d = opendir(dir);
    if (!d) fail_msg("cannot open the public header folder %s", dir);
    while ((e = readdir(d)) != NULL) {
        FILE* f;
        long size;
        char* text;
        const size_t len = strlen(e->d_name);
        if (len < 3 || strcmp(e->d_name + len - 2, ".h") != 0) continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        f = fopen(path, "rb");
        assert_non_null(f);
        fseek(f, 0, SEEK_END);
        size = ftell(f);
        fseek(f, 0, SEEK_SET);
        text = (char*)calloc((size_t)size + 1, 1);
        assert_non_null(text);
        assert_int_equal(fread(text, 1, (size_t)size, f), (size_t)size);
        fclose(f);
        count = scan_declarations(text, names, count, 512);
        free(text);
        ++headers;
    }
    closedir(d);
    assert_true(headers >= 5);
    for (i = 0; i < count; ++i)
        if (!in_list(names[i])) fail_msg("%s is declared in the headers but missing from test_dlopen.c", names[i]);
    for (i = 0; i < API_COUNT; ++i) {
        int found = 0;
        for (j = 0; j < count && !found; ++j) found = strcmp(names[j], k_api[i]) == 0;
        if (!found) fail_msg("%s is in test_dlopen.c but not declared in any header", k_api[i]);
    }
    assert_int_equal(count, API_COUNT);
}

/* ---- version and errors through pointers ---- */

static void test_version_matches_header(void** state) {
    const char* (*version)(void);
    int32_t (*major)(void);
    int32_t (*minor)(void);
    char expected[64];
    (void)state;
    LOAD(version, "o3d_version");
    LOAD(major, "o3d_version_major");
    LOAD(minor, "o3d_version_minor");
    snprintf(expected, sizeof expected, "%d.%d.%d", O3D_VERSION_MAJOR, O3D_VERSION_MINOR, O3D_VERSION_PATCH);
    assert_string_equal(version(), expected);
    assert_int_equal(major(), O3D_VERSION_MAJOR);
    assert_int_equal(minor(), O3D_VERSION_MINOR);
}

static void test_error_through_pointers(void** state) {
    o3d_status (*set_num_threads)(int32_t);
    const char* (*message)(void);
    o3d_status (*code)(void);
    (void)state;
    LOAD(set_num_threads, "o3d_set_num_threads");
    LOAD(message, "o3d_last_error_message");
    LOAD(code, "o3d_last_error_code");
    assert_int_equal(set_num_threads(-1), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(code(), O3D_ERROR_INVALID_ARGUMENT);
    assert_true(message()[0] != '\0');
}

/* ---- a small pipeline through function pointers ---- */

static void test_pipeline_through_pointers(void** state) {
    o3d_status (*create)(o3d_pointcloud_t**);
    void (*destroy)(o3d_pointcloud_t*);
    o3d_status (*set_points)(o3d_pointcloud_t*, const double*, size_t);
    o3d_status (*voxel)(o3d_pointcloud_t**, const o3d_pointcloud_t*, double);
    o3d_status (*size)(const o3d_pointcloud_t*, size_t*);
    o3d_status (*get_points)(const o3d_pointcloud_t*, double*, size_t, size_t*);
    o3d_pointcloud_t *pc = NULL, *down = NULL;
    /* 8 tight clusters (5x5x5 points, spacing 0.01) at the corners of a cube of side 10: voxel size 1
     * keeps one point per cluster, their means, wherever the voxel grid starts. */
    static double xyz[3 * 1000];
    double out[3 * 8];
    size_t n = 0, i;
    (void)state;
    LOAD(create, "o3d_pointcloud_create");
    LOAD(destroy, "o3d_pointcloud_destroy");
    LOAD(set_points, "o3d_pointcloud_set_points");
    LOAD(voxel, "o3d_pointcloud_voxel_down_sample");
    LOAD(size, "o3d_pointcloud_size");
    LOAD(get_points, "o3d_pointcloud_get_points");
    for (i = 0; i < 1000; ++i) {
        const size_t c = i / 125, l = i % 125;
        xyz[3 * i + 0] = 10.0 * (double)(c & 1) + 0.01 * (double)(l % 5);
        xyz[3 * i + 1] = 10.0 * (double)((c >> 1) & 1) + 0.01 * (double)((l / 5) % 5);
        xyz[3 * i + 2] = 10.0 * (double)((c >> 2) & 1) + 0.01 * (double)(l / 25);
    }
    assert_int_equal(create(&pc), O3D_OK);
    assert_int_equal(set_points(pc, xyz, 1000), O3D_OK);
    assert_int_equal(size(pc, &n), O3D_OK);
    assert_int_equal(n, 1000);
    assert_int_equal(voxel(&down, pc, 1.0), O3D_OK);
    assert_non_null(down);
    assert_int_equal(size(down, &n), O3D_OK);
    assert_int_equal(n, 8);
    assert_int_equal(get_points(down, out, 8, &n), O3D_OK);
    for (i = 0; i < 24; ++i) {
        const double d0 = out[i] - 0.02, d1 = out[i] - 10.02;
        if (!((d0 > -1e-9 && d0 < 1e-9) || (d1 > -1e-9 && d1 < 1e-9))) fail_msg("coordinate %zu = %.17g", i, out[i]);
    }
    destroy(down);
    destroy(pc);
    destroy(NULL);
}

/* ---- nothing but o3d_* is exported ---- */

static void test_internal_symbols_are_hidden(void** state) {
    /* Mangled names of functions inside libo3d.so (see `nm build/core/libo3d_core.a`). */
    static const char* const internal[] = {
        "_ZN3o3d7utility19resolve_num_threadsEi",           /* o3d::utility::resolve_num_threads(int) */
        "_ZN3o3d7utility19set_verbosity_levelENS0_8LogLevelE", /* o3d::utility::set_verbosity_level */
        "_ZN3o3d7utility19get_verbosity_levelEv",
        "_ZN3o3d4capi11reset_errorEv", /* o3d::capi::reset_error() */
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof internal / sizeof internal[0]; ++i) {
        dlerror();
        if (dlsym(g_lib, internal[i]) != NULL) fail_msg("internal symbol %s is exported", internal[i]);
    }
    /* Sanity: the same lookup does find a public one. */
    assert_non_null(dlsym(g_lib, "o3d_version"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_public_function_resolves),
        cmocka_unit_test(test_list_matches_headers),
        cmocka_unit_test(test_version_matches_header),
        cmocka_unit_test(test_error_through_pointers),
        cmocka_unit_test(test_pipeline_through_pointers),
        cmocka_unit_test(test_internal_symbols_are_hidden),
    };
    return cmocka_run_group_tests_name("o3d_dlopen", tests, group_setup, NULL);
}
