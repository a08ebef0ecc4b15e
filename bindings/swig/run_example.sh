#!/bin/sh
# Runs a Figure-1 example (command given as arguments) on cloud_bin_0.pcd, following the
# O3D_TEST_DATA convention: data dir from $O3D_TEST_DATA, else $O3D_TEST_DATA_DEFAULT (set by
# ctest to <repo>/../shared/data). Missing data: skip (exit 77), or fail when O3D_REQUIRE_TEST_DATA=1.
data="${O3D_TEST_DATA:-${O3D_TEST_DATA_DEFAULT:-../shared/data}}"
in="$data/open3d/Feature/cloud_bin_0.pcd"
if [ ! -f "$in" ]; then
  if [ "${O3D_REQUIRE_TEST_DATA:-0}" = "1" ]; then echo "missing test data: $in" >&2; exit 1; fi
  echo "skipped: missing test data $in"; exit 77
fi
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
"$@" "$in" "$tmp/cloud_bin_0_down.ply" || exit 1
[ -s "$tmp/cloud_bin_0_down.ply" ] || { echo "no output written" >&2; exit 1; }
