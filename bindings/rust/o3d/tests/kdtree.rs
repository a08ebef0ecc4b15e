//! KDTreeFlann batch searches against brute force.
mod common;

use common::*;
use o3d::{KDTreeFlann, PointCloud, SearchParam};

/// Brute-force neighbours of `q`, sorted by (distance, index).
fn brute(points: &[[f64; 3]], q: [f64; 3]) -> Vec<(f64, i32)> {
    let mut all: Vec<(f64, i32)> = points.iter().enumerate().map(|(i, p)| (dist2(*p, q), i as i32)).collect();
    all.sort_by(|a, b| a.partial_cmp(b).unwrap());
    all
}

#[test]
fn knn_matches_brute_force() {
    let mut rng = Rng::new(7);
    let points = rng.points(2000, -1.0, 1.0);
    let queries = rng.points(100, -1.2, 1.2);
    let tree = KDTreeFlann::new(&PointCloud::from_points(&points).unwrap()).unwrap();
    assert_eq!(tree.len().unwrap(), 2000);
    assert!(!tree.is_empty().unwrap());
    assert!(KDTreeFlann::from_points(&[]).unwrap().is_empty().unwrap());
    let r = tree.search(&queries, SearchParam::Knn { knn: 8 }).unwrap();
    assert_eq!(r.num_queries(), 100);
    assert_eq!(r.offsets.len(), 101);
    assert_eq!(r.indices.len(), 800);
    for (qi, q) in queries.iter().enumerate() {
        let (idx, d2) = r.neighbors(qi);
        let expected = brute(&points, *q);
        assert_eq!(idx.len(), 8);
        for k in 0..8 {
            assert!((d2[k] - expected[k].0).abs() < 1e-12, "query {qi} rank {k}");
            assert_eq!(dist2(points[idx[k] as usize], *q), d2[k], "distance matches the returned index");
        }
        let mut got: Vec<i32> = idx.to_vec();
        let mut want: Vec<i32> = expected[..8].iter().map(|e| e.1).collect();
        got.sort();
        want.sort();
        assert_eq!(got, want, "query {qi}");
    }
}

#[test]
fn radius_and_hybrid_match_brute_force() {
    let mut rng = Rng::new(11);
    let points = rng.points(1500, 0.0, 1.0);
    let queries = rng.points(50, 0.0, 1.0);
    let tree = KDTreeFlann::from_points(&points).unwrap();
    let radius = 0.15;
    let r = tree.search(&queries, SearchParam::Radius { radius }).unwrap();
    let h = tree.search(&queries, SearchParam::Hybrid { radius, max_nn: 5 }).unwrap();
    for (qi, q) in queries.iter().enumerate() {
        let expected: Vec<(f64, i32)> = brute(&points, *q).into_iter().filter(|e| e.0 <= radius * radius).collect();
        let (idx, d2) = r.neighbors(qi);
        assert_eq!(idx.len(), expected.len(), "query {qi}");
        let mut got: Vec<i32> = idx.to_vec();
        got.sort();
        let mut want: Vec<i32> = expected.iter().map(|e| e.1).collect();
        want.sort();
        assert_eq!(got, want);
        assert!(d2.windows(2).all(|w| w[0] <= w[1]), "sorted by distance");
        let (hidx, hd2) = h.neighbors(qi);
        assert_eq!(hidx.len(), expected.len().min(5));
        for k in 0..hidx.len() {
            assert!((hd2[k] - expected[k].0).abs() < 1e-12);
        }
    }
}

#[test]
fn zero_copy_result_f32_queries_and_single_query_helpers() {
    let points: Vec<[f64; 3]> = (0..10).map(|i| [i as f64, 0.0, 0.0]).collect();
    let tree = KDTreeFlann::from_points(&points).unwrap();
    let queries = [[2.2f32, 0.0, 0.0], [8.9, 0.0, 0.0]];
    let r = tree.search_ref_f32(&queries, SearchParam::Knn { knn: 2 }).unwrap();
    assert_eq!(r.counts().unwrap(), (2, 4));
    let (offsets, indices, d2) = r.view().unwrap();
    assert_eq!(offsets, &[0, 2, 4]);
    assert_eq!(indices, &[2, 3, 9, 8]);
    assert!((d2[0] - (2.2f32 as f64 - 2.0).powi(2)).abs() < 1e-12);
    let owned = r.to_search_result().unwrap();
    assert_eq!(
        (owned.offsets.as_slice(), owned.indices.as_slice(), owned.distances2.as_slice()),
        (offsets, indices, d2)
    );
    assert_eq!(tree.search_f32(&queries, SearchParam::Knn { knn: 2 }).unwrap(), owned);

    let (idx, d2) = tree.search_knn_vector_3d([4.4, 0.0, 0.0], 3).unwrap();
    assert_eq!(idx, vec![4, 5, 3]);
    assert!((d2[0] - 0.16).abs() < 1e-12);
    let (idx, _) = tree.search_radius_vector_3d([4.5, 0.0, 0.0], 1.0).unwrap();
    assert_eq!(idx.len(), 2);
    let (idx, _) = tree.search_hybrid_vector_3d([0.0, 0.0, 0.0], 100.0, 4).unwrap();
    assert_eq!(idx, vec![0, 1, 2, 3]);
}

#[test]
fn tree_outlives_its_cloud_and_rejects_non_finite_points() {
    let pc = PointCloud::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    let tree = KDTreeFlann::new(&pc).unwrap();
    drop(pc);
    assert_eq!(tree.search_knn_vector_3d([0.9; 3], 1).unwrap().0, vec![1]);
    let err = KDTreeFlann::from_points(&[[f64::NAN, 0.0, 0.0]]).unwrap_err();
    assert_eq!(err.code, o3d::ErrorCode::InvalidArgument);
    assert!(!err.message.is_empty());
    // Searches are `&self` and may run concurrently.
    let tree = KDTreeFlann::from_points(&Rng::new(5).points(300, 0.0, 1.0)).unwrap();
    let results: Vec<_> = std::thread::scope(|s| {
        let hs: Vec<_> =
            (0..3).map(|_| s.spawn(|| tree.search(&[[0.5; 3]], SearchParam::Knn { knn: 5 }).unwrap())).collect();
        hs.into_iter().map(|h| h.join().unwrap()).collect()
    });
    assert!(results.windows(2).all(|w| w[0] == w[1]));
}
