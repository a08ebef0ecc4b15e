//! HalfEdgeTriangleMesh and mesh topology: half-edges, fans and boundary loops of a triangle and a
//! square (worked out by hand), a closed tetrahedron without boundaries, the adjacency list,
//! non-manifold edges and vertices, self-intersecting and intersecting triangles, orient_triangles;
//! bad input is an error.
mod common;

use std::collections::HashMap;

use o3d::{ErrorCode, HalfEdge, HalfEdgeTriangleMesh, TriangleMesh};

fn mesh(vertices: &[[f64; 3]], triangles: &[[i32; 3]]) -> TriangleMesh {
    TriangleMesh::from_vertices_and_triangles(vertices, triangles).unwrap()
}

/// The unit square as two triangles (0, 1, 2) and (0, 2, 3).
fn square() -> TriangleMesh {
    mesh(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2], [0, 2, 3]])
}

/// Three triangles on the edge (0, 1).
fn fin() -> TriangleMesh {
    mesh(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 1.0]],
        &[[0, 1, 2], [1, 0, 3], [0, 1, 4]],
    )
}

fn bad_index() -> TriangleMesh {
    mesh(&[[0.0; 3]], &[[0, 1, 2]])
}

fn invalid<T: std::fmt::Debug>(r: o3d::Result<T>) {
    assert_eq!(r.unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn one_triangle() {
    let tri = mesh(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2]]);
    let he = HalfEdgeTriangleMesh::create_from_triangle_mesh(&tri).unwrap();
    assert_eq!(he.vertices().unwrap().len(), 3);
    assert_eq!(he.triangles().unwrap(), vec![[0, 1, 2]]);
    assert!(he.vertex_colors().unwrap().is_empty());
    for n in he.vertex_normals().unwrap().iter().chain(he.triangle_normals().unwrap().iter()) {
        assert!((n[2] - 1.0).abs() < 1e-12);
    }
    let edges = he.half_edges().unwrap();
    assert_eq!(edges.len(), 3);
    for (k, e) in edges.iter().enumerate() {
        let want = HalfEdge { next: (k + 1) % 3, twin: None, vertex_indices: [k, (k + 1) % 3], triangle_index: 0 };
        assert_eq!(*e, want);
        assert!(e.is_boundary());
    }
    assert_eq!(he.ordered_half_edge_from_vertex().unwrap(), vec![vec![0], vec![1], vec![2]]);
    assert_eq!(he.boundary_half_edges_from_vertex(0).unwrap(), vec![0, 1, 2]);
    assert_eq!(he.boundary_vertices_from_vertex(1).unwrap(), vec![1, 2, 0]);
    assert_eq!(he.get_boundaries().unwrap(), vec![vec![0, 1, 2]]);
    invalid(he.boundary_vertices_from_vertex(3));
    invalid(he.boundary_half_edges_from_vertex(usize::MAX));
}

#[test]
fn square_twins_and_fans() {
    let he = HalfEdgeTriangleMesh::create_from_triangle_mesh(&square()).unwrap();
    let edges = he.half_edges().unwrap();
    assert_eq!(edges.len(), 6);
    // The diagonal: side 2 of triangle 0 (2 -> 0) and side 0 of triangle 1 (0 -> 2) are twins.
    assert_eq!((edges[2].twin, edges[3].twin), (Some(3), Some(2)));
    assert_eq!(edges[3].vertex_indices, [0, 2]);
    assert_eq!(edges.iter().filter(|e| e.is_boundary()).count(), 4);
    // Vertex 0's fan starts at its boundary half-edge 0 -> 1, then turns to 0 -> 2.
    assert_eq!(he.ordered_half_edge_from_vertex().unwrap()[0], vec![0, 3]);
    assert_eq!(he.get_boundaries().unwrap(), vec![vec![0, 1, 2, 3]]);
    assert_eq!(he.boundary_vertices_from_vertex(2).unwrap(), vec![2, 3, 0, 1]);
}

#[test]
fn closed_mesh_has_no_boundary_and_bad_meshes_fail() {
    let he = HalfEdgeTriangleMesh::create_from_triangle_mesh(&TriangleMesh::create_tetrahedron(1.0).unwrap()).unwrap();
    let edges = he.half_edges().unwrap();
    assert_eq!(edges.len(), 12);
    assert!(edges.iter().all(|e| !e.is_boundary()));
    assert!(he.get_boundaries().unwrap().is_empty());
    assert!(he.boundary_vertices_from_vertex(0).unwrap().is_empty());
    assert!(he.ordered_half_edge_from_vertex().unwrap().iter().all(|fan| fan.len() == 3));
    invalid(HalfEdgeTriangleMesh::create_from_triangle_mesh(&fin()));
    invalid(HalfEdgeTriangleMesh::create_from_triangle_mesh(&bad_index()));
}

#[test]
fn adjacency_list() {
    let tetra = TriangleMesh::create_tetrahedron(1.0).unwrap().compute_adjacency_list().unwrap();
    assert_eq!(tetra.len(), 4);
    for (v, list) in tetra.iter().enumerate() {
        assert_eq!(*list, (0..4).filter(|&u| u != v).collect::<Vec<_>>());
    }
    assert_eq!(square().compute_adjacency_list().unwrap(), vec![vec![1, 2, 3], vec![0, 2], vec![0, 1, 3], vec![0, 2]]);
    invalid(bad_index().compute_adjacency_list());
}

#[test]
fn non_manifold_edges_and_vertices() {
    assert!(TriangleMesh::create_tetrahedron(1.0).unwrap().get_non_manifold_edges(false).unwrap().is_empty());
    assert!(square().get_non_manifold_edges(true).unwrap().is_empty());
    assert_eq!(square().get_non_manifold_edges(false).unwrap(), vec![[0, 1], [0, 3], [1, 2], [2, 3]]);
    assert_eq!(fin().get_non_manifold_edges(true).unwrap(), vec![[0, 1]]);
    // Two triangles touching only at vertex 0 (a bow tie).
    let bowtie = mesh(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [-1.0, -1.0, 0.0]],
        &[[0, 1, 2], [0, 3, 4]],
    );
    assert_eq!(bowtie.get_non_manifold_vertices().unwrap(), vec![0]);
    assert!(square().get_non_manifold_vertices().unwrap().is_empty());
    invalid(bad_index().get_non_manifold_edges(true));
    invalid(bad_index().get_non_manifold_vertices());
}

#[test]
fn intersections_and_orientation() {
    // Triangle 1 pierces triangle 0 and shares no vertex with it.
    let crossing = mesh(
        &[[0.0, 0.0, 0.0], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.5, 0.5, -1.0], [0.5, 0.5, 1.0], [1.5, 1.5, 1.0]],
        &[[0, 1, 2], [3, 4, 5]],
    );
    assert_eq!(crossing.get_self_intersecting_triangles().unwrap(), vec![[0, 1]]);
    assert!(square().get_self_intersecting_triangles().unwrap().is_empty());
    invalid(bad_index().get_self_intersecting_triangles());

    let cube = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    let mut near = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    near.translate([0.5, 0.5, 0.5], true).unwrap();
    let mut far = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    far.translate([5.0, 0.0, 0.0], true).unwrap();
    assert!(cube.is_intersecting(&near).unwrap());
    assert!(!cube.is_intersecting(&far).unwrap());

    // The square's second triangle turned over: orienting turns it back.
    let mut flipped =
        mesh(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]], &[[0, 1, 2], [0, 3, 2]]);
    assert!(flipped.orient_triangles().unwrap());
    let triangles = flipped.triangles_to_vec().unwrap();
    let mut directed = HashMap::new();
    for t in &triangles {
        for k in 0..3 {
            *directed.entry((t[k], t[(k + 1) % 3])).or_insert(0) += 1;
        }
    }
    assert!(directed.values().all(|&n| n == 1));
    assert_eq!(triangles[0], [0, 1, 2]);
    let mut mobius = TriangleMesh::create_mobius(|_| {}).unwrap();
    assert!(!mobius.orient_triangles().unwrap());
    invalid(bad_index().orient_triangles());
}
