//! TriangleMesh: container, views, primitives (analytic areas/volumes/topology), clean-up,
//! processing, I/O round trips and errors.
mod common;

use common::*;
use o3d::io::{self, MeshReadOptions, MeshWriteOptions};
use o3d::{ErrorCode, FilterScope, Image, MeshArray, PixelType, SimplificationContraction, TriangleMesh};

fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol
}

/// Two triangles sharing an edge: the unit square in z = 0.
fn unit_square() -> TriangleMesh {
    TriangleMesh::from_vertices_and_triangles(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
        &[[0, 1, 2], [0, 2, 3]],
    )
    .unwrap()
}

#[test]
fn box_has_analytic_area_volume_and_topology() {
    let mesh = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 8);
    assert_eq!(mesh.num_triangles().unwrap(), 12);
    assert!(close(mesh.get_surface_area().unwrap(), 6.0, 1e-12));
    assert!(close(mesh.get_volume().unwrap(), 1.0, 1e-12));
    assert!(mesh.is_watertight().unwrap());
    assert!(mesh.is_edge_manifold(false).unwrap());
    assert!(mesh.is_vertex_manifold().unwrap());
    assert!(mesh.is_orientable().unwrap());
    assert!(!mesh.is_self_intersecting().unwrap());
    assert_eq!(mesh.euler_poincare_characteristic().unwrap(), 2);
    assert_eq!(mesh.get_axis_aligned_bounding_box().unwrap(), ([0.0; 3], [1.0; 3]));

    let slab = TriangleMesh::create_box(2.0, 3.0, 0.5).unwrap();
    assert!(close(slab.get_surface_area().unwrap(), 2.0 * (6.0 + 1.0 + 1.5), 1e-12));
    assert!(close(slab.get_volume().unwrap(), 3.0, 1e-12));
    assert_eq!(slab.get_max_bound().unwrap(), [2.0, 3.0, 0.5]);
}

#[test]
fn platonic_solids_and_round_primitives() {
    for (mesh, v, f) in [
        (TriangleMesh::create_tetrahedron(1.0).unwrap(), 4, 4),
        (TriangleMesh::create_octahedron(1.0).unwrap(), 6, 8),
        (TriangleMesh::create_icosahedron(1.0).unwrap(), 12, 20),
    ] {
        assert_eq!(mesh.num_vertices().unwrap(), v);
        assert_eq!(mesh.num_triangles().unwrap(), f);
        assert_eq!(mesh.euler_poincare_characteristic().unwrap(), 2);
        // Inscribed in the unit sphere.
        for p in mesh.vertices().unwrap() {
            assert!(close(norm(*p), 1.0, 1e-12), "{p:?}");
        }
    }
    // Octahedron of radius 1: volume 4/3, area 4 sqrt(3).
    let octa = TriangleMesh::create_octahedron(1.0).unwrap();
    assert!(close(octa.get_volume().unwrap(), 4.0 / 3.0, 1e-12));
    assert!(close(octa.get_surface_area().unwrap(), 4.0 * 3f64.sqrt(), 1e-12));

    let sphere = TriangleMesh::create_sphere(2.0, 20).unwrap();
    assert!(sphere.is_watertight().unwrap());
    let volume = sphere.get_volume().unwrap();
    let exact = 4.0 / 3.0 * std::f64::consts::PI * 8.0;
    assert!(volume < exact && volume > 0.95 * exact, "{volume} vs {exact}");
    let torus = TriangleMesh::create_torus(1.0, 0.5, 30, 20).unwrap();
    assert_eq!(torus.euler_poincare_characteristic().unwrap(), 0);
    let frame = TriangleMesh::create_coordinate_frame(1.0, Some([1.0, 2.0, 3.0])).unwrap();
    assert!(frame.has_vertex_colors().unwrap());
    assert!(TriangleMesh::create_cylinder(1.0, 2.0, 20, 4).unwrap().is_watertight().unwrap());
    assert!(TriangleMesh::create_cone(1.0, 2.0, 20, 1).unwrap().is_watertight().unwrap());
    assert!(TriangleMesh::create_arrow(1.0, 1.5, 5.0, 4.0, 20, 4, 1).unwrap().num_triangles().unwrap() > 0);
}

#[test]
fn primitives_reject_bad_parameters() {
    for r in [TriangleMesh::create_box(-1.0, 1.0, 1.0), TriangleMesh::create_box(f64::NAN, 1.0, 1.0)] {
        assert_eq!(r.unwrap_err().code, ErrorCode::InvalidArgument);
    }
    assert_eq!(TriangleMesh::create_sphere(0.0, 20).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(TriangleMesh::create_sphere(1.0, 0).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn arrays_round_trip_through_views_and_copies() {
    let mut mesh = unit_square();
    assert!(mesh.has_vertices().unwrap() && mesh.has_triangles().unwrap());
    assert!(!mesh.has_vertex_normals().unwrap());
    assert_eq!(mesh.triangles().unwrap(), &[[0, 1, 2], [0, 2, 3]]);
    assert_eq!(mesh.triangles_to_vec().unwrap(), vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(mesh.array_to_vec(MeshArray::Vertices).unwrap(), mesh.vertices().unwrap().to_vec());

    mesh.set_vertex_colors(&[[1.0, 0.0, 0.0]; 4]).unwrap();
    assert!(mesh.has_vertex_colors().unwrap());
    // A wrong row count is stored but does not count (Open3D semantics).
    mesh.set_vertex_normals(&[[0.0, 0.0, 1.0]; 3]).unwrap();
    assert!(!mesh.has_array(MeshArray::VertexNormals).unwrap());

    let uvs: Vec<[f64; 2]> = (0..6).map(|i| [i as f64 / 10.0, 1.0 - i as f64 / 10.0]).collect();
    mesh.set_triangle_uvs(&uvs).unwrap();
    assert!(mesh.has_triangle_uvs().unwrap());
    assert_eq!(mesh.triangle_uvs().unwrap(), uvs.as_slice());
    assert_eq!(mesh.triangle_uvs_to_vec().unwrap(), uvs);
    mesh.set_triangle_material_ids(&[0, 1]).unwrap();
    assert!(mesh.has_triangle_material_ids().unwrap());
    assert_eq!(mesh.triangle_material_ids().unwrap(), &[0, 1]);
    mesh.triangle_material_ids_mut().unwrap()[1] = 7;
    assert_eq!(mesh.triangle_material_ids_to_vec().unwrap(), vec![0, 7]);
    mesh.triangle_uvs_mut().unwrap()[0] = [0.5, 0.5];
    assert_eq!(mesh.triangle_uvs().unwrap()[0], [0.5, 0.5]);

    mesh.vertices_mut().unwrap()[2] = [2.0, 2.0, 0.0];
    mesh.array_mut(MeshArray::VertexColors).unwrap()[0] = [0.0, 1.0, 0.0];
    mesh.triangles_mut().unwrap()[1] = [0, 3, 2];
    assert_eq!(mesh.vertices().unwrap()[2], [2.0, 2.0, 0.0]);
    assert_eq!(mesh.vertex_colors().unwrap()[0], [0.0, 1.0, 0.0]);
    assert_eq!(mesh.triangles().unwrap()[1], [0, 3, 2]);

    let copy = mesh.clone();
    mesh.clear().unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 0);
    assert!(mesh.vertices().unwrap().is_empty());
    assert_eq!(copy.num_triangles().unwrap(), 2);
}

#[test]
fn out_of_range_triangles_are_errors_not_crashes() {
    let mut mesh = unit_square();
    mesh.set_triangles(&[[0, 1, 9]]).unwrap();
    assert_eq!(mesh.get_surface_area().unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(mesh.compute_vertex_normals(true).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(mesh.sample_points_uniformly(10, false, 1).unwrap_err().code, ErrorCode::InvalidArgument);
    mesh.set_triangles(&[[0, -1, 2]]).unwrap();
    assert_eq!(mesh.remove_unreferenced_vertices().unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn normals_of_the_square_point_up() {
    let mut mesh = unit_square();
    mesh.compute_triangle_normals(true).unwrap();
    mesh.compute_vertex_normals(true).unwrap();
    for n in mesh.triangle_normals().unwrap().iter().chain(mesh.vertex_normals().unwrap()) {
        assert!(close(n[0], 0.0, 1e-12) && close(n[1], 0.0, 1e-12) && close(n[2], 1.0, 1e-12), "{n:?}");
    }
    mesh.paint_uniform_color([0.25, 0.5, 0.75]).unwrap();
    assert!(mesh.vertex_colors().unwrap().iter().all(|c| *c == [0.25, 0.5, 0.75]));
}

#[test]
fn transforms_move_the_bounds() {
    let mut mesh = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    assert_eq!(mesh.get_center().unwrap(), [0.5; 3]);
    mesh.translate([1.0, 2.0, 3.0], true).unwrap();
    assert_eq!(mesh.get_min_bound().unwrap(), [1.0, 2.0, 3.0]);
    mesh.translate([0.0; 3], false).unwrap();
    assert_eq!(mesh.get_center().unwrap(), [0.0; 3]);
    mesh.scale(2.0, None).unwrap();
    assert_eq!(mesh.get_axis_aligned_bounding_box().unwrap(), ([-1.0; 3], [1.0; 3]));
    // 90 degrees about z: (x, y) -> (-y, x).
    let rz = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
    mesh.scale(0.5, Some([0.0; 3])).unwrap().translate([0.5, 0.0, 0.0], true).unwrap();
    mesh.rotate(&rz, Some([0.0; 3])).unwrap();
    let (lo, hi) = mesh.get_axis_aligned_bounding_box().unwrap();
    assert!(close(lo[1], 0.0, 1e-12) && close(hi[1], 1.0, 1e-12) && close(lo[0], -0.5, 1e-12), "{lo:?} {hi:?}");
    let mut t = [[0.0; 4]; 4];
    for (i, row) in t.iter_mut().enumerate() {
        row[i] = 1.0;
    }
    t[2][3] = 10.0;
    mesh.transform(&t).unwrap();
    assert!(close(mesh.get_min_bound().unwrap()[2], 9.5, 1e-12));
}

#[test]
fn clean_up_merges_and_removes() {
    // Two triangles over four vertices where vertex 3 duplicates vertex 0, a degenerate triangle,
    // a duplicated triangle and an unreferenced vertex.
    let mut mesh = TriangleMesh::from_vertices_and_triangles(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [5.0, 5.0, 5.0]],
        &[[0, 1, 2], [3, 2, 1], [1, 1, 2], [2, 1, 0]],
    )
    .unwrap();
    mesh.remove_duplicated_vertices().unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 4);
    mesh.remove_degenerate_triangles().unwrap();
    assert_eq!(mesh.num_triangles().unwrap(), 3);
    mesh.remove_duplicated_triangles().unwrap();
    assert_eq!(mesh.num_triangles().unwrap(), 1);
    mesh.remove_unreferenced_vertices().unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 3);
    assert!(close(mesh.get_surface_area().unwrap(), 0.5, 1e-15));

    let mut close_pair = unit_square();
    close_pair.set_vertices(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [1.0 + 1e-4, 1.0, 0.0]]).unwrap();
    close_pair.merge_close_vertices(1e-3).unwrap();
    assert_eq!(close_pair.num_vertices().unwrap(), 3);
    assert_eq!(TriangleMesh::new().unwrap().merge_close_vertices(-1.0).unwrap_err().code, ErrorCode::InvalidArgument);

    // Three triangles on one edge: one must go.
    let mut fan = TriangleMesh::from_vertices_and_triangles(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, 2.0]],
        &[[0, 1, 2], [1, 0, 3], [0, 1, 4]],
    )
    .unwrap();
    assert!(!fan.is_edge_manifold(true).unwrap());
    fan.remove_non_manifold_edges().unwrap();
    assert_eq!(fan.num_triangles().unwrap(), 2);
    assert!(fan.is_edge_manifold(true).unwrap());
}

#[test]
fn clusters_of_two_disjoint_pieces() {
    let mut mesh = unit_square();
    let mut other = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    other.translate([5.0, 0.0, 0.0], true).unwrap();
    mesh.append(&other).unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 12);
    assert_eq!(mesh.num_triangles().unwrap(), 14);
    let clusters = mesh.cluster_connected_triangles().unwrap();
    assert_eq!(clusters.triangle_clusters.len(), 14);
    assert_eq!(&clusters.triangle_clusters[..2], &[0, 0]);
    assert!(clusters.triangle_clusters[2..].iter().all(|&c| c == 1));
    assert_eq!(clusters.cluster_n_triangles, vec![2, 12]);
    assert!(close(clusters.cluster_area[0], 1.0, 1e-12) && close(clusters.cluster_area[1], 6.0, 1e-12));
}

#[test]
fn sampling_is_on_the_surface_and_seeded() {
    let mesh = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    let a = mesh.sample_points_uniformly(500, true, 7).unwrap();
    let b = mesh.sample_points_uniformly(500, true, 7).unwrap();
    assert_eq!(a.len(), 500);
    assert_eq!(a.points(), b.points());
    assert!(a.has_normals().unwrap());
    for p in a.points() {
        let on_face = p.iter().any(|&c| close(c, 0.0, 1e-12) || close(c, 1.0, 1e-12));
        assert!(on_face && p.iter().all(|&c| (-1e-12..=1.0 + 1e-12).contains(&c)), "{p:?}");
    }
    let poisson = mesh.sample_points_poisson_disk(100, 5.0, false, 3).unwrap();
    assert_eq!(poisson.len(), 100);
    assert_eq!(mesh.sample_points_poisson_disk(100, 0.5, false, 3).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn processing_counts() {
    let box_mesh = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    let mid = box_mesh.subdivide_midpoint(1).unwrap();
    assert_eq!(mid.num_triangles().unwrap(), 48);
    assert_eq!(mid.num_vertices().unwrap(), 8 + 18);
    assert!(close(mid.get_surface_area().unwrap(), 6.0, 1e-12));
    let looped = box_mesh.subdivide_loop(2).unwrap();
    assert_eq!(looped.num_triangles().unwrap(), 12 * 16);
    assert!(looped.is_watertight().unwrap());

    let sphere = TriangleMesh::create_sphere(1.0, 20).unwrap();
    let n = sphere.num_triangles().unwrap();
    let decimated = sphere.simplify_quadric_decimation(n / 4, f64::INFINITY, 1.0).unwrap();
    assert!(decimated.num_triangles().unwrap() <= n / 4);
    let clustered = sphere.simplify_vertex_clustering(0.5, SimplificationContraction::Average).unwrap();
    assert!(clustered.num_vertices().unwrap() < sphere.num_vertices().unwrap());
    let quadric = sphere.simplify_vertex_clustering(0.5, SimplificationContraction::Quadric).unwrap();
    assert!(quadric.num_vertices().unwrap() < sphere.num_vertices().unwrap());

    for smooth in [
        sphere.filter_smooth_simple(2, FilterScope::All).unwrap(),
        sphere.filter_smooth_laplacian(2, 0.5, FilterScope::Vertex).unwrap(),
        sphere.filter_smooth_taubin(2, 0.5, -0.53, FilterScope::All).unwrap(),
    ] {
        assert_eq!(smooth.num_vertices().unwrap(), sphere.num_vertices().unwrap());
        assert_eq!(smooth.triangles().unwrap(), sphere.triangles().unwrap());
    }
    // Simple smoothing pulls every vertex of a convex sphere inwards.
    let simple = sphere.filter_smooth_simple(1, FilterScope::Vertex).unwrap();
    assert!(simple.vertices().unwrap().iter().all(|p| norm(*p) < 1.0 + 1e-12));

    let cropped = box_mesh.crop_aabb([-0.1, -0.1, -0.1], [1.1, 1.1, 0.5]).unwrap();
    // Only the z = 0 face has all three vertices in the box.
    assert_eq!(cropped.num_triangles().unwrap(), 2);
    assert_eq!(cropped.num_vertices().unwrap(), 4);
    assert_eq!(
        box_mesh.simplify_vertex_clustering(0.0, SimplificationContraction::Average).unwrap_err().code,
        ErrorCode::InvalidArgument
    );
}

#[test]
fn ply_round_trip_in_memory() {
    let mut mesh = TriangleMesh::create_box(1.0, 2.0, 3.0).unwrap();
    mesh.compute_vertex_normals(true).unwrap();
    mesh.paint_uniform_color([1.0, 0.0, 0.0]).unwrap();
    for ascii in [false, true] {
        let opts = MeshWriteOptions { write_ascii: ascii, ..Default::default() };
        let bytes = io::write_triangle_mesh_to_memory(&mesh, "ply", &opts).unwrap();
        assert!(bytes.starts_with(b"ply"));
        let back = io::read_triangle_mesh_from_memory(&bytes, "ply", &MeshReadOptions::default()).unwrap();
        assert_eq!(back.vertices().unwrap(), mesh.vertices().unwrap());
        assert_eq!(back.triangles().unwrap(), mesh.triangles().unwrap());
        assert!(back.has_vertex_normals().unwrap());
        assert_eq!(back.vertex_colors().unwrap(), mesh.vertex_colors().unwrap());
        assert!(close(back.get_volume().unwrap(), 6.0, 1e-12));
    }
    let bare = MeshWriteOptions { write_vertex_normals: false, write_vertex_colors: false, ..Default::default() };
    let back = io::read_triangle_mesh_from_memory(
        io::write_triangle_mesh_to_buffer(&mesh, "ply", &bare).unwrap().as_bytes().unwrap(),
        "ply",
        &MeshReadOptions::default(),
    )
    .unwrap();
    assert!(!back.has_vertex_normals().unwrap() && !back.has_vertex_colors().unwrap());
}

#[test]
fn other_formats_round_trip_through_files() {
    let dir = TempDir::new("mesh");
    let mesh = TriangleMesh::create_octahedron(1.0).unwrap();
    for ext in ["ply", "obj", "stl", "off", "glb"] {
        let path = dir.path(&format!("octa.{ext}"));
        io::write_triangle_mesh(&path, &mesh, "auto", &MeshWriteOptions::default()).unwrap();
        let opts = MeshReadOptions { enable_post_processing: true };
        let back = io::read_triangle_mesh(&path, "auto", &opts).unwrap();
        assert_eq!(back.num_triangles().unwrap(), 8, "{ext}");
        assert_eq!(back.num_vertices().unwrap(), 6, "{ext}");
        assert!(close(back.get_surface_area().unwrap(), 4.0 * 3f64.sqrt(), 1e-6), "{ext}");
    }
}

#[test]
fn textures_are_copied_in_and_out() {
    let mut mesh = unit_square();
    let mut tex = Image::new(2, 2, 3, PixelType::U8).unwrap();
    tex.data_mut().unwrap().copy_from_slice(&[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12]);
    mesh.add_texture(&tex).unwrap();
    mesh.add_texture(&tex).unwrap();
    assert_eq!(mesh.texture_count().unwrap(), 2);
    assert_eq!(mesh.texture(1).unwrap().data().unwrap(), tex.data().unwrap());
    assert_eq!(mesh.textures().unwrap().len(), 2);
    assert_eq!(mesh.texture(2).unwrap_err().code, ErrorCode::InvalidArgument);
    mesh.clear_textures().unwrap();
    assert_eq!(mesh.texture_count().unwrap(), 0);
}

#[test]
fn io_errors() {
    let garbage = b"not a mesh at all";
    assert!(io::read_triangle_mesh_from_memory(garbage, "ply", &Default::default()).is_err());
    assert_eq!(
        io::read_triangle_mesh_from_memory(garbage, "nope", &Default::default()).unwrap_err().code,
        ErrorCode::Unsupported
    );
    assert_eq!(
        io::read_triangle_mesh("/nonexistent/dir/x.ply", "auto", &Default::default()).unwrap_err().code,
        ErrorCode::Io
    );
}

#[test]
fn knot_from_the_shared_data() {
    let Some(path) = data_file("open3d/knot.ply") else { return };
    let mut mesh = io::read_triangle_mesh(&path, "auto", &Default::default()).unwrap();
    // Open3D 0.20 (tools/reference/record_mesh.py "knot.counts", "knot.area").
    assert_eq!((mesh.num_vertices().unwrap(), mesh.num_triangles().unwrap()), (1440, 2880));
    assert!(close(mesh.get_surface_area().unwrap(), 112072.277931022, 1e-6));
    assert!(mesh.is_watertight().unwrap());
    mesh.remove_duplicated_vertices().unwrap().remove_unreferenced_vertices().unwrap();
    assert_eq!(mesh.num_vertices().unwrap(), 1440);
    let pcd = mesh.sample_points_uniformly(1000, false, 0).unwrap();
    assert_eq!(pcd.len(), 1000);
}

#[test]
fn mobius_float32_input_and_row_checks() {
    let strip = TriangleMesh::create_mobius(|_| {}).unwrap();
    assert!(strip.num_triangles().unwrap() > 0 && strip.num_vertices().unwrap() > 0);
    let band = TriangleMesh::create_mobius(|o| (o.length_split, o.width_split) = (10, 3)).unwrap();
    assert!(band.num_vertices().unwrap() < strip.num_vertices().unwrap());
    assert_eq!(TriangleMesh::create_mobius(|o| o.radius = -1.0).unwrap_err().code, ErrorCode::InvalidArgument);

    let mut mesh = TriangleMesh::new().unwrap();
    mesh.set_array_f32(MeshArray::Vertices, &[[0.5f32, 1.0, 2.0]]).unwrap();
    assert_eq!(mesh.vertices().unwrap(), &[[0.5, 1.0, 2.0]]);
    mesh.set_triangle_uvs(&[[0.0, 1.0]; 3]).unwrap();
    assert_eq!(mesh.triangle_uvs().unwrap().len(), 3);
}
