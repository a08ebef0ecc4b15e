//! Point-cloud tools: outlier removal, crop, RANSAC plane, DBSCAN, mean/covariance, Mahalanobis.
mod common;

use common::*;
use o3d::{ErrorCode, PointCloud};

/// 10 x 10 grid (spacing 0.1) on z = 0 with three far outliers interleaved at indices 3, 47 and 102.
fn plane_with_outliers() -> (Vec<[f64; 3]>, Vec<i32>) {
    let mut grid = Vec::new();
    for i in 0..10 {
        for j in 0..10 {
            grid.push([0.1 * i as f64, 0.1 * j as f64, 0.0]);
        }
    }
    let outliers = [[50.0, 50.0, 50.0], [-40.0, 30.0, 20.0], [10.0, -60.0, 5.0]];
    let mut pts = Vec::new();
    let mut kept = Vec::new();
    let mut g = grid.into_iter();
    let mut o = outliers.iter();
    for idx in 0..103i32 {
        if idx == 3 || idx == 47 || idx == 102 {
            pts.push(*o.next().unwrap());
        } else {
            kept.push(idx);
            pts.push(g.next().unwrap());
        }
    }
    (pts, kept)
}

fn assert_invalid<T: std::fmt::Debug>(r: o3d::Result<T>) {
    let err = r.unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    assert!(!err.message.is_empty());
}

#[test]
fn statistical_outlier_removal_keeps_the_plane() {
    let (pts, expected) = plane_with_outliers();
    let pc = PointCloud::from_points(&pts).unwrap();
    let (kept_cloud, kept) = pc.remove_statistical_outlier(10, 1.0).unwrap();
    assert_eq!(kept, expected);
    let want: Vec<[f64; 3]> = expected.iter().map(|&i| pts[i as usize]).collect();
    assert_eq!(kept_cloud.points_to_vec().unwrap(), want);
    assert_eq!(pc.len(), 103, "the input is unchanged");
}

#[test]
fn radius_outlier_removal_keeps_the_plane() {
    let (pts, expected) = plane_with_outliers();
    let mut pc = PointCloud::from_points(&pts).unwrap();
    pc.paint_uniform_color([0.25, 0.5, 1.0]).unwrap();
    let (kept_cloud, kept) = pc.remove_radius_outlier(3, 0.25).unwrap();
    assert_eq!(kept, expected);
    assert_eq!(kept_cloud.len(), 100);
    assert_eq!(kept_cloud.points()[2], pts[2]);
    assert_eq!(kept_cloud.points()[3], pts[4]);
    assert_eq!(kept_cloud.colors().len(), 100, "colors follow the kept points");
}

#[test]
fn outlier_removal_rejects_bad_arguments() {
    let (pts, _) = plane_with_outliers();
    let pc = PointCloud::from_points(&pts).unwrap();
    assert_invalid(pc.remove_statistical_outlier(0, 1.0));
    assert_invalid(pc.remove_statistical_outlier(10, 0.0));
    assert_invalid(pc.remove_statistical_outlier(10, f64::NAN));
    assert_invalid(pc.remove_radius_outlier(0, 0.25));
    assert_invalid(pc.remove_radius_outlier(3, 0.0));
    assert_invalid(pc.remove_radius_outlier(3, -1.0));
    assert_invalid(pc.remove_statistical_outlier(usize::MAX, 1.0));
    let empty = PointCloud::new().unwrap();
    assert_invalid(empty.remove_statistical_outlier(10, 1.0));
    assert_invalid(empty.remove_radius_outlier(3, 0.25));
}

#[test]
fn crop_aabb_is_inclusive_and_inverts() {
    let pts: Vec<[f64; 3]> = (0..=10).map(|i| [i as f64, 0.0, 0.0]).collect();
    let pc = PointCloud::from_points(&pts).unwrap();
    let inside = pc.crop_aabb([2.0, -1.0, -1.0], [5.0, 1.0, 1.0], false).unwrap();
    assert_eq!(
        inside.points_to_vec().unwrap(),
        vec![[2.0, 0.0, 0.0], [3.0, 0.0, 0.0], [4.0, 0.0, 0.0], [5.0, 0.0, 0.0]]
    );
    let outside = pc.crop_aabb([2.0, -1.0, -1.0], [5.0, 1.0, 1.0], true).unwrap();
    let xs: Vec<f64> = outside.points().iter().map(|p| p[0]).collect();
    assert_eq!(xs, vec![0.0, 1.0, 6.0, 7.0, 8.0, 9.0, 10.0]);
    // A box touching the points only on its faces keeps them.
    let faces = pc.crop_aabb([0.0, 0.0, 0.0], [10.0, 1.0, 1.0], false).unwrap();
    assert_eq!(faces.len(), 11);
    // A box missing every point gives an empty cloud.
    assert!(pc.crop_aabb([20.0, 0.0, 0.0], [21.0, 1.0, 1.0], false).unwrap().is_empty());
}

#[test]
fn crop_aabb_rejects_bad_boxes() {
    let pc = PointCloud::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    assert_invalid(pc.crop_aabb([1.0, 0.0, 0.0], [0.0, 1.0, 1.0], false));
    assert_invalid(pc.crop_aabb([0.0, 0.0, 0.0], [0.0, 1.0, 1.0], false));
    assert_invalid(pc.crop_aabb([f64::NAN, 0.0, 0.0], [1.0, 1.0, 1.0], false));
}

/// 400 points on 0.5 x - 0.25 y - z + 1 = 0 and 20 points 1 above it, interleaved.
fn tilted_plane() -> (Vec<[f64; 3]>, Vec<i32>) {
    let z = |x: f64, y: f64| 0.5 * x - 0.25 * y + 1.0;
    let mut pts = Vec::new();
    let mut inliers = Vec::new();
    let mut rng = Rng::new(7);
    for i in 0..20 {
        for j in 0..20 {
            let (x, y) = (0.1 * i as f64, 0.1 * j as f64);
            if (i * 20 + j) % 20 == 7 {
                let (ox, oy) = (rng.range(0.0, 2.0), rng.range(0.0, 2.0));
                pts.push([ox, oy, z(ox, oy) + rng.range(0.8, 1.5)]);
            }
            inliers.push(pts.len() as i32);
            pts.push([x, y, z(x, y)]);
        }
    }
    (pts, inliers)
}

#[test]
fn segment_plane_recovers_a_known_plane() {
    let (pts, expected) = tilted_plane();
    assert_eq!(pts.len(), 420);
    let pc = PointCloud::from_points(&pts).unwrap();
    let (plane, inliers) = pc.segment_plane(0.01, 3, 1000, 0.9999, 42).unwrap();
    assert_eq!(inliers, expected);
    let n = norm([plane[0], plane[1], plane[2]]);
    assert!((n - 1.0).abs() < 1e-9, "unit normal, got {plane:?}");
    let k = 1.3125f64.sqrt();
    let want = [0.5 / k, -0.25 / k, -1.0 / k, 1.0 / k];
    let sign = if plane[2] < 0.0 { 1.0 } else { -1.0 };
    for (a, b) in plane.iter().zip(want) {
        assert!((sign * a - b).abs() < 1e-6, "plane {plane:?}, want ±{want:?}");
    }
    // Same seed → same answer.
    assert_eq!(pc.segment_plane(0.01, 3, 1000, 0.9999, 42).unwrap(), (plane, inliers));
}

#[test]
fn segment_plane_rejects_bad_arguments() {
    let (pts, _) = tilted_plane();
    let pc = PointCloud::from_points(&pts).unwrap();
    assert_invalid(pc.segment_plane(-0.01, 3, 100, 0.99, 0));
    assert_invalid(pc.segment_plane(f64::NAN, 3, 100, 0.99, 0));
    assert_invalid(pc.segment_plane(0.01, 2, 100, 0.99, 0));
    assert_invalid(pc.segment_plane(0.01, 3, 0, 0.99, 0));
    assert_invalid(pc.segment_plane(0.01, 3, 100, 0.0, 0));
    assert_invalid(pc.segment_plane(0.01, 3, 100, 1.5, 0));
    let two = PointCloud::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    assert_invalid(two.segment_plane(0.01, 3, 100, 0.99, 0));
    assert_invalid(PointCloud::new().unwrap().segment_plane(0.01, 3, 100, 0.99, 0));
}

#[test]
fn dbscan_labels_blobs_in_index_order_and_noise() {
    let blob = |c: [f64; 3]| -> Vec<[f64; 3]> {
        (0..20).map(|k| [c[0] + 0.05 * (k % 4) as f64, c[1] + 0.05 * (k / 4 % 5) as f64, c[2]]).collect()
    };
    let mut pts = vec![[100.0, 100.0, 100.0]]; // 0: noise
    pts.extend(blob([10.0, 0.0, 0.0])); // 1..=20: first cluster by lowest index
    pts.extend(blob([0.0, 0.0, 0.0])); // 21..=40
    pts.push([-100.0, 0.0, 0.0]); // 41: noise
    pts.push([5.0, 5.0, 5.0]); // 42: noise
    let pc = PointCloud::from_points(&pts).unwrap();
    let labels = pc.cluster_dbscan(0.5, 5).unwrap();
    let mut want = vec![-1];
    want.extend([0; 20]);
    want.extend([1; 20]);
    want.extend([-1, -1]);
    assert_eq!(labels, want);
}

#[test]
fn dbscan_rejects_bad_arguments() {
    let pc = PointCloud::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    assert_invalid(pc.cluster_dbscan(0.0, 5));
    assert_invalid(pc.cluster_dbscan(-1.0, 5));
    assert_invalid(pc.cluster_dbscan(f64::INFINITY, 5));
    assert_invalid(pc.cluster_dbscan(0.5, usize::MAX));
    assert_invalid(PointCloud::new().unwrap().cluster_dbscan(0.5, 5));
}

#[test]
fn mean_and_covariance_are_analytic() {
    // x = t, y = 2t, z = 0, t = 0..3: mean (1.5, 3, 0); var x = 1.25, cov xy = 2.5, var y = 5.
    let pts: Vec<[f64; 3]> = (0..4).map(|t| [t as f64, 2.0 * t as f64, 0.0]).collect();
    let (mean, cov) = PointCloud::from_points(&pts).unwrap().compute_mean_and_covariance().unwrap();
    let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
    assert!(close(mean[0], 1.5) && close(mean[1], 3.0) && close(mean[2], 0.0), "{mean:?}");
    let want = [[1.25, 2.5, 0.0], [2.5, 5.0, 0.0], [0.0, 0.0, 0.0]];
    for i in 0..3 {
        for j in 0..3 {
            assert!(close(cov[i][j], want[i][j]), "cov {cov:?}");
        }
    }
    // Axis points about c = (1, 2, 3): mean c, covariance diag(1/3, 4/3, 3).
    let (mean, cov) = PointCloud::from_points(&axis_points()).unwrap().compute_mean_and_covariance().unwrap();
    assert!(close(mean[0], 1.0) && close(mean[1], 2.0) && close(mean[2], 3.0), "{mean:?}");
    let want = [[1.0 / 3.0, 0.0, 0.0], [0.0, 4.0 / 3.0, 0.0], [0.0, 0.0, 3.0]];
    for i in 0..3 {
        for j in 0..3 {
            assert!(close(cov[i][j], want[i][j]), "cov {cov:?}");
        }
    }
    assert_invalid(PointCloud::new().unwrap().compute_mean_and_covariance());
}

fn axis_points() -> Vec<[f64; 3]> {
    let c = [1.0, 2.0, 3.0];
    [[1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, -2.0, 0.0], [0.0, 0.0, 3.0], [0.0, 0.0, -3.0]]
        .iter()
        .map(|v| [c[0] + v[0], c[1] + v[1], c[2] + v[2]])
        .collect()
}

#[test]
fn mahalanobis_distance_is_analytic() {
    // Each axis point lies sqrt(3) standard deviations out along its axis.
    let d = PointCloud::from_points(&axis_points()).unwrap().compute_mahalanobis_distance().unwrap();
    assert_eq!(d.len(), 6);
    for v in &d {
        assert!((v - 3f64.sqrt()).abs() < 1e-9, "{d:?}");
    }
    assert_invalid(PointCloud::new().unwrap().compute_mahalanobis_distance());
}
