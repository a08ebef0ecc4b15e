//! VoxelGrid editing, dense grids, cell centres and corners, meshes within bounds, space carving and
//! the octree <-> voxel grid round trip: analytic answers (a dense grid's cells and centres, corners at
//! centre +- half a voxel in Open3D 0.20's order, an all-ones mask keeping every voxel and an all-zeros
//! one removing all), errors for bad input.
use o3d::{ErrorCode, Image, Octree, PinholeCameraParameters, PinholeIntrinsic, TriangleMesh, Voxel, VoxelGrid};

fn close3(a: [f64; 3], b: [f64; 3]) -> bool {
    (0..3).all(|i| (a[i] - b[i]).abs() < 1e-12)
}

const IDENTITY: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

/// A 64 x 48 camera at the world origin looking down +z.
fn camera() -> PinholeCameraParameters {
    PinholeCameraParameters { intrinsic: PinholeIntrinsic::new(64, 48, 50.0, 50.0, 31.5, 23.5), extrinsic: IDENTITY }
}

/// A 1 m cube of 0.25 m voxels at z in [2, 3], in view.
fn cube_in_view() -> VoxelGrid {
    VoxelGrid::create_dense([-0.5, -0.5, 2.0], [1.0; 3], 0.25, 1.0, 1.0, 1.0).unwrap()
}

/// A float mask of `value` on the columns below `ones_below`, 0 elsewhere.
fn mask(value: f32, ones_below: usize) -> Image {
    let v: Vec<f32> = (0..64 * 48).map(|i| if i % 64 < ones_below { value } else { 0.0 }).collect();
    Image::from_f32(64, 48, &v).unwrap()
}

#[test]
fn dense_grid_cells_centres_and_corners() {
    let grid = VoxelGrid::create_dense([1.0, 2.0, 3.0], [0.1, 0.2, 0.3], 0.5, 1.0, 1.5, 0.5).unwrap();
    assert_eq!(grid.num_voxels().unwrap(), 6);
    assert_eq!(grid.origin().unwrap(), [1.0, 2.0, 3.0]);
    let voxels = grid.get_voxels().unwrap();
    let index: Vec<[i32; 3]> = voxels.iter().map(|v| v.grid_index).collect();
    assert_eq!(index, vec![[0, 0, 0], [0, 1, 0], [0, 2, 0], [1, 0, 0], [1, 1, 0], [1, 2, 0]]);
    assert!(voxels.iter().all(|v| v.color == [0.1, 0.2, 0.3]));
    assert!(close3(grid.get_voxel_center_coordinate([0, 0, 0]).unwrap(), [1.25, 2.25, 3.25]));
    assert!(close3(grid.get_voxel_center_coordinate([-2, 7, 1]).unwrap(), [0.25, 5.75, 3.75]));

    // Centre +- half a voxel in Open3D 0.20's order (the wheel): y slowest, then x, then z, low then high.
    let c = grid.get_voxel_center_coordinate([1, 2, 0]).unwrap();
    let corners = grid.get_voxel_bounding_points([1, 2, 0]).unwrap();
    let mut i = 0;
    for dy in [-0.25, 0.25] {
        for dx in [-0.25, 0.25] {
            for dz in [-0.25, 0.25] {
                assert!(close3(corners[i], [c[0] + dx, c[1] + dy, c[2] + dz]), "{i}: {corners:?}");
                i += 1;
            }
        }
    }
    assert!(close3(corners[0], [1.5, 3.0, 3.0]) && close3(corners[7], [2.0, 3.5, 3.5]));

    let err = VoxelGrid::create_dense([0.0; 3], [1.0; 3], 0.0, 1.0, 1.0, 1.0).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    assert!(VoxelGrid::create_dense([0.0; 3], [1.0; 3], 0.5, -1.0, 1.0, 1.0).is_err());
}

#[test]
fn add_replaces_and_remove_drops() {
    let mut grid = VoxelGrid::create_dense([0.0; 3], [0.0; 3], 1.0, 2.0, 2.0, 2.0).unwrap();
    assert_eq!(grid.num_voxels().unwrap(), 8);
    grid.add_voxel(Voxel { grid_index: [1, 0, 1], color: [1.0, 0.5, 0.0] }).unwrap(); // replaces
    assert_eq!(grid.num_voxels().unwrap(), 8);
    grid.add_voxel(Voxel { grid_index: [5, -1, 0], color: [0.0, 0.0, 1.0] }).unwrap().remove_voxel([0, 0, 0]).unwrap();
    grid.remove_voxel([9, 9, 9]).unwrap(); // nothing there
    assert_eq!(grid.num_voxels().unwrap(), 8);
    let voxels = grid.get_voxels().unwrap();
    let at = |g: [i32; 3]| voxels.iter().find(|v| v.grid_index == g).map(|v| v.color);
    assert_eq!(at([1, 0, 1]), Some([1.0, 0.5, 0.0]));
    assert_eq!(at([5, -1, 0]), Some([0.0, 0.0, 1.0]));
    assert_eq!(at([0, 0, 0]), None);
    let err = grid.add_voxel(Voxel { grid_index: [0; 3], color: [f64::NAN, 0.0, 0.0] }).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
}

#[test]
fn mesh_within_bounds() {
    // The [0, 1]^3 box at 0.5: Open3D 0.20 (the wheel) tests boxes of edge 0.5 centred on min_bound + 0.5 *
    // index, so of the 3 x 3 x 3 only the one centred inside the box, (1, 1, 1), touches no triangle.
    let box_mesh = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    let all = VoxelGrid::create_from_triangle_mesh_within_bounds(&box_mesh, 0.5, [0.0; 3], [1.0; 3]).unwrap();
    assert_eq!(all.num_voxels().unwrap(), 26);
    assert_eq!(all.origin().unwrap(), [0.0; 3]);
    for v in all.get_voxels().unwrap() {
        assert_ne!(v.grid_index, [1, 1, 1]);
        assert!(v.grid_index.iter().all(|&i| (0..=2).contains(&i)));
    }
    // Bounds halved along x: the cells past them are never made (2 x 3 x 3 less the inner one).
    let half = VoxelGrid::create_from_triangle_mesh_within_bounds(&box_mesh, 0.5, [0.0; 3], [0.5, 1.0, 1.0]).unwrap();
    assert_eq!(half.num_voxels().unwrap(), 17);
    assert!(half.get_voxels().unwrap().iter().all(|v| v.grid_index[0] <= 1));
    assert!(VoxelGrid::create_from_triangle_mesh_within_bounds(&box_mesh, 0.0, [0.0; 3], [1.0; 3]).is_err());
    assert!(VoxelGrid::create_from_triangle_mesh_within_bounds(&box_mesh, 0.5, [1.0; 3], [0.0; 3]).is_err());
}

#[test]
fn carve_silhouette() {
    let cam = camera();
    let mut grid = cube_in_view();
    assert_eq!(grid.num_voxels().unwrap(), 64);
    assert_eq!(grid.carve_silhouette(&mask(1.0, 64), &cam, false).unwrap().num_voxels().unwrap(), 64);
    assert_eq!(cube_in_view().carve_silhouette(&mask(0.0, 64), &cam, false).unwrap().num_voxels().unwrap(), 0);
    // Ones on columns 0..33: the cells with x <= 0 (u <= 31.5) stay, those with x >= 0.25 (u >= 35.6) go.
    let mut left = cube_in_view();
    left.carve_silhouette(&mask(1.0, 34), &cam, false).unwrap();
    assert_eq!(left.num_voxels().unwrap(), 48);
    assert!(left.get_voxels().unwrap().iter().all(|v| v.grid_index[0] <= 2));

    // Wider than the view: with keep_voxels_outside_image the cells seen outside the image stay.
    let wide = || VoxelGrid::create_dense([-2.0, -0.5, 2.0], [1.0; 3], 0.25, 4.0, 1.0, 1.0).unwrap();
    assert_eq!(wide().carve_silhouette(&mask(0.0, 64), &cam, false).unwrap().num_voxels().unwrap(), 0);
    let mut kept = wide();
    let n = kept.carve_silhouette(&mask(0.0, 64), &cam, true).unwrap().num_voxels().unwrap();
    assert!(n > 0 && n < 256, "{n}");
    assert!(kept.get_voxels().unwrap().iter().all(|v| v.grid_index[0] <= 3 || v.grid_index[0] >= 12));

    let mut scaled = cam;
    scaled.extrinsic[0][0] = 2.0; // not rigid
    let err = cube_in_view().carve_silhouette(&mask(1.0, 64), &scaled, false).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    let bytes = Image::from_bytes(64, 48, 1, o3d::PixelType::U8, &[1u8; 64 * 48]).unwrap(); // uint8, not float32
    assert!(cube_in_view().carve_silhouette(&bytes, &cam, false).is_err());
    let small = Image::from_f32(32, 48, &[1.0; 32 * 48]).unwrap();
    assert!(cube_in_view().carve_silhouette(&small, &cam, false).is_err());
}

#[test]
fn carve_depth_map() {
    let cam = camera();
    let depth = |d: f32| Image::from_f32(64, 48, &vec![d; 64 * 48]).unwrap();
    // Observed depth 2.4: the layer z in [2, 2.25] is in front of it (free space) and goes.
    let mut grid = cube_in_view();
    grid.carve_depth_map(&depth(2.4), &cam, false).unwrap();
    assert_eq!(grid.num_voxels().unwrap(), 48);
    assert!(grid.get_voxels().unwrap().iter().all(|v| v.grid_index[2] >= 1));
    // A surface in front hides the whole cube (kept); one far behind sees it all as free space (carved).
    assert_eq!(cube_in_view().carve_depth_map(&depth(1.0), &cam, false).unwrap().num_voxels().unwrap(), 64);
    assert_eq!(cube_in_view().carve_depth_map(&depth(10.0), &cam, false).unwrap().num_voxels().unwrap(), 0);
    let mut sheared = cam;
    sheared.extrinsic[0][1] = 0.5;
    assert!(cube_in_view().carve_depth_map(&depth(2.4), &sheared, false).is_err());
    let u16_depth = Image::from_u16(64, 48, &[2400u16; 64 * 48]).unwrap();
    assert!(cube_in_view().carve_depth_map(&u16_depth, &cam, false).is_err());
}

#[test]
fn octree_bounds_insert_and_voxel_grid_round_trip() {
    assert!(Octree::is_point_in_bound([0.0; 3], [0.0; 3], 8.0).unwrap());
    assert!(Octree::is_point_in_bound([7.99, 3.0, 5.0], [0.0; 3], 8.0).unwrap());
    assert!(!Octree::is_point_in_bound([8.0, 0.0, 0.0], [0.0; 3], 8.0).unwrap()); // half-open
    assert!(!Octree::is_point_in_bound([1.0, -0.1, 1.0], [0.0; 3], 8.0).unwrap());

    let mut tree = Octree::new_with_bounds(3, [0.0; 3], 8.0).unwrap(); // leaves of edge 1
    assert_eq!(tree.max_depth().unwrap(), 3);
    assert_eq!(tree.size().unwrap(), 8.0);
    assert_eq!(tree.num_leaf_nodes().unwrap(), 0);
    assert!(tree.insert_point([0.5, 0.5, 0.5], 1, [1.0, 0.0, 0.0]).unwrap());
    assert!(tree.insert_point([0.6, 0.4, 0.2], 0, [0.0, 0.0, 1.0]).unwrap()); // same leaf
    assert!(tree.insert_point([7.5, 7.5, 7.5], 2, [0.0, 1.0, 0.0]).unwrap());
    assert!(tree.insert_point([2.5, 0.5, 6.5], 3, [0.5; 3]).unwrap());
    assert!(!tree.insert_point([9.0, 0.0, 0.0], 4, [1.0; 3]).unwrap()); // outside the root
    assert_eq!(tree.num_leaf_nodes().unwrap(), 3);
    let leaf = tree.locate_leaf_node([0.1, 0.9, 0.1]).unwrap().expect("leaf");
    assert_eq!(leaf.indices, vec![0, 1]);
    assert!(close3(leaf.color, [0.5, 0.0, 0.5]));
    assert_eq!((leaf.info.origin, leaf.info.size, leaf.info.depth), ([0.0; 3], 1.0, 3));

    let grid = tree.to_voxel_grid().unwrap();
    assert_eq!(grid.voxel_size().unwrap(), 1.0);
    assert_eq!(grid.origin().unwrap(), [0.0; 3]);
    let voxels = grid.get_voxels().unwrap();
    let index: Vec<[i32; 3]> = voxels.iter().map(|v| v.grid_index).collect();
    assert_eq!(index, vec![[0, 0, 0], [2, 0, 6], [7, 7, 7]]);
    assert!(close3(voxels[0].color, [0.5, 0.0, 0.5]) && close3(voxels[2].color, [0.0, 1.0, 0.0]));
    assert_eq!(VoxelGrid::create_from_octree(&tree).unwrap().num_voxels().unwrap(), 3);

    let mut back = Octree::new(3).unwrap();
    back.create_from_voxel_grid(&grid).unwrap();
    assert_eq!(back.num_leaf_nodes().unwrap(), 3);
    assert_eq!(back.max_depth().unwrap(), 3);
    // One leaf per voxel centre, with the voxel's color and its position in the grid's order.
    let far = back.locate_leaf_node(grid.get_voxel_center_coordinate([7, 7, 7]).unwrap()).unwrap().expect("leaf");
    assert_eq!(far.indices, vec![2]);
    assert!(close3(far.color, [0.0, 1.0, 0.0]));
    assert_eq!(back.to_voxel_grid().unwrap().num_voxels().unwrap(), 3);

    assert_eq!(Octree::new_with_bounds(0, [0.0; 3], 1.0).unwrap_err().code, ErrorCode::InvalidArgument);
    assert!(Octree::new_with_bounds(3, [0.0; 3], 0.0).is_err());
    assert!(tree.insert_point([1.0; 3], -1, [0.0; 3]).is_err());
}
