#!/usr/bin/env python3
"""The tables of docs/boundaries.md, "Samples without parameters": a wavy closed space curve (A), cut
into the four edges of a tensor net and given as 61 samples per edge (uniform in the curve's own
angle), fitted three ways (the report's `boundary_fit` of `bpde solve` jobs in the "boundary"
form, FORMATS.md "Boundary curves"):
  - "chord-length": the normalised chord length, kept (`"parameters": "chord-length"`);
  - corrected: no parameters given (the default: the chord length, corrected to foot points);
  - given: the samples' own angle, mapped onto [0, 1].
With --solve instead the area functional at H = 0 (the minimal surface spanning the curve) on the
net of each fit, n = 8, 10, 12, for curve A and a second one (B): status, CPU seconds and the
mean-curvature range away from the corners (about 25 minutes).
The tables are printed as the sections sample-fit-degree and (--solve) sample-solve-area of
scripts/docs.py (`docs.py --run sample-fit`, `--run sample-solve`); `--list` prints their names.
Usage: python3 scripts/sample_fit_table.py [--list] [--solve] [path/to/bpde]  (default build/bpde);
python3 scripts/sample_fit_table.py --job CURVE N MODE [PROBLEM-JSON] prints the job of one case
(CURVE A or B; MODE chord-length, corrected or given; the problem defaults to the area
functional at H = 0)."""
import json
import math
import sys
import tempfile
from pathlib import Path

from sections import cpu_run, list_sections, print_section

SOLVE = "--solve" in sys.argv[1:]
list_sections(["sample-solve-area"] if SOLVE else ["sample-fit-degree"])
args = [a for a in sys.argv[1:] if a != "--solve"]
args = [] if "--job" in sys.argv[1:] else args
BPDE = args[0] if args else "build/bpde"
K = 60  # samples per edge: K + 1 points


# Two wavy closed curves, r(θ) and z(θ) trigonometric, and the angles of the four corners
# (counter-clockwise seen from +z; not symmetric on purpose). B came from a random sweep of
# boundaries (rounded), where the chord-length fit made the area functional fail.
CURVES = {
    "A": ((0.25, 0.2, 0.3, 0.2, -0.25), [0.0, 1.45, 3.3, 4.75, 2 * math.pi]),
    "B": ((0.2, 0.27, -0.35, 0.16, 0.12), [0.0, 1.435, 3.07, 4.82, 2 * math.pi]),
}


def curve(name, th):
    (a2, a3, b2, c2, b3), _ = CURVES[name]
    r = 1 + a2 * math.cos(2 * th) + a3 * math.sin(3 * th)
    z = b2 * math.cos(2 * th) + c2 * math.sin(2 * th) + b3 * math.cos(3 * th)
    return [r * math.cos(th), r * math.sin(th), z]


def boundary(n, mode, name="A"):
    cuts = CURVES[name][1]
    edges = []
    for e in range(4):
        a, b = cuts[e], cuts[e + 1]
        th = [a + (b - a) * k / K for k in range(K + 1)]
        edge = {"type": "samples", "points": [curve(name, t) for t in th]}
        if e == 3:
            edge["points"][-1] = curve(name, 0.0)  # the first corner, bit for bit
        if mode == "chord-length":
            edge["parameters"] = "chord-length"
        elif mode == "given":
            edge["parameters"] = th
        edges.append(edge)
    return {"type": "tensor", "degree": [n, n], "edges": edges}


def run(n, mode, problem, name="A"):
    job = {"boundary": boundary(n, mode, name), "problem": problem, "samples": 40}
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "job.json"
        p.write_text(json.dumps(job))
        done, seconds = cpu_run([BPDE, "solve", str(p), "--out", str(Path(d) / "out")])
        rc = done.returncode
        if rc not in (0, 1):
            sys.exit(f"bpde exited {rc} on n = {n}, {mode}")
        return json.loads((Path(d) / "out" / "result.json").read_text())["report"], seconds


if "--job" in sys.argv[1:]:  # --job CURVE N MODE [PROBLEM-JSON]: print that job instead (one case)
    i = sys.argv.index("--job")
    problem = json.loads(sys.argv[i + 4]) if len(sys.argv) > i + 4 else {"kind": "cmc", "H": 0, "functional": "area"}
    print(json.dumps({"boundary": boundary(int(sys.argv[i + 2]), sys.argv[i + 3], sys.argv[i + 1]), "problem": problem,
                      "samples": 40}))
    sys.exit(0)

MODES = ["chord-length", "corrected", "given"]
if not SOLVE:
    rows = ["| n | chord length | corrected (default) | given (the curve's angle) | iterations of the correction |",
            "|---|---|---|---|---|"]
    for n in range(4, 17, 2):
        errs, its = [], ""
        for mode in MODES:
            rep, _ = run(n, mode, {"kind": "extremal", "energy": {"name": "dirichlet"}})
            errs.append(max(e["max_error"] for e in rep["boundary_fit"]))
            if mode == "corrected":
                its = ", ".join(str(e.get("corrections", "-")) for e in rep["boundary_fit"])
        rows.append(f"| {n} | " + " | ".join(f"{x:.1e}" for x in errs) + f" | {its} |")
    print_section("sample-fit-degree", rows)
else:
    rows = ["| curve | n | parameters | boundary error | status | first variation | seconds | mean curvature |",
            "|---|---|---|---|---|---|---|---|"]
    for name in CURVES:
        for n in (8, 10, 12):
            for mode in ("chord-length", "corrected"):
                rep, s = run(n, mode, {"kind": "cmc", "H": 0, "functional": "area"}, name)
                mc = rep["mean_curvature"]
                status = "converged" if rep["converged"] else "not converged"
                err = max(e["max_error"] for e in rep["boundary_fit"])
                rows.append(f"| {name} | {n} | {mode} | {err:.1e} | {status} | {rep['residual']:.1e} | {s:.1f} | "
                            f"{mc['min']:.2g} … {mc['max']:.2g} |")
                print(rows[-1], file=sys.stderr, flush=True)
    print_section("sample-solve-area", rows, ["seconds"])
