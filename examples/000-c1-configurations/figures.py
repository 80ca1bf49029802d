"""Figures of this README: the configurations of C¹ methods Figs. IV–IX, each as the paper plots
it: the biharmonic-load surface (top) and the tetraharmonic surface (below it) coloured by mean
curvature on a scale common to the two, and the control nets of both (dark: the prescribed
boundary and adjacent rings are the outer two rings of each net).

    bash scripts/figures.sh 000-c1-configurations        # or, with the module on PYTHONPATH:
    python3 examples/000-c1-configurations/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402

GROUPS = {"figs-IV-VII": [("cylinder-fig4", "IV"), ("cylinder-fig5", "V"), ("sphere-fig6", "VI"), ("arch-fig7", "VII")],
          "figs-VIII-IX": [("arch-fig8", "VIII"), ("arch2-fig9-row1", "IX row 1"), ("arch2-fig9-row2", "IX row 2"),
                           ("arch2-fig9-row3", "IX row 3")]}


def main():
    out = fg.out_dir(default=HERE)
    for file, configs in GROUPS.items():
        top, bottom = [], []
        for config, figure in configs:
            pair = []
            for method in ("biharmonic-load", "tetraharmonic"):
                net, report = bezierpde.solve(fg.load_json(HERE / f"{config}-{method}.json"))
                pair.append(fg.Panel(net, f"{figure}: {method}", elev=30, azim=-60))
            lim = fg.pair_range(*pair)  # one scale for the two surfaces of a figure
            for p in pair:
                p.clim = lim
            top.append(pair[0])
            bottom.append(pair[1])
        panels = top + bottom
        fg.wrote(out / f"{file}.png", fg.surfaces(out / f"{file}.png", panels, cols=4, net_row=False,
                                                  size=(800, 460)))
        fg.wrote(out / f"{file}-nets.png", fg.surfaces(out / f"{file}-nets.png", panels, cols=4, nets_only=True,
                                                       size=(800, 460)))


if __name__ == "__main__":
    main()
