"""The figures of the example READMEs: surfaces coloured by mean curvature, control nets, and plots.

Headless (matplotlib's Agg backend), from the module's own data: nets from ``bezierpde.solve`` /
``blend``, meshes and mean curvature from ``bezierpde.sample``, tables from the example programs'
generated sections (``example_tables``). Every example folder has a ``figures.py`` built on this
module; ``bash scripts/figures.sh [EXAMPLE ...]`` runs them and writes the PNGs beside the READMEs.

    >>> from bezierpde import figures
    >>> figures.surfaces("fig.png", [figures.Panel(net, "H = -1")])
    >>> figures.plot("conv.png", [figures.Series("ritz", degrees, errors)], logy=True)

The mean-curvature colour scale leaves out outliers (colour_range: Tukey's fences), such as the
huge |H| at corners where x_u ∥ x_v; the panels of one figure share one scale (one colour bar), so
that their colours compare. Text is set at sizes that stay readable where the READMEs show the
pictures at their pixel size (titles and labels 11 pt, ticks 10 pt at 100 dpi). Pictures are kept
small (at most 800 x 600 pixels, a palette of at most 256 colours when Pillow is present) so that
they can be committed; each PNG gets an SVG beside it (text and lines as vectors, the shaded
surfaces as embedded images) for papers.
"""

import dataclasses
import math
import os
import pathlib
import re
import subprocess
import sys
import tempfile
import textwrap

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import colors as mcolors  # noqa: E402
from matplotlib import ticker as mticker  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Line3DCollection, Poly3DCollection  # noqa: E402

from . import _core  # noqa: E402

#: Largest figure, in pixels (width, height), at DPI dots per inch.
MAX_SIZE = (800, 600)
DPI = 100
CMAP = "coolwarm"
#: Font sizes (points): panel and plot titles, axis and colour-bar labels, tick labels, legends.
TITLE, LABEL, TICK, LEGEND = 11, 11, 10, 9
#: Pixels at the right of a surface figure for its shared colour bar with its ticks and label.
BAR_PIXELS = 150
#: Resolution of the rasterized surfaces inside the SVGs (dots per inch).
SVG_DPI = DPI

# SVG output that depends on the figure only (no random ids, no date): regenerated files diff cleanly.
plt.rcParams["svg.hashsalt"] = "bezierpde"
plt.rcParams["axes.labelsize"] = LABEL
plt.rcParams["xtick.labelsize"] = TICK
plt.rcParams["ytick.labelsize"] = TICK
plt.rcParams["legend.fontsize"] = LEGEND


@dataclasses.dataclass
class Panel:
    """One surface of a surface figure.

    net: a NET dict (FORMATS.md "Nets") or a net object; title: the panel's caption; elev, azim:
    the camera (degrees, matplotlib's convention); samples: the ``bezierpde.sample`` resolution.
    """

    net: object
    title: str = ""
    elev: float = 30.0
    azim: float = -60.0
    samples: int = 24
    clim: tuple = None  # its colour range (with shared=False); default colour_range of its H


@dataclasses.dataclass
class Series:
    """One line of a plot: label, x and y (sequences of equal length), optional matplotlib style."""

    label: str
    x: list
    y: list
    style: str = "o-"
    color: object = None


def net_dict(net):
    """A NET dict of `net` (a dict, a TensorNet, TriangularNet or BSplineNet)."""
    if isinstance(net, dict):
        return net
    if hasattr(net, "to_dict"):
        return net.to_dict()
    P = np.asarray(net.points)
    if isinstance(net, _core.TriangularNet):
        return {"type": "triangular", "degree": net.n, "points": P.tolist()}
    return {"type": "tensor", "degree": [net.n, net.m], "points": P.tolist()}


def net_lines(net):
    """(points N x 3, segments S x 2 x 3) of the control net: grid lines of a tensor or B-spline
    net, the three families of lines of a triangular net (FORMATS.md point order)."""
    d = net_dict(net)
    P = np.asarray(d["points"], dtype=np.float64).reshape(-1, 3)
    segs = []
    if d["type"] == "triangular":
        n = int(d["degree"])
        index, r = {}, 0
        for i in range(n, -1, -1):
            for j in range(n - i, -1, -1):
                index[(i, j)] = r
                r += 1
        for (i, j), a in index.items():
            k = n - i - j
            if k > 0:  # neighbours with one unit moved from k to i or j
                segs.append((P[a], P[index[(i + 1, j)]]))
                segs.append((P[a], P[index[(i, j + 1)]]))
            if i > 0 and j < n:
                segs.append((P[a], P[index[(i - 1, j + 1)]]))
    else:
        if d["type"] == "bspline":
            p, q = d["degree"]
            rows, cols = len(d["knots"][0]) - p - 1, len(d["knots"][1]) - q - 1
        else:
            rows, cols = d["degree"][0] + 1, d["degree"][1] + 1
        G = P.reshape(rows, cols, 3)
        for i in range(rows):
            for j in range(cols):
                if i + 1 < rows:
                    segs.append((G[i, j], G[i + 1, j]))
                if j + 1 < cols:
                    segs.append((G[i, j], G[i, j + 1]))
    return P, np.asarray(segs, dtype=np.float64).reshape(-1, 2, 3)


def net_rings(net):
    """Per control point, its ring: 0 on the boundary, 1 adjacent to it, 2 further in (the
    `fixed` sets of FORMATS.md: "boundary" is ring 0, "boundary+adjacent" rings 0 and 1)."""
    d = net_dict(net)
    if d["type"] == "triangular":
        n = int(d["degree"])
        return np.array([min(i, j, n - i - j, 2) for i in range(n, -1, -1) for j in range(n - i, -1, -1)])
    if d["type"] == "bspline":
        p, q = d["degree"]
        rows, cols = len(d["knots"][0]) - p - 1, len(d["knots"][1]) - q - 1
    else:
        rows, cols = d["degree"][0] + 1, d["degree"][1] + 1
    return np.array([min(i, j, rows - 1 - i, cols - 1 - j, 2) for i in range(rows) for j in range(cols)])


def colour_range(values):
    """(vmin, vmax) for a mean-curvature colour scale: Tukey's fences [q1 − 1.5 IQR, q3 + 1.5 IQR]
    of the finite values, within their min and max (the corners where x_u ∥ x_v carry huge |H|
    would otherwise flatten every other colour), widened to a width of at least
    1e-3 (1 + |median|) so that a constant H still gets a scale."""
    v = np.asarray(values, dtype=np.float64)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return -1.0, 1.0
    q1, q3 = np.percentile(v, [25.0, 75.0])
    a, b = max(float(v.min()), q1 - 1.5 * (q3 - q1)), min(float(v.max()), q3 + 1.5 * (q3 - q1))
    mid, half = 0.5 * (a + b), 0.5 * (b - a)
    half = max(half, 0.5e-3 * (1.0 + abs(float(np.median(v)))))
    return float(mid - half), float(mid + half)


def _shade(V, F):
    """Per-triangle brightness in [0.55, 1] from a light above the camera (|n . l|)."""
    a, b, c = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    n = np.cross(b - a, c - a)
    norm = np.linalg.norm(n, axis=1)
    n = n / np.where(norm > 0, norm, 1.0)[:, None]
    light = np.array([0.3, -0.4, 0.87])
    light /= np.linalg.norm(light)
    return 0.55 + 0.45 * np.abs(n @ light)


def _box(ax, V):
    lo, hi = V.min(axis=0), V.max(axis=0)
    c, r = 0.5 * (lo + hi), 0.5 * (hi - lo)
    r = np.maximum(r, 0.02 * max(float(r.max()), 1e-12))
    ax.set_xlim(c[0] - r[0], c[0] + r[0])
    ax.set_ylim(c[1] - r[1], c[1] + r[1])
    ax.set_zlim(c[2] - r[2], c[2] + r[2])
    ax.set_box_aspect(tuple(r / r.max()))


def _wrapped(title, width_px):
    """`title` broken into lines that fit `width_px` at the TITLE size (about 0.55 em a character)."""
    chars = max(10, int(width_px / (0.55 * TITLE * DPI / 72.0)))
    return "\n".join(textwrap.wrap(title, chars)) if title else title


def _axes3d(fig, rows, cols, k, panel):
    ax = fig.add_subplot(rows, cols, k, projection="3d")
    ax.view_init(elev=panel.elev, azim=panel.azim)
    ax.set_title(_wrapped(panel.title, fig.bbox.width / cols * 0.95), fontsize=TITLE, pad=0)
    ax.set_facecolor((1, 1, 1, 0))  # transparent: a neighbour's colour bar labels stay visible
    ax.set_axis_off()  # the shape, as the papers draw it; axes and ticks only clutter a small picture
    return ax


def pair_range(*panels):
    """colour_range of the H of several panels together (a scale common to them, as the C¹
    methods paper plots the two surfaces of a figure)."""
    return colour_range(np.concatenate([_mesh(p)[2] for p in panels]))


def _mesh(panel):
    V, F, H = _core.sample(net_dict(panel.net), samples=panel.samples)
    return np.asarray(V), np.asarray(F), np.asarray(H)


def surfaces(path, panels, suptitle="", cols=None, clim=None, net_row=True, size=None, shared=True, nets_only=False,
             colour_by="H", colour_label=None):
    """Writes `path` (PNG, and an SVG beside it): one column per Panel; the first row the surface
    coloured by mean curvature H (one colour bar, range `clim` or colour_range of every panel's H,
    so that the panels compare; shared=False: one bar per panel, only for panels whose colours
    show different quantities), the second row (when net_row)
    the control net over the surface in grey. nets_only: the control nets alone (no colour bar).
    colour_by="z" colours by height instead (a load or a deflection plotted as a graph).

    Returns (width, height) in pixels. Up to 4 panels per row; more wrap onto further row pairs.
    """
    panels = list(panels)
    if nets_only:
        net_row = False
    meshes = [_mesh(p) for p in panels]
    label = colour_label or ("mean curvature H" if colour_by == "H" else "z")
    if colour_by == "z":
        meshes = [(V, F, V[:, 2].copy()) for V, F, _ in meshes]
    if clim is None:
        clim = colour_range(np.concatenate([m[2] for m in meshes]))
    cmap = plt.get_cmap(CMAP)
    cols = cols or min(len(panels), 4)
    blocks = math.ceil(len(panels) / cols)
    rows = blocks * (2 if net_row else 1)
    w, h = size or (min(MAX_SIZE[0], (210 if shared else 250) * cols + (BAR_PIXELS if shared else 20)),
                    min(MAX_SIZE[1], (230 if net_row else 300) * rows + 40))
    fig = plt.figure(figsize=(w / DPI, h / DPI), dpi=DPI)
    for k, (p, (V, F, H)) in enumerate(zip(panels, meshes)):
        block, col = divmod(k, cols)
        row = block * (2 if net_row else 1)
        Pn, segs = net_lines(p.net)
        if nets_only:
            ax = _axes3d(fig, rows, cols, row * cols + col + 1, p)
            _net(ax, V, F, Pn, segs, net_rings(p.net))
            continue
        ax = _axes3d(fig, rows, cols, row * cols + col + 1, p)
        lim = clim if shared else (p.clim or colour_range(H))
        norm = mcolors.Normalize(*lim)
        Hf = np.where(np.isfinite(H), H, np.nan)[F].mean(axis=1)
        rgba = cmap(norm(np.nan_to_num(Hf, nan=0.5 * (lim[0] + lim[1]))))
        rgba[:, :3] *= _shade(V, F)[:, None]
        ax.add_collection3d(Poly3DCollection(V[F], facecolors=rgba, edgecolors="none", linewidths=0, rasterized=True))
        _box(ax, V)
        if not shared:
            cb = fig.colorbar(plt.cm.ScalarMappable(norm=norm, cmap=cmap), ax=ax, shrink=0.55, pad=0.0, aspect=15,
                              format=mticker.ScalarFormatter(useOffset=False), ticks=mticker.MaxNLocator(4))
            cb.ax.tick_params(labelsize=TICK)
            cb.ax.set_title(label.split()[-1], fontsize=LABEL)  # above the bar: never clipped at the right
        if net_row:
            ax = _axes3d(fig, rows, cols, (row + 1) * cols + col + 1, dataclasses.replace(p, title="control net"))
            _net(ax, V, F, Pn, segs, net_rings(p.net))
    shared = shared and not nets_only
    bar = 1.0 - (BAR_PIXELS - 10.0 if shared else 10.0) / w  # the colour bar, its ticks and label at the right
    # room above the first row for its titles (wrapped onto several lines) and the suptitle
    lines = max([1] + [ax.get_title().count("\n") + 1 for ax in fig.axes[:cols * (2 if net_row else 1)]])
    top_px = lines * 1.3 * TITLE * DPI / 72.0 + 6.0 + (1.6 * (TITLE + 1) * DPI / 72.0 if suptitle else 0.0)
    fig.subplots_adjust(left=0.0, right=bar, bottom=0.02, top=1.0 - top_px / h, wspace=0.02, hspace=0.12)
    if shared:
        cax = fig.add_axes([bar + 15.0 / w, 0.25, 12.0 / w, 0.5])
        cb = fig.colorbar(plt.cm.ScalarMappable(norm=mcolors.Normalize(*clim), cmap=cmap), cax=cax,
                          format=mticker.ScalarFormatter(useOffset=False), ticks=mticker.MaxNLocator(5))
        cb.set_label(label, fontsize=LABEL)
        cb.ax.tick_params(labelsize=TICK)
    if suptitle:
        fig.suptitle(suptitle, fontsize=TITLE + 1)
    return save(fig, path)


def _net(ax, V, F, Pn, segs, rings):
    """The control net over the surface in grey; points as the C¹ methods paper draws them:
    boundary dark, adjacent ring lighter, interior points white."""
    grey = np.tile([0.82, 0.82, 0.85, 0.35], (len(F), 1))
    grey[:, :3] *= _shade(V, F)[:, None]
    ax.add_collection3d(Poly3DCollection(V[F], facecolors=grey, edgecolors="none", linewidths=0, rasterized=True))
    ax.add_collection3d(Line3DCollection(segs, colors="k", linewidths=0.6))
    for ring, colour in ((0, "k"), (1, "0.55"), (2, "w")):
        Q = Pn[rings == ring]
        if len(Q):
            ax.scatter(Q[:, 0], Q[:, 1], Q[:, 2], s=6, c=colour, edgecolors="k", linewidths=0.4, depthshade=False)
    _box(ax, np.vstack([V, Pn]))


def plot(path, series, xlabel="degree n", ylabel="", title="", logy=False, logx=False, hlines=(), size=(560, 400),
         legend_loc="best"):
    """Writes `path` (PNG, and an SVG beside it): the Series as lines; `hlines`: (y, label) reference lines. Returns
    (width, height). Non-positive values are left out of a log axis."""
    fig, ax = plt.subplots(figsize=(size[0] / DPI, size[1] / DPI), dpi=DPI)
    for s in series:
        x, y = np.asarray(s.x, dtype=float), np.asarray(s.y, dtype=float)
        keep = np.isfinite(y) & ((y > 0) if logy else True)
        ax.plot(x[keep], y[keep], s.style, label=s.label, ms=4, lw=1.2, color=s.color)
    for y, label in hlines:
        ax.axhline(y, ls="--", c="gray", lw=1, label=label)
    if logy:
        ax.set_yscale("log")
    if logx:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if title:
        ax.set_title(title, fontsize=TITLE)
    ax.grid(True, which="both" if logy else "major", alpha=0.3)
    if series or hlines:
        ax.legend(fontsize=LEGEND, loc=legend_loc)
    fig.tight_layout()
    return save(fig, path)


def save(fig, path):
    """Saves and closes `fig` as a PNG (a palette image of at most 256 colours when Pillow is
    installed, to keep the committed files small) and as an SVG beside it (the same name with
    .svg: text and lines as vectors, artists marked rasterized as images at SVG_DPI). Returns the
    PNG's (width, height) in pixels."""
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path.with_suffix(".svg"), dpi=SVG_DPI, format="svg", metadata={"Date": None})
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    try:
        from PIL import Image

        with Image.open(path) as im:
            im.load()
            q = im.convert("RGB").quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
        q.save(path, optimize=True)
    except ImportError:
        pass
    return png_size(path)


def png_size(path):
    """(width, height) from the IHDR chunk of a PNG file; ValueError when it is not a PNG."""
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise ValueError(f"{path} is not a PNG file")
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


# ------------------------------------------------------------------ CMC branches

def with_H(job, H):
    """A copy of a CMC JOB dict with problem.H = H."""
    import copy

    j = copy.deepcopy(job)
    j["problem"]["H"] = float(H)
    return j


def fold_H(job, H_far):
    """The H where the branch of `job` from H = 0 towards `H_far` ends (the report's H of a run
    that stops at the fold), or H_far when it gets there."""
    _, report = _core_solve(with_H(job, H_far))
    return float(report["H"])


def branch(job, H_values):
    """(H, V) along the branch of `job` from H = 0: one solve per H (continuation from 0 each
    time), converged points only; V is the report's enclosed volume."""
    Hs, Vs = [], []
    for H in H_values:
        _, report = _core_solve(with_H(job, H))
        if report.get("converged") and report.get("volume") is not None:
            Hs.append(float(report["H"]))
            Vs.append(float(report["volume"]))
    return Hs, Vs


def fold_diagram(path, curves, title="", folds=(), size=(560, 420)):
    """Writes `path`: H against V for each (label, H list, V list) of `curves`; `folds`: (label,
    [(V, H), ...]) marked points. Returns (width, height)."""
    fig, ax = plt.subplots(figsize=(size[0] / DPI, size[1] / DPI), dpi=DPI)
    for label, Hs, Vs in curves:
        order = np.argsort(Vs)
        ax.plot(np.asarray(Vs)[order], np.asarray(Hs)[order], "-", lw=1.4, label=label)
    for label, pts in folds:
        if pts:
            v, h = zip(*pts)
            ax.plot(v, h, "kx", ms=6, label=label)
    ax.axhline(0, c="gray", lw=0.6)
    ax.axvline(0, c="gray", lw=0.6)
    ax.set_xlabel("V (enclosed volume ⅓∫⟨x_u∧x_v, x⟩)")
    ax.set_ylabel("H")
    if title:
        ax.set_title(title, fontsize=TITLE)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=LEGEND)
    fig.tight_layout()
    return save(fig, path)


def energy_volume(net, H):
    """V of a net (bezierpde.energy "cmc"), for points of a branch that solve_cmc returns."""
    return float(_core.energy(net_dict(net), "cmc", H)["V"])


def _core_solve(job):
    r = _core.solve_result(job, None)
    return r["net"], r["report"]


# ------------------------------------------------------------------ the example programs' tables

ROOT = pathlib.Path(os.environ.get("BPDE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[3]))
_BEGIN = re.compile(r"^<!-- generated: ([A-Za-z0-9_.-]+)(?:; machine-dependent: ([^>]*?))? -->$")


def build_dir():
    """The build folder: $BPDE_BUILD_DIR, else the folder two levels above this package
    (build/python/bezierpde), else ROOT/build."""
    if os.environ.get("BPDE_BUILD_DIR"):
        return pathlib.Path(os.environ["BPDE_BUILD_DIR"])
    here = pathlib.Path(__file__).resolve().parents[2]
    return here if (here / "CMakeCache.txt").exists() else ROOT / "build"


def markdown_tables(lines):
    """The markdown tables among `lines`: a list of tables, each a list of {column: cell} rows
    (cells stripped, "\\|" unescaped)."""
    tables, header = [], None
    for line in lines:
        if not line.startswith("|"):
            header = None
            continue
        cells = [c.strip().replace("\\|", "|") for c in re.split(r"(?<!\\)\|", line.strip()[1:-1])]
        if header is None:
            header = cells
            tables.append([])
        elif not set(line) <= set("|-: \n"):
            tables[-1].append(dict(zip(header, cells)))
    return tables


def parse_tables(text):
    """{section: {"tables": [[{column: cell}, ...], ...], "lines": [...]}} of the generated
    sections (scripts/docs.py markers) in a program's output; cells are strings, "\\|" unescaped."""
    out, name = {}, None
    for line in text.splitlines():
        m = _BEGIN.match(line.strip())
        if m:
            name, out[m.group(1)] = m.group(1), {"tables": [], "lines": []}
            continue
        if name is None:
            continue
        if line.strip() == "<!-- end -->":
            name = None
            continue
        out[name]["lines"].append(line)
    for v in out.values():
        v["tables"] = markdown_tables(v["lines"])
    return out


def run_program(name, *args, timeout=600):
    """stdout of build/<name> (an example program or bpde_bench) with `args` (absolute paths: it
    runs in a scratch folder); RuntimeError when it is missing or fails."""
    program = build_dir() / name
    if not program.exists():
        raise RuntimeError(f"{program} is missing: build it (bash scripts/figures.sh builds it)")
    with tempfile.TemporaryDirectory(prefix="bpde_figures_") as tmp:  # programs that write out/ write it there
        r = subprocess.run([str(program), *map(str, args)], capture_output=True, text=True, timeout=timeout, cwd=tmp)
    if r.returncode != 0:
        raise RuntimeError(f"{program.name} exited {r.returncode}: {r.stderr[-1500:]}")
    return r.stdout


def example_tables(example, *args):
    """parse_tables of the example program of examples/<example> run with `args`."""
    return parse_tables(run_program("example_" + re.sub(r"[^A-Za-z0-9_]", "_", example), *args))


def number(cell):
    """A float from a table cell ("1.2e-05", "< 1e-13" -> 1e-13, "−3" -> -3); nan when none."""
    m = re.search(r"[-−]?\d+(?:\.\d*)?(?:[eE][-+−]?\d+)?", str(cell).replace("−", "-"))
    return float(m.group(0)) if m else float("nan")


def load_json(path):
    import json

    with open(path, encoding="utf-8") as f:
        return json.load(f)


def out_dir(argv=None, default=None):
    """The output folder of an example's figures.py: its first argument, else `default`."""
    args = [a for a in (sys.argv[1:] if argv is None else argv) if not a.startswith("--")]
    d = pathlib.Path(args[0] if args else default)
    d.mkdir(parents=True, exist_ok=True)
    return d


def wrote(path, size):
    path = pathlib.Path(path)
    svg = path.with_suffix(".svg")
    also = f", and {svg.name} ({os.path.getsize(svg) // 1024} kB)" if svg.exists() else ""
    print(f"wrote {path} ({size[0]} x {size[1]}, {os.path.getsize(path) // 1024} kB){also}")
