/* SPDX-License-Identifier: MIT */
/* C API visualization.h: offscreen renders of known scenes checked against the camera model (background in
 * the corners, an unlit object's colour at its projected centre, depth along the optical axis, silhouette
 * areas against the analytic ones), camera round trips, RenderOption JSON, and the error paths.
 * Runs headless: EGL (Mesa's surfaceless platform renders in software without a display). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

#define W 160
#define H 120
/* Camera at the world origin looking along +z (Open3D's camera frame: x right, y down). */
static const double kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
static const o3d_pinhole_intrinsic_t kIntrinsic = {W, H, 100.0, 100.0, (W - 1) / 2.0, (H - 1) / 2.0};

static o3d_offscreen_renderer_t* new_renderer(void) {
    o3d_offscreen_renderer_t* r = NULL;
    assert_int_equal(o3d_offscreen_renderer_create(&r, W, H, O3D_RENDER_BACKEND_AUTO), O3D_OK);
    return r;
}

static o3d_render_material_t unlit(void) {
    o3d_render_material_t m;
    assert_int_equal(o3d_render_material_init(&m, sizeof m), O3D_OK);
    m.shader = O3D_SHADER_DEFAULT_UNLIT;
    return m;
}

/* A `size` cube centred at (0, 0, z), painted `rgb`. */
static o3d_trianglemesh_t* cube_at(double size, double z, const double rgb[3]) {
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create_box(&m, size, size, size), O3D_OK);
    const double t[16] = {1, 0, 0, -size / 2, 0, 1, 0, -size / 2, 0, 0, 1, z - size / 2, 0, 0, 0, 1};
    assert_int_equal(o3d_trianglemesh_transform(m, t), O3D_OK);
    assert_int_equal(o3d_trianglemesh_paint_uniform_color(m, rgb), O3D_OK);
    return m;
}

static const uint8_t* rgb_at(const o3d_image_t* image, int u, int v) {
    const uint8_t* data = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_image_array_view(&data, &rows, image, O3D_IMAGE_DATA), O3D_OK);
    return data + ((size_t)v * W + (size_t)u) * 3;
}

static float depth_at(const o3d_image_t* image, int u, int v) {
    const uint8_t* data = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_image_array_view(&data, &rows, image, O3D_IMAGE_DATA), O3D_OK);
    float d;
    memcpy(&d, data + ((size_t)v * W + (size_t)u) * 4, 4);
    return d;
}

static int count_color(const o3d_image_t* image, int r, int g, int b) {
    int n = 0;
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) {
            const uint8_t* p = rgb_at(image, u, v);
            n += p[0] == r && p[1] == g && p[2] == b;
        }
    return n;
}

static void test_unit_cube_colour_depth_silhouette(void** state) {
    (void)state;
    o3d_offscreen_renderer_t* r = new_renderer();
    const double red[3] = {1, 0, 0};
    o3d_trianglemesh_t* cube = cube_at(1.0, 3.0, red); /* front face at z = 2.5 */
    const o3d_render_material_t m = unlit();
    assert_int_equal(o3d_offscreen_renderer_add_trianglemesh(r, "cube", cube, &m), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_setup_camera(r, &kIntrinsic, kIdentity), O3D_OK);

    o3d_image_t* image = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    int32_t value = 0;
    assert_int_equal(o3d_image_width(&value, image), O3D_OK);
    assert_int_equal(value, W);
    /* Background: Open3D's default white, in every corner. */
    const int corners[4][2] = {{0, 0}, {W - 1, 0}, {0, H - 1}, {W - 1, H - 1}};
    for (int k = 0; k < 4; ++k) {
        const uint8_t* p = rgb_at(image, corners[k][0], corners[k][1]);
        assert_true(p[0] == 255 && p[1] == 255 && p[2] == 255);
    }
    /* The cube's colour at the projection of its centre (the principal point). */
    const uint8_t* c = rgb_at(image, W / 2, H / 2);
    assert_true(c[0] == 255 && c[1] == 0 && c[2] == 0);
    /* Silhouette: the front face, 1 m at 2.5 m, spans f / 2.5 = 40 pixels each way: 1600 pixels. */
    const int area = count_color(image, 255, 0, 0);
    assert_true(fabs(area - 1600.0) / 1600.0 < 0.03);

    /* Depth along the optical axis: the front face's 2.5 m; nothing drawn: 0, or 1 in the raw buffer. */
    o3d_image_t* depth = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_depth_image(&depth, r, 1), O3D_OK);
    assert_true(fabs(depth_at(depth, W / 2, H / 2) - 2.5) < 1e-3);
    assert_true(fabs(depth_at(depth, W / 2 + 15, H / 2 - 12) - 2.5) < 1e-3); /* a plane facing the camera */
    assert_true(depth_at(depth, 0, 0) == 0.0f);
    o3d_image_destroy(depth);
    assert_int_equal(o3d_offscreen_renderer_render_to_depth_image(&depth, r, 0), O3D_OK);
    assert_true(depth_at(depth, 0, 0) == 1.0f);
    assert_true(depth_at(depth, W / 2, H / 2) > 0.0f && depth_at(depth, W / 2, H / 2) < 1.0f);
    o3d_image_destroy(depth);
    o3d_image_destroy(image);
    o3d_trianglemesh_destroy(cube);
    o3d_offscreen_renderer_destroy(r);
}

static void test_sphere_silhouette_area(void** state) {
    (void)state;
    o3d_offscreen_renderer_t* r = new_renderer();
    o3d_trianglemesh_t* sphere = NULL;
    assert_int_equal(o3d_trianglemesh_create_sphere(&sphere, 1.0, 60), O3D_OK);
    const double t[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 4.0, 0, 0, 0, 1};
    assert_int_equal(o3d_trianglemesh_transform(sphere, t), O3D_OK);
    const double green[3] = {0, 1, 0};
    assert_int_equal(o3d_trianglemesh_paint_uniform_color(sphere, green), O3D_OK);
    const o3d_render_material_t m = unlit();
    assert_int_equal(o3d_offscreen_renderer_add_trianglemesh(r, "sphere", sphere, &m), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_setup_camera(r, &kIntrinsic, kIdentity), O3D_OK);
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    /* A sphere of radius r at distance d on the axis projects to a disc of radius f r / sqrt(d^2 - r^2). */
    const double radius = 100.0 / sqrt(15.0);
    const double expected = M_PI * radius * radius;
    const int area = count_color(image, 0, 255, 0);
    assert_true(fabs(area - expected) / expected < 0.03);
    /* Depth at the centre: the sphere's near pole, at 3 m. */
    o3d_image_t* depth = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_depth_image(&depth, r, 1), O3D_OK);
    assert_true(fabs(depth_at(depth, W / 2, H / 2) - 3.0) < 2e-3);
    o3d_image_destroy(depth);
    o3d_image_destroy(image);
    o3d_trianglemesh_destroy(sphere);
    o3d_offscreen_renderer_destroy(r);
}

static void test_coloured_point_cloud(void** state) {
    (void)state;
    o3d_offscreen_renderer_t* r = new_renderer();
    /* Three points at 2 m: on the axis, and 0.4 m right / 0.3 m up (pixels (W-1)/2 + 20, (H-1)/2 - 15). */
    const double points[9] = {0, 0, 2, 0.4, 0, 2, 0, -0.3, 2};
    const double colors[9] = {1, 0, 0, 0, 0, 1, 0, 0.50196, 0};
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, points, 3), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COLORS, colors, 3), O3D_OK);
    o3d_render_material_t m = unlit();
    m.point_size = 6;
    assert_int_equal(o3d_offscreen_renderer_add_pointcloud(r, "cloud", pc, &m), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_setup_camera(r, &kIntrinsic, kIdentity), O3D_OK);
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    const uint8_t* a = rgb_at(image, W / 2, H / 2);
    assert_true(a[0] == 255 && a[1] == 0 && a[2] == 0);
    const uint8_t* b = rgb_at(image, W / 2 + 20, H / 2);
    assert_true(b[0] == 0 && b[1] == 0 && b[2] == 255);
    const uint8_t* c = rgb_at(image, W / 2, H / 2 - 15);
    assert_true(c[0] == 0 && c[1] == 128 && c[2] == 0);
    /* Square points of 6 pixels: 36 pixels each. */
    assert_int_equal(count_color(image, 255, 0, 0), 36);
    assert_int_equal(count_color(image, 0, 0, 255), 36);
    o3d_image_destroy(image);
    o3d_pointcloud_destroy(pc);
    o3d_offscreen_renderer_destroy(r);
}

static void test_background_lighting_and_options(void** state) {
    (void)state;
    o3d_offscreen_renderer_t* r = new_renderer();
    const double white[3] = {1, 1, 1};
    o3d_trianglemesh_t* cube = cube_at(1.0, 3.0, white);
    assert_int_equal(o3d_offscreen_renderer_add_trianglemesh(r, "cube", cube, NULL), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_setup_camera(r, &kIntrinsic, kIdentity), O3D_OK);
    o3d_render_option_t o;
    assert_int_equal(o3d_render_option_init(&o, sizeof o), O3D_OK);
    assert_true(o.point_size == 5 && o.light_on == 1 && o.mesh_color_option == O3D_COLOR_OPTION_COLOR);
    o.background_color[0] = 0.2;
    o.background_color[1] = 0.4;
    o.background_color[2] = 0.6;
    o.light_on = 0;
    o.mesh_color_option = O3D_COLOR_OPTION_DEFAULT; /* default_mesh_color, 0.7 gray */
    assert_int_equal(o3d_offscreen_renderer_set_render_option(r, &o), O3D_OK);
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    const uint8_t* bg = rgb_at(image, 0, 0);
    assert_true(abs(bg[0] - 51) <= 1 && abs(bg[1] - 102) <= 1 && abs(bg[2] - 153) <= 1);
    const uint8_t* c = rgb_at(image, W / 2, H / 2);
    assert_true(abs(c[0] - 179) <= 1 && c[0] == c[1] && c[1] == c[2]);
    o3d_image_destroy(image);

    /* Lit (Open3D's lights: two in front of the scene): the face towards the camera is brighter than unlit,
     * and its colour is the material's white, saturated; no light at all (powers 0) leaves it black. */
    o.light_on = 1;
    o.mesh_color_option = O3D_COLOR_OPTION_COLOR;
    assert_int_equal(o3d_offscreen_renderer_set_render_option(r, &o), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    c = rgb_at(image, W / 2, H / 2);
    assert_true(c[0] > 200 && c[0] == c[1] && c[1] == c[2]);
    o3d_image_destroy(image);
    for (int i = 0; i < 4; ++i) o.light_diffuse_power[i] = o.light_specular_power[i] = 0;
    assert_int_equal(o3d_offscreen_renderer_set_render_option(r, &o), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    c = rgb_at(image, W / 2, H / 2);
    assert_true(c[0] == 0 && c[1] == 0 && c[2] == 0);
    o3d_image_destroy(image);

    o3d_render_option_t back;
    assert_int_equal(o3d_render_option_init(&back, sizeof back), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_get_render_option(&back, r), O3D_OK);
    assert_true(back.background_color[2] == 0.6 && back.light_diffuse_power[3] == 0);
    o3d_trianglemesh_destroy(cube);
    o3d_offscreen_renderer_destroy(r);
}

static void test_camera_round_trip(void** state) {
    (void)state;
    o3d_offscreen_renderer_t* r = new_renderer();
    o3d_trianglemesh_t* sphere = NULL;
    assert_int_equal(o3d_trianglemesh_create_sphere(&sphere, 1.0, 20), O3D_OK);
    assert_int_equal(o3d_trianglemesh_compute_vertex_normals(sphere, 1), O3D_OK);
    const double blue[3] = {0.1, 0.3, 0.9};
    o3d_trianglemesh_t* cube = cube_at(0.5, 1.5, blue);
    assert_int_equal(o3d_offscreen_renderer_add_trianglemesh(r, "sphere", sphere, NULL), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_add_trianglemesh(r, "cube", cube, NULL), O3D_OK);

    /* Open3D's default view: fx = fy = H / (2 tan 30 deg), principal point at the centre, looking along -z. */
    o3d_pinhole_intrinsic_t k;
    double e[16];
    assert_int_equal(o3d_offscreen_renderer_get_camera(&k, e, r), O3D_OK);
    assert_true(fabs(k.fx - H / (2 * tan(M_PI / 6))) < 1e-9 && k.fx == k.fy);
    assert_true(k.cx == (W - 1) / 2.0 && k.cy == (H - 1) / 2.0);
    assert_true(e[10] == -1.0 && e[5] == -1.0 && e[0] == 1.0);

    const double lookat[3] = {0.2, 0.1, 0.5}, front[3] = {0.4, 0.6, 1.0}, up[3] = {0, 1, 0};
    assert_int_equal(o3d_offscreen_renderer_setup_camera_lookat(r, lookat, front, up, 0.9), O3D_OK);
    o3d_image_t* a = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&a, r), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_get_camera(&k, e, r), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_setup_camera(r, &k, e), O3D_OK);
    o3d_image_t* b = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&b, r), O3D_OK);
    const uint8_t *pa = NULL, *pb = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_image_array_view(&pa, &rows, a, O3D_IMAGE_DATA), O3D_OK);
    assert_int_equal(o3d_image_array_view(&pb, &rows, b, O3D_IMAGE_DATA), O3D_OK);
    assert_memory_equal(pa, pb, (size_t)W * H * 3);
    assert_true(count_color(a, 255, 255, 255) < W * H - 500); /* the scene is in view */

    /* eye/center/up with a field of view: the same camera as lookat/front/up when the eye is placed alike. */
    const double center[3] = {0, 0, 0}, eye[3] = {0, 0, 5};
    assert_int_equal(o3d_offscreen_renderer_setup_camera_fov(r, 60.0, center, eye, up), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_get_camera(&k, e, r), O3D_OK);
    assert_true(fabs(e[11] - 5.0) < 1e-12 && e[10] == -1.0);
    o3d_image_destroy(a);
    o3d_image_destroy(b);
    o3d_trianglemesh_destroy(sphere);
    o3d_trianglemesh_destroy(cube);
    o3d_offscreen_renderer_destroy(r);
}

static void test_lineset_voxelgrid_and_png(void** state) {
    (void)state;
    o3d_offscreen_renderer_t* r = new_renderer();
    o3d_lineset_t* ls = NULL;
    assert_int_equal(o3d_lineset_create(&ls), O3D_OK);
    const double pts[6] = {-1, 0.01, 2, 1, 0.01, 2}; /* a horizontal line along pixel row 60, columns 30..129 */
    const int32_t lines[2] = {0, 1};
    assert_int_equal(o3d_lineset_set_array(ls, O3D_LINESET_POINTS, pts, 2), O3D_OK);
    assert_int_equal(o3d_lineset_set_index_array(ls, O3D_LINESET_LINES, lines, 1), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_add_lineset(r, "line", ls, NULL), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_setup_camera(r, &kIntrinsic, kIdentity), O3D_OK);
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    /* Lines without colours are black (Open3D); the line crosses the image at the middle row. */
    int black_in_column = 0;
    for (int v = 0; v < H; ++v) black_in_column += rgb_at(image, 50, v)[0] == 0;
    assert_int_equal(rgb_at(image, 50, 60)[0], 0);
    assert_int_equal(black_in_column, 1);
    o3d_image_destroy(image);

    /* A voxel grid of one unit voxel around (0, 0, 3): drawn as the unit cube, so 1600 pixels of its colour. */
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    const double p3[3] = {0, 0, 3}, red[3] = {1, 0, 0};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, p3, 1), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COLORS, red, 1), O3D_OK);
    o3d_voxelgrid_t* grid = NULL;
    assert_int_equal(o3d_voxelgrid_create_from_point_cloud(&grid, pc, 1.0), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_remove_geometry(r, "line"), O3D_OK);
    const o3d_render_material_t m = unlit();
    assert_int_equal(o3d_offscreen_renderer_add_voxelgrid(r, "voxels", grid, &m), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_render_to_image(&image, r), O3D_OK);
    assert_true(fabs(count_color(image, 255, 0, 0) - 1600.0) / 1600.0 < 0.03);
    o3d_image_destroy(image);
    o3d_voxelgrid_destroy(grid);
    o3d_pointcloud_destroy(pc);
    assert_int_equal(o3d_offscreen_renderer_add_lineset(r, "line", ls, NULL), O3D_OK);

    int32_t has = 0;
    assert_int_equal(o3d_offscreen_renderer_has_geometry(&has, r, "line"), O3D_OK);
    assert_int_equal(has, 1);
    assert_int_equal(o3d_offscreen_renderer_clear_geometries(r), O3D_OK);
    assert_int_equal(o3d_offscreen_renderer_has_geometry(&has, r, "line"), O3D_OK);
    assert_int_equal(has, 0);

    char path[256];
    snprintf(path, sizeof path, "/tmp/o3d_capi_vis_%d.png", (int)getpid());
    assert_int_equal(o3d_offscreen_renderer_render_to_png(r, path), O3D_OK);
    o3d_image_t* read = NULL;
    assert_int_equal(o3d_io_read_image(&read, path, NULL), O3D_OK);
    int32_t w = 0;
    assert_int_equal(o3d_image_width(&w, read), O3D_OK);
    assert_int_equal(w, W);
    o3d_image_destroy(read);
    unlink(path);
    o3d_lineset_destroy(ls);
    o3d_offscreen_renderer_destroy(r);
}

static void test_render_option_json(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/renderoption.json");
    o3d_render_option_t o;
    assert_int_equal(o3d_render_option_init(&o, sizeof o), O3D_OK);
    assert_int_equal(o3d_render_option_load_json(&o, path), O3D_OK);
    /* Values of the file (Open3D's test data). */
    assert_int_equal(o.point_color_option, O3D_COLOR_OPTION_NORMAL);
    assert_int_equal(o.mesh_color_option, O3D_COLOR_OPTION_COLOR);
    assert_true(o.point_size == 5 && o.light_diffuse_power[0] == 0.66 && o.light_position[8] == -2);
    assert_true(o.light_specular_shininess[3] == 100 && o.default_mesh_color[0] == 0.7);

    char out[256];
    snprintf(out, sizeof out, "/tmp/o3d_capi_renderoption_%d.json", (int)getpid());
    o.point_size = 3;
    o.background_color[1] = 0.25;
    assert_int_equal(o3d_render_option_save_json(out, &o), O3D_OK);
    o3d_render_option_t again;
    assert_int_equal(o3d_render_option_init(&again, sizeof again), O3D_OK);
    assert_int_equal(o3d_render_option_load_json(&again, out), O3D_OK);
    assert_memory_equal(&o, &again, sizeof o);

    FILE* f = fopen(out, "wb");
    fputs("{\"class_name\": \"RenderOption\", \"point_size\": 99}", f); /* out of range */
    fclose(f);
    O3D_ASSERT_FAILS(o3d_render_option_load_json(&again, out), O3D_ERROR_PARSE);
    assert_true(again.point_size == 3); /* unchanged */
    f = fopen(out, "wb");
    fputs("{\"class_name\": \"RenderOption\", \"point_size\": ", f);
    fclose(f);
    O3D_ASSERT_FAILS(o3d_render_option_load_json(&again, out), O3D_ERROR_PARSE);
    unlink(out);
    O3D_ASSERT_FAILS(o3d_render_option_load_json(&again, "/nonexistent/renderoption.json"), O3D_ERROR_IO);
}

/* The hidden-window fallback (GLFW) draws what EGL draws. Needs a display: ctest runs this file a second
 * time under xvfb-run (capi_test_visualization_xvfb); without DISPLAY it is skipped. */
static void test_glfw_backend_matches_egl(void** state) {
    (void)state;
    const char* display = getenv("DISPLAY");
    if (!display || !*display) skip();
    const double red[3] = {1, 0, 0};
    o3d_trianglemesh_t* cube = cube_at(1.0, 3.0, red);
    o3d_image_t* images[2] = {NULL, NULL};
    const int32_t backends[2] = {O3D_RENDER_BACKEND_EGL, O3D_RENDER_BACKEND_GLFW};
    for (int k = 0; k < 2; ++k) {
        o3d_offscreen_renderer_t* r = NULL;
        assert_int_equal(o3d_offscreen_renderer_create(&r, W, H, backends[k]), O3D_OK);
        int32_t backend = 0;
        assert_int_equal(o3d_offscreen_renderer_get_backend(&backend, r), O3D_OK);
        assert_int_equal(backend, backends[k]);
        assert_int_equal(o3d_offscreen_renderer_add_trianglemesh(r, "cube", cube, NULL), O3D_OK);
        assert_int_equal(o3d_offscreen_renderer_setup_camera(r, &kIntrinsic, kIdentity), O3D_OK);
        assert_int_equal(o3d_offscreen_renderer_render_to_image(&images[k], r), O3D_OK);
        o3d_offscreen_renderer_destroy(r);
    }
    assert_int_equal(count_color(images[1], 255, 255, 255), count_color(images[0], 255, 255, 255));
    const uint8_t* c = rgb_at(images[1], W / 2, H / 2);
    const uint8_t* e = rgb_at(images[0], W / 2, H / 2);
    assert_true(c[0] == e[0] && c[1] == e[1] && c[2] == e[2] && c[0] > 200); /* lit red, as on EGL */
    o3d_image_destroy(images[0]);
    o3d_image_destroy(images[1]);
    o3d_trianglemesh_destroy(cube);
}

static void test_errors(void** state) {
    (void)state;
    o3d_offscreen_renderer_t* r = NULL;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_create(&r, 0, 10, O3D_RENDER_BACKEND_AUTO), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(r);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_create(&r, 10, 10, 7), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_create(NULL, 10, 10, 0), O3D_ERROR_INVALID_ARGUMENT);
    r = new_renderer();
    const double red[3] = {1, 0, 0};
    o3d_trianglemesh_t* cube = cube_at(1.0, 3.0, red);
    assert_int_equal(o3d_offscreen_renderer_add_trianglemesh(r, "cube", cube, NULL), O3D_OK);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(r, "cube", cube, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(r, "", cube, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(r, NULL, cube, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(r, "x", NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(NULL, "x", cube, NULL), O3D_ERROR_INVALID_ARGUMENT);
    o3d_render_material_t bad;
    assert_int_equal(o3d_render_material_init(&bad, sizeof bad), O3D_OK);
    bad.shader = 5;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(r, "y", cube, &bad), O3D_ERROR_INVALID_ARGUMENT);
    bad.shader = O3D_SHADER_DEFAULT_LIT;
    bad.struct_size = 3;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(r, "y", cube, &bad), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_remove_geometry(r, "missing"), O3D_ERROR_INVALID_ARGUMENT);

    /* A triangle index out of range is refused before anything is drawn. */
    const int32_t tri[3] = {0, 1, 99};
    assert_int_equal(o3d_trianglemesh_set_index_array(cube, O3D_MESH_TRIANGLES, tri, 1), O3D_OK);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_add_trianglemesh(r, "broken", cube, NULL), O3D_ERROR_INVALID_ARGUMENT);

    o3d_pinhole_intrinsic_t k = kIntrinsic;
    k.width = W + 1;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera(r, &k, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    k = kIntrinsic;
    k.fx = NAN;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera(r, &k, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    const double scaled[16] = {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera(r, &kIntrinsic, scaled), O3D_ERROR_INVALID_ARGUMENT);
    const double zero[3] = {0, 0, 0}, z[3] = {0, 0, 1}, y[3] = {0, 1, 0};
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera_lookat(r, zero, z, y, 5.0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera_lookat(r, zero, zero, y, 0.7), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera_lookat(r, zero, y, y, 0.7), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera_fov(r, 180.0, zero, z, y), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_setup_camera_fov(r, 60.0, zero, zero, y), O3D_ERROR_INVALID_ARGUMENT);

    o3d_render_option_t o;
    assert_int_equal(o3d_render_option_init(&o, sizeof o), O3D_OK);
    o.point_size = NAN;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_set_render_option(r, &o), O3D_ERROR_INVALID_ARGUMENT);
    o.point_size = 5;
    o.point_color_option = 7;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_set_render_option(r, &o), O3D_ERROR_INVALID_ARGUMENT);
    o.point_color_option = 0;
    o.light_on = 2;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_set_render_option(r, &o), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_render_option_init(&o, 2), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_render_to_image(NULL, r), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_t* image = NULL;
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_render_to_image(&image, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_offscreen_renderer_render_to_png(r, "/nonexistent/dir/x.png"), O3D_ERROR_IO);
    o3d_offscreen_renderer_destroy(NULL);
    o3d_trianglemesh_destroy(cube);
    o3d_offscreen_renderer_destroy(r);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_unit_cube_colour_depth_silhouette),
        cmocka_unit_test(test_sphere_silhouette_area),
        cmocka_unit_test(test_coloured_point_cloud),
        cmocka_unit_test(test_background_lighting_and_options),
        cmocka_unit_test(test_camera_round_trip),
        cmocka_unit_test(test_lineset_voxelgrid_and_png),
        cmocka_unit_test(test_render_option_json),
        cmocka_unit_test(test_glfw_backend_matches_egl),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
