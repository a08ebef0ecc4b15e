//! Octree over a small colored cloud: root cube, leaf lookup (node info as Open3D 0.20, see
//! tools/reference/record_bindings_round2.py; color = the mean of the leaf's points, as the header
//! says), empty cells, and errors for bad input.
use o3d::{ErrorCode, Octree, PointCloud};

fn cloud() -> PointCloud {
    let mut pc = PointCloud::from_points(&[
        [0.0, 0.0, 0.0],
        [4.0, 4.0, 4.0],
        [0.5, 0.5, 0.5],
        [3.5, 0.5, 1.5],
        [3.6, 0.6, 1.6],
        [1.0, 3.0, 2.0],
    ])
    .unwrap();
    pc.set_colors(&[
        [0.0, 0.0, 0.0],
        [1.0, 1.0, 1.0],
        [0.2, 0.4, 0.6],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ])
    .unwrap();
    pc
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-12
}

#[test]
fn leaves_are_found_where_open3d_puts_them() {
    let mut tree = Octree::new(2).unwrap();
    assert_eq!(tree.max_depth().unwrap(), 2);
    tree.convert_from_point_cloud(&cloud(), 0.01).unwrap();
    // Open3D 0.20: root origin (0,0,0), size 4 * 1.01 = 4.04.
    assert_eq!(tree.origin().unwrap(), [0.0; 3]);
    assert!(close(tree.size().unwrap(), 4.04));
    assert_eq!(tree.max_depth().unwrap(), 2);
    assert_eq!(tree.num_leaf_nodes().unwrap(), 4);

    let leaf = tree.locate_leaf_node([0.5, 0.5, 0.5]).unwrap().expect("a leaf");
    assert_eq!(leaf.info.origin, [0.0; 3]);
    assert!(close(leaf.info.size, 1.01));
    assert_eq!((leaf.info.depth, leaf.info.child_index), (2, 0));
    assert_eq!(leaf.indices, vec![0, 2]);
    let mean = [0.1, 0.2, 0.3];
    assert!((0..3).all(|i| close(leaf.color[i], mean[i])), "{leaf:?}");

    let leaf = tree.locate_leaf_node([3.5, 0.5, 1.5]).unwrap().expect("a leaf");
    let origin = [3.03, 0.0, 1.01];
    assert!((0..3).all(|i| close(leaf.info.origin[i], origin[i])), "{leaf:?}");
    assert_eq!((leaf.info.depth, leaf.info.child_index), (2, 5));
    assert_eq!(leaf.indices, vec![3, 4]);
    assert!((0..3).all(|i| close(leaf.color[i], [0.5, 0.5, 0.0][i])), "{leaf:?}");

    // Outside the root, and inside it but in an empty cell.
    assert_eq!(tree.locate_leaf_node([10.0, 10.0, 10.0]).unwrap(), None);
    assert_eq!(tree.locate_leaf_node([2.5, 2.5, 2.5]).unwrap(), None);
}

#[test]
fn rebuilding_replaces_the_tree_and_empty_trees_find_nothing() {
    let mut tree = Octree::new(3).unwrap();
    assert_eq!(tree.num_leaf_nodes().unwrap(), 0);
    assert_eq!(tree.locate_leaf_node([0.0; 3]).unwrap(), None);
    tree.convert_from_point_cloud(&cloud(), 0.01).unwrap();
    let before = tree.num_leaf_nodes().unwrap();
    let single = PointCloud::from_points(&[[1.0, 2.0, 3.0], [1.5, 2.5, 3.5]]).unwrap();
    tree.convert_from_point_cloud(&single, 0.01).unwrap();
    assert!(before > 2);
    assert_eq!(tree.num_leaf_nodes().unwrap(), 2);
    assert_eq!(tree.origin().unwrap(), [1.0, 2.0, 3.0]);
    assert!(close(tree.size().unwrap(), 0.505));
    let leaf = tree.locate_leaf_node([1.01, 2.01, 3.01]).unwrap().expect("a leaf");
    assert_eq!(leaf.indices, vec![0]);
    assert_eq!(leaf.info.depth, 3);
}

#[test]
fn bad_input_is_an_error() {
    assert_eq!(Octree::new(0).unwrap_err().code, ErrorCode::InvalidArgument);
    let mut tree = Octree::new(2).unwrap();
    assert_eq!(tree.convert_from_point_cloud(&cloud(), -0.5).unwrap_err().code, ErrorCode::InvalidArgument);
    assert!(tree.convert_from_point_cloud(&PointCloud::new().unwrap(), 0.01).is_err());
    tree.convert_from_point_cloud(&cloud(), 0.01).unwrap();
    assert_eq!(tree.locate_leaf_node([f64::NAN, 0.0, 0.0]).unwrap_err().code, ErrorCode::InvalidArgument);
}
