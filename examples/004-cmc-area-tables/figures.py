"""Figures of this README: the circle in three arcs at H = −0.5, n = 8, solved with both
functionals (D_H and A_H) and coloured by mean curvature, and the error against the degree of the
degree tables (circle at H = −0.5 and −0.9, helicoid, catenoid), both functionals, log scale.

The degree plots read the `-full` generated sections of docs/cmc_measurements.md, which this example's
`--full` run writes (`bash scripts/docs.sh --full`, minutes); pass `--run` to run it here instead.

    bash scripts/figures.sh 004-cmc-area-tables        # or, with the module on PYTHONPATH:
    python3 examples/004-cmc-area-tables/figures.py [OUT_DIR] [--run]   # default: this folder
"""
import copy
import os
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402

EXAMPLE = "004-cmc-area-tables"
# section of docs/cmc_measurements.md -> (label, error column)
CIRCLE = [("cmc-area-circle-0.5-full", "circle, H = −0.5"), ("cmc-area-circle-0.9-full", "circle, H = −0.9")]
MINIMAL = [("cmc-area-helicoid-full", "helicoid (tensor)"), ("cmc-area-catenoid-full", "catenoid (triangular)")]


def tables(run):
    if run:
        return fg.example_tables(EXAMPLE, "--full")
    return fg.parse_tables((HERE.parents[1] / "docs" / "cmc_measurements.md").read_text(encoding="utf-8"))


def series(sections, cases):
    out = []
    for section, label in cases:
        rows = sections[section]["tables"][0]
        error = [c for c in rows[0] if c not in ("n", "functional")][0]
        for functional, style in (("dirichlet", "s--"), ("area", "o-")):
            picked = [r for r in rows if r["functional"] == functional]
            out.append(fg.Series(f"{label}, {functional}", [fg.number(r["n"]) for r in picked],
                                 [fg.number(r[error]) for r in picked], style=style))
    return out


def main():
    argv = [a for a in sys.argv[1:] if a != "--run"]
    out = fg.out_dir(argv=argv, default=HERE)
    job = fg.load_json(HERE.parent / "004-cmc-circle" / "circle_area.json")
    dirichlet = copy.deepcopy(job)
    dirichlet["problem"]["functional"] = "dirichlet"
    panels = []
    for title, j in (("D_H (dirichlet), n = 8, H = −0.5", dirichlet), ("A_H (area), n = 8, H = −0.5", job)):
        net, report = bezierpde.solve(j)
        panels.append(fg.Panel(net, title, elev=20, samples=30))
    fg.wrote(out / "circle-both.png", fg.surfaces(out / "circle-both.png", panels, size=(720, 560)))
    sections = tables("--run" in sys.argv[1:])
    for file, cases, ylabel in (("circle-error.png", CIRCLE, "max distance to the exact sphere"),
                                ("minimal-error.png", MINIMAL, "max distance to the exact minimal surface")):
        size = fg.plot(out / file, series(sections, cases), ylabel=ylabel, logy=True,
                       title="the two functionals on non-conformal boundaries, against the degree")
        fg.wrote(out / file, size)


if __name__ == "__main__":
    main()
