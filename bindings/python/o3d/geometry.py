"""o3d.geometry: PointCloud, TriangleMesh, TetraMesh, HalfEdgeTriangleMesh (HalfEdge), Image, RGBDImage, LineSet,
VoxelGrid, Octree, KDTreeFlann, KDTreeSearchParam*, AxisAlignedBoundingBox, OrientedBoundingBox,
OrientedBoundingEllipsoid, the enums SimplificationContraction, FilterScope, DeformAsRigidAsPossibleEnergy,
ImageFilterType, and the submodule keypoint (compute_iss_keypoints)."""
import sys
import types

import numpy as np

from . import _o3d
from . import _surface_reconstruction  # noqa: F401  (TriangleMesh.create_from_point_cloud_*)

from ._o3d import (  # noqa: F401
    ColorToIntensityConversionType,
    DeformAsRigidAsPossibleEnergy,
    FilterScope,
    HalfEdgeTriangleMesh,
    Image,
    ImageFilterType,
    RGBDImage,
    SimplificationContraction,
    TriangleMesh,
    KDTreeFlann,
    KDTreeSearchParam,
    KDTreeSearchParamHybrid,
    KDTreeSearchParamKNN,
    KDTreeSearchParamRadius,
    LineSet,
    Octree,
    PointCloud,
    TetraMesh,
    VoxelGrid,
)

# Open3D's o3d.geometry.keypoint submodule (importable as such).
keypoint = types.ModuleType(__name__ + ".keypoint", "Open3D's o3d.geometry.keypoint: compute_iss_keypoints.")
keypoint.compute_iss_keypoints = _o3d.compute_iss_keypoints
sys.modules[keypoint.__name__] = keypoint


class AxisAlignedBoundingBox:
    """Box with faces parallel to the axes, given by its min and max corners (as Open3D's)."""

    def __init__(self, min_bound=(0.0, 0.0, 0.0), max_bound=(0.0, 0.0, 0.0)):
        self.min_bound = np.array(min_bound, dtype=np.float64).reshape(3)
        self.max_bound = np.array(max_bound, dtype=np.float64).reshape(3)
        self.color = np.zeros(3)

    def get_min_bound(self):
        return self.min_bound.copy()

    def get_max_bound(self):
        return self.max_bound.copy()

    def get_center(self):
        return (self.min_bound + self.max_bound) / 2.0

    def get_extent(self):
        return self.max_bound - self.min_bound

    def get_half_extent(self):
        return self.get_extent() / 2.0

    def get_max_extent(self):
        return float(np.max(self.get_extent()))

    def volume(self):
        return float(np.prod(self.get_extent()))

    def is_empty(self):
        return self.volume() <= 0.0

    def get_box_points(self):
        """The 8 corners (Open3D's order: min, min+x, min+y, min+z, max, max-x, max-y, max-z)."""
        return _utility().Vector3dVector(_o3d._obb_get_box_points(self.get_oriented_bounding_box()))

    def get_point_indices_within_bounding_box(self, points):
        """Indices (ascending) of the (N, 3) points inside the box, boundary included."""
        return _o3d._obb_get_point_indices_within(self.get_oriented_bounding_box(), points)

    def get_axis_aligned_bounding_box(self):
        return AxisAlignedBoundingBox(self.min_bound, self.max_bound)

    def get_oriented_bounding_box(self, robust=False):
        """The same box as an OrientedBoundingBox (R = identity)."""
        return OrientedBoundingBox.create_from_axis_aligned_bounding_box(self)

    @staticmethod
    def create_from_points(points):
        pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        if len(pts) == 0:
            return AxisAlignedBoundingBox()
        return AxisAlignedBoundingBox(pts.min(axis=0), pts.max(axis=0))

    def __repr__(self):
        return f"AxisAlignedBoundingBox: min: {tuple(self.min_bound)}, max: {tuple(self.max_bound)}"


def _utility():
    from . import utility

    return utility


class _OrientedSolid:
    """The rigid motions and scaling shared by OrientedBoundingBox and OrientedBoundingEllipsoid: a centre, a
    rotation R and per-axis sizes (the attribute named by _SIZES: extent or radii)."""
    _SIZES = None

    def _assign(self, center, R, sizes, default_color):
        """Open3D's constructors: a copy of another solid of the same class, (center, R, sizes), or nothing."""
        if isinstance(center, type(self)):
            other = center
            center, R, sizes = other.center, other.R, getattr(other, self._SIZES)
            self.color = np.array(other.color, dtype=np.float64)
        else:
            self.color = default_color
        if center is None and R is None and sizes is None:
            center, R, sizes = np.zeros(3), np.eye(3), np.zeros(3)
        elif center is None or R is None or sizes is None:
            raise TypeError(f"{type(self).__name__}: give center, R and {self._SIZES} (or nothing)")
        self.center = np.array(center, dtype=np.float64).reshape(3)
        self.R = np.array(R, dtype=np.float64).reshape(3, 3)
        setattr(self, self._SIZES, np.array(sizes, dtype=np.float64).reshape(3))

    def translate(self, translation, relative=True):
        t = np.asarray(translation, dtype=np.float64).reshape(3)
        self.center = self.center + t if relative else t.copy()
        return self

    def rotate(self, R, center=None):
        R = np.asarray(R, dtype=np.float64).reshape(3, 3)
        c = self.center if center is None else np.asarray(center, dtype=np.float64).reshape(3)
        self.center = R @ (self.center - c) + c
        self.R = R @ self.R
        return self

    def scale(self, scale, center=None):
        c = self.center if center is None else np.asarray(center, dtype=np.float64).reshape(3)
        setattr(self, self._SIZES, getattr(self, self._SIZES) * scale)
        self.center = scale * (self.center - c) + c
        return self


class OrientedBoundingBox(_OrientedSolid):
    """Box of edge lengths ``extent`` along the columns of the rotation ``R``, centred at ``center`` (as
    Open3D's). A value: computed by the library, stored here as numpy arrays."""
    _SIZES = "extent"

    def __init__(self, center=None, R=None, extent=None):
        self._assign(center, R, extent, default_color=np.zeros(3))

    @staticmethod
    def create_from_points(points, robust=False):
        """Oriented box of (N, 3) points (PCA of their convex hull); robust=True handles degenerate sets."""
        return OrientedBoundingBox(*_o3d._obb_create_from_points(points, bool(robust)))

    @staticmethod
    def create_from_points_minimal(points, robust=False):
        """The minimum-volume oriented box of (N, 3) points (N >= 4); robust=True joggles flat sets into a box."""
        return OrientedBoundingBox(*_o3d._obb_create_from_points_minimal(points, bool(robust)))

    @staticmethod
    def create_from_axis_aligned_bounding_box(aabb_box):
        return OrientedBoundingBox(*_o3d._obb_create_from_axis_aligned_bounding_box(aabb_box.get_min_bound(),
                                                                                   aabb_box.get_max_bound()))

    def get_box_points(self):
        """The 8 corners, in Open3D's order."""
        return _utility().Vector3dVector(_o3d._obb_get_box_points(self))

    def get_point_indices_within_bounding_box(self, points):
        """Indices (ascending) of the (N, 3) points inside the box, boundary included."""
        return _o3d._obb_get_point_indices_within(self, points)

    def get_center(self):
        return self.center.copy()

    def get_extent(self):
        return self.extent.copy()

    def get_half_extent(self):
        return self.extent / 2.0

    def get_max_extent(self):
        return float(np.max(self.extent))

    def get_min_bound(self):
        return np.asarray(self.get_box_points()).min(axis=0)

    def get_max_bound(self):
        return np.asarray(self.get_box_points()).max(axis=0)

    def volume(self):
        return float(np.prod(self.extent))

    def is_empty(self):
        return self.volume() <= 0.0

    def get_axis_aligned_bounding_box(self):
        return AxisAlignedBoundingBox(self.get_min_bound(), self.get_max_bound())

    def get_oriented_bounding_box(self, robust=False):
        return OrientedBoundingBox(self)


    def __repr__(self):
        return f"OrientedBoundingBox: center: {tuple(self.center)}, extent: {tuple(self.extent)}"


class OrientedBoundingEllipsoid(_OrientedSolid):
    """The solid {center + R diag(radii) u : |u| <= 1}: semi-axes of lengths ``radii`` along the columns of the
    rotation ``R`` (as Open3D's). A value: computed by the library, stored here as numpy arrays."""
    _SIZES = "radii"

    def __init__(self, center=None, R=None, radii=None):
        self._assign(center, R, radii, default_color=np.ones(3))

    @staticmethod
    def create_from_points(points, robust=False):
        """The minimum-volume enclosing ellipsoid of (N, 3) points (N >= 4, not coplanar; Khachiyan's algorithm
        with Open3D's tolerance)."""
        return OrientedBoundingEllipsoid(*_o3d._obe_create_from_points(points, bool(robust)))

    def get_center(self):
        return self.center.copy()

    def volume(self):
        return float(4.0 / 3.0 * np.pi * np.prod(self.radii))

    def is_empty(self):
        return self.volume() <= 0.0

    def _half_widths(self):
        # the support of the ellipsoid along each axis: |R diag(radii)| row norms
        return np.sqrt(((self.R * self.radii) ** 2).sum(axis=1))

    def get_min_bound(self):
        return self.center - self._half_widths()

    def get_max_bound(self):
        return self.center + self._half_widths()

    def get_axis_aligned_bounding_box(self):
        return AxisAlignedBoundingBox(self.get_min_bound(), self.get_max_bound())

    def get_oriented_bounding_box(self, robust=False):
        """The box of edges 2 * radii along R's columns (the ellipsoid's tight oriented box)."""
        return OrientedBoundingBox(self.center, self.R, 2.0 * self.radii)


    def __repr__(self):
        return f"OrientedBoundingEllipsoid: center: {tuple(self.center)}, radii: {tuple(self.radii)}"


class HalfEdge:
    """One half-edge of a HalfEdgeTriangleMesh: next (the next half-edge of its triangle), twin (the opposite
    half-edge, -1 on a boundary), vertex_indices (from, to) and triangle_index (as Open3D's)."""

    def __init__(self, other=None):
        if other is None:
            self.next, self.twin, self.triangle_index = -1, -1, -1
            self.vertex_indices = np.array([-1, -1], dtype=np.int32)
        else:
            self.next, self.twin, self.triangle_index = other.next, other.twin, other.triangle_index
            self.vertex_indices = np.array(other.vertex_indices, dtype=np.int32).reshape(2)

    def is_boundary(self):
        return self.twin == -1

    def __repr__(self):
        a, b = (int(i) for i in self.vertex_indices)
        return (f"HalfEdge(vertex_indices {{{a}, {b}}}, triangle_index {self.triangle_index}, next {self.next}, "
                f"twin {self.twin})")


def _half_edges(self):
    """The half-edges (a new list of HalfEdge on each access, as Open3D's); half-edge 3t + k is side k of triangle
    t."""
    out = []
    for nxt, twin, a, b, t in self._half_edge_array().tolist():
        h = HalfEdge()
        h.next, h.twin, h.triangle_index = nxt, twin, t
        h.vertex_indices = np.array([a, b], dtype=np.int32)
        out.append(h)
    return out


def _half_edge_mesh_bound(self, which):
    v = self.vertices
    return getattr(v, which)(axis=0) if len(v) else np.zeros(3)


HalfEdgeTriangleMesh.half_edges = property(_half_edges)
HalfEdgeTriangleMesh.get_min_bound = lambda self: _half_edge_mesh_bound(self, "min")
HalfEdgeTriangleMesh.get_max_bound = lambda self: _half_edge_mesh_bound(self, "max")
HalfEdgeTriangleMesh.get_center = lambda self: _half_edge_mesh_bound(self, "mean")
HalfEdgeTriangleMesh.get_axis_aligned_bounding_box = lambda self: AxisAlignedBoundingBox(self.get_min_bound(),
                                                                                         self.get_max_bound())


class Voxel:
    """One occupied voxel of a VoxelGrid: grid_index (int32 (3,)) and color (float64 (3,))."""

    def __init__(self, grid_index=(0, 0, 0), color=(0.0, 0.0, 0.0)):
        if isinstance(grid_index, Voxel):  # the copy constructor
            grid_index, color = grid_index.grid_index, grid_index.color
        self.grid_index = np.array(grid_index, dtype=np.int32).reshape(3)
        self.color = np.array(color, dtype=np.float64).reshape(3)

    def __repr__(self):
        return f"Voxel with grid_index: {tuple(int(i) for i in self.grid_index)}, color: {tuple(self.color)}"


def _voxel_grid_get_voxels(self):
    """The occupied voxels, sorted by grid index (list of Voxel)."""
    index, colors = self._get_voxel_arrays()
    return [Voxel(i, c) for i, c in zip(index, colors)]


VoxelGrid.get_voxels = _voxel_grid_get_voxels


class _CreateFromOctree:
    """VoxelGrid.create_from_octree: Open3D's form fills a grid in place (``grid.create_from_octree(octree)``,
    returning None); called on the class (``VoxelGrid.create_from_octree(octree)``) it returns a new grid."""

    def __get__(self, grid, cls=None):
        if grid is None:
            def create_from_octree(octree):
                """A new VoxelGrid of the octree's leaves (as Octree.to_voxel_grid)."""
                return VoxelGrid._create_from_octree(octree)
        else:
            def create_from_octree(octree):
                """Replace this grid by the voxels of the octree's leaves: voxel_size = size / 2^max_depth, origin
                at the octree's origin, one voxel per leaf with its color."""
                grid._assign(VoxelGrid._create_from_octree(octree))
        return create_from_octree


VoxelGrid.create_from_octree = _CreateFromOctree()


class OctreeNodeInfo:
    """Where an octree node sits: origin (min corner), size (edge), depth (0: root), child_index (0..7)."""

    def __init__(self, origin=(0.0, 0.0, 0.0), size=0.0, depth=0, child_index=0):
        self.origin = np.array(origin, dtype=np.float64).reshape(3)
        self.size = float(size)
        self.depth = int(depth)
        self.child_index = int(child_index)

    def __repr__(self):
        return (f"OctreeNodeInfo with origin {tuple(self.origin)}, size {self.size}, depth {self.depth}, "
                f"child_index {self.child_index}")


class OctreeLeafNode:
    """Base of the octree leaves (as Open3D's)."""


class _PointColorLeafInit:
    """OctreePointColorLeafNode.get_init_function(): called, an empty OctreePointColorLeafNode."""

    def __call__(self):
        return OctreePointColorLeafNode()


class _PointColorLeafUpdate:
    """OctreePointColorLeafNode.get_update_function(idx, color): called on a leaf, adds point idx with color (as the
    octree's leaves do: indices ascending and unique, color the mean of the points')."""

    def __init__(self, idx, color):
        self.idx = int(idx)
        self.color = np.array(color, dtype=np.float64).reshape(3)

    def __call__(self, node):
        if self.idx not in node.indices:
            n = len(node.indices)
            node.color = (np.asarray(node.color, dtype=np.float64) * n + self.color) / (n + 1)
            node.indices = sorted(node.indices + [self.idx])


class OctreePointColorLeafNode(OctreeLeafNode):
    """A leaf: indices of its points (list of int, ascending) and their mean color."""

    def __init__(self, indices=None, color=(0.0, 0.0, 0.0)):
        if isinstance(indices, OctreePointColorLeafNode):  # the copy constructor
            indices, color = indices.indices, indices.color
        self.indices = list(indices) if indices is not None else []
        self.color = np.array(color, dtype=np.float64).reshape(3)

    def __repr__(self):
        return f"OctreePointColorLeafNode with color {tuple(self.color)} containing {len(self.indices)} points."

    @staticmethod
    def get_init_function():
        """The function making an empty OctreePointColorLeafNode (for Octree.insert_point)."""
        return _PointColorLeafInit()

    @staticmethod
    def get_update_function(idx, color):
        """The function adding point idx with color to a leaf (for Octree.insert_point)."""
        return _PointColorLeafUpdate(idx, color)


class _InternalNodeFunction:
    """What OctreeInternalNode / OctreeInternalPointNode's get_*_function return: accepted by Octree.insert_point,
    which keeps o3d's own internal nodes (no per-node point indices)."""

    def __init__(self, cls, idx=None):
        self.cls, self.idx = cls, idx

    def __call__(self, *node):
        return None if node else self.cls()


class OctreeInternalNode:
    """An internal octree node (Open3D's); o3d's octree keeps its own (only leaves carry data)."""

    @classmethod
    def get_init_function(cls):
        return _InternalNodeFunction(cls)

    @classmethod
    def get_update_function(cls, idx=None):
        return _InternalNodeFunction(cls, idx)


class OctreeInternalPointNode(OctreeInternalNode):
    """Open3D's internal node listing its subtree's point indices; o3d's octree does not keep them (accepted by
    insert_point for Open3D's calls, changing nothing)."""


def _octree_insert_point(self, point, f_init, f_update, fi_init=None, fi_update=None):
    """Insert a point (Open3D's form): ``insert_point(point, OctreePointColorLeafNode.get_init_function(),
    OctreePointColorLeafNode.get_update_function(index, color)[, OctreeInternal*Node.get_init_function(),
    OctreeInternal*Node.get_update_function(...)])`` adds point number index with color to the leaf at max depth
    holding point (its indices ascending and unique, its color their mean); a point outside the root changes
    nothing. Returns None, as Open3D. o3d keeps only point-colour leaves: other node functions raise
    UnsupportedError. o3d's own form ``insert_point(point, index, color)`` returns whether the point was inside."""
    if isinstance(f_update, _PointColorLeafUpdate):
        if not isinstance(f_init, _PointColorLeafInit):
            raise _o3d.UnsupportedError("insert_point: f_init must be OctreePointColorLeafNode.get_init_function()")
        for f in (fi_init, fi_update):
            if f is not None and not isinstance(f, _InternalNodeFunction):
                raise _o3d.UnsupportedError("insert_point: fi_init / fi_update must be None or "
                                            "OctreeInternalNode / OctreeInternalPointNode functions")
        self._insert_point(point, f_update.idx, f_update.color)
        return None
    if isinstance(f_init, (int, np.integer)) and not isinstance(f_init, bool) and fi_init is None and fi_update is None:
        return self._insert_point(point, f_init, f_update)
    raise _o3d.UnsupportedError("insert_point: o3d's octree keeps point-colour leaves only: pass "
                                "OctreePointColorLeafNode.get_init_function() and get_update_function(index, color), "
                                "or call insert_point(point, index, color)")


Octree.insert_point = _octree_insert_point
Octree.to_voxel_grid = lambda self: VoxelGrid._create_from_octree(self)
Octree.to_voxel_grid.__doc__ = ("The voxel grid of the leaves: voxel_size = size / 2^max_depth, origin at the octree's "
                                "origin, one voxel per leaf with the leaf's color.")


def _octree_locate_leaf_node(self, point):
    """(OctreePointColorLeafNode, OctreeNodeInfo) of the leaf holding point, or (None, None)."""
    found = self._locate_leaf_node(point)
    if found is None:
        return None, None
    indices, color, origin, size, depth, child_index = found
    return OctreePointColorLeafNode(indices, color), OctreeNodeInfo(origin, size, depth, child_index)


Octree.locate_leaf_node = _octree_locate_leaf_node


def _point_cloud_from_ply(data):
    """Unpickle a PointCloud (binary PLY keeps points, normals and colors bit-exact)."""
    from ._o3d import read_point_cloud_from_bytes

    return read_point_cloud_from_bytes(data, "ply") if data else PointCloud()


def _point_cloud_reduce(self):
    from ._o3d import write_point_cloud_to_bytes

    return _point_cloud_from_ply, (write_point_cloud_to_bytes(self, "ply") if len(self) else b"",)


PointCloud.__reduce__ = _point_cloud_reduce


_MESH_ARRAYS = ("vertices", "vertex_normals", "vertex_colors", "triangles", "triangle_normals", "triangle_uvs",
                "triangle_material_ids")


def _triangle_mesh_from_state(arrays, textures):
    """Unpickle a TriangleMesh: every array and texture, bit-exact."""
    mesh = TriangleMesh()
    for name, value in zip(_MESH_ARRAYS, arrays):
        setattr(mesh, name, value)
    mesh.textures = textures
    return mesh


def _triangle_mesh_reduce(self):
    return _triangle_mesh_from_state, (tuple(np.array(getattr(self, n)) for n in _MESH_ARRAYS), self.textures)


TriangleMesh.__reduce__ = _triangle_mesh_reduce


def _image_reduce(self):
    return (Image, (np.array(self),)) if not self.is_empty() else (Image, ())


Image.__reduce__ = _image_reduce

__all__ = ["PointCloud", "TriangleMesh", "TetraMesh", "Image", "RGBDImage", "SimplificationContraction", "FilterScope",
           "ImageFilterType", "ColorToIntensityConversionType", "KDTreeFlann", "KDTreeSearchParam",
           "KDTreeSearchParamKNN", "KDTreeSearchParamRadius", "KDTreeSearchParamHybrid", "AxisAlignedBoundingBox",
           "OrientedBoundingBox", "OrientedBoundingEllipsoid", "HalfEdgeTriangleMesh", "HalfEdge",
           "DeformAsRigidAsPossibleEnergy", "LineSet", "VoxelGrid", "Voxel", "Octree", "OctreeNodeInfo",
           "OctreeLeafNode",
           "OctreePointColorLeafNode", "OctreeInternalNode", "OctreeInternalPointNode", "keypoint"]
