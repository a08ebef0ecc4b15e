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
    pub fn o3d_buffer_view(out_data: *mut *const u8, out_size: *mut usize, buffer: *const o3d_buffer_t) -> o3d_status;
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

    pub fn o3d_pointcloud_size(out_n: *mut usize, pc: *const o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_pointcloud_has_points(out: *mut i32, pc: *const o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_pointcloud_has_normals(out: *mut i32, pc: *const o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_pointcloud_has_colors(out: *mut i32, pc: *const o3d_pointcloud_t) -> o3d_status;
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

    pub fn o3d_pointcloud_get_min_bound(out: *mut f64, pc: *const o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_pointcloud_get_max_bound(out: *mut f64, pc: *const o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_pointcloud_get_center(out: *mut f64, pc: *const o3d_pointcloud_t) -> o3d_status;
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

    // Per-point covariances (N x 9, row-major 3x3 each).
    pub fn o3d_pointcloud_has_covariances(out: *mut i32, pc: *const o3d_pointcloud_t) -> o3d_status;
    pub fn o3d_pointcloud_set_covariances(pc: *mut o3d_pointcloud_t, data: *const f64, n: usize) -> o3d_status;
    pub fn o3d_pointcloud_get_covariances(
        pc: *const o3d_pointcloud_t,
        out: *mut f64,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_covariances_view(
        pc: *const o3d_pointcloud_t,
        out_data: *mut *const f64,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_estimate_covariances(
        pc: *mut o3d_pointcloud_t,
        param: *const o3d_search_param_t,
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
    pub fn o3d_kdtree_size(out_n: *mut usize, tree: *const o3d_kdtree_t) -> o3d_status;

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
// feature.h
// ---------------------------------------------------------------------------------------------

/// Opaque feature matrix (`o3d_feature_t`): `dimension` x `num` doubles, descriptor by descriptor.
#[repr(C)]
pub struct o3d_feature {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_feature_t = o3d_feature;

extern "C" {
    pub fn o3d_feature_create(out: *mut *mut o3d_feature_t, dimension: usize, num: usize) -> o3d_status;
    pub fn o3d_feature_create_from_data(
        out: *mut *mut o3d_feature_t,
        data: *const f64,
        dimension: usize,
        num: usize,
    ) -> o3d_status;
    pub fn o3d_feature_destroy(feature: *mut o3d_feature_t);
    pub fn o3d_feature_clone(out: *mut *mut o3d_feature_t, feature: *const o3d_feature_t) -> o3d_status;
    pub fn o3d_feature_dimension(out: *mut usize, feature: *const o3d_feature_t) -> o3d_status;
    pub fn o3d_feature_num(out: *mut usize, feature: *const o3d_feature_t) -> o3d_status;
    pub fn o3d_feature_resize(feature: *mut o3d_feature_t, dimension: usize, num: usize) -> o3d_status;
    pub fn o3d_feature_data(out_data: *mut *mut f64, feature: *mut o3d_feature_t) -> o3d_status;
    pub fn o3d_feature_get_data(out: *mut f64, capacity: usize, feature: *const o3d_feature_t) -> o3d_status;
    pub fn o3d_feature_select_by_index(
        out: *mut *mut o3d_feature_t,
        feature: *const o3d_feature_t,
        indices: *const i64,
        n: usize,
        invert: i32,
    ) -> o3d_status;

    pub fn o3d_compute_fpfh_feature(
        out: *mut *mut o3d_feature_t,
        pc: *const o3d_pointcloud_t,
        param: *const o3d_search_param_t,
        indices: *const i64,
        n_indices: usize,
        num_threads: i32,
    ) -> o3d_status;

    pub fn o3d_correspondences_from_features(
        source: *const o3d_feature_t,
        target: *const o3d_feature_t,
        mutual_filter: i32,
        mutual_consistency_ratio: f64,
        num_threads: i32,
        out: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;

    pub fn o3d_io_read_feature(out: *mut *mut o3d_feature_t, path: *const c_char) -> o3d_status;
    pub fn o3d_io_write_feature(path: *const c_char, feature: *const o3d_feature_t) -> o3d_status;

    pub fn o3d_kdtree_create_from_feature(out: *mut *mut o3d_kdtree_t, feature: *const o3d_feature_t) -> o3d_status;
    pub fn o3d_kdtree_create_from_points_xd(
        out: *mut *mut o3d_kdtree_t,
        data: *const f64,
        dimension: usize,
        n: usize,
    ) -> o3d_status;
    pub fn o3d_kdtree_dimension(out: *mut usize, tree: *const o3d_kdtree_t) -> o3d_status;
    pub fn o3d_kdtree_search_xd(
        tree: *const o3d_kdtree_t,
        queries: *const f64,
        num_queries: usize,
        dimension: usize,
        param: *const o3d_search_param_t,
        num_threads: i32,
        out: *mut *mut o3d_search_result_t,
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
// io.h: triangle meshes, images, camera models
// ---------------------------------------------------------------------------------------------

/// Mesh read options (`o3d_mesh_read_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct o3d_mesh_read_options {
    pub struct_size: u32,
    pub enable_post_processing: i32,
}
pub type o3d_mesh_read_options_t = o3d_mesh_read_options;

/// Mesh write options (`o3d_mesh_write_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct o3d_mesh_write_options {
    pub struct_size: u32,
    pub write_ascii: i32,
    pub compressed: i32,
    pub write_vertex_normals: i32,
    pub write_vertex_colors: i32,
    pub write_triangle_uvs: i32,
}
pub type o3d_mesh_write_options_t = o3d_mesh_write_options;

extern "C" {
    pub fn o3d_mesh_read_options_init(opts: *mut o3d_mesh_read_options_t, struct_size: u32) -> o3d_status;
    pub fn o3d_mesh_write_options_init(opts: *mut o3d_mesh_write_options_t, struct_size: u32) -> o3d_status;

    pub fn o3d_io_read_triangle_mesh(
        out: *mut *mut o3d_trianglemesh_t,
        path: *const c_char,
        format: *const c_char,
        opts: *const o3d_mesh_read_options_t,
    ) -> o3d_status;
    pub fn o3d_io_write_triangle_mesh(
        path: *const c_char,
        mesh: *const o3d_trianglemesh_t,
        format: *const c_char,
        opts: *const o3d_mesh_write_options_t,
    ) -> o3d_status;
    pub fn o3d_io_read_triangle_mesh_from_memory(
        out: *mut *mut o3d_trianglemesh_t,
        data: *const u8,
        size: usize,
        format: *const c_char,
        opts: *const o3d_mesh_read_options_t,
    ) -> o3d_status;
    pub fn o3d_io_write_triangle_mesh_to_memory(
        out: *mut *mut o3d_buffer_t,
        mesh: *const o3d_trianglemesh_t,
        format: *const c_char,
        opts: *const o3d_mesh_write_options_t,
    ) -> o3d_status;

    pub fn o3d_io_read_image(out: *mut *mut o3d_image_t, path: *const c_char, format: *const c_char) -> o3d_status;
    pub fn o3d_io_write_image(
        path: *const c_char,
        image: *const o3d_image_t,
        format: *const c_char,
        quality: i32,
    ) -> o3d_status;
    pub fn o3d_io_read_image_from_memory(
        out: *mut *mut o3d_image_t,
        data: *const u8,
        size: usize,
        format: *const c_char,
    ) -> o3d_status;
    pub fn o3d_io_write_image_to_memory(
        out: *mut *mut o3d_buffer_t,
        image: *const o3d_image_t,
        format: *const c_char,
        quality: i32,
    ) -> o3d_status;

    pub fn o3d_io_read_pinhole_camera_intrinsic(out: *mut o3d_pinhole_intrinsic_t, path: *const c_char) -> o3d_status;
    pub fn o3d_io_write_pinhole_camera_intrinsic(
        path: *const c_char,
        intrinsic: *const o3d_pinhole_intrinsic_t,
    ) -> o3d_status;
    pub fn o3d_io_read_pinhole_camera_parameters(
        path: *const c_char,
        out_intrinsic: *mut o3d_pinhole_intrinsic_t,
        out_extrinsic: *mut f64,
    ) -> o3d_status;
    pub fn o3d_io_write_pinhole_camera_parameters(
        path: *const c_char,
        intrinsic: *const o3d_pinhole_intrinsic_t,
        extrinsic: *const f64,
    ) -> o3d_status;
    pub fn o3d_io_read_pinhole_camera_trajectory(
        out: *mut *mut o3d_camera_trajectory_t,
        path: *const c_char,
        format: *const c_char,
    ) -> o3d_status;
    pub fn o3d_io_write_pinhole_camera_trajectory(
        path: *const c_char,
        trajectory: *const o3d_camera_trajectory_t,
        format: *const c_char,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// registration.h
// ---------------------------------------------------------------------------------------------

pub const O3D_ESTIMATION_POINT_TO_POINT: i32 = 0;
pub const O3D_ESTIMATION_POINT_TO_PLANE: i32 = 1;
pub const O3D_ESTIMATION_COLORED: i32 = 2;
pub const O3D_ESTIMATION_GENERALIZED: i32 = 3;
pub const O3D_ESTIMATION_SYMMETRIC: i32 = 4;

pub const O3D_KERNEL_L2: i32 = 0;
pub const O3D_KERNEL_L1: i32 = 1;
pub const O3D_KERNEL_HUBER: i32 = 2;
pub const O3D_KERNEL_CAUCHY: i32 = 3;
pub const O3D_KERNEL_GM: i32 = 4;
pub const O3D_KERNEL_TUKEY: i32 = 5;

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
    pub kernel: i32,
    pub kernel_k: f64,
    pub lambda_geometric: f64,
    pub epsilon: f64,
}
pub type o3d_icp_options_t = o3d_icp_options;

/// Opaque registration result (`o3d_registration_result_t`).
#[repr(C)]
pub struct o3d_registration_result {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_registration_result_t = o3d_registration_result;

pub const O3D_CHECKER_EDGE_LENGTH: i32 = 0;
pub const O3D_CHECKER_DISTANCE: i32 = 1;
pub const O3D_CHECKER_NORMAL: i32 = 2;

/// Correspondence checker (`o3d_correspondence_checker_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct o3d_correspondence_checker {
    pub struct_size: u32,
    pub kind: i32,
    pub threshold: f64,
}
pub type o3d_correspondence_checker_t = o3d_correspondence_checker;

/// RANSAC options (`o3d_ransac_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct o3d_ransac_options {
    pub struct_size: u32,
    pub estimation: i32,
    pub with_scaling: i32,
    pub ransac_n: i32,
    pub max_iteration: i32,
    pub confidence: f64,
    pub mutual_filter: i32,
    pub use_seed: i32,
    pub seed: u64,
    pub num_threads: i32,
    pub progress: o3d_progress_callback,
    pub user_data: *mut c_void,
}
pub type o3d_ransac_options_t = o3d_ransac_options;

/// Fast Global Registration options (`o3d_fgr_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct o3d_fgr_options {
    pub struct_size: u32,
    pub division_factor: f64,
    pub use_absolute_scale: i32,
    pub decrease_mu: i32,
    pub maximum_correspondence_distance: f64,
    pub iteration_number: i32,
    pub tuple_scale: f64,
    pub maximum_tuple_count: i32,
    pub tuple_test: i32,
    pub use_seed: i32,
    pub seed: u64,
    pub num_threads: i32,
    pub progress: o3d_progress_callback,
    pub user_data: *mut c_void,
}
pub type o3d_fgr_options_t = o3d_fgr_options;

extern "C" {
    pub fn o3d_icp_options_init(opts: *mut o3d_icp_options_t, struct_size: u32) -> o3d_status;
    pub fn o3d_robust_kernel_weight(out: *mut f64, kernel: i32, k: f64, residual: f64) -> o3d_status;

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
    pub fn o3d_registration_result_get_fitness(out: *mut f64, result: *const o3d_registration_result_t) -> o3d_status;
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

    pub fn o3d_correspondence_checker_init(
        checker: *mut o3d_correspondence_checker_t,
        struct_size: u32,
        kind: i32,
    ) -> o3d_status;
    pub fn o3d_correspondence_checker_check(
        checker: *const o3d_correspondence_checker_t,
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        corres: *const i32,
        num_corres: usize,
        transformation: *const f64,
        out_passed: *mut i32,
    ) -> o3d_status;

    pub fn o3d_ransac_options_init(opts: *mut o3d_ransac_options_t, struct_size: u32) -> o3d_status;
    pub fn o3d_random_seed(seed: u64) -> o3d_status;
    pub fn o3d_register_ransac_based_on_feature_matching(
        out: *mut *mut o3d_registration_result_t,
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        source_feature: *const o3d_feature_t,
        target_feature: *const o3d_feature_t,
        max_correspondence_distance: f64,
        checkers: *const o3d_correspondence_checker_t,
        num_checkers: usize,
        opts: *const o3d_ransac_options_t,
    ) -> o3d_status;
    pub fn o3d_register_ransac_based_on_correspondence(
        out: *mut *mut o3d_registration_result_t,
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        corres: *const i32,
        num_corres: usize,
        max_correspondence_distance: f64,
        checkers: *const o3d_correspondence_checker_t,
        num_checkers: usize,
        opts: *const o3d_ransac_options_t,
    ) -> o3d_status;

    pub fn o3d_fgr_options_init(opts: *mut o3d_fgr_options_t, struct_size: u32) -> o3d_status;
    pub fn o3d_register_fgr_based_on_feature_matching(
        out: *mut *mut o3d_registration_result_t,
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        source_feature: *const o3d_feature_t,
        target_feature: *const o3d_feature_t,
        opts: *const o3d_fgr_options_t,
    ) -> o3d_status;
    pub fn o3d_register_fgr_based_on_correspondence(
        out: *mut *mut o3d_registration_result_t,
        source: *const o3d_pointcloud_t,
        target: *const o3d_pointcloud_t,
        corres: *const i32,
        num_corres: usize,
        opts: *const o3d_fgr_options_t,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// posegraph.h
// ---------------------------------------------------------------------------------------------

/// Opaque pose graph (`o3d_pose_graph_t`).
#[repr(C)]
pub struct o3d_pose_graph {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_pose_graph_t = o3d_pose_graph;

/// Pose-graph edge (`o3d_pose_graph_edge_t`): row-major 4x4 transformation and 6x6 information.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct o3d_pose_graph_edge {
    pub struct_size: u32,
    pub source_node_id: i32,
    pub target_node_id: i32,
    pub transformation: [f64; 16],
    pub information: [f64; 36],
    pub uncertain: i32,
    pub confidence: f64,
}
pub type o3d_pose_graph_edge_t = o3d_pose_graph_edge;

pub const O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON: i32 = 0;
pub const O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT: i32 = 1;

/// Global optimization options (`o3d_global_optimization_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct o3d_global_optimization_options {
    pub struct_size: u32,
    pub method: i32,
    pub max_iteration: i32,
    pub min_relative_increment: f64,
    pub min_relative_residual_increment: f64,
    pub min_right_term: f64,
    pub min_residual: f64,
    pub max_iteration_lm: i32,
    pub upper_scale_factor: f64,
    pub lower_scale_factor: f64,
    pub max_correspondence_distance: f64,
    pub edge_prune_threshold: f64,
    pub preference_loop_closure: f64,
    pub reference_node: i32,
    pub num_threads: i32,
    pub progress: o3d_progress_callback,
    pub user_data: *mut c_void,
}
pub type o3d_global_optimization_options_t = o3d_global_optimization_options;

/// What a global optimization did (`o3d_global_optimization_summary_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct o3d_global_optimization_summary {
    pub struct_size: u32,
    pub iterations: i32,
    pub initial_residual: f64,
    pub final_residual: f64,
    pub pruned_edges: i32,
}
pub type o3d_global_optimization_summary_t = o3d_global_optimization_summary;

extern "C" {
    pub fn o3d_pose_graph_edge_init(edge: *mut o3d_pose_graph_edge_t, struct_size: u32) -> o3d_status;
    pub fn o3d_pose_graph_create(out: *mut *mut o3d_pose_graph_t) -> o3d_status;
    pub fn o3d_pose_graph_destroy(graph: *mut o3d_pose_graph_t);
    pub fn o3d_pose_graph_clone(out: *mut *mut o3d_pose_graph_t, graph: *const o3d_pose_graph_t) -> o3d_status;
    pub fn o3d_pose_graph_num_nodes(out: *mut usize, graph: *const o3d_pose_graph_t) -> o3d_status;
    pub fn o3d_pose_graph_num_edges(out: *mut usize, graph: *const o3d_pose_graph_t) -> o3d_status;
    pub fn o3d_pose_graph_add_node(graph: *mut o3d_pose_graph_t, pose: *const f64) -> o3d_status;
    pub fn o3d_pose_graph_get_node(out_pose: *mut f64, graph: *const o3d_pose_graph_t, index: usize) -> o3d_status;
    pub fn o3d_pose_graph_set_node(graph: *mut o3d_pose_graph_t, index: usize, pose: *const f64) -> o3d_status;
    pub fn o3d_pose_graph_add_edge(graph: *mut o3d_pose_graph_t, edge: *const o3d_pose_graph_edge_t) -> o3d_status;
    pub fn o3d_pose_graph_get_edge(
        graph: *const o3d_pose_graph_t,
        index: usize,
        out_edge: *mut o3d_pose_graph_edge_t,
    ) -> o3d_status;
    pub fn o3d_pose_graph_set_edge(
        graph: *mut o3d_pose_graph_t,
        index: usize,
        edge: *const o3d_pose_graph_edge_t,
    ) -> o3d_status;
    pub fn o3d_pose_graph_clear(graph: *mut o3d_pose_graph_t) -> o3d_status;

    pub fn o3d_io_read_pose_graph(out: *mut *mut o3d_pose_graph_t, path: *const c_char) -> o3d_status;
    pub fn o3d_io_write_pose_graph(path: *const c_char, graph: *const o3d_pose_graph_t) -> o3d_status;

    pub fn o3d_global_optimization_options_init(
        opts: *mut o3d_global_optimization_options_t,
        struct_size: u32,
    ) -> o3d_status;
    pub fn o3d_global_optimization(
        graph: *mut o3d_pose_graph_t,
        opts: *const o3d_global_optimization_options_t,
        summary: *mut o3d_global_optimization_summary_t,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// image.h
// ---------------------------------------------------------------------------------------------

/// Opaque 2-D image (`o3d_image_t`).
#[repr(C)]
pub struct o3d_image {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_image_t = o3d_image;

pub const O3D_IMAGE_FILTER_GAUSSIAN3: i32 = 0;
pub const O3D_IMAGE_FILTER_GAUSSIAN5: i32 = 1;
pub const O3D_IMAGE_FILTER_GAUSSIAN7: i32 = 2;
pub const O3D_IMAGE_FILTER_SOBEL3_DX: i32 = 3;
pub const O3D_IMAGE_FILTER_SOBEL3_DY: i32 = 4;

pub const O3D_IMAGE_CONVERT_EQUAL: i32 = 0;
pub const O3D_IMAGE_CONVERT_WEIGHTED: i32 = 1;

extern "C" {
    pub fn o3d_image_create(
        out: *mut *mut o3d_image_t,
        width: i32,
        height: i32,
        num_channels: i32,
        bytes_per_channel: i32,
    ) -> o3d_status;
    pub fn o3d_image_create_from_data(
        out: *mut *mut o3d_image_t,
        width: i32,
        height: i32,
        num_channels: i32,
        bytes_per_channel: i32,
        data: *const u8,
        size: usize,
    ) -> o3d_status;
    pub fn o3d_image_destroy(image: *mut o3d_image_t);
    pub fn o3d_image_clone(out: *mut *mut o3d_image_t, src: *const o3d_image_t) -> o3d_status;

    pub fn o3d_image_width(out: *mut i32, image: *const o3d_image_t) -> o3d_status;
    pub fn o3d_image_height(out: *mut i32, image: *const o3d_image_t) -> o3d_status;
    pub fn o3d_image_num_channels(out: *mut i32, image: *const o3d_image_t) -> o3d_status;
    pub fn o3d_image_bytes_per_channel(out: *mut i32, image: *const o3d_image_t) -> o3d_status;

    pub fn o3d_image_data_view(out_data: *mut *const u8, out_size: *mut usize, image: *const o3d_image_t)
        -> o3d_status;
    pub fn o3d_image_data_mutable_view(
        image: *mut o3d_image_t,
        out_data: *mut *mut u8,
        out_size: *mut usize,
    ) -> o3d_status;
    pub fn o3d_image_get_data(
        image: *const o3d_image_t,
        out: *mut u8,
        capacity: usize,
        out_size: *mut usize,
    ) -> o3d_status;

    pub fn o3d_image_filter(out: *mut *mut o3d_image_t, image: *const o3d_image_t, filter_type: i32) -> o3d_status;
    pub fn o3d_image_downsample(out: *mut *mut o3d_image_t, image: *const o3d_image_t) -> o3d_status;
    pub fn o3d_image_flip_vertical(out: *mut *mut o3d_image_t, image: *const o3d_image_t) -> o3d_status;
    pub fn o3d_image_flip_horizontal(out: *mut *mut o3d_image_t, image: *const o3d_image_t) -> o3d_status;
    pub fn o3d_image_create_float_image(
        out: *mut *mut o3d_image_t,
        image: *const o3d_image_t,
        convert_type: i32,
    ) -> o3d_status;
    pub fn o3d_image_convert_depth_to_float(
        out: *mut *mut o3d_image_t,
        image: *const o3d_image_t,
        depth_scale: f64,
        depth_trunc: f64,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// camera.h
// ---------------------------------------------------------------------------------------------

/// Pinhole camera intrinsic (`o3d_pinhole_intrinsic_t`): a plain value struct with a frozen layout.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct o3d_pinhole_intrinsic {
    pub width: i32,
    pub height: i32,
    pub fx: f64,
    pub fy: f64,
    pub cx: f64,
    pub cy: f64,
}
pub type o3d_pinhole_intrinsic_t = o3d_pinhole_intrinsic;

pub const O3D_INTRINSIC_PRIMESENSE_DEFAULT: i32 = 0;
pub const O3D_INTRINSIC_KINECT2_DEPTH_DEFAULT: i32 = 1;
pub const O3D_INTRINSIC_KINECT2_COLOR_DEFAULT: i32 = 2;

/// Opaque camera trajectory (`o3d_camera_trajectory_t`).
#[repr(C)]
pub struct o3d_camera_trajectory {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_camera_trajectory_t = o3d_camera_trajectory;

extern "C" {
    pub fn o3d_pinhole_intrinsic_set_preset(out: *mut o3d_pinhole_intrinsic_t, preset: i32) -> o3d_status;

    pub fn o3d_camera_trajectory_create(out: *mut *mut o3d_camera_trajectory_t) -> o3d_status;
    pub fn o3d_camera_trajectory_destroy(trajectory: *mut o3d_camera_trajectory_t);
    pub fn o3d_camera_trajectory_size(out_n: *mut usize, trajectory: *const o3d_camera_trajectory_t) -> o3d_status;
    pub fn o3d_camera_trajectory_get(
        trajectory: *const o3d_camera_trajectory_t,
        index: usize,
        out_intrinsic: *mut o3d_pinhole_intrinsic_t,
        out_extrinsic: *mut f64,
    ) -> o3d_status;
    pub fn o3d_camera_trajectory_append(
        trajectory: *mut o3d_camera_trajectory_t,
        intrinsic: *const o3d_pinhole_intrinsic_t,
        extrinsic: *const f64,
    ) -> o3d_status;
    pub fn o3d_camera_trajectory_clear(trajectory: *mut o3d_camera_trajectory_t) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// rgbd.h
// ---------------------------------------------------------------------------------------------

/// Opaque RGB-D image (`o3d_rgbd_image_t`).
#[repr(C)]
pub struct o3d_rgbd_image {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_rgbd_image_t = o3d_rgbd_image;

/// RGBDImage.create_from_color_and_depth options (`o3d_rgbd_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct o3d_rgbd_options {
    pub struct_size: u32,
    pub depth_scale: f64,
    pub depth_trunc: f64,
    pub convert_rgb_to_intensity: i32,
}
pub type o3d_rgbd_options_t = o3d_rgbd_options;

pub const O3D_RGBD_FORMAT_REDWOOD: i32 = 0;
pub const O3D_RGBD_FORMAT_TUM: i32 = 1;
pub const O3D_RGBD_FORMAT_SUN: i32 = 2;
pub const O3D_RGBD_FORMAT_NYU: i32 = 3;

/// PointCloud.create_from_depth_image options (`o3d_depth_to_cloud_options_t`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct o3d_depth_to_cloud_options {
    pub struct_size: u32,
    pub depth_scale: f64,
    pub depth_trunc: f64,
    pub stride: i32,
    pub project_valid_depth_only: i32,
}
pub type o3d_depth_to_cloud_options_t = o3d_depth_to_cloud_options;

extern "C" {
    pub fn o3d_rgbd_options_init(opts: *mut o3d_rgbd_options_t, struct_size: u32) -> o3d_status;
    pub fn o3d_rgbd_image_create_from_color_and_depth(
        out: *mut *mut o3d_rgbd_image_t,
        color: *const o3d_image_t,
        depth: *const o3d_image_t,
        opts: *const o3d_rgbd_options_t,
    ) -> o3d_status;
    pub fn o3d_rgbd_image_create_from_dataset_format(
        out: *mut *mut o3d_rgbd_image_t,
        format: i32,
        color: *const o3d_image_t,
        depth: *const o3d_image_t,
        convert_rgb_to_intensity: i32,
    ) -> o3d_status;
    pub fn o3d_rgbd_image_destroy(rgbd: *mut o3d_rgbd_image_t);
    pub fn o3d_rgbd_image_get_color(out: *mut *mut o3d_image_t, rgbd: *const o3d_rgbd_image_t) -> o3d_status;
    pub fn o3d_rgbd_image_get_depth(out: *mut *mut o3d_image_t, rgbd: *const o3d_rgbd_image_t) -> o3d_status;

    pub fn o3d_depth_to_cloud_options_init(opts: *mut o3d_depth_to_cloud_options_t, struct_size: u32) -> o3d_status;
    pub fn o3d_pointcloud_create_from_depth_image(
        out: *mut *mut o3d_pointcloud_t,
        depth: *const o3d_image_t,
        intrinsic: *const o3d_pinhole_intrinsic_t,
        extrinsic: *const f64,
        opts: *const o3d_depth_to_cloud_options_t,
    ) -> o3d_status;
    pub fn o3d_pointcloud_create_from_rgbd_image(
        out: *mut *mut o3d_pointcloud_t,
        rgbd: *const o3d_rgbd_image_t,
        intrinsic: *const o3d_pinhole_intrinsic_t,
        extrinsic: *const f64,
        project_valid_depth_only: i32,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// trianglemesh.h
// ---------------------------------------------------------------------------------------------

/// Opaque triangle mesh (`o3d_trianglemesh_t`).
#[repr(C)]
pub struct o3d_trianglemesh {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_trianglemesh_t = o3d_trianglemesh;

pub const O3D_MESH_VERTICES: i32 = 0;
pub const O3D_MESH_VERTEX_NORMALS: i32 = 1;
pub const O3D_MESH_VERTEX_COLORS: i32 = 2;
pub const O3D_MESH_TRIANGLE_NORMALS: i32 = 3;
pub const O3D_MESH_TRIANGLE_UVS: i32 = 4;
pub const O3D_MESH_TRIANGLES: i32 = 100;
pub const O3D_MESH_TRIANGLE_MATERIAL_IDS: i32 = 101;

pub const O3D_SIMPLIFICATION_AVERAGE: i32 = 0;
pub const O3D_SIMPLIFICATION_QUADRIC: i32 = 1;

pub const O3D_FILTER_SCOPE_ALL: i32 = 0;
pub const O3D_FILTER_SCOPE_COLOR: i32 = 1;
pub const O3D_FILTER_SCOPE_NORMAL: i32 = 2;
pub const O3D_FILTER_SCOPE_VERTEX: i32 = 3;

extern "C" {
    // Container.
    pub fn o3d_trianglemesh_create(out: *mut *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_destroy(mesh: *mut o3d_trianglemesh_t);
    pub fn o3d_trianglemesh_clone(out: *mut *mut o3d_trianglemesh_t, src: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_clear(mesh: *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_num_vertices(out_n: *mut usize, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_num_triangles(out_n: *mut usize, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_has_array(out: *mut i32, mesh: *const o3d_trianglemesh_t, which: i32) -> o3d_status;

    pub fn o3d_trianglemesh_set_array(
        mesh: *mut o3d_trianglemesh_t,
        which: i32,
        data: *const f64,
        rows: usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_get_array(
        mesh: *const o3d_trianglemesh_t,
        which: i32,
        out: *mut f64,
        capacity: usize,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_array_view(
        mesh: *const o3d_trianglemesh_t,
        which: i32,
        out_data: *mut *const f64,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_array_mutable_view(
        mesh: *mut o3d_trianglemesh_t,
        which: i32,
        out_data: *mut *mut f64,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_set_index_array(
        mesh: *mut o3d_trianglemesh_t,
        which: i32,
        data: *const i32,
        rows: usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_get_index_array(
        mesh: *const o3d_trianglemesh_t,
        which: i32,
        out: *mut i32,
        capacity: usize,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_index_array_view(
        mesh: *const o3d_trianglemesh_t,
        which: i32,
        out_data: *mut *const i32,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_index_array_mutable_view(
        mesh: *mut o3d_trianglemesh_t,
        which: i32,
        out_data: *mut *mut i32,
        out_rows: *mut usize,
    ) -> o3d_status;

    pub fn o3d_trianglemesh_texture_count(out_n: *mut usize, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_get_texture(
        out: *mut *mut o3d_image_t,
        mesh: *const o3d_trianglemesh_t,
        index: usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_add_texture(mesh: *mut o3d_trianglemesh_t, image: *const o3d_image_t) -> o3d_status;
    pub fn o3d_trianglemesh_clear_textures(mesh: *mut o3d_trianglemesh_t) -> o3d_status;

    pub fn o3d_trianglemesh_append(mesh: *mut o3d_trianglemesh_t, other: *const o3d_trianglemesh_t) -> o3d_status;

    // Normals, colors, transforms, bounds.
    pub fn o3d_trianglemesh_compute_vertex_normals(mesh: *mut o3d_trianglemesh_t, normalized: i32) -> o3d_status;
    pub fn o3d_trianglemesh_compute_triangle_normals(mesh: *mut o3d_trianglemesh_t, normalized: i32) -> o3d_status;
    pub fn o3d_trianglemesh_normalize_normals(mesh: *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_paint_uniform_color(mesh: *mut o3d_trianglemesh_t, rgb: *const f64) -> o3d_status;
    pub fn o3d_trianglemesh_transform(mesh: *mut o3d_trianglemesh_t, transform: *const f64) -> o3d_status;
    pub fn o3d_trianglemesh_translate(
        mesh: *mut o3d_trianglemesh_t,
        translation: *const f64,
        relative: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_rotate(
        mesh: *mut o3d_trianglemesh_t,
        rotation: *const f64,
        center: *const f64,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_scale(mesh: *mut o3d_trianglemesh_t, scale: f64, center: *const f64) -> o3d_status;
    pub fn o3d_trianglemesh_get_min_bound(out: *mut f64, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_get_max_bound(out: *mut f64, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_get_center(out: *mut f64, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_get_axis_aligned_bounding_box(
        mesh: *const o3d_trianglemesh_t,
        out_min: *mut f64,
        out_max: *mut f64,
    ) -> o3d_status;

    // Clean-up.
    pub fn o3d_trianglemesh_remove_duplicated_vertices(mesh: *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_remove_duplicated_triangles(mesh: *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_remove_degenerate_triangles(mesh: *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_remove_unreferenced_vertices(mesh: *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_remove_non_manifold_edges(mesh: *mut o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_merge_close_vertices(mesh: *mut o3d_trianglemesh_t, eps: f64) -> o3d_status;

    // Queries.
    pub fn o3d_trianglemesh_get_surface_area(out: *mut f64, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_get_volume(out: *mut f64, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_is_watertight(out: *mut i32, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_is_edge_manifold(
        mesh: *const o3d_trianglemesh_t,
        allow_boundary_edges: i32,
        out: *mut i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_is_vertex_manifold(out: *mut i32, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_is_self_intersecting(out: *mut i32, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_is_orientable(out: *mut i32, mesh: *const o3d_trianglemesh_t) -> o3d_status;
    pub fn o3d_trianglemesh_euler_poincare_characteristic(out: *mut i64, mesh: *const o3d_trianglemesh_t)
        -> o3d_status;
    pub fn o3d_trianglemesh_cluster_connected_triangles(
        mesh: *const o3d_trianglemesh_t,
        out_triangle_clusters: *mut i32,
        out_cluster_n_triangles: *mut i32,
        out_cluster_area: *mut f64,
        capacity: usize,
        out_num_triangles: *mut usize,
        out_num_clusters: *mut usize,
    ) -> o3d_status;

    // Processing.
    pub fn o3d_trianglemesh_sample_points_uniformly(
        out: *mut *mut o3d_pointcloud_t,
        mesh: *const o3d_trianglemesh_t,
        number_of_points: usize,
        use_triangle_normal: i32,
        seed: u64,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_sample_points_poisson_disk(
        out: *mut *mut o3d_pointcloud_t,
        mesh: *const o3d_trianglemesh_t,
        number_of_points: usize,
        init_factor: f64,
        use_triangle_normal: i32,
        seed: u64,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_simplify_vertex_clustering(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        voxel_size: f64,
        contraction: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_simplify_quadric_decimation(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        target_number_of_triangles: usize,
        maximum_error: f64,
        boundary_weight: f64,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_filter_smooth_simple(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        number_of_iterations: i32,
        filter_scope: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_filter_smooth_laplacian(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        number_of_iterations: i32,
        lambda_filter: f64,
        filter_scope: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_filter_smooth_taubin(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        number_of_iterations: i32,
        lambda_filter: f64,
        mu: f64,
        filter_scope: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_subdivide_midpoint(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        number_of_iterations: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_subdivide_loop(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        number_of_iterations: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_crop_aabb(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        min_bound: *const f64,
        max_bound: *const f64,
    ) -> o3d_status;

    // Primitives.
    pub fn o3d_trianglemesh_create_box(
        out: *mut *mut o3d_trianglemesh_t,
        width: f64,
        height: f64,
        depth: f64,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_create_sphere(
        out: *mut *mut o3d_trianglemesh_t,
        radius: f64,
        resolution: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_create_cylinder(
        out: *mut *mut o3d_trianglemesh_t,
        radius: f64,
        height: f64,
        resolution: i32,
        split: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_create_cone(
        out: *mut *mut o3d_trianglemesh_t,
        radius: f64,
        height: f64,
        resolution: i32,
        split: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_create_torus(
        out: *mut *mut o3d_trianglemesh_t,
        torus_radius: f64,
        tube_radius: f64,
        radial_resolution: i32,
        tubular_resolution: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_create_arrow(
        out: *mut *mut o3d_trianglemesh_t,
        cylinder_radius: f64,
        cone_radius: f64,
        cylinder_height: f64,
        cone_height: f64,
        resolution: i32,
        cylinder_split: i32,
        cone_split: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_create_coordinate_frame(
        out: *mut *mut o3d_trianglemesh_t,
        size: f64,
        origin: *const f64,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_create_tetrahedron(out: *mut *mut o3d_trianglemesh_t, radius: f64) -> o3d_status;
    pub fn o3d_trianglemesh_create_octahedron(out: *mut *mut o3d_trianglemesh_t, radius: f64) -> o3d_status;
    pub fn o3d_trianglemesh_create_icosahedron(out: *mut *mut o3d_trianglemesh_t, radius: f64) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// boundingbox.h
// ---------------------------------------------------------------------------------------------

/// Oriented bounding box (`o3d_obb_t`, frozen layout): centre, row-major rotation whose column k is
/// the direction of `extent[k]`, full edge lengths.
#[repr(C)]
#[allow(non_snake_case)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct o3d_obb {
    pub center: [f64; 3],
    pub R: [f64; 9],
    pub extent: [f64; 3],
}
pub type o3d_obb_t = o3d_obb;

extern "C" {
    pub fn o3d_obb_create_from_points(out: *mut o3d_obb_t, xyz: *const f64, n: usize, robust: i32) -> o3d_status;
    pub fn o3d_obb_create_from_axis_aligned_bounding_box(
        out: *mut o3d_obb_t,
        min_bound: *const f64,
        max_bound: *const f64,
    ) -> o3d_status;
    pub fn o3d_obb_get_box_points(out: *mut f64, obb: *const o3d_obb_t) -> o3d_status;
    pub fn o3d_obb_get_point_indices_within(
        obb: *const o3d_obb_t,
        xyz: *const f64,
        n: usize,
        out_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_get_oriented_bounding_box(
        pc: *const o3d_pointcloud_t,
        robust: i32,
        out: *mut o3d_obb_t,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_get_oriented_bounding_box(
        mesh: *const o3d_trianglemesh_t,
        robust: i32,
        out: *mut o3d_obb_t,
    ) -> o3d_status;
    pub fn o3d_pointcloud_crop_obb(
        out: *mut *mut o3d_pointcloud_t,
        pc: *const o3d_pointcloud_t,
        obb: *const o3d_obb_t,
        invert: i32,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_crop_obb(
        out: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        obb: *const o3d_obb_t,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// hull.h
// ---------------------------------------------------------------------------------------------

extern "C" {
    pub fn o3d_pointcloud_compute_convex_hull(
        out_mesh: *mut *mut o3d_trianglemesh_t,
        pc: *const o3d_pointcloud_t,
        joggle_inputs: i32,
        out_point_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_trianglemesh_compute_convex_hull(
        out_mesh: *mut *mut o3d_trianglemesh_t,
        mesh: *const o3d_trianglemesh_t,
        joggle_inputs: i32,
        out_point_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_pointcloud_hidden_point_removal(
        out_mesh: *mut *mut o3d_trianglemesh_t,
        pc: *const o3d_pointcloud_t,
        camera_location: *const f64,
        radius: f64,
        out_point_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// lineset.h
// ---------------------------------------------------------------------------------------------

/// Opaque line set (`o3d_lineset_t`).
#[repr(C)]
pub struct o3d_lineset {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_lineset_t = o3d_lineset;

pub const O3D_LINESET_POINTS: i32 = 0;
pub const O3D_LINESET_COLORS: i32 = 1;

extern "C" {
    pub fn o3d_lineset_create(out: *mut *mut o3d_lineset_t) -> o3d_status;
    pub fn o3d_lineset_destroy(lineset: *mut o3d_lineset_t);
    pub fn o3d_lineset_clone(out: *mut *mut o3d_lineset_t, src: *const o3d_lineset_t) -> o3d_status;
    pub fn o3d_lineset_num_points(out_n: *mut usize, lineset: *const o3d_lineset_t) -> o3d_status;
    pub fn o3d_lineset_num_lines(out_n: *mut usize, lineset: *const o3d_lineset_t) -> o3d_status;
    pub fn o3d_lineset_set_array(lineset: *mut o3d_lineset_t, which: i32, data: *const f64, rows: usize) -> o3d_status;
    pub fn o3d_lineset_get_array(
        lineset: *const o3d_lineset_t,
        which: i32,
        out: *mut f64,
        capacity: usize,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_lineset_array_view(
        lineset: *const o3d_lineset_t,
        which: i32,
        out_data: *mut *const f64,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_lineset_set_lines(lineset: *mut o3d_lineset_t, data: *const i32, rows: usize) -> o3d_status;
    pub fn o3d_lineset_get_lines(
        lineset: *const o3d_lineset_t,
        out: *mut i32,
        capacity: usize,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_lineset_lines_view(
        lineset: *const o3d_lineset_t,
        out_data: *mut *const i32,
        out_rows: *mut usize,
    ) -> o3d_status;
    pub fn o3d_lineset_paint_uniform_color(lineset: *mut o3d_lineset_t, rgb: *const f64) -> o3d_status;
    pub fn o3d_lineset_transform(lineset: *mut o3d_lineset_t, transform: *const f64) -> o3d_status;

    pub fn o3d_lineset_create_from_point_cloud_correspondences(
        out: *mut *mut o3d_lineset_t,
        cloud0: *const o3d_pointcloud_t,
        cloud1: *const o3d_pointcloud_t,
        pairs: *const i32,
        n_pairs: usize,
    ) -> o3d_status;
    pub fn o3d_lineset_create_from_oriented_bounding_box(
        out: *mut *mut o3d_lineset_t,
        obb: *const o3d_obb_t,
    ) -> o3d_status;
    pub fn o3d_lineset_create_from_axis_aligned_bounding_box(
        out: *mut *mut o3d_lineset_t,
        min_bound: *const f64,
        max_bound: *const f64,
    ) -> o3d_status;
    pub fn o3d_lineset_create_from_triangle_mesh(
        out: *mut *mut o3d_lineset_t,
        mesh: *const o3d_trianglemesh_t,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// voxelgrid.h
// ---------------------------------------------------------------------------------------------

/// Opaque voxel grid (`o3d_voxelgrid_t`).
#[repr(C)]
pub struct o3d_voxelgrid {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_voxelgrid_t = o3d_voxelgrid;

extern "C" {
    pub fn o3d_voxelgrid_create_from_point_cloud(
        out: *mut *mut o3d_voxelgrid_t,
        pc: *const o3d_pointcloud_t,
        voxel_size: f64,
    ) -> o3d_status;
    pub fn o3d_voxelgrid_create_from_point_cloud_within_bounds(
        out: *mut *mut o3d_voxelgrid_t,
        pc: *const o3d_pointcloud_t,
        voxel_size: f64,
        min_bound: *const f64,
        max_bound: *const f64,
    ) -> o3d_status;
    pub fn o3d_voxelgrid_create_from_triangle_mesh(
        out: *mut *mut o3d_voxelgrid_t,
        mesh: *const o3d_trianglemesh_t,
        voxel_size: f64,
    ) -> o3d_status;
    pub fn o3d_voxelgrid_destroy(grid: *mut o3d_voxelgrid_t);
    pub fn o3d_voxelgrid_get_voxel_size(out: *mut f64, grid: *const o3d_voxelgrid_t) -> o3d_status;
    pub fn o3d_voxelgrid_get_origin(out: *mut f64, grid: *const o3d_voxelgrid_t) -> o3d_status;
    pub fn o3d_voxelgrid_num_voxels(out_n: *mut usize, grid: *const o3d_voxelgrid_t) -> o3d_status;
    pub fn o3d_voxelgrid_get_voxels(
        grid: *const o3d_voxelgrid_t,
        out_grid_index: *mut i32,
        out_colors: *mut f64,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
    pub fn o3d_voxelgrid_get_voxel(out_index: *mut i32, grid: *const o3d_voxelgrid_t, point: *const f64) -> o3d_status;
    pub fn o3d_voxelgrid_check_if_included(
        grid: *const o3d_voxelgrid_t,
        xyz: *const f64,
        n: usize,
        out_included: *mut i32,
    ) -> o3d_status;
}

// ---------------------------------------------------------------------------------------------
// octree.h
// ---------------------------------------------------------------------------------------------

/// Opaque octree (`o3d_octree_t`).
#[repr(C)]
pub struct o3d_octree {
    _private: [u8; 0],
    _marker: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}
pub type o3d_octree_t = o3d_octree;

/// Where an octree node sits (`o3d_octree_node_info_t`, frozen layout).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct o3d_octree_node_info {
    pub origin: [f64; 3],
    pub size: f64,
    pub depth: i32,
    pub child_index: i32,
}
pub type o3d_octree_node_info_t = o3d_octree_node_info;

extern "C" {
    pub fn o3d_octree_create(out: *mut *mut o3d_octree_t, max_depth: i32) -> o3d_status;
    pub fn o3d_octree_destroy(octree: *mut o3d_octree_t);
    pub fn o3d_octree_convert_from_point_cloud(
        octree: *mut o3d_octree_t,
        pc: *const o3d_pointcloud_t,
        size_expand: f64,
    ) -> o3d_status;
    pub fn o3d_octree_get_root(
        octree: *const o3d_octree_t,
        out_origin: *mut f64,
        out_size: *mut f64,
        out_max_depth: *mut i32,
    ) -> o3d_status;
    pub fn o3d_octree_num_leaf_nodes(out_n: *mut usize, octree: *const o3d_octree_t) -> o3d_status;
    pub fn o3d_octree_locate_leaf_node(
        octree: *const o3d_octree_t,
        point: *const f64,
        out_found: *mut i32,
        out_info: *mut o3d_octree_node_info_t,
        out_color: *mut f64,
        out_indices: *mut i32,
        capacity: usize,
        out_n: *mut usize,
    ) -> o3d_status;
}
