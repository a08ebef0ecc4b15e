"""o3d.pipelines.integration: placeholder (TSDF integration is not implemented yet)."""
