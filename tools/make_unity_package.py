#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Lays out o3d's Unity package (UPM) from the built C# assembly and the bundled native plugin.

  make_unity_package.py --out DIR --version V --assembly O3d.dll [--doc O3d.xml] --native BUNDLE

writes DIR/com.o3d.o3d/ and DIR/com.o3d.o3d-V.tgz (the folder as `npm pack` would pack it, which is what
Unity's "Add package from tarball" reads):

  package.json
  Runtime/O3d.dll, O3d.xml       the assembly and its XML docs (any platform)
  Plugins/x86_64/*.so*           libo3d_csharp.so, libo3d.so.0 and what they need, RUNPATH $ORIGIN
                                 (tools/bundle_native.py); enabled for the Linux x86-64 player and editor
  *.meta                         Unity's import settings. Unity refuses to write them into an immutable
                                 package, so they ship. GUIDs are derived from the path: a rebuild keeps them.

The same two folders serve a plain Mono program: reference Runtime/O3d.dll, and copy it with
Plugins/x86_64/* next to the program (Mono looks for libo3d_csharp.so beside the assembly).
"""
import argparse
import hashlib
import json
import os
import shutil
import sys
import tarfile

NAME = "com.o3d.o3d"


def guid(relpath):
    return hashlib.md5(f"{NAME}/{relpath}".encode()).hexdigest()


def folder_meta(rel):
    return (f"fileFormatVersion: 2\nguid: {guid(rel)}\nfolderAsset: yes\nDefaultImporter:\n"
            "  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n")


def text_meta(rel):
    return (f"fileFormatVersion: 2\nguid: {guid(rel)}\nTextScriptImporter:\n"
            "  externalObjects: {}\n  userData: \n  assetBundleName: \n  assetBundleVariant: \n")


def plugin_meta(rel, native):
    """A managed assembly loads everywhere; the native plugin only in the Linux x86-64 editor and player."""
    if native:
        platforms = ("  - first:\n      Any: \n    second:\n      enabled: 0\n      settings: {}\n"
                     "  - first:\n      Editor: Editor\n    second:\n      enabled: 1\n      settings:\n"
                     "        CPU: x86_64\n        DefaultValueInitialized: true\n        OS: Linux\n"
                     "  - first:\n      Standalone: Linux64\n    second:\n      enabled: 1\n      settings:\n"
                     "        CPU: x86_64\n")
    else:
        platforms = "  - first:\n      Any: \n    second:\n      enabled: 1\n      settings: {}\n"
    return (f"fileFormatVersion: 2\nguid: {guid(rel)}\nPluginImporter:\n  externalObjects: {{}}\n"
            "  serializedVersion: 2\n  iconMap: {}\n  executionOrder: {}\n  defineConstraints: []\n"
            f"  isPreloaded: 0\n  isOverridable: 0\n  isExplicitlyReferenced: 0\n  validateReferences: 1\n"
            f"  platformData:\n{platforms}  userData: \n  assetBundleName: \n  assetBundleVariant: \n")


def write(root, rel, text):
    with open(os.path.join(root, rel), "w") as f:
        f.write(text)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", required=True)
    p.add_argument("--version", required=True)
    p.add_argument("--assembly", required=True)
    p.add_argument("--doc")
    p.add_argument("--native", required=True, help="a tools/bundle_native.py folder (with its FILES index)")
    a = p.parse_args()

    root = os.path.join(a.out, NAME)
    shutil.rmtree(root, ignore_errors=True)
    for folder in ("Runtime", "Plugins", "Plugins/x86_64"):
        os.makedirs(os.path.join(root, folder))
        write(root, folder + ".meta", folder_meta(folder))

    package = {
        "name": NAME,
        "version": a.version,
        "displayName": "o3d",
        "description": "3D data processing (point clouds, meshes, RGB-D images, registration) through o3d's "
                       "C API. Native plugin: Linux x86-64.",
        "unity": "2021.3",
        "license": "MIT",
        "keywords": ["point cloud", "mesh", "registration", "3D"],
    }
    write(root, "package.json", json.dumps(package, indent=2) + "\n")
    write(root, "package.json.meta", text_meta("package.json"))

    for src in [a.assembly] + ([a.doc] if a.doc else []):
        rel = "Runtime/" + os.path.basename(src)
        shutil.copy2(src, os.path.join(root, rel))
        write(root, rel + ".meta", plugin_meta(rel, native=False) if rel.endswith(".dll") else text_meta(rel))

    with open(os.path.join(a.native, "FILES")) as index:
        natives = [line.strip() for line in index if line.strip()]
    for name in natives:
        rel = "Plugins/x86_64/" + name
        shutil.copy2(os.path.join(a.native, name), os.path.join(root, rel))
        write(root, rel + ".meta", plugin_meta(rel, native=True))

    tgz = os.path.join(a.out, f"{NAME}-{a.version}.tgz")
    with tarfile.open(tgz, "w:gz") as t:
        t.add(root, arcname="package")
    print(f"make_unity_package: {root} ({len(natives)} native files), {tgz} ({os.path.getsize(tgz) // 1024} KiB)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
