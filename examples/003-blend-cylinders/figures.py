"""Figures of this README: the four blends of smoothing PDE splines Fig. 2, in the paper's 2 x 2
layout (top: A = ∅ with a = 1, 10; bottom: nine points with ε = 1e-3, 1e-5), coloured by mean
curvature, and their control nets.

    bash scripts/figures.sh 003-blend-cylinders        # or, with the module on PYTHONPATH:
    python3 examples/003-blend-cylinders/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402

CASES = [("fig2a", "A = ∅, ε = 1, a = 1"), ("fig2b", "A = ∅, ε = 1, a = 10"),
         ("fig2c", "9 points, ε = 1e-3, a = 10"), ("fig2d", "9 points, ε = 1e-5, a = 10")]


def main():
    out = fg.out_dir(default=HERE)
    panels = []
    for name, title in CASES:
        net, _ = bezierpde.blend(fg.load_json(HERE / f"{name}.json"))
        panels.append(fg.Panel(net, f"{name}: {title}", elev=25, azim=-50, samples=40))
    # one colour scale per surface: fig2a's H spans [-929, 198], the others stay within [-20, 110]
    for file, kw in [("fig2-surfaces.png", {}), ("fig2-nets.png", {"nets_only": True})]:
        fg.wrote(out / file, fg.surfaces(out / file, panels, cols=2, net_row=False,
                                         size=(640, 560), **kw))


if __name__ == "__main__":
    main()
