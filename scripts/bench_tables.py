#!/usr/bin/env python3
"""The benchmark tables of the docs, measured by bpde_bench in one run.

Usage: bench_tables.py [--list] [--min-time S] [--quick] [--only SECTION,...] BPDE_BENCH

Runs the routes of bpde_bench (Google Benchmark, bench/) that the performance pages rest on, each
family once in one process (`--benchmark_format=json`), the Table 1 report (`--table1`) and the
scaling table (scripts/scaling.py: one process per size) and the start-up table (scripts/startup.py
on the `bpde` beside BPDE_BENCH), and prints every table between the
markers of scripts/docs.py:

    <!-- generated: bench-NAME; machine-dependent: COL, ... -->
    ...
    <!-- end -->

`scripts/docs.py --bench` runs this script and puts the sections into docs/performance.md (the
goals) and docs/performance_measurements.md (everything else), stamped with the commit and the
machine. All numbers are timings of this machine, so every numeric column is machine-dependent:
the docs check compares only the tables' shape (routes, sizes, goals). `--list` prints the
section names without running anything (the docs check uses it to know the bench sections).
`--quick` shortens the minimum time of each route and leaves the scaling table out (a smoke run);
`--only` runs the named sections alone and prints only them (with `goals` among them, the goals
of the sections not run print "–").

Timings are CPU milliseconds per iteration (the benchmark's `cpu_time`); a ratio column divides
two routes of the same run.
"""
import argparse
import json
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
UNIT_MS = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}


def fmt(x):
    """A timing or ratio with 3 significant digits (no exponent below 1e-4)."""
    if x is None:
        return "–"
    if x == 0:
        return "0"
    if abs(x) >= 100:
        return f"{x:.0f}"
    if abs(x) >= 1e-4:
        return f"{x:.3g}"
    return f"{x:.2e}"


class Run:
    """The CPU time (ms) and counters of every route of one bpde_bench process."""

    def __init__(self, bench, pattern, min_time, repetitions=1):
        """With repetitions > 1 each route runs that many times (interleaved by Google Benchmark's
        --benchmark_enable_random_interleaving) and keeps its fastest run and that run's counters."""
        self.ms, self.counters = {}, {}
        if pattern is None:  # not asked for (--only)
            return
        cmd = [bench, "--benchmark_filter=" + pattern, "--benchmark_format=json", f"--benchmark_min_time={min_time}"]
        if repetitions > 1:
            cmd += [f"--benchmark_repetitions={repetitions}", "--benchmark_enable_random_interleaving=true"]
        out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
        for b in json.loads(out)["benchmarks"]:
            if b.get("run_type", "iteration") != "iteration":
                continue
            name = b.get("run_name", b["name"])
            ms = b["cpu_time"] * UNIT_MS[b["time_unit"]]
            if name in self.ms and self.ms[name] <= ms:
                continue
            self.ms[name] = ms
            self.counters[name] = {k: v for k, v in b.items() if isinstance(v, (int, float))}

    def get(self, route, size):
        return self.ms.get(f"{route}/{size}")


def sizes_of(run, routes):
    found = set()
    for name in run.ms:
        head, _, last = name.rpartition("/")
        if head in routes and last.isdigit():
            found.add(int(last))
    return sorted(found)


def route_table(run, size_label, cols, ratios):
    """Rows by size; cols: [(label, route)], ratios: [(label, numerator route, denominator route)]."""
    routes = [r for _, r in cols]
    lines = ["| " + " | ".join([size_label] + [c for c, _ in cols] + [r for r, _, _ in ratios]) + " |",
             "|" + "---|" * (1 + len(cols) + len(ratios))]
    for n in sizes_of(run, routes):
        cells = [str(n)] + [fmt(run.get(r, n)) for _, r in cols]
        for _, a, b in ratios:
            x, y = run.get(a, n), run.get(b, n)
            cells.append(fmt(x / y) if x is not None and y else "–")
        lines.append("| " + " | ".join(cells) + " |")
    return lines


def section(name, lines, columns):
    head = f"<!-- generated: bench-{name}; machine-dependent: {', '.join(columns)} -->"
    return [head] + lines + ["<!-- end -->"]


# Families: (section, filter, size label, [(column, route)], [(ratio column, num, den)]).
FAMILIES = [
    ("report", "^(Solve|Report)/", "n or k",
     [(f"{w} {k} ms", f"{W}/{k}") for k in ("pde", "extremal", "cmc", "blend") for w, W in (("solve", "Solve"), ("report", "Report"))],
     [(f"report / solve {k}", f"Report/{k}", f"Solve/{k}") for k in ("pde", "extremal", "cmc", "blend")]),
    ("check", "^Check(-cgal-boxes|-report)?/", "n",
     [("grid pde ms", "Check/pde"), ("CGAL boxes pde ms", "Check-cgal-boxes/pde"), ("report pde ms", "Check-report/pde"),
      ("grid cmc ms", "Check/cmc"), ("CGAL boxes cmc ms", "Check-cgal-boxes/cmc"), ("report cmc ms", "Check-report/cmc")],
     [("CGAL boxes / grid pde", "Check-cgal-boxes/pde", "Check/pde"),
      ("CGAL boxes / grid cmc", "Check-cgal-boxes/cmc", "Check/cmc")]),
    ("kernel-grid", "^Kernel/grid-", "n",
     [("row-major ms", "Kernel/grid-row-major"), ("Eigen ms", "Kernel/grid-eigen")],
     [("Eigen / row-major", "Kernel/grid-eigen", "Kernel/grid-row-major")]),
    ("kernel-mould", "^Kernel/mould-", "n",
     [("row-major ms", "Kernel/mould-row-major"), ("Eigen ms", "Kernel/mould-eigen")],
     [("Eigen / row-major", "Kernel/mould-eigen", "Kernel/mould-row-major")]),
    ("kernel-rows", "^Kernel/rows-", "rows",
     [("row-major ms", "Kernel/rows-row-major"), ("Eigen ms", "Kernel/rows-eigen")],
     [("Eigen / row-major", "Kernel/rows-eigen", "Kernel/rows-row-major")]),
    ("blend", "^Blend/", "k",
     [("cholesky ms", "Blend/cholesky"), ("kkt ms", "Blend/kkt")],
     [("kkt / cholesky", "Blend/kkt", "Blend/cholesky")]),
    ("cmc", "^Cmc/", "n",
     [("dirichlet ms", "Cmc/dirichlet"), ("newton ms", "Cmc/newton"), ("ceres ms", "Cmc/ceres"),
      ("nlopt ms", "Cmc/nlopt")],
     [("newton / dirichlet", "Cmc/newton", "Cmc/dirichlet"), ("ceres / newton", "Cmc/ceres", "Cmc/newton"),
      ("nlopt / newton", "Cmc/nlopt", "Cmc/newton")]),
    ("cmc-area", "^CmcArea/(newton|ceres|circle)/", "n",
     [("newton ms", "CmcArea/newton"), ("ceres ms", "CmcArea/ceres"), ("circle ms", "CmcArea/circle")],
     [("ceres / newton", "CmcArea/ceres", "CmcArea/newton")]),
    ("cmc-mean-curvature", "^CmcMeanCurvature/", "n",
     [("newton ms", "CmcMeanCurvature/newton/circle"), ("ceres ms", "CmcMeanCurvature/ceres/circle"),
      ("newton-plain ms", "CmcMeanCurvature/newton-plain/circle"),
      ("newton V ms", "CmcMeanCurvature/newton-volume/circle"),
      ("ceres V ms", "CmcMeanCurvature/ceres-volume/circle")],
     [("ceres / newton", "CmcMeanCurvature/ceres/circle", "CmcMeanCurvature/newton/circle"),
      ("ceres / newton (V)", "CmcMeanCurvature/ceres-volume/circle", "CmcMeanCurvature/newton-volume/circle")]),
    ("cmc-complex", "^CmcComplex/", "patches",
     [("minimal surface ms", "CmcComplex/minimal"), ("Dirichlet extremal ms", "CmcComplex/extremal")],
     [("minimal / extremal", "CmcComplex/minimal", "CmcComplex/extremal")]),
    ("area-form", "^AreaForm/", "n",
     [(f"{op} {dom} ms", f"AreaForm/{op}/{dom}") for op in ("gradient", "rows-and-scale", "hessian")
      for dom in ("triangle", "square")], []),
    ("tetraharmonic", "^(Tetraharmonic|BiharmonicLoad)/", "n",
     [("explicit ms", "Tetraharmonic/explicit"), ("lu ms", "Tetraharmonic/lu"),
      ("lu-unrefined ms", "Tetraharmonic/lu-unrefined"), ("load lu ms", "BiharmonicLoad/lu")],
     [("lu / explicit", "Tetraharmonic/lu", "Tetraharmonic/explicit")]),
    ("plate", "^Plate/", "n",
     [("ritz ms", "Plate/ritz"), ("admissible-load ms", "Plate/admissible-load")], []),
    ("extremal", "^Extremal/", "n",
     [("direct ms", "Extremal/direct"), ("mould ms", "Extremal/mould"), ("factored ms", "Extremal/factored"),
      ("setup ms", "Extremal/setup")],
     [("direct / mould", "Extremal/direct", "Extremal/mould")]),
    ("bspline", "^BSpline", "spans",
     [("extremal direct ms", "BSplineExtremal/direct"), ("extremal reuse ms", "BSplineExtremal/reuse"),
      ("pde lu ms", "BSplinePde/lu")],
     [("direct / reuse", "BSplineExtremal/direct", "BSplineExtremal/reuse")]),
    ("sampling", "^Sample/", "n",
     [("tensor grid ms", "Sample/tensor-grid"), ("tensor de Casteljau ms", "Sample/tensor-casteljau"),
      ("triangular basis ms", "Sample/triangular-basis"),
      ("triangular de Casteljau ms", "Sample/triangular-casteljau")],
     [("tensor: de Casteljau / grid", "Sample/tensor-casteljau", "Sample/tensor-grid"),
      ("triangular: de Casteljau / basis", "Sample/triangular-casteljau", "Sample/triangular-basis")]),
]

SECTIONS = ["goals"] + [f[0] for f in FAMILIES] + ["kernel-peak", "degree-flops", "table1", "scaling", "startup"]


def family_sections(runs):
    out = []
    for name, _, size_label, cols, ratios in FAMILIES:
        lines = route_table(runs[name], size_label, cols, ratios)
        out += section(name, lines, [c for c, _ in cols] + [r for r, _, _ in ratios]) + [""]
    return out


def kernel_peak(run):
    """The mould product's FLOP rate against the core's multiply-add peak (Kernel/fma-peak)."""
    peak = run.counters.get("Kernel/fma-peak", {}).get("flops")
    lines = ["| kernel | GFLOP/s | share of the peak |", "|---|---|---|"]
    lines.append(f"| fma-peak | {fmt(peak / 1e9) if peak else '–'} | 1 |")
    for name in sorted(run.counters):
        f = run.counters[name].get("flops")
        if name.startswith("Kernel/mould-") and f:
            lines.append(f"| {name.removeprefix('Kernel/')} | {fmt(f / 1e9)} | {fmt(f / peak) if peak else '–'} |")
    return lines


def power_fit(points):
    """The exponent a of t ~ n^a by least squares on (log n, log t)."""
    import math
    pts = [(math.log(n), math.log(t)) for n, t in points if t and t > 0]
    if len(pts) < 2:
        return None
    mx = sum(x for x, _ in pts) / len(pts)
    my = sum(y for _, y in pts) / len(pts)
    sxx = sum((x - mx) ** 2 for x, _ in pts)
    return sum((x - mx) * (y - my) for x, y in pts) / sxx if sxx else None


DEGREE_COLUMNS = ["nodes", "area solve ms", "pass MFLOP", "pass GFLOP/s", "pass / peak", "Hessian MFLOP",
                  "Hessian GFLOP/s", "Hessian / peak", "D_H solve ms", "factor MFLOP", "factor GFLOP/s",
                  "factor / peak"]


def degree_flops(run):
    """The solve time against the degree (bench/bench_cmc.cpp, Degree/…): the area solve of the
    circle in three arcs and the D_H solve of the sphere's data, each beside the FLOP counts of its
    dominant kernels (counted from the sizes in bench_cmc.cpp) and their measured rates against the
    core's multiply-add peak (Kernel/fma-peak); then the fitted exponents of time against n."""
    peak = run.counters.get("Kernel/fma-peak", {}).get("flops")

    def rate(route, n):
        f = run.counters.get(f"{route}/{n}", {}).get("flops")
        return (fmt(f / 1e9), fmt(f / peak) if peak else "–") if f else ("–", "–")

    lines = ["| n | " + " | ".join(DEGREE_COLUMNS) + " |", "|" + "---|" * (1 + len(DEGREE_COLUMNS))]
    sizes = sizes_of(run, ["Degree/area", "Degree/dh"])
    for n in sizes:
        c = run.counters.get(f"Degree/area/{n}", {})
        d = run.counters.get(f"Degree/dh/{n}", {})
        mflop = lambda x: fmt(x / 1e6) if x else "–"
        cells = [str(n), fmt(c.get("nodes")), fmt(run.get("Degree/area", n)), mflop(c.get("pass_flops")),
                 *rate("Degree/area-gradient", n), mflop(c.get("hessian_flops")), *rate("Degree/area-hessian", n),
                 fmt(run.get("Degree/dh", n)), mflop(d.get("factor_flops")), *rate("Degree/dh-factor", n)]
        lines.append("| " + " | ".join(cells) + " |")
    fits = [("area solve time ~ n^, n = 6–16", "Degree/area", 6), ("area solve time ~ n^, n = 8–16", "Degree/area", 8),
            ("D_H solve time ~ n^, n = 6–16", "Degree/dh", 6), ("D_H solve time ~ n^, n = 10–16", "Degree/dh", 10)]
    lines += ["", "| measure | value |", "|---|---|",
              f"| the core's multiply-add peak (Kernel/fma-peak), GFLOP/s | {fmt(peak / 1e9) if peak else '–'} |"]
    for label, route, lo in fits:
        a = power_fit([(n, run.get(route, n)) for n in sizes if n >= lo])
        lines.append(f"| {label} | {fmt(a)} |")
    return lines


def table1(bench, min_time):
    """The Table 1 report of `bpde_bench --table1` (bench/table1_report.cpp): table and goal lines."""
    out = subprocess.run([bench, "--table1", f"--benchmark_min_time={min_time}"], check=True,
                         capture_output=True, text=True).stdout.splitlines()
    start = next(i for i, l in enumerate(out) if l.startswith("| n |"))
    table = [l for l in out[start:] if l.startswith("|")]
    verdicts, tail = [], out[start:]
    for i, l in enumerate(tail):  # a verdict line and its indented continuation lines
        if l.startswith(("goal:", "floor:", "finding:")):
            verdicts.append(l)
        elif verdicts and l.startswith(" ") and not tail[i - 1].startswith("|"):
            verdicts[-1] += " " + l.strip()
    return table, verdicts


def scaling(bench):
    out = subprocess.run([sys.executable, str(ROOT / "scripts" / "scaling.py"), bench], check=True,
                         capture_output=True, text=True).stdout.splitlines()
    return [l for l in out if l.startswith("|") or not l.strip()]


def startup(bench, runs):
    """scripts/startup.py on the bpde beside bpde_bench: [{command, min_ms, median_ms,
    ratio_to_true, relocations}]."""
    bpde = pathlib.Path(bench).parent / "bpde"
    out = subprocess.run([sys.executable, str(ROOT / "scripts" / "startup.py"), str(bpde), "--runs", str(runs),
                          "--json"], check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def startup_table(rows):
    lines = ["| command | min CPU ms | median CPU ms | min / `/bin/true` | loader relocations |", "|---|---|---|---|---|"]
    for r in rows:
        ratio = fmt(r["ratio_to_true"]) if r["ratio_to_true"] else "–"
        lines.append(f"| `{r['command']}` | {fmt(r['min_ms'])} | {fmt(r['median_ms'])} | {ratio} | {r['relocations']} |")
    return lines


def ratio(run, a, b, n):
    x, y = run.get(a, n), run.get(b, n)
    return x / y if x is not None and y else None


def verdict(ok):
    return "–" if ok is None else ("met" if ok else "not met")


def goals(runs, t1_verdicts, scale_lines, start_rows):
    """The goals of docs/performance.md, each with its measure in this run and its verdict."""
    rows = []

    def add(goal, value, ok):
        rows.append(f"| {goal} | {value} | {verdict(ok)} |")

    for v in t1_verdicts:
        m = re.match(r"^(?:goal|floor): (.*): (met|NOT met)\b", v)
        if m:
            add("Table 1: " + m.group(1), "[Table 1](performance_measurements.md#table-1)", m.group(2) == "met")
    grid = runs["kernel-grid"]
    g = [ratio(grid, "Kernel/grid-eigen", "Kernel/grid-row-major", n) for n in (5, 10, 20)]
    g = [x for x in g if x is not None]
    add("the hand-written grid kernel faster than Eigen with the same flags",
        f"Eigen / kernel {fmt(min(g))}–{fmt(max(g))}" if g else "–", min(g) > 1 if g else None)
    mould = runs["kernel-peak"].counters
    peak = mould.get("Kernel/fma-peak", {}).get("flops")
    m20 = mould.get("Kernel/mould-row-major/20", {}).get("flops")
    add("the mould product at n = 20 within 2× of the core's multiply-add peak",
        f"{fmt(m20 / peak)} of the peak" if peak and m20 else "–", m20 / peak >= 0.5 if peak and m20 else None)
    for k in ("pde", "extremal", "cmc"):
        r = ratio(runs["report"], f"Report/{k}", f"Solve/{k}", 20)
        add(f"report ≤ solve, {k} at n = 20", f"report / solve {fmt(r)}", None if r is None else r <= 1)
    r = ratio(runs["report"], "Report/blend", "Solve/blend", 32)
    add("report ≤ solve, blend at k = 32", f"report / solve {fmt(r)}", None if r is None else r <= 1)
    r = ratio(runs["blend"], "Blend/kkt", "Blend/cholesky", 128)
    add("blend 128 × 128: 10× less CPU than the KKT LU", f"kkt / cholesky {fmt(r)}", None if r is None else r >= 10)
    mem = next((l for l in scale_lines if l.startswith("| blend | 128 |")), None)
    mb = float(mem.split("|")[4]) if mem else None
    add("blend 128 × 128: at most 150 MB peak", f"{fmt(mb)} MB" if mb else "–", None if mb is None else mb <= 150)
    r = ratio(runs["cmc"], "Cmc/ceres", "Cmc/newton", 15)
    add("the Ceres CMC route within 2× of newton at n = 15", f"ceres / newton {fmt(r)}", None if r is None else r <= 2)
    r = ratio(runs["cmc"], "Cmc/newton", "Cmc/dirichlet", 10)
    add("one D_H solve at degree 10 in the time of ≤ 50 Dirichlet solves", f"newton / dirichlet {fmt(r)}",
        None if r is None else r <= 50)
    version = next((r for r in start_rows if r["command"] == "bpde --version"), None)
    add("`bpde --version` in at most 5 ms of CPU (the process floor)",
        f"{fmt(version['min_ms'])} ms" if version else "–", None if version is None else version["min_ms"] <= 5)
    lines = ["| goal | measured | status |", "|---|---|---|"] + rows
    return section("goals", lines, ["measured", "status"])


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("bench", nargs="?", default=str(ROOT / "build" / "bpde_bench"))
    ap.add_argument("--list", action="store_true", help="print the section names and exit")
    ap.add_argument("--min-time", type=float, default=0.2, help="--benchmark_min_time of each route")
    ap.add_argument("--quick", action="store_true", help="a smoke run: short routes, no scaling table")
    ap.add_argument("--only", help="comma-separated route families (names of --list without bench-)")
    a = ap.parse_args()
    if a.list:
        print("\n".join("bench-" + s for s in SECTIONS))
        return 0
    if not pathlib.Path(a.bench).exists():
        sys.exit(f"{a.bench} is missing: build it (bash scripts/build.sh bpde_bench)")
    min_time = 0.01 if a.quick else a.min_time
    only = set(a.only.split(",")) if a.only else set(SECTIONS)
    unknown = only - set(SECTIONS)
    if unknown:
        sys.exit(f"--only: no section {', '.join(sorted(unknown))} (see --list)")
    runs = {}
    for name, pattern, *_ in FAMILIES:
        print(f"bench: {name} ({pattern})", file=sys.stderr, flush=True)
        runs[name] = Run(a.bench, pattern if name in only else None, min_time)
    runs["kernel-peak"] = Run(a.bench, "^Kernel/(fma-peak|mould-)" if "kernel-peak" in only else None, min_time)
    print("bench: degree-flops", file=sys.stderr, flush=True)
    runs["degree-flops"] = Run(a.bench, "^(Degree/|Kernel/fma-peak$)" if "degree-flops" in only else None, min_time,
                               repetitions=1 if a.quick else 3)
    print("bench: table1", file=sys.stderr, flush=True)
    t1, t1_verdicts = table1(a.bench, min_time) if "table1" in only else ([], [])
    print("bench: scaling", file=sys.stderr, flush=True)
    scale = [] if a.quick or "scaling" not in only else scaling(a.bench)
    print("bench: startup", file=sys.stderr, flush=True)
    start = startup(a.bench, 5 if a.quick else 30) if "startup" in only else []
    cpu = next((l.partition(":")[2].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "")
    out = goals(runs, t1_verdicts, scale, start) + [""] + family_sections(runs)
    out += section("kernel-peak", kernel_peak(runs["kernel-peak"]), ["GFLOP/s", "share of the peak"]) + [""]
    out += section("degree-flops", degree_flops(runs["degree-flops"]), DEGREE_COLUMNS + ["value"]) + [""]
    t1_cols = [c.strip() for c in t1[0].strip("|").split("|")][2:] if t1 else []
    out += section("table1", (t1 + [""] + ["- " + v for v in t1_verdicts]) if t1 else ["(not run)"], t1_cols) + [""]
    scale_cols = ["CPU ms", "peak MB", "time ~ size^", "memory above the smallest run ~ size^"]
    out += section("scaling", scale or ["(not run)"], scale_cols) + [""]
    out += section("startup", startup_table(start) if start else ["(not run)"],
                   ["min CPU ms", "median CPU ms", "min / `/bin/true`", "loader relocations"])
    if a.only:  # only the sections asked for (docs.py --from rewrites just those)
        keep, text, on = [], [], False
        for line in out:
            m = re.match(r"<!-- generated: bench-([a-z0-9-]+);", line)
            if m:
                on = m.group(1) in only
            if on:
                keep.append(line)
            if line == "<!-- end -->":
                if on:
                    keep.append("")
                on = False
        out = keep
    print("\n".join(out))
    print(f"bench: done on {cpu}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
