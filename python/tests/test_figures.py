"""The README figures (bezierpde.figures): one example's figures.py regenerated into a temporary
folder gives real PNG images of the expected size with many colours."""

import os
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR

matplotlib = pytest.importorskip("matplotlib")


def run_figures(example, out):
    env = dict(os.environ, BPDE_SOURCE_DIR=SOURCE_DIR)
    p = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "examples", example, "figures.py"), str(out)],
                       capture_output=True, text=True, cwd=SOURCE_DIR, env=env, timeout=300)
    assert p.returncode == 0, p.stderr
    return p.stdout


def test_blend_figure_is_a_real_image(tmp_path):
    out = run_figures("003-blend-cylinders", tmp_path)
    assert "fig2-surfaces.png" in out
    path = tmp_path / "fig2-surfaces.png"
    with open(path, "rb") as f:
        head = f.read(24)
    assert head[:8] == b"\x89PNG\r\n\x1a\n" and head[12:16] == b"IHDR"
    width, height = int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")
    assert (width, height) == (640, 560)  # the size figures.py asks for
    assert path.stat().st_size < 100_000
    import matplotlib.image
    import numpy as np

    img = matplotlib.image.imread(str(path))  # decoded pixels, independent of the IHDR read above
    assert img.shape[:2] == (560, 640)
    rgb = np.round(np.asarray(img)[..., :3] * 255).astype(np.int64).reshape(-1, 3)
    colours = np.unique(rgb[:, 0] * 65536 + rgb[:, 1] * 256 + rgb[:, 2])
    assert colours.size > 64, colours.size  # a shaded surface and a colour bar, not a blank page
    # the surfaces are drawn: a good share of the pixels is not the white background
    assert (rgb.sum(axis=1) < 3 * 250).mean() > 0.1


def test_png_size_rejects_a_non_png(tmp_path):
    from bezierpde import figures

    bad = tmp_path / "x.png"
    bad.write_bytes(b"GIF89a" + bytes(30))
    with pytest.raises(ValueError):
        figures.png_size(bad)
    good = tmp_path / "y.png"
    size = figures.plot(good, [figures.Series("a", [1, 2, 3], [1e-3, 1e-6, 1e-9])], logy=True, size=(300, 200))
    assert size == figures.png_size(good) == (300, 200)


def test_net_lines_count_the_edges_of_the_net():
    from bezierpde import figures

    n = 5  # triangular: 3 n (n + 1) / 2 edges of the control triangulation, each point once
    tri = {"type": "triangular", "degree": n, "points": [[i, 0, 0] for i in range((n + 1) * (n + 2) // 2)]}
    P, segs = figures.net_lines(tri)
    assert P.shape == ((n + 1) * (n + 2) // 2, 3) and segs.shape == (3 * n * (n + 1) // 2, 2, 3)
    # every segment joins two points whose FORMATS.md indices differ by one unit move
    index, r = {}, 0
    for i in range(n, -1, -1):
        for j in range(n - i, -1, -1):
            index[r] = (i, j, n - i - j)
            r += 1
    for a, b in segs:
        I, J = index[int(a[0])], index[int(b[0])]
        assert sorted(abs(x - y) for x, y in zip(I, J)) == [0, 1, 1]
    ten = {"type": "tensor", "degree": [3, 2], "points": [[0, 0, 0]] * 12}
    assert figures.net_lines(ten)[1].shape == (3 * 3 + 4 * 2, 2, 3)  # rows of 3 edges, columns of 2


def test_colour_range_ignores_corner_spikes_and_widens_a_constant():
    from bezierpde import figures

    H = [1.0] * 98 + [-2e4, 3e4]
    lo, hi = figures.colour_range(H)
    assert lo < 1.0 < hi and hi - lo < 0.01
    lo, hi = figures.colour_range(list(range(101)))  # no outliers: the whole range
    assert (lo, hi) == (0.0, 100.0)
    lo, hi = figures.colour_range(list(range(101)) + [1000.0])  # one far outlier: left out
    assert hi < 200


def test_tables_of_a_generated_section():
    from bezierpde import figures

    text = "x\n<!-- generated: t; machine-dependent: ms -->\n| n | err \\| x |\n|---|---|\n| 4 | < 1e-13 |\n<!-- end -->\n"
    rows = figures.parse_tables(text)["t"]["tables"][0]
    assert rows == [{"n": "4", "err | x": "< 1e-13"}]
    assert figures.number(rows[0]["err | x"]) == 1e-13 and figures.number("−1.5 reached") == -1.5


def _captured_figure(monkeypatch, draw):
    """The matplotlib figure that `draw` saves through figures.save, drawn, and the paths saved."""
    from bezierpde import figures

    seen = {}
    original = figures.save

    def capture(fig, path):
        fig.canvas.draw()
        seen["texts"] = [(t, t.get_window_extent()) for t in fig.findobj(matplotlib.text.Text)
                         if t.get_visible() and t.get_text()]
        seen["bbox"] = fig.bbox
        seen["axes"] = list(fig.axes)
        return original(fig, path)

    monkeypatch.setattr(figures, "save", capture)
    draw(figures)
    return seen


def test_surface_panels_share_one_readable_colour_scale(monkeypatch, tmp_path):
    import numpy as np
    import bezierpde

    def bowl(c):  # a graph z = c (x^2 + y^2): mean curvature about 2c at the centre, different per panel
        return {"type": "tensor", "degree": [2, 2],
                "points": [[i / 2, j / 2, c * ((i / 2 - 0.5) ** 2 + (j / 2 - 0.5) ** 2)] for i in range(3) for j in range(3)]}

    path = tmp_path / "panels.png"
    seen = _captured_figure(monkeypatch, lambda fg: fg.surfaces(
        path, [fg.Panel(bowl(c), f"c = {c}: a bowl z = c (x² + y²) over the unit square") for c in (0.5, 1.0, 2.0)],
        size=(780, 520)))
    colour_bars = [ax for ax in seen["axes"] if ax.name != "3d"]
    assert len(colour_bars) == 1  # one scale for the three panels
    lo, hi = colour_bars[0].get_ylim()
    H = np.concatenate([bezierpde.sample(bowl(c), samples=24)[2] for c in (0.5, 2.0)])
    assert lo <= np.percentile(H, 30) and np.percentile(H, 70) <= hi  # it spans the panels' H, not one panel's
    fig_box = seen["bbox"]
    for text, box in seen["texts"]:
        assert text.get_fontsize() >= 9, (text.get_text(), text.get_fontsize())
        # nothing clipped at the figure's edges (the colour bar's label "mean curvature H" included)
        assert box.x0 >= fig_box.x0 - 1 and box.x1 <= fig_box.x1 + 1, (text.get_text(), box, fig_box)
        assert box.y0 >= fig_box.y0 - 1 and box.y1 <= fig_box.y1 + 1, (text.get_text(), box, fig_box)
    assert any("H" in t.get_text() for t, _ in seen["texts"])
    # no two texts overlap (long panel titles are wrapped to their panel's width)
    boxes = [box for _, box in seen["texts"]]
    for i in range(len(boxes)):
        for j in range(i + 1, len(boxes)):
            a, b = boxes[i], boxes[j]
            overlap = min(a.x1, b.x1) - max(a.x0, b.x0) > 1 and min(a.y1, b.y1) - max(a.y0, b.y0) > 1
            assert not overlap, (seen["texts"][i][0].get_text(), seen["texts"][j][0].get_text())
    svg = path.with_suffix(".svg")
    assert svg.exists()
    head = svg.read_text(encoding="utf-8")
    assert "<svg" in head and "c = 0.5" in head  # the titles are text in the SVG
    assert svg.stat().st_size < 1_500_000


def test_plots_write_an_svg_beside_the_png(monkeypatch, tmp_path):
    path = tmp_path / "plot.png"
    seen = _captured_figure(monkeypatch, lambda fg: fg.plot(
        path, [fg.Series("ritz", [4, 6, 8], [1e-3, 1e-6, 1e-9])], ylabel="error", logy=True, size=(560, 400)))
    assert all(t.get_fontsize() >= 9 for t, _ in seen["texts"])
    import xml.etree.ElementTree as ET

    root = ET.parse(path.with_suffix(".svg")).getroot()
    assert root.tag.endswith("svg") and root.get("width", "").startswith("403")  # 560 px = 403.2 pt
