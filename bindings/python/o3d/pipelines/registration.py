"""o3d.pipelines.registration: features, global registration (RANSAC, FGR), ICP variants with robust kernels,
pose graphs and their global optimization, under Open3D's names.

Long calls (ICP, RANSAC, FGR, global_optimization) take the o3d extras as keyword-only arguments:
``print_progress=True`` shows a progress bar (tqdm if installed, else stderr); ``callback(fraction)`` is
called on the calling thread and cancels the call by returning True (raises o3d.CancelledError) or by
raising (its exception propagates); ``num_threads`` (0 = default) never changes the result. RANSAC and FGR
also take ``seed``: None draws from the global generator (``o3d.utility.random.seed``), an int gives the
same result on any thread count.
"""

from .. import _o3d
from .._progress import progress_context as _progress
from .._o3d import (  # noqa: F401
    CauchyLoss,
    CorrespondenceChecker,
    CorrespondenceCheckerBasedOnDistance,
    CorrespondenceCheckerBasedOnEdgeLength,
    CorrespondenceCheckerBasedOnNormal,
    FastGlobalRegistrationOption,
    Feature,
    GlobalOptimizationConvergenceCriteria,
    GlobalOptimizationGaussNewton,
    GlobalOptimizationLevenbergMarquardt,
    GlobalOptimizationMethod,
    GlobalOptimizationOption,
    GlobalOptimizationSummary,
    GMLoss,
    HuberLoss,
    ICPConvergenceCriteria,
    L1Loss,
    L2Loss,
    PoseGraph,
    RANSACConvergenceCriteria,
    RegistrationResult,
    RobustKernel,
    TransformationEstimation,
    TransformationEstimationForColoredICP,
    TransformationEstimationForGeneralizedICP,
    TransformationEstimationPointToPlane,
    TransformationEstimationPointToPoint,
    TransformationEstimationSymmetric,
    TukeyLoss,
    compute_fpfh_feature,
    evaluate_registration,
    get_information_matrix_from_point_clouds,
)
from ._pose_graph import PoseGraphEdge, PoseGraphEdgeVector, PoseGraphNode, PoseGraphNodeVector  # noqa: F401


# Keyword defaults from the C *_init functions (o3d_icp_options_init, o3d_ransac_options_init, ...).
_ICP, _RANSAC, _FGR = _o3d._icp_defaults, _o3d._ransac_defaults, _o3d._fgr_defaults
_GLOBAL_OPTIMIZATION = _o3d._global_optimization_defaults


def _require(estimation_method, cls, function):
    if estimation_method is None:
        return cls()
    if not isinstance(estimation_method, cls):
        raise _o3d.InvalidArgumentError(f"{function}: estimation_method must be a {cls.__name__}, "
                                        f"got {type(estimation_method).__name__}")
    return estimation_method


def registration_icp(source, target, max_correspondence_distance, init=None, estimation_method=None,
                     criteria=None, *, print_progress=False, callback=None, num_threads=_ICP["num_threads"]):
    """Iterative closest point from ``source`` onto ``target``; returns a :class:`RegistrationResult`.

    ``init`` defaults to the identity, ``estimation_method`` to TransformationEstimationPointToPoint() (any
    estimation works: PointToPlane, ForColoredICP, ForGeneralizedICP, Symmetric), ``criteria`` to
    ICPConvergenceCriteria(). o3d extras (keyword-only): print_progress, callback(fraction) called after each
    iteration, num_threads; Ctrl-C interrupts with KeyboardInterrupt.
    """
    with _progress("ICP", print_progress, callback) as progress:
        return _o3d._registration_icp(source, target, max_correspondence_distance, init, estimation_method, criteria,
                                      progress, num_threads)


def registration_colored_icp(source, target, max_correspondence_distance, init=None, estimation_method=None,
                             criteria=None, *, print_progress=False, callback=None, num_threads=_ICP["num_threads"]):
    """Colored ICP (Park et al. 2017): both clouds need colors, the target normals. ``estimation_method``
    defaults to TransformationEstimationForColoredICP(lambda_geometric=0.968)."""
    estimation_method = _require(estimation_method, TransformationEstimationForColoredICP, "registration_colored_icp")
    return registration_icp(source, target, max_correspondence_distance, init, estimation_method, criteria,
                            print_progress=print_progress, callback=callback, num_threads=num_threads)


def registration_generalized_icp(source, target, max_correspondence_distance, init=None, estimation_method=None,
                                 criteria=None, *, print_progress=False, callback=None,
                                 num_threads=_ICP["num_threads"]):
    """Generalized ICP (Segal et al. 2009). ``estimation_method`` defaults to
    TransformationEstimationForGeneralizedICP(epsilon=0.001)."""
    estimation_method = _require(estimation_method, TransformationEstimationForGeneralizedICP,
                                 "registration_generalized_icp")
    return registration_icp(source, target, max_correspondence_distance, init, estimation_method, criteria,
                            print_progress=print_progress, callback=callback, num_threads=num_threads)


def registration_symmetric_icp(source, target, max_correspondence_distance, init=None, estimation_method=None,
                               criteria=None, *, print_progress=False, callback=None, num_threads=_ICP["num_threads"]):
    """Symmetric point-to-plane ICP (Rusinkiewicz 2019); both clouds need normals. ``estimation_method``
    defaults to TransformationEstimationSymmetric()."""
    estimation_method = _require(estimation_method, TransformationEstimationSymmetric, "registration_symmetric_icp")
    return registration_icp(source, target, max_correspondence_distance, init, estimation_method, criteria,
                            print_progress=print_progress, callback=callback, num_threads=num_threads)


def correspondences_from_features(source_features, target_features, mutual_filter=False,
                                  mutual_consistency_ratio=0.1, *, num_threads=0):
    """For each source descriptor its nearest target descriptor, as (source, target) pairs in an
    o3d.utility.Vector2iVector. With ``mutual_filter`` only mutually nearest pairs are kept, unless fewer than
    ``mutual_consistency_ratio`` of the source points survive (then all pairs are returned, as Open3D)."""
    from ..utility import Vector2iVector

    pairs = _o3d._correspondences_from_features(source_features, target_features, mutual_filter,
                                                mutual_consistency_ratio, num_threads)
    out = Vector2iVector()
    out._data = pairs
    return out


def registration_ransac_based_on_feature_matching(source, target, source_feature, target_feature, mutual_filter,
                                                  max_correspondence_distance, estimation_method=None,
                                                  ransac_n=_RANSAC["ransac_n"], checkers=(), criteria=None, *,
                                                  seed=None, num_threads=_RANSAC["num_threads"], callback=None,
                                                  print_progress=False):
    """RANSAC over nearest-feature correspondences. ``estimation_method`` defaults to
    TransformationEstimationPointToPoint(False) (PointToPlane also works), ``criteria`` to
    RANSACConvergenceCriteria(100000, 0.999); every hypothesis must pass every checker. o3d extras: seed,
    num_threads, callback, print_progress (see the module docstring)."""
    with _progress("RANSAC", print_progress, callback) as progress:
        return _o3d._registration_ransac_based_on_feature_matching(
            source, target, source_feature, target_feature, mutual_filter, max_correspondence_distance,
            estimation_method, ransac_n, checkers, criteria, seed, num_threads, progress)


def registration_ransac_based_on_correspondence(source, target, corres, max_correspondence_distance,
                                                estimation_method=None, ransac_n=_RANSAC["ransac_n"], checkers=(),
                                                criteria=None, *, seed=None, num_threads=_RANSAC["num_threads"],
                                                callback=None, print_progress=False):
    """RANSAC over given (source, target) index pairs (Vector2iVector, (N, 2) ndarray or list of pairs)."""
    with _progress("RANSAC", print_progress, callback) as progress:
        return _o3d._registration_ransac_based_on_correspondence(
            source, target, corres, max_correspondence_distance, estimation_method, ransac_n, checkers, criteria,
            seed, num_threads, progress)


def registration_fgr_based_on_feature_matching(source, target, source_feature, target_feature, option=None, *,
                                               seed=None, num_threads=_FGR["num_threads"], callback=None,
                                               print_progress=False):
    """Fast Global Registration (Zhou et al. 2016) on mutual feature matches. ``option`` defaults to
    Open3D's C++ defaults (note: FastGlobalRegistrationOption() itself has decrease_mu=False, as Open3D's).
    ``seed`` (o3d extra) overrides option.seed."""
    with _progress("FGR", print_progress, callback) as progress:
        return _o3d._registration_fgr_based_on_feature_matching(source, target, source_feature, target_feature,
                                                                option, seed, num_threads, progress)


def registration_fgr_based_on_correspondence(source, target, corres, option=None, *, seed=None,
                                             num_threads=_FGR["num_threads"], callback=None, print_progress=False):
    """Fast Global Registration on given (source, target) index pairs."""
    with _progress("FGR", print_progress, callback) as progress:
        return _o3d._registration_fgr_based_on_correspondence(source, target, corres, option, seed, num_threads,
                                                              progress)


def global_optimization(pose_graph, method=None, criteria=None, option=None, *, callback=None, print_progress=False,
                        num_threads=_GLOBAL_OPTIMIZATION["num_threads"]):
    """Optimize the node poses of ``pose_graph`` in place (line process, prune uncertain edges whose confidence
    ends below option.edge_prune_threshold, optimize again); edge confidences are updated. ``method`` defaults
    to GlobalOptimizationLevenbergMarquardt(), ``criteria`` and ``option`` to their defaults. Returns a
    GlobalOptimizationSummary (o3d extra; Open3D returns None). A cancelled or failed call leaves the graph
    unchanged."""
    with _progress("Global optimization", print_progress, callback) as progress:
        return _o3d._global_optimization(pose_graph, method, criteria, option, progress, num_threads)


__all__ = [
    "Feature", "compute_fpfh_feature", "correspondences_from_features",
    "CorrespondenceChecker", "CorrespondenceCheckerBasedOnEdgeLength", "CorrespondenceCheckerBasedOnDistance",
    "CorrespondenceCheckerBasedOnNormal", "RANSACConvergenceCriteria", "registration_ransac_based_on_feature_matching",
    "registration_ransac_based_on_correspondence", "FastGlobalRegistrationOption",
    "registration_fgr_based_on_feature_matching", "registration_fgr_based_on_correspondence",
    "RobustKernel", "L2Loss", "L1Loss", "HuberLoss", "CauchyLoss", "GMLoss", "TukeyLoss",
    "registration_icp", "registration_colored_icp", "registration_generalized_icp", "registration_symmetric_icp",
    "evaluate_registration", "get_information_matrix_from_point_clouds", "ICPConvergenceCriteria",
    "RegistrationResult", "TransformationEstimation", "TransformationEstimationPointToPoint",
    "TransformationEstimationPointToPlane", "TransformationEstimationForColoredICP",
    "TransformationEstimationForGeneralizedICP", "TransformationEstimationSymmetric",
    "PoseGraph", "PoseGraphNode", "PoseGraphEdge", "PoseGraphNodeVector", "PoseGraphEdgeVector",
    "global_optimization", "GlobalOptimizationMethod", "GlobalOptimizationGaussNewton",
    "GlobalOptimizationLevenbergMarquardt", "GlobalOptimizationConvergenceCriteria", "GlobalOptimizationOption",
    "GlobalOptimizationSummary",
]
