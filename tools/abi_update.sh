#!/usr/bin/env bash
# Regenerate the ABI baseline from a RelWithDebInfo build (GCC 12, Debian 12, as CI builds it).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
LIB=$(readlink -f "$BUILD/capi/libo3d.so")
abidw --headers-dir capi/include/o3d --drop-private-types --no-corpus-path --short-locs --no-comp-dir-path \
      --out-file abi/libo3d.abi.xml "$LIB"
gzip -9nf abi/libo3d.abi.xml
echo "abi_update: wrote abi/libo3d.abi.xml.gz from $LIB"
