//! VoxelGrid: cells of a few points (origin = min bound - size/2, sorted grid indices, mean
//! colors), bounded grids, a voxelised square, queries, and errors for bad input.
use o3d::{ErrorCode, PointCloud, TriangleMesh, VoxelGrid};

fn close3(a: [f64; 3], b: [f64; 3]) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
}

fn colored_cloud() -> PointCloud {
    let mut cloud =
        PointCloud::from_points(&[[2.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 3.0, 1.0], [0.2, 0.1, 0.0]]).unwrap();
    cloud.set_colors(&[[1.0, 0.0, 0.0], [0.0, 0.0, 1.0], [0.5, 0.5, 0.5], [0.0, 1.0, 0.0]]).unwrap();
    cloud
}

#[test]
fn points_fall_in_the_expected_sorted_cells() {
    let grid = VoxelGrid::create_from_point_cloud(&colored_cloud(), 1.0).unwrap();
    assert_eq!(grid.voxel_size().unwrap(), 1.0);
    assert_eq!(grid.origin().unwrap(), [-0.5, -0.5, -0.5]);
    assert_eq!(grid.num_voxels().unwrap(), 3);
    let voxels = grid.get_voxels().unwrap();
    let index: Vec<[i32; 3]> = voxels.iter().map(|v| v.grid_index).collect();
    assert_eq!(index, vec![[0, 0, 0], [0, 3, 1], [2, 0, 0]]);
    // Cell (0,0,0) holds two points: the mean of blue and green.
    assert!(close3(voxels[0].color, [0.0, 0.5, 0.5]), "{voxels:?}");
    assert!(close3(voxels[1].color, [0.5, 0.5, 0.5]));
    assert!(close3(voxels[2].color, [1.0, 0.0, 0.0]));

    assert_eq!(grid.get_voxel([0.2, 0.1, 0.0]).unwrap(), [0, 0, 0]);
    assert_eq!(grid.get_voxel([5.0, -2.0, 0.7]).unwrap(), [5, -2, 1]);
    assert_eq!(
        grid.check_if_included(&[[0.4, 0.4, 0.4], [1.0, 0.0, 0.0], [2.3, -0.2, 0.1], [0.0, 2.6, 1.4]]).unwrap(),
        vec![true, false, true, true]
    );
    assert!(grid.check_if_included(&[]).unwrap().is_empty());

    // Without colors the voxel colors are 0.
    let plain = PointCloud::from_points(&[[0.0; 3], [0.1, 0.0, 0.0]]).unwrap();
    let grid = VoxelGrid::create_from_point_cloud(&plain, 0.5).unwrap();
    let voxels = grid.get_voxels().unwrap();
    assert_eq!(voxels.len(), 1);
    assert_eq!(voxels[0].color, [0.0; 3]);
}

#[test]
fn bounded_grid_starts_at_min_bound_and_drops_outside_points() {
    let grid =
        VoxelGrid::create_from_point_cloud_within_bounds(&colored_cloud(), 1.0, [0.0; 3], [2.5, 2.5, 2.5]).unwrap();
    assert_eq!(grid.origin().unwrap(), [0.0; 3]);
    // (0, 3, 1) is outside the bounds.
    let index: Vec<[i32; 3]> = grid.get_voxels().unwrap().iter().map(|v| v.grid_index).collect();
    assert_eq!(index, vec![[0, 0, 0], [2, 0, 0]]);
}

#[test]
fn voxelised_square_covers_nine_cells() {
    // The unit square in z = 0 with cells of 0.5: origin (-0.25)^3, cells 0..3 in x and y.
    let square = TriangleMesh::from_vertices_and_triangles(
        &[[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
        &[[0, 1, 2], [0, 2, 3]],
    )
    .unwrap();
    let grid = VoxelGrid::create_from_triangle_mesh(&square, 0.5).unwrap();
    assert_eq!(grid.origin().unwrap(), [-0.25, -0.25, -0.25]);
    let index: Vec<[i32; 3]> = grid.get_voxels().unwrap().iter().map(|v| v.grid_index).collect();
    let expected: Vec<[i32; 3]> = (0..3).flat_map(|i| (0..3).map(move |j| [i, j, 0])).collect();
    assert_eq!(index, expected);
}

#[test]
fn bad_input_is_an_error() {
    let cloud = colored_cloud();
    for size in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(VoxelGrid::create_from_point_cloud(&cloud, size).unwrap_err().code, ErrorCode::InvalidArgument);
    }
    assert_eq!(
        VoxelGrid::create_from_point_cloud_within_bounds(&cloud, 1.0, [1.0; 3], [0.0; 3]).unwrap_err().code,
        ErrorCode::InvalidArgument
    );
    let mesh = TriangleMesh::from_vertices_and_triangles(&[[0.0; 3]], &[[0, 1, 2]]).unwrap();
    assert_eq!(VoxelGrid::create_from_triangle_mesh(&mesh, 1.0).unwrap_err().code, ErrorCode::InvalidArgument);
    let grid = VoxelGrid::create_from_point_cloud(&cloud, 1.0).unwrap();
    assert_eq!(grid.get_voxel([f64::NAN, 0.0, 0.0]).unwrap_err().code, ErrorCode::InvalidArgument);
}
