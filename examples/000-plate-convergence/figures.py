"""Figures of this README: the clamped plate's deflection (C¹ methods §6) with its control net,
the paper's Fig. X (the admissible load Δ²w for n = 7, 9, 11, 15 on one scale), and the
convergence of both methods: |w(½,½) − w*| / w* against the degree (log scale), w* = ritz at
n = 30, every aspect ratio.

    bash scripts/figures.sh 000-plate-convergence        # or, with the module on PYTHONPATH:
    python3 examples/000-plate-convergence/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import numpy as np  # noqa: E402

import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402

ASPECTS = (1.0, 1.3, 1.5, 1.7, 2.0)


def plate(aspect, degree, method):
    o = bezierpde.ClampedPlateOptions()
    o.aspect, o.degree, o.method = aspect, degree, method
    return bezierpde.solve_clamped_plate(o)


def scaled(net, height):
    """The net with z scaled so that its largest |z| is `height` (the deflection is ~1e-3)."""
    P = np.array(net.points)
    P[:, 2] *= height / max(np.abs(P[:, 2]).max(), 1e-300)
    return bezierpde.TensorNet(net.n, net.m, P)


def main():
    out = fg.out_dir(default=HERE)
    panels = [fg.Panel(scaled(plate(1.0, 11, m).net, 0.3), f"{m}, n = 11 (z × {0.3 / plate(1.0, 11, m).center_deflection:.0f})")
              for m in ("admissible-load", "ritz")]
    fg.wrote(out / "plate.png", fg.surfaces(out / "plate.png", panels))
    # Fig. X: the load of the admissible-load plate, n = 7, 9, 11, 15, one scale and one range
    loads = []
    for n in (7, 9, 11, 15):
        load = plate(1.0, n, "admissible-load").load
        loads.append(fg.Panel(scaled(load, np.abs(np.asarray(load.points)[:, 2]).max() / 80.0), f"load Δ²w, n = {n}"))
    size = fg.surfaces(out / "figX-load.png", loads, colour_by="z", net_row=False, size=(800, 300),
                       colour_label="load / 80", suptitle="Fig. X: the admissible load, one scale (z = load / 80)")
    fg.wrote(out / "figX-load.png", size)

    degrees = list(range(4, 31))
    series = []
    for a in ASPECTS:
        ref = plate(a, 30, "ritz").center_deflection
        for m, style in (("admissible-load", "o-"), ("ritz", "s--")):
            n = degrees if m == "admissible-load" else degrees[:-1]  # ritz at 30 is w* itself
            d = [abs(plate(a, k, m).center_deflection - ref) / ref for k in n]
            series.append(fg.Series(f"{m}, a = {a:g}", n, d, style, color=f"C{ASPECTS.index(a)}"))
    size = fg.plot(out / "convergence.png", series, ylabel="|w(½,½) − w*| / w*", logy=True, size=(640, 460),
                   title="clamped plate: distance to w* = ritz at n = 30")
    fg.wrote(out / "convergence.png", size)


if __name__ == "__main__":
    main()
