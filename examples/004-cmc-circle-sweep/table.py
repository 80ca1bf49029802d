"""The fold of the circle of triangular CMC Fig. 1 against the degree, as a table and a plot.

    PYTHONPATH=build/python python3 examples/004-cmc-circle-sweep/table.py [OUT_DIR] [--dask]

Runs fold-vs-degree.json (H = -3 for degrees 3..8: every branch from H = 0 stops at its fold, and
the report's H is where) on local processes, or with --dask on a Dask LocalCluster of two workers,
prints the table and writes OUT_DIR/fold-vs-degree.png (matplotlib, if installed). The same sweep
from the command: bpde sweep examples/004-cmc-circle-sweep/fold-vs-degree.json --out OUT_DIR.
"""

import os
import sys

import bezierpde

args = [a for a in sys.argv[1:] if not a.startswith("--")]
out_dir = args[0] if args else "out/004-cmc-circle-sweep"
spec = os.path.join(os.path.dirname(__file__), "fold-vs-degree.json")

if __name__ == "__main__":
    if "--dask" in sys.argv:
        from dask.distributed import Client, LocalCluster

        with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster:
            with Client(cluster) as client:
                table = bezierpde.sweep(spec, client=client, out=out_dir)
    else:
        table = bezierpde.sweep(spec, out=out_dir, jobs=2)
    table = table.rename(columns={"net.degree": "degree", "H": "H reached"})
    print(table[["degree", "status", "H reached", "energy", "H_min", "H_max"]].to_string(index=False))
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.exit(0)
    folds = table[table["status"] == "fold"]
    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(folds["degree"], -folds["H reached"], "o-", label="fold of the degree-n approximation")
    ax.axhline(1.0, ls="--", c="gray", label="exact: the hemisphere, |H| = 1")
    ax.set_xlabel("degree n")
    ax.set_ylabel("|H| at the fold")
    ax.legend()
    ax.set_title("circle in three arcs: the fold against the degree")
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "fold-vs-degree.png"), dpi=120)
    print("wrote", os.path.join(out_dir, "fold-vs-degree.png"))
