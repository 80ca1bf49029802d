#!/usr/bin/env python3
"""The table of docs/boundaries.md, "Geometric fits", from the test that computes and asserts it:
the largest distance of 257 points of each curve from its degree-n fit, by interpolation at the
Chebyshev–Lobatto nodes and by the geometric fit (brute-force distances;
FitBoundary.GeometricFitFollowsTheCurveNotItsParametrisation, tests/boundaries/test_fit_boundary.cpp).

Usage: geometric_fit_table.py [--list] [TEST_BOUNDARIES]  (default build/test_boundaries; seconds)

Prints the section geometric-fit-distances of scripts/docs.py (`docs.py --run geometric-fit`); its
digits at rounding level depend on the build, so it is a measurement of one build, not compared.
"""
import pathlib
import re
import subprocess
import sys

from sections import list_sections, print_section

list_sections(["geometric-fit-distances"])
args = [a for a in sys.argv[1:] if not a.startswith("--")]
test = args[0] if args else str(pathlib.Path(__file__).resolve().parent.parent / "build" / "test_boundaries")
if not pathlib.Path(test).exists():
    sys.exit(f"{test} is missing: build it (ninja -C build test_boundaries)")
r = subprocess.run([test, "--gtest_filter=FitBoundary.GeometricFitFollowsTheCurveNotItsParametrisation"],
                   capture_output=True, text=True)
if r.returncode != 0:
    sys.exit(f"{test} failed:\n{r.stdout[-2000:]}")
names = ["120° arc of the unit circle", "catenoid edge w = 0 (the tests' triangular piece)", "(cos 3t, sin 3t, t²/2)"]
rows = ["| curve | n | interpolation | geometric |", "|---|---|---|---|"]
last = None
for m in re.finditer(r"geometric fit: curve (\d+) n = (\d+) interpolation (\S+) geometric (\S+)", r.stdout):
    c, n, interp, geo = int(m.group(1)), m.group(2), m.group(3), m.group(4)
    rows.append(f"| {names[c] if c != last else ''} | {n} | {interp} | {geo} |")
    last = c
print_section("geometric-fit-distances", rows)
