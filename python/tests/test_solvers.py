"""The solver entry points (their Options, Summary and result classes) against the JSON route
(`bezierpde.solve` / `bezierpde.blend`, which test_commands.py checks against `bpde` itself) on
the example jobs: the same nets and numbers to the last bit. Then option validation, the C++
defaults, and array shapes."""


import numpy as np
import pytest

import bezierpde
from conftest import bits, ticks_during


def tensor_examples(examples):
    return [(p, j) for p, j, blend in examples if not blend and j["net"]["type"] == "tensor"]


def triangular_examples(examples):
    return [(p, j) for p, j, blend in examples if not blend and j["net"]["type"] == "triangular"]


def blend_examples(examples):
    return [(p, j) for p, j, blend in examples if blend]


def as_bspline(tensor_net):
    """A tensor Bézier net as the one-span B-spline net with clamped knots (the same surface)."""
    n, m = tensor_net["degree"]
    return {"type": "bspline", "degree": [n, m], "knots": [[0.0] * (n + 1) + [1.0] * (n + 1),
                                                             [0.0] * (m + 1) + [1.0] * (m + 1)],
            "points": tensor_net["points"]}


def bspline_nets(examples):
    """(name, bspline NET dict, fixed): the tensor example nets as one-span B-splines, and the
    bicubic multi-span nets `bpde blend` makes of the blend examples."""
    out = [(p, as_bspline(j["net"]), j.get("fixed", "boundary")) for p, j in tensor_examples(examples)]
    for p, config in blend_examples(examples):
        net, _ = bezierpde.blend(config)
        out.append((p, net, "boundary"))
    return out


def same_points(net_obj, net_dict):
    return bits(np.asarray(net_obj.points).tolist()) == bits(bezierpde.points(net_dict).tolist())


def check_summary(summary, report):
    assert summary.converged == report["converged"]
    assert (summary.status == bezierpde.Status.Converged) == report["converged"]
    assert summary.message == report.get("message", "")
    assert summary.iterations == report.get("iterations", 0)
    assert summary.seconds >= 0 and np.isfinite(summary.residual)


ENERGIES = ["dirichlet", {"name": "biharmonic"}, {"name": "laplacian-squared"}]


def test_solve_extremal_equals_the_job_route_on_tensor_examples(examples):
    cases = 0
    for path, job in tensor_examples(examples):
        data = bezierpde.net_from_dict(job["net"])
        for energy in ENERGIES:
            e = energy if isinstance(energy, dict) else {"name": energy}
            fixed = job.get("fixed", "boundary")
            net, report = bezierpde.solve(dict(job, problem={"kind": "extremal", "energy": e}))
            r = bezierpde.solve_extremal(data, energy, fixed)
            assert isinstance(r, bezierpde.ExtremalResult) and isinstance(r.net, bezierpde.TensorNet)
            assert same_points(r.net, net), (path, energy)
            assert bits(r.energy) == bits(report["energy"]), (path, energy)
            check_summary(r.summary, report)
            assert r.summary.status == bezierpde.Status.Converged and r.summary.residual <= 1e-11
            cases += 1
    assert cases >= 60


def test_solve_extremal_equals_the_job_route_on_triangular_examples(examples):
    cases = 0
    for path, job in triangular_examples(examples):
        data = bezierpde.net_from_dict(job["net"])
        for energy in ENERGIES[:2]:
            e = energy if isinstance(energy, dict) else {"name": energy}
            net, report = bezierpde.solve(dict(job, problem={"kind": "extremal", "energy": e}))
            r = bezierpde.solve_extremal(data, energy, job["fixed"])
            assert isinstance(r, bezierpde.TriangularExtremalResult) and isinstance(r.net, bezierpde.TriangularNet)
            assert same_points(r.net, net), (path, energy)
            assert bits(r.energy) == bits(report["energy"]), (path, energy)
            check_summary(r.summary, report)
            assert r.summary.converged
            cases += 1
    assert cases >= 20


def test_extremal_solver_mould_gives_the_same_extremal(examples):
    path, job = next((p, j) for p, j in tensor_examples(examples) if p.endswith("fig1-biharmonic.json"))
    data = bezierpde.net_from_dict(job["net"])
    solver = bezierpde.ExtremalSolver("biharmonic", data.n, data.m, "boundary")
    r = bezierpde.solve_extremal(data, "biharmonic")
    X = solver.solve(data.points)
    assert X.shape == (36, 3) and X.dtype == np.float64 and not X.flags["OWNDATA"]
    assert np.array_equal(X, r.net.points)
    assert solver.mould.shape == (len(solver.free_indices), len(solver.fixed_indices)) == (16, 20)
    # X_free = mould @ X_fixed, the free rows of the input ignored
    assert np.allclose(X[solver.free_indices], solver.mould @ data.points[solver.fixed_indices], rtol=0, atol=1e-12)
    scrambled = np.array(data.points)
    scrambled[solver.free_indices] = 7.0
    assert np.array_equal(solver.solve(scrambled), X)
    assert solver.reduced_residual(X) == r.summary.residual
    assert solver.extremal_energy(X) == r.energy
    # a C-ordered array, a Fortran-ordered one and a list of lists give the same answer
    assert np.array_equal(solver.solve(np.ascontiguousarray(data.points)), X)
    assert np.array_equal(solver.solve(data.points.tolist()), X)
    # the generic constructor from a Gram matrix: the chain energy 1/2|P1-P0|^2 + 1/2|P2-P1|^2,
    # whose minimiser over P1 is the midpoint of P0 and P2
    Q = np.array([[1.0, -1.0, 0.0], [-1.0, 2.0, -1.0], [0.0, -1.0, 1.0]])
    chain = bezierpde.ExtremalSolver(Q, [0, 2])
    P = chain.solve(np.array([[0.0, 0.0, 0.0], [5.0, 5.0, 5.0], [2.0, 4.0, 6.0]]))
    assert np.allclose(P[1], [1.0, 2.0, 3.0], rtol=0, atol=1e-14) and np.array_equal(P[[0, 2]], [[0, 0, 0], [2, 4, 6]])


def test_solve_bspline_extremal_equals_the_job_route(examples):
    cases = 0
    for path, net_dict, fixed in bspline_nets(examples):
        data = bezierpde.net_from_dict(net_dict)
        assert isinstance(data, bezierpde.BSplineNet)
        for energy in ENERGIES[:2]:
            e = energy if isinstance(energy, dict) else {"name": energy}
            job = {"net": net_dict, "fixed": fixed, "problem": {"kind": "extremal", "energy": e}, "samples": 12}
            net, report = bezierpde.solve(job)
            options = bezierpde.BSplineExtremalOptions()
            options.fixed = fixed
            r = bezierpde.solve_bspline_extremal(data, energy, options)
            assert isinstance(r.net, bezierpde.BSplineNet)
            assert same_points(r.net, net), (path, energy)
            assert bits(r.energy) == bits(report["energy"]), (path, energy)
            check_summary(r.summary, report)
            cases += 1
    assert cases >= 50
    # the explicit index list: the fixed set's own indices give the same extremal
    path, net_dict, _ = bspline_nets(examples)[-1]
    data = bezierpde.net_from_dict(net_dict)
    nu, nv = data.nu, data.nv
    ring = [i * nv + j for i in range(nu) for j in range(nv) if i in (0, nu - 1) or j in (0, nv - 1)]
    a = bezierpde.solve_bspline_extremal(data, "dirichlet")
    b = bezierpde.solve_bspline_extremal(data, "dirichlet", fixed_indices=ring)
    assert np.array_equal(a.net.points, b.net.points) and a.energy == b.energy


def test_solve_bspline_pde_equals_the_job_route(examples):
    cases, converged = 0, 0
    for path, net_dict, fixed in bspline_nets(examples):
        data = bezierpde.net_from_dict(net_dict)
        # fourth order with the job's data on the quintic one-span nets, second order with
        # u-boundaries on every net
        ops = [("dirichlet", "u-boundaries")]
        if data.p >= 4:
            ops.append(({"name": "biharmonic"}, fixed))
        for op, f in ops:
            o = op if isinstance(op, dict) else {"name": op}
            job = {"net": net_dict, "fixed": f, "problem": {"kind": "pde", "method": "lu", "operator": o},
                   "samples": 12}
            net, report = bezierpde.solve(job)
            options = bezierpde.BSplinePdeOptions()
            options.fixed = f
            r = bezierpde.solve_bspline_pde(data, op, options)
            assert same_points(r.net, net), (path, op)
            assert bits(r.energy) == bits(report["energy"]), (path, op)
            for field in ("rank", "equations", "free_parameters", "compatibility_conditions", "minimum_energy_member"):
                assert getattr(r, field) == report[field], (path, op, field)
            check_summary(r.summary, report)
            assert 0 <= r.rank_free <= r.rank <= r.equations
            converged += r.summary.converged
            if not r.summary.converged:
                assert r.summary.status in (bezierpde.Status.Incompatible, bezierpde.Status.NumericalLimit)
                assert r.summary.message
            cases += 1
    assert cases >= 40 and converged >= 20


def blend_problem_from_arrays(config):
    """A SmoothingSplineProblem filled field by field from numpy arrays (edges form)."""
    p = bezierpde.SmoothingSplineProblem()
    p.k, p.l = config["partition"]
    p.a, p.epsilon = config["a"], config["epsilon"]
    edges = config["edges"]
    p.y0_value = np.array(edges["y0"]["value"])
    p.y0_dy = np.asfortranarray(edges["y0"]["dy"])
    p.y1_value = edges["y1"]["value"]  # a list of lists converts too
    p.y1_dy = np.array(edges["y1"]["dy"])
    p.points = np.array(config.get("points", []), dtype=np.float64).reshape(-1, 2)
    p.data = np.array(config.get("data", []), dtype=np.float64).reshape(-1, 3)
    return p


def test_solve_smoothing_spline_equals_the_blend_route(examples):
    configs = blend_examples(examples)
    assert len(configs) >= 4
    for path, config in configs:
        net, report = bezierpde.blend(config)
        problems = [bezierpde.SmoothingSplineProblem.from_config(config)]
        if "edges" in config:
            problems.append(blend_problem_from_arrays(config))
        for problem in problems:
            r = bezierpde.solve_smoothing_spline(problem)
            assert same_points(r.spline.to_bspline_net(), net), path
            assert bits([r.functional, r.data_misfit, r.energy, r.max_data_error]) == bits(
                [report["energy"], report["data_misfit"], report["L_energy"], report["max_data_error"]]), path
            check_summary(r.summary, report)
            assert r.summary.converged and r.summary.residual <= 1e-11
            assert r.multipliers.shape == (4 * (problem.k + 1), 3)
            # the sampled surface is the one `bpde blend` writes
            V, F, H = r.spline.sample(config.get("samples", 50))
            assert V.shape == ((config.get("samples", 50) + 1) ** 2, 3)
            # the spline interpolates the prescribed edge values at the nodes
            for i in range(problem.k + 1):
                assert np.allclose(r.spline.evaluate(i / problem.k, 0.0), problem.y0_value[i], rtol=0, atol=1e-9)
                assert np.allclose(r.spline.evaluate(i / problem.k, 1.0, 0, 1), problem.y1_dy[i], rtol=0, atol=1e-9)
        # factored once, solved again: the same spline; the KKT route agrees to rounding
        solver = bezierpde.SmoothingSplineSolver(problems[0])
        again = solver.solve(problems[0])
        assert same_points(again.spline.to_bspline_net(), net), path
        options = bezierpde.SmoothingSplineOptions()
        options.method = "kkt-lu"
        kkt = bezierpde.solve_smoothing_spline(problems[0], options)
        scale = np.max(np.abs(bezierpde.points(net)))
        assert np.max(np.abs(kkt.spline.coefficients - again.spline.coefficients)) < 1e-9 * scale


def test_smoothing_spline_load_is_a_python_callable(examples):
    path, config = blend_examples(examples)[0]
    problem = bezierpde.SmoothingSplineProblem.from_config(config)
    assert problem.load is None
    base = bezierpde.solve_smoothing_spline(problem)
    calls = []

    def zero(x, y):
        calls.append((x, y))
        return np.zeros(3)

    problem.load = zero
    r = bezierpde.solve_smoothing_spline(problem)  # the GIL is re-taken for each call: no deadlock
    assert len(calls) > 0 and all(0 <= x <= 1 and 0 <= y <= 1 for x, y in calls)
    assert np.allclose(r.spline.coefficients, base.spline.coefficients, rtol=0, atol=1e-12)
    # a constant load in z pushes the surface: the energy term -2 eps (f, v) makes J smaller
    problem.load = lambda x, y: (0.0, 0.0, 100.0)
    pushed = bezierpde.solve_smoothing_spline(problem)
    assert pushed.functional < base.functional - 1.0

    def broken(x, y):
        raise KeyError("from the load")

    problem.load = broken
    with pytest.raises(KeyError, match="from the load"):
        bezierpde.solve_smoothing_spline(problem)


def test_options_have_the_cpp_defaults():
    e = bezierpde.ExtremalOptions()
    assert (e.singular_tolerance, e.conditioned_basis, e.use_cache) == (1e-13, True, False)
    b = bezierpde.BSplineExtremalOptions()
    assert (b.fixed, b.tolerance) == ("boundary", 1e-11)
    p = bezierpde.BSplinePdeOptions()
    assert (p.fixed, p.rank_tolerance, p.consistency_tolerance) == ("boundary", 1e-10, 1e-10)
    s = bezierpde.SmoothingSplineOptions()
    assert (s.method, s.load_quadrature, s.threaded_factorization) == ("elimination", 6, False)
    q = bezierpde.SmoothingSplineProblem()
    assert (q.k, q.l, q.a, q.epsilon) == (8, 4, 1.0, 1.0) and q.y0_value.shape == (0, 3)
    for o in (e, b, p, s):
        o.validate()


def test_option_validation_errors(examples):
    path, job = next((p, j) for p, j in tensor_examples(examples) if p.endswith("fig1-biharmonic.json"))
    tensor = bezierpde.net_from_dict(job["net"])
    bspline = bezierpde.net_from_dict(as_bspline(job["net"]))
    o = bezierpde.ExtremalOptions()
    o.singular_tolerance = 1.5
    with pytest.raises(bezierpde.ParameterError, match="singular_tolerance"):
        o.validate()
    with pytest.raises(bezierpde.ParameterError, match="singular_tolerance"):
        bezierpde.solve_extremal(tensor, "dirichlet", "boundary", o)
    with pytest.raises(bezierpde.ParameterError, match="fixed"):
        bezierpde.solve_extremal(tensor, "dirichlet", "everything")
    with pytest.raises(bezierpde.InvalidInput):
        bezierpde.solve_extremal(tensor, "no-such-energy")
    with pytest.raises(bezierpde.DegreeError):
        bezierpde.solve_extremal(bezierpde.TensorNet(3, 3), "dirichlet", "boundary+adjacent")
    b = bezierpde.BSplineExtremalOptions()
    with pytest.raises(bezierpde.ParameterError, match="fixed"):
        b.fixed = "interior"
    assert b.fixed == "boundary"
    b.tolerance = 0.0
    with pytest.raises(bezierpde.ParameterError, match="tolerance"):
        bezierpde.solve_bspline_extremal(bspline, "dirichlet", b)
    with pytest.raises(bezierpde.InvalidInput):
        bezierpde.solve_bspline_extremal(bspline, "dirichlet", fixed_indices=[5, 3])
    p = bezierpde.BSplinePdeOptions()
    p.rank_tolerance = -1.0
    with pytest.raises(bezierpde.ParameterError, match="tolerance"):
        bezierpde.solve_bspline_pde(bspline, "biharmonic", p)
    p = bezierpde.BSplinePdeOptions()
    p.consistency_tolerance = 1.0
    with pytest.raises(bezierpde.ParameterError, match="tolerance"):
        p.validate()
    p = bezierpde.BSplinePdeOptions()
    p.fixed = "u-boundaries"
    with pytest.raises(bezierpde.UnsupportedProblem):
        bezierpde.solve_bspline_pde(bspline, "biharmonic", p)
    s = bezierpde.SmoothingSplineOptions()
    with pytest.raises(bezierpde.ParameterError, match="method"):
        s.method = "magic"
    s.load_quadrature = 0
    config = blend_examples(examples)[0][1]
    problem = bezierpde.SmoothingSplineProblem.from_config(config)
    with pytest.raises(bezierpde.ParameterError):
        bezierpde.solve_smoothing_spline(problem, s)
    problem.epsilon = 0.0
    with pytest.raises(bezierpde.ParameterError, match="epsilon|ε"):
        bezierpde.solve_smoothing_spline(problem)
    problem.epsilon = float("nan")
    with pytest.raises(bezierpde.InvalidInput):
        problem.validate()
    with pytest.raises(bezierpde.ParseError):
        bezierpde.SmoothingSplineProblem.from_config(dict(config, colour="red"))


def test_array_shape_errors(examples):
    path, job = next((p, j) for p, j in tensor_examples(examples) if p.endswith("fig1-biharmonic.json"))
    data = bezierpde.net_from_dict(job["net"])
    solver = bezierpde.ExtremalSolver("dirichlet", data.n, data.m)
    for bad in (np.zeros((35, 3)), np.zeros((36, 2)), np.zeros(108), np.zeros((36, 3, 1))):
        with pytest.raises(bezierpde.SizeError, match=r"points: expected an array of shape \(36, 3\)"):
            solver.solve(bad)
    with pytest.raises(bezierpde.SizeError):
        solver.reduced_residual(np.zeros((4, 3)))
    with pytest.raises(bezierpde.ParseError):
        solver.solve([["a", "b", "c"]] * 36)
    with pytest.raises(bezierpde.SizeError, match="not square"):
        bezierpde.ExtremalSolver(np.zeros((3, 4)), [0])
    with pytest.raises(bezierpde.SizeError, match="outside"):
        bezierpde.ExtremalSolver(np.eye(3), [0, 3])
    problem = bezierpde.SmoothingSplineProblem()
    with pytest.raises(bezierpde.SizeError, match=r"y0_value: expected an array of shape \(N, 3\), got shape \(9, 2\)"):
        problem.y0_value = np.zeros((9, 2))
    with pytest.raises(bezierpde.SizeError, match="points"):
        problem.points = np.zeros((4, 3))
    config = blend_examples(examples)[0][1]
    problem = bezierpde.SmoothingSplineProblem.from_config(config)
    problem.y1_dy = np.zeros((problem.k, 3))  # one node short
    with pytest.raises(bezierpde.SizeError, match="y1"):
        bezierpde.solve_smoothing_spline(problem)
    # the problem's arrays are read-only views of its C++ fields
    view = problem.y0_value
    assert view.shape == (problem.k + 1, 3) and not view.flags["WRITEABLE"]
    with pytest.raises(bezierpde.SizeError):
        bezierpde.BSplineNet(3, 3, [0, 0, 0, 0, 1, 1, 1, 1], [0, 0, 0, 0, 1, 1, 1, 1], np.zeros((15, 3)))
    net = bezierpde.BSplineNet(3, 3, [0, 0, 0, 0, 1, 1, 1, 1], [0, 0, 0, 0, 1, 1, 1, 1], np.zeros((16, 3)))
    assert (net.p, net.q, net.nu, net.nv) == (3, 3, 4, 4) and net.points.shape == (16, 3)
    with pytest.raises(bezierpde.SizeError):
        net.points = np.zeros((15, 3))
    # results hold views of their nets (no copy), writable
    r = bezierpde.solve_bspline_extremal(bezierpde.net_from_dict(as_bspline(job["net"])), "dirichlet")
    P = r.net.points
    assert P.shape == (36, 3) and not P.flags["OWNDATA"]


def large_blend():
    p = bezierpde.SmoothingSplineProblem()
    p.k = p.l = 64
    x = np.arange(p.k + 1) / p.k
    p.y0_value = np.column_stack([x, 0 * x, np.sin(3 * x)])
    p.y1_value = np.column_stack([x, 0 * x + 1, np.cos(2 * x)])
    p.y0_dy = p.y1_dy = np.tile([0.0, 1.0, 0.0], (p.k + 1, 1))
    return p


def large_bspline(p=5, n=24):
    knots = [0.0] * (p + 1) + list(np.linspace(0, 1, n - p + 1)[1:-1]) + [1.0] * (p + 1)
    points = np.random.default_rng(3).random((n * n, 3))
    return bezierpde.BSplineNet(p, p, knots, knots, points)


@pytest.mark.parametrize("name", ["smoothing_spline", "bspline_pde", "extremal_solver"])
def test_the_gil_is_released_during_the_solvers(name):
    solve = {
        "smoothing_spline": lambda: bezierpde.solve_smoothing_spline(large_blend()),
        "bspline_pde": lambda: bezierpde.solve_bspline_pde(large_bspline(), "biharmonic"),
        "extremal_solver": lambda: bezierpde.ExtremalSolver("biharmonic", 30, 30, "boundary"),
    }[name]
    inside, seconds = ticks_during(solve)
    assert inside >= 3, (inside, seconds)


def test_solve_cmc_takes_each_functional_and_equals_the_job_route():
    """CmcOptions.functional from Python (dirichlet, area, mean-curvature): the C++ defaults, the
    result fields, and the same net and numbers as the job route on the Fig. 1 circle."""
    o = bezierpde.CmcOptions()
    assert (o.functional, o.mean_curvature_tolerance, o.max_least_squares_iterations, o.geodesic_acceleration,
            o.area_start, o.area_trust_region) == ("dirichlet", 1e-6, 2000, True, "mean-curvature", True)
    with pytest.raises(bezierpde.ParameterError, match="mean-curvature"):
        o.functional = "curvature"
    with pytest.raises(bezierpde.ParameterError, match="expected mean-curvature, dirichlet or minimal-surface"):
        o.area_start = "plane"
    o.area_start = "minimal-surface"
    assert o.area_start == "minimal-surface"
    o.area_start = "mean-curvature"
    job = {"boundary": {"type": "triangular", "degree": 8, "builder": "circle-three-arcs"},
           "problem": {"kind": "cmc", "H": -0.9, "functional": "mean-curvature"}}
    net_cli, report = bezierpde.solve(job)
    o.H = -0.9
    o.functional = "mean-curvature"
    o.mean_curvature_tolerance = 1e-3
    data = bezierpde.net_from_dict(net_cli)
    loose = bezierpde.solve_cmc(data, o)
    assert loose.functional == "mean-curvature" and loose.summary.converged
    assert 0 < loose.summary.residual <= 1e-3 and loose.A > 0
    o.mean_curvature_tolerance = 1e-6
    r = bezierpde.solve_cmc(data, o)
    assert r.summary.converged == report["converged"] and r.summary.residual == report["residual"]
    assert bits(np.asarray(r.net.points).tolist()) == bits(bezierpde.points(net_cli).tolist())
    assert r.A == report["area"] and r.energy == report["energy"]
    q = report["quadrature"]
    assert (r.quadrature_points, r.quadrature_grading, r.quadrature_levels, r.quadrature_nodes) == (
        q["points_per_direction"], q["grading"], q["levels"], q["nodes"])
    assert q["nodes"] == 6 * (q["levels"] + 1) * q["points_per_direction"] ** 2
    # solver "ceres" (one Ceres residual block per quadrature node): the same from both routes
    job["problem"]["solver"] = "ceres"
    net_ceres, report_ceres = bezierpde.solve(job)
    o.solver = "ceres"
    rc = bezierpde.solve_cmc(data, o)
    assert rc.summary.converged == report_ceres["converged"] and rc.summary.residual == report_ceres["residual"]
    assert bits(np.asarray(rc.net.points).tolist()) == bits(bezierpde.points(net_ceres).tolist())
    assert "Ceres" in rc.summary.message
    # geodesic_acceleration reaches the library: plain Levenberg–Marquardt takes other steps
    o.solver = "newton"
    o.geodesic_acceleration = False
    plain = bezierpde.solve_cmc(data, o)
    assert plain.summary.iterations != r.summary.iterations
    assert bits(np.asarray(plain.net.points).tolist()) != bits(np.asarray(r.net.points).tolist())


def test_area_solve_reports_its_routes_as_the_job_does():
    """The area solve's route records from Python (routes, kept_route, routes_report,
    parametrisation) and in result.json's report (FORMATS.md "routes"): the same routes in the same
    order, one kept, its first variation within the tolerance. The Fig. 1 circle at n = 8,
    H = -0.5 converges from the least-squares mean-curvature surface."""
    job = {"boundary": {"type": "triangular", "degree": 8, "builder": "circle-three-arcs"},
           "problem": {"kind": "cmc", "H": -0.5, "functional": "area"}}
    net_cli, report = bezierpde.solve(job)
    o = bezierpde.CmcOptions()
    o.H = -0.5
    o.functional = "area"
    r = bezierpde.solve_cmc(bezierpde.net_from_dict(net_cli), o)
    assert r.summary.converged and report["converged"]
    assert r.kept_route == "mean-curvature-start"
    assert [x.route for x in r.routes] == [x["route"] for x in report["routes"]]
    kept = [x for x in report["routes"] if x["kept"]]
    assert len(kept) == 1 and kept[0]["route"] == "mean-curvature-start" and kept[0]["status"] == "converged"
    assert 0 <= kept[0]["first_variation"] <= 1e-11
    assert r.routes[0].status == bezierpde.Status.Converged and r.routes[0].tried
    assert r.routes[0].first_variation <= 1e-11
    # the least squares of mean-curvature-start converged here (√Φ within 1e-6), in both records
    assert r.routes[0].least_squares_converged and 0 < r.routes[0].least_squares_residual <= 1e-6
    assert kept[0]["least_squares_residual"] == r.routes[0].least_squares_residual
    assert kept[0]["start_volume"] is None and r.routes[0].start_volume is None
    assert "mean-curvature-start: converged" in r.routes_report
    assert r.parametrisation["regular"] and r.parametrisation["checked"]
    assert report["parametrisation"]["regular"] and report["parametrisation"]["fold_corner_angle"] is None
    # the Dirichlet functional has no routes
    o.functional = "dirichlet"
    d = bezierpde.solve_cmc(bezierpde.net_from_dict(net_cli), o)
    assert d.routes == [] and d.kept_route is None and not d.parametrisation["checked"]
