"""Smoothing PDE splines and B-spline extremals from Python: the two-cylinder blend of
examples/003-blend-cylinders step by step, through the solver entry points (a notebook to copy).

Run after building (from any folder: the example's files are found from this file's place):
    PYTHONPATH=build/python python3 examples/003-python-blend/blend.py
Each block below is one notebook cell.
"""

import json
import pathlib

import numpy as np

import bezierpde

EXAMPLES = pathlib.Path(__file__).resolve().parent.parent  # examples/

# %% The blend config of Fig. 2c (nine approximation points, epsilon = 1e-3, a = 10), as `bpde blend` runs it.
with open(EXAMPLES / "003-blend-cylinders" / "fig2c.json", encoding="utf-8") as f:
    config = json.load(f)
net, report = bezierpde.blend(config)
print(f"bpde blend: J = {report['energy']:.9f}, max data error {report['max_data_error']:.3e}, "
      f"converged: {report['converged']}")

# %% The same problem built from numpy arrays: the cylinders f(x, y) = (2y - 1, 2 cos 2 pi x, 2 sin 2 pi x)
# and g(x, y) = (2y + 1, cos 2 pi x, sin 2 pi x) give the edges at the nodes x_i = i/8, and the data are
# nine points of the circle of radius 1/2 in the plane X = 0.
problem = bezierpde.SmoothingSplineProblem()
problem.k, problem.l = 8, 4
problem.a, problem.epsilon = 10.0, 1e-3
x = np.arange(problem.k + 1) / problem.k
c, s = np.cos(2 * np.pi * x), np.sin(2 * np.pi * x)
problem.y0_value = np.column_stack([np.ones_like(x), 2 * c, 2 * s])  # f(x, 1)
problem.y1_value = np.column_stack([np.ones_like(x), c, s])  # g(x, 0)
problem.y0_dy = problem.y1_dy = np.tile([2.0, 0.0, 0.0], (problem.k + 1, 1))
t = np.arange(9) / 9
problem.points = np.column_stack([t, np.full(9, 0.5)])
problem.data = np.column_stack([np.zeros(9), 0.5 * np.cos(2 * np.pi * t), 0.5 * np.sin(2 * np.pi * t)])
result = bezierpde.solve_smoothing_spline(problem)
print(result.summary)
print(f"J = {result.functional:.9f}, |sigma|_L^2 = {result.energy:.6f}, max data error {result.max_data_error:.3e}")
same = np.max(np.abs(result.spline.to_bspline_net().points - bezierpde.points(net)))
print("the same spline as bpde blend (edges recomputed here):", same < 1e-12)

# %% As epsilon -> 0 the spline passes through the data: the error becomes linear in epsilon (the
# ratio settles).
for eps in (1e-3, 1e-4, 1e-5, 1e-6, 1e-7):
    problem.epsilon = eps
    r = bezierpde.solve_smoothing_spline(problem)
    print(f"epsilon = {eps:.0e}: max |sigma(a_i) - beta_i| = {r.max_data_error:.3e}, "
          f"ratio to epsilon {r.max_data_error / eps:.4f}")
problem.epsilon = 1e-3

# %% Factor once, solve for other data: a circle of radius 3/4 instead of 1/2.
solver = bezierpde.SmoothingSplineSolver(problem)
problem.data = 1.5 * problem.data
wider = solver.solve(problem)
print(f"radius 3/4: J = {wider.functional:.9f}, sigma(0, 1/2) = {np.round(wider.spline.evaluate(0.0, 0.5), 6)}")
problem.data = problem.data / 1.5

# %% The sampled surface as (V, F, H) arrays and the spline as a bicubic B-spline net.
V, F, H = result.spline.sample(40)
print("vertices", V.shape, "triangles", F.shape, f"mean curvature in [{H.min():.3f}, {H.max():.3f}]")
bspline = result.spline.to_bspline_net()
print(bspline, "knots in u:", len(bspline.knots_u))

# %% The blend as a B-spline net is data for the B-spline solvers: the biharmonic extremal with the
# blend's boundary ring prescribed (B-spline Euler-Lagrange). It has no data term and the least
# biharmonic energy of all nets with that ring; as the ring includes the seam x = 0, 1 that the blend
# leaves free, it is another, narrower surface.
options = bezierpde.BSplineExtremalOptions()
options.fixed = "boundary"
extremal = bezierpde.solve_bspline_extremal(bspline, "biharmonic", options)
print(extremal.summary.status.text, f"biharmonic energy {extremal.energy:.6f}",
      f"(the blend's: {bezierpde.energy(bspline, 'biharmonic')['energy']:.6f})")
for name, surface in (("blend", bspline), ("extremal", extremal.net)):
    waist = surface.evaluate(0.25, 0.5)
    print(f"{name} at (1/4, 1/2): {np.round(waist, 6)}, radius |(y, z)| = {np.hypot(waist[1], waist[2]):.6f}")

# %% Bad input is an exception of one hierarchy: a ParameterError (an InvalidInput, a ValueError).
problem.epsilon = 0.0
try:
    bezierpde.solve_smoothing_spline(problem)
except bezierpde.InvalidInput as e:
    print(type(e).__name__, "->", e)
try:
    problem.points = np.zeros((9, 3))
except bezierpde.SizeError as e:
    print(type(e).__name__, "->", e)
