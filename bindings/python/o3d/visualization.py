"""o3d.visualization: placeholder (no viewer yet)."""
