#!/usr/bin/env python3
"""Regenerate (or check) the generated sections of the docs from the example programs.

Usage: docs.py [--check] [--full] [--build DIR] [EXAMPLE ...]

Every example program (examples/NNN-name/main.cpp, built as build/example_NNN_name) prints its
tables between marker lines

    <!-- generated: NAME -->            or  <!-- generated: NAME; machine-dependent: COL, COL -->
    ...
    <!-- end -->

and the same markers stand in the docs where the tables go: the example's README.md or any
docs/*.md. This script runs the programs and replaces what stands between each pair of markers by
what the program printed. With --check it writes nothing and fails (exit 1) when a section
differs, when a program prints a section that no doc holds, or when a doc holds a section that no
program printed. Columns named in `machine-dependent:` (timings) are not compared.

Heavy tables: sections whose name ends in "-full" are printed only when the program runs with the
extra arguments of FULL_ARGS (minutes, not for CI). `--full` runs those programs with them and
rewrites (or, with --check, compares) the "-full" sections too; without it they are left as they
are and not compared.
"""
import argparse
import os
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BEGIN = re.compile(r"^<!-- generated: ([A-Za-z0-9_.-]+)(?:; machine-dependent: ([^>]*?))? -->$")
END = "<!-- end -->"

# Arguments of each program ({src}: its example folder, {tmp}: a scratch folder); default none.
# The programs that write job files or surfaces get a scratch folder, so that a check leaves the
# source tree as it was.
ARGS = {
    "000-c1-configurations": ["{src}", "{tmp}/out"],
    "001-pde-figures": ["{src}", "{tmp}/out"],
    "003-blend-cylinders": ["{tmp}", "{tmp}/out"],
    "004-cmc-c1-triangle": ["{src}", "{tmp}/out"],
    "004-cmc-circle": ["{src}", "{tmp}/out"],
    "004-cmc-fig2": ["{src}", "{tmp}/out"],
    "004-cmc-sphere-convergence": ["{src}", "{tmp}/out"],
}

# The extra arguments that make a program print its heavy ("-full") sections (docs.py --full).
FULL_ARGS = {
    "004-cmc-area-tables": ["--full"],
}


def is_full(name):
    return name.endswith("-full")


def blocks(lines, where):
    """{name: (machine-dependent columns, [lines])} of the marked sections of `lines`."""
    out, name = {}, None
    for i, line in enumerate(lines):
        m = BEGIN.match(line.strip())
        if m:
            if name is not None:
                sys.exit(f"{where}:{i + 1}: section {m.group(1)} starts inside section {name}")
            name, cols, body = m.group(1), m.group(2), []
            if name in out:
                sys.exit(f"{where}:{i + 1}: section {name} appears twice")
        elif line.strip() == END and name is not None:
            out[name] = ([c.strip() for c in cols.split(",")] if cols else [], body)
            name = None
        elif name is not None:
            body.append(line)
    if name is not None:
        sys.exit(f"{where}: section {name} has no {END}")
    return out


def masked(body, columns):
    """The lines of a section with the cells of the named table columns replaced by '*'."""
    if not columns:
        return body
    out, skip = [], set()
    for line in body:
        if not line.startswith("|"):
            out.append(line)
            skip = set()
            continue
        cells = re.split(r"(?<!\\)\|", line.strip()[1:-1])  # cells; "\|" is a pipe inside a cell
        if not skip and not set(line) <= set("|-: \n"):
            names = [c.strip() for c in cells]
            if any(c in names for c in columns):
                skip = {i for i, c in enumerate(names) if c in columns}
                out.append(line)
                continue
        out.append("|" + "|".join("*" if i in skip else c for i, c in enumerate(cells)) + "|")
    return out


def run(example, build, tmp, full=False):
    program = build / ("example_" + re.sub(r"[^A-Za-z0-9_]", "_", example))
    if not program.exists():
        sys.exit(f"{program} is missing: build it (bash scripts/build.sh)")
    scratch = pathlib.Path(tmp) / example
    scratch.mkdir(parents=True)
    args = [a.format(src=ROOT / "examples" / example, tmp=scratch) for a in ARGS.get(example, [])]
    if full:
        args += FULL_ARGS.get(example, [])
    r = subprocess.run([str(program)] + args, cwd=scratch, capture_output=True, text=True,
                       timeout=None if full else 600)
    if r.returncode != 0:
        sys.exit(f"{program.name} exited {r.returncode}:\n{r.stderr[-2000:]}")
    return blocks(r.stdout.splitlines(keepends=True), program.name)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="compare only; exit 1 on a difference")
    ap.add_argument("--full", action="store_true", help="also the heavy (-full) sections of FULL_ARGS (minutes)")
    ap.add_argument("--build", default=str(ROOT / "build"), help="build folder with the example programs")
    ap.add_argument("examples", nargs="*", help="example folder names (default: all)")
    a = ap.parse_args()
    build = pathlib.Path(a.build)
    examples = a.examples or sorted(p.parent.name for p in (ROOT / "examples").glob("*/main.cpp"))

    docs = [ROOT / "examples" / e / "README.md" for e in examples] + sorted((ROOT / "docs").glob("*.md"))
    with tempfile.TemporaryDirectory(prefix="bpde_docs_") as tmp:
        printed = {}  # name -> (example, columns, lines)
        for e in examples:
            for name, (cols, body) in run(e, build, tmp, a.full).items():
                if name in printed:
                    sys.exit(f"section {name} is printed by {printed[name][0]} and {e}")
                printed[name] = (e, cols, body)

    problems, placed = [], set()
    for doc in docs:
        if not doc.exists():
            continue
        lines = doc.read_text(encoding="utf-8").splitlines(keepends=True)
        held = blocks(lines, doc)
        new, name = [], None
        for line in lines:
            m = BEGIN.match(line.strip())
            if m and m.group(1) in printed:
                name = m.group(1)
                e, cols, body = printed[name]
                placed.add(name)
                same = masked(held[name][1], cols) == masked(body, cols)
                if not same:
                    problems.append(f"{doc.relative_to(ROOT)}: section {name} differs from what "
                                    f"example_{e} prints (regenerate: bash scripts/docs.sh)")
                new.append(line)
                new.extend(held[name][1] if same else body)  # same up to timings: left as it is
                continue
            if m and a.examples == [] and not (is_full(m.group(1)) and not a.full):
                problems.append(f"{doc.relative_to(ROOT)}: section {m.group(1)} is printed by no example program")
            if name is not None:
                if line.strip() == END:
                    name = None
                    new.append(line)
                continue
            new.append(line)
        if not a.check and new != lines:
            doc.write_text("".join(new), encoding="utf-8")
            print(f"docs: rewrote {doc.relative_to(ROOT)}")
    for name, (e, _, _) in printed.items():
        if name not in placed:
            problems.append(f"example_{e} prints section {name}, which no doc holds")
    if a.check:
        for p in problems:
            print("FAIL", p)
        print(f"docs: {len(printed)} generated sections of {len(examples)} examples checked, {len(problems)} problems")
        return 1 if problems else 0
    for p in problems:
        if "differs" not in p:
            print("warning:", p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
