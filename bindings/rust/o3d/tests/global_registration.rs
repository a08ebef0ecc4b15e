//! Global registration: correspondence checkers, RANSAC (reproducible with a seed on any thread
//! count), FGR, progress with cancellation, bad arguments.
mod common;

use std::ops::ControlFlow;

use common::*;
use o3d::registration::{
    self, CorrespondenceChecker, Estimation, FgrOptions, IcpOptions, RansacOptions, RegistrationResult,
};
use o3d::{io, ErrorCode, Feature, PointCloud, SearchParam};

const VOXEL: f64 = 0.05;

/// The large known motion applied to cloud_bin_0: 60 degrees about (1, 2, 3), then a shift.
fn known_motion() -> [[f64; 4]; 4] {
    rigid(rotation([1.0, 2.0, 3.0], 60f64.to_radians()), [0.5, -0.3, 0.2])
}

/// Open3D's global-registration tutorial: voxel 0.05, normals (0.1, 30), FPFH (0.25, 100).
fn prepare(cloud: &PointCloud) -> (PointCloud, Feature) {
    let mut down = cloud.voxel_down_sample(VOXEL).unwrap();
    down.estimate_normals(SearchParam::Hybrid { radius: 2.0 * VOXEL, max_nn: 30 }).unwrap();
    let f =
        registration::compute_fpfh_feature(&down, SearchParam::Hybrid { radius: 5.0 * VOXEL, max_nn: 100 }).unwrap();
    (down, f)
}

struct Scene {
    source: PointCloud,
    target: PointCloud,
    source_feature: Feature,
    target_feature: Feature,
    /// Moves the source back onto the target (to the scans' own ~0.4 deg / 17 mm agreement).
    truth: [[f64; 4]; 4],
}

/// cloud_bin_0 moved by the known motion as the source, cloud_bin_1 as the target.
fn scene() -> Option<Scene> {
    let p0 = data_file("open3d/Feature/cloud_bin_0.pcd")?;
    let p1 = data_file("open3d/Feature/cloud_bin_1.pcd")?;
    let mut c0 = io::read_point_cloud(p0, "auto", &Default::default()).unwrap();
    let c1 = io::read_point_cloud(p1, "auto", &Default::default()).unwrap();
    let motion = known_motion();
    c0.transform(&motion).unwrap();
    let (source, source_feature) = prepare(&c0);
    let (target, target_feature) = prepare(&c1);
    Some(Scene { source, target, source_feature, target_feature, truth: rigid_inverse(&motion) })
}

/// Within `deg` degrees and `dist` metres (mean over the source points) of the truth.
fn assert_near_truth(scene: &Scene, r: &RegistrationResult, deg: f64, dist: f64) {
    let angle = rotation_error_deg(&r.transformation, &scene.truth);
    let shift = mean_displacement(scene.source.points(), &r.transformation, &scene.truth);
    assert!(angle < deg && shift < dist, "off by {angle:.3} deg / {shift:.4} m: {:?}", r.transformation);
}

fn tutorial_checkers() -> [CorrespondenceChecker; 2] {
    [CorrespondenceChecker::EdgeLength(0.9), CorrespondenceChecker::Distance(1.5 * VOXEL)]
}

fn seeded(seed: u64, num_threads: usize) -> RansacOptions {
    RansacOptions { mutual_filter: true, seed: Some(seed), num_threads, ..Default::default() }
}

fn ransac(scene: &Scene, options: &RansacOptions) -> RegistrationResult {
    registration::registration_ransac_based_on_feature_matching(
        &scene.source,
        &scene.target,
        &scene.source_feature,
        &scene.target_feature,
        1.5 * VOXEL,
        &tutorial_checkers(),
        options,
    )
    .unwrap()
}

#[test]
fn default_options_are_open3ds_and_the_librarys() {
    assert_eq!(RansacOptions::library_defaults().unwrap(), RansacOptions::default());
    let d = RansacOptions::default();
    assert_eq!((d.ransac_n, d.max_iteration, d.confidence, d.seed), (3, 100_000, 0.999, None));
    assert_eq!(FgrOptions::library_defaults().unwrap(), FgrOptions::default());
    let f = FgrOptions::default();
    assert_eq!((f.division_factor, f.maximum_correspondence_distance, f.iteration_number), (1.4, 0.025, 64));
    assert_eq!(
        CorrespondenceChecker::library_defaults().unwrap()[..2],
        [CorrespondenceChecker::EdgeLength(0.9), CorrespondenceChecker::Distance(0.075)]
    );
    let CorrespondenceChecker::Normal(angle) = CorrespondenceChecker::library_defaults().unwrap()[2] else {
        panic!("third default is not the normal checker")
    };
    assert!((angle - 30f64.to_radians()).abs() < 1e-4, "{angle}");
}

#[test]
fn ransac_recovers_a_large_known_rotation_reproducibly() {
    let Some(scene) = scene() else { return };
    let first = ransac(&scene, &seeded(42, 2));
    assert_near_truth(&scene, &first, 5.0, 0.15);
    assert!(first.fitness > 0.5, "{}", first.fitness);
    assert!(!first.correspondence_set.is_empty());
    // Same seed: the same answer again, and on one thread.
    assert_eq!(ransac(&scene, &seeded(42, 2)), first);
    assert_eq!(ransac(&scene, &seeded(42, 1)), first);

    // ICP (point-to-plane) refines it to the scans' own agreement.
    let icp = IcpOptions { estimation: Estimation::PointToPlane, ..Default::default() };
    let refined =
        registration::registration_icp(&scene.source, &scene.target, 0.4 * VOXEL, &first.transformation, &icp).unwrap();
    assert_near_truth(&scene, &refined, 1.5, 0.04);
}

#[test]
fn global_seed_makes_unseeded_runs_repeat() {
    let Some(scene) = scene() else { return };
    let unseeded = RansacOptions { mutual_filter: true, max_iteration: 20_000, ..Default::default() };
    o3d::random_seed(7).unwrap();
    let a = ransac(&scene, &unseeded);
    o3d::random_seed(7).unwrap();
    let b = ransac(&scene, &unseeded);
    assert_eq!(a, b);
    assert_near_truth(&scene, &a, 5.0, 0.15);
}

#[test]
fn ransac_on_given_correspondences() {
    let Some(scene) = scene() else { return };
    let opts = registration::MatchOptions { mutual_filter: true, ..Default::default() };
    let corres =
        registration::correspondences_from_features(&scene.source_feature, &scene.target_feature, &opts).unwrap();
    let r = registration::registration_ransac_based_on_correspondence(
        &scene.source,
        &scene.target,
        &corres,
        1.5 * VOXEL,
        &tutorial_checkers(),
        &seeded(3, 0),
    )
    .unwrap();
    assert_near_truth(&scene, &r, 5.0, 0.15);
}

#[test]
fn fgr_recovers_the_same_rotation() {
    let Some(scene) = scene() else { return };
    let opts = FgrOptions { maximum_correspondence_distance: 0.5 * VOXEL, seed: Some(1), ..Default::default() };
    let r = registration::registration_fgr_based_on_feature_matching(
        &scene.source,
        &scene.target,
        &scene.source_feature,
        &scene.target_feature,
        &opts,
    )
    .unwrap();
    assert_near_truth(&scene, &r, 5.0, 0.15);
    let again = registration::registration_fgr_based_on_feature_matching(
        &scene.source,
        &scene.target,
        &scene.source_feature,
        &scene.target_feature,
        &FgrOptions { num_threads: 1, ..opts },
    )
    .unwrap();
    assert_eq!(again, r, "same seed, one thread: same result");

    let corres = registration::correspondences_from_features(
        &scene.source_feature,
        &scene.target_feature,
        &registration::MatchOptions { mutual_filter: true, ..Default::default() },
    )
    .unwrap();
    let r2 =
        registration::registration_fgr_based_on_correspondence(&scene.source, &scene.target, &corres, &opts).unwrap();
    assert_near_truth(&scene, &r2, 5.0, 0.15);
}

/// A small exact scene: `target` is `source` moved by a known motion; correspondences are i <-> i.
fn exact_pair(n: usize) -> (PointCloud, PointCloud, [[f64; 4]; 4], Vec<[i32; 2]>) {
    let pts = Rng::new(21).points(n, 0.0, 1.0);
    let truth = rigid(rotation([0.0, 1.0, 1.0], 0.7), [0.2, 0.1, -0.3]);
    let moved: Vec<[f64; 3]> = pts.iter().map(|p| apply(&truth, *p)).collect();
    let corres = (0..n as i32).map(|i| [i, i]).collect();
    (PointCloud::from_points(&pts).unwrap(), PointCloud::from_points(&moved).unwrap(), truth, corres)
}

#[test]
fn ransac_and_fgr_are_exact_on_exact_correspondences() {
    let (source, target, truth, mut corres) = exact_pair(200);
    // A third of the pairs are wrong.
    for i in (0..corres.len()).step_by(3) {
        corres[i][1] = ((i * 7 + 5) % 200) as i32;
    }
    let r = registration::registration_ransac_based_on_correspondence(
        &source,
        &target,
        &corres,
        0.01,
        &[],
        &RansacOptions { seed: Some(5), ..Default::default() },
    )
    .unwrap();
    assert!(max_abs_diff(&r.transformation, &truth) < 1e-9, "{:?}", r.transformation);
    assert!((r.fitness - 1.0).abs() < 1e-12, "every point has its image within 1 cm: {}", r.fitness);
    let fgr = registration::registration_fgr_based_on_correspondence(
        &source,
        &target,
        &corres,
        &FgrOptions { seed: Some(5), ..Default::default() },
    )
    .unwrap();
    assert!(max_abs_diff(&fgr.transformation, &truth) < 1e-3, "{:?}", fgr.transformation);
}

#[test]
fn checkers_accept_the_truth_and_reject_a_wrong_hypothesis() {
    let (source, target, truth, corres) = exact_pair(30);
    let few = &corres[..3];
    for checker in [CorrespondenceChecker::EdgeLength(0.9), CorrespondenceChecker::Distance(0.01)] {
        assert!(checker.check(&source, &target, few, &truth).unwrap(), "{checker:?}");
    }
    // Identity leaves every source point far from its image.
    assert!(!CorrespondenceChecker::Distance(0.01).check(&source, &target, few, &registration::IDENTITY).unwrap());
    // Edge lengths do not depend on the hypothesis, but do on the pairs: swap a target.
    let wrong = [[0, 0], [1, 1], [2, 17]];
    assert!(!CorrespondenceChecker::EdgeLength(0.99).check(&source, &target, &wrong, &truth).unwrap());

    // Normals: a plane with normals and its moved copy.
    let mut plane =
        PointCloud::from_points(&(0..25).map(|i| [(i % 5) as f64, (i / 5) as f64, 0.0]).collect::<Vec<_>>()).unwrap();
    plane.set_normals(&[[0.0, 0.0, 1.0]; 25]).unwrap();
    let mut moved = plane.clone();
    moved.transform(&truth).unwrap();
    let normal = CorrespondenceChecker::Normal(5f64.to_radians());
    assert!(normal.check(&plane, &moved, &corres[..3], &truth).unwrap());
    assert!(!normal.check(&plane, &moved, &corres[..3], &registration::IDENTITY).unwrap());

    // Bad arguments: no normals, thresholds that are not positive, indices out of range.
    assert_eq!(normal.check(&source, &target, few, &truth).unwrap_err().code, ErrorCode::InvalidArgument);
    for bad in [CorrespondenceChecker::Distance(f64::NAN), CorrespondenceChecker::EdgeLength(0.0)] {
        assert_eq!(bad.check(&source, &target, few, &truth).unwrap_err().code, ErrorCode::InvalidArgument);
    }
    let out = [[0, 0], [1, 1], [2, 30]];
    let err = CorrespondenceChecker::Distance(0.1).check(&source, &target, &out, &truth).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
}

/// Random pairs that never make a confident hypothesis, so RANSAC runs every iteration.
fn hopeless() -> (PointCloud, PointCloud, Vec<[i32; 2]>) {
    let mut rng = Rng::new(8);
    let (a, b) = (rng.points(300, 0.0, 1.0), rng.points(300, 0.0, 1.0));
    let corres = (0..300).map(|i| [i, (i * 97 + 13) % 300]).collect();
    (PointCloud::from_points(&a).unwrap(), PointCloud::from_points(&b).unwrap(), corres)
}

#[test]
fn ransac_and_fgr_progress_can_cancel() {
    let (source, target, corres) = hopeless();
    let opts = RansacOptions { max_iteration: 1_000_000, confidence: 1.0, seed: Some(1), ..Default::default() };
    let mut seen = Vec::new();
    let err = registration::registration_ransac_based_on_correspondence_with_progress(
        &source,
        &target,
        &corres,
        0.001,
        &[],
        &opts,
        |f| {
            seen.push(f);
            if seen.len() == 2 {
                ControlFlow::Break(())
            } else {
                ControlFlow::Continue(())
            }
        },
    )
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");
    assert_eq!(seen.len(), 2, "no callback after cancelling");
    assert!(seen.iter().all(|f| (0.0..1.0).contains(f)), "{seen:?}");

    // Without cancelling, the fractions rise to 1.
    let short = RansacOptions { max_iteration: 2000, ..opts };
    let mut fractions = Vec::new();
    registration::registration_ransac_based_on_correspondence_with_progress(
        &source,
        &target,
        &corres,
        0.001,
        &[],
        &short,
        |f| {
            fractions.push(f);
            ControlFlow::Continue(())
        },
    )
    .unwrap();
    assert!(fractions.windows(2).all(|w| w[0] <= w[1]), "{fractions:?}");
    assert_eq!(fractions.last(), Some(&1.0));

    // FGR needs consistent tuples to get going: exact pairs.
    let (source, target, _, corres) = exact_pair(200);
    let mut calls = 0;
    let err = registration::registration_fgr_based_on_correspondence_with_progress(
        &source,
        &target,
        &corres,
        &FgrOptions { seed: Some(1), ..Default::default() },
        |_| {
            calls += 1;
            ControlFlow::Break(())
        },
    )
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");
    assert_eq!(calls, 1);
}

#[test]
fn feature_matching_progress_can_cancel() {
    let (source, target, _) = hopeless();
    let mut rng = Rng::new(4);
    let rows: Vec<[f64; 4]> = (0..300).map(|_| [0; 4].map(|_| rng.next_f64())).collect();
    let f = Feature::from_descriptors(&rows).unwrap();
    let opts = RansacOptions { max_iteration: 1_000_000, confidence: 1.0, seed: Some(1), ..Default::default() };
    let err = registration::registration_ransac_based_on_feature_matching_with_progress(
        &source,
        &target,
        &f,
        &f,
        0.001,
        &[],
        &opts,
        |_| ControlFlow::Break(()),
    )
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");
    let (source, target, _, _) = exact_pair(300);
    let err = registration::registration_fgr_based_on_feature_matching_with_progress(
        &source,
        &target,
        &f,
        &f,
        &FgrOptions::default(),
        |_| ControlFlow::Break(()),
    )
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");
}

#[test]
fn panic_in_ransac_progress_resumes_in_rust() {
    let (source, target, corres) = hopeless();
    let opts = RansacOptions { max_iteration: 1_000_000, confidence: 1.0, seed: Some(1), ..Default::default() };
    let caught = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        let _ = registration::registration_ransac_based_on_correspondence_with_progress(
            &source,
            &target,
            &corres,
            0.001,
            &[],
            &opts,
            |_| panic!("boom from RANSAC progress"),
        );
    }))
    .unwrap_err();
    assert_eq!(caught.downcast_ref::<&str>(), Some(&"boom from RANSAC progress"));
}

#[test]
fn bad_arguments_are_errors() {
    let (source, target, corres) = hopeless();
    let ransac = |opts: &RansacOptions, corres: &[[i32; 2]], dist: f64, checkers: &[CorrespondenceChecker]| {
        registration::registration_ransac_based_on_correspondence(&source, &target, corres, dist, checkers, opts)
            .unwrap_err()
            .code
    };
    let ok = RansacOptions { max_iteration: 10, seed: Some(1), ..Default::default() };
    assert_eq!(ransac(&RansacOptions { ransac_n: 2, ..ok }, &corres, 0.1, &[]), ErrorCode::InvalidArgument);
    assert_eq!(ransac(&RansacOptions { confidence: 1.5, ..ok }, &corres, 0.1, &[]), ErrorCode::InvalidArgument);
    assert_eq!(ransac(&ok, &corres, f64::NAN, &[]), ErrorCode::InvalidArgument);
    assert_eq!(ransac(&ok, &[[0, 0], [1, 1], [2, 300]], 0.1, &[]), ErrorCode::InvalidArgument);
    assert_eq!(ransac(&ok, &corres, 0.1, &[CorrespondenceChecker::Distance(-1.0)]), ErrorCode::InvalidArgument);
    // Generalized ICP is not a RANSAC estimation; point-to-plane needs target normals.
    let generalized = RansacOptions { estimation: Estimation::Generalized, ..ok };
    assert_eq!(ransac(&generalized, &corres, 0.1, &[]), ErrorCode::InvalidArgument);
    let p2l = RansacOptions { estimation: Estimation::PointToPlane, ..ok };
    assert_eq!(ransac(&p2l, &corres, 0.1, &[]), ErrorCode::InvalidArgument);

    let (f4, f3) = (Feature::new(4, 300).unwrap(), Feature::new(3, 300).unwrap());
    let err = registration::registration_ransac_based_on_feature_matching(&source, &target, &f4, &f3, 0.1, &[], &ok)
        .unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    // More descriptors than points would index past the cloud.
    let long = Feature::new(4, 400).unwrap();
    let err = registration::registration_ransac_based_on_feature_matching(&source, &target, &long, &f4, 0.1, &[], &ok)
        .unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    let err =
        registration::registration_fgr_based_on_feature_matching(&source, &target, &f4, &long, &Default::default())
            .unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");

    let fgr = |opts: &FgrOptions| {
        registration::registration_fgr_based_on_correspondence(&source, &target, &corres, opts).unwrap_err().code
    };
    assert_eq!(fgr(&FgrOptions { division_factor: 1.0, ..Default::default() }), ErrorCode::InvalidArgument);
    assert_eq!(fgr(&FgrOptions { tuple_scale: 0.0, ..Default::default() }), ErrorCode::InvalidArgument);
    assert_eq!(
        fgr(&FgrOptions { maximum_correspondence_distance: -1.0, ..Default::default() }),
        ErrorCode::InvalidArgument
    );
    let err = registration::registration_fgr_based_on_feature_matching(&source, &target, &f4, &f3, &Default::default())
        .unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
}
