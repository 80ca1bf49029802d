"""Shared helpers of the Python tests: the bpde binary, the example jobs, exact comparison."""

import glob
import json
import math
import os
import subprocess
import threading
import time

import pytest

SOURCE_DIR = os.environ.get("BPDE_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("BPDE_BINARY", os.path.join(SOURCE_DIR, "build", "bpde"))


def run_bpde(*args, cwd=None):
    """(exit code, stdout, stderr) of the bpde command."""
    p = subprocess.run([BINARY, *map(str, args)], capture_output=True, text=True, cwd=cwd)
    return p.returncode, p.stdout, p.stderr


def example_files():
    """(path, dict, is_blend) of every job and blend config in examples/ (not sweeps)."""
    out = []
    for path in sorted(glob.glob(os.path.join(SOURCE_DIR, "examples", "*", "*.json"))):
        with open(path, encoding="utf-8") as f:
            j = json.load(f)
        if isinstance(j, dict) and j.get("kind") == "blend":
            out.append((path, j, True))
        elif isinstance(j, dict) and "problem" in j and "net" in j:
            out.append((path, j, False))
    return out


def strip_seconds(x):
    """`x` without its "seconds" fields (wall times differ from run to run)."""
    if isinstance(x, dict):
        return {k: strip_seconds(v) for k, v in x.items() if k != "seconds"}
    if isinstance(x, list):
        return [strip_seconds(v) for v in x]
    return x


def bits(x):
    """A form of `x` whose equality is bit equality of every float (0.0 != -0.0)."""
    if isinstance(x, dict):
        return {k: bits(v) for k, v in x.items()}
    if isinstance(x, list):
        return [bits(v) for v in x]
    if isinstance(x, float):
        return ("float", x.hex()) if math.isfinite(x) else ("float", repr(x))
    return x


@pytest.fixture(scope="session")
def examples():
    files = example_files()
    assert len(files) >= 20, "the example jobs were not found under " + SOURCE_DIR
    return files


def ticks_during(solve):
    """How many time stamps another Python thread records while `solve()` runs on a thread (none
    could fall inside if the solve held the GIL)."""
    ticks, span = [], []
    stop = threading.Event()

    def ticker():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            stop.wait(0.001)

    def solver():
        t0 = time.perf_counter()
        solve()
        span.extend([t0, time.perf_counter()])

    t = threading.Thread(target=ticker)
    t.start()
    s = threading.Thread(target=solver)
    s.start()
    s.join()
    stop.set()
    t.join()
    t0, t1 = span
    margin = 0.1 * (t1 - t0)
    return len([x for x in ticks if t0 + margin < x < t1 - margin]), t1 - t0
