"""The Python examples run as a user runs them, and say what their READMEs say."""

import os
import subprocess
import sys

from conftest import SOURCE_DIR


def run_example(script, *args):
    env = dict(os.environ)
    p = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, script), *args], capture_output=True, text=True,
                       cwd=SOURCE_DIR, env=env, timeout=300)
    assert p.returncode == 0, p.stderr
    return p.stdout


def test_notebook_example(tmp_path):
    out = run_example("examples/004-python-circle/circle.py", str(tmp_path))
    assert "D_H = 3.870131207373, V = 0.802165303653, converged: True" in out
    assert "fold at H = -1.555" in out and "ParameterError" in out
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
