/* SPDX-License-Identifier: MIT */
/**
 * @file visualizer.h
 * @brief The viewer: Open3D's legacy Visualizer, VisualizerWithKeyCallback and VisualizerWithEditing, and
 * its ViewControl (`o3d_visualizer_view_*`).
 *
 * A visible window is a GLFW window and needs an X display (Xvfb will do). A hidden one
 * (`visible` = 0) renders through whatever the offscreen renderer gets, EGL first, so a hidden visualizer
 * captures images on a headless server too.
 *
 * Geometries are copied into the scene under a name; adding under a taken name replaces that geometry
 * (Open3D's update_geometry). The view is Open3D's ViewControl: it looks at `lookat` from the direction
 * `front`, `zoom` times the view box's largest extent away in units of the field of view.
 *
 * Input: o3d_visualizer_send_key / _send_mouse_* deliver events exactly as the window does, so scripts and
 * tests can drive the key bindings and callbacks with nobody at the keyboard. Keys use GLFW's numbers:
 * printable keys are their upper-case ASCII code ('R' = 82, '[' = 91), see O3D_KEY_* for others.
 *
 * Threads: a visualizer belongs to the thread that created its window (for a visible window, the main
 * thread); its functions are not safe to call concurrently. Callbacks run on that thread, inside
 * o3d_visualizer_run / _poll_events / _send_*, and may call any o3d_visualizer_* function except
 * o3d_visualizer_destroy and o3d_visualizer_destroy_window.
 */
#ifndef O3D_VISUALIZER_H
#define O3D_VISUALIZER_H

#include "o3d/camera.h"
#include "o3d/types.h"
#include "o3d/visualization.h"

O3D_BEGIN_DECL

/** What a key or a mouse button did (O3D_KEY_ACTION_*). */
typedef int32_t o3d_key_action;
#define O3D_KEY_ACTION_RELEASE 0 /**< a key or button went up */
#define O3D_KEY_ACTION_PRESS 1   /**< a key or button went down */
#define O3D_KEY_ACTION_REPEAT 2  /**< a key is held down */

/** A mouse button (O3D_MOUSE_BUTTON_*). */
typedef int32_t o3d_mouse_button;
#define O3D_MOUSE_BUTTON_LEFT 0   /**< left: a drag rotates; Shift + click picks when editing */
#define O3D_MOUSE_BUTTON_RIGHT 1  /**< right: Shift + click drops the last pick when editing */
#define O3D_MOUSE_BUTTON_MIDDLE 2 /**< middle: a drag translates */

#define O3D_KEY_MOD_SHIFT 1      /**< Shift was held */
#define O3D_KEY_MOD_CONTROL 2    /**< Control was held */
#define O3D_KEY_MOD_ALT 4        /**< Alt was held */
#define O3D_KEY_SPACE 32         /**< space bar */
#define O3D_KEY_ESCAPE 256       /**< Esc */
#define O3D_KEY_ENTER 257        /**< Enter */
#define O3D_KEY_RIGHT 262        /**< arrow right */
#define O3D_KEY_LEFT 263         /**< arrow left */
#define O3D_KEY_DOWN 264         /**< arrow down */
#define O3D_KEY_UP 265           /**< arrow up */

/**
 * @brief Called once per loop of o3d_visualizer_run (Open3D's animation callback). Return non-zero when the
 * geometry or the view changed, so that the frame is drawn again.
 */
typedef int32_t (*o3d_visualizer_animation_callback)(o3d_visualizer_t* vis, void* user_data);
/**
 * @brief Called for a key (Open3D's key callback, or key action callback with `action` and `mods`). Return
 * non-zero when the geometry or the view changed.
 */
typedef int32_t (*o3d_visualizer_key_callback)(o3d_visualizer_t* vis, o3d_key_action action, int32_t mods,
                                               void* user_data);

/**
 * @brief A visualizer without a window yet.
 *
 * Threads: any thread.
 * Ownership: `*out` belongs to the caller (o3d_visualizer_destroy).
 * @param out receives the handle
 * @param editing non-zero for VisualizerWithEditing: Shift + left click picks a point of the first geometry
 *   added, Shift + right click drops the last pick (o3d_visualizer_get_picked_points)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `out`.
 */
O3D_API o3d_status o3d_visualizer_create(o3d_visualizer_t** out, o3d_bool editing);
/**
 * @brief Close the window (if any) and free the visualizer. NULL is a no-op.
 *
 * Threads: the visualizer's thread, not from inside one of its callbacks.
 * @param vis the handle to destroy
 */
O3D_API void o3d_visualizer_destroy(o3d_visualizer_t* vis);
/**
 * @brief Visualizer.create_window.
 *
 * Threads: becomes the visualizer's thread; a visible window needs the main thread.
 * @param vis the visualizer
 * @param window_name the title (NULL: "o3d")
 * @param width,height pixels, 1..16384 (Open3D's defaults: 1920 x 1080)
 * @param left,top the window's position on screen; negative: where the window manager puts it
 * @param visible non-zero: a window on the display; 0: hidden (EGL when it works, so no display is needed)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, a bad size or a window already open;
 *   O3D_ERROR_UNSUPPORTED when no window or OpenGL 3.3 context can be had (the message says why).
 */
O3D_API o3d_status o3d_visualizer_create_window(o3d_visualizer_t* vis, const char* window_name, int32_t width,
                                                int32_t height, int32_t left, int32_t top, o3d_bool visible);
/**
 * @brief Visualizer.destroy_window: close the window and forget the scene (no-op without a window).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or when called from one of its callbacks.
 */
O3D_API o3d_status o3d_visualizer_destroy_window(o3d_visualizer_t* vis);
/**
 * @brief Visualizer.add_geometry / update_geometry for a point cloud: a copy is drawn under `name`.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param name the geometry's name; a taken name is replaced (update)
 * @param cloud the cloud (copied)
 * @param reset_bounding_box non-zero: the view box grows to take it in and the view is reset
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty name or no window.
 */
O3D_API o3d_status o3d_visualizer_add_pointcloud(o3d_visualizer_t* vis, const char* name, const o3d_pointcloud_t* cloud,
                                                 o3d_bool reset_bounding_box);
/**
 * @brief o3d_visualizer_add_pointcloud for a triangle mesh.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param name the geometry's name; a taken name is replaced (update)
 * @param mesh the mesh (copied)
 * @param reset_bounding_box non-zero: the view box grows to take it in and the view is reset
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty name, no window or a triangle
 *   index out of range.
 */
O3D_API o3d_status o3d_visualizer_add_trianglemesh(o3d_visualizer_t* vis, const char* name,
                                                   const o3d_trianglemesh_t* mesh, o3d_bool reset_bounding_box);
/**
 * @brief o3d_visualizer_add_pointcloud for a line set.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param name the geometry's name; a taken name is replaced (update)
 * @param lineset the line set (copied)
 * @param reset_bounding_box non-zero: the view box grows to take it in and the view is reset
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty name, no window or a line index
 *   out of range.
 */
O3D_API o3d_status o3d_visualizer_add_lineset(o3d_visualizer_t* vis, const char* name, const o3d_lineset_t* lineset,
                                              o3d_bool reset_bounding_box);
/**
 * @brief o3d_visualizer_add_pointcloud for a voxel grid (drawn as cubes).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param name the geometry's name; a taken name is replaced (update)
 * @param grid the voxel grid (copied)
 * @param reset_bounding_box non-zero: the view box grows to take it in and the view is reset
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty name or no window.
 */
O3D_API o3d_status o3d_visualizer_add_voxelgrid(o3d_visualizer_t* vis, const char* name, const o3d_voxelgrid_t* grid,
                                                o3d_bool reset_bounding_box);
/**
 * @brief o3d_visualizer_add_pointcloud for an image: shown flat under the 3D geometry, scaled to fit the
 * window with its aspect ratio kept and centred (Open3D's legacy viewer). 1, 3 or 4 channels of uint8;
 * one channel of uint16 or float32 is shown as gray up to its largest value; 3 of float32 clamped to [0, 1].
 * An image does not change the view box.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param name the geometry's name; a taken name is replaced (update)
 * @param image the image (copied)
 * @param reset_bounding_box non-zero: the view is reset (the box is unchanged)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty name, no window, an empty image or
 *   another pixel format.
 */
O3D_API o3d_status o3d_visualizer_add_image(o3d_visualizer_t* vis, const char* name, const o3d_image_t* image,
                                            o3d_bool reset_bounding_box);
/**
 * @brief Visualizer.remove_geometry.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param name the geometry's name
 * @param reset_bounding_box non-zero: the view box is computed again from what is left and the view reset
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, no window, or no geometry of that name.
 */
O3D_API o3d_status o3d_visualizer_remove_geometry(o3d_visualizer_t* vis, const char* name, o3d_bool reset_bounding_box);
/**
 * @brief Visualizer.clear_geometries.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or no window.
 */
O3D_API o3d_status o3d_visualizer_clear_geometries(o3d_visualizer_t* vis);
/**
 * @brief Whether a geometry of that name is in the scene (0 without a window).
 *
 * Threads: the visualizer's thread.
 * @param out receives 1 or 0
 * @param vis the visualizer
 * @param name the name
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_visualizer_has_geometry(o3d_bool* out, o3d_visualizer_t* vis, const char* name);
/**
 * @brief Visualizer.get_render_option (a copy; change it and pass it to o3d_visualizer_set_render_option).
 *
 * Threads: the visualizer's thread.
 * @param out receives the options (set `struct_size` first, e.g. with o3d_render_option_init)
 * @param vis the visualizer (with a window)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad `struct_size` or no window.
 */
O3D_API o3d_status o3d_visualizer_get_render_option(o3d_render_option_t* out, o3d_visualizer_t* vis);
/**
 * @brief Set the render options (checked as o3d_offscreen_renderer_set_render_option does).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param opts the options
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a value out of range or no window.
 */
O3D_API o3d_status o3d_visualizer_set_render_option(o3d_visualizer_t* vis, const o3d_render_option_t* opts);
/**
 * @brief Visualizer.poll_events: handle the window's events and draw a frame when needed.
 *
 * Threads: the visualizer's thread.
 * @param out_open receives 1 while the window is open, 0 once it was closed (may be NULL)
 * @param vis the visualizer
 * @return O3D_OK, O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, or what a callback run from it raised.
 */
O3D_API o3d_status o3d_visualizer_poll_events(o3d_bool* out_open, o3d_visualizer_t* vis);
/**
 * @brief Visualizer.update_renderer: draw the frame again at the next poll.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`.
 */
O3D_API o3d_status o3d_visualizer_update_renderer(o3d_visualizer_t* vis);
/**
 * @brief Visualizer.run: events, the animation callback and frames until the window is closed (by the
 * user, a key, or o3d_visualizer_close from a callback). A hidden window without an animation callback
 * could never be closed, so then one frame is drawn and run returns.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or no window; an error a binding's callback
 *   reported stops the loop (see o3d_visualizer_set_callback_error).
 */
O3D_API o3d_status o3d_visualizer_run(o3d_visualizer_t* vis);
/**
 * @brief Visualizer.close: the window closes; run and poll_events end.
 *
 * Threads: the visualizer's thread (callbacks included).
 * @param vis the visualizer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`.
 */
O3D_API o3d_status o3d_visualizer_close(o3d_visualizer_t* vis);
/**
 * @brief Stop the loop running a callback with an error: a binding whose callback raised calls this from
 * the callback; the run, poll or send call in progress then returns O3D_ERROR_CANCELLED with `message`.
 *
 * Threads: the visualizer's thread, from inside one of its callbacks.
 * @param vis the visualizer
 * @param message what went wrong (NULL: "a callback failed")
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`.
 */
O3D_API o3d_status o3d_visualizer_set_callback_error(o3d_visualizer_t* vis, const char* message);
/**
 * @brief Visualizer.register_animation_callback (NULL `callback` removes it).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param callback called once per loop of run
 * @param user_data passed to `callback`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`.
 */
O3D_API o3d_status o3d_visualizer_register_animation_callback(o3d_visualizer_t* vis,
                                                              o3d_visualizer_animation_callback callback,
                                                              void* user_data);
/**
 * @brief VisualizerWithKeyCallback.register_key_callback: `callback` runs on press and repeat of `key`
 * (instead of o3d's own binding of that key). NULL `callback` removes it.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param key the key (GLFW's number: 'A' = 65, O3D_KEY_*)
 * @param callback the callback
 * @param user_data passed to `callback`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or a negative `key`.
 */
O3D_API o3d_status o3d_visualizer_register_key_callback(o3d_visualizer_t* vis, int32_t key,
                                                        o3d_visualizer_key_callback callback, void* user_data);
/**
 * @brief VisualizerWithKeyCallback.register_key_action_callback: as o3d_visualizer_register_key_callback,
 * and also called on release.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param key the key (GLFW's number)
 * @param callback the callback
 * @param user_data passed to `callback`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or a negative `key`.
 */
O3D_API o3d_status o3d_visualizer_register_key_action_callback(o3d_visualizer_t* vis, int32_t key,
                                                               o3d_visualizer_key_callback callback, void* user_data);
/**
 * @brief Deliver a key event as the window does: a registered callback, else o3d's own binding (H help,
 * R reset, [ ] field of view, + - point size, N normals, W wireframe, B back faces, L light, S shading,
 * 0-4 9 colours, P capture, Ctrl+C view to clipboard, Q/Esc close).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param key the key (GLFW's number)
 * @param action O3D_KEY_ACTION_*
 * @param mods O3D_KEY_MOD_* bits
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or an unknown action; what the key's
 *   action raised (O3D_ERROR_IO when P cannot write its files; O3D_ERROR_CANCELLED from a callback).
 */
O3D_API o3d_status o3d_visualizer_send_key(o3d_visualizer_t* vis, int32_t key, o3d_key_action action, int32_t mods);
/**
 * @brief Deliver a cursor move (window pixels): a drag with the left button rotates, with Ctrl + left or
 * the middle button translates.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param x,y the cursor in window pixels (finite)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or a non-finite coordinate.
 */
O3D_API o3d_status o3d_visualizer_send_mouse_move(o3d_visualizer_t* vis, double x, double y);
/**
 * @brief Deliver a mouse button event at the cursor's place (editing: Shift + left release picks).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param button O3D_MOUSE_BUTTON_*
 * @param action O3D_KEY_ACTION_PRESS or _RELEASE
 * @param mods O3D_KEY_MOD_* bits
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, a button outside 0..7 or an unknown action.
 */
O3D_API o3d_status o3d_visualizer_send_mouse_button(o3d_visualizer_t* vis, o3d_mouse_button button,
                                                    o3d_key_action action, int32_t mods);
/**
 * @brief Deliver a wheel turn: the view's zoom changes by `dy` steps (ViewControl.scale).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param dx,dy the wheel's offsets (finite)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or a non-finite offset.
 */
O3D_API o3d_status o3d_visualizer_send_scroll(o3d_visualizer_t* vis, double dx, double dy);
/**
 * @brief Visualizer.capture_screen_float_buffer: the frame as RGB float32 in [0, 1].
 *
 * Threads: the visualizer's thread.
 * Ownership: `*out` belongs to the caller (o3d_image_destroy).
 * @param out receives the image
 * @param vis the visualizer (with a window)
 * @param do_render accepted for Open3D's signature; a frame is always drawn for the capture
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or no window.
 */
O3D_API o3d_status o3d_visualizer_capture_screen_float_buffer(o3d_image_t** out, o3d_visualizer_t* vis,
                                                              o3d_bool do_render);
/**
 * @brief Visualizer.capture_screen_image: the frame as an 8-bit RGB image file (PNG or JPEG by extension).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param path the file to write
 * @param do_render accepted for Open3D's signature; a frame is always drawn for the capture
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or no window; O3D_ERROR_IO when the file
 *   cannot be written; O3D_ERROR_UNSUPPORTED for an unknown extension.
 */
O3D_API o3d_status o3d_visualizer_capture_screen_image(o3d_visualizer_t* vis, const char* path, o3d_bool do_render);
/**
 * @brief Visualizer.capture_depth_float_buffer: float32 depth in metres along the optical axis, 0 where
 * nothing was drawn.
 *
 * Threads: the visualizer's thread.
 * Ownership: `*out` belongs to the caller (o3d_image_destroy).
 * @param out receives the image
 * @param vis the visualizer (with a window)
 * @param do_render accepted for Open3D's signature; a frame is always drawn for the capture
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or no window.
 */
O3D_API o3d_status o3d_visualizer_capture_depth_float_buffer(o3d_image_t** out, o3d_visualizer_t* vis,
                                                             o3d_bool do_render);
/**
 * @brief Visualizer.capture_depth_image: depth * `depth_scale` as a 16-bit PNG (Open3D's default scale 1000:
 * millimetres), clamped to 65535.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param path the PNG to write
 * @param do_render accepted for Open3D's signature; a frame is always drawn for the capture
 * @param depth_scale units per metre (> 0, finite)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, no window or a bad scale; O3D_ERROR_IO
 *   when the file cannot be written.
 */
O3D_API o3d_status o3d_visualizer_capture_depth_image(o3d_visualizer_t* vis, const char* path, o3d_bool do_render,
                                                      double depth_scale);
/**
 * @brief VisualizerWithEditing.get_picked_points: vertex indices of the first geometry added, in pick order.
 *
 * Threads: the visualizer's thread.
 * @param out receives the indices (`capacity` int32; NULL only counts)
 * @param capacity how many `out` holds
 * @param out_count receives how many there are (always)
 * @param vis the visualizer
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or `out_count`; O3D_ERROR_BUFFER_TOO_SMALL
 *   when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_visualizer_get_picked_points(int32_t* out, size_t capacity, size_t* out_count,
                                                    const o3d_visualizer_t* vis);
/**
 * @brief Whether the editing visualizer is selecting a region (key K locks the view for it: a left drag
 * selects a rectangle, Ctrl + left clicks add polygon corners, C crops, K again leaves).
 *
 * Threads: the visualizer's thread.
 * @param out receives 1 while selecting, else 0
 * @param vis the visualizer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_visualizer_is_selecting(o3d_bool* out, const o3d_visualizer_t* vis);
/**
 * @brief VisualizerWithEditing's crop (key C): keep the part of the first geometry (a point cloud or a
 * mesh: the triangles whose three vertices are kept) whose points project inside the selection, in front
 * of the camera; show it in place of the whole, clear the picks and leave selecting. With a crop directory
 * it is also written there as cropped_<n>.ply.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, no window, no cloud or mesh to crop, or a
 *   selection of fewer than 3 corners; O3D_ERROR_IO when the file cannot be written (the crop is kept).
 */
O3D_API o3d_status o3d_visualizer_crop_to_selection(o3d_visualizer_t* vis);
/**
 * @brief VisualizerWithEditing.get_cropped_geometry for a cropped point cloud: a copy of the last crop.
 *
 * Threads: the visualizer's thread.
 * Ownership: `*out` belongs to the caller (o3d_pointcloud_destroy); NULL when the last crop was not of a
 * point cloud or nothing was cropped.
 * @param out receives the new cloud or NULL
 * @param vis the visualizer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_visualizer_get_cropped_pointcloud(o3d_pointcloud_t** out, const o3d_visualizer_t* vis);
/**
 * @brief The last crop when it was of a triangle mesh (see o3d_visualizer_get_cropped_pointcloud).
 *
 * Threads: the visualizer's thread.
 * Ownership: `*out` belongs to the caller (o3d_trianglemesh_destroy); NULL when there is none.
 * @param out receives the new mesh or NULL
 * @param vis the visualizer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_visualizer_get_cropped_trianglemesh(o3d_trianglemesh_t** out, const o3d_visualizer_t* vis);
/**
 * @brief Where crops are written as cropped_1.ply, cropped_2.ply, ... (Open3D's `directory` without its
 * file dialog).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer
 * @param directory an existing directory, or NULL or "" not to write crops
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`.
 */
O3D_API o3d_status o3d_visualizer_set_crop_directory(o3d_visualizer_t* vis, const char* directory);

/* ---- ViewControl ---- */

/**
 * @brief ViewControl.rotate: as a left-button drag of (x, y) pixels (0.003 rad per pixel).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param x,y pixels (finite)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, no window or a non-finite value.
 */
O3D_API o3d_status o3d_visualizer_view_rotate(o3d_visualizer_t* vis, double x, double y);
/**
 * @brief ViewControl.translate: as a Ctrl + left-button drag of (x, y) pixels.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param x,y pixels (finite)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, no window or a non-finite value.
 */
O3D_API o3d_status o3d_visualizer_view_translate(o3d_visualizer_t* vis, double x, double y);
/**
 * @brief ViewControl.scale: zoom += scale * 0.02, kept in [0.02, 2].
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param scale steps (finite)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, no window or a non-finite value.
 */
O3D_API o3d_status o3d_visualizer_view_scale(o3d_visualizer_t* vis, double scale);
/**
 * @brief ViewControl.change_field_of_view: += step * 5 degrees, kept in [5, 90].
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param step steps (finite; Open3D's Python default 0.45)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, no window or a non-finite value.
 */
O3D_API o3d_status o3d_visualizer_view_change_field_of_view(o3d_visualizer_t* vis, double step);
/**
 * @brief ViewControl.get_field_of_view, in degrees.
 *
 * Threads: the visualizer's thread.
 * @param out receives the vertical field of view
 * @param vis the visualizer (with a window)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or no window.
 */
O3D_API o3d_status o3d_visualizer_view_get_field_of_view(double* out, o3d_visualizer_t* vis);
/**
 * @brief ViewControl.set_front / set_lookat / set_up / set_zoom in one call; NULL pointers keep the current
 * value, a negative `zoom` keeps it too (zoom is kept in [0.02, 2] as Open3D does).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param front direction from lookat to the eye (finite, non-zero) or NULL
 * @param lookat the point looked at (finite) or NULL
 * @param up the image's up direction (finite, non-zero, not parallel to front) or NULL
 * @param zoom the zoom, or negative to keep it
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis`, no window or a bad vector (the view is
 *   then unchanged).
 */
O3D_API o3d_status o3d_visualizer_view_set(o3d_visualizer_t* vis, const double front[3], const double lookat[3],
                                           const double up[3], double zoom);
/**
 * @brief The view's front, lookat, up and zoom.
 *
 * Threads: the visualizer's thread.
 * @param out_front,out_lookat,out_up receive 3 doubles each (each may be NULL)
 * @param out_zoom receives the zoom (may be NULL)
 * @param vis the visualizer (with a window)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or no window.
 */
O3D_API o3d_status o3d_visualizer_view_get(double out_front[3], double out_lookat[3], double out_up[3],
                                           double* out_zoom, o3d_visualizer_t* vis);
/**
 * @brief ViewControl.reset_camera_local_rotate / the R key: the view box from the scene, then Open3D's
 * default view (front +z, up +y, zoom 0.7, field of view 60).
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or no window.
 */
O3D_API o3d_status o3d_visualizer_view_reset(o3d_visualizer_t* vis);
/**
 * @brief ViewControl.convert_to_pinhole_camera_parameters.
 *
 * Threads: the visualizer's thread.
 * @param out_intrinsic receives the intrinsic (may be NULL)
 * @param out_extrinsic receives the row-major world-to-camera 4x4 (may be NULL)
 * @param vis the visualizer (with a window)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `vis` or no window.
 */
O3D_API o3d_status o3d_visualizer_view_to_pinhole(o3d_pinhole_intrinsic_t* out_intrinsic, double out_extrinsic[16],
                                                  o3d_visualizer_t* vis);
/**
 * @brief ViewControl.convert_from_pinhole_camera_parameters: the same camera gives the same image. The
 * intrinsic must be the window's size with its principal point at the centre and fx = fy, the field of
 * view in [5, 90] degrees, the extrinsic rigid.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param intrinsic the intrinsic
 * @param extrinsic row-major world-to-camera 4x4
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, no window or a camera the view cannot
 *   take (the message says which condition; the view is unchanged).
 */
O3D_API o3d_status o3d_visualizer_view_from_pinhole(o3d_visualizer_t* vis, const o3d_pinhole_intrinsic_t* intrinsic,
                                                    const double extrinsic[16]);
/**
 * @brief The view as Open3D's ViewTrajectory JSON with one entry (what Ctrl+C copies).
 *
 * Threads: the visualizer's thread.
 * Ownership: `*out` belongs to the caller (o3d_buffer_destroy).
 * @param out receives the UTF-8 JSON text
 * @param vis the visualizer (with a window)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or no window.
 */
O3D_API o3d_status o3d_visualizer_get_view_status(o3d_buffer_t** out, o3d_visualizer_t* vis);
/**
 * @brief Set the view from ViewTrajectory JSON (its first entry), as Ctrl+V does in Open3D.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param json the JSON text
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or no window; O3D_ERROR_PARSE on malformed
 *   JSON or a view out of range (the view is then unchanged).
 */
O3D_API o3d_status o3d_visualizer_set_view_status(o3d_visualizer_t* vis, const char* json);
/**
 * @brief draw_geometries_with_custom_animation's playback: show each frame of a ViewTrajectory JSON file
 * (key views with `interval` frames linearly interpolated between them), optionally writing
 * `image_%06d.png` (RGB) and `depth_%06d.png` (16-bit millimetres) into `capture_dir`.
 *
 * Threads: the visualizer's thread.
 * @param vis the visualizer (with a window)
 * @param trajectory_path a ViewTrajectory JSON file
 * @param capture_dir an existing folder for the captures, or NULL for none
 * @param capture_depth non-zero: also write the depth images
 * @param progress called after each frame (may be NULL); return non-zero to stop
 * @param user_data passed to `progress`
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or no window; O3D_ERROR_IO when a file
 *   cannot be read or written; O3D_ERROR_PARSE on a malformed trajectory; O3D_ERROR_CANCELLED when
 *   `progress` stopped it.
 */
O3D_API o3d_status o3d_visualizer_play_view_trajectory(o3d_visualizer_t* vis, const char* trajectory_path,
                                                       const char* capture_dir, o3d_bool capture_depth,
                                                       o3d_progress_callback progress, void* user_data);

O3D_END_DECL

#endif /* O3D_VISUALIZER_H */
