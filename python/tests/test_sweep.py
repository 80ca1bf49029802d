"""Sweeps: the command, local processes and a Dask LocalCluster of two workers give the same rows."""

import csv
import json
import os

import pytest

import bezierpde
from conftest import bits, run_bpde

SPEC = {
    "base": {"net": {"type": "triangular", "degree": 4}, "fixed": "boundary",
             "problem": {"kind": "cmc", "solver": "newton", "H": -1.0}, "samples": 12},
    "boundary": "circle-three-arcs",
    "axes": {"net.degree": [1, 3, 4, 5], "problem.H": [-0.5, -3.0]},
}


def normal(v):
    # A DataFrame holds null as NaN and integers of a column with nulls as floats: compare numbers
    # as the doubles they are (every bit) and NaN as null.
    if v is None or (isinstance(v, float) and v != v):
        return None
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        return v
    return float(v).hex()


def without_seconds(rows):
    return [{k: normal(v) for k, v in r.items() if k != "seconds"} for r in rows]


def records(table):
    """The rows of a sweep's table (a DataFrame, or a list of dicts without pandas)."""
    return table.to_dict("records") if hasattr(table, "to_dict") else table


def read_jsonl(path):
    with open(path, encoding="utf-8") as f:
        return [json.loads(line) for line in f]


@pytest.fixture(scope="module")
def cli_sweep(tmp_path_factory):
    d = tmp_path_factory.mktemp("cli")
    spec = d / "sweep.json"
    spec.write_text(json.dumps(SPEC))
    code, out, err = run_bpde("sweep", spec, "--out", d / "out", "--jobs", 2)
    assert code == 1, err  # some jobs are invalid or past the fold: exit 1, the tables written
    return d, read_jsonl(d / "out" / "results.jsonl")


def test_cli_rows(cli_sweep):
    d, rows = cli_sweep
    assert [r["job"] for r in rows] == [f"job-{k:04d}" for k in range(8)]
    # The last axis varies fastest; axis values are in the rows.
    assert [(r["net.degree"], r["problem.H"]) for r in rows] == [(n, h) for n in (1, 3, 4, 5) for h in (-0.5, -3.0)]
    by = {(r["net.degree"], r["problem.H"]): r for r in rows}
    # Degree 1 is refused by the cmc solver's requirements: a row with its error, exit 2.
    assert by[(1, -0.5)]["status"] == "invalid-input" and by[(1, -0.5)]["exit_code"] == 2
    assert "degree" in by[(1, -0.5)]["error"]
    assert not (d / "out" / "jobs" / "job-0000" / "result.json").exists()
    # n = 4 converges at H = -0.5 and folds before -3 (the fold of the circle at |H| = 1.5558).
    assert by[(4, -0.5)]["status"] == "converged" and by[(4, -0.5)]["exit_code"] == 0
    assert by[(4, -3.0)]["status"] == "fold" and by[(4, -3.0)]["exit_code"] == 1
    assert abs(by[(4, -3.0)]["H"] + 1.5558) < 1e-3 and by[(4, -3.0)]["error"]
    assert by[(4, -0.5)]["check_self_intersections"] == 0
    # Each job folder is what `bpde solve` writes for the expanded job.
    job_dir = d / "out" / "jobs" / "job-0004"
    code, _, err = run_bpde("solve", job_dir / "job.json", "--out", d / "solo")
    assert code == 0, err
    a = json.loads((job_dir / "result.json").read_text())
    b = json.loads((d / "solo" / "result.json").read_text())
    assert bits(a["net"]) == bits(b["net"]) and a["report"]["energy"] == b["report"]["energy"]
    assert by[(4, -0.5)]["energy"] == a["report"]["energy"]
    # results.csv: the same rows, the axis columns after index and job.
    with open(d / "out" / "results.csv", encoding="utf-8") as f:
        table = list(csv.DictReader(f))
    assert list(table[0].keys())[:4] == ["index", "job", "net.degree", "problem.H"]
    assert [t["status"] for t in table] == [r["status"] for r in rows]
    assert float(table[4]["energy"]) == rows[4]["energy"]


def test_cli_resume(cli_sweep, tmp_path):
    d, rows = cli_sweep
    stamp = {p: os.stat(d / "out" / "jobs" / p / "row.json").st_mtime_ns for p in os.listdir(d / "out" / "jobs")}
    code, out, err = run_bpde("sweep", d / "sweep.json", "--out", d / "out")
    assert code == 1 and "8 already done" in err
    assert stamp == {p: os.stat(d / "out" / "jobs" / p / "row.json").st_mtime_ns for p in stamp}
    assert read_jsonl(d / "out" / "results.jsonl") == rows
    # A changed job is rerun; the others are kept.
    (d / "out" / "jobs" / "job-0004" / "job.json").write_text("{}")
    code, out, err = run_bpde("sweep", d / "sweep.json", "--out", d / "out")
    assert "7 already done" in err


def test_expansion_is_the_commands(cli_sweep):
    d, rows = cli_sweep
    jobs, columns = bezierpde.expand_sweep(SPEC)
    assert [j["id"] for j in jobs] == [r["job"] for r in rows]
    for j in jobs:
        with open(d / "out" / "jobs" / j["id"] / "job.json", encoding="utf-8") as f:
            assert bits(json.load(f)) == bits(j["job"])
    assert columns[:4] == ["index", "job", "net.degree", "problem.H"] and "seconds" in columns


def test_local_processes_give_the_commands_rows(cli_sweep, tmp_path):
    d, rows = cli_sweep
    table = bezierpde.sweep(SPEC, out=str(tmp_path / "py"), jobs=2)
    assert without_seconds(records(table)) == without_seconds(rows)
    assert without_seconds(read_jsonl(tmp_path / "py" / "results.jsonl")) == without_seconds(rows)


def test_dask_local_cluster_gives_the_commands_rows(cli_sweep, tmp_path):
    distributed = pytest.importorskip("distributed")
    d, rows = cli_sweep
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            table = bezierpde.sweep(SPEC, client=client, out=str(tmp_path / "dask"))
            ran_on = {w for w in client.run(os.getpid).values()}
    assert len(ran_on) == 2
    assert list(records(table)[0].keys()) == bezierpde.expand_sweep(SPEC)[1]
    assert without_seconds(records(table)) == without_seconds(rows)
    with open(tmp_path / "dask" / "results.csv", encoding="utf-8") as f:
        assert len(list(csv.DictReader(f))) == 8


def test_axis_paths_deeper_than_the_readers_are_refused():
    # 100000 segments used to overflow the stack while the job was converted to Python.
    for segments in (257, 100000):
        spec = {"base": {}, "axes": {".".join(["a"] * segments): [1]}}
        with pytest.raises(bezierpde.ParseError):
            bezierpde.expand_sweep(spec, ".")
    jobs, _ = bezierpde.expand_sweep({"base": {}, "axes": {".".join(["a"] * 256): [1]}}, ".")
    assert len(jobs) == 1 and jobs[0]["error"] == ""
