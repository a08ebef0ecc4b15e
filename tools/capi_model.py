#!/usr/bin/env python3
"""The C API as data, read from capi/include/o3d/*.h: the single source every derived list comes from.

The headers follow docs/conventions.md closely enough to be read with a few regular expressions:
`O3D_API <ret> o3d_<name>(<params>);` declarations, `typedef struct <tag> { <fields> } <name>_t;`
value structs, `typedef struct <tag> <name>_t;` opaque handles (types.h), `#define O3D_<NAME> <value>`
constants and function-pointer typedefs for callbacks.

Used by the dlopen test's function list (--c-names), the SWIG interface generator
(tools/gen_swig_interface.py), the binding-coverage check and the ABI/doc scripts.

    python3 tools/capi_model.py --c-names        # "o3d_version",\\n ... (a C initializer list)
    python3 tools/capi_model.py --json           # the whole model
"""
import argparse
import json
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
INCLUDE_DIR = ROOT / "capi" / "include" / "o3d"

_COMMENT = re.compile(r"/\*.*?\*/", re.S)
_PROTO = re.compile(r"O3D_API\s+([^;{]*?)\b(o3d_\w+)\s*\(([^;]*?)\)\s*;", re.S)
_STRUCT = re.compile(r"typedef\s+struct\s+(\w+)\s*\{(.*?)\}\s*(\w+)\s*;", re.S)
_OPAQUE = re.compile(r"typedef\s+struct\s+(\w+)\s+(\w+)\s*;")
_CALLBACK = re.compile(r"typedef\s+([\w\s\*]+?)\s*\(\s*\*\s*(\w+)\s*\)\s*\(([^;]*?)\)\s*;", re.S)
_DEFINE = re.compile(r"^\s*#define\s+(O3D_[A-Z0-9_]+)\s+(\(?-?[0-9][0-9a-fA-FxX]*\)?)\s*$", re.M)


def _param(text):
    """'const double transform[16]' -> {'type': 'const double*', 'name': 'transform', 'array': 16}."""
    text = " ".join(text.split())
    m = re.match(r"^(.*?)(\w+)\s*(?:\[(\w*)\])?$", text)
    ctype, name, dim = m.group(1).strip(), m.group(2), m.group(3)
    ctype = re.sub(r"\s*\*", "*", ctype)
    if dim is not None:
        ctype += "*"
    return {"type": ctype, "name": name, "array": int(dim) if dim and dim.isdigit() else None}


def _params(text):
    text = " ".join(text.split())
    if text in ("", "void"):
        return []
    return [_param(p) for p in text.split(",")]


def load(include_dir=INCLUDE_DIR):
    """The model: {'functions': [...], 'structs': [...], 'handles': [...], 'constants': [...], 'callbacks': [...]}."""
    model = {"functions": [], "structs": [], "handles": [], "constants": [], "callbacks": []}
    for header in sorted(include_dir.glob("*.h")):
        raw = header.read_text()
        text = _COMMENT.sub("", raw)
        for ret, name, args in _PROTO.findall(text):
            model["functions"].append(
                {"name": name, "header": header.name, "ret": " ".join(ret.split()), "params": _params(args)})
        for tag, body, name in _STRUCT.findall(text):
            fields = [_param(f) for f in body.split(";") if f.strip()]
            model["structs"].append({"name": name, "tag": tag, "header": header.name, "fields": fields,
                                     "versioned": bool(fields) and fields[0]["name"] == "struct_size"})
        for tag, name in _OPAQUE.findall(text):
            model["handles"].append({"name": name, "tag": tag, "header": header.name})
        for ret, name, args in _CALLBACK.findall(text):
            model["callbacks"].append({"name": name, "ret": " ".join(ret.split()), "params": _params(args)})
        for name, value in _DEFINE.findall(text):
            if name.endswith("_H"):
                continue
            model["constants"].append({"name": name, "value": int(value.strip("()"), 0), "header": header.name})
    return model


def declarations(include_dir=INCLUDE_DIR):
    """(name, header, return type, parameter text) per function, in header order."""
    for f in load(include_dir)["functions"]:
        args = ", ".join(f"{p['type']} {p['name']}" for p in f["params"])
        yield f["name"], f["header"], f["ret"], args


def write_output(text, output):
    """Write `text` to `output` (stdout when None), leaving an unchanged file untouched so that build
    tools that compare timestamps do not rebuild what depends on it."""
    if output is None:
        sys.stdout.write(text)
        return
    output.parent.mkdir(parents=True, exist_ok=True)
    if not output.exists() or output.read_text() != text:
        output.write_text(text)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--c-names", action="store_true", help="function names as a C initializer list")
    parser.add_argument("--json", action="store_true", help="the whole model as JSON")
    parser.add_argument("--include-dir", type=pathlib.Path, default=INCLUDE_DIR)
    parser.add_argument("-o", "--output", type=pathlib.Path, help="write here instead of stdout")
    args = parser.parse_args()
    model = load(args.include_dir)
    if args.c_names:
        text = "".join(f'    "{f["name"]}",\n' for f in model["functions"])
    elif args.json:
        text = json.dumps(model, indent=1) + "\n"
    else:
        text = "".join(f'{f["name"]}\t{f["header"]}\n' for f in model["functions"])
    write_output(text, args.output)


if __name__ == "__main__":
    main()
