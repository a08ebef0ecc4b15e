#!/usr/bin/env bash
# ABI check: compare the freshly built libo3d against the committed baseline (abi/libo3d.abi).
# Any difference abidiff reports (exit != 0: 4 = ABI change, 8 = incompatible change) fails, because an
# added parameter or struct member is a break for C callers even when abidiff calls it "compatible".
# To accept a change on purpose: tools/abi_update.sh BUILD_DIR, and commit the new baseline.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
LIB=$(readlink -f "$BUILD/capi/libo3d.so")
BASE=abi/libo3d.abi
[ -f "$BASE" ] || { echo "abi_check: no baseline $BASE (run tools/abi_update.sh)"; exit 1; }
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
if abidiff --headers-dir2 capi/include/o3d --exported-interfaces-only "$BASE" "$LIB" > "$tmp/report.txt"; then
  echo "abi_check: libo3d ABI matches the baseline ($(grep -c '<elf-symbol ' "$BASE") symbols)"
else
  rc=$?
  cat "$tmp/report.txt"
  echo "abi_check: abidiff exit $rc: the ABI changed. If intended (new major version or additions), run tools/abi_update.sh $BUILD"
  exit 1
fi
