#!/usr/bin/env python3
"""The C API as data, read from capi/include/o3d/*.h: the single source every derived list comes from.

The headers follow docs/conventions.md closely enough to be read with a few regular expressions:
`O3D_API <ret> o3d_<name>(<params>);` declarations, `typedef struct <tag> { <fields> } <name>_t;`
value structs, `typedef struct <tag> <name>_t;` opaque handles (types.h), `#define O3D_<NAME> <value>`
constants, function-pointer typedefs for callbacks, and value typedefs `typedef int32_t o3d_<x>;`.

Value typedefs name what an int32_t holds (common.h: o3d_bool, o3d_count, o3d_optional_index); one
followed directly by `#define`s (each documented, lines without a blank one between) names that constant
group, e.g. `typedef int32_t o3d_shader;` + O3D_SHADER_*. Types in the model are resolved through them
(`type` is the ABI type, e.g. int32_t, as the SWIG generator needs it) and keep the written name in
`typedef`; o3d_status, the return-code type, stays as written. Doc comments (`/** */` before, `/**< */`
after) are kept for structs, fields, constants and value typedefs; a function keeps its `@brief` and each
parameter its `@param` text (`doc`).

Used by the dlopen test's function list (--c-names), the SWIG interface generator
(tools/gen_swig_interface.py), the binding-table generator (tools/gen_binding_tables.py), the
binding-coverage check and the ABI/doc scripts.

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
_VALUE_TYPEDEF = re.compile(r"^typedef\s+(u?int(?:8|16|32|64)_t)\s+(o3d_\w+)\s*;", re.M)
# A member of a constant group: one newline (no blank line), an optional doc block on its own lines, the #define
# with an optional trailing doc.
_GROUP_MEMBER = re.compile(r"[ \t]*\n(?:[ \t]*/\*\*(?!<)(?P<pre>(?:(?!\*/).)*)\*/[ \t]*\n)?[ \t]*#define[ \t]+"
                           r"(?P<name>O3D_\w+)[ \t]+\S+[ \t]*(?:/\*\*<(?P<post>(?:(?!\*/).)*)\*/)?[ \t]*(?=\n)", re.S)
_RAW_DEFINE = re.compile(r"^[ \t]*#define[ \t]+(O3D_\w+)[ \t]+\S+[ \t]*(?:/\*\*<((?:(?!\*/).)*)\*/)?", re.M)
_FIELD_END = re.compile(r"(\w+)\s*(?:\[\w*\])?\s*;")
_TRAILING_DOC = re.compile(r"[ \t]*/\*\*<((?:(?!\*/).)*)\*/", re.S)
# Typedefs the model keeps by name (the generators key on them).
NAMED_TYPES = {"o3d_status"}


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


def _clean_doc(body):
    """The text of a doc comment body: leading `*`s and line breaks removed."""
    lines = [re.sub(r"^\s*\*?\s?", "", line) for line in body.strip().splitlines()]
    return " ".join(line.strip() for line in lines if line.strip())


def _doc_before(raw, pos):
    """The `/** ... */` comment ending right before offset `pos` (only whitespace between), or None."""
    head = raw[:pos].rstrip()
    if not head.endswith("*/"):
        return None
    start = head.rfind("/*")
    block = head[start:]
    if not block.startswith("/**") or block.startswith("/**<"):
        return None
    return _clean_doc(block[3:-2])


def _brief_before(raw, pos):
    """The first paragraph of the `@brief` of the doc comment ending right before `pos`, or None."""
    head = raw[:pos].rstrip()
    if not head.endswith("*/") or not head[head.rfind("/*"):].startswith("/**"):
        return None
    block = head[head.rfind("/*") + 3:-2]
    m = re.search(r"@brief\s(.*?)(?:\n\s*\*?\s*\n|\n\s*\*\s*@|$)", block, re.S)
    return _clean_doc(m.group(1)) if m else None


def _param_docs_before(raw, pos):
    """{parameter: its `@param` text} of the doc comment ending right before `pos`."""
    head = raw[:pos].rstrip()
    if not head.endswith("*/") or not head[head.rfind("/*"):].startswith("/**"):
        return {}
    block = head[head.rfind("/*") + 3:-2]
    return {m.group(1): _clean_doc(m.group(2)) for m in re.finditer(r"@param\s+(\w+)\s(.*?)(?=\n\s*\*\s*@|$)", block, re.S)}


def _mask_comments(text):
    """`text` with each comment blanked (offsets kept)."""
    return _COMMENT.sub(lambda m: re.sub(r"[^\n]", " ", m.group(0)), text)


def _field_docs(raw_body):
    """{field name: its trailing `/**< ... */` doc} of a struct body."""
    docs = {}
    masked = _mask_comments(raw_body)
    for m in _FIELD_END.finditer(masked):
        d = _TRAILING_DOC.match(raw_body, m.end())
        if d:
            docs[m.group(1)] = _clean_doc(d.group(1))
    return docs


def _resolve(ctype, typedefs):
    """`ctype` with a value typedef replaced by its ABI type ('const o3d_bool*' -> 'const int32_t*')."""
    m = re.match(r"^(const )?(o3d_\w+)(\**)$", ctype)
    if m and m.group(2) in typedefs and m.group(2) not in NAMED_TYPES:
        return f"{m.group(1) or ''}{typedefs[m.group(2)]['base']}{m.group(3)}"
    return ctype


def _resolve_all(model):
    """Resolve value typedefs in every parameter, field and return type; the written type stays in `typedef`."""
    typedefs = {t["name"]: t for t in model["typedefs"]}

    def fix(p):
        resolved = _resolve(p["type"], typedefs)
        if resolved != p["type"]:
            p["typedef"], p["type"] = p["type"].replace("const ", "").rstrip("*"), resolved
    for f in model["functions"] + model["callbacks"]:
        for p in f["params"]:
            fix(p)
        resolved = _resolve(f["ret"], typedefs)
        if resolved != f["ret"]:
            f["ret_typedef"], f["ret"] = f["ret"], resolved
    for s in model["structs"]:
        for p in s["fields"]:
            fix(p)


def load(include_dir=INCLUDE_DIR):
    """The model: {'functions', 'structs', 'handles', 'constants', 'callbacks', 'typedefs'}, each a list in header order."""
    model = {"functions": [], "structs": [], "handles": [], "constants": [], "callbacks": [], "typedefs": []}
    for header in sorted(include_dir.glob("*.h")):
        raw = header.read_text()
        text = _COMMENT.sub("", raw)
        for m in _PROTO.finditer(_mask_comments(raw)):
            ret, name, args = m.groups()
            params, docs = _params(args), _param_docs_before(raw, m.start())
            for p in params:
                p["doc"] = docs.get(p["name"])
            model["functions"].append({"name": name, "header": header.name, "ret": " ".join(ret.split()),
                                       "params": params, "brief": _brief_before(raw, m.start())})
        for m in _STRUCT.finditer(raw):
            tag, body, name = m.groups()
            fields = [_param(f) for f in _COMMENT.sub("", body).split(";") if f.strip()]
            docs = _field_docs(body)
            for f in fields:
                f["doc"] = docs.get(f["name"])
            model["structs"].append({"name": name, "tag": tag, "header": header.name, "fields": fields,
                                     "versioned": bool(fields) and fields[0]["name"] == "struct_size",
                                     "doc": _doc_before(raw, m.start())})
        for tag, name in _OPAQUE.findall(text):
            model["handles"].append({"name": name, "tag": tag, "header": header.name})
        for ret, name, args in _CALLBACK.findall(text):
            model["callbacks"].append({"name": name, "ret": " ".join(ret.split()), "params": _params(args)})
        group_of, docs = {}, {}
        for m in _VALUE_TYPEDEF.finditer(raw):
            members, pos = [], m.end()
            while True:
                g = _GROUP_MEMBER.match(raw, pos)
                if not g:
                    break
                members.append(g.group("name"))
                docs[g.group("name")] = _clean_doc(g.group("post") or g.group("pre") or "") or None
                pos = g.end()
            group_of.update((c, m.group(2)) for c in members)
            model["typedefs"].append({"name": m.group(2), "base": m.group(1), "header": header.name,
                                      "doc": _doc_before(raw, m.start()), "constants": members})
        for m in _RAW_DEFINE.finditer(raw):
            if m.group(1) not in docs:
                docs[m.group(1)] = _clean_doc(m.group(2)) if m.group(2) else _doc_before(raw, m.start())
        for name, value in _DEFINE.findall(text):
            if name.endswith("_H"):
                continue
            model["constants"].append({"name": name, "value": int(value.strip("()"), 0), "header": header.name,
                                       "doc": docs.get(name), "group": group_of.get(name)})
    _resolve_all(model)
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
