//! Surface reconstruction: Poisson and ball pivoting of an evenly sampled unit sphere with outward normals
//! (the sphere comes back: radius, volume, area), the alpha shape of a convex sampling at a huge alpha (its
//! convex hull), progress closures and cancel, bad input.
mod common;

use std::f64::consts::PI;
use std::ops::ControlFlow;

use common::*;
use o3d::{ErrorCode, PointCloud, PoissonOptions, ProgressOptions, TetraMesh, TriangleMesh};

/// `n` points on the unit sphere with outward normals.
fn sphere_cloud(n: usize) -> PointCloud {
    let (points, normals) = fibonacci_sphere(n, 1.0);
    let mut cloud = PointCloud::from_points(&points).unwrap();
    cloud.set_normals(&normals).unwrap();
    cloud
}

/// Poisson at depth 6 (cells of 2.2 / 64 = 0.034): fast, and well within a cell of the sphere.
fn poisson_depth_6() -> PoissonOptions {
    PoissonOptions { depth: 6, ..Default::default() }
}

/// The volume the triangles enclose, positive when they are wound outwards (also for a mesh with small
/// holes, or slivers too thin to have a reliable normal of their own).
fn signed_volume(mesh: &TriangleMesh) -> f64 {
    let v = mesh.vertices().unwrap();
    mesh.triangles().unwrap().iter().map(|t| t.map(|i| v[i as usize])).map(|[a, b, c]| dot(a, cross(b, c)) / 6.0).sum()
}

/// Every triangle's normal points away from the origin (inside every convex shape here).
fn assert_outward(mesh: &TriangleMesh) {
    let v = mesh.vertices().unwrap();
    for t in mesh.triangles().unwrap() {
        let [a, b, c] = t.map(|i| v[i as usize]);
        assert!(dot(cross(sub(b, a), sub(c, a)), a) > 0.0, "triangle {t:?} faces inwards");
    }
}

fn invalid<T>(r: o3d::Result<T>) {
    assert_eq!(r.map(|_| ()).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn poisson_of_a_sphere_is_the_sphere() {
    let mut cloud = sphere_cloud(6000);
    cloud.paint_uniform_color([0.2, 0.4, 0.6]).unwrap();
    let (mesh, densities) = TriangleMesh::create_from_point_cloud_poisson(&cloud, &poisson_depth_6()).unwrap();
    let worst = mesh.vertices().unwrap().iter().map(|&v| (norm(v) - 1.0).abs()).fold(0.0, f64::max);
    assert!(worst < 0.035, "a vertex is {worst} off the sphere");
    assert!(mesh.is_watertight().unwrap());
    let volume = mesh.get_volume().unwrap();
    assert!((volume - 4.0 / 3.0 * PI).abs() < 0.05 * 4.0 / 3.0 * PI, "volume {volume}");
    assert!((signed_volume(&mesh) - volume).abs() < 1e-9 * volume, "not wound outwards");
    // One finite density per vertex; the colors are carried.
    assert_eq!(densities.len(), mesh.num_vertices().unwrap());
    assert!(densities.iter().all(|d| d.is_finite()));
    assert!(mesh.has_vertex_colors().unwrap());
    for c in mesh.vertex_colors().unwrap() {
        assert!(dist2(*c, [0.2, 0.4, 0.6]) < 1e-12, "color {c:?}");
    }
    // Open3D's trim: drop the vertices whose density is below a quantile (and their triangles).
    let mut sorted = densities.clone();
    sorted.sort_by(f64::total_cmp);
    let mask: Vec<bool> = densities.iter().map(|&d| d < sorted[sorted.len() / 10]).collect();
    let mut trimmed = mesh.clone();
    trimmed.remove_vertices_by_mask(&mask).unwrap();
    let removed = mask.iter().filter(|&&m| m).count();
    assert_eq!(trimmed.num_vertices().unwrap(), mesh.num_vertices().unwrap() - removed);
}

#[test]
fn poisson_reports_progress_and_cancels() {
    let cloud = sphere_cloud(2000);
    let mut seen = Vec::new();
    let (mesh, _) = TriangleMesh::create_from_point_cloud_poisson_with_progress(&cloud, &poisson_depth_6(), |f| {
        seen.push(f);
        ControlFlow::Continue(())
    })
    .unwrap();
    assert!(mesh.num_triangles().unwrap() > 0);
    assert!(!seen.is_empty());
    assert!(seen.iter().all(|f| (0.0..=1.0).contains(f)), "{seen:?}");
    let mut calls = 0;
    let err = TriangleMesh::create_from_point_cloud_poisson_with_progress(&cloud, &poisson_depth_6(), |_| {
        calls += 1;
        ControlFlow::Break(())
    })
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");
    assert_eq!(calls, 1, "no callback after cancelling");
}

#[test]
fn poisson_bad_input_is_invalid_argument() {
    let cloud = sphere_cloud(500);
    for depth in [0, 20] {
        invalid(TriangleMesh::create_from_point_cloud_poisson(&cloud, &PoissonOptions { depth, ..Default::default() }));
    }
    let nan_scale = PoissonOptions { scale: f64::NAN, ..poisson_depth_6() };
    invalid(TriangleMesh::create_from_point_cloud_poisson(&cloud, &nan_scale));
    // No normals; no points.
    let bare = PointCloud::from_points(&[[0.0; 3], [1.0, 0.0, 0.0]]).unwrap();
    invalid(TriangleMesh::create_from_point_cloud_poisson(&bare, &poisson_depth_6()));
    invalid(TriangleMesh::create_from_point_cloud_poisson(&PointCloud::new().unwrap(), &poisson_depth_6()));
    // A too-large count is refused before the call.
    let huge = PoissonOptions { depth: usize::MAX, ..Default::default() };
    invalid(TriangleMesh::create_from_point_cloud_poisson(&cloud, &huge));
}

#[test]
fn ball_pivoting_of_a_sphere_covers_it() {
    // 4000 evenly spread points: spacing about sqrt(4 pi / 4000) = 0.056.
    let cloud = sphere_cloud(4000);
    let mesh = TriangleMesh::create_from_point_cloud_ball_pivoting(&cloud, &[0.06, 0.09], &ProgressOptions::default())
        .unwrap();
    // The vertices are the points, with their normals.
    assert_eq!(mesh.vertices().unwrap(), cloud.points());
    assert_eq!(mesh.vertex_normals().unwrap(), cloud.normals());
    // A closed triangulation of 4000 points has 7996 triangles; pivoting leaves at most small holes.
    let triangles = mesh.num_triangles().unwrap();
    assert!(triangles > 7600 && triangles <= 7996, "{triangles} triangles");
    let area = mesh.get_surface_area().unwrap();
    assert!((area - 4.0 * PI).abs() < 0.03 * 4.0 * PI, "area {area}");
    // Wound to agree with the (outward) normals: the enclosed volume comes out positive, near 4 pi / 3.
    let volume = signed_volume(&mesh);
    assert!((volume - 4.0 / 3.0 * PI).abs() < 0.05 * 4.0 / 3.0 * PI, "signed volume {volume}");
}

#[test]
fn ball_pivoting_progress_and_bad_input() {
    let cloud = sphere_cloud(1000);
    let radii = [0.12, 0.18];
    let options = ProgressOptions { num_threads: 1 }; // the result does not depend on it
    let mut calls = 0;
    let mesh = TriangleMesh::create_from_point_cloud_ball_pivoting_with_progress(&cloud, &radii, &options, |f| {
        assert!((0.0..=1.0).contains(&f), "fraction {f}");
        calls += 1;
        ControlFlow::Continue(())
    })
    .unwrap();
    assert!(calls > 0 && mesh.num_triangles().unwrap() > 0);
    let err = TriangleMesh::create_from_point_cloud_ball_pivoting_with_progress(&cloud, &radii, &options, |_| {
        ControlFlow::Break(())
    })
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");

    let defaults = ProgressOptions::default();
    invalid(TriangleMesh::create_from_point_cloud_ball_pivoting(&cloud, &[-0.1], &defaults));
    invalid(TriangleMesh::create_from_point_cloud_ball_pivoting(&cloud, &[0.1, f64::NAN], &defaults));
    invalid(TriangleMesh::create_from_point_cloud_ball_pivoting(&cloud, &[], &defaults));
    let bare = PointCloud::from_points(cloud.points()).unwrap();
    invalid(TriangleMesh::create_from_point_cloud_ball_pivoting(&bare, &radii, &defaults));
}

/// Points inside the unit ball and on its surface, at random (a convex sampling in general position: no
/// four hull points coplanar, so the hull's triangles are unique).
fn ball_sampling() -> PointCloud {
    let random = Rng::new(11).points(800, -1.0, 1.0);
    let mut points: Vec<[f64; 3]> = random.iter().copied().filter(|&p| norm(p) < 0.9).take(150).collect();
    let on_sphere = random.iter().filter(|&&p| norm(p) > 0.1).map(|&p| p.map(|c| c / norm(p)));
    points.extend(on_sphere.take(200));
    PointCloud::from_points(&points).unwrap()
}

#[test]
fn alpha_shape_at_a_huge_alpha_is_the_convex_hull() {
    let cloud = ball_sampling();
    let (hull, _) = cloud.compute_convex_hull(false).unwrap();
    let options = ProgressOptions::default();
    let shape = TriangleMesh::create_from_point_cloud_alpha_shape(&cloud, 1e3, None, &options).unwrap();
    assert_eq!(shape.num_triangles().unwrap(), hull.num_triangles().unwrap());
    assert!((shape.get_volume().unwrap() - hull.get_volume().unwrap()).abs() < 1e-9);
    assert!((shape.get_surface_area().unwrap() - hull.get_surface_area().unwrap()).abs() < 1e-9);
    assert!(shape.is_watertight().unwrap());
    assert_outward(&shape);

    // Reusing the tetrahedralization gives the same shape.
    let (tetras, point_map) = TetraMesh::create_from_point_cloud(&cloud).unwrap();
    let reused =
        TriangleMesh::create_from_point_cloud_alpha_shape(&cloud, 1e3, Some((&tetras, &point_map)), &options).unwrap();
    assert_eq!(reused.num_triangles().unwrap(), shape.num_triangles().unwrap());
    assert!((reused.get_volume().unwrap() - shape.get_volume().unwrap()).abs() < 1e-9);

    // A smaller alpha keeps fewer tetrahedra: less volume (the shape need not be a manifold then, but its
    // outward triangles still bound the kept tetrahedra); a tiny one keeps none.
    let smaller = TriangleMesh::create_from_point_cloud_alpha_shape(&cloud, 0.15, None, &options).unwrap();
    let kept = signed_volume(&smaller);
    assert!(kept > 0.0 && kept < shape.get_volume().unwrap() - 0.1, "volume {kept}");
    let tiny = TriangleMesh::create_from_point_cloud_alpha_shape(&cloud, 1e-4, None, &options).unwrap();
    assert_eq!(tiny.num_triangles().unwrap(), 0);
}

#[test]
fn alpha_shape_progress_and_bad_input() {
    let cloud = ball_sampling();
    let options = ProgressOptions::default();
    let mut calls = 0;
    TriangleMesh::create_from_point_cloud_alpha_shape_with_progress(&cloud, 0.5, None, &options, |_| {
        calls += 1;
        ControlFlow::Continue(())
    })
    .unwrap();
    assert!(calls > 0);
    let err = TriangleMesh::create_from_point_cloud_alpha_shape_with_progress(&cloud, 0.5, None, &options, |_| {
        ControlFlow::Break(())
    })
    .unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled, "{err}");

    for alpha in [0.0, -1.0, f64::NAN] {
        invalid(TriangleMesh::create_from_point_cloud_alpha_shape(&cloud, alpha, None, &options));
    }
    // A point map that does not fit the tetra mesh: short, or naming a point the cloud lacks.
    let (tetras, mut point_map) = TetraMesh::create_from_point_cloud(&cloud).unwrap();
    let short = &point_map[..point_map.len() - 1];
    invalid(TriangleMesh::create_from_point_cloud_alpha_shape(&cloud, 0.5, Some((&tetras, short)), &options));
    point_map[0] = cloud.len() as i32;
    invalid(TriangleMesh::create_from_point_cloud_alpha_shape(&cloud, 0.5, Some((&tetras, &point_map)), &options));
    // Coplanar points have no tetrahedra.
    let flat = PointCloud::from_points(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0]]).unwrap();
    invalid(TriangleMesh::create_from_point_cloud_alpha_shape(&flat, 1.0, None, &options));
}
