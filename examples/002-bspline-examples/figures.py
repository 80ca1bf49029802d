"""Figures of this README: B-spline surfaces of §5 (a biquintic net with knots [0⁶, ½, 1⁶] in
both directions, 7 x 7 points) from one boundary ring, as bpde solve builds them: the Coons PDE
solution x_uuvv = 0 (Algorithm 2) and the biharmonic, laplacian-squared and Dirichlet extremals,
coloured by mean curvature, with their control nets.

The ring: x, y at the Greville abscissae, z = (Re((u+iv)⁵) + (u²+v²)uv)/4 there (our choice; the
program's table uses its own "generic boundary", which it does not write out).

    bash scripts/figures.sh 002-bspline-examples        # or, with the module on PYTHONPATH:
    python3 examples/002-bspline-examples/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))


import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402

PROBLEMS = [({"kind": "pde", "operator": {"name": "coons"}, "method": "lu"}, "Coons PDE x_uuvv = 0"),
            ({"kind": "extremal", "energy": {"name": "biharmonic"}}, "biharmonic extremal"),
            ({"kind": "extremal", "energy": {"name": "laplacian-squared"}}, "laplacian-squared extremal"),
            ({"kind": "extremal", "energy": {"name": "dirichlet"}}, "Dirichlet extremal")]


def ring_net():
    p, knots = 5, [0.0] * 6 + [0.5] + [1.0] * 6
    g = [sum(knots[i + 1:i + p + 1]) / p for i in range(len(knots) - p - 1)]  # Greville abscissae
    pts = []
    for i, u in enumerate(g):
        for j, v in enumerate(g):
            ring = i in (0, len(g) - 1) or j in (0, len(g) - 1)
            z = 0.25 * (((u + 1j * v) ** 5).real + (u * u + v * v) * u * v)
            pts.append([u, v, z if ring else 0.0])
    return {"type": "bspline", "degree": [p, p], "knots": [knots, knots], "points": pts}


def main():
    out = fg.out_dir(default=HERE)
    panels = []
    for problem, title in PROBLEMS:
        net, report = bezierpde.solve({"net": ring_net(), "fixed": "boundary", "problem": problem})
        panels.append(fg.Panel(net, title + ("" if report["converged"] else " (not converged)"), elev=30, azim=-120))
    fg.wrote(out / "section5.png", fg.surfaces(out / "section5.png", panels))



if __name__ == "__main__":
    main()
