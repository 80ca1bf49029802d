#!/usr/bin/env python3
"""The accuracy tables of docs/c1.md, from the tests that compute, print and assert them:

- c1-accuracy-exact-solution (section "§4.1"): max |x − f| on a 201 × 201 grid for
  f(u,v) = u cos(u) eᵛ, the biharmonic-load and tetraharmonic methods on two degree-n
  approximations of its C¹ data (ExactSolution41.BothC1MethodsApproximateUCosUExpV,
  tests/c1/test_exact_solution.cpp), beside the paper's n = 7 values;
- c1-accuracy-tetraharmonic: the relative point error of the lu and explicit tetraharmonic
  methods on an exact tetraharmonic polynomial, n = 4 … 16
  (Tetraharmonic.RecoversExactPolynomialBothMethods, tests/c1/test_tetraharmonic.cpp).

Usage: c1_accuracy_table.py [--list] [TEST_C1]  (default build/test_c1; seconds)

Prints the sections of scripts/docs.py (`docs.py --run c1-accuracy`); their digits at rounding
level depend on the build (FMA contraction), so they are a measurement of one build, not compared.
`--list` prints the names.
"""
import pathlib
import re
import subprocess
import sys

from sections import list_sections, print_section

list_sections(["c1-accuracy-exact-solution", "c1-accuracy-tetraharmonic"])
args = [a for a in sys.argv[1:] if not a.startswith("--")]
test = args[0] if args else str(pathlib.Path(__file__).resolve().parent.parent / "build" / "test_c1")
if not pathlib.Path(test).exists():
    sys.exit(f"{test} is missing: build it (ninja -C build test_c1)")


def run(gtest_filter):
    r = subprocess.run([test, "--gtest_filter=" + gtest_filter], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"{test} --gtest_filter={gtest_filter} failed:\n{r.stdout[-2000:]}")
    return r.stdout


exact = re.compile(r"n = (\d+), data = (.*?): \|data patch - f\| = (\S+), biharmonic-load (\S+), "
                   r"tetraharmonic lu (\S+), explicit (\S+)")
rows = ["| n | data | data patch | biharmonic-load | tetraharmonic lu | tetraharmonic explicit |",
        "|---|---|---|---|---|---|",
        "| 7 | paper | | **2.499e-6** | **9.108e-6** | |"]
names = {"Chebyshev-Lobatto interpolation": "A: Chebyshev–Lobatto interpolation", "L2 projection": "B: L² projection"}
for m in exact.finditer(run("ExactSolution41.BothC1MethodsApproximateUCosUExpV")):
    n, data, *errs = m.groups()
    rows.append(f"| {n} | {names.get(data, data)} | " + " | ".join(errs) + " |")
print_section("c1-accuracy-exact-solution", rows)

tetra = re.compile(r"n = (\d+) (lu|explicit) relative error (\S+), residual")
errors = {}
for m in tetra.finditer(run("Tetraharmonic.RecoversExactPolynomialBothMethods")):
    errors.setdefault(int(m.group(1)), {})[m.group(2)] = float(m.group(3))
rows = ["| n | lu | explicit |", "|---|---|---|"]
rows += [f"| {n} | {e['lu']:.1e} | {e['explicit']:.1e} |" for n, e in sorted(errors.items())]
print_section("c1-accuracy-tetraharmonic", rows)
