"""Figures of this README: the Fig. 2c blend and the biharmonic B-spline extremal with the blend's
boundary ring (the last solver cell of blend.py), coloured by mean curvature, and the data error
of the smoothing spline against ε (log-log: it becomes linear in ε).

    bash scripts/figures.sh 003-python-blend        # or, with the module on PYTHONPATH:
    python3 examples/003-python-blend/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402

EPSILONS = [10.0**-k for k in range(1, 9)]


def main():
    out = fg.out_dir(default=HERE)
    config = fg.load_json(HERE.parent / "003-blend-cylinders" / "fig2c.json")
    net, report = bezierpde.blend(config)
    bspline = bezierpde.net_from_dict(net)
    options = bezierpde.BSplineExtremalOptions()
    options.fixed = "boundary"
    extremal = bezierpde.solve_bspline_extremal(bspline, "biharmonic", options)
    panels = [fg.Panel(net, f"blend (Fig. 2c), J = {report['energy']:.4f}", elev=25, azim=-50, samples=40),
              fg.Panel(extremal.net, "biharmonic B-spline extremal, same ring", elev=25, azim=-50, samples=40)]
    fg.wrote(out / "blend-extremal.png",
             fg.surfaces(out / "blend-extremal.png", panels, net_row=False, size=(720, 360)))
    errors = []
    for eps in EPSILONS:
        config["epsilon"] = eps
        errors.append(bezierpde.blend(config)[1]["max_data_error"])
    size = fg.plot(out / "data-error.png", [fg.Series("max |σ(a_i) − β_i|", EPSILONS, errors)], xlabel="ε",
                   ylabel="data error", title="Fig. 2c data: the smoothing spline's data error against ε",
                   logy=True, logx=True)
    fg.wrote(out / "data-error.png", size)


if __name__ == "__main__":
    main()
