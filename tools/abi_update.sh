#!/usr/bin/env bash
# Regenerate the ABI baseline from a RelWithDebInfo build (GCC 12, Debian 12, as CI builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
LIB=$(readlink -f "$BUILD/capi/libo3d.so")
# --exported-interfaces-only keeps the baseline to what o3d_* functions expose (the opaque structs'
# C++ insides would otherwise fill megabytes with std:: and Eigen types).
abidw --headers-dir capi/include/o3d --drop-private-types --exported-interfaces-only --drop-undefined-syms \
      --no-corpus-path --short-locs --no-comp-dir-path --out-file abi/libo3d.abi "$LIB"
echo "abi_update: wrote abi/libo3d.abi from $LIB"
