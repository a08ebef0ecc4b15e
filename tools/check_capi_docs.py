#!/usr/bin/env python3
"""Check that every C API function is documented completely (docs/conventions.md).

For every `O3D_API` function in capi/include/o3d/*.h, the Doxygen comment (`/** ... */` or `///` lines)
right above the declaration must:
  (a) exist;
  (b) document every parameter with `@param <name>` (several on one line: `@param a,b ...`), and name no
      parameter the function does not have;
  (c) state the errors: a status-returning function has an `@return` naming the O3D_ERROR_* codes it can
      return (each must exist) or says "never fails", at least O3D_ERROR_INVALID_ARGUMENT when it takes a pointer
      (other than `void* user_data`),
      O3D_ERROR_BUFFER_TOO_SMALL when it takes a `capacity`, O3D_ERROR_CANCELLED when it takes a progress
      callback (directly or in an options struct); a function returning a value says "never fails" in its
      `@return`; a void function (destroy) needs no `@return`;
  (d) state thread-safety: a `Threads:` line;
  (e) when it writes a handle (`T** out`), a borrowed view (`const T** out_data`, `T** out_data`) or
      returns a string, carry an `Ownership:` note.

    python3 tools/check_capi_docs.py            # exit 1 and one line per gap, else exit 0
    python3 tools/check_capi_docs.py --quiet    # only the summary line

No dependencies beyond the standard library; runs in well under a second.
"""
import argparse
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import capi_model  # noqa: E402

_BLOCK = re.compile(r"/\*.*?\*/", re.S)
_LINE = re.compile(r"//[^\n]*")
_PARAM_TAG = re.compile(r"[@\\]param(?:\[[^\]]*\])?\s+(\w+(?:\s*,\s*\w+)*)")
_RETURN_TAG = re.compile(
    r"[@\\]returns?\b(.*?)(?=[@\\](?:param|return|returns|see|brief|note|warning|pre|post)\b|$)", re.S)
_ERROR = re.compile(r"\bO3D_ERROR_[A-Z_]+\b")


def _mask_comments(text):
    """The text with every comment replaced by spaces (newlines kept), so offsets still match."""
    def blank(m):
        return re.sub(r"[^\n]", " ", m.group(0))
    return _LINE.sub(blank, _BLOCK.sub(blank, text))


def _doc_comment_before(raw, pos):
    """The Doxygen comment ending right before offset `pos` (only whitespace between), or None."""
    head = raw[:pos].rstrip()
    if head.endswith("*/"):
        start = head.rfind("/*")
        if start < 0:
            return None
        block = head[start:]
        if not block.startswith("/**") or block.startswith("/**<") or block.startswith("/***"):
            return None
        body = block[3:-2]
        return "\n".join(re.sub(r"^\s*\*?\s?", "", line) for line in body.splitlines())
    lines = head.splitlines()
    doc = []
    while lines and lines[-1].lstrip().startswith("///") and not lines[-1].lstrip().startswith("///<"):
        doc.append(lines.pop().lstrip()[3:].strip())
    return "\n".join(reversed(doc)) if doc else None


def _progress_structs(model):
    """Names of options structs that carry a progress callback."""
    return {s["name"] for s in model["structs"]
            if any(f["type"] == "o3d_progress_callback" for f in s["fields"])}


def functions(include_dir=capi_model.INCLUDE_DIR):
    """(header, name, return type, params, doc comment or None) per O3D_API function, in header order."""
    for header in sorted(include_dir.glob("*.h")):
        raw = header.read_text()
        masked = _mask_comments(raw)
        for m in capi_model._PROTO.finditer(masked):
            line_start = masked.rfind("\n", 0, m.start()) + 1
            if masked[line_start:m.start()].strip():
                continue  # e.g. `#define O3D_API ...`
            ret, name, args = m.group(1), m.group(2), m.group(3)
            doc = _doc_comment_before(raw, m.start())
            yield header.name, name, " ".join(ret.split()), capi_model._params(args), doc


def check(include_dir=capi_model.INCLUDE_DIR):
    """A list of 'header: function: what is missing' strings."""
    model = capi_model.load(include_dir)
    with_progress = _progress_structs(model)
    known_codes = {c["name"] for c in model["constants"] if c["name"].startswith("O3D_ERROR_")}
    gaps = []
    count = 0
    for header, name, ret, params, doc in functions(include_dir):
        count += 1
        where = f"{header}: {name}"
        if doc is None:
            gaps.append(f"{where}: no Doxygen comment right above the declaration")
            continue
        missing = []
        # (b) parameters
        documented = set()
        for names in _PARAM_TAG.findall(doc):
            documented.update(n.strip() for n in names.split(","))
        pnames = [p["name"] for p in params]
        undocumented = [n for n in pnames if n not in documented]
        if undocumented:
            missing.append("@param " + ", ".join(undocumented))
        unknown = sorted(documented - set(pnames))
        if unknown:
            missing.append("@param names no such parameter: " + ", ".join(unknown))
        # (c) errors
        returns = " ".join(_RETURN_TAG.findall(doc))
        has_return = bool(re.search(r"[@\\]returns?\b", doc))
        if ret == "o3d_status":
            codes = set(_ERROR.findall(returns))
            if not has_return:
                missing.append("@return with the O3D_ERROR_* codes")
            elif not codes and "never fails" not in returns.lower():
                missing.append('@return names no O3D_ERROR_* code (nor says "never fails")')
            else:
                bad = sorted(codes - known_codes)
                if bad:
                    missing.append("@return names unknown codes: " + ", ".join(bad))
                needed = []
                takes_pointer = any("*" in p["type"] and p["name"] != "user_data" for p in params)
                if takes_pointer and "O3D_ERROR_INVALID_ARGUMENT" not in codes:
                    needed.append("O3D_ERROR_INVALID_ARGUMENT")
                if any(p["name"] == "capacity" for p in params) and "O3D_ERROR_BUFFER_TOO_SMALL" not in codes:
                    needed.append("O3D_ERROR_BUFFER_TOO_SMALL")
                takes_progress = any(p["type"] == "o3d_progress_callback" or
                                     p["type"].replace("const ", "").rstrip("*") in with_progress for p in params)
                if takes_progress and "O3D_ERROR_CANCELLED" not in codes:
                    needed.append("O3D_ERROR_CANCELLED")
                if needed:
                    missing.append("@return omits " + ", ".join(needed))
        elif ret != "void":
            if not has_return:
                missing.append("@return (the value; say it never fails)")
            elif "never fails" not in returns.lower() and not _ERROR.search(returns):
                missing.append('@return says neither "never fails" nor an O3D_ERROR_* code')
        # (d) threads
        if not re.search(r"^\s*(?:\*\*)?Threads:", doc, re.M):
            missing.append("a 'Threads:' line")
        # (e) ownership
        writes_pointer = any(p["type"].endswith("**") for p in params)
        returns_string = ret.replace(" ", "") in ("constchar*", "char*")
        if (writes_pointer or returns_string) and not re.search(r"Ownership:", doc):
            missing.append("an 'Ownership:' note (it writes a handle or view, or returns a string)")
        if missing:
            gaps.append(f"{where}: missing " + "; ".join(missing))
    return gaps, count


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--include-dir", type=pathlib.Path, default=capi_model.INCLUDE_DIR)
    parser.add_argument("--quiet", action="store_true", help="print only the summary")
    args = parser.parse_args()
    gaps, count = check(args.include_dir)
    if not args.quiet:
        for gap in gaps:
            print(gap)
    if gaps:
        print(f"check_capi_docs: {len(gaps)} of {count} functions documented incompletely", file=sys.stderr)
        return 1
    print(f"check_capi_docs: all {count} functions documented (params, errors, threads, ownership)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
