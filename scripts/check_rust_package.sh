#!/usr/bin/env bash
# Packages the Rust crates (o3d-sys, o3d) with `cargo package --workspace`, whose verify step builds
# them from the .crate files against an installed libo3d found through pkg-config; then copies
# examples/consumers/rust to a temporary folder outside the source tree, points its `o3d` dependency
# at the unpacked .crate files ([patch.crates-io] in that copy's .cargo/config.toml), builds and runs
# it with only the prefix's pkg-config (no O3D_LIB_DIR / O3D_INCLUDE_DIR).
# Usage: scripts/check_rust_package.sh <prefix>   (a `cmake --install build --prefix <prefix>`)
set -euo pipefail
if [ $# -ne 1 ] || [ ! -f "$1/lib/pkgconfig/o3d.pc" ]; then
  echo "usage: $0 <prefix>   (<prefix>/lib/pkgconfig/o3d.pc must exist: cmake --install build --prefix <prefix>)" >&2
  exit 2
fi
PREFIX=$(cd "$1" && pwd)
cd "$(dirname "$0")/.."
ROOT=$PWD
unset O3D_LIB_DIR O3D_INCLUDE_DIR
export PKG_CONFIG_PATH="$PREFIX/lib/pkgconfig"
export CARGO_BUILD_JOBS=${CARGO_BUILD_JOBS:-2}
WORK=$(mktemp -d /tmp/o3d-rust-consumer.XXXXXX)
trap 'rm -rf "$WORK"' EXIT

echo "--- cargo package --workspace (PKG_CONFIG_PATH=$PKG_CONFIG_PATH)"
# --allow-dirty: also package a working tree with uncommitted changes (a clean clone has none).
(cd bindings/rust && cargo package --workspace --allow-dirty)
PKG_DIR=$ROOT/bindings/rust/target/package
CRATES=()
for name in o3d-sys o3d; do
  version=$(sed -n 's/^version = "\(.*\)"/\1/p' "bindings/rust/$name/Cargo.toml" | head -1)
  crate="$PKG_DIR/$name-$version.crate"
  [ -f "$crate" ] || { echo "missing $crate" >&2; exit 1; }
  CRATES+=("$crate")
  mkdir -p "$WORK/crates"
  tar -xzf "$crate" -C "$WORK/crates"
done

echo "--- consumer: examples/consumers/rust in $WORK/consumer, against the packaged crates"
cp -r "$ROOT/examples/consumers/rust" "$WORK/consumer"
rm -rf "$WORK/consumer/target" "$WORK/consumer/Cargo.lock"
mkdir -p "$WORK/consumer/.cargo"
{
  echo "[patch.crates-io]"
  for dir in "$WORK"/crates/*/; do
    name=$(sed -n 's/^name = "\(.*\)"/\1/p' "$dir/Cargo.toml" | head -1)
    echo "$name = { path = \"${dir%/}\" }"
  done
} >"$WORK/consumer/.cargo/config.toml"
cat "$WORK/consumer/.cargo/config.toml"
# Installed into a prefix outside the loader's default path: the run finds libo3d.so.0 through
# pkg-config's libdir, as any program linked to a library in such a prefix would.
LIBDIR=$(pkg-config --variable=libdir o3d)
(cd "$WORK/consumer" && cargo tree -e normal,build --depth 2 | sed 's/^/  /' && cargo build -q &&
 LD_LIBRARY_PATH="$LIBDIR${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}" cargo run -q)

echo "--- packaged crates"
for crate in "${CRATES[@]}"; do
  printf '  %-60s %8d bytes, %3d files\n' "${crate#"$ROOT"/}" "$(stat -c %s "$crate")" "$(tar -tzf "$crate" | wc -l)"
done
echo "rust package: built and ran the consumer against $PREFIX"
