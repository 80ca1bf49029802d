"""Figures of this README: the table as a plot (round-trip and evaluation error bounds and
cond(M_n) against the degree, log scale, as example_000_power_basis_accuracy prints them in this
run), and one net of the kind it measures (degree (8, 8): a grid in x, y jittered by ±0.15, z
uniform in [−1, 1], seed 1) as a surface coloured by mean curvature with its control net.

    bash scripts/figures.sh 000-power-basis-accuracy        # or, with the module on PYTHONPATH:
    python3 examples/000-power-basis-accuracy/figures.py [OUT_DIR]   # default: this folder
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
    rows = fg.example_tables("000-power-basis-accuracy")["power-basis-accuracy"]["tables"][0]
    n = [int(r["n"]) for r in rows]
    series = [fg.Series("round-trip error (bound)", n, [fg.number(r["round-trip error"]) for r in rows]),
              fg.Series("evaluation error, power form (bound)", n,
                        [fg.number(r["evaluation error (power form)"]) for r in rows], "s--"),
              fg.Series("cond(M_n)", n, [fg.number(r["cond(M_n)"]) for r in rows], "^:")]
    size = fg.plot(out / "accuracy.png", series, ylabel="error (data O(1)) / condition number", logy=True,
                   hlines=[(2.0 ** -52, "machine epsilon")], title="power (monomial) basis: digits lost with the degree")
    fg.wrote(out / "accuracy.png", size)

    rng = np.random.default_rng(1)
    d = 8
    grid = np.array([[i / d * 2 - 1, j / d * 2 - 1, 0.0] for i in range(d + 1) for j in range(d + 1)])
    P = grid + rng.uniform(-1, 1, grid.shape) * np.array([0.15, 0.15, 1.0])
    net = bezierpde.TensorNet(d, d, P)
    size = fg.surfaces(out / "random-net.png", [fg.Panel(net, "degree (8, 8), random z", samples=40)])
    fg.wrote(out / "random-net.png", size)


if __name__ == "__main__":
    main()
