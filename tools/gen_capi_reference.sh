#!/usr/bin/env bash
# Generate the C API reference (HTML) from capi/include/o3d/*.h with Doxygen; the main page is
# docs/conventions.md. Usage: tools/gen_capi_reference.sh [OUTPUT_DIR]   (default build/capi-reference)
# Fails when doxygen reports any warning (an undocumented function, parameter, return value, macro or
# field): the warnings are printed and kept in OUTPUT_DIR/warnings.log. Needs doxygen (scripts/install-deps.sh).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${1:-$root/build/capi-reference}"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
command -v doxygen >/dev/null || { echo "gen_capi_reference: doxygen not found (scripts/install-deps.sh installs it)" >&2; exit 2; }
version="$(sed -n 's/^#define O3D_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\).*/\2/p' "$root/capi/include/o3d/common.h" | paste -sd.)"
rm -rf "$out/html" "$out/warnings.log"
cd "$root"
O3D_DOC_OUTPUT="$out" O3D_DOC_VERSION="$version" doxygen docs/capi-reference/Doxyfile >/dev/null
if [ -s "$out/warnings.log" ]; then
    cat "$out/warnings.log" >&2
    echo "gen_capi_reference: $(grep -c 'warning:' "$out/warnings.log") doxygen warnings (see above)" >&2
    exit 1
fi
echo "gen_capi_reference: C API reference $version in $out/html/index.html (no warnings)"
