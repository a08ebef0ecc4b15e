//! PointCloud: arrays in and out, zero-copy views, geometry operations, errors.
mod common;

use common::*;
use o3d::{ErrorCode, PointCloud, SearchParam};

#[test]
fn set_and_get_points_round_trip_f64() {
    let pts = Rng::new(1).points(1000, -5.0, 5.0);
    let mut pc = PointCloud::new().unwrap();
    assert!(pc.is_empty());
    assert!(!pc.has_points().unwrap());
    pc.set_points(&pts).unwrap();
    assert_eq!(pc.len(), 1000);
    assert!(pc.has_points().unwrap());
    assert!(!pc.has_normals().unwrap());
    assert_eq!(pc.points_to_vec().unwrap(), pts);
    assert_eq!(pc.points(), &pts[..]);
}

#[test]
fn set_points_f32_converts_exactly() {
    let pts: Vec<[f32; 3]> = (0..257).map(|i| [i as f32 * 0.1, -(i as f32) / 3.0, 1.0e-3 * i as f32]).collect();
    let mut pc = PointCloud::new().unwrap();
    pc.set_points_f32(&pts).unwrap();
    let back = pc.points_to_vec().unwrap();
    assert_eq!(back.len(), pts.len());
    for (a, b) in back.iter().zip(&pts) {
        assert_eq!(*a, [b[0] as f64, b[1] as f64, b[2] as f64]);
    }
}

#[test]
fn normals_and_colors_round_trip_f64_and_f32() {
    let mut pc = PointCloud::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    pc.set_normals(&[[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]).unwrap();
    pc.set_colors_f32(&[[0.5, 0.25, 1.0], [0.0, 1.0, 0.0]]).unwrap();
    assert!(pc.has_normals().unwrap() && pc.has_colors().unwrap());
    assert_eq!(pc.normals(), &[[0.0, 0.0, 1.0], [1.0, 0.0, 0.0]]);
    assert_eq!(pc.colors_to_vec().unwrap(), vec![[0.5, 0.25, 1.0], [0.0, 1.0, 0.0]]);
    pc.set_normals_f32(&[[0.0, 2.0, 0.0], [0.0, 0.0, -3.0]]).unwrap();
    pc.normalize_normals().unwrap();
    assert_eq!(pc.normals_to_vec().unwrap(), vec![[0.0, 1.0, 0.0], [0.0, 0.0, -1.0]]);
    pc.set_colors(&[[0.1, 0.2, 0.3], [0.4, 0.5, 0.6]]).unwrap();
    assert_eq!(pc.colors(), &[[0.1, 0.2, 0.3], [0.4, 0.5, 0.6]]);
    pc.paint_uniform_color([1.0, 0.0, 0.5]).unwrap();
    assert_eq!(pc.colors(), &[[1.0, 0.0, 0.5], [1.0, 0.0, 0.5]]);
    pc.clear().unwrap();
    assert_eq!(pc.len(), 0);
    assert!(!pc.has_normals().unwrap() && !pc.has_colors().unwrap());
    assert!(pc.points().is_empty() && pc.normals().is_empty());
}

#[test]
fn zero_copy_view_sees_in_place_edits() {
    let mut pc = PointCloud::from_points(&[[1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]).unwrap();
    let before = pc.points().as_ptr();
    {
        let pts = pc.points_mut();
        pts[1][2] = 60.0;
        pts[0] = [-1.0, -2.0, -3.0];
    }
    // The read-only view shows the same storage, edited.
    assert_eq!(pc.points().as_ptr(), before);
    assert_eq!(pc.points(), &[[-1.0, -2.0, -3.0], [4.0, 5.0, 60.0]]);
    // And the library computes with the edited values.
    assert_eq!(pc.get_max_bound().unwrap(), [4.0, 5.0, 60.0]);
    assert_eq!(pc.points_to_vec().unwrap(), vec![[-1.0, -2.0, -3.0], [4.0, 5.0, 60.0]]);
    pc.set_normals(&[[0.0, 0.0, 2.0], [0.0, 0.0, 2.0]]).unwrap();
    pc.normals_mut()[0] = [3.0, 0.0, 0.0];
    pc.set_colors(&[[0.0; 3], [0.0; 3]]).unwrap();
    pc.colors_mut()[1][0] = 0.75;
    assert_eq!(pc.normals()[0], [3.0, 0.0, 0.0]);
    assert_eq!(pc.colors()[1], [0.75, 0.0, 0.0]);
}

#[test]
fn clone_is_deep() {
    let mut a = PointCloud::from_points(&[[1.0, 1.0, 1.0]]).unwrap();
    let b = a.clone();
    a.points_mut()[0] = [9.0, 9.0, 9.0];
    assert_eq!(b.points(), &[[1.0, 1.0, 1.0]]);
    assert_eq!(a.try_clone().unwrap().points(), &[[9.0, 9.0, 9.0]]);
}

#[test]
fn voxel_down_sample_averages_each_voxel() {
    // Open3D's grid starts half a voxel below the minimum bound: here min = (0,0,0), edge 1, so the
    // cells are [-0.5, 0.5), [0.5, 1.5), ... on each axis. Three points share the cell at the
    // origin, two the cell around x = 2, one is alone around y = 3.
    let pts = [[0.0, 0.0, 0.0], [0.2, 0.4, 0.1], [0.4, 0.2, 0.3], [1.8, 0.1, 0.1], [2.2, 0.3, 0.3], [0.2, 3.0, 0.2]];
    let mut pc = PointCloud::from_points(&pts).unwrap();
    pc.set_colors(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0], [0.0, 0.0, 0.0], [0.5; 3]])
        .unwrap();
    let down = pc.voxel_down_sample(1.0).unwrap();
    assert_eq!(down.len(), 3);
    let got: Vec<([f64; 3], [f64; 3])> = down.points().iter().copied().zip(down.colors().iter().copied()).collect();
    let expected = [([0.2, 0.2, 0.4 / 3.0], [1.0 / 3.0; 3]), ([0.2, 3.0, 0.2], [0.5; 3]), ([2.0, 0.2, 0.2], [0.5; 3])];
    for (ep, ec) in &expected {
        // The output order is the library's; match each expected cell to its nearest output point.
        let (p, c) = got.iter().min_by(|a, b| dist2(a.0, *ep).partial_cmp(&dist2(b.0, *ep)).unwrap()).unwrap();
        for i in 0..3 {
            assert!((p[i] - ep[i]).abs() < 1e-12, "{p:?} vs {ep:?}");
            assert!((c[i] - ec[i]).abs() < 1e-12, "{c:?} vs {ec:?}");
        }
    }
}

#[test]
fn estimated_normals_of_a_sampled_plane_match_the_analytic_normal() {
    // Plane through (1,2,3) with normal n = (1,2,2)/3, sampled on a grid in its own frame.
    let n = [1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0];
    let u = [2.0 / 3.0, 1.0 / 3.0, -2.0 / 3.0]; // u . n = 0
    let v = [-2.0 / 3.0, 2.0 / 3.0, -1.0 / 3.0]; // v = n x u
    let mut pts = Vec::new();
    for i in 0..30 {
        for j in 0..30 {
            let (a, b) = (i as f64 * 0.05, j as f64 * 0.05);
            pts.push([1.0 + a * u[0] + b * v[0], 2.0 + a * u[1] + b * v[1], 3.0 + a * u[2] + b * v[2]]);
        }
    }
    let mut pc = PointCloud::from_points(&pts).unwrap();
    pc.estimate_normals(SearchParam::Hybrid { radius: 0.2, max_nn: 30 }).unwrap();
    pc.orient_normals_to_align_with_direction([0.0, 0.0, 1.0]).unwrap();
    let normals = pc.normals();
    assert_eq!(normals.len(), pts.len());
    for m in normals {
        let dot = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
        assert!((norm(*m) - 1.0).abs() < 1e-9);
        assert!((dot - 1.0).abs() < 1e-9, "normal {m:?} vs {n:?}");
    }
    // Towards a camera below the plane: every normal flips.
    pc.orient_normals_towards_camera_location([1.0 - 5.0 * n[0], 2.0 - 5.0 * n[1], 3.0 - 5.0 * n[2]]).unwrap();
    assert!(pc.normals().iter().all(|m| (m[0] * n[0] + m[1] * n[1] + m[2] * n[2] + 1.0).abs() < 1e-9));
    // Knn and radius parameters work too.
    pc.estimate_normals(SearchParam::Knn { knn: 10 }).unwrap();
    pc.estimate_normals(SearchParam::Radius { radius: 0.12 }).unwrap();
    assert!(pc.normals().iter().all(|m| (m[0] * n[0] + m[1] * n[1] + m[2] * n[2]).abs() > 1.0 - 1e-9));
}

#[test]
fn transforms_and_bounds() {
    let mut pc =
        PointCloud::from_points(&[[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 4.0, 0.0], [2.0, 4.0, 6.0]]).unwrap();
    assert_eq!(pc.get_center().unwrap(), [1.0, 2.0, 1.5]);
    assert_eq!(pc.get_axis_aligned_bounding_box().unwrap(), ([0.0; 3], [2.0, 4.0, 6.0]));
    assert_eq!(pc.get_min_bound().unwrap(), [0.0; 3]);
    pc.translate([1.0, 1.0, 1.0], true).unwrap();
    assert_eq!(pc.get_min_bound().unwrap(), [1.0; 3]);
    pc.translate([0.0, 0.0, 0.0], false).unwrap();
    assert_eq!(pc.get_center().unwrap(), [0.0; 3]);
    pc.scale(2.0, Some([0.0; 3])).unwrap();
    assert_eq!(pc.get_max_bound().unwrap(), [2.0, 4.0, 9.0]);
    pc.scale(0.5, None).unwrap();
    assert_eq!(pc.get_max_bound().unwrap(), [1.0, 2.0, 4.5]);
    // 90 degrees about z: (x, y) -> (-y, x).
    pc.rotate(&[[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]], Some([0.0; 3])).unwrap();
    let (lo, hi) = pc.get_axis_aligned_bounding_box().unwrap();
    assert!(max3(lo, [-2.0, -1.0, -1.5]) < 1e-12 && max3(hi, [2.0, 1.0, 4.5]) < 1e-12, "{lo:?} {hi:?}");
    pc.rotate(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]], None).unwrap();
    let m = rigid(rotation([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2), [10.0, 0.0, 0.0]);
    let before = pc.points_to_vec().unwrap();
    pc.transform(&m).unwrap();
    for (p, q) in before.iter().zip(pc.points()) {
        assert!(max3(apply(&m, *p), *q) < 1e-12);
    }
}

fn max3(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max)
}

#[test]
fn append_select_and_remove_non_finite() {
    let mut a = PointCloud::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    let b = PointCloud::from_points(&[[2.0; 3], [f64::NAN, 0.0, 0.0], [f64::INFINITY, 0.0, 0.0]]).unwrap();
    a.append(&b).unwrap();
    assert_eq!(a.len(), 5);
    let sel = a.select_by_index(&[0, 2], false).unwrap();
    assert_eq!(sel.points(), &[[0.0; 3], [2.0; 3]]);
    let inv = a.select_by_index(&[0, 2, 3, 4], true).unwrap();
    assert_eq!(inv.points(), &[[1.0; 3]]);
    let err = a.select_by_index(&[5], false).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    a.remove_non_finite_points(true, false).unwrap();
    assert_eq!(a.len(), 4);
    a.remove_non_finite_points(false, true).unwrap();
    assert_eq!(a.points(), &[[0.0; 3], [1.0; 3], [2.0; 3]]);
}

#[test]
fn other_down_samplers() {
    let pts: Vec<[f64; 3]> = (0..=100).map(|i| [i as f64, 0.0, 0.0]).collect();
    let pc = PointCloud::from_points(&pts).unwrap();
    let u = pc.uniform_down_sample(10).unwrap();
    assert_eq!(
        u.points().iter().map(|p| p[0]).collect::<Vec<_>>(),
        (0..=10).map(|i| i as f64 * 10.0).collect::<Vec<_>>()
    );
    let r1 = pc.random_down_sample(0.3, 42).unwrap();
    let r2 = pc.random_down_sample(0.3, 42).unwrap();
    assert_eq!(r1.len(), 30);
    assert_eq!(r1.points(), r2.points());
    assert!(r1.points().windows(2).all(|w| w[0][0] < w[1][0]), "original order kept");
    // Picks 0, then 100 (farthest), then 50; Open3D returns them in index order.
    let f = pc.farthest_point_down_sample(3, 0).unwrap();
    assert_eq!(f.points(), &[[0.0, 0.0, 0.0], [50.0, 0.0, 0.0], [100.0, 0.0, 0.0]]);
    let f = pc.farthest_point_down_sample(2, 30).unwrap();
    assert_eq!(f.points(), &[[30.0, 0.0, 0.0], [100.0, 0.0, 0.0]]);
}

#[test]
fn nearest_neighbor_and_cloud_distances() {
    let pc = PointCloud::from_points(&[[0.0; 3], [1.0, 0.0, 0.0], [3.0, 0.0, 0.0]]).unwrap();
    assert_eq!(pc.compute_nearest_neighbor_distance().unwrap(), vec![1.0, 1.0, 2.0]);
    let target = PointCloud::from_points(&[[0.0, 0.0, 2.0]]).unwrap();
    let d = pc.compute_point_cloud_distance(&target).unwrap();
    assert_eq!(d.len(), 3);
    assert!((d[1] - 5f64.sqrt()).abs() < 1e-12 && (d[2] - 13f64.sqrt()).abs() < 1e-12 && d[0] == 2.0);
}

#[test]
fn nan_voxel_size_is_invalid_argument_with_a_message() {
    let pc = PointCloud::from_points(&[[0.0; 3]]).unwrap();
    let err = pc.voxel_down_sample(f64::NAN).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    assert!(!err.message.is_empty());
    assert!(err.to_string().contains("InvalidArgument"));
    // The error was consumed: nothing is left pending on this thread.
    assert!(o3d::Error::last_on_this_thread().is_none());
    assert_eq!(pc.voxel_down_sample(-1.0).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(pc.uniform_down_sample(0).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn handles_are_send_and_sync() {
    fn assert_send_sync<T: Send + Sync>() {}
    assert_send_sync::<PointCloud>();
    assert_send_sync::<o3d::KDTreeFlann>();
    let pc = PointCloud::from_points(&Rng::new(3).points(500, 0.0, 1.0)).unwrap();
    // Concurrent const calls on one cloud.
    let centers: Vec<[f64; 3]> = std::thread::scope(|s| {
        let hs: Vec<_> = (0..4).map(|_| s.spawn(|| pc.get_center().unwrap())).collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert!(centers.windows(2).all(|w| w[0] == w[1]));
    // Move to another thread and drop there.
    let n = std::thread::spawn(move || pc.len()).join().unwrap();
    assert_eq!(n, 500);
}

#[test]
fn consistent_tangent_plane_orientation_makes_flipped_normals_agree() {
    // A sphere sampling with every third normal flipped inwards.
    let (points, mut normals) = fibonacci_sphere(2000, 1.0);
    for n in normals.iter_mut().step_by(3) {
        *n = n.map(|c| -c);
    }
    let mut pc = PointCloud::from_points(&points).unwrap();
    pc.set_normals(&normals).unwrap();
    pc.orient_normals_consistent_tangent_plane(10, 0.0, 1.0).unwrap();
    // All outward or all inward (the traversal keeps one global sign), and only signs changed.
    let outward = pc.points().iter().zip(pc.normals()).filter(|(p, n)| dot(**p, **n) > 0.0).count();
    assert!(outward == 0 || outward == points.len(), "{outward} of {} outward", points.len());
    for (after, before) in pc.normals().iter().zip(&normals) {
        assert!((dot(*after, *before).abs() - 1.0).abs() < 1e-12);
    }

    assert_eq!(pc.orient_normals_consistent_tangent_plane(0, 0.0, 1.0).unwrap_err().code, ErrorCode::InvalidArgument);
    let nan = pc.orient_normals_consistent_tangent_plane(10, f64::NAN, 1.0).unwrap_err();
    assert_eq!(nan.code, ErrorCode::InvalidArgument);
    let mut bare = PointCloud::from_points(&points[..10]).unwrap();
    let no_normals = bare.orient_normals_consistent_tangent_plane(5, 0.0, 1.0).unwrap_err();
    assert_eq!(no_normals.code, ErrorCode::InvalidArgument);
}

#[test]
fn remove_duplicated_points_keeps_the_first_of_each() {
    let mut pc =
        PointCloud::from_points(&[[0.0; 3], [1.0, 2.0, 3.0], [0.0; 3], [4.0, 5.0, 6.0], [1.0, 2.0, 3.0]]).unwrap();
    pc.set_colors(&[[0.1; 3], [0.2; 3], [0.3; 3], [0.4; 3], [0.5; 3]]).unwrap();
    pc.set_normals(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]]).unwrap();
    pc.remove_duplicated_points().unwrap();
    assert_eq!(pc.points(), &[[0.0; 3], [1.0, 2.0, 3.0], [4.0, 5.0, 6.0]]);
    // The other arrays go with their points.
    assert_eq!(pc.colors(), &[[0.1; 3], [0.2; 3], [0.4; 3]]);
    assert_eq!(pc.normals(), &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]]);
    // Nothing left to remove; an empty cloud is fine.
    pc.remove_duplicated_points().unwrap();
    assert_eq!(pc.len(), 3);
    PointCloud::new().unwrap().remove_duplicated_points().unwrap();
}
