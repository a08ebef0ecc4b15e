//! Per-point covariances: planar neighbourhoods give singular matrices with no spread along the
//! normal, explicit covariances round-trip, follow selection and rotate as R C R^T.
use o3d::{ErrorCode, PointCloud, SearchParam};

fn det(c: &[[f64; 3]; 3]) -> f64 {
    c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) - c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0])
        + c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0])
}

fn grid_on_plane_z0(n: usize) -> Vec<[f64; 3]> {
    let mut pts = Vec::new();
    for i in 0..n {
        for j in 0..n {
            pts.push([i as f64 * 0.1, j as f64 * 0.1 + 0.03 * i as f64, 0.0]);
        }
    }
    pts
}

#[test]
fn planar_neighbourhoods_have_singular_covariances() {
    let mut cloud = PointCloud::from_points(&grid_on_plane_z0(12)).unwrap();
    assert!(!cloud.has_covariances().unwrap());
    assert!(cloud.covariances().unwrap().is_empty());
    cloud.estimate_covariances(SearchParam::Knn { knn: 10 }).unwrap();
    assert!(cloud.has_covariances().unwrap());
    let covs = cloud.covariances().unwrap();
    assert_eq!(covs.len(), 144);
    for c in covs {
        assert!(det(c).abs() < 1e-15, "{c:?}");
        assert!(c[2][2].abs() < 1e-15 && c[0][2].abs() < 1e-15 && c[1][2].abs() < 1e-15, "{c:?}");
        assert!(c[0][0] > 1e-4 && c[1][1] > 1e-4, "{c:?}");
        assert!((c[0][1] - c[1][0]).abs() < 1e-15, "{c:?}");
    }
    assert_eq!(cloud.covariances_to_vec().unwrap(), covs.to_vec());

    // The default parameter is KNN 30; a hybrid search works too.
    cloud.estimate_covariances(SearchParam::default()).unwrap();
    cloud.estimate_covariances(SearchParam::Hybrid { radius: 0.25, max_nn: 20 }).unwrap();
    assert!(cloud.covariances().unwrap().iter().all(|c| det(c).abs() < 1e-15));
}

#[test]
fn covariances_with_fewer_than_three_neighbours_are_the_identity() {
    let mut cloud = PointCloud::from_points(&[[0.0; 3], [5.0, 0.0, 0.0], [0.0, 7.0, 0.0]]).unwrap();
    cloud.estimate_covariances(SearchParam::Radius { radius: 1.0 }).unwrap();
    let identity = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    assert_eq!(cloud.covariances().unwrap(), &[identity; 3]);
}

#[test]
fn explicit_covariances_round_trip_follow_selection_and_rotate() {
    let diag = |a: f64, b: f64, c: f64| [[a, 0.0, 0.0], [0.0, b, 0.0], [0.0, 0.0, c]];
    let mut cloud = PointCloud::from_points(&[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).unwrap();
    let covs = [diag(1.0, 2.0, 3.0), diag(4.0, 5.0, 6.0), diag(7.0, 8.0, 9.0)];
    cloud.set_covariances(&covs).unwrap();
    assert!(cloud.has_covariances().unwrap());
    assert_eq!(cloud.covariances().unwrap(), &covs);

    let picked = cloud.select_by_index(&[0, 2], false).unwrap();
    assert_eq!(picked.covariances_to_vec().unwrap(), vec![covs[0], covs[2]]);

    // A quarter turn about z swaps the x and y variances.
    let quarter = [[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]];
    cloud.rotate(&quarter, Some([0.0; 3])).unwrap();
    let rotated = cloud.covariances().unwrap();
    let expected = [diag(2.0, 1.0, 3.0), diag(5.0, 4.0, 6.0), diag(8.0, 7.0, 9.0)];
    for (r, e) in rotated.iter().zip(&expected) {
        for i in 0..3 {
            for j in 0..3 {
                assert!((r[i][j] - e[i][j]).abs() < 1e-12, "{rotated:?}");
            }
        }
    }

    // A count that does not match the points is not "has covariances".
    cloud.set_covariances(&covs[..2]).unwrap();
    assert!(!cloud.has_covariances().unwrap());
    cloud.set_covariances(&[]).unwrap();
    assert!(!cloud.has_covariances().unwrap());
}

#[test]
fn bad_search_parameters_are_errors() {
    let mut cloud = PointCloud::from_points(&grid_on_plane_z0(4)).unwrap();
    assert_eq!(cloud.estimate_covariances(SearchParam::Knn { knn: 0 }).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(
        cloud.estimate_covariances(SearchParam::Radius { radius: -1.0 }).unwrap_err().code,
        ErrorCode::InvalidArgument
    );
    assert!(!cloud.has_covariances().unwrap());
}
