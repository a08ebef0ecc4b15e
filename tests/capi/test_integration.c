/* SPDX-License-Identifier: MIT */
/* C API integration.h. Checked: a fronto-parallel plane (exact projective distances, so the surface comes back at its
 * depth to float precision (1e-4 m, 1/150 voxel), one vertex per voxel column), Open3D's tutorial frames against Open3D 0.20's numbers
 * (tools/reference/record_tsdf.py: 147927 vertices, 280605 triangles with its uniform volume; its scalable volume is
 * empty there), the uniform volume's arrays, and the error paths. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

#define W 160
#define H 120
#define PLANE_Z 1.0

static const o3d_pinhole_intrinsic_t kSmall = {W, H, 100.0, 100.0, 79.5, 59.5};
static const double kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* A plane at PLANE_Z in front of the camera: float depth and 8-bit RGB (200, 100, 50). */
static o3d_rgbd_image_t* plane_frame(int rgb) {
    float* depth_px = malloc(sizeof(float) * W * H);
    uint8_t* color_px = malloc(3 * W * H);
    for (int i = 0; i < W * H; ++i) {
        depth_px[i] = (float)PLANE_Z;
        color_px[3 * i] = 200;
        color_px[3 * i + 1] = 100;
        color_px[3 * i + 2] = 50;
    }
    o3d_image_t *depth = NULL, *color = NULL;
    assert_int_equal(o3d_image_create_from_data(&depth, W, H, 1, 4, (const uint8_t*)depth_px, sizeof(float) * W * H), O3D_OK);
    assert_int_equal(o3d_image_create_from_data(&color, W, H, 3, 1, color_px, 3 * W * H), O3D_OK);
    o3d_rgbd_options_t o;
    assert_int_equal(o3d_rgbd_options_init(&o, sizeof o), O3D_OK);
    o.depth_scale = 1.0;
    o.convert_rgb_to_intensity = rgb ? 0 : 1;
    o3d_rgbd_image_t* rgbd = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &o), O3D_OK);
    o3d_image_destroy(color);
    o3d_image_destroy(depth);
    free(depth_px);
    free(color_px);
    return rgbd;
}

static void check_plane_mesh(o3d_tsdf_volume_t* volume, size_t expected_vertices) {
    o3d_trianglemesh_t* mesh = NULL;
    assert_int_equal(o3d_tsdf_volume_extract_triangle_mesh(&mesh, volume), O3D_OK);
    size_t rows = 0;
    assert_int_equal(o3d_trianglemesh_get_array(NULL, 0, &rows, mesh, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(rows, expected_vertices);
    double* v = malloc(sizeof(double) * 3 * rows);
    double* c = malloc(sizeof(double) * 3 * rows);
    assert_int_equal(o3d_trianglemesh_get_array(v, rows, &rows, mesh, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_array(c, rows, &rows, mesh, O3D_MESH_VERTEX_COLORS), O3D_OK);
    for (size_t i = 0; i < rows; ++i) {
        assert_float_equal(v[3 * i + 2], PLANE_Z, 1e-4); /* float voxels */
        assert_float_equal(c[3 * i], 200.0 / 255.0, 1e-5);
        assert_float_equal(c[3 * i + 2], 50.0 / 255.0, 1e-5);
    }
    free(v);
    free(c);
    o3d_trianglemesh_destroy(mesh);
}

static void test_plane_comes_back_at_its_depth(void** state) {
    (void)state;
    o3d_rgbd_image_t* frame = plane_frame(1);
    /* A 1 m cube of 64^3 voxels from z = 0.5: the plane crosses every voxel column once. The frustum at 1 m is
     * wider than the cube, so all 64 x 64 columns are seen. */
    const double origin[3] = {-0.5, -0.5, 0.5};
    o3d_tsdf_volume_t* uniform = NULL;
    assert_int_equal(o3d_tsdf_volume_create_uniform(&uniform, 1.0, 64, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_RGB8, origin), O3D_OK);
    assert_int_equal(o3d_tsdf_volume_integrate(uniform, frame, &kSmall, kIdentity), O3D_OK);
    check_plane_mesh(uniform, 64 * 64);
    o3d_trianglemesh_t* mesh = NULL;
    size_t n = 0;
    assert_int_equal(o3d_tsdf_volume_extract_triangle_mesh(&mesh, uniform), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, mesh), O3D_OK);
    assert_int_equal(n, 2 * 63 * 63);
    o3d_trianglemesh_destroy(mesh);

    /* The scalable volume on the same grid sees the part of the plane inside the frustum. */
    o3d_tsdf_volume_t* scalable = NULL;
    assert_int_equal(o3d_tsdf_volume_create_scalable(&scalable, 1.0 / 64, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_RGB8, 16, 4), O3D_OK);
    assert_int_equal(o3d_tsdf_volume_integrate(scalable, frame, &kSmall, kIdentity), O3D_OK);
    size_t blocks = 0;
    assert_int_equal(o3d_tsdf_volume_block_count(&blocks, scalable), O3D_OK);
    assert_true(blocks > 0 && blocks < 100);
    o3d_bool is_scalable = 0;
    assert_int_equal(o3d_tsdf_volume_is_scalable(&is_scalable, scalable), O3D_OK);
    assert_true(is_scalable);
    o3d_pointcloud_t* cloud = NULL;
    assert_int_equal(o3d_tsdf_volume_extract_point_cloud(&cloud, scalable), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, cloud), O3D_OK);
    assert_true(n > 64 * 64);
    o3d_pointcloud_destroy(cloud);
    assert_int_equal(o3d_tsdf_volume_reset(scalable), O3D_OK);
    assert_int_equal(o3d_tsdf_volume_block_count(&blocks, scalable), O3D_OK);
    assert_int_equal(blocks, 0);

    /* Uniform arrays: a voxel in front of the plane (z = 0.5 + 27.5 / 64) holds (1 - z) / 0.04, clamped to 1. */
    size_t rows = 0;
    assert_int_equal(o3d_tsdf_volume_extract_volume_tsdf(NULL, 0, &rows, uniform), O3D_OK);
    assert_int_equal(rows, 64 * 64 * 64);
    float* tsdf = malloc(sizeof(float) * 2 * rows);
    assert_int_equal(o3d_tsdf_volume_extract_volume_tsdf(tsdf, rows - 1, &rows, uniform), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(o3d_tsdf_volume_extract_volume_tsdf(tsdf, rows, &rows, uniform), O3D_OK);
    const size_t at = (size_t)(32 * 64 + 32) * 64 + 30;
    const double z = 0.5 + 30.5 / 64.0;
    assert_float_equal(tsdf[2 * at], (PLANE_Z - z) / 0.04, 1e-4);
    assert_float_equal(tsdf[2 * at + 1], 1.0, 0);
    free(tsdf);
    double length = 0, got_origin[3];
    int32_t resolution = 0, stride = 0;
    assert_int_equal(o3d_tsdf_volume_get_length(&length, uniform), O3D_OK);
    assert_int_equal(o3d_tsdf_volume_get_resolution(&resolution, uniform), O3D_OK);
    assert_int_equal(o3d_tsdf_volume_get_origin(got_origin, uniform), O3D_OK);
    assert_float_equal(length, 1.0, 0);
    assert_int_equal(resolution, 64);
    assert_float_equal(got_origin[2], 0.5, 0);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_get_length(&length, scalable), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_get_depth_sampling_stride(&stride, uniform), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_tsdf_volume_get_depth_sampling_stride(&stride, scalable), O3D_OK);
    assert_int_equal(stride, 4);
    assert_int_equal(o3d_tsdf_volume_get_volume_unit_resolution(&resolution, scalable), O3D_OK);
    assert_int_equal(resolution, 16);
    o3d_tsdf_volume_destroy(uniform);
    o3d_tsdf_volume_destroy(scalable);
    o3d_rgbd_image_destroy(frame);
}

static void test_open3d_tutorial_frames(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(log_path, "open3d/RGBD/trajectory.log");
    o3d_camera_trajectory_t* poses = NULL;
    assert_int_equal(o3d_io_read_pinhole_camera_trajectory(&poses, log_path, NULL), O3D_OK);
    o3d_tsdf_volume_t* volume = NULL;
    assert_int_equal(o3d_tsdf_volume_create_scalable(&volume, 4.0 / 512, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_RGB8, 16, 4), O3D_OK);
    o3d_rgbd_options_t o;
    assert_int_equal(o3d_rgbd_options_init(&o, sizeof o), O3D_OK);
    o.depth_trunc = 4.0;
    o.convert_rgb_to_intensity = 0;
    for (int i = 0; i < 5; ++i) {
        char rel[64];
        o3d_image_t *color = NULL, *depth = NULL;
        snprintf(rel, sizeof rel, "open3d/RGBD/color/0000%d.jpg", i);
        O3D_C_TEST_DATA_OR_SKIP(color_path, rel);
        assert_int_equal(o3d_io_read_image(&color, color_path, NULL), O3D_OK);
        snprintf(rel, sizeof rel, "open3d/RGBD/depth/0000%d.png", i);
        O3D_C_TEST_DATA_OR_SKIP(depth_path, rel);
        assert_int_equal(o3d_io_read_image(&depth, depth_path, NULL), O3D_OK);
        o3d_rgbd_image_t* frame = NULL;
        assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&frame, color, depth, &o), O3D_OK);
        o3d_pinhole_intrinsic_t intrinsic;
        double extrinsic[16];
        assert_int_equal(o3d_camera_trajectory_get(&intrinsic, extrinsic, poses, (size_t)i), O3D_OK);
        assert_int_equal(o3d_tsdf_volume_integrate(volume, frame, &intrinsic, extrinsic), O3D_OK);
        o3d_rgbd_image_destroy(frame);
        o3d_image_destroy(color);
        o3d_image_destroy(depth);
    }
    o3d_trianglemesh_t* mesh = NULL;
    size_t n = 0;
    assert_int_equal(o3d_tsdf_volume_extract_triangle_mesh(&mesh, volume), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, mesh), O3D_OK);
    assert_float_equal((double)n, 147927.0, 0.002 * 147927);
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, mesh), O3D_OK);
    assert_float_equal((double)n, 280605.0, 0.002 * 280605);
    o3d_trianglemesh_destroy(mesh);
    o3d_tsdf_volume_destroy(volume);
    o3d_camera_trajectory_destroy(poses);
}

static void test_errors(void** state) {
    (void)state;
    o3d_tsdf_volume_t* volume = (o3d_tsdf_volume_t*)1;
    O3D_ASSERT_FAILS(o3d_tsdf_volume_create_scalable(&volume, 0.0, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR, 16, 4),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_null(volume);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_create_scalable(&volume, 0.01, NAN, O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR, 16, 4),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_create_scalable(&volume, 0.01, 0.04, 9, 16, 4), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_create_scalable(&volume, 0.01, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR, 1, 4),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_create_uniform(&volume, 1.0, 0, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_create_uniform(NULL, 1.0, 8, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_tsdf_volume_create_scalable(&volume, 0.01, 0.04, O3D_TSDF_VOLUME_COLOR_TYPE_RGB8, 16, 4), O3D_OK);
    o3d_rgbd_image_t* intensity = plane_frame(0);
    o3d_rgbd_image_t* rgb = plane_frame(1);
    /* An RGB8 volume cannot take intensity colour; other sizes, NaN poses and NULLs are errors too. */
    O3D_ASSERT_FAILS(o3d_tsdf_volume_integrate(volume, intensity, &kSmall, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    const o3d_pinhole_intrinsic_t wrong_size = {W * 2, H, 100.0, 100.0, 79.5, 59.5};
    O3D_ASSERT_FAILS(o3d_tsdf_volume_integrate(volume, rgb, &wrong_size, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    double nan_pose[16];
    for (int i = 0; i < 16; ++i) nan_pose[i] = kIdentity[i];
    nan_pose[3] = NAN;
    O3D_ASSERT_FAILS(o3d_tsdf_volume_integrate(volume, rgb, &kSmall, nan_pose), O3D_ERROR_INVALID_ARGUMENT);
    const double singular[16] = {0};
    O3D_ASSERT_FAILS(o3d_tsdf_volume_integrate(volume, rgb, &kSmall, singular), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_integrate(volume, NULL, &kSmall, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_integrate(NULL, rgb, &kSmall, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_integrate(volume, rgb, &kSmall, NULL), O3D_ERROR_INVALID_ARGUMENT);
    size_t blocks = 1;
    assert_int_equal(o3d_tsdf_volume_block_count(&blocks, volume), O3D_OK);
    assert_int_equal(blocks, 0); /* nothing was fused */
    size_t rows = 0;
    O3D_ASSERT_FAILS(o3d_tsdf_volume_extract_volume_tsdf(NULL, 0, &rows, volume), O3D_ERROR_INVALID_ARGUMENT);
    o3d_trianglemesh_t* mesh = (o3d_trianglemesh_t*)1;
    O3D_ASSERT_FAILS(o3d_tsdf_volume_extract_triangle_mesh(&mesh, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(mesh);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_extract_triangle_mesh(NULL, volume), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_tsdf_volume_reset(NULL), O3D_ERROR_INVALID_ARGUMENT);
    double x = 0;
    O3D_ASSERT_FAILS(o3d_tsdf_volume_get_voxel_length(NULL, volume), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_tsdf_volume_get_voxel_length(&x, volume), O3D_OK);
    assert_float_equal(x, 0.01, 0);
    o3d_tsdf_volume_color_type type = -1;
    assert_int_equal(o3d_tsdf_volume_get_color_type(&type, volume), O3D_OK);
    assert_int_equal(type, O3D_TSDF_VOLUME_COLOR_TYPE_RGB8);
    o3d_tsdf_volume_destroy(NULL);
    o3d_tsdf_volume_destroy(volume);
    o3d_rgbd_image_destroy(intensity);
    o3d_rgbd_image_destroy(rgb);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_plane_comes_back_at_its_depth),
        cmocka_unit_test(test_open3d_tutorial_frames),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
