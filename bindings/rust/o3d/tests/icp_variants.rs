//! Colored, generalized and symmetric ICP; robust kernels (weights, outliers); bad arguments.
mod common;

use common::*;
use o3d::registration::{self, Estimation, IcpOptions, RobustKernel, IDENTITY};
use o3d::{io, ErrorCode, PointCloud, SearchParam};

fn small_motion() -> [[f64; 4]; 4] {
    rigid(rotation([0.3, -0.5, 0.8], 3f64.to_radians()), [0.02, -0.01, 0.015])
}

fn tight() -> IcpOptions {
    IcpOptions { relative_fitness: 1e-12, relative_rmse: 1e-12, max_iteration: 100, ..Default::default() }
}

#[test]
fn icp_defaults_include_the_new_fields() {
    let d = IcpOptions::default();
    assert_eq!((d.kernel, d.lambda_geometric, d.epsilon), (RobustKernel::L2, 0.968, 1e-3));
    assert_eq!(IcpOptions::library_defaults().unwrap(), d);
}

#[test]
fn kernel_weights_follow_their_formulas() {
    let cases: [(RobustKernel, f64, f64); 12] = [
        (RobustKernel::L2, 3.0, 1.0),
        (RobustKernel::L1, 4.0, 0.25),
        (RobustKernel::L1, -0.5, 2.0),
        (RobustKernel::Huber { k: 1.0 }, 0.5, 1.0),
        (RobustKernel::Huber { k: 1.0 }, 2.0, 0.5),
        (RobustKernel::Cauchy { k: 1.0 }, 1.0, 0.5),
        (RobustKernel::Cauchy { k: 2.0 }, 2.0, 0.5),
        (RobustKernel::GM { k: 1.0 }, 1.0, 0.25),
        (RobustKernel::GM { k: 2.0 }, 0.0, 0.5),
        (RobustKernel::Tukey { k: 2.0 }, 1.0, 0.5625),
        (RobustKernel::Tukey { k: 2.0 }, -1.0, 0.5625),
        (RobustKernel::Tukey { k: 2.0 }, 3.0, 0.0),
    ];
    for (kernel, r, w) in cases {
        let got = kernel.weight(r).unwrap();
        assert!((got - w).abs() < 1e-12, "{kernel:?}.weight({r}) = {got}, expected {w}");
    }
    for bad in [RobustKernel::Huber { k: 0.0 }, RobustKernel::Tukey { k: -1.0 }, RobustKernel::GM { k: f64::NAN }] {
        assert_eq!(bad.weight(1.0).unwrap_err().code, ErrorCode::InvalidArgument, "{bad:?}");
    }
    assert_eq!(RobustKernel::Cauchy { k: 1.0 }.weight(f64::NAN).unwrap_err().code, ErrorCode::InvalidArgument);
}

/// A flat 1 m square with a grey pattern, and its copy shifted within the plane: point-to-plane
/// cannot see the shift, colored ICP can.
fn patterned_plane() -> (PointCloud, PointCloud, [[f64; 4]; 4]) {
    let pts: Vec<[f64; 3]> = (0..10_000).map(|i| [(i % 100) as f64 * 0.01, (i / 100) as f64 * 0.01, 0.0]).collect();
    let grey = |p: &[f64; 3]| {
        let v = 0.5 + 0.5 * (p[0] * 12.0).sin() * (p[1] * 9.0).cos();
        [v, v, v]
    };
    let colors: Vec<[f64; 3]> = pts.iter().map(grey).collect();
    let shift = [0.03, -0.02, 0.0];
    let moved: Vec<[f64; 3]> = pts.iter().map(|p| [p[0] + shift[0], p[1] + shift[1], p[2]]).collect();
    let mut source = PointCloud::from_points(&pts).unwrap();
    source.set_colors(&colors).unwrap();
    source.set_normals(&vec![[0.0, 0.0, 1.0]; pts.len()]).unwrap();
    let mut target = PointCloud::from_points(&moved).unwrap();
    target.set_colors(&colors).unwrap();
    target.set_normals(&vec![[0.0, 0.0, 1.0]; pts.len()]).unwrap();
    let identity3 = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    (source, target, rigid(identity3, shift))
}

#[test]
fn colored_icp_uses_the_colors() {
    let (source, target, truth) = patterned_plane();
    let r = registration::registration_colored_icp(&source, &target, 0.05, &IDENTITY, &tight()).unwrap();
    assert!(max_abs_diff(&r.transformation, &truth) < 1e-4, "{:?}", r.transformation);
    let p2l = IcpOptions { estimation: Estimation::PointToPlane, ..tight() };
    let geometric = registration::registration_icp(&source, &target, 0.05, &IDENTITY, &p2l).unwrap();
    assert!(max_abs_diff(&geometric.transformation, &truth) > 0.01, "the plane alone cannot show the shift");
    // Colored ICP through registration_icp and its estimation field gives the same answer.
    let colored = IcpOptions { estimation: Estimation::Colored, ..tight() };
    let same = registration::registration_icp(&source, &target, 0.05, &IDENTITY, &colored).unwrap();
    assert_eq!(same, r);
}

/// fragment.pcd (colors and normals) at a 4 cm voxel, and its copy moved by the small motion.
fn fragment_pair() -> Option<(PointCloud, PointCloud, [[f64; 4]; 4])> {
    let path = data_file("open3d/fragment.pcd")?;
    let source = io::read_point_cloud(path, "auto", &Default::default()).unwrap().voxel_down_sample(0.04).unwrap();
    assert!(source.has_colors().unwrap() && source.has_normals().unwrap());
    let mut target = source.clone();
    let truth = small_motion();
    target.transform(&truth).unwrap();
    Some((source, target, truth))
}

#[test]
fn colored_generalized_and_symmetric_icp_recover_a_small_motion() {
    let Some((source, target, truth)) = fragment_pair() else { return };
    type Icp =
        fn(&PointCloud, &PointCloud, f64, &[[f64; 4]; 4], &IcpOptions) -> o3d::Result<registration::RegistrationResult>;
    let variants: [(&str, Icp); 3] = [
        ("colored", registration::registration_colored_icp),
        ("generalized", registration::registration_generalized_icp),
        ("symmetric", registration::registration_symmetric_icp),
    ];
    for (name, icp) in variants {
        let r = icp(&source, &target, 0.08, &IDENTITY, &tight()).unwrap();
        assert!(max_abs_diff(&r.transformation, &truth) < 1e-5, "{name}: {:?}", r.transformation);
        assert!(r.fitness > 0.99, "{name}: {}", r.fitness);
        assert!(r.inlier_rmse < 1e-4, "{name}: {}", r.inlier_rmse);
    }
    // Generalized ICP on plain points (covariances from 20 neighbours) with a robust kernel.
    let plain_source = PointCloud::from_points(source.points()).unwrap();
    let plain_target = PointCloud::from_points(target.points()).unwrap();
    let opts = IcpOptions { kernel: RobustKernel::Cauchy { k: 0.05 }, epsilon: 1e-4, ..tight() };
    let r = registration::registration_generalized_icp(&plain_source, &plain_target, 0.08, &IDENTITY, &opts).unwrap();
    assert!(max_abs_diff(&r.transformation, &truth) < 1e-5, "{:?}", r.transformation);
}

#[test]
fn a_robust_kernel_keeps_point_to_plane_on_target_with_30_percent_outliers() {
    let Some(path) = data_file("open3d/Feature/cloud_bin_0.pcd") else { return };
    let mut target = io::read_point_cloud(path, "auto", &Default::default()).unwrap().voxel_down_sample(0.05).unwrap();
    target.estimate_normals(SearchParam::Hybrid { radius: 0.1, max_nn: 30 }).unwrap();
    let truth = small_motion();
    let back = rigid_inverse(&truth);
    let mut pts: Vec<[f64; 3]> = target.points().iter().map(|p| apply(&back, *p)).collect();
    // Outliers near the surface (within 10 cm of a target point), 30% of the source.
    let mut rng = Rng::new(17);
    let n_out = pts.len() * 3 / 7;
    let surface = target.points();
    for i in 0..n_out {
        let p = surface[(i * 7919) % surface.len()];
        pts.push([0, 1, 2].map(|k| p[k] + rng.range(-0.1, 0.1)));
    }
    let source = PointCloud::from_points(&pts).unwrap();
    let run = |kernel| {
        let opts = IcpOptions { estimation: Estimation::PointToPlane, kernel, ..tight() };
        let r = registration::registration_icp(&source, &target, 0.1, &IDENTITY, &opts).unwrap();
        max_abs_diff(&r.transformation, &truth)
    };
    let (l2, tukey) = (run(RobustKernel::L2), run(RobustKernel::Tukey { k: 0.05 }));
    assert!(tukey < 2e-3, "Tukey: off by {tukey}");
    assert!(l2 > 2.0 * tukey, "L2 ({l2}) should be pulled away more than Tukey ({tukey})");
}

#[test]
fn missing_attributes_and_bad_parameters_are_errors() {
    let (source, target, _) = patterned_plane();
    let bare = PointCloud::from_points(source.points()).unwrap();
    let icp = |s: &PointCloud, t: &PointCloud, opts: IcpOptions| {
        registration::registration_icp(s, t, 0.05, &IDENTITY, &opts).unwrap_err().code
    };
    let with = |estimation| IcpOptions { estimation, ..Default::default() };
    // Colored ICP needs colors on both and normals on the target; symmetric needs normals on both.
    assert_eq!(icp(&bare, &target, with(Estimation::Colored)), ErrorCode::InvalidArgument);
    assert_eq!(icp(&source, &bare, with(Estimation::Colored)), ErrorCode::InvalidArgument);
    assert_eq!(icp(&bare, &target, with(Estimation::Symmetric)), ErrorCode::InvalidArgument);
    assert_eq!(icp(&source, &bare, with(Estimation::Symmetric)), ErrorCode::InvalidArgument);
    let bad_lambda = IcpOptions { lambda_geometric: 1.5, ..with(Estimation::Colored) };
    assert_eq!(icp(&source, &target, bad_lambda), ErrorCode::InvalidArgument);
    let bad_epsilon = IcpOptions { epsilon: 0.0, ..with(Estimation::Generalized) };
    assert_eq!(icp(&source, &target, bad_epsilon), ErrorCode::InvalidArgument);
    let bad_kernel = IcpOptions { kernel: RobustKernel::Huber { k: -1.0 }, ..with(Estimation::PointToPlane) };
    assert_eq!(icp(&source, &target, bad_kernel), ErrorCode::InvalidArgument);
    let empty = PointCloud::new().unwrap();
    assert_eq!(icp(&empty, &target, with(Estimation::Generalized)), ErrorCode::InvalidArgument);
}
