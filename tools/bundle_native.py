#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Self-contained native libraries for the packages that carry them (the jar, the Unity package).

  bundle_native.py bundle --out DIR LIB [LIB ...]
      Copies each LIB into DIR, then every shared library it needs (transitively, as ldd resolves them
      here) except the C and C++ runtime that any Linux x86-64 machine has. Each file is stripped of
      debug info and gets RUNPATH $ORIGIN, so the set loads from wherever it is unpacked, with no
      LD_LIBRARY_PATH. A dependency is stored under the name its dependents ask for (its DT_NEEDED
      entry, e.g. libo3d.so.0). DIR/FILES lists the files, one per line, LIB first: a jar cannot
      list its own resources, so the loader reads that index.

  bundle_native.py verify --within DIR [--within DIR ...] FILE [FILE ...]
      Prints ldd of each FILE and fails when a library outside the runtime set resolves outside the
      DIRs (used for the bundle above and for the repaired Python wheel).

Needs ldd, readelf, strip and patchelf (scripts/install-deps.sh installs them).
"""
import argparse
import os
import re
import shutil
import subprocess
import sys

# What a package may take from the machine: glibc, the C++ runtime and zlib. This is the manylinux
# policy's base set (PEP 600), which auditwheel applies to the wheel, so the three packages agree.
RUNTIME = re.compile(r"^(linux-vdso|ld-linux|libc\.so|libm\.so|libdl\.so|librt\.so|libpthread\.so|"
                     r"libstdc\+\+\.so|libgcc_s\.so|libz\.so\.1)")


def ldd(path):
    """[(needed name, resolved path or None)] for every library the loader maps for `path`."""
    out = subprocess.run(["ldd", path], check=True, capture_output=True, text=True).stdout
    deps = []
    for line in out.splitlines():
        m = re.match(r"\s*(\S+)\s+=>\s+(not found|\S+)", line)
        if m:
            deps.append((m.group(1), None if m.group(2) == "not found" else m.group(2)))
    return deps


def bundle(out, libs):
    shutil.rmtree(out, ignore_errors=True)  # a dependency dropped since the last build must not linger
    os.makedirs(out)
    files = []  # names inside `out`, in load order of importance (the given libraries first)
    for lib in libs:
        name = os.path.basename(lib)
        shutil.copy2(os.path.realpath(lib), os.path.join(out, name))
        files.append(name)
    for lib in libs:
        for needed, where in ldd(lib):
            if RUNTIME.match(needed) or needed in files:
                continue
            if where is None:
                sys.exit(f"bundle_native: {lib} needs {needed}, which does not resolve here")
            shutil.copy2(os.path.realpath(where), os.path.join(out, needed))
            files.append(needed)
    for name in files:
        path = os.path.join(out, name)
        os.chmod(path, 0o755)
        subprocess.run(["strip", "--strip-debug", path], check=True)
        subprocess.run(["patchelf", "--set-rpath", "$ORIGIN", path], check=True)
    with open(os.path.join(out, "FILES"), "w") as index:
        index.write("".join(f + "\n" for f in files))
    total = sum(os.path.getsize(os.path.join(out, f)) for f in files)
    print(f"bundle_native: {len(files)} files, {total // 1024} KiB in {out}: {' '.join(files)}")


def verify(within, files):
    within = [os.path.realpath(d) + os.sep for d in within]
    bad = []
    for path in files:
        print(f"ldd {path}:")
        for needed, where in ldd(path):
            print(f"    {needed} => {where}")
            if RUNTIME.match(needed):
                continue
            if where is None or not any(os.path.realpath(where).startswith(d) for d in within):
                bad.append(f"{path}: {needed} => {where}")
    for line in bad:
        print(f"  NOT FROM THE PACKAGE: {line}")
    return 1 if bad else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    b = sub.add_parser("bundle")
    b.add_argument("--out", required=True)
    b.add_argument("libs", nargs="+")
    v = sub.add_parser("verify")
    v.add_argument("--within", action="append", required=True)
    v.add_argument("files", nargs="+")
    args = parser.parse_args()
    if args.command == "bundle":
        bundle(args.out, args.libs)
        return 0
    return verify(args.within, args.files)


if __name__ == "__main__":
    sys.exit(main())
