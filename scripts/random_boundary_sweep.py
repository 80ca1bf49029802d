#!/usr/bin/env python3
"""A sweep of random boundaries through `bpde solve` (docs/boundaries.md, "Samples without
parameters"): 24 wavy closed space curves (random trigonometric radius and height), each cut into
the edges of a triangular or tensor net (3 or 4, at jittered angles) and given as 61 samples per
edge without parameters; a random degree 4..8, H (mostly 0) and functional (area, mean-curvature,
dirichlet). Each job runs twice: with the samples' chord length kept (`"parameters":
"chord-length"`) and with the default (the chord length corrected to
foot points). Prints one table row per job: its outcome both ways (exit status, seconds, the
mean-curvature range away from the corners, the start of the message).
Usage: python3 scripts/random_boundary_sweep.py [path/to/bpde] [seed]  (default build/bpde 7).
About 10 minutes; a job stops after 300 s."""
import json
import math
import random
import subprocess
import sys
import tempfile
import time
from pathlib import Path

BPDE = sys.argv[1] if len(sys.argv) > 1 else "build/bpde"
random.seed(int(sys.argv[2]) if len(sys.argv) > 2 else 7)
K = 60


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
    return job, f"{'triangular' if tri else 'tensor'} {n}, H = {H}, {fn}"


def run(job):
    with tempfile.TemporaryDirectory() as d:
        p = Path(d) / "job.json"
        p.write_text(json.dumps(job))
        t = time.time()
        try:
            rc = subprocess.run([BPDE, "solve", str(p), "--out", str(Path(d) / "out")], capture_output=True,
                                timeout=300).returncode
        except subprocess.TimeoutExpired:
            return "timeout (300 s)"
        s = time.time() - t
        if rc not in (0, 1):
            return f"exit {rc}"
        r = json.loads((Path(d) / "out" / "result.json").read_text())["report"]
        mc = r["mean_curvature"]
        what = "converged" if r["converged"] else r["message"].split(":")[0].split(";")[0][:60]
        return f"{what}, {s:.1f} s, H_x {mc['min']:.3g} … {mc['max']:.3g}"


print("| job | net, H, functional | chord length kept | corrected (default) |")
print("|---|---|---|---|")
for j in range(24):
    job, label = make_job()
    chord = json.loads(json.dumps(job))
    for e in chord["boundary"]["edges"]:
        e["parameters"] = "chord-length"
    print(f"| {j} | {label} | {run(chord)} | {run(job)} |", flush=True)
