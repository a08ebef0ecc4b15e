//! Raw FFI declarations for the o3d C API (`capi/include/o3d/*.h`, library `libo3d.so.0`).
//!
//! This crate holds only `extern "C"` declarations, `#[repr(C)]` structs and constants, written by
//! hand to match the headers one for one (no bindgen, no libclang). The safe wrapper is the `o3d`
//! crate. Drift between the headers and this file is caught by this crate's tests
//! (`tests/drift.rs`: every `O3D_API` function and `#define` is declared here; `tests/layout.rs`:
//! struct sizes and offsets against a C compiler and against the library's `*_init`).
//!
//! All functions are `unsafe`: the caller upholds the header's ownership, lifetime and threading
//! rules.
#![allow(non_camel_case_types)]
#![no_std]

use core::ffi::{c_char, c_void};

// ---------------------------------------------------------------------------------------------
// common.h
// ---------------------------------------------------------------------------------------------

pub const O3D_VERSION_MAJOR: i32 = 0;
pub const O3D_VERSION_MINOR: i32 = 1;
pub const O3D_VERSION_PATCH: i32 = 0;

/// Status code returned by every fallible call: 0 on success, negative on failure.
pub type o3d_status = i32;

pub const O3D_OK: o3d_status = 0;
pub const O3D_ERROR_INVALID_ARGUMENT: o3d_status = -1;
pub const O3D_ERROR_OUT_OF_MEMORY: o3d_status = -2;
pub const O3D_ERROR_IO: o3d_status = -3;
pub const O3D_ERROR_PARSE: o3d_status = -4;
pub const O3D_ERROR_UNSUPPORTED: o3d_status = -5;
pub const O3D_ERROR_BUFFER_TOO_SMALL: o3d_status = -6;
pub const O3D_ERROR_NOT_CONVERGED: o3d_status = -7;
pub const O3D_ERROR_CANCELLED: o3d_status = -8;
pub const O3D_ERROR_INTERNAL: o3d_status = -9;

pub const O3D_LOG_ERROR: i32 = 0;
pub const O3D_LOG_WARNING: i32 = 1;
pub const O3D_LOG_INFO: i32 = 2;
pub const O3D_LOG_DEBUG: i32 = 3;

/// `typedef void (*o3d_log_callback)(int32_t level, const char* message, void* user_data);`
pub type o3d_log_callback = Option<unsafe extern "C" fn(level: i32, message: *const c_char, user_data: *mut c_void)>;

/// `typedef int32_t (*o3d_progress_callback)(double fraction, void* user_data);`
pub type o3d_progress_callback = Option<unsafe extern "C" fn(fraction: f64, user_data: *mut c_void) -> i32>;

/// Opaque owned byte buffer (`o3d_buffer_t`).
#[repr(C)]
pub struct o3d_buffer {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_buffer_t = o3d_buffer;

extern "C" {
    pub fn o3d_version() -> *const c_char;
    pub fn o3d_version_major() -> i32;
    pub fn o3d_version_minor() -> i32;
    pub fn o3d_version_patch() -> i32;

    pub fn o3d_last_error_message() -> *const c_char;
    pub fn o3d_last_error_code() -> o3d_status;
    pub fn o3d_clear_error();
    pub fn o3d_status_string(status: o3d_status) -> *const c_char;

    pub fn o3d_set_verbosity_level(level: i32) -> o3d_status;
    pub fn o3d_get_verbosity_level() -> i32;
    pub fn o3d_set_log_callback(callback: o3d_log_callback, user_data: *mut c_void) -> o3d_status;

    pub fn o3d_set_num_threads(num_threads: i32) -> o3d_status;
    pub fn o3d_get_num_threads() -> i32;

    pub fn o3d_buffer_destroy(buffer: *mut o3d_buffer_t);
    pub fn o3d_buffer_view(buffer: *const o3d_buffer_t, out_data: *mut *const u8, out_size: *mut usize) -> o3d_status;
    pub fn o3d_buffer_get_data(
        buffer: *const o3d_buffer_t,
        out: *mut u8,
        capacity: usize,
        out_size: *mut usize,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// pointcloud.h
// ---------------------------------------------------------------------------------------------

/// Opaque point cloud (`o3d_pointcloud_t`).
#[repr(C)]
pub struct o3d_pointcloud {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_pointcloud_t = o3d_pointcloud;

pub const O3D_SEARCH_KNN: i32 = 0;
pub const O3D_SEARCH_RADIUS: i32 = 1;
pub const O3D_SEARCH_HYBRID: i32 = 2;

/// Neighbourhood search parameter (`o3d_search_param_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct o3d_search_param {
    pub struct_size: u32,
    pub kind: i32,
    pub knn: i32,
    pub radius: f64,
}
pub type o3d_search_param_t = o3d_search_param;

extern "C" {
    pub fn o3d_pointcloud_create(out: *mut *mut o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_pointcloud_destroy(pc: *mut o3d_pointcloud_t);
    pub fn o3d_pointcloud_clone(out: *mut *mut o3d_pointcloud_t, src: *const o3d_pointcloud_t) -> o3d_status;

    pub fn o3d_pointcloud_size(pc: *const o3d_pointcloud_t, out_n: *mut usize) -> o3d_status;
    pub fn o3d_pointcloud_has_points(pc: *const o3d_pointcloud_t, out: *mut i32) -> o3d_status;
    pub fn o3d_pointcloud_has_normals(pc: *const o3d_pointcloud_t, out: *mut i32) -> o3d_status;
    pub fn o3d_pointcloud_has_colors(pc: *const o3d_pointcloud_t, out: *mut i32) -> o3d_status;
    pub fn o3d_pointcloud_clear(pc: *mut o3d_pointcloud_t) -> o3d_status;

    pub fn o3d_pointcloud_set_points(pc: *mut o3d_pointcloud_t, xyz: *const f64, n: usize) -> o3d_status;
    pub fn o3d_pointcloud_set_points_f32(pc: *mut o3d_pointcloud_t, xyz: *const f32, n: usize) -> o3d_status;
    pub fn o3d_pointcloud_set_normals(pc: *mut o3d_pointcloud_t, xyz: *const f64, n: usize) -> o3d_status;
    pub fn o3d_pointcloud_set_normals_f32(pc: *mut o3d_pointcloud_t, xyz: *const f32, n: usize) -> o3d_status;
    pub fn o3d_pointcloud_set_colors(pc: *mut o3d_pointcloud_t, rgb: *const f64, n: usize) -> o3d_status;
    pub fn o3d_pointcloud_set_colors_f32(pc: *mut o3d_pointcloud_t, rgb: *const f32, n: usize) -> o3d_status;

    pub fn o3d_pointcloud_get_points(
        pc: *const o3d_pointcloud_t,
        out: *mut f64,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_get_normals(
        pc: *const o3d_pointcloud_t,
        out: *mut f64,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_get_colors(
        pc: *const o3d_pointcloud_t,
        out: *mut f64,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;

    pub fn o3d_pointcloud_points_view(
        pc: *const o3d_pointcloud_t,
        out_data: *mut *const f64,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_normals_view(
        pc: *const o3d_pointcloud_t,
        out_data: *mut *const f64,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_colors_view(
        pc: *const o3d_pointcloud_t,
        out_data: *mut *const f64,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_points_mutable_view(
        pc: *mut o3d_pointcloud_t,
        out_data: *mut *mut f64,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_normals_mutable_view(
        pc: *mut o3d_pointcloud_t,
        out_data: *mut *mut f64,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_colors_mutable_view(
        pc: *mut o3d_pointcloud_t,
        out_data: *mut *mut f64,
        out_n: *mut usize,
    ) -> o3d_status;

    pub fn o3d_pointcloud_append(pc: *mut o3d_pointcloud_t, other: *const o3d_pointcloud_t) -> o3d_status;

    pub fn o3d_pointcloud_transform(pc: *mut o3d_pointcloud_t, transform: *const f64) -> o3d_status;
    pub fn o3d_pointcloud_translate(pc: *mut o3d_pointcloud_t, translation: *const f64, relative: i32) -> o3d_status;
    pub fn o3d_pointcloud_rotate(pc: *mut o3d_pointcloud_t, rotation: *const f64, center: *const f64) -> o3d_status;
    pub fn o3d_pointcloud_scale(pc: *mut o3d_pointcloud_t, scale: f64, center: *const f64) -> o3d_status;

    pub fn o3d_pointcloud_get_min_bound(pc: *const o3d_pointcloud_t, out: *mut f64) -> o3d_status;
    pub fn o3d_pointcloud_get_max_bound(pc: *const o3d_pointcloud_t, out: *mut f64) -> o3d_status;
    pub fn o3d_pointcloud_get_center(pc: *const o3d_pointcloud_t, out: *mut f64) -> o3d_status;
    pub fn o3d_pointcloud_get_axis_aligned_bounding_box(
        pc: *const o3d_pointcloud_t,
        out_min: *mut f64,
        out_max: *mut f64,
    ) -> o3d_status;
    pub fn o3d_pointcloud_paint_uniform_color(pc: *mut o3d_pointcloud_t, rgb: *const f64) -> o3d_status;
    pub fn o3d_pointcloud_select_by_index(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        indices: *const i32,
        n: usize,
        invert: i32,
    ) -> o3d_status;
    pub fn o3d_pointcloud_remove_non_finite_points(
        pc: *mut o3d_pointcloud_t,
        remove_nan: i32,
        remove_infinite: i32,
    ) -> o3d_status;
    pub fn o3d_pointcloud_normalize_normals(pc: *mut o3d_pointcloud_t) -> o3d_status;

    pub fn o3d_pointcloud_voxel_down_sample(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        voxel_size: f64,
    ) -> o3d_status;
    pub fn o3d_pointcloud_uniform_down_sample(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        every_k_points: usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_random_down_sample(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        sampling_ratio: f64,
        seed: u64,
    ) -> o3d_status;
    pub fn o3d_pointcloud_farthest_point_down_sample(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        num_samples: usize,
        start_index: usize,
    ) -> o3d_status;

    pub fn o3d_search_param_init(param: *mut o3d_search_param_t, struct_size: u32) -> o3d_status;

    pub fn o3d_pointcloud_estimate_normals(
        pc: *mut o3d_pointcloud_t,
        param: *const o3d_search_param_t,
        num_threads: i32,
    ) -> o3d_status;
    pub fn o3d_pointcloud_orient_normals_to_align_with_direction(
        pc: *mut o3d_pointcloud_t,
        direction: *const f64,
    ) -> o3d_status;
    pub fn o3d_pointcloud_orient_normals_towards_camera_location(
        pc: *mut o3d_pointcloud_t,
        camera_location: *const f64,
    ) -> o3d_status;
    pub fn o3d_pointcloud_compute_nearest_neighbor_distance(
        pc: *const o3d_pointcloud_t,
        out: *mut f64,
        capacity: usize,
        out_n: *mut usize,
        num_threads: i32,
    ) -> o3d_status;
    pub fn o3d_pointcloud_compute_point_cloud_distance(
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        out: *mut f64,
        capacity: usize,
        out_n: *mut usize,
        num_threads: i32,
    ) -> o3d_status;

    // Point-cloud tools (filters, segmentation, statistics).
    pub fn o3d_pointcloud_remove_statistical_outlier(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        nb_neighbors: i32,
        std_ratio: f64,
        out_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_remove_radius_outlier(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        nb_points: i32,
        radius: f64,
        out_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_crop_aabb(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        min_bound: *const f64,
        max_bound: *const f64,
        invert: i32,
    ) -> o3d_status;
    pub fn o3d_pointcloud_segment_plane(
        pc: *const o3d_pointcloud_t,
        distance_threshold: f64,
        ransac_n: i32,
        num_iterations: i32,
        probability: f64,
        seed: u64,
        out_plane: *mut f64,
        out_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_cluster_dbscan(
        pc: *const o3d_pointcloud_t,
        eps: f64,
        min_points: i32,
        out_labels: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_compute_mean_and_covariance(
        pc: *const o3d_pointcloud_t,
        out_mean: *mut f64,
        out_covariance: *mut f64,
    ) -> o3d_status;
    pub fn o3d_pointcloud_compute_mahalanobis_distance(
        pc: *const o3d_pointcloud_t,
        out: *mut f64,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// kdtree.h
// ---------------------------------------------------------------------------------------------

/// Opaque KD-tree (`o3d_kdtree_t`).
#[repr(C)]
pub struct o3d_kdtree {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_kdtree_t = o3d_kdtree;

/// Opaque flat batch-search result (`o3d_search_result_t`).
#[repr(C)]
pub struct o3d_search_result {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_search_result_t = o3d_search_result;

extern "C" {
    pub fn o3d_kdtree_create_from_pointcloud(out: *mut *mut o3d_kdtree_t, pc: *const o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_kdtree_create_from_points(out: *mut *mut o3d_kdtree_t, xyz: *const f64, n: usize) -> o3d_status;
    pub fn o3d_kdtree_destroy(tree: *mut o3d_kdtree_t);
    pub fn o3d_kdtree_size(tree: *const o3d_kdtree_t, out_n: *mut usize) -> o3d_status;

    pub fn o3d_kdtree_search(
        tree: *const o3d_kdtree_t,
        queries: *const f64,
        num_queries: usize,
        param: *const o3d_search_param_t,
        num_threads: i32,
        out: *mut *mut o3d_search_result_t,
    ) -> o3d_status;
    pub fn o3d_kdtree_search_f32(
        tree: *const o3d_kdtree_t,
        queries: *const f32,
        num_queries: usize,
        param: *const o3d_search_param_t,
        num_threads: i32,
        out: *mut *mut o3d_search_result_t,
    ) -> o3d_status;

    pub fn o3d_search_result_destroy(result: *mut o3d_search_result_t);
    pub fn o3d_search_result_counts(
        result: *const o3d_search_result_t,
        out_num_queries: *mut usize,
        out_total: *mut usize,
    ) -> o3d_status;
    pub fn o3d_search_result_view(
        result: *const o3d_search_result_t,
        out_offsets: *mut *const i64,
        out_indices: *mut *const i32,
        out_distances2: *mut *const f64,
    ) -> o3d_status;
    pub fn o3d_search_result_get_offsets(
        result: *const o3d_search_result_t,
        out: *mut i64,
        capacity: usize,
    ) -> o3d_status;
    pub fn o3d_search_result_get_indices(
        result: *const o3d_search_result_t,
        out: *mut i32,
        capacity: usize,
    ) -> o3d_status;
    pub fn o3d_search_result_get_distances2(
        result: *const o3d_search_result_t,
        out: *mut f64,
        capacity: usize,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// io.h
// ---------------------------------------------------------------------------------------------

/// Read options (`o3d_read_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct o3d_read_options {
    pub struct_size: u32,
    pub remove_nan_points: i32,
    pub remove_infinite_points: i32,
}
pub type o3d_read_options_t = o3d_read_options;

/// Write options (`o3d_write_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct o3d_write_options {
    pub struct_size: u32,
    pub write_ascii: i32,
    pub compressed: i32,
}
pub type o3d_write_options_t = o3d_write_options;

extern "C" {
    pub fn o3d_read_options_init(opts: *mut o3d_read_options_t, struct_size: u32) -> o3d_status;
    pub fn o3d_write_options_init(opts: *mut o3d_write_options_t, struct_size: u32) -> o3d_status;

    pub fn o3d_io_read_point_cloud(
        out: *mut *mut o3d_pointcloud_t,
        path: *const c_char,
        format: *const c_char,
        opts: *const o3d_read_options_t,
    ) -> o3d_status;
    pub fn o3d_io_write_point_cloud(
        path: *const c_char,
        pc: *const o3d_pointcloud_t,
        format: *const c_char,
        opts: *const o3d_write_options_t,
    ) -> o3d_status;
    pub fn o3d_io_read_point_cloud_from_memory(
        out: *mut *mut o3d_pointcloud_t,
        data: *const u8,
        size: usize,
        format: *const c_char,
        opts: *const o3d_read_options_t,
    ) -> o3d_status;
    pub fn o3d_io_write_point_cloud_to_memory(
        out: *mut *mut o3d_buffer_t,
        pc: *const o3d_pointcloud_t,
        format: *const c_char,
        opts: *const o3d_write_options_t,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// registration.h
// ---------------------------------------------------------------------------------------------

pub const O3D_ESTIMATION_POINT_TO_POINT: i32 = 0;
pub const O3D_ESTIMATION_POINT_TO_PLANE: i32 = 1;

/// ICP options (`o3d_icp_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct o3d_icp_options {
    pub struct_size: u32,
    pub estimation: i32,
    pub with_scaling: i32,
    pub relative_fitness: f64,
    pub relative_rmse: f64,
    pub max_iteration: i32,
    pub num_threads: i32,
    pub progress: o3d_progress_callback,
    pub user_data: *mut c_void,
}
pub type o3d_icp_options_t = o3d_icp_options;

/// Opaque registration result (`o3d_registration_result_t`).
#[repr(C)]
pub struct o3d_registration_result {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_registration_result_t = o3d_registration_result;

extern "C" {
    pub fn o3d_icp_options_init(opts: *mut o3d_icp_options_t, struct_size: u32) -> o3d_status;

    pub fn o3d_register_icp(
        out: *mut *mut o3d_registration_result_t,
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        max_correspondence_distance: f64,
        init: *const f64,
        opts: *const o3d_icp_options_t,
    ) -> o3d_status;
    pub fn o3d_evaluate_registration(
        out: *mut *mut o3d_registration_result_t,
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        max_correspondence_distance: f64,
        transformation: *const f64,
    ) -> o3d_status;
    pub fn o3d_get_information_matrix_from_point_clouds(
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        max_correspondence_distance: f64,
        transformation: *const f64,
        out: *mut f64,
    ) -> o3d_status;

    pub fn o3d_registration_result_destroy(result: *mut o3d_registration_result_t);
    pub fn o3d_registration_result_get_transformation(
        result: *const o3d_registration_result_t,
        out: *mut f64,
    ) -> o3d_status;
    pub fn o3d_registration_result_get_fitness(result: *const o3d_registration_result_t, out: *mut f64) -> o3d_status;
    pub fn o3d_registration_result_get_inlier_rmse(
        result: *const o3d_registration_result_t,
        out: *mut f64,
    ) -> o3d_status;
    pub fn o3d_registration_result_get_correspondence_set(
        result: *const o3d_registration_result_t,
        out: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
}
