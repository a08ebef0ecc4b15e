//! The bindings bindgen generated match the library at run time: calls through them (outputs
//! first, `size_t` as `usize`, macro constants as `i32`) give what the headers promise, and the
//! generated struct sizes are the ones each `*_init` accepts.
use std::mem::size_of;
use std::ptr;

use o3d_sys::*;

#[test]
fn calls_through_the_generated_declarations_work() {
    unsafe {
        let v = std::ffi::CStr::from_ptr(o3d_version()).to_str().unwrap();
        assert_eq!(v, format!("{O3D_VERSION_MAJOR}.{O3D_VERSION_MINOR}.{O3D_VERSION_PATCH}"));

        let mut pc: *mut o3d_pointcloud_t = ptr::null_mut();
        assert_eq!(o3d_pointcloud_create(&mut pc), O3D_OK);
        assert!(!pc.is_null());
        let points = [[0.0f64, 1.0, 2.0], [3.0, 4.0, 5.0]];
        assert_eq!(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, points.as_ptr().cast(), 2), O3D_OK);
        let (mut rows, mut cols) = (0usize, 0usize);
        assert_eq!(o3d_pointcloud_array_shape(&mut rows, &mut cols, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
        assert_eq!((rows, cols), (2, 3));
        assert_eq!(o3d_pointcloud_array_shape(&mut rows, &mut cols, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
        assert_eq!(cols, 9);
        let mut out = [[0.0f64; 3]; 2];
        let mut n = 0usize;
        // A capacity of one row is too small: the needed count comes back.
        let st = o3d_pointcloud_get_array(out.as_mut_ptr().cast(), 1, &mut n, pc, O3D_POINTCLOUD_POINTS);
        assert_eq!((st, n), (O3D_ERROR_BUFFER_TOO_SMALL, 2));
        assert_eq!(o3d_pointcloud_get_array(out.as_mut_ptr().cast(), 2, &mut n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
        assert_eq!(out, points);
        let mut has = -1;
        assert_eq!(o3d_pointcloud_has_array(&mut has, pc, O3D_POINTCLOUD_NORMALS), O3D_OK);
        assert_eq!(has, 0);
        assert_eq!(o3d_pointcloud_has_array(&mut has, pc, 12345), O3D_ERROR_INVALID_ARGUMENT);
        o3d_pointcloud_destroy(pc);
    }
}

#[test]
fn generated_struct_sizes_are_accepted_by_their_init() {
    unsafe {
        let mut p = o3d_search_param_t::default();
        assert_eq!(o3d_search_param_init(&mut p, size_of::<o3d_search_param_t>() as u32), O3D_OK);
        assert_eq!(p.struct_size as usize, size_of::<o3d_search_param_t>());
        let mut icp = o3d_icp_options_t::default();
        assert_eq!(o3d_icp_options_init(&mut icp, size_of::<o3d_icp_options_t>() as u32), O3D_OK);
        assert_eq!(icp.struct_size as usize, size_of::<o3d_icp_options_t>());
        assert_eq!(icp.estimation, O3D_ESTIMATION_POINT_TO_POINT);
        let mut r = o3d_ransac_options_t::default();
        assert_eq!(o3d_ransac_options_init(&mut r, size_of::<o3d_ransac_options_t>() as u32), O3D_OK);
    }
}
