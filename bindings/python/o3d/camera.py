"""o3d.camera: placeholder (camera intrinsics/trajectories are not implemented yet)."""
