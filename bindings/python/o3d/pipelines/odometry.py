"""o3d.pipelines.odometry: placeholder (RGB-D odometry is not implemented yet)."""
