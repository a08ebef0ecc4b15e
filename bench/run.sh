#!/usr/bin/env bash
# The one benchmark command: o3d against Open3D + small_gicp (Python) and PCL (C++), same data and threads.
#
#   bench/run.sh [--threads N] [--repeat R] [--warmup W] [--budget S] [--synthetic-points N] [--data DIR]
#                [--note TEXT] [--only SUBSTR...]
#
# 1. creates the throwaway venv bench/.venv and installs numpy, open3d, small_gicp from PyPI and o3d from
#    this checkout (`pip install <repo>`);
# 2. runs bench/bench.py in it, which writes bench/RESULTS.md;
# 3. builds bench/cpp (build-bench/, -DO3D_BUILD_BENCH=ON; PCL rows when PCL 1.13 is found) and appends its table.
# Environment: JOBS (build parallelism, default 2), PYTHON (interpreter for the venv, default python3),
# SKIP_PY=1 / SKIP_CPP=1 (skip a half), SKIP_INSTALL=1 (reuse the venv as it is).
set -euo pipefail

HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
REPO="$(dirname "$HERE")"
VENV="$HERE/.venv"
JOBS="${JOBS:-2}"
PYTHON="${PYTHON:-python3}"
RESULTS="$HERE/RESULTS.md"
BUILD="$REPO/build-bench"

# Options shared by both halves go to both; the others only to bench.py.
THREADS=""
PY_ARGS=()
CPP_ARGS=()
while [ $# -gt 0 ]; do
  case "$1" in
    --threads) THREADS="$2"; shift 2 ;;
    --repeat|--warmup|--budget|--synthetic-points|--data)
      PY_ARGS+=("$1" "$2"); CPP_ARGS+=("$1" "$2"); shift 2 ;;
    *) PY_ARGS+=("$1"); shift ;;
  esac
done
if [ -z "$THREADS" ] || [ "$THREADS" = 0 ]; then THREADS="$(nproc)"; fi
PY_ARGS+=(--threads "$THREADS")
CPP_ARGS+=(--threads "$THREADS")

if [ -z "${SKIP_INSTALL:-}" ]; then
  # The open3d wheel links libusb-1.0; PCL rows need libpcl-dev (optional: skipped when absent).
  SUDO=""; [ "$(id -u)" != 0 ] && SUDO=sudo
  "$REPO/scripts/install-deps.sh"
  for pkg in libusb-1.0-0 libpcl-dev; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" ||
      { $SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "$pkg"; } ||
      echo "note: could not install $pkg"
  done
  echo "== venv $VENV"
  [ -x "$VENV/bin/python" ] || "$PYTHON" -m venv "$VENV"
  "$VENV/bin/python" -m pip install -q --upgrade pip
  "$VENV/bin/python" -m pip install -q numpy open3d small_gicp
  echo "== pip install $REPO (o3d)"
  if ! CMAKE_BUILD_PARALLEL_LEVEL="$JOBS" "$VENV/bin/python" -m pip install -q --force-reinstall --no-deps "$REPO"; then
    echo "!! o3d could not be installed: the Python table will show it as unavailable" >&2
  fi
fi

if [ -z "${SKIP_PY:-}" ]; then
  echo "== Python benchmark (threads=$THREADS)"
  # Run from bench/ so that `import o3d` is the installed package, not a source directory.
  (cd "$HERE" && "$VENV/bin/python" "$HERE/bench.py" --out "$RESULTS" "${PY_ARGS[@]}")
else
  printf '# o3d benchmark results\n\n(Python half skipped)\n' > "$RESULTS"
fi

if [ -z "${SKIP_CPP:-}" ]; then
  echo "== C++ benchmark (build $BUILD)"
  cmake -S "$REPO" -B "$BUILD" -DCMAKE_BUILD_TYPE=Release -DO3D_BUILD_BENCH=ON -DO3D_BUILD_TESTS=OFF \
    -DO3D_BUILD_EXAMPLES=OFF -DO3D_BUILD_PYTHON=OFF >/dev/null
  cmake --build "$BUILD" --target o3d_bench -j "$JOBS"
  "$BUILD/bench/cpp/o3d_bench" --md "$RESULTS" "${CPP_ARGS[@]}"
fi
echo "== wrote $RESULTS"
