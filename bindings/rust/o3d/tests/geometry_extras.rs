//! Bounding volumes, smoothing, covariances, planar patches, traced down-sampling, sharpening,
//! ellipsoids and as-rigid-as-possible deformation, each against an analytic answer: a rotated box's
//! minimal box, an ellipsoid recovered from its own vertices, two points smoothed by hand, a cube's
//! corner covariance, a flat patch, a rigid ARAP motion reproduced; bad input is an error.
mod common;

use common::*;
use o3d::{
    DeformAsRigidAsPossibleEnergy, ErrorCode, FilterScope, OrientedBoundingBox, OrientedBoundingEllipsoid,
    PlanarPatchOptions, PointCloud, SearchParam, TriangleMesh,
};

type Mat3 = [[f64; 3]; 3];

fn invalid<T: std::fmt::Debug>(r: o3d::Result<T>) {
    assert_eq!(r.unwrap_err().code, ErrorCode::InvalidArgument);
}

fn some_rotation() -> Mat3 {
    rotation([1.0, 2.0, 3.0], 0.7)
}

fn mul(r: &Mat3, v: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2])
}

/// r^T (v - c): `v` in the frame of `r`'s columns about `c`.
fn local(r: &Mat3, v: [f64; 3], c: [f64; 3]) -> [f64; 3] {
    let d = [v[0] - c[0], v[1] - c[1], v[2] - c[2]];
    [0, 1, 2].map(|j| r[0][j] * d[0] + r[1][j] * d[1] + r[2][j] * d[2])
}

fn sorted(mut a: [f64; 3]) -> [f64; 3] {
    a.sort_by(|x, y| x.partial_cmp(y).unwrap());
    a
}

fn near(a: f64, b: f64, tol: f64) {
    assert!((a - b).abs() <= tol, "{a} vs {b} (tolerance {tol})");
}

fn grid(n: usize, step: f64) -> Vec<[f64; 3]> {
    (0..n * n).map(|k| [(k / n) as f64 * step, (k % n) as f64 * step, 0.0]).collect()
}

#[test]
fn minimal_box_of_a_rotated_box() {
    let mut cuboid = TriangleMesh::create_box(1.0, 2.0, 3.0).unwrap();
    cuboid.rotate(&some_rotation(), Some([0.0; 3])).unwrap();
    let obb = cuboid.get_minimal_oriented_bounding_box(false).unwrap();
    near(obb.volume(), 6.0, 1e-6);
    let e = sorted(obb.extent);
    for (got, want) in e.iter().zip([1.0, 2.0, 3.0]) {
        near(*got, want, 1e-6);
    }
    let vertices = cuboid.vertices().unwrap().to_vec();
    near(OrientedBoundingBox::create_from_points_minimal(&vertices, false).unwrap().volume(), 6.0, 1e-6);
    let cloud = PointCloud::from_points(&vertices).unwrap();
    near(cloud.get_minimal_oriented_bounding_box(false).unwrap().volume(), 6.0, 1e-6);
    invalid(OrientedBoundingBox::create_from_points_minimal(&vertices[..3], false));
    invalid(PointCloud::from_points(&grid(3, 1.0)).unwrap().get_minimal_oriented_bounding_box(false));
}

#[test]
fn ellipsoid_recovered_from_its_vertices() {
    let r = some_rotation();
    let t = [1.0, -2.0, 0.5];
    let mut mesh = TriangleMesh::create_ellipsoid(1.0, 2.0, 3.0, 10, false).unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 2 + 9 * 20);
    for v in mesh.vertices().unwrap().to_vec() {
        near(v[0] * v[0] + v[1] * v[1] / 4.0 + v[2] * v[2] / 9.0, 1.0, 1e-9);
    }
    mesh.rotate(&r, Some([0.0; 3])).unwrap();
    mesh.translate(t, true).unwrap();
    let obe = mesh.get_oriented_bounding_ellipsoid(false).unwrap();
    for i in 0..3 {
        near(obe.center[i], t[i], 1e-2);
    }
    for (got, want) in sorted(obe.radii).iter().zip([1.0, 2.0, 3.0]) {
        near(*got, want, 1e-2);
    }
    let vertices = mesh.vertices().unwrap().to_vec();
    let from_cloud = PointCloud::from_points(&vertices).unwrap().get_oriented_bounding_ellipsoid(false).unwrap();
    near(from_cloud.volume(), obe.volume(), 1e-9);
    near(OrientedBoundingEllipsoid::create_from_points(&vertices, false).unwrap().volume(), obe.volume(), 1e-9);

    // Its mesh lies on it.
    let shell = TriangleMesh::create_from_oriented_bounding_ellipsoid(&obe, [1.0; 3], 8, false).unwrap();
    assert_eq!(shell.num_vertices().unwrap(), 2 + 7 * 16);
    for v in shell.vertices().unwrap().to_vec() {
        let u = local(&obe.r, v, obe.center);
        near((0..3).map(|i| u[i] * u[i] / (obe.radii[i] * obe.radii[i])).sum(), 1.0, 1e-9);
    }
    invalid(OrientedBoundingEllipsoid::create_from_points(&grid(3, 1.0), false));
    invalid(TriangleMesh::create_ellipsoid(1.0, 1.0, 1.0, 1, false));
    invalid(TriangleMesh::create_ellipsoid(-1.0, 1.0, 1.0, 20, false));
    let flat = OrientedBoundingEllipsoid { radii: [1.0, 0.0, 1.0], ..obe };
    invalid(TriangleMesh::create_from_oriented_bounding_ellipsoid(&flat, [1.0; 3], 20, false));
}

#[test]
fn mesh_of_a_box() {
    let obb = OrientedBoundingBox::new([1.0, 2.0, 3.0], some_rotation(), [1.0, 2.0, 3.0]);
    let mesh = TriangleMesh::create_from_oriented_bounding_box(&obb, [2.0, 1.0, 1.0], false).unwrap();
    assert_eq!((mesh.num_vertices().unwrap(), mesh.num_triangles().unwrap()), (8, 12));
    assert!(mesh.is_watertight().unwrap());
    near(mesh.get_volume().unwrap(), 12.0, 1e-9);
    let bad = OrientedBoundingBox { extent: [1.0, -2.0, 3.0], ..obb };
    invalid(TriangleMesh::create_from_oriented_bounding_box(&bad, [1.0; 3], false));
}

#[test]
fn smoothing_two_points_by_hand() {
    let two = PointCloud::from_points(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]).unwrap();
    // One Laplacian step of 0.5 meets in the middle.
    let p = two.smooth_laplacian(1, 0.5, 1, false).unwrap().points_to_vec().unwrap();
    near(p[0][0], 0.5, 1e-12);
    near(p[1][0], 0.5, 1e-12);
    // Taubin: 0.25 in to (0.25, 0.75), then -0.5 back out to (0, 1).
    let p = two.smooth_taubin(1, 0.25, -0.5, 1, true).unwrap().points_to_vec().unwrap();
    near(p[0][0], 0.0, 1e-12);
    near(p[1][0], 1.0, 1e-12);
    invalid(two.smooth_laplacian(1, 0.5, 0, false));
    invalid(two.smooth_taubin(1, f64::NAN, -0.53, 20, false));
}

#[test]
fn smoothing_keeps_a_plane_flat() {
    let mut plane = PointCloud::from_points(&grid(10, 0.01)).unwrap();
    let hybrid = SearchParam::Hybrid { radius: 0.05, max_nn: 30 };
    assert!(plane.smooth_mls(hybrid).unwrap().points_to_vec().unwrap().iter().all(|p| p[2].abs() < 1e-12));
    plane.set_normals(&vec![[0.0, 0.0, 1.0]; 100]).unwrap();
    let b = plane.smooth_bilateral(hybrid, 0.05, 0.05).unwrap().points_to_vec().unwrap();
    assert_eq!(b.len(), 100);
    assert!(b.iter().all(|p| p[2].abs() < 1e-12));
    invalid(plane.smooth_bilateral(hybrid, 0.0, 0.05));
    invalid(plane.smooth_mls(SearchParam::Radius { radius: -1.0 }));
}

#[test]
fn point_covariances_of_cube_corners() {
    let corners: Vec<[f64; 3]> =
        (0..8).map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64]).collect();
    let cube = PointCloud::from_points(&corners).unwrap();
    let cov = PointCloud::estimate_point_covariances(&cube, SearchParam::Knn { knn: 8 }).unwrap();
    assert_eq!(cov.len(), 8);
    for c in &cov {
        for i in 0..3 {
            for j in 0..3 {
                near(c[i][j], if i == j { 0.25 } else { 0.0 }, 1e-12);
            }
        }
    }
    assert!(!cube.has_covariances().unwrap()); // static: the cloud is unchanged
    invalid(PointCloud::estimate_point_covariances(&cube, SearchParam::Radius { radius: f64::NAN }));
}

#[test]
fn planar_patches_of_a_flat_grid() {
    let mut plane = PointCloud::from_points(&grid(30, 1.0 / 29.0)).unwrap();
    let mut options = PlanarPatchOptions::default();
    assert_eq!((options.normal_variance_threshold_deg, options.coplanarity_deg), (60.0, 75.0));
    assert_eq!(options.search_param, SearchParam::Knn { knn: 30 });
    invalid(plane.detect_planar_patches(&options)); // needs normals
    plane.set_normals(&vec![[0.0, 0.0, 1.0]; 900]).unwrap();
    options.search_param = SearchParam::Knn { knn: 20 };
    let patches = plane.detect_planar_patches(&options).unwrap();
    assert_eq!(patches.len(), 1);
    let p = patches[0];
    near(p.r[2][2].abs(), 1.0, 1e-6); // column 2, the normal, along z
    near(p.center[2], 0.0, 1e-6);
    near(p.center[0], 0.5, 0.05);
    near(p.center[1], 0.5, 0.05);
    options.outlier_ratio = 1.5;
    invalid(plane.detect_planar_patches(&options));
}

#[test]
fn voxel_down_sample_and_trace_two_voxels() {
    let cloud = PointCloud::from_points(&[[0.1, 0.1, 0.1], [0.2, 0.2, 0.2], [1.7, 0.1, 0.1]]).unwrap();
    let trace = cloud.voxel_down_sample_and_trace(1.0, [0.0; 3], [2.0; 3], false).unwrap();
    let pts = trace.cloud.points_to_vec().unwrap();
    assert_eq!(pts.len(), 2);
    near(pts[0][0], 0.15, 1e-12);
    near(pts[1][0], 1.7, 1e-12);
    assert_eq!(trace.original_indices, vec![vec![0, 1], vec![2]]);
    let mut lower = [None; 8];
    lower[0] = Some(1); // both in the lower octant
    let mut upper_x = [None; 8];
    upper_x[1] = Some(2); // upper half along x
    assert_eq!(trace.cubic_ids, vec![lower, upper_x]);
    invalid(cloud.voxel_down_sample_and_trace(0.0, [0.0; 3], [2.0; 3], false));
    invalid(cloud.voxel_down_sample_and_trace(1.0, [0.0; 3], [-1.0, 2.0, 2.0], false));
}

#[test]
fn sharpen_one_triangle_by_hand() {
    let tri =
        TriangleMesh::from_vertices_and_triangles(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2]])
            .unwrap();
    // v += sum over neighbours (v - neighbour).
    let v = tri.filter_sharpen(1, 1.0, FilterScope::All).unwrap().vertices().unwrap().to_vec();
    assert_eq!(v, vec![[-1.0, -1.0, 0.0], [3.0, -1.0, 0.0], [-1.0, 3.0, 0.0]]);
    let half = tri.filter_sharpen(1, 0.5, FilterScope::Vertex).unwrap().vertices().unwrap().to_vec();
    assert_eq!(half[0], [-0.5, -0.5, 0.0]);
    invalid(tri.filter_sharpen(1, f64::INFINITY, FilterScope::All));
}

#[test]
fn arap_reproduces_a_rigid_motion() {
    let sphere = TriangleMesh::create_sphere(1.0, 8).unwrap();
    let verts = sphere.vertices().unwrap().to_vec();
    let r = some_rotation();
    let t = [0.4, -1.0, 2.0];
    let moved = |v: [f64; 3]| {
        let m = mul(&r, v);
        [m[0] + t[0], m[1] + t[1], m[2] + t[2]]
    };
    // Both caps (|z| > 0.5) moved rigidly: the whole sphere follows.
    let ids: Vec<usize> = (0..verts.len()).filter(|&i| verts[i][2].abs() > 0.5).collect();
    let targets: Vec<[f64; 3]> = ids.iter().map(|&i| moved(verts[i])).collect();
    let out = sphere
        .deform_as_rigid_as_possible(&ids, &targets, 60, DeformAsRigidAsPossibleEnergy::Spokes, 0.01)
        .unwrap()
        .vertices()
        .unwrap()
        .to_vec();
    assert_eq!(out.len(), verts.len());
    for (o, v) in out.iter().zip(&verts) {
        assert!(dist2(*o, moved(*v)).sqrt() < 1e-6);
    }
    // A translation is reproduced by either energy at once.
    let shifted: Vec<[f64; 3]> =
        ids.iter().map(|&i| [verts[i][0] + t[0], verts[i][1] + t[1], verts[i][2] + t[2]]).collect();
    for energy in [DeformAsRigidAsPossibleEnergy::Spokes, DeformAsRigidAsPossibleEnergy::Smoothed] {
        let out =
            sphere.deform_as_rigid_as_possible(&ids, &shifted, 2, energy, 0.01).unwrap().vertices().unwrap().to_vec();
        for (o, v) in out.iter().zip(&verts) {
            assert!(dist2(*o, [v[0] + t[0], v[1] + t[1], v[2] + t[2]]).sqrt() < 1e-9);
        }
    }
    let energy = DeformAsRigidAsPossibleEnergy::default();
    assert_eq!(energy, DeformAsRigidAsPossibleEnergy::Spokes);
    // No iteration: the input positions.
    assert_eq!(
        sphere.deform_as_rigid_as_possible(&ids, &targets, 0, energy, 0.01).unwrap().vertices().unwrap().to_vec(),
        verts
    );
    invalid(sphere.deform_as_rigid_as_possible(&[0, 1], &targets[..1], 5, energy, 0.01));
    invalid(sphere.deform_as_rigid_as_possible(&[], &[], 5, energy, 0.01));
    invalid(sphere.deform_as_rigid_as_possible(&[100000], &targets[..1], 5, energy, 0.01));
    invalid(sphere.deform_as_rigid_as_possible(&[0, 0], &targets[..2], 5, energy, 0.01));
    invalid(sphere.deform_as_rigid_as_possible(&[0], &targets[..1], 5, energy, f64::NAN));
}
