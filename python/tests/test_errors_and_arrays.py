"""The exception hierarchy (core/errors.h mirrored), array shapes and views, the GIL."""

import json

import numpy as np
import pytest

import bezierpde
from conftest import ticks_during


def circle_job(degree=4, H=-1.0):
    spec = {"base": {"net": {"type": "triangular", "degree": degree}, "fixed": "boundary",
                     "problem": {"kind": "cmc", "H": H}, "samples": 10},
            "boundary": "circle-three-arcs"}
    jobs, _ = bezierpde.expand_sweep(spec)
    return jobs[0]["job"]


def test_hierarchy():
    for name in ("ParseError", "FileError", "DegreeError", "SizeError", "NonFiniteError", "ParameterError",
                 "UnsupportedProblem"):
        cls = getattr(bezierpde, name)
        assert issubclass(cls, bezierpde.InvalidInput) and cls.__module__ == "bezierpde"
    assert issubclass(bezierpde.InvalidInput, ValueError) and issubclass(bezierpde.InvalidInput, bezierpde.Error)
    assert issubclass(bezierpde.InternalError, RuntimeError) and issubclass(bezierpde.InternalError, bezierpde.Error)
    assert not issubclass(bezierpde.InternalError, ValueError)


@pytest.mark.parametrize(
    "mutate,cls,words",
    [
        (lambda j: j.update(net=3), bezierpde.ParseError, "job.net"),
        (lambda j: j["net"].update(degree=1), bezierpde.SizeError, "points"),
        (lambda j: j["problem"].update(H=float("nan")), bezierpde.NonFiniteError, "finite"),
        (lambda j: j.update(problem={"kind": "tetraharmonic"}), bezierpde.UnsupportedProblem, "tensor net"),
        (lambda j: j["problem"].update(solver="simplex"), bezierpde.ParseError, "simplex"),
        (lambda j: j.update(samples=0), bezierpde.InvalidInput, "samples"),
        (lambda j: j.update(colour="red"), bezierpde.ParseError, "colour"),
    ],
)
def test_bad_jobs_raise_the_typed_exception(mutate, cls, words):
    job = circle_job()
    mutate(job)
    with pytest.raises(cls) as e:
        bezierpde.solve(job)
    assert words in str(e.value)


def test_other_bad_input():
    with pytest.raises(bezierpde.DegreeError):
        bezierpde.plate(1.0, 2, "admissible-load")
    with pytest.raises(bezierpde.ParseError):
        bezierpde.plate(1.0, 8, "magic")
    with pytest.raises(bezierpde.ParameterError):
        bezierpde.plate(1000.0, 8, "ritz")
    with pytest.raises(bezierpde.FileError):
        bezierpde.solve(circle_job(), out="/proc/no/such/dir")
    with pytest.raises(bezierpde.ParameterError):
        bezierpde.sample(circle_job()["net"], samples=0)
    with pytest.raises(bezierpde.InvalidInput):
        bezierpde.energy(circle_job()["net"], "no-such-energy")
    with pytest.raises(bezierpde.ParseError):
        bezierpde.solve({"net": {1: 2}})
    with pytest.raises(bezierpde.SizeError):
        deep = []
        for _ in range(300):
            deep = [deep]
        bezierpde.solve({"net": deep})
    with pytest.raises(bezierpde.SizeError):
        bezierpde.TriangularNet(4).points = np.zeros((3, 3))
    with pytest.raises(bezierpde.InvalidInput):
        bezierpde.sweep({"base": circle_job(), "axes": {"problem.H": []}})


@pytest.mark.parametrize(
    "call,cls,argument",
    [
        (lambda net: bezierpde.energy(net, "cmc"), bezierpde.ParseError, "H"),
        (lambda net: bezierpde.energy(net, "cmc", H=float("inf")), bezierpde.NonFiniteError, "H"),
        (lambda net: bezierpde.energy(net, "no-such-energy"), bezierpde.ParseError, "energy"),
        (lambda net: bezierpde.energy(net, '{"name": 3}'), bezierpde.ParseError, "energy"),
        (lambda net: bezierpde.plate(1.0, 2, "ritz"), bezierpde.DegreeError, "degree"),
        (lambda net: bezierpde.plate(1000.0, 8, "ritz"), bezierpde.ParameterError, "aspect"),
        (lambda net: bezierpde.plate(-1.0, 8, "ritz"), bezierpde.ParameterError, "aspect"),
        (lambda net: bezierpde.plate(1.0, 8, "magic"), bezierpde.ParseError, "method"),
        (lambda net: bezierpde.sample(net, samples=0), bezierpde.ParameterError, "samples"),
        (lambda net: bezierpde.solve_extremal(bezierpde.net_from_dict(net), "no-such-energy", "boundary"),
         bezierpde.ParseError, "energy"),
    ],
)
def test_errors_name_the_python_argument_not_a_command_flag(call, cls, argument):
    with pytest.raises(cls) as e:
        call(circle_job()["net"])
    text = str(e.value)
    assert argument in text and "--" not in text, text


def test_arrays_shapes_and_views():
    job = circle_job(degree=5)
    net, report = bezierpde.solve(job)
    V, F, H = bezierpde.sample(net, samples=10)
    assert V.shape == (66, 3) and V.dtype == np.float64
    assert F.shape == (100, 3) and F.dtype == np.int32 and F.min() == 0 and F.max() == 65
    assert H.shape == (66,) and H.dtype == np.float64
    # the arrays own the C++ buffers (no copy was made, none is shared)
    assert not V.flags["OWNDATA"] and V.base is not None
    tensor = bezierpde.TensorNet(2, 3)
    assert tensor.points.shape == (12, 3)
    # points is a view: writing through it changes the net
    tri = bezierpde.net_from_dict(net)
    assert isinstance(tri, bezierpde.TriangularNet) and tri.points.shape == (21, 3)
    P = tri.points
    P[0, 2] = 0.5
    assert tri.points[0, 2] == 0.5 and tri.to_dict()["points"][0][2] == 0.5
    tri.points = np.asarray(bezierpde.points(net))
    assert np.array_equal(tri.points, bezierpde.points(net))
    assert np.allclose(tri.evaluate(1.0, 0.0), tri.points[0])
    # numpy input: a C-ordered array and a list give the same net
    a = bezierpde.TriangularNet(5, np.ascontiguousarray(bezierpde.points(net)))
    assert np.array_equal(a.points, tri.points)
    assert bezierpde.check_mesh(V, F)["self_intersections"] == 0


def test_the_gil_is_released_during_solves():
    # While one solve runs in C++ on a thread, another Python thread keeps running: it records
    # time stamps, and some fall inside the solve (none could if the solve held the GIL).
    job = circle_job(degree=16, H=-0.5)
    converged = []
    inside, seconds = ticks_during(lambda: converged.append(bezierpde.solve(job)[1]["converged"]))
    assert converged == [True]
    assert inside >= 3, (inside, seconds)


SURROGATE = "\ud800"  # a lone surrogate: a str that UTF-8 cannot hold


@pytest.mark.parametrize(
    "call,cls,argument",
    [
        # wrong array shapes: SizeError naming the argument, never pybind11's TypeError
        (lambda: bezierpde.TensorNet(2, 2, np.zeros((9, 2))), bezierpde.SizeError, "points"),
        (lambda: bezierpde.TriangularNet(2, np.zeros((6, 4))), bezierpde.SizeError, "points"),
        (lambda: bezierpde.TriangularNet(2, [[1.0, 2.0]]), bezierpde.SizeError, "points"),
        (lambda: bezierpde.TriangularNet(2, np.zeros(18)), bezierpde.SizeError, "points"),
        (lambda: bezierpde.TriangularNet(2, [["a", "b", "c"]] * 6), bezierpde.ParseError, "points"),
        (lambda: setattr(bezierpde.TriangularNet(2), "points", np.zeros((6, 2))), bezierpde.SizeError, "points"),
        (lambda: bezierpde.check_mesh(np.zeros((3, 2)), [[0, 1, 2]]), bezierpde.SizeError, "V"),
        (lambda: bezierpde.check_mesh(np.eye(3), [[0, 1]]), bezierpde.SizeError, "F"),
        (lambda: bezierpde.check_mesh(np.eye(3), [[0, 1, 3]]), bezierpde.ParameterError, "F"),
        (lambda: bezierpde.ExtremalSolver(np.ones(4), [0]), bezierpde.SizeError, "gram"),
        (lambda: bezierpde.ExtremalSolver(np.diag([1.0, np.nan]), [0]), bezierpde.NonFiniteError, "gram"),
        # strings that are not valid Unicode (a lone surrogate) or not strings at all
        (lambda: bezierpde.net_from_dict({"type": SURROGATE}), bezierpde.ParseError, "net"),
        (lambda: bezierpde.net_from_dict({SURROGATE: 1}), bezierpde.ParseError, "net"),
        (lambda: bezierpde.energy(bezierpde.TriangularNet(2), SURROGATE), bezierpde.ParseError, "energy"),
        (lambda: bezierpde.solve_extremal(bezierpde.TriangularNet(4), "dirichlet", SURROGATE),
         bezierpde.ParseError, "fixed"),
        (lambda: bezierpde.solve_extremal(bezierpde.TriangularNet(4), "dirichlet", 3), bezierpde.ParseError, "fixed"),
        (lambda: setattr(bezierpde.CmcOptions(), "solver", SURROGATE), bezierpde.ParseError, "solver"),
        (lambda: bezierpde.plate(1.0, 8, SURROGATE), bezierpde.ParseError, "method"),
        (lambda: bezierpde.sample(bezierpde.TriangularNet(2), 3, SURROGATE), bezierpde.ParseError, "out"),
        (lambda: bezierpde.expand_sweep({"base": {}, "axes": {SURROGATE: [1]}}), bezierpde.ParseError, "spec"),
        # the sweep's process count, as `bpde sweep --jobs`
        (lambda: bezierpde.sweep({"base": circle_job(), "axes": {"problem.H": [-1.0]}}, jobs=1025),
         bezierpde.ParameterError, "jobs"),
        (lambda: bezierpde.sweep({"base": circle_job(), "axes": {"problem.H": [-1.0]}}, jobs=-1),
         bezierpde.ParameterError, "jobs"),
    ],
)
def test_bad_arguments_raise_the_documented_typed_exception(call, cls, argument):
    with pytest.raises(cls) as e:
        call()
    assert isinstance(e.value, bezierpde.InvalidInput) and isinstance(e.value, ValueError)
    assert str(e.value).startswith(argument), str(e.value)


def test_nan_points_are_refused_by_the_setter_and_by_every_command():
    net = bezierpde.TriangularNet(4)
    good = np.arange(45, dtype=float).reshape(15, 3)
    net.points = good
    bad = good.copy()
    bad[7, 1] = np.nan
    with pytest.raises(bezierpde.NonFiniteError) as e:
        net.points = bad
    assert str(e.value).startswith("points") and "row 7 column 1" in str(e.value)
    assert np.array_equal(net.points, good)  # unchanged by the refused assignment
    bad[7, 1] = np.inf
    with pytest.raises(bezierpde.NonFiniteError):
        bezierpde.TriangularNet(4, bad)
    # a NaN written through the `points` view reaches no result: every command refuses the net
    net.points[3, 2] = np.nan
    for call in (lambda: bezierpde.sample(net, samples=4), lambda: bezierpde.check(net, samples=4),
                 lambda: bezierpde.energy(net, "dirichlet")):
        with pytest.raises(bezierpde.NonFiniteError) as e:
            call()
        assert "row 3 column 2" in str(e.value)


def test_a_sweep_file_is_read_as_bpde_reads_it(tmp_path):
    # A key given twice: json.load keeps the last, `bpde sweep` and bezierpde.sweep refuse the file.
    path = tmp_path / "sweep.json"
    base = json.dumps(circle_job())
    path.write_text('{"base": %s, "axes": {"problem.H": [-1.0]}, "axes": {"problem.H": [-2.0]}}' % base)
    with pytest.raises(bezierpde.ParseError):
        bezierpde.sweep(str(path), out=str(tmp_path / "out"))
    with pytest.raises(bezierpde.ParseError):
        bezierpde.sweep(path, out=str(tmp_path / "out"))
    assert not (tmp_path / "out").exists()
    path.write_text('{"base": %s, "axes": {"problem.H": [-2.0]}}' % base)  # the same spec, once
    table = bezierpde.sweep(str(path), out=str(tmp_path / "out"), jobs=1)
    assert len(table) == 1
    with pytest.raises(bezierpde.FileError):
        bezierpde.sweep(str(tmp_path / "missing.json"))
