//! Figure 1 of the Open3D paper on the real scan, and ICP on the real pair against Open3D 0.20's
//! numbers (the same ones as tests/core/registration_reference_test.cpp).
mod common;

use common::*;
use o3d::io::{self, ReadOptions, WriteOptions};
use o3d::registration::{self, Estimation, IcpOptions, IDENTITY};
use o3d::SearchParam;

#[test]
fn figure1_on_cloud_bin_0() {
    let Some(input) = data_file("open3d/Feature/cloud_bin_0.pcd") else { return };
    let pcd = io::read_point_cloud(&input, "auto", &ReadOptions::default()).unwrap();
    assert_eq!(pcd.len(), 3903);
    let mut down = pcd.voxel_down_sample(0.05).unwrap();
    let n = down.len();
    assert!(n > 100 && n < 3903, "{n} points after voxel_down_sample(0.05)");
    // Each output point is a cell average, so it lies inside the input's bounding box.
    let (lo, hi) = pcd.get_axis_aligned_bounding_box().unwrap();
    assert!(down.points().iter().all(|p| (0..3).all(|i| p[i] >= lo[i] - 1e-9 && p[i] <= hi[i] + 1e-9)));
    down.estimate_normals(SearchParam::Hybrid { radius: 0.1, max_nn: 30 }).unwrap();
    assert_eq!(down.normals().len(), n);
    assert!(down.normals().iter().all(|m| (norm(*m) - 1.0).abs() < 1e-6));

    let dir = TempDir::new("figure1");
    let out = dir.path("down.ply");
    io::write_point_cloud(&out, &down, "auto", &WriteOptions::default()).unwrap();
    let back = io::read_point_cloud(&out, "auto", &ReadOptions::default()).unwrap();
    assert_eq!(back.points(), down.points());
    assert_eq!(back.normals(), down.normals());
}

#[test]
fn icp_on_the_real_pair_matches_open3d() {
    let (Some(s), Some(t)) = (data_file("open3d/Feature/cloud_bin_0.pcd"), data_file("open3d/Feature/cloud_bin_1.pcd"))
    else {
        return;
    };
    let source = io::read_point_cloud(s, "auto", &ReadOptions::default()).unwrap();
    let target = io::read_point_cloud(t, "auto", &ReadOptions::default()).unwrap();
    assert_eq!((source.len(), target.len()), (3903, 3458));
    assert!(target.has_normals().unwrap());

    let e = registration::evaluate_registration(&source, &target, 0.02, &IDENTITY).unwrap();
    assert_eq!(e.correspondence_set.len(), 1166);
    assert_eq!(e.fitness, 0.29874455547015116);
    assert!((e.inlier_rmse - 0.015019684565660246).abs() < 1e-12);

    let p2p = registration::registration_icp(&source, &target, 0.02, &IDENTITY, &IcpOptions::default()).unwrap();
    assert_eq!(p2p.correspondence_set.len(), 1404);
    assert_eq!(p2p.fitness, 0.35972328977709456);
    assert!((p2p.inlier_rmse - 0.014213863942948555).abs() < 1e-10);
    let expected = [
        [0.9999645253257959, 0.007589106481647855, 0.003654251326990515, -0.0015292659508640708],
        [-0.007594769279088394, 0.9999699761498986, 0.0015382712260112786, 0.006782699718971379],
        [-0.0036424675081643213, -0.0015659698520555094, 0.9999921400535475, 0.015287140186638048],
        [0.0, 0.0, 0.0, 1.0],
    ];
    assert!(max_abs_diff(&p2p.transformation, &expected) < 1e-9);

    let p2l = IcpOptions { estimation: Estimation::PointToPlane, ..Default::default() };
    let r = registration::registration_icp(&source, &target, 0.02, &IDENTITY, &p2l).unwrap();
    assert_eq!(r.correspondence_set.len(), 1206);
    assert_eq!(r.fitness, 0.30899308224442734);
    assert!((r.inlier_rmse - 0.014912024278676082).abs() < 1e-10);

    let info = registration::get_information_matrix_from_point_clouds(&source, &target, 0.02, &IDENTITY).unwrap();
    assert!((info[0][0] - 4419.837908946901).abs() < 1e-9);
    assert!((info[1][1] - 9444.652311184585).abs() < 1e-9);
    assert_eq!(info[3][3], 1166.0);
}
