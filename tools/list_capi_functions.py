#!/usr/bin/env python3
"""List the o3d_* functions declared in capi/include/o3d/*.h, one per line (name<TAB>header<TAB>prototype).

Used by the binding-coverage check and by whoever needs the API surface as data.
"""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
PROTO = re.compile(r"O3D_API\s+([^;{]*?)\b(o3d_\w+)\s*\(([^;]*?)\)\s*;", re.S)


def declarations(include_dir=ROOT / "capi" / "include" / "o3d"):
    for header in sorted(include_dir.glob("*.h")):
        text = re.sub(r"/\*.*?\*/", "", header.read_text(), flags=re.S)
        for ret, name, args in PROTO.findall(text):
            yield name, header.name, " ".join(ret.split()), " ".join(args.split())


if __name__ == "__main__":
    for name, header, ret, args in declarations():
        print(f"{name}\t{header}\t{ret} {name}({args})")
