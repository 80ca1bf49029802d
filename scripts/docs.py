#!/usr/bin/env python3
"""Regenerate (or check) the generated sections of the docs from the example programs.

Usage: docs.py [--check] [--full [--full-sections NAME,...]] [--run GEN,...] [--from GEN=FILE ...] [--bench] [--build DIR] [EXAMPLE ...]

Every example program (examples/NNN-name/main.cpp, built as build/example_NNN_name) prints its
tables between marker lines

    <!-- generated: NAME -->            or  <!-- generated: NAME; machine-dependent: COL, COL -->
    ...
    <!-- end -->

and the same markers stand in the docs where the tables go: the example's README.md or any
docs/*.md. This script runs the programs and replaces what stands between each pair of markers by
what the program printed. With --check it writes nothing and fails (exit 1) when a section
differs, when a program prints a section that no doc holds, or when a doc holds a section that no
program printed. Columns named in `machine-dependent:` (timings) are not compared. The columns
that ROUNDING below names for a section hold numbers whose last printed digit depends on how the
build rounds (FMA contraction with -march=native against the portable build,
docs/performance_measurements.md, "Kernels"): there each number may differ from the documented
one by one unit of its last printed digit (1.000001 against 1.000002; -0.0000 against 0.0000), and
a bound "< 1eK" (examples/common/generated.h, order_bound) by one power of ten; the text around
the numbers must be the same. Anything more is a difference.

Heavy tables: sections whose name ends in "-full" are printed only when the program runs with the
extra arguments of FULL_ARGS (minutes, not for CI). `--full` runs those programs with them and
rewrites (or, with --check, compares) the "-full" sections too; without it they are left as they
are and not compared. `--full --full-sections NAME,...` runs them with the section names appended
to FULL_ARGS, so that they print (and this script rewrites) only those "-full" sections; the
others are left as they are.

Measurement scripts: sections whose name starts with "GEN-" for a generator GEN of GENERATORS
below are printed by a script that runs for minutes (benchmarks, Surface Evolver, sweeps), not
by an example. `--run GEN` runs it (`--bench` is `--run bench`; `--from GEN=FILE` takes a saved
output of it instead) and rewrites its sections whenever it runs; otherwise they are left as they
are, and the check only requires that the docs hold exactly the sections that the script's
`--list` names. Their numbers are this machine's measurements: nothing in them is compared.

Stamp: a doc that holds a line starting with "Stamp:" (the measurement pages,
docs/*_measurements.md) gets that line rewritten to the commit and the machine whenever this script
rewrites one of its sections. The check never compares it: it says where the numbers last came
from, not what they are.
"""
import argparse
import os
import platform
import pathlib
import re
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
BEGIN = re.compile(r"^<!-- generated: ([A-Za-z0-9_.-]+)(?:; machine-dependent: ([^>]*?))? -->$")
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")
END = "<!-- end -->"
STAMP = "Stamp:"

# Arguments of each program ({src}: its example folder, {tmp}: a scratch folder); default none.
# The programs that write job files or surfaces get a scratch folder, so that a check leaves the
# source tree as it was.
ARGS = {
    "000-c1-configurations": ["{src}", "{tmp}/out"],
    "001-pde-figures": ["{src}", "{tmp}/out"],
    "003-blend-cylinders": ["{tmp}", "{tmp}/out"],
    "004-cmc-c1-triangle": ["{src}", "{tmp}/out"],
    "004-cmc-circle": ["{src}", "{tmp}/out"],
    "004-cmc-circle-sweep": ["{src}", "{tmp}/out"],
    "004-cmc-fig2": ["{src}", "{tmp}/out"],
    "004-cmc-sphere-convergence": ["{src}", "{tmp}/out"],
}

# The extra arguments that make a program print its heavy ("-full") sections (docs.py --full).
# With --full-sections NAME,... the names follow them: 004-cmc-area-tables then prints only the
# named "-full" sections (its whole --full run takes many minutes; cmc-area-trust-region-full
# about 5 minutes, cmc-area-starts-full about 2, cmc-area-conformal-gate-full,
# cmc-mean-curvature-circle-10-full and cmc-mean-curvature-volume-form-full seconds).
FULL_ARGS = {
    "004-cmc-area-tables": ["--full"],
}


def is_full(name):
    return name.endswith("-full")


# The columns of a section whose numbers are rounding-dependent in their last printed digit,
# measured against a -march=native build (docs/performance_measurements.md, "Kernels").
ROUNDING = {
    "cmc-fig2-jobs": ["H mean"],  # -0.0000 portable, 0.0000 native (H = 0)
    # square n = 16: H min 0.999999 / 1.000000, |H_mean - 1| 3.3e-08 / 3.2e-08 (portable / native)
    "cmc-sphere-convergence": ["H min / max", "\\|H_mean − 1\\|"],
    # the fold as the continuation's step control locates it (4 decimals; not measured portable)
    "cmc-sphere-fold": ["fold H > 0", "fold H < 0"],
    # differences of two quadratures, 2 digits from 1e-13 up (not measured portable)
    "cmc-area-rule-probe": ["q = 11", "15", "20", "27", "36", "48", "64", "86"],
    # the fold as the continuation locates it, 6 digits; sampled curvature and energies to their
    # last printed digit (not measured portable)
    "cmc-circle-sweep-fold": ["H reached", "D_H at that H"],
    "cmc-circle-sweep-degree-axis": ["H_min", "H_max", "energy"],
}


def column_keys(name, cols):
    """{"machine-dependent": [COL, ...], "rounding": [COL, ...]} of a section."""
    return {"machine-dependent": [c.strip() for c in cols.split(",")] if cols else [],
            "rounding": ROUNDING.get(name, [])}


def blocks(lines, where):
    """{name: (column keys, [lines])} of the marked sections of `lines`."""
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
            out[name] = (column_keys(name, cols), body)
            name = None
        elif name is not None:
            body.append(line)
    if name is not None:
        sys.exit(f"{where}: section {name} has no {END}")
    return out


def split_cells(line):
    return re.split(r"(?<!\\)\|", line.strip()[1:-1])  # cells; "\|" is a pipe inside a cell


def table_kinds(body, keys):
    """Per line of `body`: {cell index: "machine-dependent" | "rounding"} of the table it is in
    (from the table's header line), {} outside tables."""
    named = {c: k for k in ("machine-dependent", "rounding") for c in keys[k]}
    out, kinds, header = [], {}, False
    for line in body:
        if not line.startswith("|"):
            kinds, header = {}, False
        elif not header and not set(line) <= set("|-: \n"):
            header = True
            kinds = {i: named[c.strip()] for i, c in enumerate(split_cells(line)) if c.strip() in named}
            out.append({})  # the header itself is compared as text
            continue
        out.append(kinds)
    return out


def last_digit_unit(text):
    """One unit of the last printed digit of a number as printed ("1.0000112" -> 1e-7)."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 10.0 ** (int(exponent or 0) - decimals)


def same_rounding_cell(doc, new):
    """True when two cells agree up to rounding: the same text around the numbers, each number
    within one unit of its last printed digit, a bound "< 1eK" within one power of ten."""
    a, b = NUMBER.findall(doc), NUMBER.findall(new)
    if len(a) != len(b) or NUMBER.sub("#", doc).strip() != NUMBER.sub("#", new).strip():
        return False
    bound = doc.strip().startswith("<")
    for x, y in zip(a, b):
        if bound:
            ex, ey = x.lower().partition("e")[2], y.lower().partition("e")[2]
            if not (ex and ey and abs(int(ex) - int(ey)) <= 1 and float(x) > 0 and float(y) > 0):
                return False
        elif abs(float(x) - float(y)) > 1.0001 * max(last_digit_unit(x), last_digit_unit(y)):
            return False
    return True


def same_section(doc_body, new_body, keys):
    """The documented and the printed section agree: equal, but for the cells of machine-dependent
    columns (not compared) and of rounding columns (same_rounding_cell)."""
    if len(doc_body) != len(new_body):
        return False
    kinds_doc, kinds_new = table_kinds(doc_body, keys), table_kinds(new_body, keys)
    for d, n, kd, kn in zip(doc_body, new_body, kinds_doc, kinds_new):
        if d == n:
            continue
        if not kd or kd != kn:
            return False
        cd, cn = split_cells(d), split_cells(n)
        if len(cd) != len(cn):
            return False
        for i, (x, y) in enumerate(zip(cd, cn)):
            kind = kd.get(i)
            if kind == "machine-dependent" or x == y:
                continue
            if kind != "rounding" or not same_rounding_cell(x, y):
                return False
    return True


def stamp_line():
    """"Stamp: ..." with the commit (git describe) and the machine (CPU model, cores)."""
    try:
        commit = subprocess.run(["git", "-C", str(ROOT), "describe", "--always", "--dirty"],
                                capture_output=True, text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        commit = "unknown"
    cpu = platform.processor() or platform.machine()
    try:
        for line in pathlib.Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.partition(":")[2].strip()
                break
    except OSError:
        pass
    return (f"{STAMP} generated by scripts/docs.py at commit {commit} on {cpu}, "
            f"{os.cpu_count()} cores ({platform.system()} {platform.machine()}).\n")


def run(example, build, tmp, full=False, full_sections=()):
    program = build / ("example_" + re.sub(r"[^A-Za-z0-9_]", "_", example))
    if not program.exists():
        sys.exit(f"{program} is missing: build it (bash scripts/build.sh)")
    scratch = pathlib.Path(tmp) / example
    scratch.mkdir(parents=True)
    args = [a.format(src=ROOT / "examples" / example, tmp=scratch) for a in ARGS.get(example, [])]
    if full:
        args += FULL_ARGS.get(example, [])
        if example in FULL_ARGS:
            args += list(full_sections)
    r = subprocess.run([str(program)] + args, cwd=scratch, capture_output=True, text=True,
                       timeout=None if full else 600)
    if r.returncode != 0:
        sys.exit(f"{program.name} exited {r.returncode}:\n{r.stderr[-2000:]}")
    return blocks(r.stdout.splitlines(keepends=True), program.name)


# Measurement scripts (GEN: the script and its arguments; {build}: the build folder). Each prints
# sections named "GEN-..." and lists their names with --list (given after the same arguments).
GENERATORS = {
    "bench": ["scripts/bench_tables.py", "{build}/bpde_bench"],  # minutes
    "boundary-fit": ["scripts/boundary_fit_table.py", "{build}/bpde"],  # seconds
    "sample-fit": ["scripts/sample_fit_table.py", "{build}/bpde"],  # seconds
    "sample-solve": ["scripts/sample_fit_table.py", "--solve", "{build}/bpde"],  # about 25 minutes
    "boundary-sweep": ["scripts/random_boundary_sweep.py", "{build}/bpde", "7"],  # about 10 minutes
    "corner-sweep": ["scripts/random_boundary_sweep.py", "--corners", "{build}/bpde", "7"],  # minutes
    "pde-accuracy": ["scripts/pde_accuracy_table.py", "{build}/test_pde"],  # seconds
    "circle-join": ["scripts/circle_join_table.py", "{build}/bpde"],  # seconds
    "c1-accuracy": ["scripts/c1_accuracy_table.py", "{build}/test_c1"],  # seconds
    "geometric-fit": ["scripts/geometric_fit_table.py", "{build}/test_boundaries"],  # seconds
    # the exact cases of patch complexes (docs/complex.md), examples/005-complex-exact; about 10 minutes
    "complex-exact": ["scripts/complex_exact_tables.py", "{build}/example_005_complex_exact"],
    # Surface Evolver (`evolver`, Debian package evolver-nox) against bpde solve; about 17 minutes
    "evolver": ["scripts/evolver_compare.py", "--bpde", "{build}/bpde", "--case", "all",
                "--degrees", "4,5,6,7,8,9,10,12,14,16", "--linear-levels", "1..8", "--quadratic-levels", "1..8",
                "--mc-tolerances", "1e-7,1e-8", "--area-dirichlet-start"],
}


def generated_sections(gen, a, build):
    """({name: (keys, lines)} printed by generator gen when it runs (--run / --from), else {};
    the names its --list gives)."""
    script, *args = GENERATORS[gen]
    args = [x.format(build=build) for x in args]
    names = subprocess.run([sys.executable, str(ROOT / script)] + args + ["--list"], check=True,
                           capture_output=True, text=True).stdout.split()
    saved = dict(f.split("=", 1) for f in a.saved)
    if gen in saved:
        text = pathlib.Path(saved[gen]).read_text(encoding="utf-8")
    elif gen in a.run:
        cmd = [sys.executable, str(ROOT / script)] + args
        text = subprocess.run(cmd, check=True, stdout=subprocess.PIPE, text=True).stdout
    else:
        return {}, names
    return blocks(text.splitlines(keepends=True), script), names


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--check", action="store_true", help="compare only; exit 1 on a difference")
    ap.add_argument("--full", action="store_true", help="also the heavy (-full) sections of FULL_ARGS (minutes)")
    ap.add_argument("--full-sections", default="",
                    help="with --full: only these comma-separated -full sections (the others are left as they are)")
    ap.add_argument("--run", default="", help="comma-separated measurement scripts to run (GENERATORS; minutes)")
    ap.add_argument("--bench", action="store_true", help="the same as --run bench")
    ap.add_argument("--from", dest="saved", action="append", default=[], metavar="GEN=FILE",
                    help="a measurement script's sections from its saved output")
    ap.add_argument("--build", default=str(ROOT / "build"), help="build folder with the example programs")
    ap.add_argument("examples", nargs="*", help="example folder names (default: all)")
    a = ap.parse_args()
    a.full_sections = [x for x in a.full_sections.split(",") if x]
    if a.full_sections and not a.full:
        sys.exit("--full-sections needs --full")
    a.run = set(filter(None, a.run.split(","))) | ({"bench"} if a.bench else set())
    unknown = (a.run | {f.split("=", 1)[0] for f in a.saved}) - set(GENERATORS)
    if unknown:
        sys.exit(f"no measurement script {', '.join(sorted(unknown))} (GENERATORS: {', '.join(GENERATORS)})")
    build = pathlib.Path(a.build)
    examples = a.examples or sorted(p.parent.name for p in (ROOT / "examples").glob("*/main.cpp"))

    docs = [ROOT / "examples" / e / "README.md" for e in examples] + sorted((ROOT / "docs").glob("*.md"))
    with tempfile.TemporaryDirectory(prefix="bpde_docs_") as tmp:
        printed = {}  # name -> (example, columns, lines)
        for e in examples:
            for name, (cols, body) in run(e, build, tmp, a.full, a.full_sections).items():
                if name in printed:
                    sys.exit(f"section {name} is printed by {printed[name][0]} and {e}")
                printed[name] = (e, cols, body)

    measured, idle = set(), set()  # sections of measurement scripts that ran / did not run
    for gen in GENERATORS:
        sections, names = generated_sections(gen, a, build)
        for name, (cols, body) in sections.items():
            printed[name] = (GENERATORS[gen][0], cols, body)
            measured.add(name)
        idle |= set(names) - set(sections)  # not run, or not among the sections a saved run holds

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
                e, keys, body = printed[name]
                placed.add(name)
                same = name not in measured and same_section(held[name][1], body, keys)
                if not same and name not in measured:
                    problems.append(f"{doc.relative_to(ROOT)}: section {name} differs from what "
                                    f"example_{e} prints (regenerate: bash scripts/docs.sh)")
                new.append(line)
                new.extend(held[name][1] if same else body)  # same up to timings and rounding: left as it is
                continue
            if m and m.group(1) in idle:
                placed.add(m.group(1))  # a measurement script's table, not run: left as it is
            elif m and a.examples == [] and not (is_full(m.group(1)) and
                                                 (not a.full or (a.full_sections and m.group(1) not in a.full_sections))):
                problems.append(f"{doc.relative_to(ROOT)}: section {m.group(1)} is printed by no example program")
            if name is not None:
                if line.strip() == END:
                    name = None
                    new.append(line)
                continue
            new.append(line)
        if not a.check and new != lines:
            new = [stamp_line() if line.startswith(STAMP) else line for line in new]
            doc.write_text("".join(new), encoding="utf-8")
            print(f"docs: rewrote {doc.relative_to(ROOT)}")
    for name in idle:
        if name not in placed and a.examples == []:
            problems.append(f"a measurement script prints section {name}, which no doc holds")
    for name, (e, _, _) in printed.items():
        if name not in placed:
            problems.append(f"{e} prints section {name}, which no doc holds")
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
