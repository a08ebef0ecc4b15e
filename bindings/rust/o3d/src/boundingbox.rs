//! [`OrientedBoundingBox`] (o3d.geometry.OrientedBoundingBox) and [`OrientedBoundingEllipsoid`]
//! (o3d.geometry.OrientedBoundingEllipsoid), plain values; the boxes and ellipsoids of clouds and
//! meshes, meshes of them, cropping by a box, and a cloud's planar patches (one box each).
use o3d_sys as sys;

use crate::error::{check, Result};
use crate::pointcloud::{new_cloud, PlanarPatchOptions, PointCloud};
use crate::trianglemesh::{new_mesh, TriangleMesh};
use crate::util::copy_out;

/// A box with centre `center`, axes the columns of the rotation `r` and full edge lengths `extent`
/// (`o3d_obb_t`). Axis-aligned boxes are `(min_bound, max_bound)` pairs, as elsewhere in the crate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrientedBoundingBox {
    /// The box's centre.
    pub center: [f64; 3],
    /// Row-major rotation; column k (`r[0][k], r[1][k], r[2][k]`) is the direction of `extent[k]`.
    pub r: [[f64; 3]; 3],
    /// Full edge lengths along the axes (>= 0).
    pub extent: [f64; 3],
}

impl Default for OrientedBoundingBox {
    /// The empty box at the origin with identity axes (Open3D's `OrientedBoundingBox()`).
    fn default() -> Self {
        OrientedBoundingBox {
            center: [0.0; 3],
            r: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            extent: [0.0; 3],
        }
    }
}

impl OrientedBoundingBox {
    /// A box from its three parts.
    pub fn new(center: [f64; 3], r: [[f64; 3]; 3], extent: [f64; 3]) -> OrientedBoundingBox {
        OrientedBoundingBox { center, r, extent }
    }

    pub(crate) fn to_raw(self) -> sys::o3d_obb_t {
        let mut rot = [0.0; 9];
        for (i, row) in self.r.iter().enumerate() {
            rot[3 * i..3 * i + 3].copy_from_slice(row);
        }
        sys::o3d_obb_t { center: self.center, R: rot, extent: self.extent }
    }

    pub(crate) fn from_raw(raw: sys::o3d_obb_t) -> OrientedBoundingBox {
        let m = raw.R;
        OrientedBoundingBox {
            center: raw.center,
            r: [[m[0], m[1], m[2]], [m[3], m[4], m[5]], [m[6], m[7], m[8]]],
            extent: raw.extent,
        }
    }

    /// Run a C call filling an `o3d_obb_t`.
    pub(crate) fn filled_by(f: impl FnOnce(*mut sys::o3d_obb_t) -> sys::o3d_status) -> Result<OrientedBoundingBox> {
        let mut raw = sys::o3d_obb_t::default();
        check(f(&mut raw))?;
        Ok(OrientedBoundingBox::from_raw(raw))
    }

    /// The oriented box of `points` (at least 4, not all coplanar unless `robust`): PCA of their
    /// convex hull. `robust` joggles the hull input so degenerate sets still give a box.
    pub fn create_from_points(points: &[[f64; 3]], robust: bool) -> Result<OrientedBoundingBox> {
        // SAFETY: points.len() rows of 3 contiguous doubles; writable struct.
        Self::filled_by(|out| unsafe {
            sys::o3d_obb_create_from_points(out, points.as_ptr().cast(), points.len(), robust as i32)
        })
    }

    /// The minimum-volume oriented box of `points` (at least 4, not all coplanar unless `robust`,
    /// which joggles them); axes the right-handed order closest to the identity.
    pub fn create_from_points_minimal(points: &[[f64; 3]], robust: bool) -> Result<OrientedBoundingBox> {
        // SAFETY: points.len() rows of 3 contiguous doubles; writable struct.
        Self::filled_by(|out| unsafe {
            sys::o3d_obb_create_from_points_minimal(out, points.as_ptr().cast(), points.len(), i32::from(robust))
        })
    }

    /// The oriented box equal to the axis-aligned box `[min_bound, max_bound]` (identity axes).
    pub fn create_from_axis_aligned_bounding_box(
        min_bound: [f64; 3],
        max_bound: [f64; 3],
    ) -> Result<OrientedBoundingBox> {
        // SAFETY: 3 + 3 doubles; writable struct.
        Self::filled_by(|out| unsafe {
            sys::o3d_obb_create_from_axis_aligned_bounding_box(out, min_bound.as_ptr(), max_bound.as_ptr())
        })
    }

    /// The 8 corners, in Open3D's `get_box_points` order.
    pub fn get_box_points(&self) -> Result<[[f64; 3]; 8]> {
        let raw = self.to_raw();
        let mut out = [[0.0; 3]; 8];
        // SAFETY: valid struct; room for 24 contiguous doubles.
        check(unsafe { sys::o3d_obb_get_box_points(out.as_mut_ptr().cast(), &raw) })?;
        Ok(out)
    }

    /// Indices (ascending) of the `points` inside the box, boundary included.
    pub fn get_point_indices_within_bounding_box(&self, points: &[[f64; 3]]) -> Result<Vec<i32>> {
        let raw = self.to_raw();
        let mut out = vec![0i32; points.len()];
        let mut n = 0usize;
        // SAFETY: points.len() rows of 3 doubles; `out` has room for one index per point.
        check(unsafe {
            sys::o3d_obb_get_point_indices_within(
                out.as_mut_ptr(),
                out.len(),
                &mut n,
                &raw,
                points.as_ptr().cast(),
                points.len(),
            )
        })?;
        out.truncate(n.min(points.len()));
        Ok(out)
    }

    /// Volume: the product of the extents.
    pub fn volume(&self) -> f64 {
        self.extent.iter().product()
    }

    /// The centre (Open3D's `get_center`).
    pub fn get_center(&self) -> [f64; 3] {
        self.center
    }
}

/// The solid `{center + r diag(radii) u : |u| <= 1}` (`o3d_obe_t`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OrientedBoundingEllipsoid {
    /// The ellipsoid's centre.
    pub center: [f64; 3],
    /// Row-major rotation; column k (`r[0][k], r[1][k], r[2][k]`) is the direction of semi-axis k.
    pub r: [[f64; 3]; 3],
    /// The semi-axis lengths (>= 0).
    pub radii: [f64; 3],
}

impl Default for OrientedBoundingEllipsoid {
    /// The empty ellipsoid at the origin with identity axes (Open3D's `OrientedBoundingEllipsoid()`).
    fn default() -> Self {
        OrientedBoundingEllipsoid {
            center: [0.0; 3],
            r: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            radii: [0.0; 3],
        }
    }
}

impl OrientedBoundingEllipsoid {
    /// An ellipsoid from its three parts.
    pub fn new(center: [f64; 3], r: [[f64; 3]; 3], radii: [f64; 3]) -> OrientedBoundingEllipsoid {
        OrientedBoundingEllipsoid { center, r, radii }
    }

    pub(crate) fn to_raw(self) -> sys::o3d_obe_t {
        let mut rot = [0.0; 9];
        for (i, row) in self.r.iter().enumerate() {
            rot[3 * i..3 * i + 3].copy_from_slice(row);
        }
        sys::o3d_obe_t { center: self.center, R: rot, radii: self.radii }
    }

    pub(crate) fn from_raw(raw: sys::o3d_obe_t) -> OrientedBoundingEllipsoid {
        let m = raw.R;
        OrientedBoundingEllipsoid {
            center: raw.center,
            r: [[m[0], m[1], m[2]], [m[3], m[4], m[5]], [m[6], m[7], m[8]]],
            radii: raw.radii,
        }
    }

    /// Run a C call filling an `o3d_obe_t`.
    pub(crate) fn filled_by(
        f: impl FnOnce(*mut sys::o3d_obe_t) -> sys::o3d_status,
    ) -> Result<OrientedBoundingEllipsoid> {
        let mut raw = sys::o3d_obe_t::default();
        check(f(&mut raw))?;
        Ok(OrientedBoundingEllipsoid::from_raw(raw))
    }

    /// The minimum-volume enclosing ellipsoid of `points` (at least 4, not all coplanar): Khachiyan's
    /// algorithm with Open3D's tolerance, so a point may lie up to about 0.2% outside. `robust`
    /// joggles the hull's input.
    pub fn create_from_points(points: &[[f64; 3]], robust: bool) -> Result<OrientedBoundingEllipsoid> {
        // SAFETY: points.len() rows of 3 contiguous doubles; writable struct.
        Self::filled_by(|out| unsafe {
            sys::o3d_obe_create_from_points(out, points.as_ptr().cast(), points.len(), i32::from(robust))
        })
    }

    /// Volume: 4/3 pi times the product of the radii.
    pub fn volume(&self) -> f64 {
        4.0 / 3.0 * std::f64::consts::PI * self.radii.iter().product::<f64>()
    }

    /// The centre (Open3D's `get_center`).
    pub fn get_center(&self) -> [f64; 3] {
        self.center
    }
}

impl PointCloud {
    /// The minimum-volume oriented box of the points (see
    /// [`OrientedBoundingBox::create_from_points_minimal`]).
    pub fn get_minimal_oriented_bounding_box(&self, robust: bool) -> Result<OrientedBoundingBox> {
        // SAFETY: valid handle; writable struct.
        OrientedBoundingBox::filled_by(|out| unsafe {
            sys::o3d_pointcloud_get_minimal_oriented_bounding_box(out, self.as_raw(), i32::from(robust))
        })
    }

    /// The minimum-volume enclosing ellipsoid of the points (see
    /// [`OrientedBoundingEllipsoid::create_from_points`]).
    pub fn get_oriented_bounding_ellipsoid(&self, robust: bool) -> Result<OrientedBoundingEllipsoid> {
        // SAFETY: valid handle; writable struct.
        OrientedBoundingEllipsoid::filled_by(|out| unsafe {
            sys::o3d_pointcloud_get_oriented_bounding_ellipsoid(out, self.as_raw(), i32::from(robust))
        })
    }

    /// Planar patches (Araujo & Oliveira 2020, Open3D's `detect_planar_patches`): one oriented box
    /// per patch (column 2 of `r` its normal), largest first. The cloud needs normals.
    pub fn detect_planar_patches(&self, options: &PlanarPatchOptions) -> Result<Vec<OrientedBoundingBox>> {
        let raw = options.to_raw()?;
        // SAFETY: `out` has room for `cap` boxes (o3d_obb_t is the documented 15 doubles) or is NULL.
        let boxes = copy_out::<sys::o3d_obb_t>(|out, cap, n| unsafe {
            sys::o3d_pointcloud_detect_planar_patches(out.cast(), cap, n, self.as_raw(), &raw)
        })?;
        Ok(boxes.into_iter().map(OrientedBoundingBox::from_raw).collect())
    }

    /// The oriented bounding box of the points (see [`OrientedBoundingBox::create_from_points`]).
    pub fn get_oriented_bounding_box(&self, robust: bool) -> Result<OrientedBoundingBox> {
        // SAFETY: valid handle; writable struct.
        OrientedBoundingBox::filled_by(|out| unsafe {
            sys::o3d_pointcloud_get_oriented_bounding_box(out, self.as_raw(), robust as i32)
        })
    }

    /// New cloud with the points inside `obb` (boundary included), or outside it when `invert`.
    pub fn crop_obb(&self, obb: &OrientedBoundingBox, invert: bool) -> Result<PointCloud> {
        let raw = obb.to_raw();
        // SAFETY: valid handle and struct.
        new_cloud(|out| unsafe { sys::o3d_pointcloud_crop_obb(out, self.as_raw(), &raw, invert as i32) })
    }
}

impl TriangleMesh {
    /// The minimum-volume oriented box of the vertices (see
    /// [`OrientedBoundingBox::create_from_points_minimal`]).
    pub fn get_minimal_oriented_bounding_box(&self, robust: bool) -> Result<OrientedBoundingBox> {
        // SAFETY: valid handle; writable struct.
        OrientedBoundingBox::filled_by(|out| unsafe {
            sys::o3d_trianglemesh_get_minimal_oriented_bounding_box(out, self.as_raw(), i32::from(robust))
        })
    }

    /// The minimum-volume enclosing ellipsoid of the vertices (see
    /// [`OrientedBoundingEllipsoid::create_from_points`]).
    pub fn get_oriented_bounding_ellipsoid(&self, robust: bool) -> Result<OrientedBoundingEllipsoid> {
        // SAFETY: valid handle; writable struct.
        OrientedBoundingEllipsoid::filled_by(|out| unsafe {
            sys::o3d_trianglemesh_get_oriented_bounding_ellipsoid(out, self.as_raw(), i32::from(robust))
        })
    }

    /// The box as a closed mesh of 8 vertices (its `get_box_points` order) and 12 outward triangles,
    /// its extents multiplied by `scale` about the centre (Open3D's default `[1.0; 3]`).
    pub fn create_from_oriented_bounding_box(
        obox: &OrientedBoundingBox,
        scale: [f64; 3],
        create_uv_map: bool,
    ) -> Result<TriangleMesh> {
        let raw = obox.to_raw();
        // SAFETY: valid struct and 3 doubles.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_create_from_oriented_bounding_box(out, &raw, scale.as_ptr(), i32::from(create_uv_map))
        })
    }

    /// The ellipsoid as a mesh: [`TriangleMesh::create_ellipsoid`] of its radii times `scale`
    /// (`resolution` rings, Open3D's default 20), rotated and moved to it, painted white.
    pub fn create_from_oriented_bounding_ellipsoid(
        obel: &OrientedBoundingEllipsoid,
        scale: [f64; 3],
        resolution: usize,
        create_uv_map: bool,
    ) -> Result<TriangleMesh> {
        let raw = obel.to_raw();
        let resolution = crate::util::to_i32(resolution, "resolution")?;
        // SAFETY: valid struct and 3 doubles.
        new_mesh(|out| unsafe {
            sys::o3d_trianglemesh_create_from_oriented_bounding_ellipsoid(
                out,
                &raw,
                scale.as_ptr(),
                resolution,
                i32::from(create_uv_map),
            )
        })
    }

    /// The oriented bounding box of the vertices.
    pub fn get_oriented_bounding_box(&self, robust: bool) -> Result<OrientedBoundingBox> {
        // SAFETY: valid handle; writable struct.
        OrientedBoundingBox::filled_by(|out| unsafe {
            sys::o3d_trianglemesh_get_oriented_bounding_box(out, self.as_raw(), robust as i32)
        })
    }

    /// New mesh with the triangles whose three vertices lie inside `obb` (unused vertices dropped).
    pub fn crop_obb(&self, obb: &OrientedBoundingBox) -> Result<TriangleMesh> {
        let raw = obb.to_raw();
        // SAFETY: valid handle and struct.
        new_mesh(|out| unsafe { sys::o3d_trianglemesh_crop_obb(out, self.as_raw(), &raw) })
    }
}
