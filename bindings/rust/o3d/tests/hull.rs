//! Convex hull (cube corners plus interior points: 8 vertices, 12 outward triangles, volume 1)
//! and hidden-point removal on a sphere seen from above.
mod common;

use common::*;
use o3d::{ErrorCode, PointCloud, TriangleMesh};

fn cube_corners_and_interior() -> Vec<[f64; 3]> {
    let mut pts = Vec::new();
    let mut rng = Rng::new(7);
    // Interior points first, so the hull's indices are not simply 0..8.
    pts.extend(rng.points(20, 0.1, 0.9));
    for x in [0.0, 1.0] {
        for y in [0.0, 1.0] {
            for z in [0.0, 1.0] {
                pts.push([x, y, z]);
            }
        }
    }
    pts
}

/// Every triangle's normal points away from `inside`.
fn assert_outward(mesh: &TriangleMesh, inside: [f64; 3]) {
    let v = mesh.vertices().unwrap();
    for t in mesh.triangles().unwrap() {
        let [a, b, c] = t.map(|i| v[i as usize]);
        let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let w = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
        let n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]];
        let out = [a[0] - inside[0], a[1] - inside[1], a[2] - inside[2]];
        assert!(n[0] * out[0] + n[1] * out[1] + n[2] * out[2] > 0.0, "triangle {t:?} faces inwards");
    }
}

#[test]
fn hull_of_a_cube_is_the_cube() {
    let pts = cube_corners_and_interior();
    let cloud = PointCloud::from_points(&pts).unwrap();
    let (hull, indices) = cloud.compute_convex_hull(false).unwrap();
    assert_eq!(hull.num_vertices().unwrap(), 8);
    assert_eq!(hull.num_triangles().unwrap(), 12);
    assert!((hull.get_volume().unwrap() - 1.0).abs() < 1e-12);
    assert!((hull.get_surface_area().unwrap() - 6.0).abs() < 1e-12);
    assert!(hull.is_watertight().unwrap());
    assert_outward(&hull, [0.5; 3]);
    // One index per hull vertex, naming the corner it came from.
    let mut sorted = indices.clone();
    sorted.sort();
    assert_eq!(sorted, (20..28).collect::<Vec<i32>>());
    for (v, &i) in hull.vertices().unwrap().iter().zip(&indices) {
        assert_eq!(*v, pts[i as usize]);
    }

    // The mesh version hulls the vertices.
    let mesh = TriangleMesh::create_sphere(1.0, 10).unwrap();
    let (mesh_hull, mesh_indices) = mesh.compute_convex_hull(false).unwrap();
    assert_eq!(mesh_indices.len(), mesh_hull.num_vertices().unwrap());
    assert_eq!(mesh_hull.num_vertices().unwrap(), mesh.num_vertices().unwrap()); // all on the sphere
    assert!(mesh_hull.is_watertight().unwrap());
    assert!((mesh_hull.get_volume().unwrap() - mesh.get_volume().unwrap()).abs() < 1e-9);
    assert_outward(&mesh_hull, [0.0; 3]);
}

#[test]
fn hull_errors_and_joggle() {
    let planar = PointCloud::from_points(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]).unwrap();
    assert!(planar.compute_convex_hull(false).is_err());
    let (joggled, idx) = planar.compute_convex_hull(true).unwrap();
    assert_eq!(idx.len(), joggled.num_vertices().unwrap());
    assert!(joggled.num_triangles().unwrap() >= 2);
    let three = PointCloud::from_points(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).unwrap();
    assert_eq!(three.compute_convex_hull(false).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(PointCloud::new().unwrap().compute_convex_hull(true).unwrap_err().code, ErrorCode::InvalidArgument);
    let mut nan = cube_corners_and_interior();
    nan[0][2] = f64::NAN;
    let nan = PointCloud::from_points(&nan).unwrap();
    assert_eq!(nan.compute_convex_hull(false).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn hidden_point_removal_keeps_the_side_facing_the_camera() {
    // A sphere of radius 1 seen from (0, 0, 10): only points with z > 0.1 are visible.
    let sphere = TriangleMesh::create_sphere(1.0, 20).unwrap();
    let pts = sphere.vertices().unwrap().to_vec();
    let cloud = PointCloud::from_points(&pts).unwrap();
    let (mesh, visible) = cloud.hidden_point_removal([0.0, 0.0, 10.0], 1000.0).unwrap();
    assert_eq!(visible.len(), mesh.num_vertices().unwrap());
    assert!(!visible.is_empty());
    for (v, &i) in mesh.vertices().unwrap().iter().zip(&visible) {
        assert_eq!(*v, pts[i as usize]);
        assert!(pts[i as usize][2] > 0.0, "hidden point {i} {:?} reported visible", pts[i as usize]);
    }
    let north = pts.iter().position(|p| p[2] > 1.0 - 1e-12).unwrap() as i32;
    let south = pts.iter().position(|p| p[2] < -1.0 + 1e-12).unwrap() as i32;
    assert!(visible.contains(&north));
    assert!(!visible.contains(&south));
    // Most of the upper cap (z > 0.2) is seen.
    let cap = pts.iter().filter(|p| p[2] > 0.2).count();
    let seen_cap = visible.iter().filter(|&&i| pts[i as usize][2] > 0.2).count();
    assert!(seen_cap * 10 >= cap * 9, "{seen_cap} of {cap}");

    assert_eq!(cloud.hidden_point_removal([0.0, 0.0, 10.0], 0.0).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(cloud.hidden_point_removal([f64::NAN, 0.0, 10.0], 100.0).unwrap_err().code, ErrorCode::InvalidArgument);
}
