/* SPDX-License-Identifier: MIT */
/* C API color_map.h. Checked on data whose answer is known: the inside of a box room with a smooth colour texture,
 * ray-cast here into 8-bit RGB + float depth images from five cameras looking into one corner, given to the
 * optimizers with each pose perturbed by 1.5 degrees and about 2 cm: the poses move toward the true ones and the
 * vertex colours toward the texture, for the rigid and the non-rigid optimizer; no iterations leave the poses as
 * given; the defaults; progress and cancelling; and the error paths (every one leaves both outputs NULL). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_room.h"
#include "o3d_test_util.h"

#define W 160
#define H 120
#define VIEWS 5
#define GRID 31 /* vertices along each wall */

static const o3d_pinhole_intrinsic_t kCamera = {W, H, 140.0, 140.0, 79.5, 59.5};
#define kLo o3d_test_room_lo
#define kHi o3d_test_room_hi


/* ---- the scene ----------------------------------------------------------------------------------------------- */

typedef struct {
    o3d_trianglemesh_t* mesh;
    o3d_rgbd_image_t* images[VIEWS];
    double truth[VIEWS][16]; /* world to camera */
    o3d_camera_trajectory_t* start; /* perturbed */
} scene_t;

static o3d_rgbd_image_t* render(const double pose[16]) {
    uint8_t* rgb = malloc(3 * W * H);
    float* depth = malloc(sizeof(float) * W * H);
    o3d_test_room_render(pose, &kCamera, rgb, depth);
    o3d_image_t *color = NULL, *dimg = NULL;
    assert_int_equal(o3d_image_create_from_data(&color, W, H, 3, 1, rgb, 3 * W * H), O3D_OK);
    assert_int_equal(o3d_image_create_from_data(&dimg, W, H, 1, 4, (const uint8_t*)depth, sizeof(float) * W * H), O3D_OK);
    o3d_rgbd_options_t o;
    assert_int_equal(o3d_rgbd_options_init(&o, sizeof o), O3D_OK);
    o.depth_scale = 1.0; /* float metres already */
    o.depth_trunc = 10.0;
    o.convert_rgb_to_intensity = 0; /* RGB, as Open3D's colour-map examples */
    o3d_rgbd_image_t* rgbd = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, dimg, &o), O3D_OK);
    o3d_image_destroy(color);
    o3d_image_destroy(dimg);
    free(rgb);
    free(depth);
    return rgbd;
}

static o3d_trianglemesh_t* room_mesh(void) {
    double* xyz = malloc(sizeof(double) * 3 * 6 * GRID * GRID);
    size_t n = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            for (int j = 0; j < GRID; ++j)
                for (int i = 0; i < GRID; ++i, ++n) {
                    xyz[3 * n + axis] = side ? kHi[axis] : kLo[axis];
                    xyz[3 * n + a] = kLo[a] + (kHi[a] - kLo[a]) * i / (GRID - 1);
                    xyz[3 * n + b] = kLo[b] + (kHi[b] - kLo[b]) * j / (GRID - 1);
                }
        }
    o3d_trianglemesh_t* mesh = NULL;
    assert_int_equal(o3d_trianglemesh_create(&mesh), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(mesh, O3D_MESH_VERTICES, xyz, n), O3D_OK);
    free(xyz);
    return mesh;
}

static scene_t* make_scene(void) {
    scene_t* s = calloc(1, sizeof *s);
    s->mesh = room_mesh();
    /* Spread apart, all looking into one corner: three walls at right angles, seen with parallax, leave no motion
     * common to all cameras that photometric consistency cannot see. */
    const double centres[VIEWS][3] = {{0, 0, 0}, {-0.6, -0.4, -0.5}, {0.5, -0.5, 0.3}, {-0.5, 0.5, 0.5}, {0.4, 0.4, -0.6}};
    const double targets[VIEWS][3] = {{1.2, 1.0, 1.6}, {1.0, 1.0, 1.6}, {1.2, 0.8, 1.6}, {1.2, 1.0, 1.4}, {1.1, 0.9, 1.5}};
    const double axes[VIEWS][3] = {{1, 2, 0}, {-1, 0, 2}, {0, 1, 1}, {2, -1, 1}, {1, 1, -1}};
    const double shifts[VIEWS][3] = {{0.02, -0.01, 0.01}, {-0.01, 0.02, 0}, {0, -0.02, -0.015}, {0.015, 0.01, 0.01}, {-0.02, 0, 0.01}};
    assert_int_equal(o3d_camera_trajectory_create(&s->start), O3D_OK);
    for (int c = 0; c < VIEWS; ++c) {
        double pose[16], p[16], start[16];
        o3d_test_look_at(centres[c], targets[c], pose);
        s->images[c] = render(pose);
        o3d_test_rigid_inverse(pose, s->truth[c]);
        o3d_test_motion(axes[c], 1.5, shifts[c], p);
        o3d_test_mat_mul(p, s->truth[c], start);
        assert_int_equal(o3d_camera_trajectory_append(s->start, &kCamera, start), O3D_OK);
    }
    return s;
}

static int setup(void** state) {
    *state = make_scene();
    return 0;
}

static int teardown(void** state) {
    scene_t* s = *state;
    o3d_trianglemesh_destroy(s->mesh);
    for (int c = 0; c < VIEWS; ++c) o3d_rgbd_image_destroy(s->images[c]);
    o3d_camera_trajectory_destroy(s->start);
    free(s);
    return 0;
}

/* Mean pose errors of a trajectory against the truth. */
static void trajectory_error(const o3d_camera_trajectory_t* t, const scene_t* s, double* deg, double* metres) {
    size_t n = 0;
    assert_int_equal(o3d_camera_trajectory_size(&n, t), O3D_OK);
    assert_int_equal(n, VIEWS);
    *deg = *metres = 0;
    for (int c = 0; c < VIEWS; ++c) {
        double e[16], d, m;
        assert_int_equal(o3d_camera_trajectory_get(NULL, e, t, (size_t)c), O3D_OK);
        o3d_test_pose_error(e, s->truth[c], &d, &m);
        *deg += d / VIEWS;
        *metres += m / VIEWS;
    }
}

/* Mean RGB distance of the mesh's vertex colours from the texture, over the vertices facing the corner's walls
 * (the three walls x = hi, y = hi, z = hi, which every camera sees a part of). */
static double color_error(const o3d_trianglemesh_t* mesh) {
    size_t n = 0, nc = 0;
    assert_int_equal(o3d_trianglemesh_get_array(NULL, 0, &n, mesh, O3D_MESH_VERTICES), O3D_OK);
    double* xyz = malloc(sizeof(double) * 3 * n);
    double* rgb = malloc(sizeof(double) * 3 * n);
    assert_int_equal(o3d_trianglemesh_get_array(xyz, n, &n, mesh, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_array(rgb, n, &nc, mesh, O3D_MESH_VERTEX_COLORS), O3D_OK);
    assert_int_equal(nc, n);
    double sum = 0;
    size_t used = 0;
    for (size_t i = 0; i < n; ++i) {
        const double* p = xyz + 3 * i;
        /* near the corner, where the cameras look: within 1 m of it on its three walls */
        if (fabs(p[0] - kHi[0]) + fabs(p[1] - kHi[1]) + fabs(p[2] - kHi[2]) > 1.0 + 1e-9) continue;
        double t[3];
        o3d_test_room_texture(p, t);
        sum += sqrt(pow(rgb[3 * i] - t[0], 2) + pow(rgb[3 * i + 1] - t[1], 2) + pow(rgb[3 * i + 2] - t[2], 2));
        ++used;
    }
    free(xyz);
    free(rgb);
    assert_true(used > 50);
    return sum / (double)used;
}

static void set_scene_options(o3d_color_map_rigid_options_t* o, int iterations) {
    assert_int_equal(o3d_color_map_rigid_options_init(o, sizeof *o), O3D_OK);
    o->maximum_iteration = iterations;
    o->maximum_allowable_depth = 4.0;
    /* 160 x 120 pixels are four times Open3D's 640 x 480 ones: slanted walls change depth by several cm per pixel,
     * which is no discontinuity; the poses start a few cm off, so visibility gets a looser depth test. */
    o->depth_threshold_for_discontinuity_check = 1.0;
    o->depth_threshold_for_visibility_check = 0.2;
    o->image_boundary_margin = 4;
}

static void test_rigid_recovers_the_poses(void** state) {
    const scene_t* s = *state;
    o3d_color_map_rigid_options_t o;
    o3d_trianglemesh_t *mesh0 = NULL, *mesh1 = NULL;
    o3d_camera_trajectory_t *t0 = NULL, *t1 = NULL;
    set_scene_options(&o, 0);
    assert_int_equal(o3d_color_map_run_rigid_optimizer(&mesh0, &t0, s->mesh, (const o3d_rgbd_image_t* const*)s->images,
                                                       VIEWS, s->start, &o), O3D_OK);
    set_scene_options(&o, 150);
    assert_int_equal(o3d_color_map_run_rigid_optimizer(&mesh1, &t1, s->mesh, (const o3d_rgbd_image_t* const*)s->images,
                                                       VIEWS, s->start, &o), O3D_OK);
    double deg0, m0, deg1, m1;
    trajectory_error(t0, s, &deg0, &m0);
    trajectory_error(t1, s, &deg1, &m1);
    const double c0 = color_error(mesh0), c1 = color_error(mesh1);
    print_message("rigid: pose error %.3f deg %.4f m -> %.3f deg %.4f m; colour error %.4f -> %.4f\n", deg0, m0, deg1,
                  m1, c0, c1);
    assert_float_equal(deg0, 1.5, 1e-9); /* no iterations: the poses as given */
    assert_true(deg1 < 0.5 * deg0);
    assert_true(m1 < 0.6 * m0);
    assert_true(c1 < 0.5 * c0);
    /* The output mesh is a copy: the input has no colours. */
    int32_t has = 1;
    assert_int_equal(o3d_trianglemesh_has_array(&has, s->mesh, O3D_MESH_VERTEX_COLORS), O3D_OK);
    assert_int_equal(has, 0);
    o3d_trianglemesh_destroy(mesh0);
    o3d_trianglemesh_destroy(mesh1);
    o3d_camera_trajectory_destroy(t0);
    o3d_camera_trajectory_destroy(t1);
}

static void test_non_rigid_recovers_the_poses(void** state) {
    const scene_t* s = *state;
    o3d_color_map_rigid_options_t r;
    set_scene_options(&r, 150);
    o3d_color_map_non_rigid_options_t o;
    assert_int_equal(o3d_color_map_non_rigid_options_init(&o, sizeof o), O3D_OK);
    o.number_of_vertical_anchors = 6;
    o.maximum_iteration = r.maximum_iteration;
    o.maximum_allowable_depth = r.maximum_allowable_depth;
    o.depth_threshold_for_discontinuity_check = r.depth_threshold_for_discontinuity_check;
    o.depth_threshold_for_visibility_check = r.depth_threshold_for_visibility_check;
    o.image_boundary_margin = r.image_boundary_margin;
    o3d_trianglemesh_t *mesh = NULL, *rigid_mesh = NULL;
    o3d_camera_trajectory_t *t = NULL, *rigid_t = NULL;
    assert_int_equal(o3d_color_map_run_non_rigid_optimizer(&mesh, &t, s->mesh, (const o3d_rgbd_image_t* const*)s->images,
                                                           VIEWS, s->start, &o), O3D_OK);
    assert_int_equal(o3d_color_map_run_rigid_optimizer(&rigid_mesh, &rigid_t, s->mesh,
                                                       (const o3d_rgbd_image_t* const*)s->images, VIEWS, s->start, &r),
                     O3D_OK);
    double deg, m;
    trajectory_error(t, s, &deg, &m);
    const double c = color_error(mesh), c_rigid = color_error(rigid_mesh);
    print_message("non-rigid: pose error %.3f deg %.4f m; colour error %.4f (rigid %.4f)\n", deg, m, c, c_rigid);
    assert_true(deg < 0.75);
    assert_true(m < 0.015);
    assert_true(c < 1.1 * c_rigid);
    o3d_trianglemesh_destroy(mesh);
    o3d_trianglemesh_destroy(rigid_mesh);
    o3d_camera_trajectory_destroy(t);
    o3d_camera_trajectory_destroy(rigid_t);
}

static void test_defaults_are_open3ds(void** state) {
    (void)state;
    o3d_color_map_non_rigid_options_t n;
    assert_int_equal(o3d_color_map_non_rigid_options_init(&n, sizeof n), O3D_OK);
    assert_int_equal(n.struct_size, sizeof n);
    assert_int_equal(n.number_of_vertical_anchors, 16);
    assert_float_equal(n.non_rigid_anchor_point_weight, 0.316, 0);
    assert_int_equal(n.maximum_iteration, 300);
    assert_float_equal(n.maximum_allowable_depth, 2.5, 0);
    assert_float_equal(n.depth_threshold_for_visibility_check, 0.03, 0);
    assert_float_equal(n.depth_threshold_for_discontinuity_check, 0.1, 0);
    assert_int_equal(n.half_dilation_kernel_size_for_discontinuity_map, 3);
    assert_int_equal(n.image_boundary_margin, 10);
    assert_int_equal(n.invisible_vertex_color_knn, 3);
    assert_int_equal(n.num_threads, 0);
    assert_null(n.progress);
    o3d_color_map_rigid_options_t r;
    assert_int_equal(o3d_color_map_rigid_options_init(&r, sizeof r), O3D_OK);
    assert_int_equal(r.maximum_iteration, 300);
    assert_int_equal(r.invisible_vertex_color_knn, 3);
    O3D_ASSERT_FAILS(o3d_color_map_rigid_options_init(NULL, sizeof r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_color_map_rigid_options_init(&r, sizeof r + 8), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_color_map_non_rigid_options_init(&n, 2), O3D_ERROR_INVALID_ARGUMENT);
}

typedef struct {
    int calls;
    double last;
    int stop_after;
} progress_t;

static int32_t on_progress(double fraction, void* user_data) {
    progress_t* p = user_data;
    p->calls++;
    p->last = fraction;
    return p->calls >= p->stop_after;
}

static void test_progress_and_cancel(void** state) {
    const scene_t* s = *state;
    o3d_color_map_rigid_options_t o;
    set_scene_options(&o, 4);
    progress_t p = {0, 0.0, 100};
    o.progress = on_progress;
    o.user_data = &p;
    o3d_trianglemesh_t* mesh = NULL;
    o3d_camera_trajectory_t* t = NULL;
    const o3d_rgbd_image_t* const* images = (const o3d_rgbd_image_t* const*)s->images;
    assert_int_equal(o3d_color_map_run_rigid_optimizer(&mesh, &t, s->mesh, images, VIEWS, s->start, &o), O3D_OK);
    assert_int_equal(p.calls, 4);
    assert_float_equal(p.last, 1.0, 0);
    o3d_trianglemesh_destroy(mesh);
    o3d_camera_trajectory_destroy(t);
    p.calls = 0;
    p.stop_after = 2;
    O3D_ASSERT_FAILS(o3d_color_map_run_rigid_optimizer(&mesh, &t, s->mesh, images, VIEWS, s->start, &o),
                     O3D_ERROR_CANCELLED);
    assert_null(mesh);
    assert_null(t);
    assert_int_equal(p.calls, 2);
}

/* Every failure leaves both outputs NULL, even when they held something before. */
#define ASSERT_RIGID_FAILS(mesh_, images_, n_, traj_, opts_)                                                   \
    do {                                                                                                       \
        o3d_trianglemesh_t* m_ = (o3d_trianglemesh_t*)&sentinel;                                               \
        o3d_camera_trajectory_t* t_ = (o3d_camera_trajectory_t*)&sentinel;                                     \
        O3D_ASSERT_FAILS(o3d_color_map_run_rigid_optimizer(&m_, &t_, mesh_, images_, n_, traj_, opts_),        \
                         O3D_ERROR_INVALID_ARGUMENT);                                                          \
        assert_null(m_);                                                                                       \
        assert_null(t_);                                                                                       \
    } while (0)

static void test_errors(void** state) {
    const scene_t* s = *state;
    int sentinel = 0;
    const o3d_rgbd_image_t* const* images = (const o3d_rgbd_image_t* const*)s->images;
    o3d_color_map_rigid_options_t o;
    set_scene_options(&o, 1);
    o3d_trianglemesh_t* m = NULL;
    o3d_camera_trajectory_t* t = NULL;
    O3D_ASSERT_FAILS(o3d_color_map_run_rigid_optimizer(NULL, &t, s->mesh, images, VIEWS, s->start, &o),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_color_map_run_rigid_optimizer(&m, NULL, s->mesh, images, VIEWS, s->start, &o),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_null(m);
    ASSERT_RIGID_FAILS(NULL, images, VIEWS, s->start, &o);
    ASSERT_RIGID_FAILS(s->mesh, NULL, VIEWS, s->start, &o);
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS, NULL, &o);
    /* counts that do not pair up, and none at all */
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS - 1, s->start, &o);
    o3d_camera_trajectory_t* empty_trajectory = NULL;
    assert_int_equal(o3d_camera_trajectory_create(&empty_trajectory), O3D_OK);
    ASSERT_RIGID_FAILS(s->mesh, images, 0, empty_trajectory, &o);
    o3d_camera_trajectory_destroy(empty_trajectory);
    /* a NULL image */
    const o3d_rgbd_image_t* with_null[VIEWS];
    memcpy(with_null, images, sizeof with_null);
    with_null[2] = NULL;
    ASSERT_RIGID_FAILS(s->mesh, with_null, VIEWS, s->start, &o);
    /* an empty mesh, a mesh with a NaN vertex */
    o3d_trianglemesh_t* bad_mesh = NULL;
    assert_int_equal(o3d_trianglemesh_create(&bad_mesh), O3D_OK);
    ASSERT_RIGID_FAILS(bad_mesh, images, VIEWS, s->start, &o);
    const double nan_vertex[3] = {0.0, NAN, 1.0};
    assert_int_equal(o3d_trianglemesh_set_array(bad_mesh, O3D_MESH_VERTICES, nan_vertex, 1), O3D_OK);
    ASSERT_RIGID_FAILS(bad_mesh, images, VIEWS, s->start, &o);
    o3d_trianglemesh_destroy(bad_mesh);
    /* An image of another size than its intrinsic. (A colour or depth of another format cannot reach the optimizer
     * through the C API: o3d_rgbd_image_create_from_color_and_depth already checks and converts them.) */
    uint8_t* bytes = calloc(W * H, 3);
    o3d_rgbd_options_t ro;
    assert_int_equal(o3d_rgbd_options_init(&ro, sizeof ro), O3D_OK);
    ro.convert_rgb_to_intensity = 0;
    o3d_image_t *small_rgb = NULL, *small_depth = NULL;
    assert_int_equal(o3d_image_create_from_data(&small_rgb, W / 2, H / 2, 3, 1, bytes, 3 * (W / 2) * (H / 2)), O3D_OK);
    assert_int_equal(o3d_image_create_from_data(&small_depth, W / 2, H / 2, 1, 2, bytes, 2 * (W / 2) * (H / 2)), O3D_OK);
    o3d_rgbd_image_t* small = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&small, small_rgb, small_depth, &ro), O3D_OK);
    memcpy(with_null, images, sizeof with_null);
    with_null[1] = small;
    ASSERT_RIGID_FAILS(s->mesh, with_null, VIEWS, s->start, &o);
    o3d_rgbd_image_destroy(small);
    o3d_image_destroy(small_rgb);
    o3d_image_destroy(small_depth);
    free(bytes);
    /* bad options */
    o3d_color_map_rigid_options_t b = o;
    b.maximum_allowable_depth = NAN;
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS, s->start, &b);
    b = o;
    b.maximum_iteration = -1;
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS, s->start, &b);
    b = o;
    b.depth_threshold_for_visibility_check = NAN;
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS, s->start, &b);
    b = o;
    b.invisible_vertex_color_knn = 0;
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS, s->start, &b);
    b = o;
    b.num_threads = -2;
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS, s->start, &b);
    b = o;
    b.struct_size = 1;
    ASSERT_RIGID_FAILS(s->mesh, images, VIEWS, s->start, &b);
    /* the non-rigid checks */
    o3d_color_map_non_rigid_options_t n;
    assert_int_equal(o3d_color_map_non_rigid_options_init(&n, sizeof n), O3D_OK);
    n.maximum_iteration = 1;
    n.number_of_vertical_anchors = 1;
    m = (o3d_trianglemesh_t*)&sentinel;
    t = (o3d_camera_trajectory_t*)&sentinel;
    O3D_ASSERT_FAILS(o3d_color_map_run_non_rigid_optimizer(&m, &t, s->mesh, images, VIEWS, s->start, &n),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_null(m);
    assert_null(t);
    n.number_of_vertical_anchors = 4;
    n.non_rigid_anchor_point_weight = NAN;
    O3D_ASSERT_FAILS(o3d_color_map_run_non_rigid_optimizer(&m, &t, s->mesh, images, VIEWS, s->start, &n),
                     O3D_ERROR_INVALID_ARGUMENT);
    n.non_rigid_anchor_point_weight = -1;
    O3D_ASSERT_FAILS(o3d_color_map_run_non_rigid_optimizer(&m, &t, s->mesh, images, VIEWS, s->start, &n),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_null(m);
    assert_null(t);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rigid_recovers_the_poses),
        cmocka_unit_test(test_non_rigid_recovers_the_poses),
        cmocka_unit_test(test_defaults_are_open3ds),
        cmocka_unit_test(test_progress_and_cancel),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
