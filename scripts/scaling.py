#!/usr/bin/env python3
"""Scaling table of the main jobs (docs/performance_measurements.md "Scaling").

Runs every Scaling/<kind>/<n> route of bpde_bench (bench/bench_scaling.cpp: one whole job, cold,
solve + report + files) in its own process under /usr/bin/time, so that the peak resident memory
belongs to that size alone, and prints a markdown table of CPU time and peak memory per size with
the exponents of a least-squares fit of log(value) against log(size) over the upper half of the
sizes (where fixed costs no longer dominate).

Usage: scripts/scaling.py [path/to/bpde_bench] [--filter REGEX]
"""
import json
import math
import re
import subprocess
import sys
import tempfile
import os


def routes(bench, pattern):
    out = subprocess.run([bench, "--benchmark_list_tests=true", "--benchmark_filter=" + pattern],
                         check=True, capture_output=True, text=True).stdout
    return [line.strip() for line in out.splitlines() if line.startswith("Scaling/")]


def run(bench, name):
    with tempfile.NamedTemporaryFile(suffix=".txt", delete=False) as f:
        timefile = f.name
    try:
        # The route's own name, anchored: one size per process.
        res = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", timefile, bench,
                              "--benchmark_filter=^" + re.escape(name).replace("\\/", "/") + "$",
                              "--benchmark_format=json"], capture_output=True, text=True)
        with open(timefile) as f:
            rss_kb = int(f.read().split()[-1])
    finally:
        os.unlink(timefile)
    if res.returncode != 0:
        raise RuntimeError(name + ": " + res.stderr)
    b = json.loads(res.stdout)["benchmarks"][0]
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[b["time_unit"]]
    return b["cpu_time"] * scale, rss_kb / 1024.0


def slope(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(y) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    sxx = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / sxx if sxx > 0 else float("nan")


def main():
    args = sys.argv[1:]
    pattern = "^Scaling/"
    if "--filter" in args:
        i = args.index("--filter")
        pattern = args[i + 1]
        del args[i:i + 2]
    bench = args[0] if args else "build/bpde_bench"
    table = {}
    for name in routes(bench, pattern):
        _, kind, size = name.split("/")[:3]
        size = int(size.split("/")[0])
        ms, mb = run(bench, name)
        table.setdefault(kind, []).append((size, ms, mb))
        print(f"{name}: {ms:.2f} ms CPU, {mb:.1f} MB peak", file=sys.stderr, flush=True)
    print("| job | size | CPU ms | peak MB |")
    print("|---|---|---|---|")
    fits = []
    for kind, rows in table.items():
        for size, ms, mb in rows:
            print(f"| {kind} | {size} | {ms:.2f} | {mb:.1f} |")
        upper = rows[len(rows) // 2:] if len(rows) >= 4 else rows
        sizes = [r[0] for r in upper]
        fits.append((kind, sizes[0], sizes[-1], slope(sizes, [r[1] for r in upper]),
                     slope(sizes, [max(r[2] - rows[0][2], 0.1) for r in upper])))
    print()
    print("| job | fitted over sizes | time ~ size^ | memory above the smallest run ~ size^ |")
    print("|---|---|---|---|")
    for kind, lo, hi, et, em in fits:
        print(f"| {kind} | {lo}..{hi} | {et:.1f} | {em:.1f} |")


if __name__ == "__main__":
    main()
