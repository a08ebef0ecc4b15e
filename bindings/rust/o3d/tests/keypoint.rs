//! ISS keypoints of a unit box sampled on a grid on its faces: flat neighbourhoods (eigenvalues l1 = l2) are
//! no keypoints, so every keypoint lies near an edge; they are points of the cloud, at ascending indices,
//! with their colors; the eigenvalue-ratio tests filter; bad options are errors.
use o3d::keypoint::{compute_iss_keypoints, IssOptions};
use o3d::{ErrorCode, PointCloud};

/// Samples per edge of each face: a grid of spacing 0.05.
const M: usize = 21;

/// The unit box's faces sampled on a grid, each point once (the edges are shared by two faces).
fn box_cloud() -> PointCloud {
    let mut points = Vec::new();
    for axis in 0..3 {
        for side in [0.0, 1.0] {
            for i in 0..M {
                for j in 0..M {
                    let mut q = [0.0; 3];
                    q[axis] = side;
                    q[(axis + 1) % 3] = i as f64 / (M - 1) as f64;
                    q[(axis + 2) % 3] = j as f64 / (M - 1) as f64;
                    points.push(q);
                }
            }
        }
    }
    let mut cloud = PointCloud::from_points(&points).unwrap();
    cloud.remove_duplicated_points().unwrap();
    assert_eq!(cloud.len(), 6 * M * M - 12 * M + 8);
    // A color that tells the points apart, to follow them into the keypoints.
    let colors: Vec<[f64; 3]> = cloud.points().to_vec();
    cloud.set_colors(&colors).unwrap();
    cloud
}

/// Radii of 3.2 grid spacings: no grid point lies on a ball's boundary, so a ball inside one face holds a
/// symmetric grid patch (l1 = l2: not salient).
fn options() -> IssOptions {
    IssOptions { salient_radius: 0.16, non_max_radius: 0.16, ..Default::default() }
}

#[test]
fn keypoints_of_a_box_lie_near_its_edges() {
    let cloud = box_cloud();
    let (keys, indices) = compute_iss_keypoints(&cloud, &options()).unwrap();
    assert!(!indices.is_empty() && indices.len() < cloud.len() / 10, "{} keypoints", indices.len());
    assert_eq!(keys.len(), indices.len());
    assert!(indices.windows(2).all(|w| w[0] < w[1]), "ascending");
    let near = |c: f64| !(0.16..=1.0 - 0.16).contains(&c);
    for (k, &i) in keys.points().iter().zip(&indices) {
        assert_eq!(*k, cloud.points()[i as usize]);
        assert!(k.iter().filter(|&&c| near(c)).count() >= 2, "keypoint {k:?} is far from every edge");
    }
    assert_eq!(keys.colors(), keys.points());

    // The method is the same call.
    let (_, same) = cloud.compute_iss_keypoints(&options()).unwrap();
    assert_eq!(same, indices);
    // No point has eigenvalue ratios below 1e-6.
    let strict = IssOptions { gamma_21: 1e-6, gamma_32: 1e-6, ..options() };
    let (none, no_indices) = compute_iss_keypoints(&cloud, &strict).unwrap();
    assert!(none.is_empty() && no_indices.is_empty());
    // Radii derived from the resolution (the defaults) find keypoints too.
    assert!(!compute_iss_keypoints(&cloud, &IssOptions::default()).unwrap().1.is_empty());
}

#[test]
fn bad_options_are_invalid_argument() {
    let cloud = box_cloud();
    let bad = [
        IssOptions { salient_radius: -1.0, ..options() },
        IssOptions { non_max_radius: f64::NAN, ..options() },
        IssOptions { gamma_21: 0.0, ..options() },
        IssOptions { gamma_32: 1.5, ..options() },
    ];
    for options in bad {
        let err = compute_iss_keypoints(&cloud, &options).unwrap_err();
        assert_eq!(err.code, ErrorCode::InvalidArgument, "{options:?}");
    }
    let nan = PointCloud::from_points(&[[0.0; 3], [f64::NAN, 0.0, 0.0]]).unwrap();
    assert_eq!(compute_iss_keypoints(&nan, &options()).unwrap_err().code, ErrorCode::InvalidArgument);
    // An empty cloud has no keypoints.
    let (keys, indices) = compute_iss_keypoints(&PointCloud::new().unwrap(), &options()).unwrap();
    assert!(keys.is_empty() && indices.is_empty());
}
