"""Figures of this README: the surfaces of explicit PDE solutions Figs. 1-4 coloured by mean
curvature with their control nets, the error of the explicit and LU routes against the degree on
exact biharmonic solutions, and Table 1 (timings) beside the paper's milliseconds.

    bash scripts/figures.sh 001-pde-figures        # or, with the module on PYTHONPATH:
    python3 examples/001-pde-figures/figures.py [OUT_DIR]   # default: this folder

Table 1 comes from `bpde_bench --table1` run here (times of this machine, the paper's beside).
"""
import math
import os
import pathlib
import sys
from fractions import Fraction

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, os.environ.get("BPDE_PYTHON_DIR", str(HERE.parents[1] / "build" / "python")))
import numpy as np  # noqa: E402

import bezierpde  # noqa: E402
from bezierpde import figures as fg  # noqa: E402


def job_net(name):
    net, report = bezierpde.solve(fg.load_json(HERE / f"{name}.json"))
    assert report["converged"], (name, report.get("message"))
    return net


def poly_mul(a, b):
    out = {}
    for (i, j), x in a.items():
        for (k, l), y in b.items():
            out[(i + k, j + l)] = out.get((i + k, j + l), 0) + x * y
    return out


def exact_biharmonic_net(n):
    """The Bernstein net of degree (n, n), exact then rounded, of x = u, y = v,
    z = Re((s + it)^n) + (s² + t²) Im((s + it)^(n−2)) with s = 2u − 1, t = 2v − 1: a biharmonic
    polynomial of total degree n (harmonic, and |w|² times harmonic)."""
    s, t = {(1, 0): 2, (0, 0): -1}, {(0, 1): 2, (0, 0): -1}
    w = {(0, 0): complex(1)}
    powers = [w]
    for _ in range(n):
        w = poly_mul(w, {k: complex(v) for k, v in s.items()} | {(0, 1): 2j, (0, 0): -1 - 1j})
        powers.append(w)
    r2 = poly_mul(s, s)
    for k, v in poly_mul(t, t).items():
        r2[k] = r2.get(k, 0) + v
    z = {k: Fraction(int(v.real)) for k, v in powers[n].items()}
    for k, v in poly_mul(r2, {k: int(v.imag) for k, v in powers[n - 2].items()}).items():
        z[k] = z.get(k, 0) + v
    # monomial -> Bernstein: b_ij = sum_{k<=i, l<=j} C(i,k) C(j,l) / (C(n,k) C(n,l)) a_kl, exactly
    P = np.zeros(((n + 1) * (n + 1), 3))
    for i in range(n + 1):
        for j in range(n + 1):
            b = sum((Fraction(math.comb(i, k) * math.comb(j, l), math.comb(n, k) * math.comb(n, l)) * a
                     for (k, l), a in z.items() if k <= i and l <= j), Fraction(0))
            P[i * (n + 1) + j] = (i / n, j / n, float(b))
    return P


def accuracy(degrees):
    """{route: [relative error]} of solve_pde_explicit and solve_pde_lu given the outer ring."""
    errors = {"explicit": [], "lu": []}
    for n in degrees:
        exact = exact_biharmonic_net(n)
        data = bezierpde.TensorNet(n, n, exact)
        for route, solve in (("explicit", bezierpde.solve_pde_explicit), ("lu", bezierpde.solve_pde_lu)):
            net, summary = solve(data, "biharmonic")
            err = np.abs(np.asarray(net.points) - exact).max() / np.abs(exact).max()
            errors[route].append(max(err, 1e-17))
    return errors


def main():
    out = fg.out_dir(default=HERE)
    fig1 = job_net("fig1-biharmonic")
    # Fig. 1: "two views" of the biharmonic surface; Fig. 2: the modified biharmonic a² = 0.1, 1.5
    panels = [fg.Panel(fig1, "Fig. 1, biharmonic"), fg.Panel(fig1, "Fig. 1, second view", elev=55, azim=30),
              fg.Panel(job_net("fig2-modified-a2-0.1"), "Fig. 2, modified a² = 0.1"),
              fg.Panel(job_net("fig2-modified-a2-1.5"), "Fig. 2, modified a² = 1.5")]
    fg.wrote(out / "fig1-2.png", fg.surfaces(out / "fig1-2.png", panels))
    panels = [fg.Panel(job_net(f"fig{f}-gnorm-t-{t}"), f"Fig. {f}, G-norm t = {label}")
              for f, t, label in ((3, "pi2", "π/2"), (4, "pi3", "π/3"), (4, "pi4", "π/4"), (4, "pi8", "π/8"))]
    fg.wrote(out / "fig3-4.png", fg.surfaces(out / "fig3-4.png", panels))

    degrees = list(range(4, 21))
    err = accuracy(degrees)
    size = fg.plot(out / "accuracy.png", [fg.Series(f"{r}", degrees, e) for r, e in err.items()],
                   ylabel="max |P − P*| / max |P*|", logy=True,
                   title="biharmonic, exact polynomial solution of degree n, outer ring given")
    fg.wrote(out / "accuracy.png", size)

    rows = fg.markdown_tables(fg.run_program("bpde_bench", "--table1", "--benchmark_min_time=0.05").splitlines())
    rows = next(t for t in rows if t and "paper explicit" in t[0])
    n = [int(r["n"]) for r in rows]
    col = lambda c: [fg.number(r[c]) for r in rows]  # noqa: E731
    series = [fg.Series("paper: explicit (2011 laptop)", n, col("paper explicit"), "s--"),
              fg.Series("paper: LU linear system", n, col("paper linear system"), "^--"),
              fg.Series("bezierpde explicit", n, col("explicit")), fg.Series("bezierpde lu (block)", n, col("lu")),
              fg.Series("bezierpde lu-bernstein (dense)", n, col("lu-bernstein")),
              fg.Series("bezierpde mould", n, col("mould"))]
    size = fg.plot(out / "table1.png", series, ylabel="CPU ms (solve + 50×50 evaluation)", logy=True,
                   title="Table 1: biharmonic timings, the paper's beside this machine's", legend_loc="upper left")
    fg.wrote(out / "table1.png", size)


if __name__ == "__main__":
    main()
