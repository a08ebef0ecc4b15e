#!/usr/bin/env python3
"""Binding-coverage check: every public o3d_* function must be reachable from every language.

For each function declared in capi/include/o3d/*.h this checks that its name is called from the
hand-written source of the C++ wrapper, the Python extension, the C# and Java layers and the safe
Rust crate. With --lib it also checks that the shared library exports exactly the declared functions.
Exit status 1 lists what is missing.
"""
import argparse
import pathlib
import re
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from list_capi_functions import ROOT, declarations  # noqa: E402

# Hand-written sources per language (generated SWIG output is excluded on purpose).
LANGUAGES = {
    "C++ wrapper": ["bindings/cpp/include/**/*.hpp"],
    "Python": ["bindings/python/src/**/*.cpp", "bindings/python/src/**/*.h", "bindings/python/o3d/**/*.py"],
    "C#": ["bindings/csharp/**/*.cs"],
    "Java": ["bindings/java/src/main/**/*.java"],
    "Rust": ["bindings/rust/o3d/src/**/*.rs"],
}
EXCLUDE = re.compile(r"(/gen/|/generated/|/target/|/tests?/|Test\.cs$|Tests?\.java$)")


def sources(patterns):
    text = []
    for pattern in patterns:
        for path in sorted(ROOT.glob(pattern)):
            rel = "/" + str(path.relative_to(ROOT))
            if path.is_file() and not EXCLUDE.search(rel):
                text.append(path.read_text(errors="replace"))
    return "\n".join(text)


def exported_symbols(lib):
    out = subprocess.run(["nm", "-D", "--defined-only", lib], check=True, capture_output=True, text=True).stdout
    return {line.split()[-1].split("@")[0] for line in out.splitlines() if line.split()[1:2] == ["T"]}


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--lib", help="path of libo3d.so to compare exports against the headers")
    args = parser.parse_args()

    names = sorted({name for name, *_ in declarations()})
    problems = []
    if args.lib:
        exported = exported_symbols(args.lib)
        for name in sorted(exported - set(names)):
            problems.append(f"exported but not declared in a public header: {name}")
        for name in sorted(set(names) - exported):
            problems.append(f"declared but not exported by {args.lib}: {name}")

    for language, patterns in LANGUAGES.items():
        text = sources(patterns)
        if not text:
            problems.append(f"{language}: no sources found ({', '.join(patterns)})")
            continue
        missing = [n for n in names if not re.search(r"\b" + re.escape(n) + r"\b", text)]
        for n in missing:
            problems.append(f"{language}: {n} is not reachable")
        print(f"{language}: {len(names) - len(missing)}/{len(names)} functions reachable")

    if problems:
        print("\n".join(problems))
        print(f"binding coverage: {len(problems)} problem(s)")
        return 1
    print(f"binding coverage: all {len(names)} functions reachable from every language")
    return 0


if __name__ == "__main__":
    sys.exit(main())
