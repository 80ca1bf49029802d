"""Figures of this README: triangular CMC Fig. 4 (the C¹ problem on the equilateral triangle,
n = 6, H = −2, −1.5, −1) coloured by mean curvature with the control nets (Fig. 3: the prescribed
boundary and adjacent lines are the net's outer two rings), and the fold diagram, H against V
along the branch from H = 0 for n = 6, 7, 8, 10, with the folds the example program prints.

    bash scripts/figures.sh 004-cmc-c1-triangle        # or, with the module on PYTHONPATH:
    python3 examples/004-cmc-c1-triangle/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import numpy as np  # noqa: E402

import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402



def c1_job(n, lift=0.25):
    """The job of this example at degree n (main.cpp's c1_triangle): corners on the unit circle at
    0, 120°, 240°, every point at its barycentric position, the ring of smallest index 1 at
    z = lift, the rest at z = 0; boundary and adjacent ring prescribed."""
    c = [np.array([np.cos(a), np.sin(a), 0.0]) for a in (0.0, 2 * np.pi / 3, 4 * np.pi / 3)]
    pts = []
    for i in range(n, -1, -1):  # FORMATS.md order: i from n down, j from n - i down
        for j in range(n - i, -1, -1):
            k = n - i - j
            p = (i * c[0] + j * c[1] + k * c[2]) / n
            p[2] = lift if min(i, j, k) == 1 else 0.0
            pts.append(p.tolist())
    return {"net": {"type": "triangular", "degree": n, "points": pts}, "fixed": "boundary+adjacent",
            "problem": {"kind": "cmc", "H": 0.0, "solver": "newton"}, "samples": 10}


def main():
    out = fg.out_dir(default=HERE)
    panels = []
    for name, H in (("n6-a-H-2", "−2"), ("n6-b-H-1.5", "−1.5"), ("n6-c-H-1", "−1")):
        net, report = bezierpde.solve(fg.load_json(HERE / f"{name}.json"))
        panels.append(fg.Panel(net, f"Fig. 4: n = 6, H = {H}", elev=40, azim=-75))
    fg.wrote(out / "fig4.png", fg.surfaces(out / "fig4.png", panels))

    with tempfile.TemporaryDirectory() as tmp:
        tables = fg.example_tables("004-cmc-c1-triangle", HERE, tmp + "/out")
    rows = tables["cmc-c1-triangle-fold"]["tables"][0]
    folds = {}
    for r in rows:
        for col in ("fold H < 0", "fold H > 0"):
            if "reached" not in r[col]:
                folds.setdefault(int(r["n"]), []).append(fg.number(r[col]))
    curves, points = [], []
    for n in (6, 7, 8, 10):
        job = c1_job(n)
        lo, hi = fg.fold_H(job, -3.0), fg.fold_H(job, 3.0)  # the fold, or ±3 when there is none
        grid = np.concatenate([np.linspace(lo, 0, 16), np.linspace(0, hi, 16)[1:], [0.995 * lo, 0.995 * hi]])
        Hs, Vs = fg.branch(job, np.sort(grid))
        curves.append((f"n = {n}" + ("" if n in folds else " (no fold for |H| ≤ 3)"), Hs, Vs))
        for h in folds.get(n, []):  # the program's fold, its V from a solve just inside it
            Hf, Vf = fg.branch(job, [0.999 * h])
            points += [(Vf[0], h)] if Vf else []
    size = fg.fold_diagram(out / "fold.png", curves, folds=[("folds of example_004_cmc_c1_triangle", points)],
                           title="C¹ triangle (lift 0.25): H against V along the branch from H = 0")
    fg.wrote(out / "fold.png", size)


if __name__ == "__main__":
    main()
