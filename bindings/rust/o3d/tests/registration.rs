//! ICP, evaluation, information matrix; progress callbacks with cancellation and panics.
mod common;

use std::ops::ControlFlow;

use common::*;
use o3d::registration::{self, Estimation, IcpOptions, IDENTITY};
use o3d::{ErrorCode, PointCloud};

/// A random cloud and a copy moved by a known rigid transform.
fn pair() -> (PointCloud, PointCloud, [[f64; 4]; 4]) {
    let pts = Rng::new(99).points(600, 0.0, 1.0);
    let truth = rigid(rotation([1.0, 2.0, 3.0], 4f64.to_radians()), [0.03, -0.02, 0.04]);
    let moved: Vec<[f64; 3]> = pts.iter().map(|p| apply(&truth, *p)).collect();
    (PointCloud::from_points(&pts).unwrap(), PointCloud::from_points(&moved).unwrap(), truth)
}

fn tight() -> IcpOptions {
    IcpOptions { relative_fitness: 1e-12, relative_rmse: 1e-12, max_iteration: 200, ..Default::default() }
}

#[test]
fn default_options_are_open3ds_and_the_librarys() {
    let d = IcpOptions::default();
    assert_eq!((d.relative_fitness, d.relative_rmse, d.max_iteration), (1e-6, 1e-6, 30));
    assert_eq!(d.estimation, Estimation::PointToPoint);
    assert!(!d.with_scaling);
    assert_eq!(IcpOptions::library_defaults().unwrap(), d);
}

#[test]
fn icp_recovers_a_known_rigid_transform() {
    let (source, target, truth) = pair();
    let r = registration::registration_icp(&source, &target, 0.3, &IDENTITY, &tight()).unwrap();
    assert!(max_abs_diff(&r.transformation, &truth) < 1e-6, "{:?}\nvs\n{truth:?}", r.transformation);
    assert_eq!(r.fitness, 1.0);
    assert!(r.inlier_rmse < 1e-6);
    assert_eq!(r.correspondence_set.len(), 600);
    assert!(r.correspondence_set.iter().all(|&[s, t]| s == t), "every point pairs with its own image");
    // Starting from the answer, point-to-plane stays there (the target needs normals).
    let mut target_n = target.clone();
    target_n.estimate_normals(o3d::SearchParam::Knn { knn: 10 }).unwrap();
    let p2l = IcpOptions { estimation: Estimation::PointToPlane, ..tight() };
    let r2 = registration::registration_icp(&source, &target_n, 0.3, &truth, &p2l).unwrap();
    assert!(max_abs_diff(&r2.transformation, &truth) < 1e-6);
}

#[test]
fn icp_with_scaling_recovers_the_scale() {
    let pts = Rng::new(5).points(400, 0.0, 1.0);
    let scaled: Vec<[f64; 3]> = pts.iter().map(|p| [1.1 * p[0] + 0.01, 1.1 * p[1], 1.1 * p[2]]).collect();
    let (s, t) = (PointCloud::from_points(&pts).unwrap(), PointCloud::from_points(&scaled).unwrap());
    let opts = IcpOptions { with_scaling: true, ..tight() };
    let r = registration::registration_icp(&s, &t, 0.5, &IDENTITY, &opts).unwrap();
    assert!((r.transformation[0][0] - 1.1).abs() < 1e-6, "{:?}", r.transformation);
    assert!((r.transformation[0][3] - 0.01).abs() < 1e-6);
}

#[test]
#[allow(clippy::needless_range_loop)]
fn evaluate_and_information_matrix() {
    let (source, target, truth) = pair();
    let at_truth = registration::evaluate_registration(&source, &target, 0.01, &truth).unwrap();
    assert_eq!(at_truth.fitness, 1.0);
    assert!(at_truth.inlier_rmse < 1e-12);
    assert_eq!(at_truth.transformation, truth);
    let at_identity = registration::evaluate_registration(&source, &target, 0.01, &IDENTITY).unwrap();
    assert!(at_identity.fitness < 0.5);
    let info = registration::get_information_matrix_from_point_clouds(&source, &target, 0.01, &truth).unwrap();
    for i in 0..6 {
        for j in 0..6 {
            assert!((info[i][j] - info[j][i]).abs() < 1e-9, "symmetric");
        }
    }
    // Translation block: one identity per correspondence.
    assert_eq!([info[3][3], info[4][4], info[5][5]], [600.0; 3]);
    assert_eq!(info[3][4], 0.0);
}

#[test]
fn progress_reports_increasing_fractions() {
    let (source, target, _) = pair();
    let mut seen = Vec::new();
    let opts = IcpOptions { max_iteration: 10, relative_fitness: 0.0, relative_rmse: 0.0, ..Default::default() };
    registration::registration_icp_with_progress(&source, &target, 0.3, &IDENTITY, &opts, |f| {
        seen.push(f);
        ControlFlow::Continue(())
    })
    .unwrap();
    assert!(!seen.is_empty());
    assert!(seen.windows(2).all(|w| w[0] <= w[1]), "{seen:?}");
    assert!(seen.iter().all(|f| (0.0..=1.0).contains(f)), "{seen:?}");
}

#[test]
fn progress_callback_can_cancel() {
    let (source, target, _) = pair();
    let mut calls = 0;
    let err = registration::registration_icp_with_progress(&source, &target, 0.3, &IDENTITY, &tight(), |_| {
        calls += 1;
        if calls == 2 {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    })
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled);
    assert!(!err.message.is_empty());
    assert_eq!(calls, 2, "no callback after cancelling");
}

#[test]
fn panic_in_progress_callback_resumes_in_rust() {
    let (source, target, _) = pair();
    let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let _ = registration::registration_icp_with_progress(&source, &target, 0.3, &IDENTITY, &tight(), |_| {
            panic!("boom from the callback")
        });
    }))
    .unwrap_err();
    assert_eq!(caught.downcast_ref::<&str>(), Some(&"boom from the callback"));
    // The library still works afterwards on this thread.
    let r = registration::registration_icp(&source, &target, 0.3, &IDENTITY, &tight()).unwrap();
    assert_eq!(r.fitness, 1.0);
}

#[test]
fn bad_arguments_are_rejected() {
    let (source, target, _) = pair();
    let err =
        registration::registration_icp(&source, &target, f64::NAN, &IDENTITY, &IcpOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    // Point-to-plane needs target normals.
    let p2l = IcpOptions { estimation: Estimation::PointToPlane, ..Default::default() };
    let err = registration::registration_icp(&source, &target, 0.3, &IDENTITY, &p2l).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
}
