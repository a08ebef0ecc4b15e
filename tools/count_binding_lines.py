#!/usr/bin/env python3
"""Count hand-written binding code: lines of tracked files under bindings/ with the extensions
.h .hpp .cpp .py .pyi .cs .java .rs .i, leaving out test folders, C# *Test*.cs files, benches and files whose first
five lines mark them generated (`@generated`, "automatically generated", "auto-generated" or "do not edit": the
test of /work/shared/tools/count_binding_lines.sh, the measure of issue 10). Prints per language and the total.

    python3 tools/count_binding_lines.py [--files]
"""
import collections
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXTENSIONS = (".h", ".hpp", ".cpp", ".py", ".pyi", ".cs", ".java", ".rs", ".i")
TEST_DIR = re.compile(r"(^|/)(tests?|benches)/|Test[^/]*\.cs$")
# A mention of the word "generated" is not enough: only these markers say the file itself is generated.
GENERATED = re.compile(r"@generated|automatically generated|auto-generated|do not edit", re.I)


def counted_files():
    listed = subprocess.run(["git", "ls-files", "bindings"], cwd=ROOT, capture_output=True, text=True,
                            check=True).stdout.split()
    for rel in listed:
        path = ROOT / rel
        if not rel.endswith(EXTENSIONS) or TEST_DIR.search(rel) or not path.is_file():
            continue
        head = "".join(path.read_text(errors="replace").splitlines(keepends=True)[:5])
        if GENERATED.search(head):
            continue
        yield rel, sum(1 for _ in path.open(errors="replace"))


def main():
    per_language = collections.Counter()
    files = sorted(counted_files())
    for rel, lines in files:
        language = rel.split("/")[1]
        per_language["SWIG" if rel.endswith(".i") and language == "swig" else language] += lines
        if "--files" in sys.argv:
            print(f"{lines:6d} {rel}")
    for language, lines in sorted(per_language.items()):
        print(f"{language:8s} {lines:6d}")
    print(f"{'total':8s} {sum(per_language.values()):6d}")


if __name__ == "__main__":
    main()
