"""Figures of this README: triangular CMC Fig. 1 (the circle in three arcs, degree 4, H = −1.5,
−1, −0.5) coloured by mean curvature with the control nets, and the fold diagram: H against V
along the branch from H = 0 for several degrees, with the folds the example program prints.

    bash scripts/figures.sh 004-cmc-circle        # or, with the module on PYTHONPATH:
    python3 examples/004-cmc-circle/figures.py [OUT_DIR]   # default: this folder
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


def main():
    out = fg.out_dir(default=HERE)
    panels = []
    for name, H in (("n4-a-H-1.5", "−1.5"), ("n4-b-H-1", "−1"), ("n4-c-H-0.5", "−0.5")):
        net, report = bezierpde.solve(fg.load_json(HERE / f"{name}.json"))
        panels.append(fg.Panel(net, f"n = 4, H = {H}", elev=20))
    fg.wrote(out / "fig1.png", fg.surfaces(out / "fig1.png", panels))

    curves, folds = [], []
    for n in (4, 6, 8, 12):
        job = {"boundary": {"type": "triangular", "degree": n, "builder": "circle-three-arcs"}, "fixed": "boundary",
               "problem": {"kind": "cmc", "H": 0.0, "solver": "newton"}, "samples": 10}
        h = fold_H = fg.fold_H(job, -3.0)
        grid = np.concatenate([np.linspace(0.0, 0.97 * h, 14), 0.97 * h + (h - 0.97 * h) * np.array([0.5, 0.9, 0.99])])
        Hs, Vs = fg.branch(job, np.concatenate([grid, -grid[1:]]))
        curves.append((f"n = {n} (fold H = {fold_H:.4f})", Hs, Vs))
    with tempfile.TemporaryDirectory() as tmp:
        tables = fg.example_tables("004-cmc-circle", HERE, tmp)
    rows = tables["cmc-circle-fold"]["tables"][0]
    folds.append(("folds of example_004_cmc_circle (H < 0)",
                  [(fg.number(r["V at the fold (H < 0)"]), fg.number(r["fold H < 0"])) for r in rows]))
    size = fg.fold_diagram(out / "fold.png", curves, folds=folds,
                           title="circle in three arcs: the branch from H = 0 and its folds")
    fg.wrote(out / "fold.png", size)


if __name__ == "__main__":
    main()
