#!/usr/bin/env bash
# The README's pictures, rendered by o3d itself (offscreen, no display): runs the demo and keeps the PNGs it
# writes in docs/images/. Usage: tools/make_readme_pictures.sh [python with o3d installed, default .venv/bin/python]
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${1:-.venv/bin/python}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$PY" examples/demo/demo.py "$out" >/dev/null
mkdir -p docs/images
cp "$out"/*.png docs/images/
ls -l docs/images/*.png
