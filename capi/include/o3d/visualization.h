/* SPDX-License-Identifier: MIT */
/**
 * @file visualization.h
 * @brief Rendering without a display: an offscreen renderer for point clouds, triangle meshes, line sets
 * and voxel grids, styled by a RenderOption, seen through a pinhole camera or Open3D's
 * lookat/front/up/zoom view (o3d.visualization.RenderOption, o3d.visualization.rendering.OffscreenRenderer).
 *
 * The renderer draws with OpenGL 3.3 into an offscreen framebuffer. Its context comes from EGL (Mesa's
 * surfaceless platform, no X server; software rendering where there is no GPU) or, when EGL is not
 * there, from a hidden GLFW window (needs a display, e.g. Xvfb). libEGL and libglfw are looked up at run
 * time, so o3d loads and runs on machines without them.
 *
 * Geometries are copied when added: later changes to a handle do not show until it is removed and added
 * again. The camera: a pinhole camera (intrinsic + world-to-camera extrinsic) is used as given; a
 * lookat/front/up/zoom view is resolved at each render against the bounding box of the geometries then
 * in the scene, as Open3D's ViewControl does (field of view 60 degrees). Without either, the view is
 * Open3D's default: lookat the box centre, front +z, up +y, zoom 0.7.
 *
 * **Threads:** a renderer may be used from any thread, one call at a time (calls on one renderer are
 * serialized internally; with the GLFW fallback, create and use it on the main thread).
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_VISUALIZATION_H
#define O3D_VISUALIZATION_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/camera.h"

O3D_BEGIN_DECL

/** Where the renderer's OpenGL context comes from (O3D_RENDER_BACKEND_*). */
typedef int32_t o3d_render_backend;
#define O3D_RENDER_BACKEND_AUTO 0 /**< EGL when it works, else a hidden GLFW window */
#define O3D_RENDER_BACKEND_EGL 1  /**< EGL only (headless) */
#define O3D_RENDER_BACKEND_GLFW 2 /**< a hidden GLFW window only (needs a display) */

/** RenderOption.mesh_shade_option (Open3D's MeshShadeOption; O3D_MESH_SHADE_*). */
typedef int32_t o3d_mesh_shade_option;
#define O3D_MESH_SHADE_FLAT 0   /**< FlatShade: one normal per triangle */
#define O3D_MESH_SHADE_SMOOTH 1 /**< SmoothShade: the vertex normals (flat where the mesh has none) */

/** RenderOption.point_color_option and mesh_color_option (Open3D's PointColorOption / MeshColorOption;
 *  O3D_COLOR_OPTION_*). */
typedef int32_t o3d_color_option;
#define O3D_COLOR_OPTION_DEFAULT 0 /**< points: their colors, else a Jet map of z; meshes: default_mesh_color */
#define O3D_COLOR_OPTION_COLOR 1   /**< their colors, else as DEFAULT */
#define O3D_COLOR_OPTION_X 2       /**< Jet color map of x over the scene's box */
#define O3D_COLOR_OPTION_Y 3       /**< Jet color map of y over the scene's box */
#define O3D_COLOR_OPTION_Z 4       /**< Jet color map of z over the scene's box */
#define O3D_COLOR_OPTION_NORMAL 9  /**< normal * 0.5 + 0.5 (black without normals) */

/** A material's shader (O3D_SHADER_*). */
typedef int32_t o3d_shader;
#define O3D_SHADER_DEFAULT_LIT 0   /**< "defaultLit": the RenderOption's lights (when light_on) */
#define O3D_SHADER_DEFAULT_UNLIT 1 /**< "defaultUnlit": colors as they are, no lighting */

/**
 * o3d.visualization.RenderOption. Lights are Open3D's Phong lights: light i sits at
 * center + extent * (p.x * right + p.y * up + p.z * front) of the scene's box, in the camera's frame, with
 * p = light_position[3i..3i+2]; a fragment's color is
 * `color * (ambient + sum_i diffuse_i * max(n.l_i, 0) * light_color_i) + sum_i specular_i * max(r_i.v, 0)^shininess_i * light_color_i`.
 */
typedef struct o3d_render_option {
    uint32_t struct_size;            /**< sizeof(o3d_render_option_t) */
    double background_color[3];      /**< RGB in [0, 1]; default white */
    double point_size;               /**< pixels, in [1, 25]; default 5 */
    double line_width;               /**< pixels, in [1, 10]; default 1 */
    o3d_bool light_on;               /**< light lit materials with the four Phong lights; default 1 */
    o3d_bool point_show_normal;      /**< draw each point's normal as a line; default 0 */
    o3d_bool mesh_show_wireframe;    /**< draw triangle edges over the faces; default 0 */
    o3d_bool mesh_show_back_face;    /**< draw triangles seen from behind; default 0 (culled) */
    o3d_mesh_shade_option mesh_shade_option; /**< O3D_MESH_SHADE_*; default FLAT */
    o3d_color_option point_color_option; /**< O3D_COLOR_OPTION_*; default DEFAULT */
    o3d_color_option mesh_color_option; /**< O3D_COLOR_OPTION_*; default COLOR */
    double default_mesh_color[3];    /**< RGB of meshes without colors (in Open3D's JSON, not its Python API); default 0.7 gray */
    double light_ambient_color[3];   /**< RGB of the ambient light (in Open3D's JSON, not its Python API); default black */
    double light_position[12];       /**< 4 lights, row-major 4x3: (right, up, front) relative to the box (see above); default (0,0,2) twice, (0,0,-2) twice */
    double light_color[12];          /**< 4 lights, row-major 4x3 RGB; default white */
    double light_diffuse_power[4];   /**< per light; default 0.66 */
    double light_specular_power[4];  /**< per light; default 0.2 */
    double light_specular_shininess[4]; /**< per light; default 100 */
} o3d_render_option_t;

/**
 * @brief Fill Open3D's RenderOption defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_render_option_init(o3d_render_option_t* opts, uint32_t struct_size);
/**
 * @brief RenderOption.load_from_json: fields present in the file replace those of `*out`, others keep
 * their value (Open3D's layout, e.g. the shared data's renderoption.json).
 *
 * Threads: any thread.
 * @param out the options to update (fill with o3d_render_option_init first)
 * @param path a JSON file with "class_name": "RenderOption"
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `struct_size`; O3D_ERROR_IO when the
 *   file cannot be read; O3D_ERROR_PARSE on malformed JSON, another class_name, or a field of the wrong
 *   type or out of range (`*out` is then unchanged).
 */
O3D_API o3d_status o3d_render_option_load_json(o3d_render_option_t* out, const char* path);
/**
 * @brief RenderOption.save_to_json, in Open3D's layout.
 *
 * Threads: any thread.
 * @param path the file to write
 * @param opts the options (NULL: the defaults)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `path` or a bad `struct_size`; O3D_ERROR_IO when the
 *   file cannot be written.
 */
O3D_API o3d_status o3d_render_option_save_json(const char* path, const o3d_render_option_t* opts);

/** A geometry's material: how it is shaded, and its size and tint. */
typedef struct o3d_render_material {
    uint32_t struct_size;  /**< sizeof(o3d_render_material_t) */
    o3d_shader shader;     /**< O3D_SHADER_*; default DEFAULT_LIT */
    double base_color[4];  /**< multiplies the geometry's colors (RGBA; alpha unused); default 1,1,1,1 */
    double point_size;     /**< pixels; 0 (default) = the RenderOption's */
    double line_width;     /**< pixels; 0 (default) = the RenderOption's */
} o3d_render_material_t;

/**
 * @brief Fill the material defaults (lit, white tint, the RenderOption's sizes).
 *
 * Threads: any thread.
 * @param material the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_render_material_init(o3d_render_material_t* material, uint32_t struct_size);

/**
 * @brief New offscreen renderer of `width` x `height` pixels (OffscreenRenderer(width, height)).
 *
 * Threads: any thread (O3D_RENDER_BACKEND_GLFW: the main thread).
 * Ownership: `*out` is the caller's, to free with o3d_offscreen_renderer_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param width image width, 1..16384
 * @param height image height, 1..16384
 * @param backend O3D_RENDER_BACKEND_*
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a size out of range or an unknown backend;
 *   O3D_ERROR_UNSUPPORTED when no OpenGL 3.3 context can be made (the message says what each backend
 *   answered).
 */
O3D_API o3d_status o3d_offscreen_renderer_create(o3d_offscreen_renderer_t** out, int32_t width, int32_t height,
                                                 o3d_render_backend backend);
/**
 * @brief Destroy, with its GPU resources. NULL is a no-op.
 *
 * Threads: needs exclusive access to `renderer`: no other call may use it during or after.
 * @param renderer the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_offscreen_renderer_destroy(o3d_offscreen_renderer_t* renderer);
/**
 * @brief The backend the renderer runs on (O3D_RENDER_BACKEND_EGL or _GLFW).
 *
 * Threads: any thread.
 * @param out receives O3D_RENDER_BACKEND_EGL or O3D_RENDER_BACKEND_GLFW
 * @param renderer the renderer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_offscreen_renderer_get_backend(o3d_render_backend* out, const o3d_offscreen_renderer_t* renderer);
/**
 * @brief The image size.
 *
 * Threads: any thread.
 * @param out_width receives the width in pixels
 * @param out_height receives the height in pixels
 * @param renderer the renderer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_offscreen_renderer_get_size(int32_t* out_width, int32_t* out_height,
                                                   const o3d_offscreen_renderer_t* renderer);
/**
 * @brief Add a copy of a point cloud under `name` (scene.add_geometry). Points with a NaN or infinite
 * coordinate are not drawn.
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param name a name not yet in the scene (non-empty)
 * @param pc the cloud (may be empty)
 * @param material NULL: o3d_render_material_init's defaults
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty name, a name already in the scene
 *   or a bad material.
 */
O3D_API o3d_status o3d_offscreen_renderer_add_pointcloud(o3d_offscreen_renderer_t* renderer, const char* name,
                                                         const o3d_pointcloud_t* pc,
                                                         const o3d_render_material_t* material);
/**
 * @brief Add a copy of a triangle mesh under `name`. Triangles with an index out of range are an error.
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param name a name not yet in the scene (non-empty)
 * @param mesh the mesh (may be empty)
 * @param material NULL: o3d_render_material_init's defaults
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty or taken name, a bad material or
 *   a triangle index out of range.
 */
O3D_API o3d_status o3d_offscreen_renderer_add_trianglemesh(o3d_offscreen_renderer_t* renderer, const char* name,
                                                           const o3d_trianglemesh_t* mesh,
                                                           const o3d_render_material_t* material);
/**
 * @brief Add a copy of a line set under `name` (lines without colors are black, as in Open3D).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param name a name not yet in the scene (non-empty)
 * @param lineset the line set (may be empty)
 * @param material NULL: o3d_render_material_init's defaults (line sets are never lit)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty or taken name, a bad material or
 *   a line index out of range.
 */
O3D_API o3d_status o3d_offscreen_renderer_add_lineset(o3d_offscreen_renderer_t* renderer, const char* name,
                                                      const o3d_lineset_t* lineset,
                                                      const o3d_render_material_t* material);
/**
 * @brief Add a voxel grid under `name`: one cube per voxel, in the voxel's color (default_mesh_color
 * when the grid has none).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param name a name not yet in the scene (non-empty)
 * @param grid the voxel grid (may be empty)
 * @param material NULL: o3d_render_material_init's defaults
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty or taken name or a bad material.
 */
O3D_API o3d_status o3d_offscreen_renderer_add_voxelgrid(o3d_offscreen_renderer_t* renderer, const char* name,
                                                        const o3d_voxelgrid_t* grid,
                                                        const o3d_render_material_t* material);
/**
 * @brief Whether a geometry named `name` is in the scene (scene.has_geometry).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param out receives 1 or 0
 * @param renderer the renderer
 * @param name the name
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_offscreen_renderer_has_geometry(o3d_bool* out, o3d_offscreen_renderer_t* renderer,
                                                       const char* name);
/**
 * @brief Remove the geometry named `name` (scene.remove_geometry).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param name the name
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a name not in the scene.
 */
O3D_API o3d_status o3d_offscreen_renderer_remove_geometry(o3d_offscreen_renderer_t* renderer, const char* name);
/**
 * @brief Remove every geometry (scene.clear_geometry).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_offscreen_renderer_clear_geometries(o3d_offscreen_renderer_t* renderer);
/**
 * @brief Replace the render option (background, sizes, lights, color options).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param opts the options (NULL: the defaults)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `renderer`, a bad `struct_size` or a value out of
 *   range (a NaN, a size outside its range, an unknown option).
 */
O3D_API o3d_status o3d_offscreen_renderer_set_render_option(o3d_offscreen_renderer_t* renderer,
                                                            const o3d_render_option_t* opts);
/**
 * @brief The current render option.
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param out receives the options (its struct_size must be set, e.g. by o3d_render_option_init)
 * @param renderer the renderer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `struct_size`.
 */
O3D_API o3d_status o3d_offscreen_renderer_get_render_option(o3d_render_option_t* out,
                                                            o3d_offscreen_renderer_t* renderer);
/**
 * @brief Look through a pinhole camera (setup_camera(intrinsic, extrinsic)). The intrinsic's size must be
 * the renderer's; its principal point may be anywhere. Near and far planes follow the scene's box.
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param intrinsic width/height equal to the renderer's, fx and fy > 0, all finite
 * @param extrinsic row-major 4x4 world-to-camera rigid transform (camera looks along +z, y down)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a size mismatch, a non-positive focal
 *   length, a non-finite value or an extrinsic that is not rigid.
 */
O3D_API o3d_status o3d_offscreen_renderer_setup_camera(o3d_offscreen_renderer_t* renderer,
                                                       const o3d_pinhole_intrinsic_t* intrinsic,
                                                       const double extrinsic[16]);
/**
 * @brief Open3D's ViewControl view: look at `lookat` from direction `front`, with `up` up, at `zoom`
 * (draw_geometries' lookat/front/up/zoom). The distance follows from the scene's box at render time.
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param lookat the point looked at
 * @param front direction from `lookat` towards the camera (non-zero)
 * @param up the up direction (non-zero, not parallel to `front`)
 * @param zoom in [0.02, 2] as Open3D's ViewControl clamps it (Open3D's default 0.7)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a non-finite value, a zero or parallel
 *   front/up or a zoom out of range.
 */
O3D_API o3d_status o3d_offscreen_renderer_setup_camera_lookat(o3d_offscreen_renderer_t* renderer,
                                                              const double lookat[3], const double front[3],
                                                              const double up[3], double zoom);
/**
 * @brief A perspective camera at `eye` looking at `center` with `up` up and a vertical field of view
 * (setup_camera(vertical_field_of_view, center, eye, up)).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param vertical_fov_deg vertical field of view in degrees, in (0, 180)
 * @param center the point looked at
 * @param eye the camera position (not equal to `center`)
 * @param up the up direction (not parallel to eye - center)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a non-finite value, an angle out of range,
 *   eye == center or a parallel up.
 */
O3D_API o3d_status o3d_offscreen_renderer_setup_camera_fov(o3d_offscreen_renderer_t* renderer,
                                                           double vertical_fov_deg, const double center[3],
                                                           const double eye[3], const double up[3]);
/**
 * @brief The camera the next render uses, as pinhole parameters
 * (ViewControl.convert_to_pinhole_camera_parameters): passing them to o3d_offscreen_renderer_setup_camera
 * reproduces the image.
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param out_intrinsic receives the intrinsic (may be NULL)
 * @param out_extrinsic receives the row-major 4x4 world-to-camera extrinsic (may be NULL)
 * @param renderer the renderer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `renderer`.
 */
O3D_API o3d_status o3d_offscreen_renderer_get_camera(o3d_pinhole_intrinsic_t* out_intrinsic,
                                                     double out_extrinsic[16],
                                                     o3d_offscreen_renderer_t* renderer);
/**
 * @brief Render the scene to a new RGB image (3 channels, 1 byte each; render_to_image).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the image
 * @param renderer the renderer
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_INTERNAL when OpenGL reports an
 *   error.
 */
O3D_API o3d_status o3d_offscreen_renderer_render_to_image(o3d_image_t** out, o3d_offscreen_renderer_t* renderer);
/**
 * @brief Render the scene's depth to a new float image (1 channel, 4 bytes; render_to_depth_image).
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the image
 * @param renderer the renderer
 * @param z_in_view_space non-zero: the distance along the camera's axis in scene units (metres), 0 where
 *   nothing was drawn (as Open3D's capture_depth_float_buffer); zero: the depth buffer in [0, 1], 1 where
 *   nothing was drawn (as Open3D's render_to_depth_image default)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_INTERNAL when OpenGL reports an
 *   error.
 */
O3D_API o3d_status o3d_offscreen_renderer_render_to_depth_image(o3d_image_t** out,
                                                                o3d_offscreen_renderer_t* renderer,
                                                                int32_t z_in_view_space);
/**
 * @brief Render the scene and write it as a PNG file in one call.
 *
 * The renderer comes first, as the subject of a method, before the file it writes.
 *
 * Threads: any thread, one call per renderer at a time (serialized).
 * @param renderer the renderer
 * @param path the PNG file to write
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be
 *   written; O3D_ERROR_INTERNAL when OpenGL reports an error.
 */
O3D_API o3d_status o3d_offscreen_renderer_render_to_png(o3d_offscreen_renderer_t* renderer, const char* path);

O3D_END_DECL

#endif /* O3D_VISUALIZATION_H */
