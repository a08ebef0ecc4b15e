#!/usr/bin/env bash
# Build the libFuzzer targets with clang and fuzz each reader (clouds, meshes, images) for N seconds.
#   tests/fuzz/run_fuzz.sh [seconds per format, default 30] [corpus folders: ply, mesh_obj, image_png, ...]
# Findings (crash-*, leak-*, timeout-*) land in build-fuzz/findings/<format>/; the committed
# corpus is read, never written: new interesting inputs go to build-fuzz/corpus/<format>/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
secs=${1:-30}
shift || true
formats=${*:-ply pcd xyz xyzn xyzrgb pts mesh_ply mesh_obj mesh_stl mesh_off mesh_glb mesh_gltf image_png image_jpg image_ppm image_pgm}
build=${O3D_FUZZ_BUILD_DIR:-$root/build-fuzz}
jobs=${O3D_FUZZ_JOBS:-2}

# tests/fuzz is its own small project: only the readers, instrumented, and the fuzz targets.
CXX=clang++ cmake -S "$here" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
targets=()
for f in $formats; do targets+=("fuzz_io_$f"); done
cmake --build "$build" -j"$jobs" --target "${targets[@]}"

status=0
for f in $formats; do
  mkdir -p "$build/corpus/$f" "$build/findings/$f"
  echo "== fuzzing $f for ${secs}s"
  # -rss_limit_mb keeps a header-driven allocation from passing unnoticed as "slow".
  if ! "$build/fuzz_io_$f" "$build/corpus/$f" "$here/corpus/$f" \
      -max_total_time="$secs" -rss_limit_mb=1024 -malloc_limit_mb=512 -timeout=10 -print_final_stats=1 \
      -artifact_prefix="$build/findings/$f/" 2>"$build/findings/$f/log.txt"; then
    echo "!! $f: finding, see $build/findings/$f/ (log.txt)"
    tail -30 "$build/findings/$f/log.txt"
    status=1
  else
    grep -E "stat::number_of_executed_runs|cov:" "$build/findings/$f/log.txt" | tail -2
  fi
done
exit $status
