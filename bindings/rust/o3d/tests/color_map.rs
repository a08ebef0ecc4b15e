//! Colour-map optimization on tests/capi/test_color_map.c's scene, whose answer is known: a box room
//! with a smooth colour texture, ray-cast into five 8-bit RGB + float depth views of one corner, given
//! with each pose turned by 1.5 degrees and moved about 2 cm. Both optimizers move the poses toward the
//! truth and the colours toward the texture; and the errors.
use std::f64::consts::PI;

use o3d::color_map::{run_non_rigid_optimizer, run_rigid_optimizer, ColorMapNonRigidOptions, ColorMapRigidOptions};
use o3d::{CameraTrajectory, ErrorCode, Image, PinholeIntrinsic, PixelType, RgbdImage, RgbdOptions, TriangleMesh};

type Mat4 = [[f64; 4]; 4];
type Vec3 = [f64; 3];
const W: i32 = 160;
const H: i32 = 120;
const LO: Vec3 = [-1.2, -1.0, -1.0];
const HI: Vec3 = [1.2, 1.0, 1.6];

fn camera() -> PinholeIntrinsic {
    PinholeIntrinsic::new(W, H, 140.0, 140.0, 79.5, 59.5)
}

fn texture(p: Vec3) -> Vec3 {
    [
        0.5 + 0.2 * (5.0 * p[0] + 2.0 * p[2]).sin() * (4.0 * p[1]).cos() + 0.15 * (11.0 * p[2] + 3.0 * p[1]).sin(),
        0.5 + 0.2 * (4.5 * p[1] + 1.0).cos() * (5.5 * p[2] - p[0]).sin() + 0.15 * (10.0 * p[0] - 4.0 * p[1]).cos(),
        0.5 + 0.25 * (3.0 * (p[0] + p[1] + p[2])).sin() + 0.15 * (12.0 * p[1] - 5.0 * p[2] + 3.0 * p[0]).cos(),
    ]
}

fn mul(a: &Mat4, b: &Mat4) -> Mat4 {
    let mut t = [[0.0; 4]; 4];
    for r in 0..4 {
        for c in 0..4 {
            t[r][c] = (0..4).map(|k| a[r][k] * b[k][c]).sum();
        }
    }
    t
}

fn rigid_inverse(m: &Mat4) -> Mat4 {
    let mut out = [[0.0; 4]; 4];
    for r in 0..3 {
        for c in 0..3 {
            out[r][c] = m[c][r];
            out[r][3] -= m[c][r] * m[c][3];
        }
    }
    out[3][3] = 1.0;
    out
}

fn unit(v: Vec3) -> Vec3 {
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    [v[0] / n, v[1] / n, v[2] / n]
}

fn cross(a: Vec3, b: Vec3) -> Vec3 {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

/// Camera-to-world pose at `centre` looking at `target` (world y points down).
fn look_at(centre: Vec3, target: Vec3) -> Mat4 {
    let z = unit([target[0] - centre[0], target[1] - centre[1], target[2] - centre[2]]);
    let x = unit(cross([0.0, 1.0, 0.0], z));
    let y = cross(z, x);
    let mut m = [[0.0; 4]; 4];
    for r in 0..3 {
        m[r] = [x[r], y[r], z[r], centre[r]];
    }
    m[3][3] = 1.0;
    m
}

/// Rotation by `deg` about `axis` (Rodrigues), then translation `t`.
fn motion(axis: Vec3, deg: f64, t: Vec3) -> Mat4 {
    let k = unit(axis);
    let (s, c) = (deg * PI / 180.0).sin_cos();
    let mut m = [[0.0; 4]; 4];
    for r in 0..3 {
        for q in 0..3 {
            m[r][q] = (1.0 - c) * k[r] * k[q] + if r == q { c } else { 0.0 };
        }
        m[r][3] = t[r];
    }
    m[0][1] -= s * k[2];
    m[0][2] += s * k[1];
    m[1][0] += s * k[2];
    m[1][2] -= s * k[0];
    m[2][0] -= s * k[1];
    m[2][1] += s * k[0];
    m[3][3] = 1.0;
    m
}

/// The RGB-D view from camera-to-world `pose`: each ray meets the room's box where it leaves it.
fn render(pose: &Mat4) -> RgbdImage {
    let (cam, mut rgb, mut depth) = (camera(), Vec::new(), Vec::new());
    for v in 0..H {
        for u in 0..W {
            let dc = [(u as f64 - cam.cx) / cam.fx, (v as f64 - cam.cy) / cam.fy, 1.0];
            let d: Vec<f64> = (0..3).map(|r| pose[r][0] * dc[0] + pose[r][1] * dc[1] + pose[r][2] * dc[2]).collect();
            let t = (0..3)
                .filter(|&a| d[a] != 0.0)
                .map(|a| ((if d[a] > 0.0 { HI[a] } else { LO[a] }) - pose[a][3]) / d[a])
                .fold(f64::INFINITY, f64::min);
            let p = [pose[0][3] + t * d[0], pose[1][3] + t * d[1], pose[2][3] + t * d[2]];
            rgb.extend(texture(p).iter().map(|c| (255.0 * c).round() as u8));
            depth.push(t as f32); // the camera ray has z = 1: t is the depth
        }
    }
    let color = Image::from_bytes(W, H, 3, PixelType::U8, &rgb).unwrap();
    let depth = Image::from_f32(W, H, &depth).unwrap();
    let o = RgbdOptions { depth_scale: 1.0, depth_trunc: 10.0, convert_rgb_to_intensity: false };
    RgbdImage::from_color_and_depth(&color, &depth, &o).unwrap()
}

struct Scene {
    mesh: TriangleMesh,
    images: Vec<RgbdImage>,
    start: CameraTrajectory,
    truth: Vec<Mat4>, // world to camera
}

fn scene() -> Scene {
    const GRID: usize = 31;
    let mut xyz = Vec::new();
    for axis in 0..3 {
        for side in [LO, HI] {
            let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
            for j in 0..GRID {
                for i in 0..GRID {
                    let mut p = [0.0; 3];
                    p[axis] = side[axis];
                    p[a] = LO[a] + (HI[a] - LO[a]) * i as f64 / (GRID - 1) as f64;
                    p[b] = LO[b] + (HI[b] - LO[b]) * j as f64 / (GRID - 1) as f64;
                    xyz.push(p);
                }
            }
        }
    }
    let mut mesh = TriangleMesh::new().unwrap();
    mesh.set_vertices(&xyz).unwrap();
    let centres = [[0.0, 0.0, 0.0], [-0.6, -0.4, -0.5], [0.5, -0.5, 0.3], [-0.5, 0.5, 0.5], [0.4, 0.4, -0.6]];
    let targets = [[1.2, 1.0, 1.6], [1.0, 1.0, 1.6], [1.2, 0.8, 1.6], [1.2, 1.0, 1.4], [1.1, 0.9, 1.5]];
    let axes = [[1.0, 2.0, 0.0], [-1.0, 0.0, 2.0], [0.0, 1.0, 1.0], [2.0, -1.0, 1.0], [1.0, 1.0, -1.0]];
    let shifts =
        [[0.02, -0.01, 0.01], [-0.01, 0.02, 0.0], [0.0, -0.02, -0.015], [0.015, 0.01, 0.01], [-0.02, 0.0, 0.01]];
    let mut s = Scene { mesh, images: Vec::new(), start: CameraTrajectory::new().unwrap(), truth: Vec::new() };
    for c in 0..5 {
        let pose = look_at(centres[c], targets[c]);
        s.images.push(render(&pose));
        s.truth.push(rigid_inverse(&pose));
        s.start.push(&camera(), &mul(&motion(axes[c], 1.5, shifts[c]), &s.truth[c])).unwrap();
    }
    s
}

/// Mean rotation error (degrees) and camera-centre distance (metres) against the truth.
fn pose_error(t: &CameraTrajectory, s: &Scene) -> (f64, f64) {
    let (mut deg, mut metres) = (0.0, 0.0);
    for (c, truth) in s.truth.iter().enumerate() {
        let a = t.get(c).unwrap().extrinsic;
        let e = mul(&a, &rigid_inverse(truth));
        deg += ((e[0][0] + e[1][1] + e[2][2] - 1.0) / 2.0).clamp(-1.0, 1.0).acos() * 180.0 / PI / 5.0;
        let (ia, ib) = (rigid_inverse(&a), rigid_inverse(truth));
        metres += (0..3).map(|r| (ia[r][3] - ib[r][3]).powi(2)).sum::<f64>().sqrt() / 5.0;
    }
    (deg, metres)
}

/// Mean RGB distance from the texture over the vertices within 1 m of the corner the cameras see.
fn color_error(mesh: &TriangleMesh) -> f64 {
    let (xyz, rgb) = (mesh.vertices().unwrap(), mesh.vertex_colors().unwrap());
    assert_eq!(rgb.len(), xyz.len());
    let near: Vec<usize> =
        (0..xyz.len()).filter(|&i| (0..3).map(|k| (xyz[i][k] - HI[k]).abs()).sum::<f64>() <= 1.0 + 1e-9).collect();
    assert!(near.len() > 50);
    let dist = |i: usize| (0..3).map(|k| (rgb[i][k] - texture(xyz[i])[k]).powi(2)).sum::<f64>().sqrt();
    near.iter().map(|&i| dist(i)).sum::<f64>() / near.len() as f64
}

fn rigid_options(iterations: usize) -> ColorMapRigidOptions {
    ColorMapRigidOptions {
        maximum_iteration: iterations,
        maximum_allowable_depth: 4.0,
        depth_threshold_for_discontinuity_check: 1.0, // slanted walls at 160 x 120 are no discontinuity
        depth_threshold_for_visibility_check: 0.2,    // the poses start a few cm off
        image_boundary_margin: 4,
        ..Default::default()
    }
}

#[test]
fn both_optimizers_recover_the_poses() {
    let s = scene();
    let (mesh0, t0) = run_rigid_optimizer(&s.mesh, &s.images, &s.start, &rigid_options(0)).unwrap();
    let (mesh1, t1) = run_rigid_optimizer(&s.mesh, &s.images, &s.start, &rigid_options(150)).unwrap();
    let ((deg0, m0), (deg1, m1)) = (pose_error(&t0, &s), pose_error(&t1, &s));
    assert!((deg0 - 1.5).abs() < 1e-9, "{deg0}"); // no iterations: the poses as given
    assert!(deg1 < 0.5 * deg0 && m1 < 0.6 * m0, "{deg1} deg, {m1} m");
    let (c0, c1) = (color_error(&mesh0), color_error(&mesh1));
    assert!(c1 < 0.5 * c0, "{c0} -> {c1}");
    assert!(!s.mesh.has_vertex_colors().unwrap()); // the result is a copy

    let r = rigid_options(150);
    let o = ColorMapNonRigidOptions {
        number_of_vertical_anchors: 6,
        maximum_iteration: r.maximum_iteration,
        maximum_allowable_depth: r.maximum_allowable_depth,
        depth_threshold_for_discontinuity_check: r.depth_threshold_for_discontinuity_check,
        depth_threshold_for_visibility_check: r.depth_threshold_for_visibility_check,
        image_boundary_margin: r.image_boundary_margin,
        ..Default::default()
    };
    let (mesh, t) = run_non_rigid_optimizer(&s.mesh, &s.images, &s.start, &o).unwrap();
    let (deg, m) = pose_error(&t, &s);
    assert!(deg < 0.75 && m < 0.015, "{deg} deg, {m} m");
    assert!(color_error(&mesh) < 1.1 * c1);
}

#[test]
fn errors() {
    let s = scene();
    let e = run_rigid_optimizer(&s.mesh, &s.images[..2], &s.start, &rigid_options(1)).err().unwrap();
    assert_eq!(e.code, ErrorCode::InvalidArgument); // fewer images than poses
    let o = ColorMapNonRigidOptions { number_of_vertical_anchors: 1, ..Default::default() };
    let e = run_non_rigid_optimizer(&s.mesh, &s.images, &s.start, &o).err().unwrap();
    assert_eq!(e.code, ErrorCode::InvalidArgument);
}
