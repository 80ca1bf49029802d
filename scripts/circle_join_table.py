#!/usr/bin/env python3
"""The circle table of docs/boundaries.md, "Corners and C¹ data": the circle in three arcs
(builder circle-three-arcs, H = -0.5, the area functional) with its corners kept as fitted (the
plain Chebyshev–Lobatto interpolants, `"smooth_corner_angle": 0`) and joined G¹ with the rows'
parameters corrected (the default), per degree: the distance to the cap of radius 2 on the grid
of scripts/evolver_compare.py, the area error |A − A_exact| and the largest edge error
(`boundary_fit[].max_error`).

Usage: circle_join_table.py [--list] [path/to/bpde]  (default build/bpde; seconds)

Prints the table as the section circle-join-fits of scripts/docs.py (`docs.py --run
circle-join`); `--list` prints its name.
"""
import copy
import json
import os
import sys
import tempfile

import evolver_compare as ec
from sections import list_sections, print_section

list_sections(["circle-join-fits"])
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
BPDE = os.path.abspath(ARGS[0] if ARGS else "build/bpde")
GRID = 60  # evolver_compare.py's default --grid
CASE = ec.circle_case()


def cell(degree, kept, work):
    job = copy.deepcopy(CASE.job(degree, "area"))
    del job["boundary"]["fit"]  # the area functional's default
    if kept:
        job["boundary"].update({"smooth_corner_angle": 0, "fit": "interpolation"})
    d = os.path.join(work, "n%d-%s" % (degree, "kept" if kept else "joined"))
    os.makedirs(d)
    with open(os.path.join(d, "job.json"), "w") as f:
        json.dump(job, f)
    p, _ = ec.timed([BPDE, "solve", os.path.join(d, "job.json"), "--out", os.path.join(d, "out")])
    if p.returncode not in (0, 1):
        sys.exit("bpde exited %d on n = %d: %s" % (p.returncode, degree, p.stderr.strip()))
    with open(os.path.join(d, "out", "result.json")) as f:
        result = json.load(f)
    rep = result["report"]
    fit = max(e["max_error"] for e in rep["boundary_fit"])
    if not rep["converged"]:
        turn = max(e.get("end_corner_turn", 0.0) for e in rep["boundary_fit"])
        what = "fold at a corner (turn %.3f°)" % turn if "flips near the corner" in rep.get("message", "") \
            else rep.get("message", "not converged").split(":")[0][:50]
        return "%s, —, %.1e" % (what, fit)
    dist = ec.net_sphere_error(result["net"], CASE.centre, CASE.radius, GRID)
    return "%.1e, %.1e, %.1e" % (dist, abs(rep["area"] - CASE.area_exact), fit)


rows = ["| n | kept: distance, \\|A − A_exact\\|, fit | joined, corrected (default): distance, \\|A − A_exact\\|, fit |",
        "|---|---|---|"]
with tempfile.TemporaryDirectory() as work:
    for n in (4, 5, 6, 8, 10, 12):
        rows.append("| %d | %s | %s |" % (n, cell(n, True, work), cell(n, False, work)))
print_section("circle-join-fits", rows)
