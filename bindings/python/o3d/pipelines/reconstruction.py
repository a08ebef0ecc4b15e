"""o3d.pipelines.reconstruction: the scene reconstruction system (Choi, Zhou, Koltun 2015, as Open3D's tutorial
``reconstruction_system`` runs it). A folder of colour/depth frames and a config in Open3D's JSON layout in,
``scene/integrated.ply`` and ``scene/trajectory.log`` out.

The stages are Open3D's: make fragments, register fragments, refine registration, integrate scene, plus an
optional colour map. Each reads the previous stages' files, resumes from its own (``resume=False`` redoes the
work), shows a progress bar (``print_progress``) and can be cancelled (``callback(fraction)`` returning True, or
Ctrl-C); errors raise and name the stage and the frame or fragment.

``config`` is a path to the JSON file or a dict with the same keys. From the command line, with Open3D's
``run_system.py`` flags::

    python -m o3d.pipelines.reconstruction --config config.json --make --register --refine --integrate

(also installed as ``o3d-reconstruction``; the C library ships the same program for C users).
"""
import argparse
import contextlib
import json
import os
import sys
import tempfile
import time

from .. import _o3d
from .._o3d import ReconstructionStage
from .._progress import progress_context

__all__ = ["ReconstructionStage", "run_stage", "make_fragments", "register_fragments", "refine_registration",
           "integrate_scene", "color_map", "run_system", "main"]

# (run_system keyword / command-line flag, stage, progress label), in the order the stages run.
_STAGES = (
    ("make", ReconstructionStage.MakeFragments, "make fragments"),
    ("register", ReconstructionStage.RegisterFragments, "register fragments"),
    ("refine", ReconstructionStage.RefineRegistration, "refine registration"),
    ("integrate", ReconstructionStage.IntegrateScene, "integrate scene"),
    ("color_map", ReconstructionStage.ColorMap, "color map"),
)


@contextlib.contextmanager
def _config_path(config):
    """A config file path for the C call: the path itself, or a dict written to a temporary file."""
    if isinstance(config, dict):
        handle, path = tempfile.mkstemp(suffix=".json", prefix="o3d_reconstruction_")
        try:
            with os.fdopen(handle, "w") as f:
                json.dump(config, f)
            yield path
        finally:
            os.unlink(path)
    elif isinstance(config, (str, os.PathLike)):
        yield os.fspath(config)
    else:
        raise TypeError(f"config: expected a path or a dict, got {type(config).__name__}")


def run_stage(config, stage, *, resume=True, num_threads=0, print_progress=True, callback=None):
    """Run one :class:`ReconstructionStage` on the dataset ``config`` names (the GIL is released meanwhile)."""
    label = next(name for _, s, name in _STAGES if s == stage)
    with _config_path(config) as path, progress_context(label, print_progress, callback) as progress:
        _o3d._reconstruction_run_stage(path, stage, resume, num_threads, progress)


def make_fragments(config, **kwargs):
    """Stage 1: odometry, loop closures and a pose graph per fragment, and each fragment's TSDF point cloud."""
    run_stage(config, ReconstructionStage.MakeFragments, **kwargs)


def register_fragments(config, **kwargs):
    """Stage 2: FPFH + RANSAC (or FGR) between fragment pairs and the global pose graph with the line process."""
    run_stage(config, ReconstructionStage.RegisterFragments, **kwargs)


def refine_registration(config, **kwargs):
    """Stage 3: multi-scale ICP (coloured by default) on every kept fragment pair, and the graph again."""
    run_stage(config, ReconstructionStage.RefineRegistration, **kwargs)


def integrate_scene(config, **kwargs):
    """Stage 4: every frame into one TSDF with its final pose; scene/integrated.ply and scene/trajectory.log."""
    run_stage(config, ReconstructionStage.IntegrateScene, **kwargs)


def color_map(config, **kwargs):
    """Stage 5 (optional): colour-map optimization of the scene mesh over the keyframes."""
    run_stage(config, ReconstructionStage.ColorMap, **kwargs)


def run_system(config, make=False, register=False, refine=False, integrate=False, color_map=False, **kwargs):
    """Run the stages asked for, in order (make, register, refine and integrate when none is); returns
    {stage label: seconds}. Keyword arguments go to :func:`run_stage`."""
    wanted = {"make": make, "register": register, "refine": refine, "integrate": integrate, "color_map": color_map}
    if not any(wanted.values()):
        wanted.update(make=True, register=True, refine=True, integrate=True)
    seconds = {}
    for key, stage, label in _STAGES:
        if wanted[key]:
            start = time.perf_counter()
            run_stage(config, stage, **kwargs)
            seconds[label] = time.perf_counter() - start
    return seconds


def main(argv=None):
    """The command line (Open3D's run_system.py flags, plus --color_map, --no-resume and --threads)."""
    parser = argparse.ArgumentParser(prog="o3d-reconstruction", description=__doc__.split("\n\n")[0])
    parser.add_argument("--config", required=True, help="the JSON config (Open3D's reconstruction-system layout)")
    for key, _, label in _STAGES:
        parser.add_argument(f"--{key}", action="store_true", help=f"run the {label} stage")
    parser.add_argument("--no-resume", action="store_true", help="redo work whose outputs exist")
    parser.add_argument("--threads", type=int, default=0, help="threads (0 = all cores)")
    args = parser.parse_args(argv)
    try:
        seconds = run_system(args.config, args.make, args.register, args.refine, args.integrate, args.color_map,
                             resume=not args.no_resume, num_threads=args.threads)
    except (KeyboardInterrupt, _o3d.CancelledError):
        print("cancelled; finished outputs are kept, run again to resume", file=sys.stderr)
        return 130
    except _o3d.O3DError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    for label, s in seconds.items():
        print(f"{label}: {s:.2f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
