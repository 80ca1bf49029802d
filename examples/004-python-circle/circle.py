"""bezierpde from Python, step by step: the circle of triangular CMC Fig. 1 (a notebook to copy).

Run after building (from any folder: the example's files are found from this file's place):
    PYTHONPATH=build/python python3 examples/004-python-circle/circle.py [OUT_DIR]
Each block below is one notebook cell.
"""

import json
import pathlib
import sys

import numpy as np

import bezierpde

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent  # examples/

out_dir = sys.argv[1] if len(sys.argv) > 1 else "out/004-python-circle"

# %% A job is the dict of a JOB.json file: here the circle split into three arcs, degree 4, H = -1.
with open(EXAMPLES / "004-cmc-circle" / "n4-b-H-1.json", encoding="utf-8") as f:
    job = json.load(f)
print("job:", job["problem"], "degree", job["net"]["degree"])

# %% Solve it as `bpde solve` does: the net and the report of result.json (as dicts).
net, report = bezierpde.solve(job, out=out_dir + "/solve")  # `out` also writes the job folder
print(f"D_H = {report['energy']:.12f}, V = {report['volume']:.12f}, converged: {report['converged']}")
print("mean curvature over the samples:", report["mean_curvature"])

# %% The control points as an N x 3 array, and the sampled surface as (V, F, H) arrays.
P = bezierpde.points(net)
V, F, H = bezierpde.sample(net, samples=30)
print("points", P.shape, "vertices", V.shape, "triangles", F.shape, "H per vertex", H.shape)
print(f"H at the centre vertex: {H[len(H) // 2]:.6f}")

# %% The other commands: energies and the CGAL checks of the surface.
print("Dirichlet energy:", bezierpde.energy(net, "dirichlet")["energy"])
print("D + 2HV at H = -1:", bezierpde.energy(net, "cmc", H=-1.0)["DH"], "(the report: D_H =", report["energy"], ")")
print("CGAL:", bezierpde.check(net, samples=30))

# %% The solver itself, with its Options and Summary: continue H to the fold of this boundary.
data = bezierpde.net_from_dict(job["net"])
options = bezierpde.CmcOptions()
options.H = -3.0  # beyond the fold at |H| ~ 1.556: the solver stops there and says so
result = bezierpde.solve_cmc(data, options)
print(result.summary.status.text, "at H =", result.H, "-", result.summary.message)

# %% At H = 0 the CMC functional D + 2HV is the Dirichlet energy: its critical point is the Dirichlet
# extremal of the same boundary, which solve_extremal computes directly (one factorisation).
flat = bezierpde.solve_cmc(data, bezierpde.CmcOptions())
extremal = bezierpde.solve_extremal(data, "dirichlet", "boundary")
print("Dirichlet extremal:", extremal.summary.status.text, f"energy {extremal.energy:.12f},",
      "max |extremal - CMC at H = 0| =", f"{np.max(np.abs(extremal.net.points - flat.net.points)):.1e}")

# %% Bad input is an exception of one hierarchy (bezierpde.InvalidInput is a ValueError).
try:
    bezierpde.solve(dict(job, samples=0))
except bezierpde.InvalidInput as e:
    print(type(e).__name__, "->", e)

# %% A net edited in place: points is a view of the C++ net.
data.points[:, 2] += 0.1  # lift the whole boundary by 0.1
lifted = bezierpde.solve_cmc(data, bezierpde.CmcOptions())  # H = 0: the Dirichlet extremal
print("lifted boundary, H = 0:", lifted.summary.status.text, "z of the first point", lifted.net.points[0, 2])
assert np.isclose(lifted.net.points[0, 2], 0.1)
