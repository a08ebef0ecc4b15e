#!/usr/bin/env bash
# Installs o3d from a build folder into a fresh prefix, then builds and runs every consumer project of
# examples/consumers from a temporary folder outside the source tree, against that prefix only:
# find_package(o3d) in C and C++, pkg-config, dlopen, C# with Mono's mcs (the Unity package's assembly
# and native plugin) and Java with only a jar on the class path (the installed one, or the one given,
# e.g. Maven's target/o3d-<version>.jar). Programs run with no LD_LIBRARY_PATH.
# Usage: scripts/check_consumers.sh [build-folder] [jar]
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
BUILD=${1:-build}
JAR=${2:-}
[ -z "$JAR" ] || JAR=$(realpath "$JAR")
unset LD_LIBRARY_PATH O3D_NATIVE_DIR MONO_PATH
WORK=$(mktemp -d /tmp/o3d-consumers.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
PREFIX=$WORK/prefix
cmake --install "$BUILD" --prefix "$PREFIX" >/dev/null
cp -r "$ROOT/examples/consumers/." "$WORK/"
echo "installed into $PREFIX:"
(cd "$PREFIX" && find . -type f -o -type l | sort | sed 's/^/  /' | grep -v '/o3d/.*\.h$\|/o3dpp/.*\.hpp$')
echo "  + $(ls "$PREFIX/include/o3d" | wc -l) C headers, $(ls "$PREFIX/include/o3dpp" | wc -l) C++ wrapper headers"
LIBDIR=$(dirname "$(find "$PREFIX" -name 'libo3d.so.0' ! -path '*/share/*' | head -1)")  # share/ holds the packages' copies

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

UNITY=$PREFIX/share/o3d/unity
if [ -d "$UNITY/com.o3d.o3d" ]; then
  PKG=$UNITY/com.o3d.o3d
  echo "--- unity: the package as Unity reads it ($(basename "$UNITY"/com.o3d.o3d-*.tgz), $(du -k "$UNITY"/com.o3d.o3d-*.tgz | cut -f1) KiB)"
  listing=$(tar tzf "$UNITY"/com.o3d.o3d-*.tgz | sort)
  echo "$listing" | grep -v '\.meta$' | sed 's/^/  /'
  for f in package/package.json package/Runtime/O3d.dll package/Plugins/x86_64/libo3d_csharp.so; do
    echo "$listing" | grep -qx "$f" || { echo "the tarball lacks $f"; exit 1; }
  done
  # Every file Unity imports needs its .meta beside it (a package is immutable in Unity's cache).
  (cd "$PKG" && find . -mindepth 1 ! -name '*.meta' | while read -r f; do [ -f "$f.meta" ] || { echo "no $f.meta"; exit 1; }; done)
  python3 "$ROOT/tools/bundle_native.py" verify --within "$PKG/Plugins/x86_64" $(ls "$PKG"/Plugins/x86_64/*.so* | grep -v '\.meta$')

  echo "--- csharp: mcs -r:Runtime/O3d.dll; O3d.dll and Plugins/x86_64/* copied beside the program"
  mkdir -p "$WORK/csharp/bin"
  mcs -nologo -target:exe -out:"$WORK/csharp/bin/Consumer.exe" -r:"$PKG/Runtime/O3d.dll" "$WORK/csharp/Program.cs"
  cp "$PKG/Runtime/O3d.dll" $(ls "$PKG"/Plugins/x86_64/*.so* | grep -v '\.meta$') "$WORK/csharp/bin/"
  (cd / && mono "$WORK/csharp/bin/Consumer.exe")
fi

JAR=${JAR:-$PREFIX/share/java/o3d.jar}
if [ -f "$JAR" ]; then
  echo "--- java: javac/java with only $(basename "$JAR") ($(du -k "$JAR" | cut -f1) KiB) on the class path"
  mkdir -p "$WORK/java/lib" "$WORK/java/classes" "$WORK/java/unpacked"
  cp "$JAR" "$WORK/java/lib/o3d.jar"
  # What the jar carries, unpacked here only to show it and to check that it resolves within itself.
  (cd "$WORK/java/unpacked" && jar xf ../lib/o3d.jar org/o3d/native)
  NATIVE=$(dirname "$(find "$WORK/java/unpacked" -name FILES | head -1)")
  (cd "$WORK/java/unpacked" && find . -type f -exec ls -l {} + | awk '{print "  " $5 " " $9}')
  python3 "$ROOT/tools/bundle_native.py" verify --within "$NATIVE" "$NATIVE"/*.so*
  javac -d "$WORK/java/classes" -cp "$WORK/java/lib/o3d.jar" "$WORK/java/Main.java"
  (cd / && java -cp "$WORK/java/lib/o3d.jar:$WORK/java/classes" Main)
fi
echo "consumers: all ran against $PREFIX${2:+ and $JAR}"
