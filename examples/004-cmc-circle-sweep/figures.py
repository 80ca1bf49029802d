"""Figures of this README: the sweep fold-vs-degree.json run here (bezierpde.sweep, two local
processes): |H| at the fold against the degree beside the exact problem's |H| = 1, and the
surface each job stops at (coloured by mean curvature) with its control net.

    bash scripts/figures.sh 004-cmc-circle-sweep        # or, with the module on PYTHONPATH:
    python3 examples/004-cmc-circle-sweep/figures.py [OUT_DIR]   # default: this folder
"""
import os
import pathlib
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402



def main():
    out = fg.out_dir(default=HERE)
    with tempfile.TemporaryDirectory(prefix="bpde_sweep_") as tmp:
        table = bezierpde.sweep(str(HERE / "fold-vs-degree.json"), out=tmp, jobs=2)
        rows = table.to_dict("records") if hasattr(table, "to_dict") else table
        panels = []
        for r in rows:
            net = fg.load_json(pathlib.Path(tmp) / "jobs" / r["job"] / "result.json")["net"]
            panels.append(fg.Panel(net, f"n = {r['net.degree']}: {r['status']} at H = {r['H']:.4f}", elev=20,
                                   samples=16))
    folds = [r for r in rows if r["status"] == "fold"]
    size = fg.plot(out / "fold-vs-degree.png",
                   [fg.Series("fold of the degree-n approximation", [r["net.degree"] for r in folds],
                              [-r["H"] for r in folds])],
                   ylabel="|H| at the fold", hlines=[(1.0, "exact: the hemisphere, |H| = 1")],
                   title="circle in three arcs: the fold against the degree")
    fg.wrote(out / "fold-vs-degree.png", size)
    fg.wrote(out / "surfaces.png", fg.surfaces(out / "surfaces.png", panels, cols=3, net_row=False,
                                               size=(780, 520)))
    fg.wrote(out / "nets.png", fg.surfaces(out / "nets.png", panels, cols=3, nets_only=True, size=(780, 520)))


if __name__ == "__main__":
    main()
