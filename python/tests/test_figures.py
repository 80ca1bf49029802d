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
