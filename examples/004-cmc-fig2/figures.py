"""Figures of this README: triangular CMC Fig. 2 in the paper's layout (top: the
corner-isothermal Enneper boundary, H = −1, 0, 1; bottom: three circular arcs, H = −2, −1.5,
−1), coloured by mean curvature, and their control nets in the same layout.

    bash scripts/figures.sh 004-cmc-fig2        # or, with the module on PYTHONPATH:
    python3 examples/004-cmc-fig2/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402

JOBS = [("top-a-enneper-H-1", "top: Enneper, H = −1"), ("top-b-enneper-H0", "top: Enneper, H = 0"),
        ("top-c-enneper-H1", "top: Enneper, H = 1"), ("bottom-a-arcs-H-2", "bottom: arcs, H = −2"),
        ("bottom-b-arcs-H-1.5", "bottom: arcs, H = −1.5"), ("bottom-c-arcs-H-1", "bottom: arcs, H = −1")]


def main():
    out = fg.out_dir(default=HERE)
    panels = []
    for name, title in JOBS:
        net, report = bezierpde.solve(fg.load_json(HERE / f"{name}.json"))
        panels.append(fg.Panel(net, title if report["converged"] else title + " (not converged)", elev=25))
    for file, kw in (("fig2-surfaces.png", {}), ("fig2-nets.png", {"nets_only": True})):
        fg.wrote(out / file, fg.surfaces(out / file, panels, cols=3, net_row=False,
                                         size=(780, 520), **kw))


if __name__ == "__main__":
    main()
