/* SPDX-License-Identifier: MIT */
/* C API visualizer.h: the viewer driven from code, with nobody at the keyboard. A hidden window renders
 * through EGL (no display needed); the visible-window test runs when $DISPLAY is set (ctest runs this file
 * once more under Xvfb). Checked: the default view against Open3D's ViewControl model (depth at the
 * centre), pinhole round trips reproducing the image, key bindings and key callbacks by their effect on the
 * render option and the captured image, animation callbacks, mouse drags against the rotation formula,
 * point picking, view-status JSON, trajectory playback with captures, and the error paths. */
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

static o3d_visualizer_t* new_window(int editing) {
    o3d_visualizer_t* v = NULL;
    assert_int_equal(o3d_visualizer_create(&v, editing), O3D_OK);
    assert_int_equal(o3d_visualizer_create_window(v, "test", W, H, -1, -1, 0), O3D_OK);
    return v;
}

/* A unit cube centred at the origin, painted `rgb`, added with the view reset to it; lights off so that
 * its pixels have exactly its colour. */
static void add_unit_cube(o3d_visualizer_t* v, const double rgb[3]) {
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create_box(&m, 1, 1, 1), O3D_OK);
    const double t[16] = {1, 0, 0, -0.5, 0, 1, 0, -0.5, 0, 0, 1, -0.5, 0, 0, 0, 1};
    assert_int_equal(o3d_trianglemesh_transform(m, t), O3D_OK);
    assert_int_equal(o3d_trianglemesh_paint_uniform_color(m, rgb), O3D_OK);
    assert_int_equal(o3d_visualizer_add_trianglemesh(v, "cube", m, 1), O3D_OK);
    o3d_trianglemesh_destroy(m);
    o3d_render_option_t o;
    assert_int_equal(o3d_render_option_init(&o, sizeof o), O3D_OK);
    assert_int_equal(o3d_visualizer_get_render_option(&o, v), O3D_OK);
    o.light_on = 0;
    assert_int_equal(o3d_visualizer_set_render_option(v, &o), O3D_OK);
}

static const uint8_t* pixels(const o3d_image_t* image) {
    const uint8_t* data = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_image_array_view(&data, &rows, image, O3D_IMAGE_DATA), O3D_OK);
    return data;
}

/* RGB floats of the screen at (u, v). */
static void screen_at(o3d_visualizer_t* v, int u, int vv, float out[3]) {
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_visualizer_capture_screen_float_buffer(&image, v, 1), O3D_OK);
    memcpy(out, pixels(image) + ((size_t)vv * W + (size_t)u) * 12, 12);
    o3d_image_destroy(image);
}

static int count_background(o3d_visualizer_t* v) {
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_visualizer_capture_screen_float_buffer(&image, v, 1), O3D_OK);
    const float* p = (const float*)pixels(image);
    int n = 0;
    for (int i = 0; i < W * H; ++i) n += p[3 * i] == 1.0f && p[3 * i + 1] == 1.0f && p[3 * i + 2] == 1.0f;
    o3d_image_destroy(image);
    return n;
}

static void test_default_view_matches_the_viewcontrol_model(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(0);
    const double red[3] = {1, 0, 0};
    add_unit_cube(v, red);
    float c[3];
    screen_at(v, 0, 0, c);
    assert_true(c[0] == 1.0f && c[1] == 1.0f && c[2] == 1.0f); /* white background */
    screen_at(v, W / 2, H / 2, c);
    assert_true(c[0] == 1.0f && c[1] == 0.0f && c[2] == 0.0f); /* the cube's colour */
    /* Open3D's default view: eye on +z at zoom * extent / tan(30 deg) from the box centre; the front face
     * (z = 0.5) is that minus 0.5 away. */
    o3d_image_t* depth = NULL;
    assert_int_equal(o3d_visualizer_capture_depth_float_buffer(&depth, v, 1), O3D_OK);
    float d;
    memcpy(&d, pixels(depth) + ((size_t)(H / 2) * W + W / 2) * 4, 4);
    const double expected = 0.7 / tan(M_PI / 6) - 0.5;
    assert_true(fabs(d - expected) < 1e-3 * expected);
    o3d_image_destroy(depth);
    double fov = 0;
    assert_int_equal(o3d_visualizer_view_get_field_of_view(&fov, v), O3D_OK);
    assert_true(fabs(fov - 60) < 1e-12);
    /* capture_depth_image: millimetres in a 16-bit PNG. */
    char path[] = "/tmp/o3d_vis_depth_XXXXXX.png";
    close(mkstemps(path, 4));
    assert_int_equal(o3d_visualizer_capture_depth_image(v, path, 1, 1000.0), O3D_OK);
    o3d_image_t* png = NULL;
    assert_int_equal(o3d_io_read_image(&png, path, NULL), O3D_OK);
    uint16_t mm;
    memcpy(&mm, pixels(png) + ((size_t)(H / 2) * W + W / 2) * 2, 2);
    assert_int_equal(mm, (int)lround(expected * 1000));
    o3d_image_destroy(png);
    unlink(path);
    o3d_visualizer_destroy(v);
}

static void test_pinhole_round_trip_reproduces_the_image(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(0);
    const double green[3] = {0, 1, 0};
    add_unit_cube(v, green);
    assert_int_equal(o3d_visualizer_view_rotate(v, 120, -40), O3D_OK);
    assert_int_equal(o3d_visualizer_view_change_field_of_view(v, -2), O3D_OK); /* 50 degrees */
    o3d_pinhole_intrinsic_t k;
    double e[16];
    assert_int_equal(o3d_visualizer_view_to_pinhole(&k, e, v), O3D_OK);
    assert_true(fabs(k.fy - H / (2 * tan(25 * M_PI / 180))) < 1e-9);
    const int before = count_background(v);
    assert_int_equal(o3d_visualizer_view_reset(v), O3D_OK);
    assert_true(count_background(v) != before); /* another view, another picture */
    assert_int_equal(o3d_visualizer_view_from_pinhole(v, &k, e), O3D_OK);
    assert_int_equal(count_background(v), before);
    o3d_pinhole_intrinsic_t k2;
    double e2[16];
    assert_int_equal(o3d_visualizer_view_to_pinhole(&k2, e2, v), O3D_OK);
    assert_true(o3d_test_max_abs_diff16(e, e2) < 1e-9);
    assert_true(fabs(k2.fy - k.fy) < 1e-9);
    /* A camera the view cannot take leaves it unchanged. */
    o3d_pinhole_intrinsic_t off = k;
    off.cx += 3;
    O3D_ASSERT_FAILS(o3d_visualizer_view_from_pinhole(v, &off, e), O3D_ERROR_INVALID_ARGUMENT);
    off = k;
    off.width = W * 2;
    O3D_ASSERT_FAILS(o3d_visualizer_view_from_pinhole(v, &off, e), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(count_background(v), before);
    o3d_visualizer_destroy(v);
}

static int32_t paint_black(o3d_visualizer_t* v, int32_t action, int32_t mods, void* user_data) {
    (void)action;
    (void)mods;
    ++*(int*)user_data;
    o3d_render_option_t o;
    o3d_render_option_init(&o, sizeof o);
    o3d_visualizer_get_render_option(&o, v);
    o.background_color[0] = o.background_color[1] = o.background_color[2] = 0;
    o3d_visualizer_set_render_option(v, &o);
    return 1;
}

static double point_size(o3d_visualizer_t* v) {
    o3d_render_option_t o;
    assert_int_equal(o3d_render_option_init(&o, sizeof o), O3D_OK);
    assert_int_equal(o3d_visualizer_get_render_option(&o, v), O3D_OK);
    return o.point_size;
}

static void test_keys_and_key_callbacks(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(0);
    const double red[3] = {1, 0, 0};
    add_unit_cube(v, red);
    /* o3d's own bindings. */
    assert_int_equal(o3d_visualizer_send_key(v, '=', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_true(point_size(v) == 6);
    assert_int_equal(o3d_visualizer_send_key(v, '-', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_send_key(v, '-', O3D_KEY_ACTION_REPEAT, 0), O3D_OK);
    assert_true(point_size(v) == 4);
    const int default_view = count_background(v);
    assert_int_equal(o3d_visualizer_send_key(v, '[', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    double fov = 0;
    assert_int_equal(o3d_visualizer_view_get_field_of_view(&fov, v), O3D_OK);
    assert_true(fabs(fov - 55) < 1e-12);
    assert_true(count_background(v) != default_view); /* same apparent size, another perspective */
    assert_int_equal(o3d_visualizer_view_rotate(v, 200, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_send_key(v, 'R', O3D_KEY_ACTION_PRESS, 0), O3D_OK); /* reset: fov 60 again */
    double front[3];
    assert_int_equal(o3d_visualizer_view_get(front, NULL, NULL, NULL, v), O3D_OK);
    assert_true(fabs(front[0]) < 1e-12 && fabs(front[2] - 1) < 1e-12);
    assert_int_equal(count_background(v), default_view);
    /* A key callback replaces the binding, on press and repeat but not release. */
    int calls = 0;
    assert_int_equal(o3d_visualizer_register_key_callback(v, 'K', paint_black, &calls), O3D_OK);
    assert_int_equal(o3d_visualizer_send_key(v, 'K', O3D_KEY_ACTION_RELEASE, 0), O3D_OK);
    assert_int_equal(calls, 0);
    assert_int_equal(o3d_visualizer_send_key(v, 'K', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(calls, 1);
    float c[3];
    screen_at(v, 0, 0, c);
    assert_true(c[0] == 0.0f && c[1] == 0.0f && c[2] == 0.0f);
    int action_calls = 0;
    assert_int_equal(o3d_visualizer_register_key_action_callback(v, '=', paint_black, &action_calls), O3D_OK);
    assert_int_equal(o3d_visualizer_send_key(v, '=', O3D_KEY_ACTION_RELEASE, 0), O3D_OK);
    assert_int_equal(action_calls, 1);
    assert_true(point_size(v) == 4); /* the binding no longer runs */
    /* W toggles the wireframe, N the normals. */
    assert_int_equal(o3d_visualizer_send_key(v, 'W', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    o3d_render_option_t o;
    o3d_render_option_init(&o, sizeof o);
    assert_int_equal(o3d_visualizer_get_render_option(&o, v), O3D_OK);
    assert_int_equal(o.mesh_show_wireframe, 1);
    O3D_ASSERT_FAILS(o3d_visualizer_send_key(v, 'W', 7, 0), O3D_ERROR_INVALID_ARGUMENT);
    /* Q closes: poll_events reports it. */
    int32_t open = -1;
    assert_int_equal(o3d_visualizer_poll_events(&open, v), O3D_OK);
    assert_int_equal(open, 1);
    assert_int_equal(o3d_visualizer_send_key(v, 'Q', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_poll_events(&open, v), O3D_OK);
    assert_int_equal(open, 0);
    o3d_visualizer_destroy(v);
}

typedef struct {
    int frames;
    int stop_after;
    int fail;
} Animation;

static int32_t spin(o3d_visualizer_t* v, void* user_data) {
    Animation* a = user_data;
    o3d_visualizer_view_rotate(v, 10, 0);
    if (++a->frames == a->stop_after) {
        if (a->fail) o3d_visualizer_set_callback_error(v, "spin failed on purpose");
        o3d_visualizer_close(v);
    }
    return 1;
}

static int32_t destroy_inside(o3d_visualizer_t* v, void* user_data) {
    *(o3d_status*)user_data = o3d_visualizer_destroy_window(v);
    o3d_visualizer_close(v);
    return 0;
}

static void test_animation_callback_rotates_the_view(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(0);
    const double blue[3] = {0, 0, 1};
    add_unit_cube(v, blue);
    const int still = count_background(v);
    Animation a = {0, 5, 0};
    assert_int_equal(o3d_visualizer_register_animation_callback(v, spin, &a), O3D_OK);
    assert_int_equal(o3d_visualizer_run(v), O3D_OK);
    assert_int_equal(a.frames, 5);
    /* Five turns of 10 px about the up axis: 0.15 rad in all. */
    double front[3];
    assert_int_equal(o3d_visualizer_view_get(front, NULL, NULL, NULL, v), O3D_OK);
    assert_true(fabs(front[0] + sin(0.15)) < 1e-9 && fabs(front[1]) < 1e-9 && fabs(front[2] - cos(0.15)) < 1e-9);
    assert_true(count_background(v) != still); /* the turned cube draws another picture */
    /* A callback that reports an error ends run with it. */
    assert_int_equal(o3d_visualizer_destroy_window(v), O3D_OK);
    assert_int_equal(o3d_visualizer_create_window(v, NULL, W, H, -1, -1, 0), O3D_OK);
    Animation failing = {0, 2, 1};
    assert_int_equal(o3d_visualizer_register_animation_callback(v, spin, &failing), O3D_OK);
    O3D_ASSERT_FAILS(o3d_visualizer_run(v), O3D_ERROR_CANCELLED);
    assert_non_null(strstr(o3d_last_error_message(), "spin failed on purpose"));
    /* destroy_window from inside a callback is refused, not a crash. */
    o3d_status inside = O3D_OK;
    assert_int_equal(o3d_visualizer_destroy_window(v), O3D_OK);
    assert_int_equal(o3d_visualizer_create_window(v, NULL, W, H, -1, -1, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_register_animation_callback(v, destroy_inside, &inside), O3D_OK);
    assert_int_equal(o3d_visualizer_run(v), O3D_OK);
    assert_int_equal(inside, O3D_ERROR_INVALID_ARGUMENT);
    o3d_visualizer_destroy(v);
}

static void test_mouse_drag_and_wheel(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(0);
    const double red[3] = {1, 0, 0};
    add_unit_cube(v, red);
    assert_int_equal(o3d_visualizer_send_mouse_move(v, 10, 10), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_move(v, 110, 10), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_RELEASE, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_move(v, 300, 10), O3D_OK); /* no button: no rotation */
    double front[3], lookat[3], zoom = 0;
    assert_int_equal(o3d_visualizer_view_get(front, lookat, NULL, &zoom, v), O3D_OK);
    assert_true(fabs(front[0] + sin(0.3)) < 1e-9 && fabs(front[2] - cos(0.3)) < 1e-9);
    /* Ctrl + drag translates: a window height of drag is 2 * zoom * extent. */
    assert_int_equal(o3d_visualizer_view_reset(v), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_PRESS,
                                                      O3D_KEY_MOD_CONTROL), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_move(v, 300, 10 + H), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_RELEASE, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_view_get(NULL, lookat, NULL, NULL, v), O3D_OK);
    assert_true(fabs(lookat[0]) < 1e-9 && fabs(lookat[1] - 2 * 0.7) < 1e-9 && fabs(lookat[2]) < 1e-9);
    assert_int_equal(o3d_visualizer_send_scroll(v, 0, 5), O3D_OK);
    assert_int_equal(o3d_visualizer_view_get(NULL, NULL, NULL, &zoom, v), O3D_OK);
    assert_true(fabs(zoom - 0.8) < 1e-12);
    O3D_ASSERT_FAILS(o3d_visualizer_send_mouse_move(v, NAN, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_send_mouse_button(v, 9, O3D_KEY_ACTION_PRESS, 0), O3D_ERROR_INVALID_ARGUMENT);
    o3d_visualizer_destroy(v);
}

static void test_editing_picks_the_clicked_point(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(1);
    const double pts[9] = {-0.5, 0, 0, 0, 0.3, 0, 0.5, -0.2, 0.1};
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, pts, 3), O3D_OK);
    assert_int_equal(o3d_visualizer_add_pointcloud(v, "cloud", pc, 1), O3D_OK);
    o3d_pinhole_intrinsic_t k;
    double e[16];
    assert_int_equal(o3d_visualizer_view_to_pinhole(&k, e, v), O3D_OK);
    for (int pick = 2; pick >= 1; --pick) {
        const double* p = pts + 3 * pick;
        const double x = e[0] * p[0] + e[1] * p[1] + e[2] * p[2] + e[3];
        const double y = e[4] * p[0] + e[5] * p[1] + e[6] * p[2] + e[7];
        const double z = e[8] * p[0] + e[9] * p[1] + e[10] * p[2] + e[11];
        assert_int_equal(o3d_visualizer_send_mouse_move(v, k.fx * x / z + k.cx + 1, k.fy * y / z + k.cy), O3D_OK);
        assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_PRESS,
                                                          O3D_KEY_MOD_SHIFT), O3D_OK);
        assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_RELEASE,
                                                          O3D_KEY_MOD_SHIFT), O3D_OK);
    }
    int32_t picked[4];
    size_t n = 0;
    assert_int_equal(o3d_visualizer_get_picked_points(picked, 4, &n, v), O3D_OK);
    assert_int_equal(n, 2);
    assert_int_equal(picked[0], 2);
    assert_int_equal(picked[1], 1);
    O3D_ASSERT_FAILS(o3d_visualizer_get_picked_points(picked, 1, &n, v), O3D_ERROR_BUFFER_TOO_SMALL);
    /* A click on empty background picks nothing; Shift + right click drops the last pick. */
    assert_int_equal(o3d_visualizer_send_mouse_move(v, 1, 1), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_RELEASE,
                                                      O3D_KEY_MOD_SHIFT), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(v, O3D_MOUSE_BUTTON_RIGHT, O3D_KEY_ACTION_RELEASE,
                                                      O3D_KEY_MOD_SHIFT), O3D_OK);
    assert_int_equal(o3d_visualizer_get_picked_points(picked, 4, &n, v), O3D_OK);
    assert_int_equal(n, 1);
    assert_int_equal(picked[0], 2);
    o3d_pointcloud_destroy(pc);
    o3d_visualizer_destroy(v);
}

static int progress_calls;
static double last_fraction;
static int32_t count_progress(double fraction, void* user_data) {
    (void)user_data;
    ++progress_calls;
    last_fraction = fraction;
    return 0;
}

static void test_view_status_and_trajectory_playback(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(0);
    const double red[3] = {1, 0, 0};
    add_unit_cube(v, red);
    assert_int_equal(o3d_visualizer_view_rotate(v, 50, 20), O3D_OK);
    o3d_buffer_t* json = NULL;
    assert_int_equal(o3d_visualizer_get_view_status(&json, v), O3D_OK);
    const uint8_t* text = NULL;
    size_t size = 0;
    assert_int_equal(o3d_buffer_view(&text, &size, json), O3D_OK);
    char* status = calloc(size + 1, 1);
    memcpy(status, text, size);
    o3d_buffer_destroy(json);
    assert_non_null(strstr(status, "\"class_name\": \"ViewTrajectory\""));
    double front[3], again[3];
    assert_int_equal(o3d_visualizer_view_get(front, NULL, NULL, NULL, v), O3D_OK);
    assert_int_equal(o3d_visualizer_view_reset(v), O3D_OK);
    assert_int_equal(o3d_visualizer_set_view_status(v, status), O3D_OK);
    assert_int_equal(o3d_visualizer_view_get(again, NULL, NULL, NULL, v), O3D_OK);
    for (int i = 0; i < 3; ++i) assert_true(fabs(front[i] - again[i]) < 1e-9);
    O3D_ASSERT_FAILS(o3d_visualizer_set_view_status(v, "{\"class_name\": \"ViewTrajectory\""), O3D_ERROR_PARSE);
    O3D_ASSERT_FAILS(o3d_visualizer_set_view_status(v, "{\"class_name\": \"RenderOption\"}"), O3D_ERROR_PARSE);
    free(status);
    /* Two key views, two frames between: four frames, each captured. */
    char dir[] = "/tmp/o3d_vis_traj_XXXXXX";
    assert_non_null(mkdtemp(dir));
    char path[256];
    snprintf(path, sizeof path, "%s/trajectory.json", dir);
    FILE* f = fopen(path, "w");
    fputs("{\"class_name\": \"ViewTrajectory\", \"interval\": 2, \"is_loop\": false, \"trajectory\": ["
          "{\"boundingbox_max\": [0.5, 0.5, 0.5], \"boundingbox_min\": [-0.5, -0.5, -0.5], \"field_of_view\": 60.0,"
          " \"front\": [0, 0, 1], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"zoom\": 0.7},"
          "{\"boundingbox_max\": [0.5, 0.5, 0.5], \"boundingbox_min\": [-0.5, -0.5, -0.5], \"field_of_view\": 60.0,"
          " \"front\": [1, 0, 0], \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"zoom\": 0.7}]}", f);
    fclose(f);
    progress_calls = 0;
    assert_int_equal(o3d_visualizer_play_view_trajectory(v, path, dir, 1, count_progress, NULL), O3D_OK);
    assert_int_equal(progress_calls, 4);
    assert_true(last_fraction == 1.0);
    assert_int_equal(o3d_visualizer_view_get(front, NULL, NULL, NULL, v), O3D_OK);
    assert_true(fabs(front[0] - 1) < 1e-12); /* ends on the last key view */
    for (int k = 0; k < 4; ++k) {
        char frame[300];
        snprintf(frame, sizeof frame, "%s/image_%06d.png", dir, k);
        assert_int_equal(access(frame, R_OK), 0);
        unlink(frame);
        snprintf(frame, sizeof frame, "%s/depth_%06d.png", dir, k);
        assert_int_equal(access(frame, R_OK), 0);
        unlink(frame);
    }
    unlink(path);
    rmdir(dir);
    O3D_ASSERT_FAILS(o3d_visualizer_play_view_trajectory(v, "/nonexistent/t.json", NULL, 0, NULL, NULL), O3D_ERROR_IO);
    o3d_visualizer_destroy(v);
}

static void test_image_shown_flat(void** state) {
    (void)state;
    o3d_visualizer_t* v = new_window(0);
    /* 2 x 1 pixels, red then blue: scaled by min(160 / 2, 120 / 1) = 80 to 160 x 80, rows 20..99. */
    const uint8_t rgb[6] = {255, 0, 0, 0, 0, 255};
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_image_create_from_data(&image, 2, 1, 3, 1, rgb, sizeof rgb), O3D_OK);
    assert_int_equal(o3d_visualizer_add_image(v, "picture", image, 1), O3D_OK);
    float c[3];
    screen_at(v, 40, 60, c);
    assert_true(c[0] == 1.0f && c[1] == 0.0f && c[2] == 0.0f);
    screen_at(v, 120, 60, c);
    assert_true(c[0] == 0.0f && c[1] == 0.0f && c[2] == 1.0f);
    screen_at(v, 80, 10, c);
    assert_true(c[0] == 1.0f && c[1] == 1.0f && c[2] == 1.0f); /* above the picture: background */
    screen_at(v, 80, 21, c);
    assert_true(c[2] == 1.0f && c[1] == 0.0f);
    /* A cube drawn with it lies over it. */
    const double green[3] = {0, 1, 0};
    add_unit_cube(v, green);
    screen_at(v, W / 2, H / 2, c);
    assert_true(c[0] == 0.0f && c[1] == 1.0f && c[2] == 0.0f);
    /* A failed update (3 channels of uint16: no display format) keeps the picture. */
    o3d_image_t* two = NULL;
    assert_int_equal(o3d_image_create(&two, 4, 4, 3, 2), O3D_OK);
    O3D_ASSERT_FAILS(o3d_visualizer_add_image(v, "picture", two, 0), O3D_ERROR_INVALID_ARGUMENT);
    screen_at(v, 5, 60, c);
    assert_true(c[0] == 1.0f && c[1] == 0.0f && c[2] == 0.0f);
    o3d_image_destroy(two);
    o3d_image_destroy(image);
    o3d_visualizer_destroy(v);
}

static void test_errors_never_crash(void** state) {
    (void)state;
    o3d_visualizer_t* v = NULL;
    O3D_ASSERT_FAILS(o3d_visualizer_create(NULL, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_run(NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_view_rotate(NULL, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    o3d_visualizer_destroy(NULL);
    assert_int_equal(o3d_visualizer_create(&v, 0), O3D_OK);
    /* Without a window. */
    O3D_ASSERT_FAILS(o3d_visualizer_run(v), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_view_rotate(v, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_t* image = NULL;
    O3D_ASSERT_FAILS(o3d_visualizer_capture_screen_float_buffer(&image, v, 1), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(image);
    O3D_ASSERT_FAILS(o3d_visualizer_create_window(v, "x", 0, 10, -1, -1, 0), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_visualizer_create_window(v, "x", W, H, -1, -1, 0), O3D_OK);
    O3D_ASSERT_FAILS(o3d_visualizer_create_window(v, "x", W, H, -1, -1, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_add_pointcloud(v, "p", NULL, 1), O3D_ERROR_INVALID_ARGUMENT);
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    O3D_ASSERT_FAILS(o3d_visualizer_add_pointcloud(v, "", pc, 1), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_visualizer_add_pointcloud(v, "empty", pc, 1), O3D_OK); /* an empty cloud draws nothing */
    O3D_ASSERT_FAILS(o3d_visualizer_remove_geometry(v, "absent", 1), O3D_ERROR_INVALID_ARGUMENT);
    const double nan3[3] = {NAN, 0, 0}, zero3[3] = {0, 0, 0}, y[3] = {0, 1, 0};
    O3D_ASSERT_FAILS(o3d_visualizer_view_set(v, nan3, NULL, NULL, -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_view_set(v, zero3, NULL, NULL, -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_view_set(v, y, NULL, NULL, -1), O3D_ERROR_INVALID_ARGUMENT); /* front = up */
    O3D_ASSERT_FAILS(o3d_visualizer_view_rotate(v, INFINITY, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_capture_depth_image(v, "/tmp/x.png", 1, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_register_key_callback(v, -1, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_visualizer_capture_screen_image(v, "/nonexistent/dir/x.png", 1), O3D_ERROR_IO);
    /* The hidden window without an animation callback: run draws once and returns. */
    assert_int_equal(o3d_visualizer_run(v), O3D_OK);
    o3d_pointcloud_destroy(pc);
    o3d_visualizer_destroy(v);
}

static void test_visible_window(void** state) {
    (void)state;
    o3d_visualizer_t* v = NULL;
    assert_int_equal(o3d_visualizer_create(&v, 0), O3D_OK);
    const char* display = getenv("DISPLAY");
    if (!display || !*display) {
        O3D_ASSERT_FAILS(o3d_visualizer_create_window(v, "o3d", W, H, 10, 10, 1), O3D_ERROR_UNSUPPORTED);
        o3d_visualizer_destroy(v);
        return;
    }
    assert_int_equal(o3d_visualizer_create_window(v, "o3d", W, H, 10, 10, 1), O3D_OK);
    const double red[3] = {1, 0, 0};
    add_unit_cube(v, red);
    Animation a = {0, 3, 0};
    assert_int_equal(o3d_visualizer_register_animation_callback(v, spin, &a), O3D_OK);
    assert_int_equal(o3d_visualizer_run(v), O3D_OK);
    assert_int_equal(a.frames, 3);
    float c[3];
    screen_at(v, W / 2, H / 2, c);
    assert_true(c[0] == 1.0f && c[1] == 0.0f && c[2] == 0.0f);
    screen_at(v, 0, 0, c);
    assert_true(c[0] == 1.0f && c[1] == 1.0f && c[2] == 1.0f);
    assert_int_equal(o3d_visualizer_destroy_window(v), O3D_OK);
    o3d_visualizer_destroy(v);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_default_view_matches_the_viewcontrol_model),
        cmocka_unit_test(test_pinhole_round_trip_reproduces_the_image),
        cmocka_unit_test(test_keys_and_key_callbacks),
        cmocka_unit_test(test_animation_callback_rotates_the_view),
        cmocka_unit_test(test_mouse_drag_and_wheel),
        cmocka_unit_test(test_editing_picks_the_clicked_point),
        cmocka_unit_test(test_view_status_and_trajectory_playback),
        cmocka_unit_test(test_image_shown_flat),
        cmocka_unit_test(test_errors_never_crash),
        cmocka_unit_test(test_visible_window),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
