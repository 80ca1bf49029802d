#!/usr/bin/env python3
"""The table of docs/pde_accuracy.md, "Errors against exact solutions": the relative error of the
explicit, lu and mould PDE solvers against exact polynomial solutions, beside the data-rounding
floor, per operator and degree.

Usage: pde_accuracy_table.py [--list] [TEST_PDE]  (default build/test_pde)

Runs the test PdeAccuracy.Table of tests/pde/test_accuracy_table.cpp (which computes the table,
prints it and asserts every entry below 50 × floor + 1e-14; about 10 s) and prints its table as
the section pde-accuracy-errors of scripts/docs.py (`docs.py --run pde-accuracy`). The digits at
rounding level depend on the build (FMA contraction), so the table is a measurement of one build,
not compared by the docs check. `--list` prints the section name.
"""
import pathlib
import subprocess
import sys

from sections import list_sections, print_section

list_sections(["pde-accuracy-errors"])
args = [a for a in sys.argv[1:] if not a.startswith("--")]
test = args[0] if args else str(pathlib.Path(__file__).resolve().parent.parent / "build" / "test_pde")
if not pathlib.Path(test).exists():
    sys.exit(f"{test} is missing: build it (ninja -C build test_pde)")
r = subprocess.run([test, "--gtest_filter=PdeAccuracy.Table"], capture_output=True, text=True)
if r.returncode != 0:
    sys.exit(f"{test} --gtest_filter=PdeAccuracy.Table failed:\n{r.stdout[-2000:]}")
print_section("pde-accuracy-errors", [line for line in r.stdout.splitlines() if line.startswith("|")])
