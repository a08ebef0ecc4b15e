//! Feature: construction, views, resize, selection, files; FPFH; KD-trees over features; matching.
mod common;

use common::*;
use o3d::registration::{self, Feature, MatchOptions};
use o3d::{io, ErrorCode, KDTreeFlann, PointCloud, SearchParam};

#[test]
fn construction_views_and_copies() {
    let zeros = Feature::new(4, 3).unwrap();
    assert_eq!((zeros.dimension(), zeros.num(), zeros.is_empty()), (4, 3, false));
    assert_eq!(zeros.data(), &[0.0; 12]);

    let values: Vec<f64> = (0..12).map(f64::from).collect();
    let mut f = Feature::from_data(&values, 3).unwrap();
    assert_eq!((f.dimension(), f.num()), (3, 4));
    assert_eq!(f.data(), &values[..]);
    assert_eq!(f.descriptor(1), Some(&[3.0, 4.0, 5.0][..]));
    assert_eq!(f.descriptor(4), None);
    assert_eq!(f.descriptors().count(), 4);
    assert_eq!(f.to_vec().unwrap(), values);

    let rows = Feature::from_descriptors(&[[1.0, 2.0], [3.0, 4.0]]).unwrap();
    assert_eq!((rows.dimension(), rows.num()), (2, 2));
    assert_eq!(rows.data(), &[1.0, 2.0, 3.0, 4.0]);

    // The mutable view writes into the library's buffer; clones are deep.
    let copy = f.clone();
    f.data_mut()[0] = 42.0;
    assert_eq!(f.to_vec().unwrap()[0], 42.0);
    assert_eq!(copy.data()[0], 0.0);

    // Resize with the same dimension keeps the first descriptors and zero-fills the new ones.
    f.resize(3, 6).unwrap();
    assert_eq!((f.dimension(), f.num()), (3, 6));
    assert_eq!(&f.data()[..3], &[42.0, 1.0, 2.0]);
    assert_eq!(&f.data()[12..], &[0.0; 6]);
    f.resize(0, 0).unwrap();
    assert!(f.is_empty() && f.data().is_empty());
}

#[test]
fn select_by_index_keeps_order_or_inverts() {
    let f = Feature::from_descriptors(&[[0.0, 0.5], [1.0, 1.5], [2.0, 2.5], [3.0, 3.5]]).unwrap();
    let picked = f.select_by_index(&[3, 1], false).unwrap();
    assert_eq!(picked.data(), &[3.0, 3.5, 1.0, 1.5]);
    let rest = f.select_by_index(&[3, 1], true).unwrap();
    assert_eq!(rest.data(), &[0.0, 0.5, 2.0, 2.5]);
    for bad in [4, -1] {
        let err = f.select_by_index(&[0, bad], false).unwrap_err();
        assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    }
}

#[test]
fn bad_construction_arguments_are_errors() {
    let err = Feature::from_data(&[1.0, 2.0, 3.0], 2).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    let err = Feature::from_data(&[1.0], 0).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    let err = Feature::from_data(&[1.0, f64::NAN], 2).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    assert!(!err.message.is_empty());
    let err = Feature::from_descriptors(&[[f64::INFINITY]]).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
}

#[test]
fn file_round_trip_and_file_errors() {
    let dir = TempDir::new("feature");
    let f = Feature::from_descriptors(&[[0.25, -1.0, 3.5], [1e-300, 7.0, 8.0]]).unwrap();
    let path = dir.path("f.bin");
    io::write_feature(&path, &f).unwrap();
    // Open3D's layout: int32 dimension, int32 num, then the doubles descriptor by descriptor.
    let bytes = std::fs::read(&path).unwrap();
    assert_eq!(bytes.len(), 8 + 6 * 8);
    assert_eq!(&bytes[..8], &[3, 0, 0, 0, 2, 0, 0, 0]);
    let back = io::read_feature(&path).unwrap();
    assert_eq!((back.dimension(), back.num()), (3, 2));
    assert_eq!(back.data(), f.data());

    std::fs::write(dir.path("short.bin"), &bytes[..bytes.len() - 1]).unwrap();
    assert_eq!(io::read_feature(dir.path("short.bin")).unwrap_err().code, ErrorCode::Parse);
    assert_eq!(io::read_feature(dir.path("missing.bin")).unwrap_err().code, ErrorCode::Io);
    assert_eq!(io::write_feature(dir.path("no/such/dir/f.bin"), &f).unwrap_err().code, ErrorCode::Io);
}

#[test]
fn reads_the_shared_fpfh_file() {
    let Some(path) = data_file("open3d/Feature/cloud_bin_0.fpfh.bin") else { return };
    let f = io::read_feature(&path).unwrap();
    assert_eq!((f.dimension(), f.num()), (33, 3903));
    // FPFH: three 11-bin histograms, each normalised to 100.
    for d in f.descriptors() {
        for part in d.chunks(11) {
            let sum: f64 = part.iter().sum();
            assert!((sum - 100.0).abs() < 1e-3, "{sum}");
        }
    }
    // Open3D's first descriptor (the file is written from float32 values).
    assert!((f.data()[0] - 6.711_965_56).abs() < 1e-6, "{}", f.data()[0]);
}

/// The share of `source` points whose nearest `target` feature lies within 0.075 m of them (the
/// two shared clouds are aligned to about 0.4 deg / 17 mm).
fn matching_share(source: &PointCloud, target: &PointCloud, fs: &Feature, ft: &Feature) -> f64 {
    let pairs = registration::correspondences_from_features(fs, ft, &MatchOptions::default()).unwrap();
    assert_eq!(pairs.len(), fs.num());
    let (ps, pt) = (source.points(), target.points());
    let good = pairs.iter().filter(|&&[s, t]| dist2(ps[s as usize], pt[t as usize]) < 0.075 * 0.075).count();
    good as f64 / pairs.len() as f64
}

#[test]
fn stored_features_match_across_the_two_scans() {
    let (Some(p0), Some(p1), Some(f0), Some(f1)) = (
        data_file("open3d/Feature/cloud_bin_0.pcd"),
        data_file("open3d/Feature/cloud_bin_1.pcd"),
        data_file("open3d/Feature/cloud_bin_0.fpfh.bin"),
        data_file("open3d/Feature/cloud_bin_1.fpfh.bin"),
    ) else {
        return;
    };
    let (c0, c1) = (read(&p0), read(&p1));
    let (f0, f1) = (io::read_feature(f0).unwrap(), io::read_feature(f1).unwrap());
    // Chance would put well under 1% of the matches this close; the stored features reach about 11%.
    let share = matching_share(&c1, &c0, &f1, &f0);
    assert!((0.09..0.14).contains(&share), "{share}");

    // Mutual filtering keeps a subset of the plain matches.
    let plain = registration::correspondences_from_features(&f1, &f0, &MatchOptions::default()).unwrap();
    let mutual_opts = MatchOptions { mutual_filter: true, ..Default::default() };
    let mutual = registration::correspondences_from_features(&f1, &f0, &mutual_opts).unwrap();
    assert!(!mutual.is_empty() && mutual.len() < plain.len(), "{} of {}", mutual.len(), plain.len());
    assert!(mutual.iter().all(|p| plain.binary_search(p).is_ok()));
}

fn read(path: &std::path::Path) -> PointCloud {
    io::read_point_cloud(path, "auto", &Default::default()).unwrap()
}

fn tutorial_fpfh(cloud: &PointCloud) -> (PointCloud, Feature) {
    let mut down = cloud.voxel_down_sample(0.05).unwrap();
    down.estimate_normals(SearchParam::Hybrid { radius: 0.1, max_nn: 30 }).unwrap();
    let f = registration::compute_fpfh_feature(&down, SearchParam::Hybrid { radius: 0.25, max_nn: 100 }).unwrap();
    (down, f)
}

#[test]
fn fpfh_on_cloud_bin_is_a_histogram_that_matches_across_scans() {
    let (Some(p0), Some(p1)) =
        (data_file("open3d/Feature/cloud_bin_0.pcd"), data_file("open3d/Feature/cloud_bin_1.pcd"))
    else {
        return;
    };
    let (d0, f0) = tutorial_fpfh(&read(&p0));
    let (d1, f1) = tutorial_fpfh(&read(&p1));
    assert_eq!((f0.dimension(), f0.num()), (33, d0.len()));
    // Open3D 0.20 adds the point's own histograms (each part normalised to 100) to the weighted
    // mean of its neighbours': each 11-bin part sums to 200 (the older stored files: 100).
    for d in f0.descriptors() {
        assert!(d.iter().all(|v| v.is_finite() && *v >= 0.0));
        for part in d.chunks(11) {
            let sum: f64 = part.iter().sum();
            assert!((sum - 200.0).abs() < 1e-9, "{sum}");
        }
    }
    // Our FPFH matches the scans about as well as Open3D's (14% on this setting).
    let share = matching_share(&d1, &d0, &f1, &f0);
    assert!(share > 0.10, "{share}");

    // The thread count does not change the result; a subset of indices gives those descriptors,
    // in ascending point order (Open3D's mask semantics).
    let param = SearchParam::Hybrid { radius: 0.25, max_nn: 100 };
    let one = registration::compute_fpfh_feature_with(&d0, param, &[], 1).unwrap();
    assert_eq!(one.data(), f0.data());
    let some = registration::compute_fpfh_feature_with(&d0, param, &[17, 0, 5], 2).unwrap();
    assert_eq!(some.num(), 3);
    assert_eq!(some.data(), f0.select_by_index(&[0, 5, 17], false).unwrap().data());
}

#[test]
fn fpfh_is_invariant_under_a_rigid_motion() {
    let Some(p0) = data_file("open3d/Feature/cloud_bin_0.pcd") else { return };
    let mut cloud = read(&p0).voxel_down_sample(0.05).unwrap();
    cloud.estimate_normals(SearchParam::Hybrid { radius: 0.1, max_nn: 30 }).unwrap();
    let param = SearchParam::Hybrid { radius: 0.25, max_nn: 100 };
    let f = registration::compute_fpfh_feature(&cloud, param).unwrap();
    let mut moved = cloud.clone();
    moved.transform(&rigid(rotation([1.0, -2.0, 0.5], 1.1), [3.0, -1.0, 2.0])).unwrap();
    let g = registration::compute_fpfh_feature(&moved, param).unwrap();
    // Angles near a bin edge may fall on either side after rounding (Open3D's own descriptors
    // change a little for about a tenth of the points under this motion), but each point's moved
    // descriptor stays nearest to its original one.
    let pairs = registration::correspondences_from_features(&g, &f, &MatchOptions::default()).unwrap();
    let share = pairs.iter().filter(|[s, t]| s == t).count() as f64 / f.num() as f64;
    assert!(share > 0.98, "{share}");
}

#[test]
fn fpfh_and_matching_reject_bad_input() {
    let pts = Rng::new(3).points(50, 0.0, 1.0);
    let no_normals = PointCloud::from_points(&pts).unwrap();
    let err = registration::compute_fpfh_feature(&no_normals, SearchParam::Knn { knn: 10 }).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    let mut with_normals = no_normals.clone();
    with_normals.estimate_normals(SearchParam::Knn { knn: 10 }).unwrap();
    let err = registration::compute_fpfh_feature(&with_normals, SearchParam::Radius { radius: f64::NAN }).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
    let err =
        registration::compute_fpfh_feature_with(&with_normals, SearchParam::Knn { knn: 10 }, &[50], 0).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");

    let (a, b) = (Feature::new(3, 4).unwrap(), Feature::new(2, 4).unwrap());
    let err = registration::correspondences_from_features(&a, &b, &MatchOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument, "{err}");
}

#[test]
fn matching_a_feature_with_itself_pairs_each_descriptor_with_itself() {
    let mut rng = Rng::new(11);
    let rows: Vec<[f64; 5]> = (0..200).map(|_| [0; 5].map(|_| rng.range(0.0, 1.0))).collect();
    let f = Feature::from_descriptors(&rows).unwrap();
    for mutual_filter in [false, true] {
        let opts = MatchOptions { mutual_filter, num_threads: 2, ..Default::default() };
        let pairs = registration::correspondences_from_features(&f, &f, &opts).unwrap();
        assert_eq!(pairs, (0..200).map(|i| [i, i]).collect::<Vec<_>>());
    }
}

#[test]
fn kdtree_over_a_feature_and_over_xd_points() {
    let mut rng = Rng::new(7);
    let rows: Vec<[f64; 6]> = (0..300).map(|_| [0; 6].map(|_| rng.range(-1.0, 1.0))).collect();
    let f = Feature::from_descriptors(&rows).unwrap();
    let tree = KDTreeFlann::from_feature(&f).unwrap();
    assert_eq!((tree.dimension().unwrap(), tree.len().unwrap()), (6, 300));
    // Each descriptor finds itself first, then its brute-force nearest neighbour.
    let (idx, d2) = tree.search_knn_vector_xd(&rows[17], 2).unwrap();
    assert_eq!((idx[0], d2[0]), (17, 0.0));
    let brute = (0..300)
        .filter(|&i| i != 17)
        .min_by(|&a, &b| {
            let d = |i: usize| rows[i].iter().zip(&rows[17]).map(|(x, y)| (x - y).powi(2)).sum::<f64>();
            d(a).total_cmp(&d(b))
        })
        .unwrap();
    assert_eq!(idx[1], brute as i32);

    let all = tree.search_feature(&f, SearchParam::Knn { knn: 1 }).unwrap();
    assert_eq!(all.indices, (0..300).collect::<Vec<i32>>());
    let (within, _) = tree.search_radius_vector_xd(&rows[0], 1e-9).unwrap();
    assert_eq!(within, vec![0]);
    let (hybrid, _) = tree.search_hybrid_vector_xd(&rows[0], 10.0, 5).unwrap();
    assert_eq!(hybrid.len(), 5);

    // Row-major points of any dimension; 3-D trees report dimension 3.
    let flat = [0.0, 0.0, 1.0, 1.0, 5.0, 5.0];
    let tree2 = KDTreeFlann::from_points_xd(&flat, 2).unwrap();
    assert_eq!((tree2.dimension().unwrap(), tree2.len().unwrap()), (2, 3));
    let r = tree2.search_xd(&[0.9, 0.8, 4.0, 4.0], 2, SearchParam::Knn { knn: 1 }).unwrap();
    assert_eq!(r.indices, vec![1, 2]);
    let by_ref = tree2.search_xd_ref(&[0.9, 0.8], 2, SearchParam::Knn { knn: 3 }, 1).unwrap();
    assert_eq!(by_ref.view().unwrap().1, &[1, 0, 2]);
    let tree3 = KDTreeFlann::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    assert_eq!(tree3.dimension().unwrap(), 3);

    // A query of the wrong dimension, ragged data and non-finite points are errors.
    assert_eq!(tree.search_knn_vector_xd(&[0.0; 5], 1).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(
        tree2.search_xd(&[0.0; 3], 2, SearchParam::Knn { knn: 1 }).unwrap_err().code,
        ErrorCode::InvalidArgument
    );
    assert_eq!(KDTreeFlann::from_points_xd(&flat, 4).unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(KDTreeFlann::from_points_xd(&[f64::NAN, 0.0], 2).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn data_through_the_array_family() {
    let mut f = Feature::new(2, 1).unwrap();
    assert!(f.has_data().unwrap());
    f.set_data(&[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).unwrap();
    assert_eq!((f.dimension(), f.num()), (2, 3));
    assert_eq!(f.data(), &[1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(f.descriptor_rows::<2>().unwrap(), &[[1.0, 2.0], [3.0, 4.0], [5.0, 6.0]]);
    assert_eq!(f.descriptor_rows::<3>().unwrap_err().code, ErrorCode::InvalidArgument);
    assert_eq!(f.set_data(&[1.0, 2.0, 3.0]).unwrap_err().code, ErrorCode::InvalidArgument);
    f.set_descriptors_f32(&[[0.5f32, 0.25]]).unwrap();
    assert_eq!(f.data(), &[0.5, 0.25]);
    assert_eq!(f.set_descriptors_f32(&[[0.5f32; 3]]).unwrap_err().code, ErrorCode::InvalidArgument);
}
