//! Removing a mesh's vertices or triangles by index or mask: what stays keeps its order and attributes,
//! triangles are renumbered onto the kept vertices, and bad input leaves the mesh unchanged.
use o3d::{ErrorCode, TriangleMesh};

const VERTICES: [[f64; 3]; 5] = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0], [0.5, 2.0, 0.0]];

/// A unit square (two triangles) and a roof triangle on its top edge; vertex `i` colored `[i / 10; 3]`.
fn square_and_roof() -> TriangleMesh {
    let mut mesh = TriangleMesh::from_vertices_and_triangles(&VERTICES, &[[0, 1, 2], [0, 2, 3], [3, 2, 4]]).unwrap();
    let colors: Vec<[f64; 3]> = (0..5).map(|i| [i as f64 / 10.0; 3]).collect();
    mesh.set_vertex_colors(&colors).unwrap();
    mesh
}

fn assert_unchanged(mesh: &TriangleMesh) {
    assert_eq!(mesh.vertices().unwrap(), &VERTICES);
    assert_eq!(mesh.triangles().unwrap(), &[[0, 1, 2], [0, 2, 3], [3, 2, 4]]);
}

#[test]
fn removing_vertices_drops_their_triangles_and_renumbers_the_rest() {
    let mut mesh = square_and_roof();
    mesh.remove_vertices_by_index(&[1, 1]).unwrap(); // repeats allowed
    assert_eq!(mesh.vertices().unwrap(), &[VERTICES[0], VERTICES[2], VERTICES[3], VERTICES[4]]);
    assert_eq!(mesh.vertex_colors().unwrap(), &[[0.0; 3], [0.2; 3], [0.3; 3], [0.4; 3]]);
    assert_eq!(mesh.triangles().unwrap(), &[[0, 1, 2], [2, 1, 3]]);

    let mut mesh = square_and_roof();
    mesh.remove_vertices_by_mask(&[false, false, false, false, true]).unwrap();
    assert_eq!(mesh.vertices().unwrap(), &VERTICES[..4]);
    assert_eq!(mesh.triangles().unwrap(), &[[0, 1, 2], [0, 2, 3]]);
}

#[test]
fn removing_triangles_keeps_every_vertex() {
    let mut mesh = square_and_roof();
    mesh.remove_triangles_by_index(&[0, 2]).unwrap();
    assert_eq!(mesh.vertices().unwrap(), &VERTICES);
    assert_eq!(mesh.triangles().unwrap(), &[[0, 2, 3]]);

    let mut mesh = square_and_roof();
    mesh.remove_triangles_by_mask(&[false, true, false]).unwrap();
    assert_eq!(mesh.triangles().unwrap(), &[[0, 1, 2], [3, 2, 4]]);
    assert_eq!(mesh.num_vertices().unwrap(), 5);
}

#[test]
fn bad_indices_or_masks_leave_the_mesh_unchanged() {
    let mut mesh = square_and_roof();
    let errors = [
        mesh.remove_vertices_by_index(&[5]).map(|_| ()).unwrap_err(),
        mesh.remove_vertices_by_index(&[-1]).map(|_| ()).unwrap_err(),
        mesh.remove_vertices_by_mask(&[true; 4]).map(|_| ()).unwrap_err(),
        mesh.remove_triangles_by_index(&[3]).map(|_| ()).unwrap_err(),
        mesh.remove_triangles_by_mask(&[true; 4]).map(|_| ()).unwrap_err(),
    ];
    for err in errors {
        assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    }
    assert_unchanged(&mesh);
    // A triangle naming a missing vertex is caught before it is followed.
    let mut bad = TriangleMesh::from_vertices_and_triangles(&VERTICES, &[[0, 1, 9]]).unwrap();
    assert_eq!(bad.remove_vertices_by_index(&[0]).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(bad.num_vertices().unwrap(), 5);
}
