"""The README's Python snippets run as a user runs them: each saved as a file and run with this
interpreter from the repository root (not through `python -c`, where a script's re-import by
worker processes does not happen)."""

import os
import re
import subprocess
import sys

import pytest

from conftest import SOURCE_DIR


def readme_programs():
    """The README's ```python blocks as programs: a block that begins with an import starts a
    program, a block that does not continues the one before it (it uses its names)."""
    with open(os.path.join(SOURCE_DIR, "README.md"), encoding="utf-8") as f:
        blocks = re.findall(r"^```python\n(.*?)^```", f.read(), flags=re.S | re.M)
    programs = []
    for block in blocks:
        if re.match(r"(import|from) ", block) or not programs:
            programs.append(block)
        else:
            programs[-1] += block
    return programs


def test_the_readme_has_its_snippets():
    programs = readme_programs()
    assert len(programs) >= 2
    assert any("LocalCluster" in p for p in programs)


@pytest.mark.parametrize("index", range(len(readme_programs())))
def test_readme_snippet_runs_as_a_file(index, tmp_path):
    program = readme_programs()[index]
    if "dask" in program:
        pytest.importorskip("distributed")
        pytest.importorskip("pandas")
    script = tmp_path / f"snippet{index}.py"
    script.write_text(program, encoding="utf-8")
    p = subprocess.run([sys.executable, str(script)], capture_output=True, text=True, cwd=SOURCE_DIR,
                       env=dict(os.environ), timeout=240)
    assert p.returncode == 0, p.stderr[-4000:]
    if "LocalCluster" in program:
        assert "fold" in p.stdout  # the status column the snippet prints
