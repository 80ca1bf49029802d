"""The pure parts of scripts/evolver_compare.py (the Surface Evolver comparison of docs/cmc_evolver.md).
Nothing here runs Evolver: the comparison itself is not part of the test suite."""

import importlib.util
import math
import os
import random
import re

import pytest

from conftest import SOURCE_DIR

SCRIPT = os.path.join(SOURCE_DIR, "scripts", "evolver_compare.py")
spec = importlib.util.spec_from_file_location("evolver_compare", SCRIPT)
ec = importlib.util.module_from_spec(spec)
spec.loader.exec_module(ec)


def test_triangular_evaluation_in_the_formats_order():
    # x(u, v) = (u, v, u v) at degree 2: P_I = (i/2, j/2, [I = (1,1,0)] / 2), i from 2 down, then j.
    pts = []
    for i in range(2, -1, -1):
        for j in range(2 - i, -1, -1):
            pts.append((i / 2, j / 2, 0.5 if (i, j) == (1, 1) else 0.0))
    rng = random.Random(1)
    for _ in range(20):
        u = rng.random()
        v = rng.random() * (1 - u)
        x = ec.eval_triangular(2, pts, u, v)
        assert x == pytest.approx([u, v, u * v], abs=1e-15)


def test_quadratic_facet_reproduces_a_quadratic_map():
    def f(l1, l2):
        return (l1 * l1 + 2 * l2, l1 * l2 - l2, 3 * l1 * l1 * 0.5 + l2 * l2)

    corners = [f(1, 0), f(0, 1), f(0, 0)]
    mids = [f(0.5, 0.5), f(0, 0.5), f(0.5, 0)]
    for l1, l2 in [(0.2, 0.3), (1 / 3, 1 / 3), (0.6, 0.1)]:
        assert ec.facet_point(corners, mids, l1, l2) == pytest.approx(list(f(l1, l2)), abs=1e-14)
    # the flat triangle: the linear interpolant, which misses the quadratic part
    assert ec.facet_point(corners, None, 0.5, 0.5) == pytest.approx([0.5 * (a + b) for a, b in zip(f(1, 0), f(0, 1))])


def test_evolver_pressure_follows_the_bpde_sign():
    # Fig. 1 circle: H < 0 bulges towards x_u ^ x_v = +z; a sphere of radius R has P = 2/R.
    assert ec.evolver_pressure(-0.5) == 1.0
    assert ec.evolver_pressure(1.0) == -2.0
    assert "pressure 1\n" in ec.fe_circle(-0.5) + "\n"


def test_circle_file_faces_point_to_plus_z():
    fe = ec.fe_circle(-0.5)
    section = lambda name: fe.split("\n" + name + "\n")[1].split("\n\n")[0].splitlines()
    ang = {int(l.split()[0]): int(l.split()[1].split("*")[0]) * math.pi / 3 for l in section("vertices")[:6]}
    pos = {k: (math.cos(a), math.sin(a), 0.0) for k, a in ang.items()}
    pos[7] = (0.0, 0.0, 0.2)
    edges = {int(l.split()[0]): (int(l.split()[1]), int(l.split()[2])) for l in section("edges")}
    faces = section("faces")
    assert len(faces) == 6
    for line in faces:
        oriented = [edges[e] if e > 0 else edges[-e][::-1] for e in map(int, line.split()[1:4])]
        assert all(oriented[k][1] == oriented[(k + 1) % 3][0] for k in range(3))  # a closed loop
        a, b, c = (pos[o[0]] for o in oriented)
        nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
        assert nz > 0


def test_sphere_file_constraints_are_the_images_of_the_edges():
    # the edges t = -1/3 (v = 0), s + t = 1/3 (w = 0), s = -1/3 (u = 0) lie in the planes of the .fe file
    planes = {
        2: lambda x, y, z: 3 * y + 1 - z,
        3: lambda x, y, z: 3 * x + 3 * y + z - 1,
        4: lambda x, y, z: 3 * x + 1 - z,
    }
    fe = ec.fe_sphere(1.0)
    assert "formula: 3*y + 1 - z = 0" in fe and "formula: 3*x + 3*y + z = 1" in fe and "formula: 3*x + 1 - z = 0" in fe
    for k in range(11):
        r = k / 10
        for c, (u, v) in ((2, (r, 0)), (3, (r, 1 - r)), (4, (0, r))):
            x = ec.inverse_stereographic(u - 1 / 3, v - 1 / 3)
            assert abs(planes[c](*x)) < 1e-14 and abs(math.hypot(*x) - 1) < 1e-15
    # and each boundary vertex of the file is on the sphere and on the planes it names
    for line in fe.split("\nvertices\n")[1].split("\n\n")[0].splitlines()[:6]:
        f = line.split()
        x = tuple(map(float, f[1:4]))
        cons = [int(t) for t in f[f.index("constraint") + 1:]]
        assert cons[0] == 1 and abs(math.hypot(*x) - 1) < 1e-15
        assert all(abs(planes[c](*x)) < 1e-14 for c in cons[1:])


def test_run_cmd_refines_the_asked_number_of_times():
    cmd = ec.run_cmd(3, quadratic=True)
    assert cmd.count(ec.REFINE_STEP) == 3 and ec.REFINE_STEP.startswith("r;")
    assert "M 2;" in cmd and cmd.rstrip().endswith("q")
    assert "M 2" not in ec.run_cmd(2, quadratic=False)


def test_evolver_output_parser_measures_vertices_and_facets():
    # one flat facet with corners on the unit sphere: vertex error 0; the worst 4-grid sample is (1/4, 1/4, 1/2).
    a, b, c = (1, 0, 0), (0, 1, 0), (0, 0, 1)
    out = "\n".join([
        "X 1 %r %r %r" % a, "X 2 %r %r %r" % b, "X 3 %r %r %r" % c,
        "F 1 2 0 2 3 0 3 1 0",
        "S 1 3 0.8 0.1 2",
    ])
    v_err, s_err, facets, verts, area, hsteps = ec.evolver_errors(out, (0, 0, 0), 1.0)
    assert v_err == 0.0 and facets == 1 and verts == 3 and hsteps == 2
    assert s_err == pytest.approx(1 - math.sqrt(6) / 4, rel=1e-12)
    with pytest.raises(RuntimeError):
        ec.evolver_errors("Enter command:", (0, 0, 0), 1.0)


def test_refuses_in_one_line_without_evolver(capsys):
    assert ec.main(["--evolver", "no-such-evolver-binary-x"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and re.search(r"apt-get install evolver-nox", err)


def test_library_route_measures_the_printed_net_and_takes_the_cheapest_hit(tmp_path):
    # A stand-in for `example_004_cmc_area_tables --solve-circle N T`: it prints the JSON of the real
    # program, with the degree-1 net of the plane z = 0 through three points of the unit circle.
    # The sphere of radius 2 about (0, 0, -sqrt(3)) meets z = 0 in that circle, so the error is the
    # largest gap between the flat triangle and the sphere, at its centroid (0, 0, 0): 2 - sqrt(3).
    fake = tmp_path / "fake_example"
    pts = [[1.0, 0.0, 0.0], [-0.5, math.sqrt(3) / 2, 0.0], [-0.5, -math.sqrt(3) / 2, 0.0]]
    out = {"degree": 1, "H": -0.5, "tolerance": 1e-7, "status": "converged", "converged": True, "residual": 3e-8,
           "iterations": 4, "seconds": 0.01, "net": {"type": "triangular", "degree": 1, "points": pts}}
    import json as _json
    fake.write_text("#!/bin/sh\ntest \"$1\" = --solve-circle && test \"$2\" = 1 && test \"$3\" = 1e-07 || exit 7\n"
                    "cat <<'END'\n" + _json.dumps(out) + "\nEND\n")
    fake.chmod(0o755)
    case = ec.circle_case()
    r = ec.run_library(str(fake), case, 1, 1e-7, 30)
    assert r["converged"] and r["tolerance"] == 1e-7 and r["iterations"] == 4
    assert r["error"] == pytest.approx(2 - math.sqrt(3), abs=1e-3)  # the 30-grid reaches the centroid to 1e-3
    assert "failed" in ec.run_library(str(fake), case, 2, 1e-7, 30)  # the stand-in exits 7 for other arguments
    rows = [dict(r, cpu=0.5), dict(r, cpu=0.2, error=1e-6, tolerance=1e-9), dict(r, cpu=0.1, error=1e-6, converged=False)]
    table = ec.time_to_accuracy(case, [], [], [1e-5, 1e-7], rows)
    assert "bezierpde area, library" in table.splitlines()[0]
    assert "| 1e-05 | 0.200 s (n = 1, 1e-09) |" in table  # the unconverged 0.1 s row does not count
    assert "| 1e-07 | not reached |" in table
    assert "1e-07 | 0.500" not in table
    assert "tolerance" in ec.library_table(rows).splitlines()[0]
    # a program that solved another H is a failed row, not a measurement
    other = tmp_path / "other_h"
    other.write_text("#!/bin/sh\ncat <<'END'\n" + _json.dumps(dict(out, H=-0.9)) + "\nEND\n")
    other.chmod(0o755)
    assert "H = -0.9" in ec.run_library(str(other), case, 1, 1e-7, 30)["failed"]


def test_refuses_malformed_tolerances(capsys):
    for bad in ("abc", "1e-7,x", "0", "1e-2"):
        assert ec.main(["--tolerances", bad, "--library", SCRIPT]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--tolerances" in err


def test_mean_curvature_rows_by_tolerance():
    # the circle case runs both geometric functionals; --mc-tolerances adds jobs with the tolerance in them
    case = ec.circle_case()
    assert case.functionals == ["area", "mean-curvature"]
    assert ec.sphere_case().functionals == ["dirichlet", "area", "mean-curvature"]
    assert case.job(8, "area")["problem"]["functional"] == "area"
    j = case.job(8, "mean-curvature", 1e-7)["problem"]
    assert (j["functional"], j["mean_curvature_tolerance"]) == ("mean-curvature", 1e-7)
    assert "functional" not in case.job(8, "dirichlet")["problem"]
    base = {"degree": 8, "functional": "mean-curvature", "converged": True, "error": 1e-7, "residual": 1e-6,
            "area": None, "H_min": -0.5, "H_max": -0.5, "seconds": 0.1}
    rows = [dict(base, cpu=0.3), dict(base, cpu=0.1, mc_tolerance=1e-5, error=1e-6),
            dict(base, cpu=0.05, mc_tolerance=1e-3, error=1e-6, converged=False)]
    table = ec.time_to_accuracy(case, rows, [], [1e-6, 1e-7])
    head = table.splitlines()[0]
    assert "bezierpde mean-curvature |" in head and "bezierpde mean-curvature (degree and tolerance)" in head
    assert "| 1e-06 | 0.30 s (n = 8) | 0.100 s (n = 8, √Φ ≤ 1e-05) |" in table  # default rows alone; unconverged left out
    assert "| 1e-07 | 0.30 s (n = 8) | 0.30 s (n = 8) |" in table
    assert "(√Φ ≤ 1e-05)" in ec.bpde_table(case, rows)


def test_area_rows_with_the_dirichlet_start_are_a_route_of_their_own():
    # --area-dirichlet-start adds area jobs with "start": "dirichlet"; they must not mix with the default area rows
    case = ec.circle_case()
    assert case.job(8, "area", start="dirichlet")["problem"]["start"] == "dirichlet"
    assert "start" not in case.job(8, "area")["problem"]
    base = {"degree": 8, "functional": "area", "converged": True, "error": 1e-8, "residual": 1e-12,
            "area": 1.0, "H_min": -0.5, "H_max": -0.5, "seconds": 0.1}
    rows = [dict(base, cpu=0.5), dict(base, cpu=0.2, error=1e-7, start="dirichlet")]
    table = ec.time_to_accuracy(case, rows, [], [1e-7, 1e-8])
    assert "| bezierpde area | bezierpde area (start: dirichlet) |" in table.splitlines()[0]
    assert "| 1e-07 | 0.50 s (n = 8) | 0.20 s (n = 8) |" in table
    assert "| 1e-08 | 0.50 s (n = 8) | not reached |" in table
    assert "| area (start: dirichlet) | 8 |" in ec.bpde_table(case, rows)


def test_refuses_malformed_mc_tolerances(capsys):
    for bad in ("abc", "1e-7,x", "0", "1"):
        assert ec.main(["--mc-tolerances", bad]) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "--mc-tolerances" in err


def test_catenoid_neck_and_area_are_the_example_job_s():
    # examples/005-complex-exact/README.md: the unit circles at z = +-0.5, A = 5.99179697580228.
    a = ec.catenoid_neck()
    assert a * math.cosh(0.5 / a) == pytest.approx(1.0, abs=1e-14)
    assert 0.8 < a < 0.9  # the larger root: the stable catenoid, not the one near the discs
    assert ec.catenoid_area(a) == pytest.approx(ec.CATENOID_AREA, rel=1e-14)
    assert ec.catenoid_distance((a, 0.0, 0.0), a) == pytest.approx(0.0, abs=1e-15)
    assert ec.catenoid_distance((0.0, 1.0, 0.5), a) == pytest.approx(0.0, abs=1e-14)
    assert ec.catenoid_distance((0.0, 1.2, 0.0), a) == pytest.approx(1.2 - a, rel=1e-14)


def test_catenoid_file_is_one_consistently_oriented_tube():
    fe = ec.fe_catenoid(6)
    section = lambda name: fe.split("\n" + name + "\n")[1].split("\n\n")[0].strip().splitlines()
    pos = {}
    for line in section("vertices"):
        k, ang, _, b = line.split()[:4]
        pos[int(k)] = (math.cos(int(ang.split("*")[0]) * math.pi / 6), math.sin(int(ang.split("*")[0]) * math.pi / 6),
                       0.5 if b == "1" else -0.5)
    assert "boundary 1" in fe and "boundary 2" in fe and "bodies" not in fe
    edges = {int(l.split()[0]): (int(l.split()[1]), int(l.split()[2])) for l in section("edges")}
    uses = {e: [] for e in edges}
    faces = section("faces")
    assert len(faces) == 12
    for line in faces:
        signed = list(map(int, line.split()[1:4]))
        oriented = [edges[e] if e > 0 else edges[-e][::-1] for e in signed]
        assert all(oriented[k][1] == oriented[(k + 1) % 3][0] for k in range(3))  # a closed loop
        for e in signed:
            uses[abs(e)].append(e > 0)
        a, b, c = (pos[o[0]] for o in oriented)
        n = [(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
             (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
             (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])]
        centroid = [(a[d] + b[d] + c[d]) / 3 for d in range(3)]
        assert n[0] * centroid[0] + n[1] * centroid[1] > 0  # every normal points away from the axis
    for e, used in uses.items():
        if e <= 12:  # the two boundary rings: one facet each
            assert len(used) == 1
        else:  # verticals and diagonals: two facets, traversed both ways
            assert sorted(used) == [False, True]


def test_run_cmd_without_a_body_prints_no_volume():
    assert "body[1]" not in ec.run_cmd(2, quadratic=True, volume="0.0")
    assert "body[1].volume" in ec.run_cmd(2, quadratic=True)


def test_loglog_time_interpolates_a_power_law_along_the_cheapest_rows():
    rows = [{"cpu": 0.1, "error": 1e-4}, {"cpu": 1.0, "error": 1e-8}, {"cpu": 5.0, "error": 1e-6}]  # the last: off the front
    assert ec.loglog_time(rows, 1e-6) == pytest.approx(10 ** -0.5, rel=1e-12)  # error ~ cpu^-4 between the two
    assert ec.loglog_time(rows, 1e-3) == 0.1  # the cheapest row is already below it
    assert ec.loglog_time(rows, 1e-9) is None
    table = ec.catenoid_time_table(
        [dict(r, degree=4, refine=0, converged=True) for r in rows[:2]],
        [{"model": "quadratic", "cpu": 10.0, "error": 1e-6, "facets": 768}], [1e-6, 1e-8])
    lines = table.splitlines()
    assert lines[2].endswith("| 0.316 s | 10.000 s | 32× |")
    assert "> 10× (Evolver not reached)" in lines[3]
