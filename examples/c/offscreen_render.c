/* SPDX-License-Identifier: MIT */
/* Offscreen rendering through the C API, with no display: a sphere and a box, lit with Open3D's default
 * lights, smooth shading where a mesh has vertex normals, seen through Open3D's lookat/front/up/zoom view
 * aimed at the sphere's centre; writes a PNG and prints the backend, the centre pixel and the depth there.
 * Usage: offscreen_render <output.png> */
#include <stdio.h>
#include <string.h>

#include "o3d/o3d.h"

#define WIDTH 640
#define HEIGHT 480

/* Run `call`; on failure print it with the library's message and leave through `done`. */
#define TRY(call)                                                                                       \
    do {                                                                                                \
        if ((s = (call)) != O3D_OK) {                                                                   \
            fprintf(stderr, "offscreen_render: %s failed: %s: %s\n", #call, o3d_status_string(s),       \
                    o3d_last_error_message());                                                          \
            goto done;                                                                                  \
        }                                                                                               \
    } while (0)

/* Move `mesh` by `t` and paint it `rgb`. */
static o3d_status place(o3d_trianglemesh_t* mesh, const double t[3], const double rgb[3]) {
    o3d_status s = o3d_trianglemesh_translate(mesh, t, 1);
    return s != O3D_OK ? s : o3d_trianglemesh_paint_uniform_color(mesh, rgb);
}

int main(int argc, char** argv) {
    static const double blue[3] = {0.1, 0.4, 0.9}, orange[3] = {1.0, 0.6, 0.1};
    static const double at_origin[3] = {0, 0, 0}, box_corner[3] = {1.0, -0.4, -0.4};
    static const double front[3] = {0, 0, 1}, up[3] = {0, 1, 0};
    o3d_offscreen_renderer_t* renderer = NULL;
    o3d_trianglemesh_t *sphere = NULL, *box = NULL;
    o3d_image_t *color = NULL, *depth = NULL;
    o3d_render_option_t option;
    const uint8_t* rgb = NULL;
    const uint8_t* z = NULL;
    size_t rows = 0;
    int32_t backend = 0;
    float centre_depth = 0;
    o3d_status s = O3D_OK;
    int rc = 1;

    if (argc != 2) {
        fprintf(stderr, "usage: %s <output.png>\n", argv[0]);
        return 2;
    }

    /* EGL without a display where it works, else a hidden GLFW window (O3D_ERROR_UNSUPPORTED if neither). */
    TRY(o3d_offscreen_renderer_create(&renderer, WIDTH, HEIGHT, O3D_RENDER_BACKEND_AUTO));
    TRY(o3d_offscreen_renderer_get_backend(&backend, renderer));
    printf("backend: %s\n", backend == O3D_RENDER_BACKEND_EGL ? "EGL" : "GLFW");

    /* A sphere of radius 0.6 at the origin, with vertex normals so that it shades smoothly, and a 0.8 box
     * beside it on +x, without normals so that its faces stay flat. */
    TRY(o3d_trianglemesh_create_sphere(&sphere, 0.6, 40));
    TRY(place(sphere, at_origin, blue));
    TRY(o3d_trianglemesh_compute_vertex_normals(sphere, 1));
    TRY(o3d_trianglemesh_create_box(&box, 0.8, 0.8, 0.8));
    TRY(place(box, box_corner, orange));
    TRY(o3d_offscreen_renderer_add_trianglemesh(renderer, "sphere", sphere, NULL)); /* NULL: lit material */
    TRY(o3d_offscreen_renderer_add_trianglemesh(renderer, "box", box, NULL));

    /* Open3D's RenderOption, with smooth shading and a light gray background. */
    TRY(o3d_render_option_init(&option, sizeof option));
    option.mesh_shade_option = O3D_MESH_SHADE_SMOOTH;
    option.background_color[0] = option.background_color[1] = option.background_color[2] = 0.9;
    TRY(o3d_offscreen_renderer_set_render_option(renderer, &option));

    /* Look at the sphere's centre from +z; the distance follows from the scene's box (zoom 0.7). */
    TRY(o3d_offscreen_renderer_setup_camera_lookat(renderer, at_origin, front, up, 0.7));

    TRY(o3d_offscreen_renderer_render_to_png(renderer, argv[1]));
    printf("wrote %dx%d image to %s\n", WIDTH, HEIGHT, argv[1]);

    /* The pixel and the depth (metres along the axis) at the image centre: the front of the sphere, at
     * Open3D's distance zoom * max extent / tan(30 deg) = 0.7 * 2.4 / tan(30 deg) from the origin, less 0.6. */
    TRY(o3d_offscreen_renderer_render_to_image(&color, renderer));
    TRY(o3d_image_array_view(&rgb, &rows, color, O3D_IMAGE_DATA));
    TRY(o3d_offscreen_renderer_render_to_depth_image(&depth, renderer, 1));
    TRY(o3d_image_array_view(&z, &rows, depth, O3D_IMAGE_DATA));
    {
        const size_t centre = (size_t)(HEIGHT / 2) * WIDTH + WIDTH / 2;
        const uint8_t* p = rgb + 3 * centre;
        /* Float pixels are native-order bytes: copy them out rather than cast (alignment). */
        memcpy(&centre_depth, z + sizeof(float) * centre, sizeof centre_depth);
        printf("corner pixel: %u %u %u\n", rgb[0], rgb[1], rgb[2]);
        printf("centre pixel: %u %u %u, depth %.4f\n", p[0], p[1], p[2], centre_depth);
        /* The blue sphere, not the background, is at the centre. */
        rc = (p[0] != rgb[0] || p[1] != rgb[1] || p[2] != rgb[2]) && p[2] > p[0] && centre_depth > 0 ? 0 : 1;
    }

done:
    o3d_image_destroy(depth);
    o3d_image_destroy(color);
    o3d_trianglemesh_destroy(box);
    o3d_trianglemesh_destroy(sphere);
    o3d_offscreen_renderer_destroy(renderer);
    return s != O3D_OK ? 1 : rc;
}
