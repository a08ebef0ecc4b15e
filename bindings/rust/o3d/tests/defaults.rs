//! Every options type's `Default` is what the library's `*_init` writes, field by field, and the
//! enums' values are the C constants.
use std::mem::{size_of, MaybeUninit};

use o3d::keypoint::IssOptions;
use o3d::registration::{
    Estimation, FgrOptions, GlobalOptimizationMethod, GlobalOptimizationOptions, IcpOptions, PoseGraphEdge,
    RansacOptions, RobustKernel,
};
use o3d::{io, sys, DepthToCloudOptions, LogLevel, PoissonOptions, ProgressOptions, RgbdOptions, SearchParam};

/// The struct as the C init function fills it.
fn c_init<T>(init: unsafe extern "C" fn(*mut T, u32) -> sys::o3d_status) -> T {
    let mut raw = MaybeUninit::<T>::zeroed();
    // SAFETY: the options structs are plain numbers and nullable pointers; init writes size_of::<T>() bytes.
    unsafe {
        assert_eq!(init(raw.as_mut_ptr(), size_of::<T>() as u32), sys::O3D_OK);
        raw.assume_init()
    }
}

#[test]
fn icp_defaults_are_the_librarys() {
    let c = c_init(sys::o3d_icp_options_init);
    let d = IcpOptions::default();
    assert_eq!(d.estimation as i32, c.estimation);
    assert_eq!(d.with_scaling, c.with_scaling != 0);
    assert_eq!(d.relative_fitness, c.relative_fitness);
    assert_eq!(d.relative_rmse, c.relative_rmse);
    assert_eq!(d.max_iteration as i32, c.max_iteration);
    assert_eq!(d.num_threads as i32, c.num_threads);
    assert_eq!(c.kernel, sys::O3D_KERNEL_L2);
    assert_eq!(d.kernel, RobustKernel::L2);
    assert_eq!(d.lambda_geometric, c.lambda_geometric);
    assert_eq!(d.epsilon, c.epsilon);
    assert_eq!(Estimation::default() as i32, c.estimation);
    assert_eq!(RobustKernel::default(), RobustKernel::L2);
}

#[test]
fn ransac_and_fgr_defaults_are_the_librarys() {
    let c = c_init(sys::o3d_ransac_options_init);
    let d = RansacOptions::default();
    assert_eq!(d.estimation as i32, c.estimation);
    assert_eq!(d.with_scaling, c.with_scaling != 0);
    assert_eq!(d.ransac_n as i32, c.ransac_n);
    assert_eq!(d.max_iteration as i32, c.max_iteration);
    assert_eq!(d.confidence, c.confidence);
    assert_eq!(d.mutual_filter, c.mutual_filter != 0);
    assert_eq!(d.seed.is_some(), c.use_seed != 0);
    assert_eq!(d.num_threads as i32, c.num_threads);

    let c = c_init(sys::o3d_fgr_options_init);
    let d = FgrOptions::default();
    assert_eq!(d.division_factor, c.division_factor);
    assert_eq!(d.use_absolute_scale, c.use_absolute_scale != 0);
    assert_eq!(d.decrease_mu, c.decrease_mu != 0);
    assert_eq!(d.maximum_correspondence_distance, c.maximum_correspondence_distance);
    assert_eq!(d.iteration_number as i32, c.iteration_number);
    assert_eq!(d.tuple_scale, c.tuple_scale);
    assert_eq!(d.maximum_tuple_count as i32, c.maximum_tuple_count);
    assert_eq!(d.tuple_test, c.tuple_test != 0);
    assert_eq!(d.seed.is_some(), c.use_seed != 0);
}

#[test]
fn global_optimization_and_edge_defaults_are_the_librarys() {
    let c = c_init(sys::o3d_global_optimization_options_init);
    let d = GlobalOptimizationOptions::default();
    assert_eq!(d.method as i32, c.method);
    assert_eq!(GlobalOptimizationMethod::default() as i32, c.method);
    assert_eq!(d.max_iteration as i32, c.max_iteration);
    assert_eq!(d.max_iteration_lm as i32, c.max_iteration_lm);
    assert_eq!(d.upper_scale_factor, c.upper_scale_factor);
    assert_eq!(d.lower_scale_factor, c.lower_scale_factor);
    assert_eq!(d.max_correspondence_distance, c.max_correspondence_distance);
    assert_eq!(d.edge_prune_threshold, c.edge_prune_threshold);
    assert_eq!(d.preference_loop_closure, c.preference_loop_closure);
    assert_eq!(d.reference_node.map_or(-1, |n| n as i32), c.reference_node);

    let c = c_init(sys::o3d_pose_graph_edge_init);
    let e = PoseGraphEdge::default();
    assert_eq!((e.source_node_id, e.target_node_id), (c.source_node_id, c.target_node_id));
    assert_eq!(e.transformation.concat(), c.transformation);
    assert_eq!(e.information.concat(), c.information);
    assert_eq!((e.uncertain, e.confidence), (c.uncertain != 0, c.confidence));
    let built = PoseGraphEdge::new(1, 2, e.transformation, e.information, true);
    assert_eq!(built.confidence, c.confidence);
}

#[test]
fn rgbd_io_and_search_defaults_are_the_librarys() {
    let c = c_init(sys::o3d_rgbd_options_init);
    let d = RgbdOptions::default();
    assert_eq!((d.depth_scale, d.depth_trunc), (c.depth_scale, c.depth_trunc));
    assert_eq!(d.convert_rgb_to_intensity, c.convert_rgb_to_intensity != 0);

    let c = c_init(sys::o3d_depth_to_cloud_options_init);
    let d = DepthToCloudOptions::default();
    assert_eq!((d.depth_scale, d.depth_trunc, d.stride), (c.depth_scale, c.depth_trunc, c.stride));
    assert_eq!(d.project_valid_depth_only, c.project_valid_depth_only != 0);

    let c = c_init(sys::o3d_mesh_write_options_init);
    let d = io::MeshWriteOptions::default();
    assert_eq!((d.write_ascii, d.compressed), (c.write_ascii != 0, c.compressed != 0));
    assert_eq!(d.write_vertex_normals, c.write_vertex_normals != 0);
    assert_eq!(d.write_vertex_colors, c.write_vertex_colors != 0);
    assert_eq!(d.write_triangle_uvs, c.write_triangle_uvs != 0);

    let c = c_init(sys::o3d_search_param_init);
    assert_eq!(c.kind, sys::O3D_SEARCH_KNN);
    assert_eq!(SearchParam::default(), SearchParam::Knn { knn: c.knn as usize });
}

#[test]
fn surface_reconstruction_and_keypoint_defaults_are_the_librarys() {
    let c = c_init(sys::o3d_poisson_options_init);
    let d = PoissonOptions::default();
    assert_eq!((d.depth as i32, d.width, d.scale), (c.depth, c.width, c.scale));
    assert_eq!((d.linear_fit, d.num_threads as i32), (c.linear_fit != 0, c.num_threads));
    // Open3D's create_from_point_cloud_poisson(depth=8, width=0, scale=1.1, linear_fit=False).
    assert_eq!((d.depth, d.width, d.scale, d.linear_fit), (8, 0.0, 1.1, false));

    let c = c_init(sys::o3d_progress_options_init);
    assert_eq!(ProgressOptions::default().num_threads as i32, c.num_threads);

    let c = c_init(sys::o3d_iss_options_init);
    let d = IssOptions::default();
    assert_eq!((d.salient_radius, d.non_max_radius), (c.salient_radius, c.non_max_radius));
    assert_eq!((d.gamma_21, d.gamma_32), (c.gamma_21, c.gamma_32));
    assert_eq!((d.min_neighbors as i32, d.num_threads as i32), (c.min_neighbors, c.num_threads));
    assert_eq!((d.gamma_21, d.gamma_32, d.min_neighbors), (0.975, 0.975, 5));
}

#[test]
fn enum_values_are_the_c_constants() {
    assert_eq!(Estimation::PointToPlane as i32, sys::O3D_ESTIMATION_POINT_TO_PLANE);
    assert_eq!(Estimation::Symmetric as i32, sys::O3D_ESTIMATION_SYMMETRIC);
    assert_eq!(GlobalOptimizationMethod::GaussNewton as i32, sys::O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON);
    assert_eq!(LogLevel::Warning as i32, sys::O3D_LOG_WARNING);
    assert_eq!(LogLevel::Debug as i32, sys::O3D_LOG_DEBUG);
    assert_eq!(o3d::RgbdFormat::Nyu as i32, sys::O3D_RGBD_FORMAT_NYU);
    assert_eq!(o3d::MeshArray::TriangleNormals as i32, sys::O3D_MESH_TRIANGLE_NORMALS);
    assert_eq!(o3d::FilterScope::Vertex as i32, sys::O3D_FILTER_SCOPE_VERTEX);
    assert_eq!(o3d::ImageFilter::Sobel3Dy as i32, sys::O3D_IMAGE_FILTER_SOBEL3_DY);
}
