//! OrientedBoundingBox: PCA box of an axis-aligned point set (analytic extents and volume), corner
//! order and line set as Open3D 0.20 (tools/reference/record_bindings_round2.py), point
//! containment, cropping clouds and meshes, and errors for bad input.
mod common;

use common::*;
use o3d::{ErrorCode, LineSet, OrientedBoundingBox, PointCloud, TriangleMesh};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Corners of the box [0,2] x [0,1] x [0,0.5], then its centre and one more interior point.
fn box_points() -> Vec<[f64; 3]> {
    let mut pts = Vec::new();
    for x in [0.0, 2.0] {
        for y in [0.0, 1.0] {
            for z in [0.0, 0.5] {
                pts.push([x, y, z]);
            }
        }
    }
    pts.push([1.0, 0.5, 0.25]);
    pts.push([0.5, 0.2, 0.1]);
    pts
}

fn sorted(mut v: Vec<[f64; 3]>) -> Vec<[f64; 3]> {
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v
}

/// Each column of `r` is a unit coordinate axis (up to sign) and det(r) = +-1.
fn assert_axis_aligned(r: &[[f64; 3]; 3]) {
    for k in 0..3 {
        let col = [r[0][k], r[1][k], r[2][k]];
        let big = col.iter().filter(|v| close(v.abs(), 1.0, 1e-9)).count();
        let zero = col.iter().filter(|v| close(**v, 0.0, 1e-9)).count();
        assert_eq!((big, zero), (1, 2), "column {k} of {r:?} is not a coordinate axis");
    }
}

#[test]
fn box_of_an_axis_aligned_point_set_has_its_extents_and_volume() {
    let pts = box_points();
    let obb = OrientedBoundingBox::create_from_points(&pts, false).unwrap();
    assert!(close(obb.volume(), 1.0, 1e-9), "{obb:?}");
    for i in 0..3 {
        assert!(close(obb.center[i], [1.0, 0.5, 0.25][i], 1e-9), "{obb:?}");
    }
    let mut extent = obb.extent;
    extent.sort_by(|a, b| b.partial_cmp(a).unwrap());
    for i in 0..3 {
        assert!(close(extent[i], [2.0, 1.0, 0.5][i], 1e-9), "{obb:?}");
    }
    assert_axis_aligned(&obb.r);
    // Whatever the axis order, the corners are the box's corners.
    let corners = sorted(obb.get_box_points().unwrap().to_vec());
    let expected = sorted(pts[..8].to_vec());
    for (c, e) in corners.iter().zip(&expected) {
        assert!(dist2(*c, *e) < 1e-18, "{corners:?} vs {expected:?}");
    }
    // The cloud and mesh versions agree with the free function.
    let cloud = PointCloud::from_points(&pts).unwrap();
    let from_cloud = cloud.get_oriented_bounding_box(false).unwrap();
    assert!(close(from_cloud.volume(), 1.0, 1e-9));
    let mesh = TriangleMesh::create_box(2.0, 1.0, 0.5).unwrap();
    let from_mesh = mesh.get_oriented_bounding_box(false).unwrap();
    assert!(close(from_mesh.volume(), 1.0, 1e-9), "{from_mesh:?}");
}

#[test]
fn rotated_points_give_a_rotated_box() {
    let r = rotation([1.0, 2.0, 3.0], 0.7);
    let m = rigid(r, [5.0, -1.0, 2.0]);
    let pts: Vec<_> = box_points().into_iter().map(|p| apply(&m, p)).collect();
    let obb = OrientedBoundingBox::create_from_points(&pts, false).unwrap();
    assert!(close(obb.volume(), 1.0, 1e-9), "{obb:?}");
    let centre = apply(&m, [1.0, 0.5, 0.25]);
    assert!(dist2(obb.center, centre) < 1e-18, "{obb:?}");
    // Every input point is inside (boundary included, with a hair of tolerance).
    let grown = OrientedBoundingBox { extent: obb.extent.map(|e| e + 1e-9), ..obb };
    assert_eq!(grown.get_point_indices_within_bounding_box(&pts).unwrap(), (0..10).collect::<Vec<i32>>());
}

#[test]
fn axis_aligned_box_points_and_lines_follow_open3d_order() {
    let obb = OrientedBoundingBox::create_from_axis_aligned_bounding_box([0.0; 3], [2.0, 1.0, 0.5]).unwrap();
    assert_eq!(obb.center, [1.0, 0.5, 0.25]);
    assert_eq!(obb.r, [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]);
    assert_eq!(obb.extent, [2.0, 1.0, 0.5]);
    assert_eq!(obb.volume(), 1.0);
    // Open3D 0.20 get_box_points() of this box (record_bindings_round2.py).
    let open3d = [
        [0.0, 0.0, 0.0],
        [2.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 0.5],
        [2.0, 1.0, 0.5],
        [0.0, 1.0, 0.5],
        [2.0, 0.0, 0.5],
        [2.0, 1.0, 0.0],
    ];
    assert_eq!(obb.get_box_points().unwrap(), open3d);

    let lines = LineSet::create_from_oriented_bounding_box(&obb).unwrap();
    assert_eq!(lines.num_points().unwrap(), 8);
    assert_eq!(lines.num_lines().unwrap(), 12);
    assert_eq!(lines.points().unwrap(), &open3d[..]);
    // Every edge runs along one axis, with that axis's length: 4 edges each of 2, 1 and 0.5.
    let mut lengths: Vec<f64> = lines
        .lines()
        .unwrap()
        .iter()
        .map(|[a, b]| {
            let (p, q) = (open3d[*a as usize], open3d[*b as usize]);
            assert_eq!((0..3).filter(|&i| p[i] != q[i]).count(), 1, "edge {a}-{b} is not axis-aligned");
            dist2(p, q).sqrt()
        })
        .collect();
    lengths.sort_by(|a, b| a.partial_cmp(b).unwrap());
    assert_eq!(lengths, [0.5, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0]);
}

#[test]
fn point_indices_within_and_crop() {
    // A box rotated 45 degrees about z, centred at the origin, 2 x 1 x 1.
    let r = rotation([0.0, 0.0, 1.0], std::f64::consts::FRAC_PI_4);
    let obb = OrientedBoundingBox::new([0.0; 3], r, [2.0, 1.0, 1.0]);
    let s = std::f64::consts::FRAC_1_SQRT_2;
    let pts = [
        [0.0, 0.0, 0.0],         // centre: in
        [0.9 * s, 0.9 * s, 0.0], // along the long axis, 0.9 < 1: in
        [0.9, 0.0, 0.0],         // 0.9 along x is 0.64 across the short axis: out
        [-0.3 * s, 0.3 * s, 0.4],
        [0.0, 0.0, 0.6], // above: out
    ];
    assert_eq!(obb.get_point_indices_within_bounding_box(&pts).unwrap(), vec![0, 1, 3]);
    assert!(obb.get_point_indices_within_bounding_box(&[]).unwrap().is_empty());

    let cloud = PointCloud::from_points(&pts).unwrap();
    assert_eq!(cloud.crop_obb(&obb, false).unwrap().points(), &[pts[0], pts[1], pts[3]]);
    assert_eq!(cloud.crop_obb(&obb, true).unwrap().points(), &[pts[2], pts[4]]);

    // Mesh crop keeps the triangles whose three vertices are inside, and drops unused vertices.
    let mesh = TriangleMesh::from_vertices_and_triangles(&pts, &[[0, 1, 3], [0, 1, 2], [1, 3, 4]]).unwrap();
    let cropped = mesh.crop_obb(&obb).unwrap();
    assert_eq!(cropped.num_triangles().unwrap(), 1);
    assert_eq!(cropped.num_vertices().unwrap(), 3);
}

#[test]
fn bad_input_is_an_error() {
    let code = |r: o3d::Result<OrientedBoundingBox>| r.unwrap_err().code;
    // Too few points, and a planar set without robust.
    assert_eq!(
        code(OrientedBoundingBox::create_from_points(&[[0.0; 3], [1.0, 0.0, 0.0]], false)),
        ErrorCode::InvalidArgument
    );
    let planar = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.5, 0.2, 0.0]];
    assert!(OrientedBoundingBox::create_from_points(&planar, false).is_err());
    // robust joggles the input: a (thin) box around the square.
    let robust = OrientedBoundingBox::create_from_points(&planar, true).unwrap();
    let mut extent = robust.extent;
    extent.sort_by(|a, b| b.partial_cmp(a).unwrap());
    assert!(extent[0] >= 1.0 - 1e-6 && extent[2] < 1e-3, "{robust:?}");
    // Non-finite input.
    let mut bad = box_points();
    bad[3][1] = f64::NAN;
    assert_eq!(code(OrientedBoundingBox::create_from_points(&bad, false)), ErrorCode::InvalidArgument);
    assert_eq!(
        code(OrientedBoundingBox::create_from_axis_aligned_bounding_box([1.0; 3], [0.0; 3])),
        ErrorCode::InvalidArgument
    );
    let nan_box = OrientedBoundingBox { center: [f64::NAN, 0.0, 0.0], ..Default::default() };
    assert_eq!(nan_box.get_box_points().unwrap_err().code, ErrorCode::InvalidArgument);
    let cloud = PointCloud::from_points(&box_points()).unwrap();
    assert_eq!(cloud.crop_obb(&nan_box, false).unwrap_err().code, ErrorCode::InvalidArgument);
    // An empty cloud has no oriented box.
    assert!(PointCloud::new().unwrap().get_oriented_bounding_box(false).is_err());
}
