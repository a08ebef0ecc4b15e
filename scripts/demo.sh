#!/usr/bin/env bash
# The README's demo command: installs what is needed, builds o3d's Python package into .venv, and runs
# the paper's Figure 1 task (read, voxel down-sample, normals, write) plus ICP, global registration and a mesh pass on synthesized data.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
[ -x .venv/bin/python ] || python3 -m venv .venv
.venv/bin/pip install -q numpy
.venv/bin/pip install -q .
.venv/bin/python examples/demo/demo.py "$@"
