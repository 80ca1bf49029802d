"""The limits of FORMATS.md "Input limits" in the solver entry points called directly (as a job
checks them), and Ctrl-C during long solves called from Python."""

import os
import signal
import threading
import time

import numpy as np
import pytest

import bezierpde


def circle_job(degree, **problem):
    spec = {"base": {"net": {"type": "triangular", "degree": degree}, "fixed": "boundary",
                     "problem": {"kind": "cmc", "H": -1.0, **problem}, "samples": 10},
            "boundary": "circle-three-arcs"}
    jobs, _ = bezierpde.expand_sweep(spec)
    return jobs[0]["job"]


def cmc_options(**fields):
    o = bezierpde.CmcOptions()
    o.H = -1.0
    for k, v in fields.items():
        setattr(o, k, v)
    return o


def seconds_of(call):
    t = time.monotonic()
    call()
    return time.monotonic() - t


@pytest.mark.parametrize(
    "call,cls,name",
    [
        # cmc: tensor n, m <= 16, triangular n <= 25 (kMaxCmcTensorDegree, kMaxCmcTriangularDegree)
        (lambda: bezierpde.solve_cmc(bezierpde.TriangularNet(64), cmc_options()), bezierpde.DegreeError, "solve_cmc"),
        (lambda: bezierpde.solve_cmc(bezierpde.TriangularNet(26), cmc_options()), bezierpde.DegreeError, "solve_cmc"),
        (lambda: bezierpde.solve_cmc(bezierpde.TensorNet(17, 4), cmc_options()), bezierpde.DegreeError, "solve_cmc"),
        (lambda: bezierpde.solve_cmc(bezierpde.TensorNet(4, 30), cmc_options()), bezierpde.DegreeError, "solve_cmc"),
        (lambda: bezierpde.solve_cmc(bezierpde.TriangularNet(8), cmc_options(fixed="u-boundaries")),
         bezierpde.UnsupportedProblem, "solve_cmc"),
        # triangular extremal: n <= 20 (kMaxTriangularExtremalDegree)
        (lambda: bezierpde.solve_extremal(bezierpde.TriangularNet(21), "dirichlet", "boundary"),
         bezierpde.DegreeError, "solve_extremal"),
        # tetraharmonic: n = m <= 40 (kMaxC1Degree)
        (lambda: bezierpde.solve_tetraharmonic(bezierpde.TensorNet(41, 41)), bezierpde.DegreeError,
         "solve_tetraharmonic"),
        # samples 1..2000 (kMaxSamples)
        (lambda: bezierpde.sample(bezierpde.TriangularNet(2), samples=2001), bezierpde.ParameterError, "samples"),
        (lambda: bezierpde.check(bezierpde.TriangularNet(2), samples=2001), bezierpde.ParameterError, "samples"),
    ],
)
def test_entry_points_refuse_what_the_limits_table_refuses(call, cls, name):
    # Refused at once, before any work: each of these ran for minutes (or 7 GB) when it was taken.
    with pytest.raises(cls) as e:
        assert seconds_of(call) is None  # not reached
    assert str(e.value).startswith(name), str(e.value)


def test_entry_points_take_what_the_limits_table_takes():
    # The largest degrees allowed still run (and converge on the circle data of Fig. 1).
    net = bezierpde.net_from_dict(circle_job(25)["net"])
    r = bezierpde.solve_cmc(net, cmc_options())
    assert r.summary.status == bezierpde.Status.Converged and abs(r.H + 1.0) < 1e-9
    plane = bezierpde.TriangularNet(20)
    n = 20
    plane.points = np.array([[i / n, j / n, 0.0] for i in range(n, -1, -1) for j in range(n - i, -1, -1)])
    r = bezierpde.solve_extremal(plane, "dirichlet", "boundary")
    assert np.abs(r.net.points[:, 2]).max() < 1e-6


def interrupt_after(seconds):
    """SIGINT to this process after `seconds`, from another thread (as Ctrl-C on a terminal)."""
    timer = threading.Timer(seconds, os.kill, (os.getpid(), signal.SIGINT))
    timer.start()
    return timer


@pytest.mark.parametrize(
    "call",
    [
        # The area functional at degree 25 takes about 24 s on the build machine (the least-squares
        # start and the soft-mode phases); both entry points stop within a second of Ctrl-C.
        lambda: bezierpde.solve(circle_job(25, functional="area")),
        lambda: bezierpde.solve_cmc(bezierpde.net_from_dict(circle_job(25)["net"]), cmc_options(functional="area")),
    ],
    ids=["solve", "solve_cmc"],
)
def test_ctrl_c_stops_a_long_solve(call):
    # Python's own handler, whatever the test runner inherited (a background job may ignore SIGINT)
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = interrupt_after(1.0)
    t = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()  # a solve that ends before the signal fails here (no KeyboardInterrupt)
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    assert time.monotonic() - t < 10.0
    # the module is usable afterwards
    assert bezierpde.solve(circle_job(6))[1]["converged"]


# Seconds from Ctrl-C to KeyboardInterrupt allowed in a long factorisation: the next interruption
# point is well under a second away on an idle machine (docs/robustness.md, "Interrupting a solve");
# without the points each call below runs to its end and raises nothing.
LATENCY_BOUND = 20.0


def sheet(n):
    net = bezierpde.TensorNet(n, n)
    net.points = np.array([[i / n, j / n, 0.2 * np.sin(3 * i / n) * np.cos(2 * j / n)]
                           for i in range(n + 1) for j in range(n + 1)])
    return net


@pytest.mark.parametrize(
    "call",
    [
        # The largest sizes the limits allow: the dense tetraharmonic operator at degree 40 (86 s on
        # an idle machine), the tensor extremal at degree 64 (its Gram matrix and Cholesky factor;
        # 7.5 s on the loaded build machine) and a 256 x 256 blend job. Each stops at its next
        # interruption point (core/interruption.h) instead of running to its end.
        lambda: bezierpde.solve_tetraharmonic(sheet(40)),
        lambda: bezierpde.solve_extremal(sheet(64), "biharmonic", "boundary"),
        lambda: bezierpde.blend({"kind": "blend", "partition": [256, 256], "a": 1, "epsilon": 0.01, "samples": 4,
                                 "surfaces": {"f": {"type": "tensor", "degree": [1, 1],
                                                    "points": [[0, 0, 0], [0, 1, 0], [1, 0, 0], [1, 1, 0.5]]},
                                              "g": {"type": "tensor", "degree": [1, 1],
                                                    "points": [[0, 2, 0], [0, 3, 0], [1, 2, 0], [1, 3, 1]]}}}),
    ],
    ids=["tetraharmonic", "extremal", "blend"],
)
def test_ctrl_c_stops_a_long_factorisation(call, record_property):
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = interrupt_after(1.0)
    t = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, previous)
    latency = time.monotonic() - t - 1.0
    record_property("latency_s", latency)
    assert latency < LATENCY_BOUND
    assert bezierpde.solve(circle_job(6))[1]["converged"]
