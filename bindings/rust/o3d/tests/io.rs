//! Reading and writing: files, memory, formats, errors.
mod common;

use common::*;
use o3d::io::{self, ReadOptions, WriteOptions};
use o3d::{ErrorCode, PointCloud};

/// Max coordinate difference between two equally long arrays.
fn max_diff(a: &[[f64; 3]], b: &[[f64; 3]]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter().zip(b).flat_map(|(p, q)| (0..3).map(move |i| (p[i] - q[i]).abs())).fold(0.0, f64::max)
}

/// PLY stores doubles (exact); PCD stores float32, as Open3D does.
fn tolerance(name: &str) -> f64 {
    if name.ends_with("ply") {
        0.0
    } else {
        3.0 * f32::EPSILON as f64 * 3.0
    }
}

fn sample_cloud() -> PointCloud {
    let mut rng = Rng::new(21);
    let pts = rng.points(200, -3.0, 3.0);
    let normals: Vec<[f64; 3]> = pts
        .iter()
        .map(|p| {
            let n = norm(*p);
            [p[0] / n, p[1] / n, p[2] / n]
        })
        .collect();
    let colors: Vec<[f64; 3]> = (0..200).map(|i| [i as f64 / 255.0, 0.5, 1.0]).collect();
    let mut pc = PointCloud::from_points(&pts).unwrap();
    pc.set_normals(&normals).unwrap();
    pc.set_colors(&colors).unwrap();
    pc
}

#[test]
fn file_round_trip_binary_formats() {
    let dir = TempDir::new("io");
    let pc = sample_cloud();
    for (name, opts) in [
        ("a.ply", WriteOptions::default()),
        ("b.pcd", WriteOptions::default()),
        ("c.pcd", WriteOptions { compressed: true, ..Default::default() }),
    ] {
        let path = dir.path(name);
        io::write_point_cloud(&path, &pc, "auto", &opts).unwrap();
        assert!(std::fs::metadata(&path).unwrap().len() > 0);
        let back = io::read_point_cloud(&path, "auto", &ReadOptions::default()).unwrap();
        assert!(max_diff(back.points(), pc.points()) <= tolerance(name), "{name}");
        assert!(max_diff(back.normals(), pc.normals()) <= tolerance(name), "{name}");
        assert_eq!(back.colors().len(), 200, "{name}");
        for (a, b) in back.colors().iter().zip(pc.colors()) {
            assert!((0..3).all(|i| (a[i] - b[i]).abs() <= 0.5 / 255.0 + 1e-12), "{name}: {a:?} vs {b:?}");
        }
    }
}

#[test]
fn file_round_trip_ascii_with_explicit_format() {
    let dir = TempDir::new("io-ascii");
    let pc = sample_cloud();
    let path = dir.path("cloud.txt");
    io::write_point_cloud(&path, &pc, "xyzn", &WriteOptions::default()).unwrap();
    let back = io::read_point_cloud(&path, "xyzn", &ReadOptions::default()).unwrap();
    assert_eq!(back.len(), 200);
    assert!(back.has_normals().unwrap());
    for (a, b) in back.points().iter().zip(pc.points()) {
        assert!(dist2(*a, *b) < 1e-12, "{a:?} vs {b:?}");
    }
    let ply = dir.path("ascii.ply");
    io::write_point_cloud(&ply, &pc, "auto", &WriteOptions { write_ascii: true, ..Default::default() }).unwrap();
    assert!(std::fs::read_to_string(&ply).unwrap().contains("format ascii"));
}

#[test]
fn memory_round_trip() {
    let pc = sample_cloud();
    for format in ["ply", "pcd"] {
        let bytes = io::write_point_cloud_to_memory(&pc, format, &WriteOptions::default()).unwrap();
        assert!(bytes.len() > 200 * 3 * 8, "{format}: {} bytes", bytes.len());
        let back = io::read_point_cloud_from_memory(&bytes, format, &ReadOptions::default()).unwrap();
        assert!(max_diff(back.points(), pc.points()) <= tolerance(format), "{format}");
        assert!(max_diff(back.normals(), pc.normals()) <= tolerance(format), "{format}");
    }
    // The zero-copy buffer and its copy agree.
    let buf = io::write_point_cloud_to_buffer(&pc, "ply", &WriteOptions::default()).unwrap();
    assert_eq!(buf.as_bytes().unwrap(), &buf.to_vec().unwrap()[..]);
    assert!(buf.as_bytes().unwrap().starts_with(b"ply"));
}

#[test]
fn read_options_remove_non_finite_points() {
    let text = b"0 0 0\nnan 1 1\n2 2 2\ninf 0 0\n";
    let all = io::read_point_cloud_from_memory(text, "xyz", &ReadOptions::default()).unwrap();
    assert_eq!(all.len(), 4);
    let finite = io::read_point_cloud_from_memory(
        text,
        "xyz",
        &ReadOptions { remove_nan_points: true, remove_infinite_points: true },
    )
    .unwrap();
    assert_eq!(finite.points(), &[[0.0; 3], [2.0; 3]]);
}

#[test]
fn missing_file_is_io_error() {
    let dir = TempDir::new("io-missing");
    let err = io::read_point_cloud(dir.path("nope.pcd"), "auto", &ReadOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::Io, "{err}");
    assert!(err.message.contains("nope.pcd"), "{err}");
}

#[test]
fn garbage_bytes_are_parse_error() {
    let garbage = b"this is not a point cloud \x00\x01\x02\xff";
    for format in ["pcd", "ply"] {
        let err = io::read_point_cloud_from_memory(garbage, format, &ReadOptions::default()).unwrap_err();
        assert_eq!(err.code, ErrorCode::Parse, "{format}: {err}");
        assert!(!err.message.is_empty());
    }
    let dir = TempDir::new("io-garbage");
    let path = dir.path("bad.pcd");
    std::fs::write(&path, garbage).unwrap();
    let err = io::read_point_cloud(&path, "auto", &ReadOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::Parse, "{err}");
}

#[test]
fn unknown_format_and_bad_strings_are_rejected() {
    let pc = sample_cloud();
    let err = io::write_point_cloud_to_memory(&pc, "nosuchformat", &WriteOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::Unsupported, "{err}");
    let err = io::read_point_cloud_from_memory(b"0 0 0\n", "xy\0z", &ReadOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
}

#[cfg(unix)]
#[test]
fn non_utf8_path_is_invalid_argument() {
    use std::ffi::OsStr;
    use std::os::unix::ffi::OsStrExt;
    let path = std::path::Path::new(OsStr::from_bytes(b"/tmp/\xff\xfe.pcd"));
    let err = io::read_point_cloud(path, "auto", &ReadOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
    assert!(err.message.contains("UTF-8"));
    let err = io::write_point_cloud(path, &sample_cloud(), "pcd", &WriteOptions::default()).unwrap_err();
    assert_eq!(err.code, ErrorCode::InvalidArgument);
}
