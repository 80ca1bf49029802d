#!/usr/bin/env python3
"""A sweep of random boundaries through `bpde solve` (docs/boundaries.md, "Samples without
parameters" and "Corners and C¹ data"): 24 wavy closed space curves (random trigonometric radius
and height), each cut into the edges of a triangular or tensor net (3 or 4, at jittered angles)
and given as 61 samples per edge without parameters; a random degree 4..8, H (mostly 0) and
functional (area, mean-curvature, dirichlet).

Without --corners each job runs twice: with the samples' chord length kept (`"parameters":
"chord-length"`) and with the default (the chord length corrected to foot points); one table row
per job gives its outcome both ways (status, CPU seconds, the mean-curvature range away from the
corners, the start of the message): the section boundary-sweep-parameters (about 10 minutes).
With --corners only the area jobs run, with the corners kept as fitted (`"smooth_corner_angle":
0`) and joined G¹ (the default), each row with the fitted edges' turns at the corners: the
section corner-sweep-join (a few minutes). Seconds are the CPU seconds of the `bpde solve`
process; a job stops after 900 s of wall time.

The sections are those of scripts/docs.py (`docs.py --run boundary-sweep`, `--run corner-sweep`);
`--list` prints their names.
Usage: python3 scripts/random_boundary_sweep.py [--list] [--corners] [path/to/bpde] [seed]
(default build/bpde 7)."""
import json
import math
import random
import sys
import tempfile
from pathlib import Path

from sections import cpu_run, list_sections, print_section

CORNERS = "--corners" in sys.argv[1:]
list_sections(["corner-sweep-join"] if CORNERS else ["boundary-sweep-parameters"])
ARGS = [a for a in sys.argv[1:] if not a.startswith("--")]
BPDE = ARGS[0] if ARGS else "build/bpde"
random.seed(int(ARGS[1]) if len(ARGS) > 1 else 7)
K = 60
TIMEOUT = 900  # wall seconds of one job (a busy machine stretches them; the table gives CPU seconds)


def make_job():
    tri = random.random() < 0.5
    n = random.choice([4, 5, 6, 7, 8])
    H = random.choice([0, 0, round(random.uniform(-1.2, 1.2), 3)])
    fn = random.choice(["area", "area", "mean-curvature", "dirichlet"])
    ne = 3 if tri else 4
    a = [random.uniform(-0.3, 0.3) for _ in range(4)]
    b = [random.uniform(-0.4, 0.4) for _ in range(4)]
    cuts = [k / ne + random.uniform(-0.05, 0.05) * (k > 0) for k in range(ne)] + [1.0]

    def c(s):
        t = 2 * math.pi * s
        r = 1 + a[0] * math.cos(2 * t) + a[1] * math.sin(3 * t)
        z = b[0] * math.cos(2 * t) + b[1] * math.sin(2 * t) + b[2] * math.cos(3 * t)
        return [r * math.cos(t), r * math.sin(t), z]

    edges = [{"type": "samples", "points": [c(cuts[e] + (cuts[e + 1] - cuts[e]) * k / K) for k in range(K + 1)]}
             for e in range(ne)]
    for e in range(ne):
        edges[e]["points"][-1] = edges[(e + 1) % ne]["points"][0]  # the corners bit for bit
    job = {"boundary": {"type": "triangular" if tri else "tensor", "degree": n if tri else [n, n], "edges": edges},
           "fixed": "boundary", "problem": {"kind": "cmc", "H": H, "functional": fn}, "samples": 30}
    return job, f"{'triangular' if tri else 'tensor'} {n}", H, fn


def solve(job):
    """(report or None, seconds, what went wrong or None)."""
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "job.json"
        p.write_text(json.dumps(job))
        done, s = cpu_run([BPDE, "solve", str(p), "--out", str(Path(d) / "out")], timeout=TIMEOUT)
        if done is None:
            return None, s, f"timeout ({TIMEOUT} s)"
        if done.returncode not in (0, 1):
            return None, s, f"exit {done.returncode}"
        return json.loads((Path(d) / "out" / "result.json").read_text())["report"], s, None


def outcome(job):
    r, s, bad = solve(job)
    if bad:
        return bad
    mc = r["mean_curvature"]
    what = "converged" if r["converged"] else r["message"].split(":")[0].split(";")[0][:60]
    return f"{what}, {s:.1f} s, H_x {mc['min']:.3g} … {mc['max']:.3g}"


def corner_outcome(job):
    r, s, bad = solve(job)
    if bad:
        return bad, None
    fit = max(e["max_error"] for e in r["boundary_fit"])
    if r["converged"]:
        what = "converged"
    elif "flips near the corner" in r["message"]:
        what = "fold at a corner"
    else:
        what = f"{r['message'].split(':')[0].split(';')[0][:60]} ({r['residual']:.1e})"
    turns = [e.get("end_corner_turn", 0.0) for e in r["boundary_fit"]]
    return f"{what}, {s:.1f} s, fit {fit:.1e}", turns


def main():
    if CORNERS:
        rows = ["| job | net, H | turns | kept | joined |", "|---|---|---|---|---|"]
    else:
        rows = ["| job | net, H, functional | chord length kept | corrected (default) |", "|---|---|---|---|"]
    for j in range(24):
        job, net, H, fn = make_job()
        if not CORNERS:
            chord = json.loads(json.dumps(job))
            for e in chord["boundary"]["edges"]:
                e["parameters"] = "chord-length"
            rows.append(f"| {j} | {net}, H = {H}, {fn} | {outcome(chord)} | {outcome(job)} |")
        elif fn == "area":
            kept = json.loads(json.dumps(job))
            kept["boundary"]["smooth_corner_angle"] = 0
            k, _ = corner_outcome(kept)
            g, turns = corner_outcome(job)
            t = (", ".join(f"{x:.2f}" for x in turns) if net.startswith("triangular")
                 else f"{min(turns):.3f} … {max(turns):.3f}")
            rows.append(f"| {j} | {net}, {H:g} | {t} | {k} | {g} |")
        else:
            continue
        print(rows[-1], file=sys.stderr, flush=True)
    if CORNERS:
        print_section("corner-sweep-join", rows, ["kept", "joined"])
    else:
        print_section("boundary-sweep-parameters", rows, ["chord length kept", "corrected (default)"])


main()
