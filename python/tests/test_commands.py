"""Every command of the bpde contract from Python against the command itself, on the example jobs:
the same JSON, every float to the last bit (but wall times)."""

import json
import os

import numpy as np
import pytest

import bezierpde
from conftest import bits, run_bpde, strip_seconds


def read_obj_vertices(path):
    with open(path, encoding="utf-8") as f:
        return np.array([[float(t) for t in line.split()[1:4]] for line in f if line.startswith("v ")])


def read_ply_curvature(path):
    """The per-vertex mean_curvature and regular columns of the ASCII PLY (x y z mean_curvature regular)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().splitlines()
    n = next(int(line.split()[2]) for line in lines if line.startswith("element vertex"))
    start = lines.index("end_header") + 1
    rows = [line.split() for line in lines[start : start + n]]
    return np.array([float(r[3]) for r in rows]), np.array([r[4] == "1" for r in rows])


def test_solve_and_blend_equal_the_command_on_every_example(examples, tmp_path):
    for k, (path, job, is_blend) in enumerate(examples):
        out = tmp_path / f"cli{k}"
        code, _, err = run_bpde("blend" if is_blend else "solve", path, "--out", out)
        assert code in (0, 1), f"{path}: {err}"
        with open(out / "result.json", encoding="utf-8") as f:
            cli = json.load(f)
        net, report = (bezierpde.blend if is_blend else bezierpde.solve)(job)
        assert bits(net) == bits(cli["net"]), path
        assert bits(strip_seconds(report)) == bits(strip_seconds(cli["report"])), path
        assert report["converged"] == (code == 0), path
        if not is_blend:
            # The whole result.json (extra fields such as "load" too), and the files with `out`.
            full = bezierpde.solve_result(job)
            assert bits(strip_seconds(full)) == bits(strip_seconds(cli)), path
            pyout = tmp_path / f"py{k}"
            bezierpde.solve(job, out=str(pyout))
            for name in ("surface.obj", "surface.ply", "net.obj"):
                assert (pyout / name).read_bytes() == (out / name).read_bytes(), f"{path}: {name}"


def test_complex_job_equals_the_command(tmp_path):
    # A patch complex (FORMATS.md "Patch complexes") with a tolerance: result.json's complex net,
    # the located certificate and the rounds, as the command writes them.
    job = {"boundary": {"type": "complex", "patch": "triangular", "degree": 3,
                        "loops": [[{"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]},
           "problem": {"kind": "cmc", "H": -0.5}, "samples": 8, "tolerance": {"boundary": 1e-5}}
    path = tmp_path / "complex.json"
    path.write_text(json.dumps(job), encoding="utf-8")
    code, _, err = run_bpde("solve", path, "--out", tmp_path / "cli")
    assert code == 0, err
    with open(tmp_path / "cli" / "result.json", encoding="utf-8") as f:
        cli = json.load(f)
    full = bezierpde.solve_result(job)
    assert full["net"]["type"] == "complex"
    assert len(full["report"]["rounds"]) >= 2
    assert bits(strip_seconds(full)) == bits(strip_seconds(cli))


@pytest.mark.parametrize("index", [0, 16, 30])
def test_sample_energy_check_equal_the_command(examples, tmp_path, index):
    path, job, _ = examples[index]
    net_file = tmp_path / "net.json"
    net_file.write_text(json.dumps(job["net"]))
    # sample: the OBJ vertices (17 significant digits: exact) and the PLY mean curvature.
    code, _, err = run_bpde("sample", net_file, "--out", tmp_path / "s", "--samples", 12)
    assert code == 0, err
    V, F, H = bezierpde.sample(job["net"], samples=12)
    assert np.array_equal(V, read_obj_vertices(tmp_path / "s" / "surface.obj"))
    # The PLY's mean_curvature equals the mesh's H at its regular vertices (elsewhere it is the mean
    # of the regular neighbours, FORMATS.md "Surface files").
    H_ply, regular = read_ply_curvature(tmp_path / "s" / "surface.ply")
    assert regular.sum() > len(regular) // 2
    assert np.array_equal(H[regular], H_ply[regular])
    bezierpde.sample(job["net"], samples=12, out=str(tmp_path / "p"))
    for name in ("surface.obj", "surface.ply", "net.obj"):
        assert (tmp_path / "p" / name).read_bytes() == (tmp_path / "s" / name).read_bytes()
    # energy, by bare name and as an ENERGY object
    for e in ("dirichlet", "biharmonic", '{"name": "laplacian-squared"}'):
        code, out, err = run_bpde("energy", net_file, "--energy", e)
        assert code == 0, err
        assert bits(bezierpde.energy(job["net"], e)) == bits(json.loads(out))
    code, out, err = run_bpde("energy", net_file, "--energy", "cmc", "--H", -1.25)
    assert code == 0, err
    assert bits(bezierpde.energy(job["net"], "cmc", H=-1.25)) == bits(json.loads(out))
    # check (CGAL)
    code, out, err = run_bpde("check", net_file, "--samples", 15)
    assert code == 0, err
    assert bits(bezierpde.check(job["net"], samples=15)) == bits(json.loads(out))
    # the same through a net object
    assert bits(bezierpde.check(bezierpde.net_from_dict(job["net"]), samples=15)) == bits(json.loads(out))


@pytest.mark.parametrize(
    "aspect,degree,method", [(1.0, 8, "admissible-load"), (2.0, 10, "ritz"), (0.5, 6, "admissible-load")]
)
def test_plate_equals_the_command(aspect, degree, method):
    code, out, err = run_bpde("plate", "--aspect", aspect, "--degree", degree, "--method", method)
    assert code == 0, err
    assert bits(strip_seconds(bezierpde.plate(aspect, degree, method))) == bits(strip_seconds(json.loads(out)))


def test_a_fold_is_a_report_not_an_exception(examples):
    path, job, _ = next(e for e in examples if e[0].endswith("n6-H-1.5-past-fold.json"))
    net, report = bezierpde.solve(job)
    assert report["converged"] is False and "fold" in report["message"] or "branch" in report["message"]
    assert report["H"] > -1.5


def test_solver_entry_points_with_options_and_summary(examples):
    # CMC (triangular) on the circle of Fig. 1: the same D_H as the job through bpde solve.
    path, job, _ = next(e for e in examples if e[0].endswith("n4-b-H-1.json"))
    _, report = bezierpde.solve(job)
    options = bezierpde.CmcOptions()
    options.H = -1.0
    options.solver = "newton"
    r = bezierpde.solve_cmc(bezierpde.net_from_dict(job["net"]), options)
    assert r.summary.status == bezierpde.Status.Converged and r.summary.converged
    assert r.summary.iterations > 0 and 0 <= r.summary.residual <= 1e-11
    assert r.DH == report["energy"] and r.D == report["D"]
    assert isinstance(r.net, bezierpde.TriangularNet) and r.net.points.shape == (15, 3)
    # PDE (explicit and lu agree on the biharmonic example, as the paper's two methods must).
    path, job, _ = next(e for e in examples if e[0].endswith("fig1-biharmonic.json"))
    data = bezierpde.net_from_dict(job["net"])
    net_e, s_e = bezierpde.solve_pde_explicit(data, "biharmonic")
    net_l, s_l = bezierpde.solve_pde_lu(data, {"name": "biharmonic"}, bezierpde.PdeLuOptions())
    assert s_e.converged and s_l.converged and s_e.status.text == "converged"
    assert np.max(np.abs(net_e.points - net_l.points)) < 1e-9
    net_cli, _ = bezierpde.solve(job)
    by_method = net_e if job["problem"].get("method") == "explicit" else net_l
    assert np.array_equal(bezierpde.points(net_cli), by_method.points)
    # Tetraharmonic and the clamped plate.
    path, job, _ = next(e for e in examples if e[0].endswith("arch-fig7-tetraharmonic.json"))
    net_t, s_t = bezierpde.solve_tetraharmonic(bezierpde.net_from_dict(job["net"]))
    assert s_t.converged and net_t.n == net_t.m == job["net"]["degree"][0]
    po = bezierpde.ClampedPlateOptions()
    po.aspect, po.degree, po.method = 1.0, 8, "admissible-load"
    plate = bezierpde.solve_clamped_plate(po)
    assert plate.summary.converged
    assert plate.center_deflection == bezierpde.plate(1.0, 8, "admissible-load")["center_deflection"]
