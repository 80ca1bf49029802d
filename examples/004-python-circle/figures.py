"""Figures of this README: the three steps of circle.py as surfaces coloured by mean curvature
with their control nets (bezierpde.solve at H = −1; solve_cmc run on to the fold; the boundary
lifted by 0.1, H = 0), and H against V along the branch that solve_cmc follows.

    bash scripts/figures.sh 004-python-circle        # or, with the module on PYTHONPATH:
    python3 examples/004-python-circle/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import numpy as np  # noqa: E402

import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402


def main():
    out = fg.out_dir(default=HERE)
    job = fg.load_json(HERE.parent / "004-cmc-circle" / "n4-b-H-1.json")
    net, report = bezierpde.solve(job)
    data = bezierpde.net_from_dict(job["net"])
    options = bezierpde.CmcOptions()
    options.H = -3.0
    fold = bezierpde.solve_cmc(data, options)
    data.points[:, 2] += 0.1
    lifted = bezierpde.solve_cmc(data, bezierpde.CmcOptions())
    panels = [fg.Panel(net, f"solve: H = −1, V = {report['volume']:.4f}", elev=20),
              fg.Panel(fold.net, f"solve_cmc: stopped at the fold, H = {fold.H:.4f}", elev=20),
              fg.Panel(lifted.net, "boundary lifted by 0.1, H = 0", elev=20)]
    fg.wrote(out / "steps.png", fg.surfaces(out / "steps.png", panels))
    h = fold.H
    Hs, Vs = fg.branch(job, np.concatenate([np.linspace(0, 0.97 * h, 15), h * np.array([0.985, 0.995, 0.999])]))
    V_fold = fg.energy_volume(fold.net, h)
    size = fg.fold_diagram(out / "branch.png", [("n = 4, branch from H = 0", Hs, Vs)],
                           folds=[("solve_cmc's stop (the fold)", [(V_fold, h)])],
                           title="circle.py: the branch that solve_cmc follows to its fold")
    fg.wrote(out / "branch.png", size)


if __name__ == "__main__":
    main()
