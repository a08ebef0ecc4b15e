//! TetraMesh: arrays in and out, the Delaunay tetrahedralization of a cube's corners (its tetrahedra
//! fill the unit cube: volume 1), the iso-surface of a linear field (a plane), errors.
mod common;

use common::*;
use o3d::{ErrorCode, PointCloud, TetraMesh};

/// The unit cube's 8 corners.
fn cube_corners() -> Vec<[f64; 3]> {
    (0..8).map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, ((i >> 2) & 1) as f64]).collect()
}

/// Unsigned volume of each tetrahedron.
fn tetra_volumes(mesh: &TetraMesh) -> Vec<f64> {
    let v = mesh.vertices().unwrap();
    let volume = |t: &[i32; 4]| {
        let [a, b, c, d] = t.map(|i| v[i as usize]);
        dot(sub(b, a), cross(sub(c, a), sub(d, a))).abs() / 6.0
    };
    mesh.tetras().unwrap().iter().map(volume).collect()
}

#[test]
fn arrays_round_trip_and_clone_is_deep() {
    let mut mesh = TetraMesh::new().unwrap();
    assert!(!mesh.has_vertices().unwrap() && !mesh.has_tetras().unwrap());
    assert_eq!((mesh.num_vertices().unwrap(), mesh.num_tetras().unwrap()), (0, 0));
    let vertices = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0]];
    let tetras = [[0, 1, 2, 3], [1, 2, 3, 4]];
    mesh.set_vertices(&vertices).unwrap();
    mesh.set_tetras(&tetras).unwrap();
    assert!(mesh.has_vertices().unwrap() && mesh.has_tetras().unwrap());
    assert_eq!((mesh.num_vertices().unwrap(), mesh.num_tetras().unwrap()), (5, 2));
    assert_eq!(mesh.vertices().unwrap(), &vertices);
    assert_eq!(mesh.tetras().unwrap(), &tetras);
    assert_eq!(mesh.vertices_to_vec().unwrap(), vertices);
    assert_eq!(mesh.tetras_to_vec().unwrap(), tetras);
    assert_eq!(format!("{mesh:?}"), "TetraMesh { vertices: 5, tetras: 2 }");

    let copy = mesh.clone();
    mesh.vertices_mut().unwrap()[0] = [-1.0, -1.0, -1.0];
    mesh.tetras_mut().unwrap()[1][0] = 0;
    assert_eq!(copy.vertices().unwrap(), &vertices);
    assert_eq!(copy.tetras().unwrap(), &tetras);
    assert_eq!(mesh.vertices().unwrap()[0], [-1.0, -1.0, -1.0]);
    assert_eq!(mesh.tetras().unwrap()[1], [0, 2, 3, 4]);

    mesh.set_vertices_f32(&[[0.5, 0.25, 0.125]]).unwrap();
    assert_eq!(mesh.vertices().unwrap(), &[[0.5, 0.25, 0.125]]);
    let built = TetraMesh::from_vertices_and_tetras(&vertices, &tetras).unwrap();
    assert_eq!(built.tetras().unwrap(), &tetras);
    // Moved to another thread and dropped there.
    let n = std::thread::spawn(move || built.num_tetras().unwrap()).join().unwrap();
    assert_eq!(n, 2);
}

#[test]
fn delaunay_of_a_cube_fills_the_cube() {
    let corners = cube_corners();
    let cloud = PointCloud::from_points(&corners).unwrap();
    let (mesh, point_map) = TetraMesh::create_from_point_cloud(&cloud).unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 8);
    // Each vertex is the input point the map names, and every corner is used once.
    assert_eq!(point_map.len(), 8);
    for (v, &i) in mesh.vertices().unwrap().iter().zip(&point_map) {
        assert_eq!(*v, corners[i as usize]);
    }
    let mut sorted = point_map.clone();
    sorted.sort();
    assert_eq!(sorted, (0..8).collect::<Vec<i32>>());
    // A cube splits into 5 or 6 tetrahedra (more only as flat slivers of no volume) of total volume 1.
    let volumes = tetra_volumes(&mesh);
    assert_eq!(volumes.len(), mesh.num_tetras().unwrap());
    let solid = volumes.iter().filter(|&&v| v > 1e-12).count();
    assert!(solid == 5 || solid == 6, "{volumes:?}");
    assert!((volumes.iter().sum::<f64>() - 1.0).abs() < 1e-9, "{volumes:?}");
}

#[test]
fn iso_surface_of_a_linear_field_is_a_plane() {
    // Interior points as well, so the cut crosses tetrahedra of several shapes.
    let mut points = cube_corners();
    points.extend(Rng::new(3).points(20, 0.1, 0.9));
    let cloud = PointCloud::from_points(&points).unwrap();
    let (mesh, _) = TetraMesh::create_from_point_cloud(&cloud).unwrap();
    assert!((tetra_volumes(&mesh).iter().sum::<f64>() - 1.0).abs() < 1e-9);
    let values: Vec<f64> = mesh.vertices().unwrap().iter().map(|v| v[0] + 2.0 * v[1]).collect();
    // x + 2y = 1 cuts the unit cube in a rectangle of sides 1 and sqrt(1 + 1/4): area sqrt(5) / 2.
    let cut = mesh.extract_triangle_mesh(&values, 1.0).unwrap();
    assert!(cut.num_triangles().unwrap() >= 2);
    for v in cut.vertices().unwrap() {
        assert!((v[0] + 2.0 * v[1] - 1.0).abs() < 1e-12, "{v:?} is off the plane");
    }
    let area = cut.get_surface_area().unwrap();
    assert!((area - 5f64.sqrt() / 2.0).abs() < 1e-9, "area {area}");
    // A level above every value: no surface.
    let none = mesh.extract_triangle_mesh(&values, 10.0).unwrap();
    assert_eq!(none.num_triangles().unwrap(), 0);
}

fn invalid<T>(r: o3d::Result<T>) {
    assert_eq!(r.map(|_| ()).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn bad_input_is_invalid_argument() {
    // Fewer than 4 points; coplanar points; a NaN point.
    let flat = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [0.5, 0.5, 0.0]];
    invalid(TetraMesh::create_from_point_cloud(&PointCloud::from_points(&flat[..3]).unwrap()));
    invalid(TetraMesh::create_from_point_cloud(&PointCloud::from_points(&flat).unwrap()));
    let mut nan = cube_corners();
    nan[2][1] = f64::NAN;
    invalid(TetraMesh::create_from_point_cloud(&PointCloud::from_points(&nan).unwrap()));

    let corners = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let mesh = TetraMesh::from_vertices_and_tetras(&corners, &[[0, 1, 2, 3]]).unwrap();
    // One value per vertex, all finite; a finite level.
    invalid(mesh.extract_triangle_mesh(&[0.0, 1.0, 1.0], 0.5));
    invalid(mesh.extract_triangle_mesh(&[0.0, 1.0, f64::NAN, 1.0], 0.5));
    invalid(mesh.extract_triangle_mesh(&[0.0, 1.0, 1.0, 1.0], f64::INFINITY));
    // A tetra index out of range is caught before it is followed.
    let bad = TetraMesh::from_vertices_and_tetras(&corners, &[[0, 1, 2, 7]]).unwrap();
    invalid(bad.extract_triangle_mesh(&[0.0, 1.0, 1.0, 1.0], 0.5));
}
