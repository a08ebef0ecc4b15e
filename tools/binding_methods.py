"""Pass-through methods: C functions that a binding shows as one method (or static function) of a handle's class,
passing its arguments to the one C call and returning what that call writes (tools/gen_binding_tables.py writes them).

The shapes, by the C declaration (outputs first, docs/conventions.md), each returning a status:
  method       the class's handle first (`const` when the call only reads it), then plain parameters;
  with a value one output before the handle: a scalar (int32_t*, int64_t*, size_t*, double*) or a fixed array
               (`double out[3]`, `int32_t out[3]`), the method's value; an int32_t* typed o3d_bool* or documented
               "receives 1 (true) or 0 (false)" is a bool; one typed as a constant group's typedef is that enum;
  deriving     a new handle `o3d_<x>_t** out` before the handle: the method returns a new object of x's class;
  constructor  a new handle of the class and no handle of it after: a static function returning a new object.

A parameter is plain when its type says how each language takes it:
  int32_t, double            numbers
  o3d_bool                   a bool; so is an int32_t documented "non-zero ..." (flags typed before o3d_bool was)
  a constant group's typedef that enum
  size_t                     a count (Rust usize; Python a non-negative int)
  uint64_t seed              a random seed (Python: an int, or None for a fresh one)
  const char*                a string; a path when named `path` or `*_path`
  const double x[N]          an array of N, a matrix when documented "row-major RxC"; optional when documented
                             "(NULL: ...)" (in its @param or the @brief: the library then picks the value)
  const o3d_<x>_t*           a reference to x's class
Each language lists the functions it shows this way and names what the C name does not say (the METHODS tables in
gen_binding_tables.py); the rest of a class is written by hand.
"""
import re

FIXED = {"do_render": "1"}  # arguments every binding passes as this value (its methods draw a frame first)
_VALUE_OUTS = {"int32_t*": "int", "int64_t*": "int64", "size_t*": "size", "double*": "double"}


def is_flag(p):
    """o3d_bool, or an int32_t documented as one ("non-zero: ..." / "receives 1 (true) or 0 (false)")."""
    return p.get("typedef") == "o3d_bool" or (p["type"] in ("int32_t", "int32_t*") and bool(
        re.match(r"non-zero\b|receives 1 \(true\) or 0 \(false\)", p.get("doc") or "")))


def matrix(p):
    """(rows, cols) of an array documented "row-major RxC", else None."""
    m = re.search(r"row-major (\d+)x(\d+)", p.get("doc") or "")
    return (int(m.group(1)), int(m.group(2))) if m else None


class Method:
    def __init__(self, f, handle, groups, handles):
        self.c, self.brief = f["name"], re.sub(r"\s*@see .*$", "", f["brief"] or "")  # (@see names Open3D's method)
        params = list(f["params"])
        first = params[0]["type"] if params else ""
        self.new = first[:-2] if first.endswith("**") and first[:-2] in handles else None  # the new object's handle
        self.out = None
        if self.new:
            params.pop(0)
        elif first in _VALUE_OUTS and (params[0]["array"] is None or first in ("double*", "int32_t*")):
            self.out = params.pop(0)
        self.static = not params or params[0]["type"] not in (f"{handle}*", f"const {handle}*")
        if self.static and self.new != handle:
            raise ValueError(f"{self.c}: not a method of {handle}")
        self.const = not self.static and params[0]["type"].startswith("const ")
        if not self.static:
            params.pop(0)
        self.params = [dict(p, kind=kind(p, groups, handles, self.brief)) for p in params]
        o = self.out
        self.out_kind = None if o is None else "array" if o["array"] else "bool" if is_flag(o) else \
            "enum" if o.get("typedef") in groups else _VALUE_OUTS[o["type"]]
        self.out_group = groups[o["typedef"]] if self.out_kind == "enum" else None  # the enum an "enum" out is

    def default_name(self, handle):
        """o3d_visualizer_view_get_field_of_view -> field_of_view: without the handle's prefix, `view_`, `view_get_`."""
        name = self.c[len(handle) - 1:]  # o3d_visualizer_t -> o3d_visualizer_
        return re.sub(r"^view_(get_)?", "", name)


def kind(p, groups, handles, brief=""):
    t, td = p["type"], p.get("typedef")
    if p["name"] in FIXED:
        return "fixed"
    if is_flag(p):
        return "bool"
    if td in groups:
        return "enum"
    if t in ("int32_t", "double"):
        return t
    if t == "size_t":
        return "size"
    if t == "uint64_t" and p["name"] == "seed":
        return "seed"
    if t == "const char*":
        return "path" if p["name"] == "path" or p["name"].endswith("_path") else "string"
    if t == "const double*" and p["array"]:
        optional = "(NULL: " in (p.get("doc") or "") or f"`{p['name']}` (NULL: " in brief
        return "optional_array" if optional else "array"
    if t.startswith("const ") and t[len("const "):-1] in handles and t.endswith("*"):
        return "handle"
    raise ValueError(f"{p['name']}: {t} is not a plain parameter")


def methods(model, groups, handle, wanted):
    """The Method of each function in `wanted` (C names) of `handle`, in header order."""
    prefix = handle[:-1]  # o3d_visualizer_t -> o3d_visualizer_
    handles = {h["name"] for h in model["handles"]}
    return [Method(f, handle, groups, handles) for f in model["functions"] if f["name"] in wanted and f["name"].startswith(prefix)]


def handle_type(p):
    return p["type"][len("const "):-1]
