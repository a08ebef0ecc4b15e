//! SelectionPolygonVolume: analytic crops of a grid and a two-triangle mesh by a unit-square prism,
//! Open3D's reference crop of its fragment, errors, and a VisualizerWithEditing crop driven by keys and
//! the mouse in a hidden window.
mod common;

use o3d::visualization::{Axis, KeyAction, MouseButton, SelectionPolygonVolume, Visualizer};
use o3d::{io, ErrorCode, PointCloud, TriangleMesh};

/// 30 x 30 points of step 0.1 from -0.95 at height `z`: 10 x 10 of them fall in (0, 1)^2, none on its edges.
fn grid(z: f64) -> PointCloud {
    let points: Vec<[f64; 3]> =
        (0..30).flat_map(|i| (0..30).map(move |j| [-0.95 + 0.1 * i as f64, -0.95 + 0.1 * j as f64, z])).collect();
    PointCloud::from_points(&points).unwrap()
}

/// The unit square across Z, over z in [0, 1].
fn unit_square() -> SelectionPolygonVolume {
    let mut v = SelectionPolygonVolume::new().unwrap();
    v.set_orthogonal_axis(Axis::Z).unwrap();
    v.set_axis_min(0.0).unwrap();
    v.set_axis_max(1.0).unwrap();
    v.set_bounding_polygon(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]]).unwrap();
    v
}

#[test]
fn accessors_round_trip() {
    let empty = SelectionPolygonVolume::new().unwrap();
    assert_eq!(empty.get_orthogonal_axis().unwrap(), Axis::Y); // the C default
    assert!(empty.get_bounding_polygon().unwrap().is_empty());
    let v = unit_square();
    assert_eq!(v.get_orthogonal_axis().unwrap(), Axis::Z);
    assert_eq!((v.get_axis_min().unwrap(), v.get_axis_max().unwrap()), (0.0, 1.0));
    let corners = v.get_bounding_polygon().unwrap();
    assert_eq!(corners.len(), 4);
    assert_eq!(corners[2], [1.0, 1.0, 0.0]);
}

#[test]
fn crops_grid_analytically() {
    let v = unit_square();
    let inside = v.crop_point_cloud(&grid(0.5)).unwrap();
    assert_eq!(inside.len(), 100);
    for p in inside.points() {
        assert!(p[0] > 0.0 && p[0] < 1.0 && p[1] > 0.0 && p[1] < 1.0, "{p:?}");
    }
    assert_eq!(v.crop_point_cloud(&grid(1.5)).unwrap().len(), 0); // above axis_max
    let idx = v.crop_in_polygon(&grid(0.5)).unwrap();
    assert_eq!(idx.len(), 100);
    assert_eq!((idx[0], idx[99]), (10 * 30 + 10, 19 * 30 + 19)); // (0.05, 0.05) .. (0.95, 0.95)
}

#[test]
fn mesh_keeps_triangles_with_all_vertices_inside() {
    // Vertex 3 is outside: triangle (1, 3, 2) goes, (0, 1, 2) stays with its 3 vertices.
    let vertices = [[0.1, 0.1, 0.5], [0.9, 0.1, 0.5], [0.1, 0.9, 0.5], [1.5, 0.9, 0.5]];
    let mesh = TriangleMesh::from_vertices_and_triangles(&vertices, &[[0, 1, 2], [1, 3, 2]]).unwrap();
    let cropped = unit_square().crop_triangle_mesh(&mesh).unwrap();
    assert_eq!(cropped.num_triangles().unwrap(), 1);
    assert_eq!(cropped.num_vertices().unwrap(), 3);
}

#[test]
fn open3d_fragment_reference() {
    let (Some(json), Some(pcd)) =
        (common::data_file("open3d/Crop/cropped.json"), common::data_file("open3d/fragment.pcd"))
    else {
        return;
    };
    let v = SelectionPolygonVolume::read_json(json).unwrap();
    assert_eq!(v.get_orthogonal_axis().unwrap(), Axis::Y);
    assert!((v.get_axis_min().unwrap() - -0.76341366767883301).abs() < 1e-15);
    assert!((v.get_axis_max().unwrap() - 4.022921085357666).abs() < 1e-15);
    assert_eq!(v.get_bounding_polygon().unwrap().len(), 20);
    let cloud = io::read_point_cloud(pcd, "auto", &Default::default()).unwrap();
    assert_eq!(cloud.len(), 113662);
    assert_eq!(v.crop_point_cloud(&cloud).unwrap().len(), 29873);
    assert_eq!(v.crop_in_polygon(&cloud).unwrap().len(), 29873);
}

#[test]
fn errors() {
    let mut v = SelectionPolygonVolume::new().unwrap();
    assert_eq!(v.crop_point_cloud(&grid(0.0)).unwrap_err().code, ErrorCode::InvalidArgument); // no polygon
    assert_eq!(v.set_axis_min(f64::NAN).unwrap_err().code, ErrorCode::InvalidArgument);
    let bad = [[0.0, 0.0, 0.0], [1.0, f64::INFINITY, 0.0], [1.0, 1.0, 0.0]];
    assert_eq!(v.set_bounding_polygon(&bad).unwrap_err().code, ErrorCode::InvalidArgument);
    v.set_bounding_polygon(&[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).unwrap();
    v.set_axis_min(2.0).unwrap();
    v.set_axis_max(1.0).unwrap();
    assert_eq!(v.crop_in_polygon(&grid(0.0)).unwrap_err().code, ErrorCode::InvalidArgument); // min > max
    let missing = SelectionPolygonVolume::read_json("/nonexistent/volume.json").unwrap_err();
    assert_eq!(missing.code, ErrorCode::Io);
}

#[test]
fn visualizer_crops_the_dragged_rectangle() {
    let vis = Visualizer::with_editing().unwrap();
    vis.create_window("crop", 160, 120, -1, -1, false).unwrap();
    let cloud = grid(0.0);
    vis.add_geometry("grid", &cloud, true).unwrap();
    let dir = common::TempDir::new("crop");
    vis.set_crop_directory(dir.0.to_str().unwrap()).unwrap();
    assert!(vis.cropped_point_cloud().unwrap().is_none()); // nothing cropped yet
    assert_eq!(vis.crop_to_selection().unwrap_err().code, ErrorCode::InvalidArgument); // no selection

    vis.send_key('K' as i32, KeyAction::Press, 0).unwrap();
    assert!(vis.is_selecting().unwrap());
    vis.send_mouse_move(50.0, 40.0).unwrap();
    vis.send_mouse_button(MouseButton::Left, KeyAction::Press, 0).unwrap();
    vis.send_mouse_move(80.0, 60.0).unwrap();
    vis.send_mouse_move(110.0, 80.0).unwrap();
    vis.send_mouse_button(MouseButton::Left, KeyAction::Release, 0).unwrap();
    vis.send_key('C' as i32, KeyAction::Press, 0).unwrap();
    assert!(!vis.is_selecting().unwrap());

    let cropped = vis.cropped_point_cloud().unwrap().expect("a cropped cloud");
    assert!(cropped.len() > 0 && cropped.len() < cloud.len(), "{} of {}", cropped.len(), cloud.len());
    assert!(vis.cropped_triangle_mesh().unwrap().is_none()); // the crop was of a cloud
    let written = io::read_point_cloud(dir.0.join("cropped_1.ply"), "auto", &Default::default()).unwrap();
    assert_eq!(written.len(), cropped.len());
}
