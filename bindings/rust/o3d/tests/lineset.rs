//! LineSet: container and views, the unique edges of a mesh, correspondences between clouds,
//! colors and transforms, and errors for bad input.
mod common;

use common::*;
use o3d::{ErrorCode, LineSet, PointCloud, TriangleMesh};

#[test]
fn container_views_and_copies() {
    let mut set = LineSet::new().unwrap();
    assert_eq!((set.num_points().unwrap(), set.num_lines().unwrap()), (0, 0));
    assert!(set.points().unwrap().is_empty() && set.lines().unwrap().is_empty() && set.colors().unwrap().is_empty());
    let pts = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0]];
    set.set_points(&pts).unwrap();
    set.set_lines(&[[0, 1], [1, 2]]).unwrap();
    assert_eq!(set.points().unwrap(), &pts);
    assert_eq!(set.lines().unwrap(), &[[0, 1], [1, 2]]);
    assert_eq!(set.points_to_vec().unwrap(), pts.to_vec());
    assert_eq!(set.lines_to_vec().unwrap(), vec![[0, 1], [1, 2]]);

    set.paint_uniform_color([0.25, 0.5, 1.0]).unwrap();
    assert_eq!(set.colors_to_vec().unwrap(), vec![[0.25, 0.5, 1.0]; 2]);
    set.set_colors(&[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).unwrap();
    assert_eq!(set.colors().unwrap(), &[[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]);

    let copy = set.try_clone().unwrap();
    let m = rigid(rotation([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_2), [1.0, 2.0, 3.0]);
    set.transform(&m).unwrap();
    for (p, q) in set.points().unwrap().iter().zip(copy.points().unwrap()) {
        assert!(dist2(*p, apply(&m, *q)) < 1e-24);
    }
    // The copy is independent; lines and colors do not move.
    assert_eq!(copy.points().unwrap(), &pts);
    assert_eq!(set.lines().unwrap(), copy.lines().unwrap());
    let built = LineSet::from_points_and_lines(&pts, &[[2, 0]]).unwrap();
    assert_eq!(format!("{built:?}"), "LineSet { points: 3, lines: 1 }");
}

#[test]
fn mesh_edges_are_unique() {
    // A box: 8 vertices, 12 triangles, 18 unique edges (12 sides + 6 face diagonals).
    let mesh = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    let set = LineSet::create_from_triangle_mesh(&mesh).unwrap();
    assert_eq!(set.num_points().unwrap(), 8);
    assert_eq!(set.points().unwrap(), mesh.vertices().unwrap());
    let mut edges: Vec<[i32; 2]> = set.lines().unwrap().iter().map(|&[a, b]| [a.min(b), a.max(b)]).collect();
    edges.sort();
    edges.dedup();
    assert_eq!(edges.len(), 18);
    assert_eq!(set.num_lines().unwrap(), 18);
    // Every edge of every triangle is among them.
    for t in mesh.triangles().unwrap() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            assert!(edges.binary_search(&[a.min(b), a.max(b)]).is_ok());
        }
    }
}

#[test]
fn correspondences_join_two_clouds() {
    let c0 = PointCloud::from_points(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]).unwrap();
    let c1 = PointCloud::from_points(&[[0.0, 5.0, 0.0], [1.0, 5.0, 0.0], [2.0, 5.0, 0.0]]).unwrap();
    let set = LineSet::create_from_point_cloud_correspondences(&c0, &c1, &[[0, 2], [1, 0]]).unwrap();
    assert_eq!(set.num_points().unwrap(), 5);
    assert_eq!(set.points().unwrap()[2], [0.0, 5.0, 0.0]);
    assert_eq!(set.lines().unwrap(), &[[0, 4], [1, 2]]);

    let err = LineSet::create_from_point_cloud_correspondences(&c0, &c1, &[[0, 3]]).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    let err = LineSet::create_from_point_cloud_correspondences(&c0, &c1, &[[-1, 0]]).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
}

#[test]
fn axis_aligned_box_lines_and_errors() {
    let set = LineSet::create_from_axis_aligned_bounding_box([-1.0, 0.0, 2.0], [1.0, 3.0, 2.5]).unwrap();
    assert_eq!((set.num_points().unwrap(), set.num_lines().unwrap()), (8, 12));
    let pts = set.points().unwrap();
    let mut total = 0.0;
    for &[a, b] in set.lines().unwrap() {
        total += dist2(pts[a as usize], pts[b as usize]).sqrt();
    }
    assert!((total - 4.0 * (2.0 + 3.0 + 0.5)).abs() < 1e-12);

    assert_eq!(
        LineSet::create_from_axis_aligned_bounding_box([1.0; 3], [0.0; 3]).unwrap_err().code,
        ErrorCode::InvalidArgument
    );
    assert_eq!(
        LineSet::create_from_axis_aligned_bounding_box([f64::NAN, 0.0, 0.0], [1.0; 3]).unwrap_err().code,
        ErrorCode::InvalidArgument
    );
}
