"""Pass-through methods: C functions that take a handle first (or one scalar out-parameter, then the handle) and
plain values, and return a status, shown as methods of the handle's class (tools/gen_binding_tables.py writes them).

A parameter is plain when its type says how each language takes it: int32_t and double as numbers, o3d_bool as
a bool, a constant group's typedef as that enum, `const char*` as a string (a path when named `path` or
`*_path`), `const double x[N]` as an array of N, another handle `const o3d_<x>_t*` as a reference to its class. A scalar out-parameter (o3d_bool*,
int32_t*, double*) is the method's value. Each language lists the functions it shows this way and names what
the C name does not say (METHODS tables in gen_binding_tables.py); the rest of the class is written by hand.
"""
import re

FIXED = {"do_render": "1"}  # arguments every binding passes as this value (its methods draw a frame first)


class Method:
    def __init__(self, f, handle, groups, handles):
        self.c, self.brief = f["name"], f["brief"] or ""
        params = list(f["params"])
        self.out = params.pop(0) if params and params[0]["type"] in ("int32_t*", "double*") else None
        self_param = params.pop(0) if params else {"type": None}
        if self_param["type"] not in (f"{handle}*", f"const {handle}*"):
            raise ValueError(f"{self.c}: not a method of {handle}")
        self.params = [dict(p, kind=kind(p, groups, handles)) for p in params]
        self.out_kind = None if self.out is None else {"int32_t*": "bool" if self.out.get("typedef") == "o3d_bool"
                                                         else "int", "double*": "double"}[self.out["type"]]

    def default_name(self, handle):
        """o3d_visualizer_view_get_field_of_view -> field_of_view: without the handle's prefix, `view_`, `get_`."""
        name = self.c[len(handle) - 1:]  # o3d_visualizer_t -> o3d_visualizer_
        return re.sub(r"^(view_)?(get_)?", "", name)


def kind(p, groups, handles):
    t, td = p["type"], p.get("typedef")
    if p["name"] in FIXED:
        return "fixed"
    if td == "o3d_bool":
        return "bool"
    if td in groups:
        return "enum"
    if t in ("int32_t", "double"):
        return t
    if t == "const char*":
        return "path" if p["name"] == "path" or p["name"].endswith("_path") else "string"
    if t == "const double*" and p["array"]:
        return "array"
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
