//! Layout of every `#[repr(C)]` struct: against values computed by hand from the headers, against a
//! C compiler (when one is available: `$CC` or `cc`), and against the library itself (each
//! `o3d_*_init` must accept `size_of::<T>()` as `struct_size`).
use std::mem::{align_of, offset_of, size_of};
use std::path::PathBuf;
use std::process::Command;

use o3d_sys::*;

/// (C expression, value computed from the Rust declarations, value computed by hand on LP64).
fn rust_layout() -> Vec<(&'static str, usize, usize)> {
    vec![
        ("sizeof(o3d_search_param_t)", size_of::<o3d_search_param_t>(), 24),
        ("_Alignof(o3d_search_param_t)", align_of::<o3d_search_param_t>(), 8),
        ("offsetof(o3d_search_param_t, struct_size)", offset_of!(o3d_search_param_t, struct_size), 0),
        ("offsetof(o3d_search_param_t, kind)", offset_of!(o3d_search_param_t, kind), 4),
        ("offsetof(o3d_search_param_t, knn)", offset_of!(o3d_search_param_t, knn), 8),
        ("offsetof(o3d_search_param_t, radius)", offset_of!(o3d_search_param_t, radius), 16),
        ("sizeof(o3d_read_options_t)", size_of::<o3d_read_options_t>(), 12),
        ("_Alignof(o3d_read_options_t)", align_of::<o3d_read_options_t>(), 4),
        ("offsetof(o3d_read_options_t, struct_size)", offset_of!(o3d_read_options_t, struct_size), 0),
        ("offsetof(o3d_read_options_t, remove_nan_points)", offset_of!(o3d_read_options_t, remove_nan_points), 4),
        (
            "offsetof(o3d_read_options_t, remove_infinite_points)",
            offset_of!(o3d_read_options_t, remove_infinite_points),
            8,
        ),
        ("sizeof(o3d_write_options_t)", size_of::<o3d_write_options_t>(), 12),
        ("_Alignof(o3d_write_options_t)", align_of::<o3d_write_options_t>(), 4),
        ("offsetof(o3d_write_options_t, struct_size)", offset_of!(o3d_write_options_t, struct_size), 0),
        ("offsetof(o3d_write_options_t, write_ascii)", offset_of!(o3d_write_options_t, write_ascii), 4),
        ("offsetof(o3d_write_options_t, compressed)", offset_of!(o3d_write_options_t, compressed), 8),
        ("sizeof(o3d_icp_options_t)", size_of::<o3d_icp_options_t>(), 88),
        ("_Alignof(o3d_icp_options_t)", align_of::<o3d_icp_options_t>(), 8),
        ("offsetof(o3d_icp_options_t, struct_size)", offset_of!(o3d_icp_options_t, struct_size), 0),
        ("offsetof(o3d_icp_options_t, estimation)", offset_of!(o3d_icp_options_t, estimation), 4),
        ("offsetof(o3d_icp_options_t, with_scaling)", offset_of!(o3d_icp_options_t, with_scaling), 8),
        ("offsetof(o3d_icp_options_t, relative_fitness)", offset_of!(o3d_icp_options_t, relative_fitness), 16),
        ("offsetof(o3d_icp_options_t, relative_rmse)", offset_of!(o3d_icp_options_t, relative_rmse), 24),
        ("offsetof(o3d_icp_options_t, max_iteration)", offset_of!(o3d_icp_options_t, max_iteration), 32),
        ("offsetof(o3d_icp_options_t, num_threads)", offset_of!(o3d_icp_options_t, num_threads), 36),
        ("offsetof(o3d_icp_options_t, progress)", offset_of!(o3d_icp_options_t, progress), 40),
        ("offsetof(o3d_icp_options_t, user_data)", offset_of!(o3d_icp_options_t, user_data), 48),
        ("offsetof(o3d_icp_options_t, kernel)", offset_of!(o3d_icp_options_t, kernel), 56),
        ("offsetof(o3d_icp_options_t, kernel_k)", offset_of!(o3d_icp_options_t, kernel_k), 64),
        ("offsetof(o3d_icp_options_t, lambda_geometric)", offset_of!(o3d_icp_options_t, lambda_geometric), 72),
        ("offsetof(o3d_icp_options_t, epsilon)", offset_of!(o3d_icp_options_t, epsilon), 80),
        ("sizeof(o3d_correspondence_checker_t)", size_of::<o3d_correspondence_checker_t>(), 16),
        ("_Alignof(o3d_correspondence_checker_t)", align_of::<o3d_correspondence_checker_t>(), 8),
        (
            "offsetof(o3d_correspondence_checker_t, struct_size)",
            offset_of!(o3d_correspondence_checker_t, struct_size),
            0,
        ),
        ("offsetof(o3d_correspondence_checker_t, kind)", offset_of!(o3d_correspondence_checker_t, kind), 4),
        ("offsetof(o3d_correspondence_checker_t, threshold)", offset_of!(o3d_correspondence_checker_t, threshold), 8),
        ("sizeof(o3d_ransac_options_t)", size_of::<o3d_ransac_options_t>(), 72),
        ("_Alignof(o3d_ransac_options_t)", align_of::<o3d_ransac_options_t>(), 8),
        ("offsetof(o3d_ransac_options_t, struct_size)", offset_of!(o3d_ransac_options_t, struct_size), 0),
        ("offsetof(o3d_ransac_options_t, estimation)", offset_of!(o3d_ransac_options_t, estimation), 4),
        ("offsetof(o3d_ransac_options_t, with_scaling)", offset_of!(o3d_ransac_options_t, with_scaling), 8),
        ("offsetof(o3d_ransac_options_t, ransac_n)", offset_of!(o3d_ransac_options_t, ransac_n), 12),
        ("offsetof(o3d_ransac_options_t, max_iteration)", offset_of!(o3d_ransac_options_t, max_iteration), 16),
        ("offsetof(o3d_ransac_options_t, confidence)", offset_of!(o3d_ransac_options_t, confidence), 24),
        ("offsetof(o3d_ransac_options_t, mutual_filter)", offset_of!(o3d_ransac_options_t, mutual_filter), 32),
        ("offsetof(o3d_ransac_options_t, use_seed)", offset_of!(o3d_ransac_options_t, use_seed), 36),
        ("offsetof(o3d_ransac_options_t, seed)", offset_of!(o3d_ransac_options_t, seed), 40),
        ("offsetof(o3d_ransac_options_t, num_threads)", offset_of!(o3d_ransac_options_t, num_threads), 48),
        ("offsetof(o3d_ransac_options_t, progress)", offset_of!(o3d_ransac_options_t, progress), 56),
        ("offsetof(o3d_ransac_options_t, user_data)", offset_of!(o3d_ransac_options_t, user_data), 64),
        ("sizeof(o3d_fgr_options_t)", size_of::<o3d_fgr_options_t>(), 96),
        ("_Alignof(o3d_fgr_options_t)", align_of::<o3d_fgr_options_t>(), 8),
        ("offsetof(o3d_fgr_options_t, struct_size)", offset_of!(o3d_fgr_options_t, struct_size), 0),
        ("offsetof(o3d_fgr_options_t, division_factor)", offset_of!(o3d_fgr_options_t, division_factor), 8),
        ("offsetof(o3d_fgr_options_t, use_absolute_scale)", offset_of!(o3d_fgr_options_t, use_absolute_scale), 16),
        ("offsetof(o3d_fgr_options_t, decrease_mu)", offset_of!(o3d_fgr_options_t, decrease_mu), 20),
        (
            "offsetof(o3d_fgr_options_t, maximum_correspondence_distance)",
            offset_of!(o3d_fgr_options_t, maximum_correspondence_distance),
            24,
        ),
        ("offsetof(o3d_fgr_options_t, iteration_number)", offset_of!(o3d_fgr_options_t, iteration_number), 32),
        ("offsetof(o3d_fgr_options_t, tuple_scale)", offset_of!(o3d_fgr_options_t, tuple_scale), 40),
        ("offsetof(o3d_fgr_options_t, maximum_tuple_count)", offset_of!(o3d_fgr_options_t, maximum_tuple_count), 48),
        ("offsetof(o3d_fgr_options_t, tuple_test)", offset_of!(o3d_fgr_options_t, tuple_test), 52),
        ("offsetof(o3d_fgr_options_t, use_seed)", offset_of!(o3d_fgr_options_t, use_seed), 56),
        ("offsetof(o3d_fgr_options_t, seed)", offset_of!(o3d_fgr_options_t, seed), 64),
        ("offsetof(o3d_fgr_options_t, num_threads)", offset_of!(o3d_fgr_options_t, num_threads), 72),
        ("offsetof(o3d_fgr_options_t, progress)", offset_of!(o3d_fgr_options_t, progress), 80),
        ("offsetof(o3d_fgr_options_t, user_data)", offset_of!(o3d_fgr_options_t, user_data), 88),
        ("sizeof(o3d_pose_graph_edge_t)", size_of::<o3d_pose_graph_edge_t>(), 448),
        ("_Alignof(o3d_pose_graph_edge_t)", align_of::<o3d_pose_graph_edge_t>(), 8),
        ("offsetof(o3d_pose_graph_edge_t, struct_size)", offset_of!(o3d_pose_graph_edge_t, struct_size), 0),
        ("offsetof(o3d_pose_graph_edge_t, source_node_id)", offset_of!(o3d_pose_graph_edge_t, source_node_id), 4),
        ("offsetof(o3d_pose_graph_edge_t, target_node_id)", offset_of!(o3d_pose_graph_edge_t, target_node_id), 8),
        ("offsetof(o3d_pose_graph_edge_t, transformation)", offset_of!(o3d_pose_graph_edge_t, transformation), 16),
        ("offsetof(o3d_pose_graph_edge_t, information)", offset_of!(o3d_pose_graph_edge_t, information), 144),
        ("offsetof(o3d_pose_graph_edge_t, uncertain)", offset_of!(o3d_pose_graph_edge_t, uncertain), 432),
        ("offsetof(o3d_pose_graph_edge_t, confidence)", offset_of!(o3d_pose_graph_edge_t, confidence), 440),
        ("sizeof(o3d_global_optimization_options_t)", size_of::<o3d_global_optimization_options_t>(), 120),
        ("_Alignof(o3d_global_optimization_options_t)", align_of::<o3d_global_optimization_options_t>(), 8),
        (
            "offsetof(o3d_global_optimization_options_t, struct_size)",
            offset_of!(o3d_global_optimization_options_t, struct_size),
            0,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, method)",
            offset_of!(o3d_global_optimization_options_t, method),
            4,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, max_iteration)",
            offset_of!(o3d_global_optimization_options_t, max_iteration),
            8,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, min_relative_increment)",
            offset_of!(o3d_global_optimization_options_t, min_relative_increment),
            16,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, min_relative_residual_increment)",
            offset_of!(o3d_global_optimization_options_t, min_relative_residual_increment),
            24,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, min_right_term)",
            offset_of!(o3d_global_optimization_options_t, min_right_term),
            32,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, min_residual)",
            offset_of!(o3d_global_optimization_options_t, min_residual),
            40,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, max_iteration_lm)",
            offset_of!(o3d_global_optimization_options_t, max_iteration_lm),
            48,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, upper_scale_factor)",
            offset_of!(o3d_global_optimization_options_t, upper_scale_factor),
            56,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, lower_scale_factor)",
            offset_of!(o3d_global_optimization_options_t, lower_scale_factor),
            64,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, max_correspondence_distance)",
            offset_of!(o3d_global_optimization_options_t, max_correspondence_distance),
            72,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, edge_prune_threshold)",
            offset_of!(o3d_global_optimization_options_t, edge_prune_threshold),
            80,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, preference_loop_closure)",
            offset_of!(o3d_global_optimization_options_t, preference_loop_closure),
            88,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, reference_node)",
            offset_of!(o3d_global_optimization_options_t, reference_node),
            96,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, num_threads)",
            offset_of!(o3d_global_optimization_options_t, num_threads),
            100,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, progress)",
            offset_of!(o3d_global_optimization_options_t, progress),
            104,
        ),
        (
            "offsetof(o3d_global_optimization_options_t, user_data)",
            offset_of!(o3d_global_optimization_options_t, user_data),
            112,
        ),
        ("sizeof(o3d_global_optimization_summary_t)", size_of::<o3d_global_optimization_summary_t>(), 32),
        ("_Alignof(o3d_global_optimization_summary_t)", align_of::<o3d_global_optimization_summary_t>(), 8),
        (
            "offsetof(o3d_global_optimization_summary_t, struct_size)",
            offset_of!(o3d_global_optimization_summary_t, struct_size),
            0,
        ),
        (
            "offsetof(o3d_global_optimization_summary_t, iterations)",
            offset_of!(o3d_global_optimization_summary_t, iterations),
            4,
        ),
        (
            "offsetof(o3d_global_optimization_summary_t, initial_residual)",
            offset_of!(o3d_global_optimization_summary_t, initial_residual),
            8,
        ),
        (
            "offsetof(o3d_global_optimization_summary_t, final_residual)",
            offset_of!(o3d_global_optimization_summary_t, final_residual),
            16,
        ),
        (
            "offsetof(o3d_global_optimization_summary_t, pruned_edges)",
            offset_of!(o3d_global_optimization_summary_t, pruned_edges),
            24,
        ),
        ("sizeof(o3d_pinhole_intrinsic_t)", size_of::<o3d_pinhole_intrinsic_t>(), 40),
        ("_Alignof(o3d_pinhole_intrinsic_t)", align_of::<o3d_pinhole_intrinsic_t>(), 8),
        ("offsetof(o3d_pinhole_intrinsic_t, width)", offset_of!(o3d_pinhole_intrinsic_t, width), 0),
        ("offsetof(o3d_pinhole_intrinsic_t, height)", offset_of!(o3d_pinhole_intrinsic_t, height), 4),
        ("offsetof(o3d_pinhole_intrinsic_t, fx)", offset_of!(o3d_pinhole_intrinsic_t, fx), 8),
        ("offsetof(o3d_pinhole_intrinsic_t, fy)", offset_of!(o3d_pinhole_intrinsic_t, fy), 16),
        ("offsetof(o3d_pinhole_intrinsic_t, cx)", offset_of!(o3d_pinhole_intrinsic_t, cx), 24),
        ("offsetof(o3d_pinhole_intrinsic_t, cy)", offset_of!(o3d_pinhole_intrinsic_t, cy), 32),
        ("sizeof(o3d_rgbd_options_t)", size_of::<o3d_rgbd_options_t>(), 32),
        ("_Alignof(o3d_rgbd_options_t)", align_of::<o3d_rgbd_options_t>(), 8),
        ("offsetof(o3d_rgbd_options_t, struct_size)", offset_of!(o3d_rgbd_options_t, struct_size), 0),
        ("offsetof(o3d_rgbd_options_t, depth_scale)", offset_of!(o3d_rgbd_options_t, depth_scale), 8),
        ("offsetof(o3d_rgbd_options_t, depth_trunc)", offset_of!(o3d_rgbd_options_t, depth_trunc), 16),
        (
            "offsetof(o3d_rgbd_options_t, convert_rgb_to_intensity)",
            offset_of!(o3d_rgbd_options_t, convert_rgb_to_intensity),
            24,
        ),
        ("sizeof(o3d_depth_to_cloud_options_t)", size_of::<o3d_depth_to_cloud_options_t>(), 32),
        ("_Alignof(o3d_depth_to_cloud_options_t)", align_of::<o3d_depth_to_cloud_options_t>(), 8),
        (
            "offsetof(o3d_depth_to_cloud_options_t, struct_size)",
            offset_of!(o3d_depth_to_cloud_options_t, struct_size),
            0,
        ),
        (
            "offsetof(o3d_depth_to_cloud_options_t, depth_scale)",
            offset_of!(o3d_depth_to_cloud_options_t, depth_scale),
            8,
        ),
        (
            "offsetof(o3d_depth_to_cloud_options_t, depth_trunc)",
            offset_of!(o3d_depth_to_cloud_options_t, depth_trunc),
            16,
        ),
        ("offsetof(o3d_depth_to_cloud_options_t, stride)", offset_of!(o3d_depth_to_cloud_options_t, stride), 24),
        (
            "offsetof(o3d_depth_to_cloud_options_t, project_valid_depth_only)",
            offset_of!(o3d_depth_to_cloud_options_t, project_valid_depth_only),
            28,
        ),
        ("sizeof(o3d_mesh_read_options_t)", size_of::<o3d_mesh_read_options_t>(), 8),
        ("_Alignof(o3d_mesh_read_options_t)", align_of::<o3d_mesh_read_options_t>(), 4),
        ("offsetof(o3d_mesh_read_options_t, struct_size)", offset_of!(o3d_mesh_read_options_t, struct_size), 0),
        (
            "offsetof(o3d_mesh_read_options_t, enable_post_processing)",
            offset_of!(o3d_mesh_read_options_t, enable_post_processing),
            4,
        ),
        ("sizeof(o3d_mesh_write_options_t)", size_of::<o3d_mesh_write_options_t>(), 24),
        ("_Alignof(o3d_mesh_write_options_t)", align_of::<o3d_mesh_write_options_t>(), 4),
        ("offsetof(o3d_mesh_write_options_t, struct_size)", offset_of!(o3d_mesh_write_options_t, struct_size), 0),
        ("offsetof(o3d_mesh_write_options_t, write_ascii)", offset_of!(o3d_mesh_write_options_t, write_ascii), 4),
        ("offsetof(o3d_mesh_write_options_t, compressed)", offset_of!(o3d_mesh_write_options_t, compressed), 8),
        (
            "offsetof(o3d_mesh_write_options_t, write_vertex_normals)",
            offset_of!(o3d_mesh_write_options_t, write_vertex_normals),
            12,
        ),
        (
            "offsetof(o3d_mesh_write_options_t, write_vertex_colors)",
            offset_of!(o3d_mesh_write_options_t, write_vertex_colors),
            16,
        ),
        (
            "offsetof(o3d_mesh_write_options_t, write_triangle_uvs)",
            offset_of!(o3d_mesh_write_options_t, write_triangle_uvs),
            20,
        ),
        ("sizeof(o3d_obb_t)", size_of::<o3d_obb_t>(), 120),
        ("_Alignof(o3d_obb_t)", align_of::<o3d_obb_t>(), 8),
        ("offsetof(o3d_obb_t, center)", offset_of!(o3d_obb_t, center), 0),
        ("offsetof(o3d_obb_t, R)", offset_of!(o3d_obb_t, R), 24),
        ("offsetof(o3d_obb_t, extent)", offset_of!(o3d_obb_t, extent), 96),
        ("sizeof(o3d_octree_node_info_t)", size_of::<o3d_octree_node_info_t>(), 40),
        ("_Alignof(o3d_octree_node_info_t)", align_of::<o3d_octree_node_info_t>(), 8),
        ("offsetof(o3d_octree_node_info_t, origin)", offset_of!(o3d_octree_node_info_t, origin), 0),
        ("offsetof(o3d_octree_node_info_t, size)", offset_of!(o3d_octree_node_info_t, size), 24),
        ("offsetof(o3d_octree_node_info_t, depth)", offset_of!(o3d_octree_node_info_t, depth), 32),
        ("offsetof(o3d_octree_node_info_t, child_index)", offset_of!(o3d_octree_node_info_t, child_index), 36),
        ("sizeof(o3d_odometry_options_t)", size_of::<o3d_odometry_options_t>(), 32),
        ("_Alignof(o3d_odometry_options_t)", align_of::<o3d_odometry_options_t>(), 8),
        ("offsetof(o3d_odometry_options_t, depth_diff_max)", offset_of!(o3d_odometry_options_t, depth_diff_max), 8),
        ("offsetof(o3d_odometry_options_t, depth_min)", offset_of!(o3d_odometry_options_t, depth_min), 16),
        ("offsetof(o3d_odometry_options_t, depth_max)", offset_of!(o3d_odometry_options_t, depth_max), 24),
        ("sizeof(o3d_color_map_rigid_options_t)", size_of::<o3d_color_map_rigid_options_t>(), 64),
        ("_Alignof(o3d_color_map_rigid_options_t)", align_of::<o3d_color_map_rigid_options_t>(), 8),
        (
            "offsetof(o3d_color_map_rigid_options_t, maximum_allowable_depth)",
            offset_of!(o3d_color_map_rigid_options_t, maximum_allowable_depth),
            8,
        ),
        (
            "offsetof(o3d_color_map_rigid_options_t, num_threads)",
            offset_of!(o3d_color_map_rigid_options_t, num_threads),
            44,
        ),
        ("offsetof(o3d_color_map_rigid_options_t, progress)", offset_of!(o3d_color_map_rigid_options_t, progress), 48),
        ("sizeof(o3d_reconstruction_options_t)", size_of::<o3d_reconstruction_options_t>(), 32),
        ("_Alignof(o3d_reconstruction_options_t)", align_of::<o3d_reconstruction_options_t>(), 8),
        ("offsetof(o3d_reconstruction_options_t, resume)", offset_of!(o3d_reconstruction_options_t, resume), 4),
        ("offsetof(o3d_reconstruction_options_t, num_threads)", offset_of!(o3d_reconstruction_options_t, num_threads), 8),
        ("offsetof(o3d_reconstruction_options_t, progress)", offset_of!(o3d_reconstruction_options_t, progress), 16),
        ("offsetof(o3d_reconstruction_options_t, user_data)", offset_of!(o3d_reconstruction_options_t, user_data), 24),
        ("sizeof(o3d_color_map_non_rigid_options_t)", size_of::<o3d_color_map_non_rigid_options_t>(), 80),
        ("_Alignof(o3d_color_map_non_rigid_options_t)", align_of::<o3d_color_map_non_rigid_options_t>(), 8),
        (
            "offsetof(o3d_color_map_non_rigid_options_t, maximum_allowable_depth)",
            offset_of!(o3d_color_map_non_rigid_options_t, maximum_allowable_depth),
            24,
        ),
        (
            "offsetof(o3d_color_map_non_rigid_options_t, user_data)",
            offset_of!(o3d_color_map_non_rigid_options_t, user_data),
            72,
        ),
        ("sizeof(o3d_progress_options_t)", size_of::<o3d_progress_options_t>(), 24),
        ("_Alignof(o3d_progress_options_t)", align_of::<o3d_progress_options_t>(), 8),
        ("offsetof(o3d_progress_options_t, num_threads)", offset_of!(o3d_progress_options_t, num_threads), 4),
        ("offsetof(o3d_progress_options_t, progress)", offset_of!(o3d_progress_options_t, progress), 8),
        ("offsetof(o3d_progress_options_t, user_data)", offset_of!(o3d_progress_options_t, user_data), 16),
        ("sizeof(o3d_poisson_options_t)", size_of::<o3d_poisson_options_t>(), 48),
        ("_Alignof(o3d_poisson_options_t)", align_of::<o3d_poisson_options_t>(), 8),
        ("offsetof(o3d_poisson_options_t, depth)", offset_of!(o3d_poisson_options_t, depth), 4),
        ("offsetof(o3d_poisson_options_t, width)", offset_of!(o3d_poisson_options_t, width), 8),
        ("offsetof(o3d_poisson_options_t, scale)", offset_of!(o3d_poisson_options_t, scale), 16),
        ("offsetof(o3d_poisson_options_t, linear_fit)", offset_of!(o3d_poisson_options_t, linear_fit), 24),
        ("offsetof(o3d_poisson_options_t, num_threads)", offset_of!(o3d_poisson_options_t, num_threads), 28),
        ("offsetof(o3d_poisson_options_t, progress)", offset_of!(o3d_poisson_options_t, progress), 32),
        ("offsetof(o3d_poisson_options_t, user_data)", offset_of!(o3d_poisson_options_t, user_data), 40),
        ("sizeof(o3d_iss_options_t)", size_of::<o3d_iss_options_t>(), 48),
        ("_Alignof(o3d_iss_options_t)", align_of::<o3d_iss_options_t>(), 8),
        ("offsetof(o3d_iss_options_t, salient_radius)", offset_of!(o3d_iss_options_t, salient_radius), 8),
        ("offsetof(o3d_iss_options_t, non_max_radius)", offset_of!(o3d_iss_options_t, non_max_radius), 16),
        ("offsetof(o3d_iss_options_t, gamma_21)", offset_of!(o3d_iss_options_t, gamma_21), 24),
        ("offsetof(o3d_iss_options_t, gamma_32)", offset_of!(o3d_iss_options_t, gamma_32), 32),
        ("offsetof(o3d_iss_options_t, min_neighbors)", offset_of!(o3d_iss_options_t, min_neighbors), 40),
        ("offsetof(o3d_iss_options_t, num_threads)", offset_of!(o3d_iss_options_t, num_threads), 44),
        ("sizeof(o3d_obe_t)", size_of::<o3d_obe_t>(), 120),
        ("_Alignof(o3d_obe_t)", align_of::<o3d_obe_t>(), 8),
        ("offsetof(o3d_obe_t, center)", offset_of!(o3d_obe_t, center), 0),
        ("offsetof(o3d_obe_t, R)", offset_of!(o3d_obe_t, R), 24),
        ("offsetof(o3d_obe_t, radii)", offset_of!(o3d_obe_t, radii), 96),
        ("sizeof(o3d_planar_patch_options_t)", size_of::<o3d_planar_patch_options_t>(), 80),
        ("_Alignof(o3d_planar_patch_options_t)", align_of::<o3d_planar_patch_options_t>(), 8),
        (
            "offsetof(o3d_planar_patch_options_t, normal_variance_threshold_deg)",
            offset_of!(o3d_planar_patch_options_t, normal_variance_threshold_deg),
            8,
        ),
        (
            "offsetof(o3d_planar_patch_options_t, coplanarity_deg)",
            offset_of!(o3d_planar_patch_options_t, coplanarity_deg),
            16,
        ),
        (
            "offsetof(o3d_planar_patch_options_t, outlier_ratio)",
            offset_of!(o3d_planar_patch_options_t, outlier_ratio),
            24,
        ),
        (
            "offsetof(o3d_planar_patch_options_t, min_plane_edge_length)",
            offset_of!(o3d_planar_patch_options_t, min_plane_edge_length),
            32,
        ),
        (
            "offsetof(o3d_planar_patch_options_t, min_num_points)",
            offset_of!(o3d_planar_patch_options_t, min_num_points),
            40,
        ),
        (
            "offsetof(o3d_planar_patch_options_t, search_param)",
            offset_of!(o3d_planar_patch_options_t, search_param),
            48,
        ),
        ("offsetof(o3d_planar_patch_options_t, num_threads)", offset_of!(o3d_planar_patch_options_t, num_threads), 72),
        // Callback pointers are plain (nullable) function pointers.
        ("sizeof(o3d_progress_callback)", size_of::<o3d_progress_callback>(), 8),
        ("sizeof(o3d_log_callback)", size_of::<o3d_log_callback>(), 8),
        ("sizeof(o3d_status)", size_of::<o3d_status>(), 4),
    ]
}

#[test]
#[cfg(all(target_pointer_width = "64", not(windows)))]
fn layout_matches_hand_computed_lp64_values() {
    for (expr, rust, hand) in rust_layout() {
        assert_eq!(rust, hand, "{expr}: Rust gives {rust}, the header gives {hand}");
    }
}

/// Compile and run a C program printing every expression of `rust_layout()`; None without a compiler.
fn c_layout() -> Option<Vec<(String, usize)>> {
    let include = PathBuf::from(env!("O3D_HEADER_DIR"));
    let dir = std::env::temp_dir().join(format!("o3d-sys-layout-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut src = String::from("#include <stdio.h>\n#include <stddef.h>\n#include \"o3d/o3d.h\"\nint main(void) {\n");
    for (expr, _, _) in rust_layout() {
        src += &format!("    printf(\"%s=%zu\\n\", \"{expr}\", (size_t)({expr}));\n");
    }
    src += "    return 0;\n}\n";
    let c_file = dir.join("layout.c");
    let exe = dir.join("layout");
    std::fs::write(&c_file, src).unwrap();
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let compiled = Command::new(&cc).args(["-std=c11", "-I"]).arg(&include).arg(&c_file).arg("-o").arg(&exe).status();
    match compiled {
        Ok(s) if s.success() => {}
        Ok(s) => panic!("{cc} failed ({s}) on the layout probe: do the headers still compile as C11?"),
        Err(e) => {
            eprintln!("note: no C compiler ({cc}: {e}); layout checked against hand-computed values only");
            return None;
        }
    }
    let out = Command::new(&exe).output().unwrap();
    assert!(out.status.success());
    let _ = std::fs::remove_dir_all(&dir);
    Some(
        String::from_utf8(out.stdout)
            .unwrap()
            .lines()
            .map(|l| {
                let (k, v) = l.rsplit_once('=').unwrap();
                (k.to_string(), v.parse().unwrap())
            })
            .collect(),
    )
}

#[test]
fn layout_matches_the_c_compiler() {
    let Some(c) = c_layout() else { return };
    let rust = rust_layout();
    assert_eq!(c.len(), rust.len());
    for ((expr, rust, _), (c_expr, c_value)) in rust.iter().zip(&c) {
        assert_eq!(expr, c_expr);
        assert_eq!(rust, c_value, "{expr}: Rust gives {rust}, C gives {c_value}");
    }
}

fn last_message() -> String {
    unsafe { std::ffi::CStr::from_ptr(o3d_last_error_message()).to_string_lossy().into_owned() }
}

#[test]
fn search_param_init_accepts_rust_size_and_fills_defaults() {
    unsafe {
        let mut p: o3d_search_param_t = std::mem::zeroed();
        let st = o3d_search_param_init(&mut p, size_of::<o3d_search_param_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(p.struct_size as usize, size_of::<o3d_search_param_t>());
        assert_eq!((p.kind, p.knn, p.radius), (O3D_SEARCH_KNN, 30, 0.0));
    }
}

#[test]
fn io_options_init_accepts_rust_sizes_and_fills_defaults() {
    unsafe {
        let mut r: o3d_read_options_t = std::mem::zeroed();
        let st = o3d_read_options_init(&mut r, size_of::<o3d_read_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(r.struct_size as usize, size_of::<o3d_read_options_t>());
        assert_eq!((r.remove_nan_points, r.remove_infinite_points), (0, 0));

        let mut w: o3d_write_options_t = std::mem::zeroed();
        let st = o3d_write_options_init(&mut w, size_of::<o3d_write_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(w.struct_size as usize, size_of::<o3d_write_options_t>());
        assert_eq!((w.write_ascii, w.compressed), (0, 0));
    }
}

#[test]
fn icp_options_init_accepts_rust_size_and_fills_defaults() {
    unsafe {
        let mut i: o3d_icp_options_t = std::mem::zeroed();
        let st = o3d_icp_options_init(&mut i, size_of::<o3d_icp_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(i.struct_size as usize, size_of::<o3d_icp_options_t>());
        assert_eq!((i.estimation, i.with_scaling), (O3D_ESTIMATION_POINT_TO_POINT, 0));
        assert_eq!((i.relative_fitness, i.relative_rmse, i.max_iteration), (1e-6, 1e-6, 30));
        assert_eq!(i.num_threads, 0);
        assert!(i.progress.is_none());
        assert!(i.user_data.is_null());
        assert_eq!((i.kernel, i.kernel_k, i.lambda_geometric, i.epsilon), (O3D_KERNEL_L2, 1.0, 0.968, 1e-3));

        // A size larger than the library knows is refused, with a message.
        let mut big = [0u64; 32];
        let st = o3d_icp_options_init(big.as_mut_ptr().cast(), 256);
        assert_eq!(st, O3D_ERROR_INVALID_ARGUMENT);
        assert_eq!(o3d_last_error_code(), O3D_ERROR_INVALID_ARGUMENT);
        assert!(!last_message().is_empty());
    }
}

#[test]
fn global_registration_options_init_accept_rust_sizes_and_fill_defaults() {
    unsafe {
        let mut r: o3d_ransac_options_t = std::mem::zeroed();
        let st = o3d_ransac_options_init(&mut r, size_of::<o3d_ransac_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(r.struct_size as usize, size_of::<o3d_ransac_options_t>());
        assert_eq!((r.estimation, r.with_scaling, r.ransac_n), (O3D_ESTIMATION_POINT_TO_POINT, 0, 3));
        assert_eq!((r.max_iteration, r.confidence), (100000, 0.999));
        assert_eq!((r.mutual_filter, r.use_seed, r.num_threads), (0, 0, 0));
        assert!(r.progress.is_none() && r.user_data.is_null());

        let mut f: o3d_fgr_options_t = std::mem::zeroed();
        let st = o3d_fgr_options_init(&mut f, size_of::<o3d_fgr_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(f.struct_size as usize, size_of::<o3d_fgr_options_t>());
        assert_eq!((f.division_factor, f.use_absolute_scale, f.decrease_mu), (1.4, 0, 1));
        assert_eq!((f.maximum_correspondence_distance, f.iteration_number), (0.025, 64));
        assert_eq!((f.tuple_scale, f.maximum_tuple_count, f.tuple_test), (0.95, 1000, 1));
        assert_eq!((f.use_seed, f.num_threads), (0, 0));
        assert!(f.progress.is_none() && f.user_data.is_null());

        for (kind, threshold) in [(O3D_CHECKER_EDGE_LENGTH, 0.9), (O3D_CHECKER_DISTANCE, 0.075)] {
            let mut c: o3d_correspondence_checker_t = std::mem::zeroed();
            let st = o3d_correspondence_checker_init(&mut c, size_of::<o3d_correspondence_checker_t>() as u32, kind);
            assert_eq!(st, O3D_OK, "{}", last_message());
            assert_eq!(c, o3d_correspondence_checker_t { struct_size: 16, kind, threshold });
        }
        let mut c: o3d_correspondence_checker_t = std::mem::zeroed();
        let st = o3d_correspondence_checker_init(&mut c, 16, O3D_CHECKER_NORMAL);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert!((c.threshold - 30f64.to_radians()).abs() < 1e-4, "{}", c.threshold);
        assert_eq!(o3d_correspondence_checker_init(&mut c, 16, 99), O3D_ERROR_INVALID_ARGUMENT);
    }
}

#[test]
fn pose_graph_structs_init_accept_rust_sizes_and_fill_defaults() {
    unsafe {
        let mut e: o3d_pose_graph_edge_t = std::mem::zeroed();
        let st = o3d_pose_graph_edge_init(&mut e, size_of::<o3d_pose_graph_edge_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(e.struct_size as usize, size_of::<o3d_pose_graph_edge_t>());
        assert_eq!((e.source_node_id, e.target_node_id, e.uncertain, e.confidence), (0, 0, 0, 1.0));
        for (i, v) in e.transformation.iter().enumerate() {
            assert_eq!(*v, if i % 5 == 0 { 1.0 } else { 0.0 }, "transformation[{i}]");
        }
        for (i, v) in e.information.iter().enumerate() {
            assert_eq!(*v, if i % 7 == 0 { 1.0 } else { 0.0 }, "information[{i}]");
        }

        let mut g: o3d_global_optimization_options_t = std::mem::zeroed();
        let st = o3d_global_optimization_options_init(&mut g, size_of::<o3d_global_optimization_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(g.struct_size as usize, size_of::<o3d_global_optimization_options_t>());
        assert_eq!(
            (g.method, g.max_iteration, g.max_iteration_lm),
            (O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT, 100, 20)
        );
        assert_eq!(
            (g.min_relative_increment, g.min_relative_residual_increment, g.min_right_term, g.min_residual),
            (1e-6, 1e-6, 1e-6, 1e-6)
        );
        assert_eq!((g.upper_scale_factor, g.lower_scale_factor), (2.0 / 3.0, 1.0 / 3.0));
        assert_eq!(
            (g.max_correspondence_distance, g.edge_prune_threshold, g.preference_loop_closure),
            (0.075, 0.25, 1.0)
        );
        assert_eq!((g.reference_node, g.num_threads), (-1, 0));
        assert!(g.progress.is_none() && g.user_data.is_null());
    }
}

#[test]
fn rgbd_and_depth_options_init_accept_rust_sizes_and_fill_defaults() {
    unsafe {
        let mut r: o3d_rgbd_options_t = std::mem::zeroed();
        let st = o3d_rgbd_options_init(&mut r, size_of::<o3d_rgbd_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(r.struct_size as usize, size_of::<o3d_rgbd_options_t>());
        assert_eq!((r.depth_scale, r.depth_trunc, r.convert_rgb_to_intensity), (1000.0, 3.0, 1));

        let mut d: o3d_depth_to_cloud_options_t = std::mem::zeroed();
        let st = o3d_depth_to_cloud_options_init(&mut d, size_of::<o3d_depth_to_cloud_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(d.struct_size as usize, size_of::<o3d_depth_to_cloud_options_t>());
        assert_eq!((d.depth_scale, d.depth_trunc, d.stride, d.project_valid_depth_only), (1000.0, 1000.0, 1, 1));

        let mut o: o3d_odometry_options_t = std::mem::zeroed();
        let st = o3d_odometry_options_init(&mut o, size_of::<o3d_odometry_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(o.struct_size as usize, size_of::<o3d_odometry_options_t>());
        assert_eq!((o.depth_diff_max, o.depth_min, o.depth_max), (0.03, 0.0, 4.0));

        let mut c: o3d_color_map_rigid_options_t = std::mem::zeroed();
        let st = o3d_color_map_rigid_options_init(&mut c, size_of::<o3d_color_map_rigid_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!((c.struct_size as usize, c.maximum_iteration), (size_of::<o3d_color_map_rigid_options_t>(), 300));

        let mut r: o3d_reconstruction_options_t = std::mem::zeroed();
        let st = o3d_reconstruction_options_init(&mut r, size_of::<o3d_reconstruction_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(
            (r.struct_size as usize, r.resume, r.num_threads),
            (size_of::<o3d_reconstruction_options_t>(), 1, 0)
        );

        let mut n: o3d_color_map_non_rigid_options_t = std::mem::zeroed();
        let st = o3d_color_map_non_rigid_options_init(&mut n, size_of::<o3d_color_map_non_rigid_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(
            (n.struct_size as usize, n.number_of_vertical_anchors),
            (size_of::<o3d_color_map_non_rigid_options_t>(), 16)
        );
    }
}

#[test]
fn mesh_io_options_init_accept_rust_sizes_and_fill_defaults() {
    unsafe {
        let mut r: o3d_mesh_read_options_t = std::mem::zeroed();
        let st = o3d_mesh_read_options_init(&mut r, size_of::<o3d_mesh_read_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(r.struct_size as usize, size_of::<o3d_mesh_read_options_t>());
        assert_eq!(r.enable_post_processing, 0);

        let mut w: o3d_mesh_write_options_t = std::mem::zeroed();
        let st = o3d_mesh_write_options_init(&mut w, size_of::<o3d_mesh_write_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(w.struct_size as usize, size_of::<o3d_mesh_write_options_t>());
        assert_eq!((w.write_ascii, w.compressed), (0, 0));
        assert_eq!((w.write_vertex_normals, w.write_vertex_colors, w.write_triangle_uvs), (1, 1, 1));
    }
}

#[test]
fn surface_reconstruction_and_keypoint_options_init_accept_rust_sizes_and_fill_defaults() {
    unsafe {
        let mut p: o3d_progress_options_t = std::mem::zeroed();
        let st = o3d_progress_options_init(&mut p, size_of::<o3d_progress_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!((p.struct_size as usize, p.num_threads), (size_of::<o3d_progress_options_t>(), 0));
        assert!(p.progress.is_none() && p.user_data.is_null());

        let mut s: o3d_poisson_options_t = std::mem::zeroed();
        let st = o3d_poisson_options_init(&mut s, size_of::<o3d_poisson_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(s.struct_size as usize, size_of::<o3d_poisson_options_t>());
        // Open3D's create_from_point_cloud_poisson(depth=8, width=0, scale=1.1, linear_fit=False).
        assert_eq!((s.depth, s.width, s.scale, s.linear_fit, s.num_threads), (8, 0.0, 1.1, 0, 0));
        assert!(s.progress.is_none());

        let mut i: o3d_iss_options_t = std::mem::zeroed();
        let st = o3d_iss_options_init(&mut i, size_of::<o3d_iss_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(i.struct_size as usize, size_of::<o3d_iss_options_t>());
        // Open3D's compute_iss_keypoints(salient_radius=0, non_max_radius=0, gamma_21=0.975, gamma_32=0.975,
        // min_neighbors=5).
        assert_eq!((i.salient_radius, i.non_max_radius, i.gamma_21, i.gamma_32), (0.0, 0.0, 0.975, 0.975));
        assert_eq!((i.min_neighbors, i.num_threads), (5, 0));
    }
}

#[test]
fn planar_patch_options_init_accepts_rust_size_and_fills_defaults() {
    unsafe {
        let mut o: o3d_planar_patch_options_t = std::mem::zeroed();
        let st = o3d_planar_patch_options_init(&mut o, size_of::<o3d_planar_patch_options_t>() as u32);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(o.struct_size as usize, size_of::<o3d_planar_patch_options_t>());
        // Open3D's detect_planar_patches(normal_variance_threshold_deg=60, coplanarity_deg=75, outlier_ratio=0.75,
        // min_plane_edge_length=0, min_num_points=0, search_param=KDTreeSearchParamKNN(30)).
        assert_eq!((o.normal_variance_threshold_deg, o.coplanarity_deg, o.outlier_ratio), (60.0, 75.0, 0.75));
        assert_eq!((o.min_plane_edge_length, o.min_num_points, o.num_threads), (0.0, 0, 0));
        assert_eq!((o.search_param.kind, o.search_param.knn), (O3D_SEARCH_KNN, 30));
        assert_eq!(o.search_param.struct_size as usize, size_of::<o3d_search_param_t>());
    }
}

#[test]
fn intrinsic_preset_fills_the_frozen_struct() {
    unsafe {
        let mut k = o3d_pinhole_intrinsic_t::default();
        let st = o3d_pinhole_intrinsic_set_preset(&mut k, O3D_INTRINSIC_PRIMESENSE_DEFAULT);
        assert_eq!(st, O3D_OK, "{}", last_message());
        assert_eq!(k, o3d_pinhole_intrinsic_t { width: 640, height: 480, fx: 525.0, fy: 525.0, cx: 319.5, cy: 239.5 });
        assert_eq!(o3d_pinhole_intrinsic_set_preset(&mut k, 99), O3D_ERROR_INVALID_ARGUMENT);
    }
}

#[test]
fn version_constants_match_the_library() {
    unsafe {
        assert_eq!(o3d_version_major(), O3D_VERSION_MAJOR);
        assert_eq!(o3d_version_minor(), O3D_VERSION_MINOR);
        assert_eq!(o3d_version_patch(), O3D_VERSION_PATCH);
        let v = std::ffi::CStr::from_ptr(o3d_version()).to_str().unwrap();
        assert_eq!(v, format!("{O3D_VERSION_MAJOR}.{O3D_VERSION_MINOR}.{O3D_VERSION_PATCH}"));
    }
}
