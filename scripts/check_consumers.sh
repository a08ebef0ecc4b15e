#!/usr/bin/env bash
# Installs o3d from a build folder into a fresh prefix, then builds and runs every consumer project of
# examples/consumers from a temporary folder outside the source tree, against that prefix only:
# find_package(o3d) in C and C++, pkg-config, and dlopen. Usage: scripts/check_consumers.sh [build-folder]
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD=${1:-build}
WORK=$(mktemp -d /tmp/o3d-consumers.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
PREFIX=$WORK/prefix
cmake --install "$BUILD" --prefix "$PREFIX" >/dev/null
cp -r "$ROOT/examples/consumers/." "$WORK/"
echo "installed into $PREFIX:"
(cd "$PREFIX" && find . -type f -o -type l | sort | sed 's/^/  /' | grep -v '/o3d/.*\.h$\|/o3dpp/.*\.hpp$')
echo "  + $(ls "$PREFIX/include/o3d" | wc -l) C headers, $(ls "$PREFIX/include/o3dpp" | wc -l) C++ wrapper headers"
LIBDIR=$(dirname "$(find "$PREFIX" -name 'libo3d.so.0' | head -1)")

for project in cmake_c cmake_cpp; do
  echo "--- $project: find_package(o3d)"
  cmake -S "$WORK/$project" -B "$WORK/$project/build" -G Ninja -DCMAKE_PREFIX_PATH="$PREFIX" >/dev/null
  cmake --build "$WORK/$project/build" >/dev/null
  "$WORK/$project/build/consumer_${project#cmake_}"
done

echo "--- pkgconfig_c: pkg-config --cflags --libs o3d (the C program of cmake_c, built without CMake)"
export PKG_CONFIG_PATH="$LIBDIR/pkgconfig"
mkdir -p "$WORK/pkgconfig_c"
cc -std=c99 -Wall -Werror "$WORK/cmake_c/main.c" -o "$WORK/pkgconfig_c/consumer" $(pkg-config --cflags --libs o3d) \
   -Wl,-rpath,"$(pkg-config --variable=libdir o3d)"
"$WORK/pkgconfig_c/consumer"

echo "--- dlopen_c: dlopen($LIBDIR/libo3d.so.0), headers from the prefix, no link"
cc -std=c99 -Wall -Werror -I"$PREFIX/include" "$WORK/dlopen_c/main.c" -o "$WORK/dlopen_c/consumer" -ldl
"$WORK/dlopen_c/consumer" "$LIBDIR/libo3d.so.0"
echo "consumers: all ran against $PREFIX"
