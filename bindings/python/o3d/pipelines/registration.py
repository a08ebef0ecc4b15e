"""o3d.pipelines.registration: ICP, evaluation, information matrix (Open3D names)."""
from .. import _o3d
from .._progress import ProgressBar
from .._o3d import (  # noqa: F401
    ICPConvergenceCriteria,
    RegistrationResult,
    TransformationEstimation,
    TransformationEstimationPointToPlane,
    TransformationEstimationPointToPoint,
    evaluate_registration,
    get_information_matrix_from_point_clouds,
)


def registration_icp(source, target, max_correspondence_distance, init=None, estimation_method=None,
                     criteria=None, *, print_progress=False, callback=None, num_threads=0):
    """Iterative closest point from ``source`` onto ``target``; returns a :class:`RegistrationResult`.

    ``init`` defaults to the identity, ``estimation_method`` to TransformationEstimationPointToPoint(),
    ``criteria`` to ICPConvergenceCriteria(). o3d extras: ``print_progress=True`` shows a progress bar
    (tqdm if installed, else stderr); ``callback(fraction)`` is called after each iteration and cancels
    the registration by returning True (raises o3d.CancelledError) or by raising (its exception
    propagates). Ctrl-C interrupts with KeyboardInterrupt.
    """
    bar = ProgressBar("ICP") if print_progress else None
    progress = None
    if bar is not None or callback is not None:
        if callback is not None and not callable(callback):
            raise TypeError("callback: expected a callable")

        def progress(fraction):
            if bar is not None:
                bar.update(fraction)
            return bool(callback(fraction)) if callback is not None else False

    try:
        return _o3d._registration_icp(source, target, max_correspondence_distance, init, estimation_method, criteria,
                                      progress, num_threads)
    finally:
        if bar is not None:
            bar.close()


__all__ = ["registration_icp", "evaluate_registration", "get_information_matrix_from_point_clouds",
           "ICPConvergenceCriteria", "RegistrationResult", "TransformationEstimation",
           "TransformationEstimationPointToPoint", "TransformationEstimationPointToPlane"]
