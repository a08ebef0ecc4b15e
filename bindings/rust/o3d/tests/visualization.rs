//! OffscreenRenderer: pixels against a known pinhole camera. The scene is a unit box
//! [-0.5, 0.5]^2 x [2.5, 3.5] seen from the origin along +z with fx = fy = 100 and the principal point
//! at the image centre (79.5, 59.5) of a 160 x 120 image, so its front face (z = 2.5) covers the
//! 40 x 40 pixels 60..99 x 40..79 and the depth along the axis there is 2.5. Test names start with
//! `visualization_` so that `cargo test visualization` selects them.
mod common;

use common::*;
use o3d::visualization::{ColorOption, OffscreenRenderer, RenderBackend, RenderMaterial, RenderOption, Shader};
use o3d::{io, ErrorCode, Image, LineSet, PinholeIntrinsic, PointCloud, TriangleMesh, VoxelGrid};

const W: usize = 160;
const H: usize = 120;
/// A pixel on the box's front face, next to the optical axis.
const CENTRE: (usize, usize) = (80, 60);
const BOX_COLOR: [f64; 3] = [0.2, 0.4, 0.6];
const WHITE: [f64; 3] = [1.0; 3];
const IDENTITY: [[f64; 4]; 4] =
    [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];

fn camera_k() -> PinholeIntrinsic {
    PinholeIntrinsic::new(W as i32, H as i32, 100.0, 100.0, 79.5, 59.5)
}

fn unit_box(color: [f64; 3]) -> TriangleMesh {
    let mut b = TriangleMesh::create_box(1.0, 1.0, 1.0).unwrap();
    b.translate([-0.5, -0.5, 2.5], true).unwrap();
    b.paint_uniform_color(color).unwrap();
    b
}

fn unlit() -> RenderMaterial {
    RenderMaterial::with_shader(Shader::DefaultUnlit)
}

/// A renderer looking through camera_k() from the origin.
fn pinhole_renderer() -> OffscreenRenderer {
    let mut r = OffscreenRenderer::new(W as i32, H as i32, RenderBackend::Auto).unwrap();
    r.setup_camera(&camera_k(), &IDENTITY).unwrap();
    r
}

fn pixel(img: &Image, (u, v): (usize, usize)) -> [u8; 3] {
    let d = img.data().unwrap();
    let i = (v * W + u) * 3;
    [d[i], d[i + 1], d[i + 2]]
}

/// `color` in [0, 1] as 8-bit, within one step (rounding or truncation).
fn assert_rgb(got: [u8; 3], color: [f64; 3], what: &str) {
    for c in 0..3 {
        assert!((f64::from(got[c]) - 255.0 * color[c]).abs() <= 1.0, "{what}: {got:?} vs {color:?}");
    }
}

fn assert_corners(img: &Image, color: [f64; 3]) {
    for uv in [(0, 0), (W - 1, 0), (0, H - 1), (W - 1, H - 1)] {
        assert_rgb(pixel(img, uv), color, &format!("corner {uv:?}"));
    }
}

/// Pixels more than one step away from `background` in some channel.
fn count_not(img: &Image, background: [f64; 3]) -> usize {
    img.data()
        .unwrap()
        .chunks_exact(3)
        .filter(|p| (0..3).any(|c| (f64::from(p[c]) - 255.0 * background[c]).abs() > 1.0))
        .count()
}

fn depth_at(r: &mut OffscreenRenderer, z_in_view_space: bool, (u, v): (usize, usize)) -> f32 {
    r.render_to_depth_image(z_in_view_space).unwrap().to_f32_vec().unwrap()[v * W + u]
}

#[test]
fn visualization_option_and_material_defaults_are_open3ds() {
    let o = RenderOption::default();
    assert_eq!(o.background_color, WHITE);
    assert_eq!((o.point_size, o.line_width, o.light_on), (5.0, 1.0, true));
    assert_eq!((o.point_color_option, o.mesh_color_option), (ColorOption::Default, ColorOption::Color));
    assert_eq!(o.default_mesh_color, [0.7; 3]);
    assert_eq!(o.light_position, [[0.0, 0.0, 2.0], [0.0, 0.0, 2.0], [0.0, 0.0, -2.0], [0.0, 0.0, -2.0]]);
    assert_eq!(o.light_diffuse_power, [0.66; 4]);
    let m = RenderMaterial::default();
    assert_eq!((m.shader, m.base_color, m.point_size, m.line_width), (Shader::DefaultLit, [1.0; 4], 0.0, 0.0));
}

#[test]
fn visualization_option_json_round_trip_and_open3d_file() {
    let dir = TempDir::new("visualization");
    let o = RenderOption {
        background_color: [0.1, 0.2, 0.3],
        point_size: 7.0,
        mesh_show_wireframe: true,
        mesh_color_option: ColorOption::ZCoordinate,
        light_color: [[1.0; 3], [0.5, 1.0, 1.0], [1.0; 3], [1.0; 3]],
        ..Default::default()
    };
    o.save_to_json(dir.path("option.json")).unwrap();
    let mut back = RenderOption::default();
    back.load_from_json(dir.path("option.json")).unwrap();
    assert_eq!(back, o);
    let err = back.load_from_json(dir.path("missing.json")).unwrap_err();
    assert_eq!(err.code, ErrorCode::Io);
    assert_eq!(back, o, "unchanged on error");

    let Some(path) = data_file("open3d/renderoption.json") else { return };
    // Open3D's file differs from the defaults only in point_color_option (9, Normal).
    let mut file = RenderOption::default();
    file.load_from_json(path).unwrap();
    assert_eq!(file, RenderOption { point_color_option: ColorOption::Normal, ..Default::default() });
}

#[test]
fn visualization_unlit_box_color_depth_and_silhouette_under_a_pinhole_camera() {
    let mut r = pinhole_renderer();
    assert!(matches!(r.backend().unwrap(), RenderBackend::Egl | RenderBackend::Glfw));
    assert_eq!(r.size().unwrap(), (W as i32, H as i32));
    r.add_geometry("box", &unit_box(BOX_COLOR), &unlit()).unwrap();

    let img = r.render_to_image().unwrap();
    assert_eq!((img.width().unwrap(), img.height().unwrap(), img.num_channels().unwrap()), (W as i32, H as i32, 3));
    assert_eq!(img.bytes_per_channel().unwrap(), 1);
    assert_corners(&img, WHITE);
    assert_rgb(pixel(&img, CENTRE), BOX_COLOR, "box centre");
    assert_rgb(pixel(&img, (61, 41)), BOX_COLOR, "inside the face's top-left corner");
    assert_rgb(pixel(&img, (58, 60)), WHITE, "left of the face");
    assert_rgb(pixel(&img, (80, 81)), WHITE, "below the face");
    // The silhouette is the front face: 40 x 40 pixels.
    let area = count_not(&img, WHITE) as f64;
    assert!((area - 1600.0).abs() <= 0.02 * 1600.0, "silhouette {area} pixels");

    assert!((depth_at(&mut r, true, CENTRE) - 2.5).abs() < 1e-3);
    assert!((depth_at(&mut r, true, (61, 41)) - 2.5).abs() < 1e-3);
    assert_eq!(depth_at(&mut r, true, (0, 0)), 0.0);
    let buffer = depth_at(&mut r, false, CENTRE);
    assert!(buffer > 0.0 && buffer < 1.0, "depth buffer {buffer}");
    assert_eq!(depth_at(&mut r, false, (W - 1, H - 1)), 1.0);

    let cam = r.camera().unwrap();
    assert_eq!(cam.intrinsic, camera_k());
    assert!(max_abs_diff(&cam.extrinsic, &IDENTITY) < 1e-12);
}

#[test]
fn visualization_background_tint_and_ambient_only_light() {
    let mut r = pinhole_renderer();
    let mut o = RenderOption { background_color: [0.1, 0.2, 0.3], ..Default::default() };
    r.set_render_option(&o).unwrap();
    assert_eq!(r.render_option().unwrap(), o);
    let tinted = RenderMaterial { base_color: [0.5, 1.0, 1.0, 1.0], ..unlit() };
    r.add_geometry("box", &unit_box(BOX_COLOR), &tinted).unwrap();
    let img = r.render_to_image().unwrap();
    assert_corners(&img, o.background_color);
    assert_rgb(pixel(&img, CENTRE), [0.1, 0.4, 0.6], "tinted box");

    // Lit with only ambient light: color * ambient (the header's formula, every light at power 0).
    o.light_on = true;
    o.light_ambient_color = [0.5; 3];
    o.light_diffuse_power = [0.0; 4];
    o.light_specular_power = [0.0; 4];
    r.set_render_option(&o).unwrap();
    r.clear_geometry().unwrap();
    r.add_geometry("box", &unit_box(BOX_COLOR), &RenderMaterial::default()).unwrap();
    assert_rgb(pixel(&r.render_to_image().unwrap(), CENTRE), [0.1, 0.2, 0.3], "ambient-lit box");
}

#[test]
fn visualization_scene_add_has_remove_clear() {
    let mut r = pinhole_renderer();
    assert!(!r.has_geometry("box").unwrap());
    r.add_geometry("box", &unit_box(BOX_COLOR), &unlit()).unwrap();
    assert!(r.has_geometry("box").unwrap());
    let taken = r.add_geometry("box", &unit_box(BOX_COLOR), &unlit()).unwrap_err();
    assert_eq!(taken.code, ErrorCode::InvalidArgument);
    assert!(!taken.message.is_empty());
    assert_eq!(r.add_geometry("", &unit_box(BOX_COLOR), &unlit()).unwrap_err().code, ErrorCode::InvalidArgument);
    r.remove_geometry("box").unwrap();
    assert!(!r.has_geometry("box").unwrap());
    assert_eq!(r.remove_geometry("box").unwrap_err().code, ErrorCode::InvalidArgument);
    assert_rgb(pixel(&r.render_to_image().unwrap(), CENTRE), WHITE, "removed box");

    // Geometries are copied: painting the mesh afterwards does not show.
    let mut mesh = unit_box(BOX_COLOR);
    r.add_geometry("a", &mesh, &unlit()).unwrap();
    mesh.paint_uniform_color([1.0, 0.0, 0.0]).unwrap();
    assert_rgb(pixel(&r.render_to_image().unwrap(), CENTRE), BOX_COLOR, "the copy added");
    r.add_geometry("b", &unit_box(BOX_COLOR), &unlit()).unwrap();
    r.clear_geometry().unwrap();
    assert!(!r.has_geometry("a").unwrap() && !r.has_geometry("b").unwrap());
    assert_eq!(count_not(&r.render_to_image().unwrap(), WHITE), 0);
}

#[test]
fn visualization_point_cloud_line_set_and_voxel_grid_on_the_axis() {
    let mut r = pinhole_renderer();
    let mut cloud = PointCloud::from_points(&[[0.0, 0.0, 2.5]]).unwrap();
    cloud.paint_uniform_color([1.0, 0.0, 0.0]).unwrap();
    r.add_geometry("cloud", &cloud, &RenderMaterial { point_size: 9.0, ..unlit() }).unwrap();
    let img = r.render_to_image().unwrap();
    assert_rgb(pixel(&img, CENTRE), [1.0, 0.0, 0.0], "point");
    assert_rgb(pixel(&img, (90, 60)), WHITE, "beside the point");

    // A horizontal line through the axis, 5 pixels wide.
    let mut line = LineSet::from_points_and_lines(&[[-1.0, 0.0, 2.5], [1.0, 0.0, 2.5]], &[[0, 1]]).unwrap();
    line.paint_uniform_color([0.0, 1.0, 0.0]).unwrap();
    r.clear_geometry().unwrap();
    r.add_geometry("line", &line, &RenderMaterial { line_width: 5.0, ..unlit() }).unwrap();
    let img = r.render_to_image().unwrap();
    assert_rgb(pixel(&img, CENTRE), [0.0, 1.0, 0.0], "line");
    assert_rgb(pixel(&img, (110, 60)), [0.0, 1.0, 0.0], "line, 30 pixels along");
    assert_rgb(pixel(&img, (80, 70)), WHITE, "below the line");

    // One voxel of edge 1 around (0, 0, 3): the unit box again.
    let mut centre = PointCloud::from_points(&[[0.0, 0.0, 3.0]]).unwrap();
    centre.paint_uniform_color([0.0, 0.0, 1.0]).unwrap();
    r.clear_geometry().unwrap();
    r.add_geometry("grid", &VoxelGrid::create_from_point_cloud(&centre, 1.0).unwrap(), &unlit()).unwrap();
    let img = r.render_to_image().unwrap();
    assert_rgb(pixel(&img, CENTRE), [0.0, 0.0, 1.0], "voxel");
    let area = count_not(&img, WHITE) as f64;
    assert!((area - 1600.0).abs() <= 0.02 * 1600.0, "voxel silhouette {area} pixels");
    assert!((depth_at(&mut r, true, CENTRE) - 2.5).abs() < 1e-3);
}

#[test]
fn visualization_fov_and_lookat_cameras_look_at_the_box() {
    let mut r = OffscreenRenderer::new(W as i32, H as i32, RenderBackend::Auto).unwrap();
    r.add_geometry("box", &unit_box(BOX_COLOR), &unlit()).unwrap();

    // From the origin towards +z with image-down = world +y: the pinhole camera, as a field of view.
    let fov = 2.0 * (60.0f64 / 100.0).atan().to_degrees(); // fy = (H / 2) / tan(fov / 2) = 100
    r.setup_camera_fov(fov, [0.0, 0.0, 3.0], [0.0; 3], [0.0, -1.0, 0.0]).unwrap();
    let cam = r.camera().unwrap();
    assert!((cam.intrinsic.fx - 100.0).abs() < 1e-6 && (cam.intrinsic.fy - 100.0).abs() < 1e-6, "{cam:?}");
    assert!(max_abs_diff(&cam.extrinsic, &IDENTITY) < 1e-9, "{cam:?}");
    assert!((depth_at(&mut r, true, CENTRE) - 2.5).abs() < 1e-3);

    // Open3D's view, looking at a point off the box's centre from -z (zoom 2 keeps the box inside the
    // image): that point projects on the optical axis, in front of the camera.
    let at = [0.2, 0.1, 3.0];
    r.setup_camera_lookat(at, [0.0, 0.0, -1.0], [0.0, -1.0, 0.0], 2.0).unwrap();
    let cam = r.camera().unwrap();
    let p = apply(&cam.extrinsic, at);
    assert!(p[0].abs() < 1e-9 && p[1].abs() < 1e-9 && p[2] > 1.0, "lookat in camera frame {p:?}");
    let img = r.render_to_image().unwrap();
    assert_rgb(pixel(&img, (W / 2, H / 2)), BOX_COLOR, "lookat centre");
    assert_corners(&img, WHITE);

    // setup_camera(camera()) reproduces the image (the box is off-centre, so a flip would show); at
    // most a few edge pixels may round differently.
    let mut again = OffscreenRenderer::new(W as i32, H as i32, RenderBackend::Auto).unwrap();
    again.add_geometry("box", &unit_box(BOX_COLOR), &unlit()).unwrap();
    again.setup_camera(&cam.intrinsic, &cam.extrinsic).unwrap();
    let (a, b) = (img.to_vec().unwrap(), again.render_to_image().unwrap().to_vec().unwrap());
    let differ = a.chunks_exact(3).zip(b.chunks_exact(3)).filter(|(x, y)| x != y).count();
    assert!(differ <= 20, "{differ} pixels differ");
}

#[test]
fn visualization_render_to_png_writes_the_image() {
    let dir = TempDir::new("visualization-png");
    let mut r = pinhole_renderer();
    r.add_geometry("box", &unit_box(BOX_COLOR), &unlit()).unwrap();
    r.render_to_png(dir.path("box.png")).unwrap();
    let png = io::read_image(dir.path("box.png"), "auto").unwrap();
    assert_eq!(png.num_channels().unwrap(), 3);
    assert_eq!(png.to_vec().unwrap(), r.render_to_image().unwrap().to_vec().unwrap());
    assert_eq!(r.render_to_png("/nonexistent/dir/box.png").unwrap_err().code, ErrorCode::Io);
}

#[test]
fn visualization_bad_arguments_are_errors() {
    let code = |e: o3d::Error| e.code;
    assert_eq!(code(OffscreenRenderer::new(0, 10, RenderBackend::Auto).unwrap_err()), ErrorCode::InvalidArgument);
    let mut r = OffscreenRenderer::new(W as i32, H as i32, RenderBackend::Auto).unwrap();
    let wrong_size = PinholeIntrinsic::new(W as i32 + 1, H as i32, 100.0, 100.0, 80.0, 60.0);
    assert_eq!(code(r.setup_camera(&wrong_size, &IDENTITY).unwrap_err()), ErrorCode::InvalidArgument);
    let mut scaled = IDENTITY;
    scaled[0][0] = 2.0;
    assert_eq!(code(r.setup_camera(&camera_k(), &scaled).unwrap_err()), ErrorCode::InvalidArgument);
    let lookat = r.setup_camera_lookat([0.0; 3], [0.0, 0.0, 1.0], [0.0, 0.0, 1.0], 0.7);
    assert_eq!(code(lookat.unwrap_err()), ErrorCode::InvalidArgument);
    let zoom = r.setup_camera_lookat([0.0; 3], [0.0, 0.0, 1.0], [0.0, 1.0, 0.0], 5.0);
    assert_eq!(code(zoom.unwrap_err()), ErrorCode::InvalidArgument);
    let fov = r.setup_camera_fov(0.0, [0.0, 0.0, 1.0], [0.0; 3], [0.0, 1.0, 0.0]);
    assert_eq!(code(fov.unwrap_err()), ErrorCode::InvalidArgument);
    let big_points = RenderOption { point_size: 100.0, ..Default::default() };
    assert_eq!(code(r.set_render_option(&big_points).unwrap_err()), ErrorCode::InvalidArgument);
}
