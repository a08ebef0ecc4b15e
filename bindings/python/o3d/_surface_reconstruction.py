"""Surface reconstruction from point clouds, as Open3D's static TriangleMesh methods:
create_from_point_cloud_poisson, create_from_point_cloud_ball_pivoting, create_from_point_cloud_alpha_shape.

Each runs with the GIL released and takes the o3d extras as keyword-only arguments: ``print_progress=True``
shows a progress bar (tqdm if installed, else stderr); ``callback(fraction)`` is called on the calling thread
and cancels the call by returning True (raises o3d.CancelledError) or by raising (its exception propagates);
Ctrl-C interrupts with KeyboardInterrupt; ``num_threads`` (0 = default) never changes the result.
"""
from . import _o3d
from ._progress import progress_context as _progress
from .utility import DoubleVector

# Keyword defaults from o3d_poisson_options_init and o3d_progress_options_init.
_POISSON, _PROGRESS = _o3d._poisson_defaults, _o3d._progress_defaults
# Open3D 0.20 keywords that the C options do not have: accepted at Open3D's default only.
_POISSON_FIXED = {"full_depth": 5, "samples_per_node": 1.5, "point_weight": 2.0}


def create_from_point_cloud_poisson(pcd, depth=_POISSON["depth"], width=_POISSON["width"], scale=_POISSON["scale"],
                                    linear_fit=_POISSON["linear_fit"], n_threads=-1,
                                    full_depth=_POISSON_FIXED["full_depth"],
                                    samples_per_node=_POISSON_FIXED["samples_per_node"],
                                    point_weight=_POISSON_FIXED["point_weight"], *, print_progress=False,
                                    callback=None):
    """Screened Poisson reconstruction (Kazhdan & Hoppe 2013) of an oriented cloud (it needs normals):
    ``(TriangleMesh, densities)``, a watertight mesh and per vertex the sampling density there as an octree
    depth (an o3d.utility.DoubleVector; trim low-density vertices with ``densities < quantile``).

    ``depth`` bounds the octree depth; ``width`` > 0 sets the finest cells' width instead; ``scale`` is the ratio
    of the reconstruction cube to the samples' bounding cube; ``linear_fit`` places iso-vertices by linear
    interpolation. ``n_threads`` -1 (or any negative value, or 0) uses the default thread count.
    ``full_depth``, ``samples_per_node`` and ``point_weight`` are accepted at Open3D's defaults only.
    """
    given = {"full_depth": full_depth, "samples_per_node": samples_per_node, "point_weight": point_weight}
    for name, value in given.items():
        if value != _POISSON_FIXED[name]:
            raise _o3d.UnsupportedError(f"create_from_point_cloud_poisson: {name} other than "
                                        f"{_POISSON_FIXED[name]} is not supported")
    num_threads = max(int(n_threads), 0)  # Open3D's -1: automatic, the C API's 0
    with _progress("Poisson", print_progress, callback) as progress:
        mesh, values = _o3d._create_from_point_cloud_poisson(pcd, depth, width, scale, linear_fit, num_threads,
                                                             progress)
    densities = DoubleVector()
    densities._data = values  # a fresh array: no second copy
    return mesh, densities


def create_from_point_cloud_ball_pivoting(pcd, radii, *, print_progress=False, callback=None,
                                          num_threads=_PROGRESS["num_threads"]):
    """Ball pivoting (Bernardini et al. 1999) over an oriented cloud (it needs normals): a ball of each of
    ``radii`` (DoubleVector, list or array; each > 0) in increasing order pivots about the front's edges. The
    mesh's vertices are the cloud's points (with their normals and colors), its triangles wound to agree with
    the normals."""
    with _progress("Ball pivoting", print_progress, callback) as progress:
        return _o3d._create_from_point_cloud_ball_pivoting(pcd, radii, num_threads, progress)


def create_from_point_cloud_alpha_shape(pcd, alpha, tetra_mesh=None, pt_map=None, *, print_progress=False,
                                        callback=None, num_threads=_PROGRESS["num_threads"]):
    """The alpha shape (Edelsbrunner & Muecke 1994): the boundary of the Delaunay tetrahedra whose circumradius
    is below ``alpha`` (> 0; a huge alpha gives the convex hull), wound outwards. ``tetra_mesh`` and ``pt_map``,
    from ``TetraMesh.create_from_point_cloud(pcd)``, reuse a tetrahedralization across alphas."""
    with _progress("Alpha shape", print_progress, callback) as progress:
        return _o3d._create_from_point_cloud_alpha_shape(pcd, alpha, tetra_mesh, pt_map, num_threads, progress)


_o3d.TriangleMesh.create_from_point_cloud_poisson = staticmethod(create_from_point_cloud_poisson)
_o3d.TriangleMesh.create_from_point_cloud_ball_pivoting = staticmethod(create_from_point_cloud_ball_pivoting)
_o3d.TriangleMesh.create_from_point_cloud_alpha_shape = staticmethod(create_from_point_cloud_alpha_shape)
