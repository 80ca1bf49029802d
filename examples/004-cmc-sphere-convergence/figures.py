"""Figures of this README: the two n = 8 jobs (triangular and tensor pieces of the unit sphere,
H = +1) coloured by mean curvature with their control nets, and the convergence tables as plots:
the distance to the sphere and |H_mean − 1| against the degree (log scale), as
example_004_cmc_sphere_convergence computes them in this run.

    bash scripts/figures.sh 004-cmc-sphere-convergence        # or, with the module on PYTHONPATH:
    python3 examples/004-cmc-sphere-convergence/figures.py [OUT_DIR]   # default: this folder
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
    panels = []
    for name, title in (("triangle-n8", "sphere_triangle, n = 8, H = 1"), ("square-n8", "sphere_square, n = 8, H = 1")):
        net, report = bezierpde.solve(fg.load_json(HERE / f"{name}.json"))
        panels.append(fg.Panel(net, title, elev=35, azim=-60))
    # H is close to 1 everywhere: one scale for both shows how close
    fg.wrote(out / "surfaces.png", fg.surfaces(out / "surfaces.png", panels))

    with tempfile.TemporaryDirectory() as tmp:
        tables = fg.example_tables("004-cmc-sphere-convergence", HERE, tmp + "/out")
    tri, square = [t for t in tables["cmc-sphere-convergence"]["tables"] if t and "n" in t[0]][:2]
    series = []
    for label, rows, c in (("triangular", tri, "C0"), ("tensor", square, "C1")):
        n = [int(r["n"]) for r in rows]
        series.append(fg.Series(f"{label}: max | |x| − 1 |", n, [fg.number(r["max ||x| − 1|"]) for r in rows], "o-", c))
        series.append(fg.Series(f"{label}: |H_mean − 1|", n, [fg.number(r["|H_mean − 1|"]) for r in rows], "s--", c))
    size = fg.plot(out / "convergence.png", series, ylabel="error", logy=True,
                   title="conformal sphere data, H = +1: convergence with the degree")
    fg.wrote(out / "convergence.png", size)


if __name__ == "__main__":
    main()
