#!/usr/bin/env python3
"""List the o3d_* functions declared in capi/include/o3d/*.h, one per line (name<TAB>header<TAB>prototype).

A thin view of tools/capi_model.py, kept for the scripts that import `declarations` from here.
"""
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from capi_model import INCLUDE_DIR, ROOT, declarations  # noqa: E402,F401

if __name__ == "__main__":
    for name, header, ret, args in declarations():
        print(f"{name}\t{header}\t{ret} {name}({args})")
