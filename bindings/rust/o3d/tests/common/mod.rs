//! Shared test helpers: test data lookup, a deterministic generator, small geometry.
#![allow(dead_code)]
use std::path::PathBuf;

/// `$O3D_TEST_DATA/<rel>` (default `<repo>/../shared/data`). `None` (with a note) when missing,
/// unless `O3D_REQUIRE_TEST_DATA=1`, where a missing file fails the test.
pub fn data_file(rel: &str) -> Option<PathBuf> {
    let root = std::env::var_os("O3D_TEST_DATA")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../../../shared/data"));
    let path = root.join(rel);
    if path.is_file() {
        return Some(path);
    }
    if std::env::var("O3D_REQUIRE_TEST_DATA").as_deref() == Ok("1") {
        panic!("test data {} is missing and O3D_REQUIRE_TEST_DATA=1", path.display());
    }
    eprintln!("note: skipping, test data {} not found (set O3D_TEST_DATA)", path.display());
    None
}

/// A fresh, unique temporary directory, removed on drop.
pub struct TempDir(pub PathBuf);

impl TempDir {
    pub fn new(tag: &str) -> TempDir {
        use std::sync::atomic::{AtomicUsize, Ordering};
        static N: AtomicUsize = AtomicUsize::new(0);
        let dir = std::env::temp_dir().join(format!(
            "o3d-rust-{tag}-{}-{}",
            std::process::id(),
            N.fetch_add(1, Ordering::Relaxed)
        ));
        std::fs::create_dir_all(&dir).unwrap();
        TempDir(dir)
    }

    pub fn path(&self, name: &str) -> PathBuf {
        self.0.join(name)
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Deterministic xorshift generator (no external crates).
pub struct Rng(u64);

impl Rng {
    pub fn new(seed: u64) -> Rng {
        Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1)
    }

    /// Uniform in [0, 1).
    pub fn next_f64(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }

    pub fn points(&mut self, n: usize, lo: f64, hi: f64) -> Vec<[f64; 3]> {
        (0..n).map(|_| [self.range(lo, hi), self.range(lo, hi), self.range(lo, hi)]).collect()
    }
}

pub fn dist2(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum()
}

pub fn norm(a: [f64; 3]) -> f64 {
    dist2(a, [0.0; 3]).sqrt()
}

/// Row-major rotation about a unit `axis` by `angle` radians (Rodrigues).
pub fn rotation(axis: [f64; 3], angle: f64) -> [[f64; 3]; 3] {
    let n = norm(axis);
    let [x, y, z] = [axis[0] / n, axis[1] / n, axis[2] / n];
    let (s, c) = angle.sin_cos();
    let t = 1.0 - c;
    [
        [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
        [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
        [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
    ]
}

/// 4x4 from rotation and translation.
pub fn rigid(r: [[f64; 3]; 3], t: [f64; 3]) -> [[f64; 4]; 4] {
    let mut m = [[0.0; 4]; 4];
    for i in 0..3 {
        m[i][..3].copy_from_slice(&r[i]);
        m[i][3] = t[i];
    }
    m[3][3] = 1.0;
    m
}

pub fn apply(m: &[[f64; 4]; 4], p: [f64; 3]) -> [f64; 3] {
    let mut out = [0.0; 3];
    for i in 0..3 {
        out[i] = m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2] + m[i][3];
    }
    out
}

pub fn max_abs_diff(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> f64 {
    let mut d: f64 = 0.0;
    for i in 0..4 {
        for j in 0..4 {
            d = d.max((a[i][j] - b[i][j]).abs());
        }
    }
    d
}

pub fn mat_mul(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> [[f64; 4]; 4] {
    let mut m = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            m[i][j] = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    m
}

/// Inverse of a rigid 4x4 (transpose the rotation, move the translation back).
pub fn rigid_inverse(m: &[[f64; 4]; 4]) -> [[f64; 4]; 4] {
    let mut r = [[0.0; 3]; 3];
    for i in 0..3 {
        for j in 0..3 {
            r[i][j] = m[j][i];
        }
    }
    let t = [0, 1, 2].map(|i| -(0..3).map(|k| r[i][k] * m[k][3]).sum::<f64>());
    rigid(r, t)
}

/// Angle (degrees) of the rotation between the rotation parts of `a` and `b`.
pub fn rotation_error_deg(a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> f64 {
    let d = mat_mul(a, &rigid_inverse(b));
    let trace = d[0][0] + d[1][1] + d[2][2];
    ((trace - 1.0) / 2.0).clamp(-1.0, 1.0).acos().to_degrees()
}

/// Mean distance between `points` moved by `a` and by `b`.
pub fn mean_displacement(points: &[[f64; 3]], a: &[[f64; 4]; 4], b: &[[f64; 4]; 4]) -> f64 {
    points.iter().map(|p| dist2(apply(a, *p), apply(b, *p)).sqrt()).sum::<f64>() / points.len().max(1) as f64
}

/// `n` points on the sphere of `radius` about the origin (a Fibonacci lattice: even spacing,
/// deterministic) and their outward unit normals.
pub fn fibonacci_sphere(n: usize, radius: f64) -> (Vec<[f64; 3]>, Vec<[f64; 3]>) {
    let golden = std::f64::consts::PI * (3.0 - 5f64.sqrt());
    let normals: Vec<[f64; 3]> = (0..n)
        .map(|i| {
            let z = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let r = (1.0 - z * z).sqrt();
            let phi = golden * i as f64;
            [r * phi.cos(), r * phi.sin(), z]
        })
        .collect();
    (normals.iter().map(|u| u.map(|c| radius * c)).collect(), normals)
}

pub fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

pub fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
