"""o3d.pipelines.color_map: colour-map optimization (Open3D's run_rigid_optimizer and run_non_rigid_optimizer with
RigidOptimizerOption and NonRigidOptimizerOption): refine the poses of the RGB-D images a mesh was built from, then
colour the mesh's vertices from them."""
from .._o3d import (  # noqa: F401
    NonRigidOptimizerOption,
    RigidOptimizerOption,
    run_non_rigid_optimizer,
    run_rigid_optimizer,
)

__all__ = ["NonRigidOptimizerOption", "RigidOptimizerOption", "run_non_rigid_optimizer", "run_rigid_optimizer"]
