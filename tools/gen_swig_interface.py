#!/usr/bin/env python3
"""Emit the mechanical part of the SWIG interface (C# and Java) from tools/capi_model.py's model.

    python3 tools/gen_swig_interface.py -o build/bindings/swig/o3d_generated.i

Run by CMake at build time (bindings/swig/CMakeLists.txt); the output is never committed.
The hand-written bindings/swig/o3d.i includes it and holds the typemaps it relies on:
  o3dx_in_f64 / _f32 / _i32 / _i64 / _u8   managed array in (pointer + length, pinned or copied once)
  o3dx_out_f64 / _i32 / _i64 / _u8        managed array out (one copy; `owned` buffers are freed)
  O3DX_CHECK(call)                        a failed status jumps to `fail:`; %exception raises it
Rules (per C function `o3d_<noun>_<verb>`, noun = an opaque handle or a value struct):
  * outputs come first (docs/conventions.md): `T** out` -> returned object (%newobject), scalar out ->
    return value (`_is_`/`has_` int32 -> bool), `double out[N]` -> returned array, copy-out triples
    (out, capacity, out_n) -> returned array sized by array_shape, a count query, or an upper bound
    (CAPACITY below; a function with side effects or real cost is never called twice); several
    outputs -> a generated result class with one getter per output (a view function's: `<Noun><Verb>`,
    e.g. SearchResultView); value-struct outputs are filled by their `*_init` first (struct_size set);
  * the first input of the noun's type -> a method of the noun's class, otherwise a static method;
    functions of no noun -> static methods of the module class `Library`;
  * `<x>_f32` becomes a float[] overload of `<x>`; `o3d_<noun>_create(T** out)` the constructor;
    `_destroy` the destructor; `*_init` fills a struct's defaults in its constructor;
  * array inputs followed by a count lose the count (length / row width, checked); so does an array of
    handles `const o3d_<x>_t* const* name, size_t num_name`, which becomes an array of <x>'s proxies
    (o3dx_handles_<x>: O3DX_HANDLES_TYPE in o3d.i, O3DX_HANDLES_IN in each language's .i).
"""
import argparse
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import capi_model  # noqa: E402

CLASS_NAMES = {  # C type -> class name (default: CamelCase of the noun)
    "o3d_pointcloud_t": "PointCloud", "o3d_trianglemesh_t": "TriangleMesh", "o3d_kdtree_t": "KDTreeFlann",
    "o3d_lineset_t": "LineSet", "o3d_voxelgrid_t": "VoxelGrid", "o3d_rgbd_image_t": "RGBDImage", "o3d_tsdf_volume_t": "TSDFVolume",
    "o3d_obb_t": "OrientedBoundingBox", "o3d_pinhole_intrinsic_t": "PinholeCameraIntrinsic",
    "o3d_camera_trajectory_t": "PinholeCameraTrajectory", "o3d_icp_options_t": "IcpOptions",
    "o3d_fgr_options_t": "FgrOptions", "o3d_rgbd_options_t": "RgbdOptions", "o3d_tetramesh_t": "TetraMesh",
    "o3d_obe_t": "OrientedBoundingEllipsoid", "o3d_halfedgemesh_t": "HalfEdgeTriangleMesh",
}
# Callbacks are hand-written (o3d.i). Views (`T** out_data` + row counts) become o3dx_view results: a
# borrowed address, rows and bytes (C#: struct View; Java: a direct ByteBuffer), valid until the owner changes.
SKIP = re.compile(r"^o3d_set_log_callback$")
VIEW = re.compile(r"(^|_)view$")
# Rows of view outputs without a count output.
VIEW_ROWS = {"out_offsets": "o3dx_search_count($self, 0)", "out_indices": "o3dx_search_count($self, 1)",
             "out_distances2": "o3dx_search_count($self, 1)"}
# Copy-out capacity (in rows) per function: C expression over the inputs, "query" (a NULL call that
# only counts: allowed for cheap, side-effect-free getters), or "shape" (array_shape of `which`).
PC_SIZE = "o3dx_count(o3d_pointcloud_size, {0})"
CAPACITY = {
    "o3d_obb_get_point_indices_within": "xyz.n / 3",
    "o3d_buffer_get_data": "query",
    "o3d_correspondences_from_features": "o3dx_count(o3d_feature_num, source)",
    "o3d_search_result_get_offsets": "o3dx_search_count(result, 0)",
    "o3d_search_result_get_indices": "o3dx_search_count(result, 1)",
    "o3d_search_result_get_distances2": "o3dx_search_count(result, 1)",
    "o3d_octree_locate_leaf_node": "query",
    "o3d_index_lists_get_offsets": "query", "o3d_index_lists_get_values": "query",
    **{f"o3d_trianglemesh_{c}": "query" for c in (
        "get_non_manifold_edges", "get_non_manifold_vertices", "get_self_intersecting_triangles")},
    **{f"o3d_halfedgemesh_{c}": "query" for c in (
        "get_array", "get_triangles", "get_half_edges", "boundary_half_edges_from_vertex",
        "boundary_vertices_from_vertex")},
    "o3d_pointcloud_estimate_point_covariances": PC_SIZE.format("pc"),
    "o3d_pointcloud_detect_planar_patches": "query",
    "o3d_pointcloud_compute_nearest_neighbor_distance": PC_SIZE.format("pc"),
    "o3d_pointcloud_compute_point_cloud_distance": PC_SIZE.format("source"),
    "o3d_pointcloud_remove_statistical_outlier": PC_SIZE.format("pc"),
    "o3d_pointcloud_remove_radius_outlier": PC_SIZE.format("pc"),
    "o3d_pointcloud_segment_plane": PC_SIZE.format("pc"),
    "o3d_pointcloud_cluster_dbscan": PC_SIZE.format("pc"),
    "o3d_pointcloud_compute_mahalanobis_distance": PC_SIZE.format("pc"),
    "o3d_pointcloud_compute_convex_hull": PC_SIZE.format("pc"),
    "o3d_pointcloud_hidden_point_removal": PC_SIZE.format("pc"),
    "o3d_pointcloud_compute_iss_keypoints": PC_SIZE.format("pc"),
    "o3d_tetramesh_create_from_point_cloud": PC_SIZE.format("pc"),
    "o3d_registration_result_get_correspondence_set": "query",
    "o3d_trianglemesh_cluster_connected_triangles": "o3dx_count(o3d_trianglemesh_num_triangles, mesh)",
    "o3d_trianglemesh_compute_convex_hull": "o3dx_count(o3d_trianglemesh_num_vertices, mesh)",
    "o3d_voxelgrid_check_if_included": "xyz.n / 3",
    "o3d_visualizer_get_picked_points": "query",
    "o3d_selection_polygon_volume_get_bounding_polygon": "query",
    "o3d_tsdf_volume_extract_volume_tsdf": "query", "o3d_tsdf_volume_extract_volume_color": "query",
    "o3d_selection_polygon_volume_crop_in_polygon": PC_SIZE.format("pc"),
}
# o3d_buffer_t outputs holding UTF-8 text: returned as a string (o3dx_text: copied once, then freed).
TEXT = {"o3d_visualizer_get_view_status"}
# Array inputs whose length two other inputs give.
LENGTH = {"o3d_feature_create_from_data": "dimension * num", "o3d_kdtree_create_from_points_xd": "dimension * n"}
PAIRS = {"o3d_correspondences_from_features", "o3d_registration_result_get_correspondence_set"}
# Values per row of a copy-out array whose count is in rows (default 1; PAIRS: 2).
OUT_WIDTH = {"o3d_selection_polygon_volume_get_bounding_polygon": 3,
             "o3d_trianglemesh_get_non_manifold_edges": 2, "o3d_trianglemesh_get_self_intersecting_triangles": 2,
             "o3d_halfedgemesh_get_array": 3, "o3d_halfedgemesh_get_triangles": 3, "o3d_halfedgemesh_get_half_edges": 5,
             "o3d_pointcloud_estimate_point_covariances": 9, "o3d_pointcloud_detect_planar_patches": 15, "o3d_tsdf_volume_extract_volume_tsdf": 2,
             "o3d_tsdf_volume_extract_volume_color": 3}
# Row width of array inputs followed by a count (default 1); `data` of set_array comes from array_shape.
ROW_WIDTH = {"xyz": 3, "constraint_vertex_positions": 3, "queries": 3, "corres": 2, "pairs": 2, "corners": 3}
# int32 outputs that are flags (besides an `_is_` / `has_` function's).
BOOL_OUTS = {"out_found", "out_open", "out_success"}
SCALARS = {"size_t": "size_t", "int32_t": "int32_t", "double": "double", "int64_t": "int64_t", "uint64_t": "uint64_t"}
ELEM = {"double": "f64", "float": "f32", "int32_t": "i32", "int64_t": "i64", "uint8_t": "u8"}


def camel(s):
    return "".join(w[:1].upper() + w[1:] for w in s.split("_"))


class Gen:
    def __init__(self, model):
        self.m = model
        self.handles = {h["name"] for h in model["handles"]}
        self.structs = {s["name"]: s for s in model["structs"]}
        self.nouns = sorted((n[4:-2] for n in self.handles | set(self.structs)), key=len, reverse=True)
        self.fnames = {f["name"] for f in model["functions"]}
        self.inits = {f["name"]: f for f in model["functions"] if f["name"].endswith("_init")}
        self.out, self.view_results = [], set()

    def cls(self, ctype):
        return CLASS_NAMES.get(ctype, camel(ctype[4:-2]))

    # ---- parameters ------------------------------------------------------------------------------
    def split(self, f):
        """(outputs, copy-out groups, inputs) of a function, outputs first as the convention says."""
        ps, outs, i = f["params"], [], 0
        while i < len(ps):
            p, t = ps[i], ps[i]["type"]
            if t.startswith("const") or t in SCALARS or t == "const char*":
                break
            base = t.rstrip("*")
            if t.endswith("**") or (base in self.structs and not t.startswith("const")) or \
                    (base in SCALARS and t.count("*") == 1) or base in ELEM:
                if base in self.handles and t.count("*") == 1:
                    break  # `H* self`: an input
                outs.append(p)
                i += 1
                continue
            break
        # copy-out group: array outputs followed by `size_t capacity` and size_t* counts
        names = [p["name"] for p in ps]
        if "capacity" in names:
            c = names.index("capacity")
            j = c + 1
            while j < len(ps) and ps[j]["type"] == "size_t*":
                j += 1
            is_arr = lambda p: p in outs and p["type"].rstrip("*") in ELEM and not p["array"] and not p["type"].endswith("**")
            k = c  # the run of array outputs right before `capacity` (earlier int32_t* are scalar outputs)
            while k > 0 and is_arr(ps[k - 1]):
                k -= 1
            arrays = ps[k:c]
            counts = ps[c + 1:j]
            outs = [p for p in outs if p not in arrays] + [p for p in ps[c + 1:j] if False]
            return outs, (arrays, counts), ps[j:], ps[:c]
        return outs, None, ps[i:], None

    def noun_of(self, name):
        for n in self.nouns:
            if name.startswith(f"o3d_{n}_"):
                return n, name[len(n) + 5:]
        return None, name[4:]

    # ---- one function -> one wrapper -----------------------------------------------------------
    def wrapper(self, f, noun, verb):
        outs, group, ins, pre_cap = self.split(f)
        ctype = f"o3d_{noun}_t" if noun else None
        ps = f["params"]
        is_method = bool(ins) and ctype and ins[0]["type"].rstrip("*").replace("const ", "") == ctype
        decl, body, call, post = [], [], [], []
        arrays_in = {}
        for k, p in enumerate(ins):
            t, n = p["type"], p["name"]
            if is_method and k == 0:
                call_args = None
                continue
            base = t.replace("const ", "").rstrip("*")
            if t.startswith("const") and base in ELEM and t.count("*") == 1:
                decl.append(f"o3dx_in_{ELEM[base]} {n}")
                arrays_in[n] = p
                if p["array"]:
                    body.append(f"if ({n}.p && {n}.n != {p['array']}) {{ o3dx_fail_len(\"{n}\", {p['array']}); goto fail; }}")
                elif f["name"] in LENGTH:
                    body.append(f"if ({n}.n != {LENGTH[f['name']]}) {{ o3dx_fail_len(\"{n}\", {LENGTH[f['name']]}); goto fail; }}")
            elif base in self.structs and t.startswith("const") and ins[k + 1:k + 2] and \
                    ins[k + 1]["type"] == "size_t" and ins[k + 1]["name"].startswith("num_"):
                decl.append(f"o3dx_in_{base} {n}")
                arrays_in[n] = p
            elif self.handle_array(ins, k):
                decl.append(f"o3dx_handles_{self.handle_array(ins, k)} {n}")
                arrays_in[n] = p
            elif self.is_count(ins, k, arrays_in):
                continue
            else:
                decl.append(f"{t.replace('*', ' *')} {n}")
        # argument list of the C call
        args = []
        for k, p in enumerate(ps):
            n, t = p["name"], p["type"]
            if p in ins:
                idx = ins.index(p)
                if is_method and idx == 0:
                    args.append("$self")
                elif n in arrays_in:
                    args.append(f"{n}.p")
                elif self.is_count(ins, idx, arrays_in):
                    a = ins[idx - 1]
                    width = self.row_width(f, a, ins)
                    if width == 1:
                        args.append(f"{a['name']}.n")
                    else:
                        body.append(f"if ({a['name']}.n % {width}) {{ o3dx_fail_len(\"{a['name']}\", {width}); goto fail; }}")
                        args.append(f"(size_t)({a['name']}.n / {width})")
                else:
                    args.append(n)
            else:
                args.append(None)  # outputs, filled below
        # outputs
        results = []  # (field name, C type of the field, expr to pass, kind)
        for p in outs:
            t, n = p["type"], p["name"]
            base = t.rstrip("*")
            field = self.field_name(n, base)
            if t.endswith("**"):
                text = f["name"] in TEXT
                results.append((field, "o3dx_text" if text else f"{base} *", "text" if text else "handle", p, base))
            elif base in self.structs:
                results.append((field, base, "struct", p, base))
            elif p["array"]:
                results.append((field, f"o3dx_out_{ELEM[base]}", "fixed", p, base))
            else:
                kind = "bool" if base == "int32_t" and re.search(r"(^|_)(is|has)_", verb) or n in BOOL_OUTS else "scalar"
                results.append((field, "bool" if kind == "bool" else base, kind, p, base))
        if group:
            arrays, counts = group
            for a in arrays:
                base = a["type"].rstrip("*")
                results.append((self.field_name(a["name"], base), f"o3dx_out_{ELEM[base]}", "copy", a, base))
        # locals and the call
        lines = []
        for field, ft, kind, p, base in results:
            if kind in ("handle", "text"):
                lines.append(f"{base} *{field} = NULL;")
                args[ps.index(p)] = f"&{field}"
            elif kind == "struct":  # struct_size set, defaults from *_init where it takes no more than the size
                lines.append(f"{base} {field}; memset(&{field}, 0, sizeof {field});")
                init = f"o3d_{base[4:-2]}_init"
                if any(x["name"] == "struct_size" for x in self.structs[base]["fields"]):
                    if init in self.inits and len(self.inits[init]["params"]) == 2:
                        lines.append(f"O3DX_CHECK({init}(&{field}, (uint32_t)sizeof {field}));")
                    else:
                        lines.append(f"{field}.struct_size = (uint32_t)sizeof {field};")
                args[ps.index(p)] = f"&{field}"
            elif kind == "fixed":
                lines.append(f"o3dx_out_{ELEM[base]} {field} = o3dx_alloc_{ELEM[base]}({p['array']});")
                args[ps.index(p)] = f"{field}.p"
            elif kind in ("scalar", "bool"):
                lines.append(f"{base} {field}_ = 0;")
                args[ps.index(p)] = f"&{field}_"
            else:  # copy
                lines.append(f"o3dx_out_{ELEM[base]} {field} = {{0, 0, 1}};")
        if group:
            arrays, counts = group
            width = OUT_WIDTH.get(f["name"], 2 if f["name"] in PAIRS else 1)
            cap = CAPACITY.get(f["name"])
            shaped = verb in ("get_array", "get_index_array") and f"o3d_{noun}_array_shape" in self.fnames
            if shaped:
                lines.append(f"size_t rows_ = 0, cols_ = 0;")
                body.append(f"O3DX_CHECK(o3d_{noun}_array_shape(&rows_, &cols_, $self, which));")
                cap, width = "rows_", "cols_"
            elif cap is None:
                raise SystemExit(f"gen_swig_interface: no CAPACITY rule for {f['name']} (add one)")
            for c in counts:
                lines.append(f"size_t {c['name']}_ = 0;")
                args[ps.index(c)] = f"&{c['name']}_"
            args[ps.index(next(p for p in ps if p["name"] == "capacity"))] = "cap_"
            lines.append("size_t cap_ = 0;")
            if cap == "query":
                qargs = [("NULL" if p in arrays else ("0" if p["name"] == "capacity" else x)) for p, x in zip(ps, args)]
                body.append(f"O3DX_CHECK({f['name']}({', '.join(qargs)}));")
                cap = f"{counts[0]['name']}_"
            if is_method:
                cap = re.sub(r"\b%s\b" % ins[0]["name"], "$self", cap)
            body.append(f"cap_ = {cap};")
            for a in arrays:
                field = self.field_name(a["name"], a["type"].rstrip("*"))
                e = ELEM[a["type"].rstrip("*")]
                body.append(f"{field} = o3dx_alloc_{e}(cap_ * {width});")
                body.append("if (o3dx_err) goto fail;")
                args[ps.index(a)] = f"{field}.p"
        body.append(f"O3DX_CHECK({f['name']}({', '.join(args)}));")
        if group:
            arrays, counts = group
            shaped = verb in ("get_array", "get_index_array") and f"o3d_{noun}_array_shape" in self.fnames
            width = ("cols_" if shaped
                     else OUT_WIDTH.get(f["name"], 2 if f["name"] in PAIRS else 1))
            for k, a in enumerate(arrays):
                field = self.field_name(a["name"], a["type"].rstrip("*"))
                cnt = counts[0] if k == 0 else counts[-1]
                body.append(f"{field}.n = {cnt['name']}_ * {width};")
        return decl, lines, body, results, is_method

    def handle_array(self, ins, k):
        """The handle type of an array of handles `const o3d_X_t* const* name, size_t num_name`, else None."""
        m = re.fullmatch(r"const (o3d_\w+_t)\* const\*", ins[k]["type"])
        nxt = ins[k + 1] if k + 1 < len(ins) else None
        if m and m.group(1) in self.handles and nxt and nxt["type"] == "size_t" and nxt["name"] == "num_" + ins[k]["name"]:
            return m.group(1)
        return None

    def handle_arrays(self):
        """Every handle type some function takes an array of."""
        return sorted({self.handle_array(f["params"], k) for f in self.m["functions"] for k in range(len(f["params"]))} - {None})

    @staticmethod
    def is_count(ins, k, arrays_in):
        """A size_t right after an array input that counts its rows (hidden: the length gives it)."""
        return ins[k]["type"] == "size_t" and k > 0 and ins[k - 1]["name"] in arrays_in and \
            ins[k]["name"] != "dimension"

    def row_width(self, f, a, ins):
        names = [p["name"] for p in ins]
        if "dimension" in names and a["name"] in ("data", "queries"):
            return "dimension"
        if a["name"] == "data" and "which" in names:
            return "o3dx_cols(o3d_%s_array_shape, $self, which)" % self.noun_of(f["name"])[0]
        return ROW_WIDTH.get(a["name"], 1)

    @staticmethod
    def field_name(n, base):
        n = re.sub(r"^out_?", "", n)
        if not n:
            n = {"o3d_trianglemesh_t": "mesh", "o3d_pointcloud_t": "cloud"}.get(base, "value")
        return n

    # ---- views: borrowed memory -------------------------------------------------------------------
    def emit_view(self, f, noun, verb):
        ps = f["params"]
        ptrs = [p for p in ps if p["type"].endswith("**")]
        counts = [p for p in ps if p["type"] == "size_t*"]
        ins = [p for p in ps if p not in ptrs and p not in counts]
        mut = "mutable" in verb
        kind = "o3dx_mview" if mut else "o3dx_view"
        args, lines, body, fields = [], [], [], []
        which = any(p["name"] == "which" for p in ins)
        for p in ps:
            if p in ptrs:
                fld = self.field_name(p["name"], "")
                lines.append(f"{p['type'][:-1].replace('*', ' *')}{fld}_ = NULL;")
                args.append(f"&{fld}_")
            elif p in counts:
                lines.append(f"size_t {p['name']}_ = 0;")
                args.append(f"&{p['name']}_")
            else:
                args.append("$self" if p is ins[0] else p["name"])
        body.append(f"O3DX_CHECK({f['name']}({', '.join(args)}));")
        for p in ptrs:
            fld = self.field_name(p["name"], "")
            rows = f"{counts[0]['name']}_" if counts else VIEW_ROWS[p["name"]]
            cols = f"o3dx_cols(o3d_{noun}_array_shape, $self, which)" if which else "1"
            body.append(f"{fld}.p = (void *){fld}_; {fld}.rows = {rows}; {fld}.bytes = {fld}.rows * {cols} * sizeof *{fld}_;")
            fields.append(fld)
        decl = ", ".join(f"{p['type'].replace('*', ' *')} {p['name']}" for p in ins[1:])
        code = []
        if len(fields) == 1:
            code.append(f"  {kind} {verb}({decl}) {{")
            code.append(f"    {kind} {fields[0]} = {{0, 0, 0}};")
            result_type, ret = None, fields[0]
        else:
            name = f"o3dx_{f['name'][4:]}_result"
            code.append(f"  {name} *{verb}({decl}) {{")
            code.append(f"    {kind} {' , '.join(x + ' = {0, 0, 0}' for x in fields)};")
            result_type = (name, [(x, kind, "view", None, None) for x in fields])
            self.view_results.add(name)  # named after its function: SearchResultView
            ret = None
        code += [f"    {l}" for l in lines] + [f"    {b}" for b in body] + ["  fail:"]
        if ret:
            code.append(f"    return {ret};")
        else:
            code.append(f"    {{ {name} *r_ = ({name} *)calloc(1, sizeof *r_);")
            code += [f"      if (r_) r_->{x} = {x};" for x in fields]
            code.append("      return r_; }")
        code.append("  }")
        return noun, verb, ret is None, "\n".join(code), result_type

    # ---- emit ------------------------------------------------------------------------------------
    def skip_reason(self, f):
        """Why a function gets no generated wrapper (None: it gets one)."""
        noun, verb = self.noun_of(f["name"])
        if verb == "destroy":
            return "destructor"
        if verb == "init" or f["name"].endswith("_init"):
            return "constructor"
        if SKIP.search(f["name"]) or any("callback" in p["type"] for p in f["params"]):
            return "hand-written"
        return None

    def emit_function(self, f):
        noun, verb = self.noun_of(f["name"])
        if self.skip_reason(f):
            return None
        if VIEW.search(verb) and any(p["type"].endswith("**") for p in f["params"]):  # not view_get_field_of_view
            return self.emit_view(f, noun, verb)
        decl, lines, body, results, is_method = self.wrapper(f, noun, verb)
        method = verb[:-4] if verb.endswith("_f32") else verb
        if f["ret"] != "o3d_status" or f["name"] == "o3d_last_error_code":  # plain getters (version, verbosity, status_string)
            args = ", ".join(p["name"] for p in f["params"])
            return noun, method, False, f"{f['ret'].replace('*', ' *')} {method}({', '.join(decl)}) {{ return {f['name']}({args}); }}", None
        ctype = f"o3d_{noun}_t" if noun else None
        if noun and verb == "create" and not decl and len(results) == 1:
            sig = f"{ctype}()"
            ret = f"{ctype} *"
            results_t = None
        newobj = False
        if not results:
            ret, tail = "void", ""
        elif len(results) == 1:
            field, ft, kind, p, base = results[0]
            ret = {"scalar": base, "bool": "bool"}.get(kind, ft)
            tail = f"{field}_" if kind in ("scalar", "bool") else f"o3dx_text_of({field})" if kind == "text" else field
            newobj = kind == "handle"
        else:
            ret = f"o3dx_{f['name'][4:]}_result"
            tail = None
        code = []
        if noun and verb == "create" and not decl and len(results) == 1:
            head = f"{ctype}()"
        else:
            head = ("" if is_method or not noun else "static ") + f"{ret}{' *' if tail is None else ''} {method}({', '.join(decl)})"
        code.append(f"  {head} {{")
        code += [f"    {l}" for l in lines]
        code += [f"    {b}" for b in body]
        code.append("  fail:")
        cleanup = []
        for field, ft, kind, p, base in results:
            if kind == "handle":
                cleanup.append(f"if (o3dx_err) {{ {base[:-2]}_destroy({field}); {field} = NULL; }}")
            elif kind in ("fixed", "copy"):
                cleanup.append(f"if (o3dx_err) {{ free({field}.p); {field}.p = NULL; {field}.n = 0; }}")
        code += [f"    {c}" for c in cleanup]
        result_type = None
        if tail is not None:
            code.append(f"    return {tail};" if ret != "void" else "    return;")
        else:
            fields = "; ".join(f"{ft} {fld}" for fld, ft, k, p, b in results)
            code.append(f"    {{ {ret} *r_ = ({ret} *)calloc(1, sizeof *r_);")
            for fld, ft, k, p, b in results:
                code.append(f"      r_->{fld} = {fld}{'_' if k in ('scalar', 'bool') else ''};")
            code.append("      return r_; }")
            result_type = (ret, results)
        code.append("  }")
        text = "\n".join(code)
        if ret != "void" and tail is None:
            newobj = True
        return noun, method, newobj, text, result_type

    def emit(self):
        o = self.out
        o.append("/* generated by tools/gen_swig_interface.py from capi/include/o3d/*.h: do not edit */")
        classes, module, results = {}, [], []
        # arrays of handles: the C pair (pointer + count) and the language's array-of-proxies typemaps (o3d.i)
        for h in self.handle_arrays():
            o.append(f"%{{\nO3DX_HANDLES_TYPE({h})\n%}}")
            o.append(f"O3DX_HANDLES_IN({h}, {self.cls(h)})")
        for f in self.m["functions"]:
            r = self.emit_function(f)
            if r is None:
                continue
            noun, method, newobj, text, result_type = r
            if result_type:
                results.append(result_type)
            ctype = f"o3d_{noun}_t" if noun else None
            if noun:
                classes.setdefault(ctype, []).append((method, newobj, text))
            else:
                module.append((method, newobj, text))
        # result classes (several outputs)
        for name, fields in results:
            o.append("%{")
            o.append(f"typedef struct {name} {{ " + " ".join(
                f"{ft} {fld};" for fld, ft, k, p, b in fields) + f" }} {name};")
            o.append("%}")
            o.append(f"%nodefaultctor {name};")
            verb = self.noun_of("o3d_" + name[5:-7])[1]
            clash = sum(1 for n2, _ in results if self.noun_of("o3d_" + n2[5:-7])[1] == verb) > 1
            if name in self.view_results:
                o.append(f"%rename({camel(name[5:-7])}) {name};")
            else:
                o.append(f"%rename({camel(name[5:-7] if clash else verb)}Result) {name};")
            o.append(f"typedef struct {{}} {name};")
            o.append(f"%extend {name} {{")
            frees = []
            for fld, ft, k, p, b in fields:
                if k == "handle":
                    o.append(f"  %newobject {fld};")
                    o.append(f"  {ft}{fld}() {{ {ft}h = $self->{fld}; $self->{fld} = NULL; if (!h) o3dx_fail_taken(\"{fld}\"); return h; }}")
                    frees.append(f"{b[:-2]}_destroy($self->{fld});")
                elif k in ("fixed", "copy"):
                    o.append(f"  {ft} {fld}() {{ {ft} v = $self->{fld}; v.owned = 0; return v; }}")
                    frees.append(f"free($self->{fld}.p);")
                else:
                    o.append(f"  {ft} {fld}() {{ return $self->{fld}; }}")
            o.append(f"  ~{name}() {{ {' '.join(frees)} free($self); }}")
            o.append("}")
        for s in self.m["structs"]:
            name = s["name"]
            o.append(f"%rename({self.cls(name)}) {name};")
            init = f"o3d_{name[4:-2]}_init"
            fl = []
            for fld in s["fields"]:  # what SWIG sees: the plain fields (the others have methods)
                if not (fld["name"] in ("struct_size", "progress", "user_data") or fld["array"]):
                    fl.append(f"{fld['type'].replace('*', ' *')} {fld['name']};")
            if any(x["name"] == "progress" for x in s["fields"]):
                o.append(f"O3DX_PROGRESS({name})")  # callback typemaps: before the class
            o.append(f"typedef struct {{ {' '.join(fl)} }} {name};")
            o.append(f"%extend {name} {{")
            if init in self.fnames:
                extra = [p for p in next(f for f in self.m["functions"] if f["name"] == init)["params"][2:]]
                decl = ", ".join(f"{p['type']} {p['name']}" for p in extra)
                args = "".join(f", {p['name']}" for p in extra)
                o.append(f"  {name}({decl}) {{ {name} *s = ({name} *)calloc(1, sizeof *s); if (s) {init}(s, (uint32_t)sizeof *s{args}); return s; }}")
            else:
                o.append(f"  {name}() {{ return ({name} *)calloc(1, sizeof({name})); }}")
            o.append(f"  ~{name}() {{ o3dx_struct_free_{'progress' if any(x['name'] == 'progress' for x in s['fields']) else 'plain'}($self, $self); }}")
            for fld in s["fields"]:
                if fld["array"]:
                    e, n, k = ELEM[fld["type"][:-1]], fld["name"], fld["array"]
                    o.append(f"  o3dx_out_{e} get_{n}() {{ o3dx_out_{e} v = {{$self->{n}, {k}, 0}}; return v; }}")
                    o.append(f"  void set_{n}(o3dx_in_{e} v) {{ if (!v.p || v.n != {k}) o3dx_fail_len(\"{n}\", {k}); else memcpy($self->{n}, v.p, sizeof $self->{n}); }}")
            for method, newobj, text in classes.pop(name, []):
                if newobj:
                    o.append(f"  %newobject {method};")
                o.append(text)
            o.append("}")
        for h in sorted(self.handles):
            noun = h[4:-2]
            o.append(f"%rename({self.cls(h)}) {h};")
            o.append(f"%nodefaultctor {h};")
            o.append(f"typedef struct {{}} {h};")
            o.append(f"%extend {h} {{")
            o.append(f"  ~{h}() {{ o3d_{noun}_destroy($self); }}")
            for method, newobj, text in classes.pop(h, []):
                if text.lstrip().startswith(f"{h}()"):
                    o.append(text.replace(f"  {h}() {{", f"  {h}() {{", 1))
                    continue
                if newobj:
                    o.append(f"  %newobject {method};")
                o.append(text)
            o.append("}")
        assert not classes, classes
        o.append("%inline %{")
        o.append("%}")
        for method, newobj, text in module:
            if newobj:
                o.append(f"%newobject {method};")
            o.append("%inline %{\nstatic " + text.strip() + "\n%}")
        for c in self.m["constants"]:
            o.append(f"%constant int {c['name'][4:]} = {c['value']};  /* {c['name']} */")
        return "\n".join(o) + "\n"


def list_skipped(gen):
    """C functions neither generated, nor used as a constructor/destructor, nor wrapped by o3d.i or by
    both language .i files (one per line; the lead's coverage check wants this empty)."""
    root = pathlib.Path(__file__).resolve().parent.parent / "bindings"
    shared = (root / "swig" / "o3d.i").read_text()
    langs = [(root / "csharp" / "o3d_csharp.i").read_text(), (root / "java" / "o3d_java.i").read_text()]
    for f in gen.m["functions"]:
        why = gen.skip_reason(f)
        name = re.compile(r"\b%s\b" % f["name"])
        if why == "hand-written" and (name.search(shared) or all(name.search(t) for t in langs)):
            continue
        if why == "hand-written":
            print(f["name"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("-o", "--output", type=pathlib.Path)
    parser.add_argument("--include-dir", type=pathlib.Path, default=capi_model.INCLUDE_DIR)
    parser.add_argument("--list-skipped", action="store_true", help="print the C functions without a wrapper")
    args = parser.parse_args()
    gen = Gen(capi_model.load(args.include_dir))
    if args.list_skipped:
        return list_skipped(gen)
    text = gen.emit()
    capi_model.write_output(text, args.output)


if __name__ == "__main__":
    main()
