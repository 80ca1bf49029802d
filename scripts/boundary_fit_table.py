#!/usr/bin/env python3
"""The table of docs/boundaries.md: the fit error of boundary curves against the degree, read from
the `boundary_fit` report of `bpde solve` jobs in the "boundary" form (FORMATS.md "Boundary
curves"). Usage: python3 scripts/boundary_fit_table.py [--list] [path/to/bpde]  (default build/bpde).
Prints the table as the section boundary-fit-degree of scripts/docs.py (`docs.py --run
boundary-fit`; about a minute)."""
import json
import math
import subprocess
import sys
import tempfile
from pathlib import Path

from sections import list_sections, print_section

list_sections(["boundary-fit-degree"])
BPDE = sys.argv[1] if len(sys.argv) > 1 else "build/bpde"
THIRD = 2 * math.pi / 3


def max_error(boundary, edge=None):
    job = {"boundary": boundary, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, "samples": 2}
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "job.json"
        p.write_text(json.dumps(job))
        r = subprocess.run([BPDE, "solve", str(p), "--out", str(Path(d) / "out")], capture_output=True, text=True)
        if r.returncode not in (0, 1):  # 1: the extremal did not converge; its boundary is fitted all the same
            sys.exit(f"bpde exited {r.returncode} on {json.dumps(boundary)[:200]}: {r.stderr.strip()}")
        fit = json.loads((Path(d) / "out" / "result.json").read_text())["report"]["boundary_fit"]
    return max(e["max_error"] for e in fit) if edge is None else fit[edge]["max_error"]


def bound(n, theta):
    # sqrt(2) θ^(n+1) / ((n+1)! 4^n): the remainder bound of Chebyshev–Lobatto interpolation
    return math.sqrt(2) * theta ** (n + 1) / (math.factorial(n + 1) * 4.0 ** n)


def helix(n):
    edges = [{"type": "helix", "center": [0, 0, 0], "axis": [0, 0, 1], "radius": 1, "angles": [0, math.pi / 2],
              "pitch": 0.5},
             {"type": "segment", "from": [0, 1, 0.125], "to": [0, 0, 0]},
             {"type": "segment", "from": [0, 0, 0], "to": [1, 0, 0]}]
    return {"type": "triangular", "degree": n, "edges": edges}


rows = ["| n | circle-three-arcs, interpolation | least-squares | bound (θ = 2π/3) | "
        "helix arc (θ = π/2), interpolation | bound (θ = π/2) | circle-three-arcs, joined (default) |",
        "|---|---|---|---|---|---|---|"]
for n in range(3, 17):
    joined = {"type": "triangular", "degree": n, "builder": "circle-three-arcs"}
    circ = dict(joined, smooth_corner_angle=0)  # the corners as fitted: the plain interpolants
    ls = dict(circ, fit="least-squares")
    rows.append(f"| {n} | {max_error(circ):.2e} | {max_error(ls):.2e} | {bound(n, THIRD):.2e} | "
                f"{max_error(helix(n), 0):.2e} | {bound(n, math.pi / 2):.2e} | {max_error(joined):.2e} |")
print_section("boundary-fit-degree", rows)
