"""Patch complexes from Python (FORMATS.md "Patch complexes"): built from loops as a job's
"boundary" builds them, solved by the extremal and cmc solvers, read as numpy arrays and nets,
sampled, and run as jobs and sweeps with the command's results."""

import json
import math
import os

import numpy as np
import pytest

import bezierpde

from conftest import run_bpde

DIRICHLET = {"kind": "extremal", "energy": {"name": "dirichlet"}}


def polygon_loop(k, z=lambda t: 0.0):
    """The regular k-gon of radius 1 as k segments, its vertex j at height z(2 pi j / k)."""
    pts = [[math.cos(2 * math.pi * j / k), math.sin(2 * math.pi * j / k), z(2 * math.pi * j / k)] for j in range(k)]
    return [{"type": "segment", "from": pts[j], "to": pts[(j + 1) % k]} for j in range(k)]


def boundary(loop, degree=3, refine=0, patch="triangular"):
    return {"type": "complex", "patch": patch, "degree": degree, "refine": refine, "loops": [loop]}


def job(bnd, problem=DIRICHLET, samples=6):
    return {"boundary": bnd, "problem": problem, "samples": samples}


def saddle(t):
    return 0.3 * math.cos(2 * t)


def test_a_complex_is_built_from_loops_and_read_as_arrays_and_nets():
    c = bezierpde.complex_from_boundary(boundary(polygon_loop(5), degree=3))
    assert c.kind == "triangular" and c.degree == 3 and len(c) >= 3
    P = c.points
    assert isinstance(P, np.ndarray) and P.shape[1] == 3 and P.dtype == np.float64
    fixed = c.fixed
    assert fixed == sorted(set(fixed)) and 0 < len(fixed) < P.shape[0]
    # The fixed rows lie on the pentagon (the plane z = 0, inside the unit circle, every vertex).
    assert np.allclose(P[fixed, 2], 0.0) and (np.hypot(P[fixed, 0], P[fixed, 1]) <= 1 + 1e-12).all()
    for j in range(5):
        v = [math.cos(2 * math.pi * j / 5), math.sin(2 * math.pi * j / 5), 0.0]
        assert np.linalg.norm(P[fixed] - v, axis=1).min() < 1e-12
    assert np.isfinite(P).all()
    for p, net in enumerate(c.patches):
        assert isinstance(net, bezierpde.TriangularNet) and net.n == 3
        np.testing.assert_array_equal(np.asarray(net.points), P[c.patch_rows(p)])
        np.testing.assert_array_equal(np.asarray(c.patch(p).points), np.asarray(net.points))
    # refine 1 splits every patch in four
    assert len(bezierpde.complex_from_boundary(boundary(polygon_loop(5), degree=3, refine=1))) == 4 * len(c)
    q = bezierpde.complex_from_boundary(boundary(polygon_loop(4), degree=2, patch="tensor"))
    assert q.kind == "tensor" and all(isinstance(n, bezierpde.TensorNet) for n in q.patches)


def test_the_extremal_of_planar_data_is_planar_and_equals_the_job():
    c = bezierpde.complex_from_boundary(boundary(polygon_loop(5), degree=4))
    r = bezierpde.solve_complex_extremal(c, "dirichlet")
    assert r.summary.status == bezierpde.Status.Converged
    P = r.complex.points
    assert np.abs(P[:, 2]).max() < 1e-12  # planar data, planar extremal
    np.testing.assert_array_equal(P[c.fixed], c.points[c.fixed])  # the data are kept
    # The sampled surface covers the pentagon: its area is the pentagon's (planar, straight edges).
    V, F, H, patch = bezierpde.sample_complex(r.complex, 8)
    assert V.shape[1] == 3 and F.shape[1] == 3 and H.shape == (V.shape[0],) and patch.shape == (F.shape[0],)
    assert set(np.unique(patch)) == set(range(len(c)))
    a, b, d = V[F[:, 0]], V[F[:, 1]], V[F[:, 2]]
    area = 0.5 * np.linalg.norm(np.cross(b - a, d - a), axis=1).sum()
    assert abs(area - 2.5 * math.sin(2 * math.pi / 5)) < 1e-9
    assert np.abs(H).max() < 1e-8


@pytest.mark.parametrize("patch", ["triangular", "tensor"])
def test_solve_of_a_complex_job_is_the_commands_and_the_entry_points(patch, tmp_path):
    bnd = boundary(polygon_loop(4 if patch == "tensor" else 5, saddle), degree=4, patch=patch)
    j = job(bnd)
    net, report = bezierpde.solve(j)
    assert net["type"] == "complex" and report["converged"] and report["patches"] == len(net["patches"])
    # the command's result.json, to the last bit (but for the wall times)
    (tmp_path / "job.json").write_text(json.dumps(j))
    code, _, err = run_bpde("solve", tmp_path / "job.json", "--out", tmp_path / "out")
    assert code == 0, err
    cli = json.loads((tmp_path / "out" / "result.json").read_text())
    assert cli["net"] == net
    # the entry points give the same patches
    r = bezierpde.solve_complex_extremal(bezierpde.complex_from_boundary(bnd), "dirichlet")
    for p, patch_net in enumerate(r.complex.patches):
        np.testing.assert_allclose(np.asarray(patch_net.points), bezierpde.points(net["patches"][p]), rtol=0, atol=1e-12)
    assert abs(r.energy - report["energy"]) <= 1e-12 * abs(report["energy"])


def test_cmc_on_a_complex():
    bnd = boundary(polygon_loop(5), degree=4)
    o = bezierpde.CmcOptions()
    o.H = -0.5
    r = bezierpde.solve_cmc(bezierpde.complex_from_boundary(bnd), o)
    assert r.summary.status == bezierpde.Status.Converged and abs(r.H + 0.5) < 1e-12
    assert isinstance(r.net, bezierpde.PatchComplex)
    P = r.net.points
    # H != 0 bulges the planar pentagon to one side, by about the height of the sphere of radius
    # 1/|H| = 2 over the pentagon's circle, 2 - sqrt(3) = 0.27 (less over the pentagon).
    z = P[:, 2] * np.sign(P[np.argmax(np.abs(P[:, 2])), 2])
    assert (z > -1e-12).all() and 0.05 < z.max() < 0.4
    net, report = bezierpde.solve(job(bnd, {"kind": "cmc", "H": -0.5}))
    assert report["converged"]
    for p, patch_net in enumerate(r.net.patches):
        np.testing.assert_allclose(np.asarray(patch_net.points), bezierpde.points(net["patches"][p]), rtol=0, atol=1e-9)


def test_complex_jobs_in_a_sweep_with_degree_and_refine_axes(tmp_path):
    spec = {"base": job(boundary(polygon_loop(5, saddle), degree=3)),
            "axes": {"boundary.degree": [3, 4], "boundary.refine": [0, 1]}}
    rows = bezierpde.sweep(spec, out=str(tmp_path / "s"), jobs=2)
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert [r["status"] for r in rows] == ["converged"] * 4
    patches = []
    for r in rows:
        result = json.loads((tmp_path / "s" / "jobs" / r["job"] / "result.json").read_text())
        assert result["report"]["degree"] == r["boundary.degree"] and result["report"]["refine"] == r["boundary.refine"]
        patches.append(result["report"]["patches"])
    assert patches[1] == 4 * patches[0] and patches[3] == 4 * patches[2]
    # the energy falls as the space grows (degree or refinement: the coarser spaces are contained)
    e = [r["energy"] for r in rows]
    assert e[1] <= e[0] + 1e-12 and e[2] <= e[0] + 1e-12 and e[3] <= min(e[1], e[2]) + 1e-12


@pytest.mark.parametrize(
    "call,cls",
    [
        (lambda: bezierpde.complex_from_boundary(boundary(polygon_loop(5), degree=21)), bezierpde.DegreeError),
        (lambda: bezierpde.complex_from_boundary(boundary(polygon_loop(5), refine=6)), bezierpde.SizeError),
        (lambda: bezierpde.complex_from_boundary(boundary(polygon_loop(5)[:4])), bezierpde.ParameterError),  # open loop
        (lambda: bezierpde.complex_from_boundary(boundary(polygon_loop(5)), fit="bogus"), bezierpde.ParameterError),
        (lambda: bezierpde.complex_from_boundary({**boundary(polygon_loop(5)), "extra": 1}), bezierpde.ParseError),
        (lambda: bezierpde.complex_from_boundary(boundary(polygon_loop(5)), fit=b"x"), bezierpde.ParseError),
        (lambda: bezierpde.solve_complex_extremal(bezierpde.complex_from_boundary(boundary(polygon_loop(5))), "bogus"),
         bezierpde.InvalidInput),
        (lambda: bezierpde.sample_complex(bezierpde.complex_from_boundary(boundary(polygon_loop(5))), 0),
         bezierpde.ParameterError),
        (lambda: bezierpde.complex_from_boundary({**boundary(polygon_loop(5)), "continuity": "C1"}),
         bezierpde.UnsupportedProblem),
    ],
)
def test_bad_complexes_raise_the_documented_errors(call, cls):
    with pytest.raises(cls):
        call()


def test_points_of_a_complex_are_checked():
    c = bezierpde.complex_from_boundary(boundary(polygon_loop(5)))
    with pytest.raises(bezierpde.SizeError):
        c.points = np.zeros((3, 3))
    P = c.points
    P[0, 0] = np.nan
    with pytest.raises(bezierpde.NonFiniteError):
        c.points = P
    P[0, 0] = 2.0
    c.points = P
    assert c.points[0, 0] == 2.0
