#!/usr/bin/env python3
"""The benchmark tables of the docs can be produced: scripts/bench_tables.py runs a few route
families of bpde_bench (--quick --only) and prints, for each, a section whose every row has a
number in every timing column, a ratio that is their quotient, and a goals table whose rows for
those families carry a verdict; its --list names exactly the bench-* sections the docs hold.

Usage: check_bench_tables.py SOURCE_DIR BPDE_BENCH
"""
import pathlib
import re
import subprocess
import sys

root, bench = pathlib.Path(sys.argv[1]), sys.argv[2]
script = root / "scripts" / "bench_tables.py"
failures = []

names = subprocess.run([sys.executable, str(script), "--list"], check=True, capture_output=True,
                       text=True).stdout.split()
held = set()
for doc in (root / "docs").glob("*.md"):
    held |= set(re.findall(r"<!-- generated: (bench-[a-z0-9-]+)", doc.read_text(encoding="utf-8")))
if set(names) != held:
    failures.append(f"--list {sorted(names)} against the docs' bench sections {sorted(held)}")

out = subprocess.run([sys.executable, str(script), "--quick", "--only", "goals,kernel-grid,kernel-rows,kernel-peak", bench],
                     check=True, capture_output=True, text=True).stdout
sections = dict((m.group(1), m.group(2)) for m in re.finditer(
    r"<!-- generated: (bench-[a-z0-9-]+);[^>]*-->\n(.*?)<!-- end -->", out, re.S))
asked = {"bench-goals", "bench-kernel-grid", "bench-kernel-rows", "bench-kernel-peak"}
if set(sections) != asked or not asked <= set(names):
    failures.append(f"printed sections {sorted(sections)} against --only {sorted(asked)} and --list {sorted(names)}")


def rows(body):
    lines = [l for l in body.splitlines() if l.startswith("|")]
    return [[c.strip() for c in l.strip("|").split("|")] for l in lines[2:]]


for name in ("bench-kernel-grid", "bench-kernel-rows"):
    table = rows(sections.get(name, ""))
    if len(table) < 3:
        failures.append(f"{name}: {len(table)} rows")
    for r in table:
        try:
            kernel, eigen, ratio = float(r[1]), float(r[2]), float(r[3])
        except (ValueError, IndexError):
            failures.append(f"{name}: row {r} is not all numbers")
            continue
        if not (kernel > 0 and eigen > 0 and abs(ratio - eigen / kernel) <= 0.02 * ratio + 2e-3):
            failures.append(f"{name}: row {r}: ratio is not Eigen / row-major")
peak = rows(sections.get("bench-kernel-peak", ""))
if not peak or peak[0][0] != "fma-peak" or not float(peak[0][1]) > 0:
    failures.append(f"bench-kernel-peak: {peak}")
goals = {r[0]: r[2] for r in rows(sections.get("bench-goals", ""))}
kernel_goal = [v for k, v in goals.items() if k.startswith("the hand-written grid kernel")]
if kernel_goal not in (["met"], ["not met"]):
    failures.append(f"bench-goals: the kernel goal has verdict {kernel_goal}")
if any(v not in ("met", "not met", "–") for v in goals.values()):
    failures.append(f"bench-goals: verdicts {sorted(set(goals.values()))}")

for f in failures:
    print("FAIL", f)
print(f"bench tables: {len(failures)} problems")
sys.exit(1 if failures else 0)
