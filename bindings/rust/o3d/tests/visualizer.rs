//! Visualizer: a hidden 160 x 120 window (EGL, no display needed) showing a unit cube centred at the
//! origin, lights off so that its pixels have exactly its colour. Checked against Open3D's ViewControl
//! model (the default view's depth at the centre), by the effect of keys and callbacks on the render
//! option, the view and the captured image, and the error paths. Test names start with `visualizer_`.
use std::cell::Cell;
use std::ops::ControlFlow;
use std::rc::Rc;

use o3d::visualization::{KeyAction, MouseButton, View, Visualizer};
use o3d::{sys, ErrorCode, Image, TriangleMesh};

const W: usize = 160;
const H: usize = 120;

fn window(color: [f64; 3]) -> Visualizer {
    let vis = Visualizer::new().unwrap();
    vis.create_window("test", W as i32, H as i32, -1, -1, false).unwrap();
    let mut cube = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    cube.translate([-0.5, -0.5, -0.5], true).unwrap();
    cube.paint_uniform_color(color).unwrap();
    vis.add_geometry("cube", &cube, true).unwrap();
    let mut option = vis.render_option().unwrap();
    option.light_on = false;
    vis.set_render_option(&option).unwrap();
    vis
}

fn floats(image: &Image) -> Vec<f32> {
    image.data().unwrap().chunks_exact(4).map(|b| f32::from_ne_bytes([b[0], b[1], b[2], b[3]])).collect()
}

fn rgb_at(vis: &Visualizer, u: usize, v: usize) -> [f32; 3] {
    let f = floats(&vis.capture_screen_float_buffer().unwrap());
    let i = (v * W + u) * 3;
    [f[i], f[i + 1], f[i + 2]]
}

fn background_pixels(vis: &Visualizer) -> usize {
    floats(&vis.capture_screen_float_buffer().unwrap()).chunks_exact(3).filter(|p| p == &[1.0, 1.0, 1.0]).count()
}

#[test]
fn visualizer_default_view_matches_the_viewcontrol_model() {
    let vis = window([1.0, 0.0, 0.0]);
    assert_eq!(rgb_at(&vis, 0, 0), [1.0, 1.0, 1.0]); // white background
    assert_eq!(rgb_at(&vis, W / 2, H / 2), [1.0, 0.0, 0.0]); // the cube's colour, unlit
                                                             // Eye on +z at zoom * extent / tan(30 deg) from the centre; the front face is 0.5 nearer.
    let depth = floats(&vis.capture_depth_float_buffer().unwrap())[H / 2 * W + W / 2] as f64;
    let expected = 0.7 / (30f64).to_radians().tan() - 0.5;
    assert!((depth - expected).abs() < 1e-3 * expected, "depth {depth} vs {expected}");
    assert_eq!(vis.field_of_view().unwrap(), 60.0);
    let view = vis.view().unwrap();
    assert_eq!((view.front, view.up, view.zoom), ([0.0, 0.0, 1.0], [0.0, 1.0, 0.0], 0.7));
    assert!(vis.has_geometry("cube").unwrap() && !vis.has_geometry("other").unwrap());
}

#[test]
fn visualizer_builtin_keys_by_their_effect() {
    let vis = window([1.0, 0.0, 0.0]);
    vis.send_key('=' as i32, KeyAction::Press, 0).unwrap();
    assert_eq!(vis.render_option().unwrap().point_size, 6.0);
    let default_view = background_pixels(&vis);
    vis.send_key('[' as i32, KeyAction::Press, 0).unwrap();
    assert_eq!(vis.field_of_view().unwrap(), 55.0);
    assert_ne!(background_pixels(&vis), default_view); // another perspective
    vis.send_key('R' as i32, KeyAction::Press, 0).unwrap();
    assert_eq!(vis.field_of_view().unwrap(), 60.0);
    assert_eq!(background_pixels(&vis), default_view);
    assert!(vis.poll_events().unwrap());
    vis.send_key('Q' as i32, KeyAction::Press, 0).unwrap();
    assert!(!vis.poll_events().unwrap()); // Q closed it
}

#[test]
fn visualizer_key_callbacks_change_the_capture() {
    let mut vis = window([1.0, 0.0, 0.0]);
    let calls = Rc::new(Cell::new(0));
    let seen = calls.clone();
    vis.register_key_callback('K' as i32, move |v, action, mods| {
        seen.set(seen.get() + 1);
        assert_eq!((action, mods), (KeyAction::Press, sys::O3D_KEY_MOD_SHIFT));
        let mut option = v.render_option().unwrap();
        option.background_color = [0.0; 3];
        v.set_render_option(&option).unwrap();
        true
    })
    .unwrap();
    vis.send_key('K' as i32, KeyAction::Release, 0).unwrap(); // not on release
    assert_eq!(calls.get(), 0);
    vis.send_key('K' as i32, KeyAction::Press, sys::O3D_KEY_MOD_SHIFT).unwrap();
    assert_eq!(calls.get(), 1);
    assert_eq!(rgb_at(&vis, 0, 0), [0.0, 0.0, 0.0]);
    // An action callback runs on release too, instead of the '=' binding.
    let actions = Rc::new(Cell::new(Vec::new()));
    let log = actions.clone();
    vis.register_key_action_callback('=' as i32, move |_, action, _| {
        log.set([log.take(), vec![action]].concat());
        false
    })
    .unwrap();
    vis.send_key('=' as i32, KeyAction::Press, 0).unwrap();
    vis.send_key('=' as i32, KeyAction::Release, 0).unwrap();
    assert_eq!(actions.take(), [KeyAction::Press, KeyAction::Release]);
    assert_eq!(vis.render_option().unwrap().point_size, 5.0);
}

#[test]
fn visualizer_animation_callback_rotates_the_view_then_closes() {
    let mut vis = window([0.0, 0.0, 1.0]);
    let still = background_pixels(&vis);
    let frames = Rc::new(Cell::new(0));
    let counter = frames.clone();
    vis.register_animation_callback(move |v| {
        v.rotate(10.0, 0.0).unwrap();
        counter.set(counter.get() + 1);
        if counter.get() == 5 {
            v.close().unwrap();
        }
        true
    })
    .unwrap();
    vis.run().unwrap();
    assert_eq!(frames.get(), 5);
    let front = vis.view().unwrap().front; // five turns of 10 px = 0.15 rad about up
    let expected = [-(0.15f64).sin(), 0.0, (0.15f64).cos()];
    assert!(front.iter().zip(expected).all(|(a, b)| (a - b).abs() < 1e-9), "{front:?}");
    assert_ne!(background_pixels(&vis), still);
}

#[test]
fn visualizer_panicking_callbacks_make_run_and_send_err() {
    let mut vis = window([0.0, 1.0, 0.0]);
    vis.register_animation_callback(|_| panic!("spin failed on purpose")).unwrap();
    let err = vis.run().unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled);
    assert!(err.message.contains("spin failed on purpose"), "{}", err.message);
    vis.register_key_callback('K' as i32, |_, _, _| panic!("key failed")).unwrap();
    let err = vis.send_key('K' as i32, KeyAction::Press, 0).unwrap_err();
    assert!(err.message.contains("key failed"), "{}", err.message);
    // A callback sending its own key would run itself inside itself: the inner send is refused, not aliased.
    let inner = Rc::new(Cell::new(None));
    let report = inner.clone();
    vis.register_key_callback('J' as i32, move |v, _, _| {
        report.set(v.send_key('J' as i32, KeyAction::Press, 0).err());
        false
    })
    .unwrap();
    vis.send_key('J' as i32, KeyAction::Press, 0).unwrap();
    let err = inner.take().expect("the inner send_key failed");
    assert!(err.code == ErrorCode::Cancelled && err.message.contains("inside itself"), "{err}");
    // The visualizer still works afterwards.
    vis.register_animation_callback(|v| v.close().is_ok()).unwrap();
    vis.run().unwrap();
}

#[test]
fn visualizer_pinhole_round_trip_gives_the_same_capture() {
    let vis = window([0.0, 1.0, 0.0]);
    vis.rotate(120.0, -40.0).unwrap();
    vis.change_field_of_view(-2.0).unwrap(); // 50 degrees
    let camera = vis.to_pinhole().unwrap();
    assert!((camera.intrinsic.fy - H as f64 / (2.0 * (25f64).to_radians().tan())).abs() < 1e-9);
    let before = vis.capture_screen_float_buffer().unwrap().data().unwrap().to_vec();
    vis.reset_view().unwrap();
    assert_ne!(vis.capture_screen_float_buffer().unwrap().data().unwrap(), &before[..]);
    vis.from_pinhole(&camera).unwrap();
    assert_eq!(vis.capture_screen_float_buffer().unwrap().data().unwrap(), &before[..]);
    let mut off = camera;
    off.intrinsic.cx += 3.0;
    assert_eq!(vis.from_pinhole(&off).unwrap_err().code, ErrorCode::InvalidArgument);
}

#[test]
fn visualizer_view_status_set_view_and_mouse() {
    let vis = window([1.0, 0.0, 0.0]);
    vis.rotate(50.0, 20.0).unwrap();
    let (status, turned) = (vis.view_status().unwrap(), vis.view().unwrap());
    assert!(status.contains("\"class_name\": \"ViewTrajectory\""), "{status}");
    vis.reset_view().unwrap();
    vis.set_view_status(&status).unwrap();
    let again = vis.view().unwrap();
    assert!(again.front.iter().zip(turned.front).all(|(a, b)| (a - b).abs() < 1e-9));
    assert_eq!(vis.set_view_status("{\"class_name\": \"RenderOption\"}").unwrap_err().code, ErrorCode::Parse);
    let side = View { front: [1.0, 0.0, 0.0], lookat: [0.0; 3], up: [0.0, 1.0, 0.0], zoom: 0.5 };
    vis.set_view(&side).unwrap();
    assert_eq!(vis.view().unwrap(), side);
    // A left drag of 100 px turns by 0.3 rad; the wheel steps the zoom by 0.02.
    vis.reset_view().unwrap();
    vis.send_mouse_move(10.0, 10.0).unwrap();
    vis.send_mouse_button(MouseButton::Left, KeyAction::Press, 0).unwrap();
    vis.send_mouse_move(110.0, 10.0).unwrap();
    vis.send_mouse_button(MouseButton::Left, KeyAction::Release, 0).unwrap();
    vis.send_scroll(0.0, 5.0).unwrap();
    let view = vis.view().unwrap();
    assert!((view.front[0] + (0.3f64).sin()).abs() < 1e-9 && (view.zoom - 0.8).abs() < 1e-12, "{view:?}");
}

#[test]
fn visualizer_editing_picks_and_trajectory_playback() {
    let vis = Visualizer::with_editing().unwrap();
    vis.create_window("edit", W as i32, H as i32, -1, -1, false).unwrap();
    let points = [[-0.5, 0.0, 0.0], [0.0, 0.3, 0.0], [0.5, -0.2, 0.1]];
    vis.add_geometry("cloud", &o3d::PointCloud::from_points(&points).unwrap(), true).unwrap();
    let camera = vis.to_pinhole().unwrap();
    let (e, k) = (camera.extrinsic, camera.intrinsic);
    let p = points[2];
    let c: Vec<f64> = (0..3).map(|r| (0..3).map(|j| e[r][j] * p[j]).sum::<f64>() + e[r][3]).collect();
    vis.send_mouse_move(k.fx * c[0] / c[2] + k.cx + 1.0, k.fy * c[1] / c[2] + k.cy).unwrap();
    vis.send_mouse_button(MouseButton::Left, KeyAction::Press, sys::O3D_KEY_MOD_SHIFT).unwrap();
    vis.send_mouse_button(MouseButton::Left, KeyAction::Release, sys::O3D_KEY_MOD_SHIFT).unwrap();
    assert_eq!(vis.picked_points().unwrap(), [2]);
    // Two key views two frames apart: four frames, each written, the last view kept.
    let dir = std::env::temp_dir().join(format!("o3d-rust-visualizer-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("trajectory.json");
    let key = |front: &str| {
        format!("{{\"boundingbox_max\": [0.5, 0.5, 0.5], \"boundingbox_min\": [-0.5, -0.5, -0.5], \"field_of_view\": 60.0, \"front\": {front}, \"lookat\": [0, 0, 0], \"up\": [0, 1, 0], \"zoom\": 0.7}}")
    };
    let json = format!(
        "{{\"class_name\": \"ViewTrajectory\", \"interval\": 2, \"is_loop\": false, \"trajectory\": [{}, {}]}}",
        key("[0, 0, 1]"),
        key("[1, 0, 0]")
    );
    std::fs::write(&path, json).unwrap();
    let mut fractions = Vec::new();
    vis.play_view_trajectory(&path, Some(&dir), false, |f| {
        fractions.push(f);
        ControlFlow::Continue(())
    })
    .unwrap();
    assert_eq!(fractions.len(), 4);
    assert_eq!(fractions.last(), Some(&1.0));
    assert!((vis.view().unwrap().front[0] - 1.0).abs() < 1e-12);
    assert!((0..4).all(|i| dir.join(format!("image_{i:06}.png")).is_file()));
    let err = vis.play_view_trajectory(&path, None, false, |_| ControlFlow::Break(())).unwrap_err();
    assert_eq!(err.code, ErrorCode::Cancelled);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn visualizer_errors_are_err_not_panics() {
    let vis = Visualizer::new().unwrap();
    assert_eq!(vis.run().unwrap_err().code, ErrorCode::InvalidArgument); // no window
    assert_eq!(vis.rotate(1.0, 1.0).unwrap_err().code, ErrorCode::InvalidArgument);
    assert!(vis.capture_screen_float_buffer().is_err() && vis.view().is_err() && vis.render_option().is_err());
    assert!(vis.add_geometry("c", &TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap(), true).is_err());
    assert_eq!(vis.create_window("x", 0, 10, -1, -1, false).unwrap_err().code, ErrorCode::InvalidArgument);
    vis.create_window("x", W as i32, H as i32, -1, -1, false).unwrap();
    assert!(vis.create_window("x", W as i32, H as i32, -1, -1, false).is_err()); // already open
    assert!(vis.remove_geometry("absent", true).is_err());
    assert!(vis.rotate(f64::INFINITY, 0.0).is_err());
    assert!(vis.capture_depth_image("/tmp/x.png", 0.0).is_err());
    assert_eq!(vis.capture_screen_image("/nonexistent/dir/x.png").unwrap_err().code, ErrorCode::Io);
    let bad = View { front: [0.0, 1.0, 0.0], lookat: [0.0; 3], up: [0.0, 1.0, 0.0], zoom: 0.7 };
    assert!(vis.set_view(&bad).is_err()); // front parallel to up
    vis.run().unwrap(); // a hidden window without an animation callback: one frame
    vis.destroy_window().unwrap();
    assert!(vis.poll_events().is_ok());
}

#[test]
fn visualizer_figure2_example_writes_turning_frames() {
    // Cargo builds examples before integration tests; find it next to this test binary.
    let exe = std::env::current_exe().unwrap().parent().unwrap().parent().unwrap().join("examples/figure2");
    assert!(exe.exists(), "{} was not built (run plain `cargo test`)", exe.display());
    let dir = std::env::temp_dir().join(format!("o3d-rust-figure2-{}", std::process::id()));
    let run = std::process::Command::new(&exe).arg(&dir).arg("4").output().unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success(), "stdout: {stdout}\nstderr: {}", String::from_utf8_lossy(&run.stderr));
    let paths: Vec<&str> = stdout.lines().collect();
    assert_eq!(paths.len(), 4, "{stdout}");
    let frames: Vec<Image> = paths.iter().map(|p| o3d::io::read_image(p, "auto").unwrap()).collect();
    assert_eq!((frames[0].width().unwrap(), frames[0].height().unwrap()), (640, 480));
    // A quarter turn apart, each frame shows the scene from another side, and none is empty.
    assert!(frames.iter().all(|f| f.data().unwrap().iter().any(|&b| b < 200)));
    assert!(frames.windows(2).all(|w| w[0].data().unwrap() != w[1].data().unwrap()));
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(std::process::Command::new(&exe).output().unwrap().status.code(), Some(2));
}

#[test]
fn visualizer_images_are_shown_flat_and_scaled_to_fit() {
    let vis = Visualizer::new().unwrap();
    vis.create_window("image", W as i32, H as i32, -1, -1, false).unwrap();
    let green: Vec<u8> = [0u8, 255, 0].repeat(8 * 8);
    let image = Image::from_bytes(8, 8, 3, o3d::PixelType::U8, &green).unwrap();
    vis.add_image("photo", &image, true).unwrap();
    assert!(vis.has_geometry("photo").unwrap());
    // 8 x 8 scaled to the window's height and centred: columns 20..139 of 160.
    assert_eq!(rgb_at(&vis, W / 2, H / 2), [0.0, 1.0, 0.0]);
    assert_eq!(rgb_at(&vis, 25, 5), [0.0, 1.0, 0.0]);
    assert_eq!(rgb_at(&vis, 5, H / 2), [1.0, 1.0, 1.0]);
    let empty = Image::new(0, 0, 3, o3d::PixelType::U8);
    assert!(empty.is_err() || vis.add_image("empty", &empty.unwrap(), true).is_err());
}
