"""The Python examples run as a user runs them, from any folder, and say what their READMEs say."""

import os
import subprocess
import sys
import tempfile

from conftest import SOURCE_DIR


def run_example(script, *args):
    """The example's output, run as a user runs it from a folder of their own: a new temporary
    folder, not the repository (an example finds its files from its own place)."""
    env = dict(os.environ)
    with tempfile.TemporaryDirectory() as cwd:
        p = subprocess.run([sys.executable, os.path.join(os.path.abspath(SOURCE_DIR), script), *args],
                           capture_output=True, text=True, cwd=cwd, env=env, timeout=300)
    assert p.returncode == 0, p.stderr
    return p.stdout


def test_notebook_example(tmp_path):
    out = run_example("examples/004-python-circle/circle.py", str(tmp_path))
    # the README's numbers, to the solve's tolerance (relative first variation 1e-11)
    line = next(l for l in out.splitlines() if l.startswith("D_H = "))
    d_h = float(line.split("D_H = ")[1].split(",")[0])
    vol = float(line.split("V = ")[1].split(",")[0])
    assert abs(d_h - 3.870131207373) < 1e-9 and abs(vol - 0.802165303653) < 1e-9, line
    assert line.endswith("converged: True"), line
    assert "fold at H = -1.555" in out and "ParameterError" in out
    # at H = 0 the CMC critical point is the Dirichlet extremal (the energy of the extremal job)
    assert "Dirichlet extremal: converged energy 4.572326885124," in out
    extremal_vs_cmc = float(out.split("max |extremal - CMC at H = 0| =")[1].split()[0])
    assert extremal_vs_cmc < 1e-12
    assert (tmp_path / "solve" / "result.json").exists()


def test_sweep_example_table(tmp_path):
    out = run_example("examples/004-cmc-circle-sweep/table.py", str(tmp_path))
    lines = [line.split() for line in out.splitlines()]
    rows = {int(l[0]): (l[1], float(l[2])) for l in lines if l and l[0].isdigit()}
    assert rows[3] == ("converged", -3.0)
    expected = {4: -1.55578, 5: -1.24656, 6: -1.14221, 7: -1.10445, 8: -1.08932}
    for n, H in expected.items():
        assert rows[n][0] == "fold" and abs(rows[n][1] - H) < 1e-5, (n, rows[n])
    # the fold approaches the exact problem's |H| = 1 from above, monotonically
    folds = [-rows[n][1] for n in range(4, 9)]
    assert all(a > b > 1 for a, b in zip(folds, folds[1:]))
    assert (tmp_path / "results.csv").exists()


def test_blend_example():
    out = run_example("examples/003-python-blend/blend.py")
    assert "bpde blend: J = 20.985443936," in out and "J = 20.985443936, |sigma|_L^2" in out
    assert "the same spline as bpde blend (edges recomputed here): True" in out
    # the data error shrinks with epsilon and becomes linear in it: the ratio to epsilon settles
    ratios = [float(line.split("ratio to epsilon")[1]) for line in out.splitlines() if "ratio to epsilon" in line]
    errors = [float(line.split("=")[2].split(",")[0]) for line in out.splitlines() if "ratio to epsilon" in line]
    assert len(ratios) == 5 and all(a > b for a, b in zip(errors, errors[1:]))
    assert abs(ratios[-1] - ratios[-2]) < 0.01 * ratios[-1]
    assert "converged biharmonic energy" in out
    energies = [float(w) for w in out.split("converged biharmonic energy")[1].split("\n")[0].replace(")", "").split()
                if w[0].isdigit()]
    assert energies[0] < energies[1]  # the extremal's energy is below the blend's (same ring)
    assert "ParameterError -> epsilon" in out and "SizeError -> points" in out
