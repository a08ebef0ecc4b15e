#!/usr/bin/env bash
# The README's pictures, rendered by o3d itself (offscreen, no display): runs the demo and keeps the PNGs it
# writes in docs/images/, a frame of Figure 2 (examples/python/figure2.py) and the reconstruction system's scene
# (examples/python/reconstruction_system.py).
# Usage: tools/make_readme_pictures.sh [python with o3d installed, default .venv/bin/python]
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${1:-.venv/bin/python}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$PY" examples/demo/demo.py "$out" >/dev/null
mkdir -p docs/images
cp "$out"/*.png docs/images/
# Figure 2 (a cloud and a mesh in the viewer, a hidden window): needs Open3D's test data.
data=${O3D_TEST_DATA:-../shared/data}
if [ -f "$data/open3d/Feature/cloud_bin_0.pcd" ]; then
  "$PY" examples/python/figure2.py "$data/open3d/Feature/cloud_bin_0.pcd" "$data/open3d/knot.ply" \
      --frames 1 --out "$out/figure2" >/dev/null
  cp "$out/figure2/frame_000.png" docs/images/figure2.png
fi
# The reconstruction system on all 211 shared frames (about 1.5 min on 2 cores), the scene seen from above.
if [ -f "$data/livingroom1_clean_micro/depth/00000.png" ]; then
  printf '{"path_dataset": "%s", "path_output": "%s"}' "$(cd "$data" && pwd)/livingroom1_clean_micro" "$out/scene" \
      > "$out/scene.json"
  "$PY" examples/python/reconstruction_system.py "$out/scene.json" --picture docs/images/reconstruction.png >/dev/null
fi
ls -l docs/images/*.png
