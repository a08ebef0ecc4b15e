//! Version, verbosity, threads, logging callback.
use std::sync::{Arc, Mutex};

use o3d::{LogLevel, PointCloud};

#[test]
fn version_is_consistent() {
    let (major, minor, patch) = o3d::version_numbers();
    assert_eq!(o3d::version(), format!("{major}.{minor}.{patch}"));
    assert_eq!(major, o3d::sys::O3D_VERSION_MAJOR);
}

#[test]
fn error_code_names_come_from_the_library() {
    assert_eq!(o3d::ErrorCode::Io.name(), "O3D_ERROR_IO");
    assert_eq!(o3d::ErrorCode::from_raw(-4), o3d::ErrorCode::Parse);
    assert_eq!(o3d::ErrorCode::Cancelled.raw(), -8);
    assert_eq!(o3d::ErrorCode::from_raw(-1000), o3d::ErrorCode::Other(-1000));
}

// One test owns the global settings (log sink, verbosity, thread count) so that tests running in
// parallel in this binary do not race on them.
#[test]
fn global_settings_and_log_callback() {
    // Threads.
    o3d::set_num_threads(2).unwrap();
    assert_eq!(o3d::get_num_threads(), 2);
    o3d::set_num_threads(0).unwrap();
    assert!(o3d::get_num_threads() >= 1);

    // Verbosity.
    let old = o3d::get_verbosity_level();
    o3d::set_verbosity_level(LogLevel::Debug).unwrap();
    assert_eq!(o3d::get_verbosity_level(), LogLevel::Debug);

    // Log lines reach the closure; a panicking closure is contained.
    let lines: Arc<Mutex<Vec<(LogLevel, String)>>> = Arc::default();
    let sink = lines.clone();
    o3d::set_log_callback(Some(move |level, msg: &str| sink.lock().unwrap().push((level, msg.to_string())))).unwrap();
    // Every failure is logged at debug level with its message, on the failing thread.
    let pc = PointCloud::from_points(&[[0.0; 3], [1.0; 3]]).unwrap();
    let err = pc.voxel_down_sample(f64::NAN).unwrap_err();
    let got = lines.lock().unwrap().clone();
    assert!(
        got.iter().any(|(level, m)| *level == LogLevel::Debug && *m == err.message),
        "log lines {got:?} lack the failure {err:?}"
    );
    // Below debug level, nothing is delivered for it.
    o3d::set_verbosity_level(LogLevel::Warning).unwrap();
    lines.lock().unwrap().clear();
    let _ = pc.voxel_down_sample(f64::NAN).unwrap_err();
    assert!(lines.lock().unwrap().is_empty());
    // A panicking closure is contained (the call still returns its error normally).
    o3d::set_verbosity_level(LogLevel::Debug).unwrap();
    o3d::set_log_callback(Some(|_, _: &str| panic!("contained"))).unwrap();
    assert_eq!(pc.voxel_down_sample(f64::NAN).unwrap_err().code, o3d::ErrorCode::InvalidArgument);
    // None restores the default sink; the old closure is no longer called.
    static CALLS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    o3d::set_log_callback(Some(|_, _: &str| {
        CALLS.fetch_add(1, std::sync::atomic::Ordering::SeqCst);
    }))
    .unwrap();
    let _ = pc.voxel_down_sample(f64::NAN).unwrap_err();
    assert_eq!(CALLS.load(std::sync::atomic::Ordering::SeqCst), 1);
    o3d::set_log_callback(None::<fn(LogLevel, &str)>).unwrap();
    let _ = pc.voxel_down_sample(f64::NAN).unwrap_err(); // goes to stderr
    assert_eq!(CALLS.load(std::sync::atomic::Ordering::SeqCst), 1);
    o3d::set_verbosity_level(old).unwrap();
    assert_eq!(o3d::get_verbosity_level(), old);
}
