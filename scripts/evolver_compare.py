#!/usr/bin/env python3
"""Time-to-accuracy of bezierpde against Surface Evolver on the same boundary (bezierpde docs/cmc_evolver.md).

    python3 scripts/evolver_compare.py [--bpde build/bpde] [--case circle|sphere|all]
                                       [--degrees 4,6,8] [--linear-levels 1..8]
                                       [--quadratic-levels 1..7] [--out DIR]
                                       [--tolerances 1e-7,1e-9,1e-11]
                                       [--library build/example_004_cmc_area_tables]
                                       [--mc-tolerances 1e-5,1e-7] [--area-dirichlet-start]

Every table is printed between the section markers of scripts/docs.py (sections
evolver-CASE-bezierpde, -library, -evolver and -time; `--list` prints the names that the other
arguments select), so that `python3 scripts/docs.py --run evolver` writes the run of
docs/cmc_evolver_measurements.md (its arguments are in scripts/docs.py, GENERATORS).

Both programs solve the same problem, a surface of constant mean curvature H with a fixed
boundary, and the error is the distance to the exact sphere:

- circle (non-conformal data): the unit circle in z = 0, H = -0.5. bezierpde: the circle in three
  arcs parametrised by angle (builder `circle-three-arcs`), `"functional": "area"` and
  `"mean-curvature"` (with --mc-tolerances also at those `mean_curvature_tolerance`). The answer is
  the small spherical cap of radius 2 through the circle, centre (0, 0, -sqrt(3)).
- sphere (conformal data): the triangle patch of the inverse stereographic projection (builder
  `sphere-triangle`), H = +1, answer the unit sphere; bezierpde with all three functionals
  (`"dirichlet"`, the paper's D_H, `"area"` and `"mean-curvature"`, the latter with --mc-tolerances
  too).

bezierpde runs `bpde solve` on a job per degree; the error is max | |x - c| - R | over the
triangular grid u = a/N, v = b/N (a + b <= N, N = --grid, corners included), evaluated here from
the result's net. Surface Evolver runs `evolver -x -f run.cmd file.fe < /dev/null` once per
refinement level, from the .fe file each time (so every row is a time from scratch): per level
r (refine), g 5 (gradient steps), u (equiangulate) and V; V (vertex averaging, which keeps the mesh
regular), then (quadratic model: M 2) g 10 and Hessian steps until the energy stops changing. Its
error is the maximum over the vertices (quadratic model: the edge midpoints included) and, the
"surface" column, over 15 points of every facet (the flat or the quadratic triangle).

Evolver minimises E = area - P * V, V = the body's volume integral (z dx dy over its facets, with
the facet normals); at a critical point P = k1 + k2 = 2 |H| with the curvature measured towards
the facet normal. bezierpde's A_H = A + 2 H V uses V = (1/3) int <x_u ^ x_v, x> and H < 0 bulges
towards x_u ^ x_v. So the .fe facets are oriented as x_u ^ x_v and P = -2 H: the same functional
up to a constant that depends only on the (fixed) boundary.

--tolerances (circle only) adds a third program row: the same area solve through the library,
one process of examples/004-cmc-area-tables (`--solve-circle N TOLERANCE`) per degree and
first-variation tolerance, so that bezierpde, like Evolver with its refinement levels, has an
accuracy knob besides the degree. `bpde solve` always solves to 1e-11 (FORMATS.md, "converged");
a looser tolerance is a library option (CmcOptions::tolerance), and a result there is "converged"
to that tolerance only.

CPU seconds are the user + system time of the child process (resource.getrusage(RUSAGE_CHILDREN)
before and after each run), so the load of other processes on the machine does not count.
"""

import argparse
import json
import math
import os
import resource
import shutil
import subprocess
import sys
import tempfile

INSTALL_HINT = "install it with `sudo apt-get install evolver-nox` (Debian/Ubuntu; the package of Surface Evolver)"


# --------------------------------------------------------------------------- geometry (pure)

def inverse_stereographic(s, t):
    """(2s, 2t, s^2 + t^2 - 1) / (1 + s^2 + t^2): the conformal data of examples/004-cmc-sphere-convergence."""
    d = 1.0 + s * s + t * t
    return (2.0 * s / d, 2.0 * t / d, (s * s + t * t - 1.0) / d)


def eval_triangular(degree, points, u, v):
    """x(u, v) = sum P_I n!/(i! j! k!) u^i v^j w^k, w = 1 - u - v, points in the FORMATS.md order
    (i from n down to 0, then j from n - i down to 0)."""
    n = degree
    w = 1.0 - u - v
    pu = [u ** e for e in range(n + 1)]
    pv = [v ** e for e in range(n + 1)]
    pw = [w ** e for e in range(n + 1)]
    fact = [math.factorial(e) for e in range(n + 1)]
    x = [0.0, 0.0, 0.0]
    idx = 0
    for i in range(n, -1, -1):
        for j in range(n - i, -1, -1):
            k = n - i - j
            b = fact[n] / (fact[i] * fact[j] * fact[k]) * pu[i] * pv[j] * pw[k]
            p = points[idx]
            x[0] += b * p[0]
            x[1] += b * p[1]
            x[2] += b * p[2]
            idx += 1
    return x


def sphere_distance(x, centre, radius):
    return abs(math.dist(x, centre) - radius)


def net_sphere_error(net, centre, radius, grid):
    """max | |x - c| - R | over u = a/N, v = b/N, a + b <= N (corners included)."""
    worst = 0.0
    for a in range(grid + 1):
        for b in range(grid + 1 - a):
            x = eval_triangular(net["degree"], net["points"], a / grid, b / grid)
            worst = max(worst, sphere_distance(x, centre, radius))
    return worst


def eval_tensor(degree, points, u, v):
    """x(u, v) = sum B_i^n(u) B_j^m(v) P_ij, P_ij at index i*(m+1) + j (FORMATS.md)."""
    n, m = degree
    bu = [math.comb(n, i) * u ** i * (1.0 - u) ** (n - i) for i in range(n + 1)]
    bv = [math.comb(m, j) * v ** j * (1.0 - v) ** (m - j) for j in range(m + 1)]
    x = [0.0, 0.0, 0.0]
    for i in range(n + 1):
        for j in range(m + 1):
            b = bu[i] * bv[j]
            p = points[i * (m + 1) + j]
            for d in range(3):
                x[d] += b * p[d]
    return x


# The catenoid between the unit circles at z = +-CATENOID_HALF_HEIGHT (examples/005-complex-exact,
# catenoid.json): r(z) = a cosh(z / a) with a cosh(h / a) = 1, the larger root (the stable catenoid).
CATENOID_HALF_HEIGHT = 0.5
CATENOID_AREA = 5.99179697580228  # pi a (2h + a sinh(2h / a)), the job's exact area


def catenoid_neck(h=CATENOID_HALF_HEIGHT):
    """a with a cosh(h / a) = 1 on [0.6, 1] (the larger root for h = 0.5: a = 0.84833793809...)."""
    lo, hi = 0.6, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (lo * math.cosh(h / lo) - 1.0) * (mid * math.cosh(h / mid) - 1.0) <= 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def catenoid_area(a, h=CATENOID_HALF_HEIGHT):
    return math.pi * a * (2.0 * h + a * math.sinh(2.0 * h / a))


def catenoid_distance(x, a):
    """| r - a cosh(z / a) |, r the distance to the z axis: the radial distance to the catenoid."""
    return abs(math.hypot(x[0], x[1]) - a * math.cosh(x[2] / a))


def net_max_distance(net, distance, grid):
    """max distance(x) over a grid of a triangular (u = a/N, v = b/N, a + b <= N) or tensor
    (u = a/N, v = b/N) patch."""
    if net["type"] == "tensor":
        return max(distance(eval_tensor(net["degree"], net["points"], a / grid, b / grid))
                   for a in range(grid + 1) for b in range(grid + 1))
    return max(distance(eval_triangular(net["degree"], net["points"], a / grid, b / grid))
               for a in range(grid + 1) for b in range(grid + 1 - a))


# Barycentric sample points of a facet for the "surface" error: the 15 points of a 4-grid.
FACET_SAMPLES = [(a / 4, b / 4) for a in range(5) for b in range(5 - a)]


def facet_point(corners, mids, l1, l2):
    """The 6-node quadratic triangle (mids = None: the flat one) at barycentric (l1, l2, 1 - l1 - l2).
    mids[0] is the midpoint of corners 0-1, mids[1] of 1-2, mids[2] of 2-0."""
    l3 = 1.0 - l1 - l2
    lam = (l1, l2, l3)
    if mids is None:
        return [sum(lam[c] * corners[c][d] for c in range(3)) for d in range(3)]
    pairs = ((0, 1), (1, 2), (2, 0))
    out = []
    for d in range(3):
        val = sum(lam[c] * (2.0 * lam[c] - 1.0) * corners[c][d] for c in range(3))
        val += sum(4.0 * lam[a] * lam[b] * mids[e][d] for e, (a, b) in enumerate(pairs))
        out.append(val)
    return out


# --------------------------------------------------------------------------- the two problems

class Case:
    """One problem: the boundary, H, the exact sphere, the bpde jobs and the Evolver data file."""

    def __init__(self, name, builder, H, centre, radius, area_exact, functionals, complex_job=False):
        self.complex_job = complex_job  # the boundary as a COMPLEX job (the automatic fan of 6 patches)
        self.name = name
        self.builder = builder
        self.H = H
        self.centre = centre
        self.radius = radius
        self.area_exact = area_exact
        self.functionals = functionals

    def job(self, degree, functional, mc_tolerance=None, start=None):
        # The same boundary net for every functional: the interpolant, pinned (a job
        # without "fit" gets the geometric fit for the area and mean-curvature functionals, which
        # would change the sphere case's boundary and the published tables; the circle's corners
        # are joined, so its arcs are refitted geometrically either way).
        boundary = {"type": "triangular", "degree": degree, "builder": self.builder, "fit": "interpolation"}
        if self.complex_job:  # the unit circle as one circle curve, the fan of 6 triangular patches
            boundary = {"type": "complex", "patch": "triangular", "degree": degree,
                        "loops": [[{"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]}
        problem = {"kind": "cmc", "H": self.H, "solver": "newton"}
        if functional != "dirichlet":
            problem["functional"] = functional
        if mc_tolerance is not None:
            problem["mean_curvature_tolerance"] = mc_tolerance
        if start is not None:
            problem["start"] = start
        job = {"boundary": boundary, "fixed": "boundary", "problem": problem, "samples": 40}
        if self.complex_job:
            del job["fixed"]  # a complex holds its boundary rows
        return job


def circle_case():
    H = -0.5
    R = 1.0 / abs(H)
    h = R - math.sqrt(R * R - 1.0)  # the cap's height over the unit circle
    return Case("circle", "circle-three-arcs", H, (0.0, 0.0, -math.sqrt(R * R - 1.0)), R, 2.0 * math.pi * R * h,
                ["area", "mean-curvature"])


def circle_complex_case():
    """The circle's cap as a complex job: the same exact cap and Evolver file as `circle`."""
    c = circle_case()
    return Case("circle-complex", None, c.H, c.centre, c.radius, c.area_exact, ["area"], complex_job=True)


def sphere_case():
    return Case("sphere", "sphere-triangle", 1.0, (0.0, 0.0, 0.0), 1.0, None, ["dirichlet", "area", "mean-curvature"])


class CatenoidCase:
    """The catenoid as a complex job (examples/005-complex-exact/catenoid.json: the unit circles at
    z = +-0.5 as two loops, the inner one the other way round, the annulus ring of tensor patches,
    the area functional, H = 0) with its degree and refine set per row; the error is the relative
    area error |A - A*| / A* against the exact area."""

    name = "catenoid-complex"
    H = 0.0
    complex_job = True
    functionals = ["area"]

    def __init__(self, example_job):
        self.example_job = example_job
        self.neck = catenoid_neck()
        self.area_exact = CATENOID_AREA

    def job(self, degree, refine):
        with open(self.example_job) as f:
            job = json.load(f)
        job["boundary"]["degree"] = degree
        job["boundary"]["refine"] = refine
        return job

    def distance(self, x):
        return catenoid_distance(x, self.neck)

    def relative_area_error(self, area):
        return abs(area - self.area_exact) / self.area_exact


def evolver_pressure(H):
    """Evolver's prescribed pressure for bezierpde's H, with the facets oriented as x_u ^ x_v."""
    return -2.0 * H


def fan_faces_and_body(H):
    """The .fe lines shared by both start meshes, after the six boundary edges 1..6 (vertex k+1 to
    k+2): the spokes 7..12 from the boundary vertices to the centre vertex 7, the six facets
    (boundary edge k+1, spoke to the centre, spoke back: counter-clockwise, normals as x_u ^ x_v) and
    the body with the pressure of H."""
    lines = ["%d  %d 7" % (k + 7, k + 1) for k in range(6)]
    lines += ["", "faces"] + ["%d  %d %d %d" % (k + 1, k + 1, (k + 1) % 6 + 7, -(k + 7)) for k in range(6)]
    return lines + ["", "bodies", "1  1 2 3 4 5 6  pressure %.17g" % evolver_pressure(H), ""]


def fe_circle(H):
    """The .fe file of the circle: the unit circle as a boundary parametrised by angle (refinement puts
    new boundary vertices on the exact circle), six fixed boundary vertices and one free centre, six
    facets counter-clockwise seen from +z (normal +z, as x_u ^ x_v of the three arcs)."""
    lines = [
        "// bezierpde scripts/evolver_compare.py: CMC cap over the unit circle, H = %g (bezierpde)" % H,
        "boundary 1 parameters 1",
        "x1: cos(p1)",
        "x2: sin(p1)",
        "x3: 0",
        "",
        "vertices",
    ]
    for k in range(6):
        lines.append("%d  %d*pi/3  boundary 1 fixed" % (k + 1, k))
    lines += ["7  0 0 0.2", "", "edges"]
    for k in range(6):
        lines.append("%d  %d %d  boundary 1 fixed" % (k + 1, k + 1, (k + 1) % 6 + 1))
    return "\n".join(lines + fan_faces_and_body(H))


def fe_catenoid(sides=6):
    """The .fe file of the catenoid: the unit circles at z = +-0.5 as two boundaries parametrised by
    angle (refinement puts new boundary vertices on the exact circles), `sides` fixed vertices on each
    at p1 = 2 pi k / sides, and the tube between them: per side a vertical edge (bottom k to top k), a
    diagonal (bottom k to top k + 1) and two triangles. No body (H = 0: area alone). The start tube
    is the prism of the two polygons; its middle ring, made at the first refinement, starts at radius 1
    and moves in towards the neck (a = 0.848) under the gradient steps."""
    K = sides
    lines = [
        "// bezierpde scripts/evolver_compare.py: catenoid between the unit circles at z = +-%g" % CATENOID_HALF_HEIGHT,
        "boundary 1 parameters 1", "x1: cos(p1)", "x2: sin(p1)", "x3: %.17g" % CATENOID_HALF_HEIGHT,
        "boundary 2 parameters 1", "x1: cos(p1)", "x2: sin(p1)", "x3: %.17g" % -CATENOID_HALF_HEIGHT,
        "", "vertices",
    ]
    top = lambda k: k % K + 1  # noqa: E731  vertices 1..K on z = +0.5
    bottom = lambda k: k % K + K + 1  # noqa: E731  vertices K+1..2K on z = -0.5
    lines += ["%d  %d*pi/%d  boundary 1 fixed" % (top(k), 2 * k, K) for k in range(K)]
    lines += ["%d  %d*pi/%d  boundary 2 fixed" % (bottom(k), 2 * k, K) for k in range(K)]
    lines += ["", "edges"]
    lines += ["%d  %d %d  boundary 1 fixed" % (k + 1, top(k), top(k + 1)) for k in range(K)]  # top ring
    lines += ["%d  %d %d  boundary 2 fixed" % (K + k + 1, bottom(k), bottom(k + 1)) for k in range(K)]
    lines += ["%d  %d %d" % (2 * K + k + 1, bottom(k), top(k)) for k in range(K)]  # verticals
    lines += ["%d  %d %d" % (3 * K + k + 1, bottom(k), top(k + 1)) for k in range(K)]  # diagonals
    lines += ["", "faces"]
    for k in range(K):
        vert_next = 2 * K + (k + 1) % K + 1
        lines.append("%d  %d %d %d" % (2 * k + 1, K + k + 1, vert_next, -(3 * K + k + 1)))
        lines.append("%d  %d %d %d" % (2 * k + 2, 3 * K + k + 1, -(k + 1), -(2 * K + k + 1)))
    return "\n".join(lines) + "\n"


def sphere_triangle_parameters():
    """(u, v) of the seven vertices of the Evolver start mesh on the bezierpde triangle: the corners
    P_00n (0,0), P_n00 (1,0), P_0n0 (0,1), the edge midpoints and the centroid; and the six facets,
    counter-clockwise in (u, v), so that their normals follow x_u ^ x_v."""
    uv = [(0, 0), (0.5, 0), (1, 0), (0.5, 0.5), (0, 1), (0, 0.5), (1 / 3, 1 / 3)]
    facets = [(0, 1, 6), (1, 2, 6), (2, 3, 6), (3, 4, 6), (4, 5, 6), (5, 0, 6)]
    return uv, facets


def fe_sphere(H):
    """The .fe file of the conformal triangle: its three edges are circles on the unit sphere, each
    the sphere cut by a plane through the north pole (the images of the lines t = -1/3, s + t = 1/3,
    s = -1/3 under the inverse stereographic projection, (s, t) = (u - 1/3, v - 1/3)). The boundary
    vertices are fixed and on two constraints (the sphere and their plane), so refinement projects
    new boundary vertices onto the exact curve. The start centre is the mean of the boundary (flat)."""
    uv, facets = sphere_triangle_parameters()
    xs = [inverse_stereographic(u - 1 / 3, v - 1 / 3) for u, v in uv[:6]]
    centre = [sum(p[d] for p in xs) / 6 for d in range(3)]
    # constraint 1: the sphere; 2: edge v = 0 (t = -1/3); 3: edge w = 0 (s + t = 1/3); 4: edge u = 0.
    lines = [
        "// bezierpde scripts/evolver_compare.py: CMC patch, the conformal sphere triangle, H = %g (bezierpde)" % H,
        "constraint 1", "formula: x^2 + y^2 + z^2 = 1",
        "constraint 2", "formula: 3*y + 1 - z = 0",
        "constraint 3", "formula: 3*x + 3*y + z = 1",
        "constraint 4", "formula: 3*x + 1 - z = 0",
        "", "vertices",
    ]
    # corner 0 on edges u=0, v=0; corner 2 on v=0, w=0; corner 4 on w=0, u=0; midpoints on one edge.
    vertex_constraints = ["1 2 4", "1 2", "1 2 3", "1 3", "1 3 4", "1 4"]
    for k in range(6):
        x, y, z = xs[k]
        lines.append("%d  %.17g %.17g %.17g  fixed constraint %s" % (k + 1, x, y, z, vertex_constraints[k]))
    lines += ["7  %.17g %.17g %.17g" % tuple(centre), "", "edges"]
    edge_constraints = ["1 2", "1 2", "1 3", "1 3", "1 4", "1 4"]
    for k in range(6):
        lines.append("%d  %d %d  fixed constraint %s" % (k + 1, k + 1, (k + 1) % 6 + 1, edge_constraints[k]))
    return "\n".join(lines + fan_faces_and_body(H))


REFINE_STEP = "r; g 5; u; V; V;"


def run_cmd(levels, quadratic, volume="body[1].volume"):
    """The Evolver command file: `levels` times (r; g 5; u; V; V: refine, relax, equiangulate, average
    the vertices), then the quadratic model if asked, g 10 and Hessian steps until the energy changes
    by less than 1e-14 relative (at most 12), then the mesh."""
    cmd = ["quiet on;"]
    cmd += [REFINE_STEP] * levels
    if quadratic:
        cmd.append("M 2;")
    cmd += [
        "g 10;",
        "hcount := 0;",
        "do { eold := total_energy; hessian; hcount += 1 }"
        " while (abs(eold - total_energy) > 1e-14 * abs(total_energy) and hcount < 12);",
        "quiet off;",
        'foreach vertex vv do printf "X %d %.17g %.17g %.17g\\n", vv.id, vv.x, vv.y, vv.z;',
    ]
    if quadratic:
        cmd.append('foreach facet ff do { printf "F"; foreach ff.edge ee do printf " %d %d %d", '
                   'ee.vertex[1].id, ee.vertex[2].id, ee.midv; printf "\\n" };')
    else:
        cmd.append('foreach facet ff do { printf "F"; foreach ff.edge ee do printf " %d %d 0", '
                   'ee.vertex[1].id, ee.vertex[2].id; printf "\\n" };')
    cmd += [
        'printf "S %%d %%d %%.17g %%.17g %%d\\n", facet_count, vertex_count, total_area, %s, hcount;' % volume,
        "q",
    ]
    return "\n".join(cmd) + "\n"


def evolver_errors(output, centre, radius, distance=None):
    """Parse the run's output: (vertex error, surface error, facets, vertices, area, hessian steps);
    the errors are the distance to the sphere (centre, radius), or distance(x) when given."""
    if distance is None:
        distance = lambda x: sphere_distance(x, centre, radius)  # noqa: E731
    verts = {}
    facets = []
    summary = None
    for line in output.splitlines():
        if line.startswith("X "):
            f = line.split()
            verts[int(f[1])] = (float(f[2]), float(f[3]), float(f[4]))
        elif line.startswith("F "):
            facets.append([int(t) for t in line.split()[1:]])
        elif line.startswith("S "):
            f = line.split()
            summary = (int(f[1]), int(f[2]), float(f[3]), float(f[4]), int(f[5]))
    if summary is None or not verts:
        raise RuntimeError("Evolver printed no mesh (its output ends: %r)" % output[-300:])
    vertex_err = max(distance(x) for x in verts.values())
    surface_err = 0.0
    for f in facets:
        # three oriented edges (tail, head, midpoint) in facet order: corners are the tails.
        corners = [verts[f[3 * e]] for e in range(3)]
        mids = None if f[2] == 0 else [verts[f[3 * e + 2]] for e in range(3)]
        for l1, l2 in FACET_SAMPLES:
            surface_err = max(surface_err, distance(facet_point(corners, mids, l1, l2)))
    return vertex_err, surface_err, summary[0], summary[1], summary[2], summary[4]


# --------------------------------------------------------------------------- running

def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def timed(cmd, **kw):
    t0 = child_cpu()
    p = subprocess.run(cmd, capture_output=True, text=True, **kw)
    return p, child_cpu() - t0


def run_bpde(bpde, case, degree, functional, work, grid, mc_tolerance=None, start=None):
    """One `bpde solve` of the case's job (with mc_tolerance: the mean-curvature functional to that
    tolerance, the job's "mean_curvature_tolerance"; with start: the area functional's job field
    "start")."""
    tag = ("" if mc_tolerance is None else "-t%g" % mc_tolerance) + ("" if start is None else "-" + start)
    d = os.path.join(work, "bpde-%s-%s-n%d%s" % (case.name, functional, degree, tag))
    os.makedirs(d, exist_ok=True)
    job = os.path.join(d, "job.json")
    with open(job, "w") as f:
        json.dump(case.job(degree, functional, mc_tolerance, start), f, indent=1)
    p, cpu = timed([bpde, "solve", job, "--out", os.path.join(d, "out")])
    res_file = os.path.join(d, "out", "result.json")
    extra = {} if mc_tolerance is None else {"mc_tolerance": mc_tolerance}
    if start is not None:
        extra["start"] = start
    if p.returncode not in (0, 1) or not os.path.exists(res_file):
        return dict({"degree": degree, "functional": functional, "cpu": cpu, "failed": (p.stderr or p.stdout).strip()},
                    **extra)
    with open(res_file) as f:
        result = json.load(f)
    rep = result["report"]
    mc = rep.get("mean_curvature") or {}
    return {
        **extra,
        "degree": degree,
        "functional": functional,
        "cpu": cpu,
        "seconds": rep.get("seconds"),
        "converged": rep.get("converged"),
        "residual": rep.get("residual"),
        "error": (max(net_sphere_error(q, case.centre, case.radius, grid // 2) for q in result["net"]["patches"])
                  if result["net"].get("type") == "complex" else net_sphere_error(result["net"], case.centre,
                                                                                   case.radius, grid)),
        "area": rep.get("area"),
        "H_min": mc.get("min"),
        "H_max": mc.get("max"),
    }


def run_evolver(evolver, case, level, quadratic, work):
    d = os.path.join(work, "evolver-%s-%s-l%d" % (case.name, "quadratic" if quadratic else "linear", level))
    os.makedirs(d, exist_ok=True)
    fe = os.path.join(d, "file.fe")
    catenoid = isinstance(case, CatenoidCase)
    with open(fe, "w") as f:
        f.write(fe_catenoid() if catenoid else fe_circle(case.H) if case.name in ("circle", "circle-complex")
                else fe_sphere(case.H))
    with open(os.path.join(d, "run.cmd"), "w") as f:
        f.write(run_cmd(level, quadratic, "0.0" if catenoid else "body[1].volume"))
    with open(os.devnull) as devnull:
        p, cpu = timed([evolver, "-x", "-f", "run.cmd", "file.fe"], cwd=d, stdin=devnull)
    with open(os.path.join(d, "evolver.log"), "w") as f:
        f.write(p.stdout)
    if catenoid:
        v_err, s_err, facets, verts, area, hsteps = evolver_errors(p.stdout, None, None, case.distance)
        return {"level": level, "model": "quadratic" if quadratic else "linear", "cpu": cpu,
                "error": case.relative_area_error(area), "distance": v_err, "surface": s_err, "facets": facets,
                "vertices": verts, "area": area, "hessian": hsteps}
    v_err, s_err, facets, verts, area, hsteps = evolver_errors(p.stdout, case.centre, case.radius)
    return {"level": level, "model": "quadratic" if quadratic else "linear", "cpu": cpu, "error": v_err,
            "surface": s_err, "facets": facets, "vertices": verts, "area": area, "hessian": hsteps}


def run_bpde_catenoid(bpde, case, degree, refine, work, grid):
    """One `bpde solve` of the catenoid complex job at (degree, refine): the relative area error from
    the report's area, and the largest distance to the catenoid over a grid of every patch."""
    d = os.path.join(work, "bpde-%s-n%d-r%d" % (case.name, degree, refine))
    os.makedirs(d, exist_ok=True)
    job = os.path.join(d, "job.json")
    with open(job, "w") as f:
        json.dump(case.job(degree, refine), f, indent=1)
    p, cpu = timed([bpde, "solve", job, "--out", os.path.join(d, "out")])
    res_file = os.path.join(d, "out", "result.json")
    row = {"degree": degree, "refine": refine, "functional": "area", "cpu": cpu}
    if p.returncode not in (0, 1) or not os.path.exists(res_file):
        return dict(row, failed=(p.stderr or p.stdout).strip())
    with open(res_file) as f:
        result = json.load(f)
    rep = result["report"]
    patches = result["net"]["patches"]
    return dict(row, seconds=rep.get("seconds"), converged=rep.get("converged"), residual=rep.get("residual"),
                area=rep.get("area"), patches=len(patches), error=case.relative_area_error(rep["area"]),
                distance=max(net_max_distance(q, case.distance, grid) for q in patches))


def loglog_time(rows, error):
    """The CPU seconds a program needs for `error`: along its cheapest rows (each with a smaller error
    than every cheaper row), log CPU interpolated linearly in log error between the two rows around
    it; the cheapest row's time when it is already below `error`; None when no row reaches it."""
    front = []
    for r in sorted(rows, key=lambda r: r["cpu"]):
        if r["error"] > 0 and (not front or r["error"] < front[-1]["error"]):
            front.append(r)
    if not front or front[-1]["error"] > error:
        return None
    if front[0]["error"] <= error:
        return front[0]["cpu"]
    for a, b in zip(front, front[1:]):
        if b["error"] <= error < a["error"]:
            s = math.log(error / a["error"]) / math.log(b["error"] / a["error"])
            return math.exp(math.log(max(a["cpu"], 1e-3)) + s * (math.log(max(b["cpu"], 1e-3))
                                                                 - math.log(max(a["cpu"], 1e-3))))
    return None


def catenoid_bpde_table(rows):
    out = ["| n | refine | patches | \\|A − A*\\| / A* | distance to the catenoid (max over the grid) | residual "
           "| converged | CPU s (process) | solve s (report, wall) |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        if "failed" in r:
            out.append("| %d | %d | | failed: %s | | | | %.2f | |" % (r["degree"], r["refine"], r["failed"], r["cpu"]))
            continue
        out.append("| %d | %d | %d | %s | %s | %s | %s | %.2f | %.2f |" % (
            r["degree"], r["refine"], r["patches"], fmt(r["error"]), fmt(r["distance"]), fmt(r["residual"]),
            "yes" if r["converged"] else "no", r["cpu"], r["seconds"] or 0.0))
    return "\n".join(out)


def catenoid_evolver_table(rows):
    out = ["| model | refinements | facets | vertices | area | \\|A − A*\\| / A* | distance (max over the vertices) "
           "| distance (facets sampled) | Hessian steps | CPU s |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        out.append("| %s | %d | %d | %d | %.12f | %s | %s | %s | %d | %.2f |" % (
            r["model"], r["level"], r["facets"], r["vertices"], r["area"], fmt(r["error"]), fmt(r["distance"]),
            fmt(r["surface"]), r["hessian"], r["cpu"]))
    return "\n".join(out)


def catenoid_time_table(brows, erows, targets):
    """Per relative area error: the least CPU seconds that reached it (the row), the log-log
    interpolated time of each program and the ratio Evolver / bezierpde at that error (Evolver: the
    faster of its two models)."""
    bok = [r for r in brows if "failed" not in r and r["converged"]]
    routes = [("bezierpde", bok)] + [("Evolver " + m, [r for r in erows if r["model"] == m])
                                     for m in ("linear", "quadratic")]
    out = ["| \\|A − A*\\| / A* ≤ | bezierpde (least CPU s reached) | Evolver linear | Evolver quadratic "
           "| bezierpde interpolated | Evolver interpolated | Evolver / bezierpde |",
           "| --- | --- | --- | --- | --- | --- | --- |"]
    for t in targets:
        cells = []
        for name, rows in routes:
            hits = [r for r in rows if r["error"] <= t]
            b = min(hits, key=lambda r: r["cpu"]) if hits else None
            if b is None:
                cells.append("not reached")
            elif name == "bezierpde":
                cells.append("%.2f s (n = %d, refine %d)" % (b["cpu"], b["degree"], b["refine"]))
            else:
                cells.append("%.2f s (%d facets)" % (b["cpu"], b["facets"]))
        tb = loglog_time(bok, t)
        te = [x for x in (loglog_time(rows, t) for _, rows in routes[1:]) if x is not None]
        te = min(te) if te else None
        cells.append("%.3f s" % tb if tb is not None else "not reached")
        cells.append("%.3f s" % te if te is not None else "not reached")
        if tb is not None and te is not None:
            cells.append("%.0f×" % (te / tb) if te / tb >= 10 else "%.1f×" % (te / tb))
        elif tb is not None and erows:
            lower = max(r["cpu"] for r in erows) / tb  # Evolver's costliest level did not reach it
            cells.append(("> %.0f× (Evolver not reached)" if lower >= 10 else "> %.1f× (Evolver not reached)") % lower)
        else:
            cells.append("")
        out.append("| %.0e | " % t + " | ".join(cells) + " |")
    return "\n".join(out)


def run_library(example, case, degree, tolerance, grid):
    """One `example_004_cmc_area_tables --solve-circle N T` process: the area solve to tolerance T."""
    p, cpu = timed([example, "--solve-circle", str(degree), repr(tolerance)])
    if p.returncode not in (0, 1):
        return {"degree": degree, "functional": "area", "tolerance": tolerance, "cpu": cpu,
                "failed": (p.stderr or p.stdout).strip()}
    r = json.loads(p.stdout)
    if r.get("H") != case.H:
        return {"degree": degree, "functional": "area", "tolerance": tolerance, "cpu": cpu,
                "failed": "the library route solved H = %r, the case is H = %r" % (r.get("H"), case.H)}
    return {
        "degree": degree,
        "functional": "area",
        "tolerance": tolerance,
        "cpu": cpu,
        "seconds": r["seconds"],
        "converged": r["converged"],
        "status": r["status"],
        "residual": r["residual"],
        "iterations": r["iterations"],
        "error": net_sphere_error(r["net"], case.centre, case.radius, grid),
    }


def library_table(rows):
    out = ["| n | tolerance | error (max over the grid) | residual | status | iterations | CPU s (process) "
           "| solve s (wall) |",
           "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        if "failed" in r:
            out.append("| %d | %.0e | failed: %s | | | | %.3f | |" % (r["degree"], r["tolerance"], r["failed"], r["cpu"]))
            continue
        out.append("| %d | %.0e | %s | %s | %s | %d | %.3f | %.3f |" % (
            r["degree"], r["tolerance"], fmt(r["error"]), fmt(r["residual"]), r["status"], r["iterations"], r["cpu"],
            r["seconds"]))
    return "\n".join(out)


def fmt(x, spec=".1e"):
    return "" if x is None else format(x, spec)


def area_err(case, a):
    return "" if case.area_exact is None or a is None else fmt(abs(a - case.area_exact))


def label(r):
    """The functional of a bpde row, with its mean-curvature tolerance or its start when the job set one."""
    return r["functional"] + ("" if "mc_tolerance" not in r else " (√Φ ≤ %.0e)" % r["mc_tolerance"]) + \
        ("" if "start" not in r else " (start: %s)" % r["start"])


def bpde_table(case, rows):
    out = ["| functional | n | error (max over the grid) | \\|A − A_exact\\| | H min … max | residual | converged "
           "| CPU s (process) | solve s (report, wall) |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        if "failed" in r:
            out.append("| %s | %d | failed: %s | | | | | %.2f | |" %
                       (label(r), r["degree"], r["failed"], r["cpu"]))
            continue
        hr = "%.6f … %.6f" % (r["H_min"], r["H_max"]) if r["H_min"] is not None else ""
        out.append("| %s | %d | %s | %s | %s | %s | %s | %.2f | %.2f |" % (
            label(r), r["degree"], fmt(r["error"]), area_err(case, r["area"]), hr, fmt(r["residual"]),
            "yes" if r["converged"] else "no", r["cpu"], r["seconds"] or 0.0))
    return "\n".join(out)


def evolver_table(case, rows):
    out = ["| model | refinements | facets | vertices | error (max over the vertices) | error (facets sampled) "
           "| \\|A − A_exact\\| | Hessian steps | CPU s |",
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        out.append("| %s | %d | %d | %d | %s | %s | %s | %d | %.2f |" % (
            r["model"], r["level"], r["facets"], r["vertices"], fmt(r["error"]), fmt(r["surface"]),
            area_err(case, r["area"]), r["hessian"], r["cpu"]))
    return "\n".join(out)


def time_to_accuracy(case, brows, erows, targets, lrows=()):
    """For each error target: the least CPU seconds of each program (and route) that reached it
    (bezierpde: converged results only; the library rows: converged to their own tolerance)."""
    def best(rows, key):
        hits = [r for r in rows if "failed" not in r and r.get("converged", True) and r["error"] <= key]
        return min(hits, key=lambda r: r["cpu"]) if hits else None

    routes = [("bezierpde " + f, [r for r in brows if r["functional"] == f and "mc_tolerance" not in r
                                  and "start" not in r]) for f in case.functionals]
    starts = sorted({r["start"] for r in brows if "start" in r})
    routes += [("bezierpde area (start: %s)" % s, [r for r in brows if r.get("start") == s]) for s in starts]
    mc_rows = [r for r in brows if r["functional"] == "mean-curvature"]
    if any("mc_tolerance" in r for r in mc_rows):
        routes.append(("bezierpde mean-curvature (degree and tolerance)", mc_rows))
    if lrows:
        routes.append(("bezierpde area, library (degree and tolerance)", list(lrows)))
    routes += [("Evolver " + m, [r for r in erows if r["model"] == m]) for m in ("linear", "quadratic")]
    routes = [(name, rows) for name, rows in routes if rows]
    out = ["| error ≤ | " + " | ".join(name for name, _ in routes) + " |",
           "| --- |" + " --- |" * len(routes)]
    for t in targets:
        cells = []
        for name, rows in routes:
            b = best(rows, t)
            if b is None:
                cells.append("not reached")
            elif "tolerance" in b:
                cells.append("%.3f s (n = %d, %.0e)" % (b["cpu"], b["degree"], b["tolerance"]))
            elif "mc_tolerance" in b:
                cells.append("%.3f s (n = %d, √Φ ≤ %.0e)" % (b["cpu"], b["degree"], b["mc_tolerance"]))
            elif "degree" in b:
                cells.append("%.2f s (n = %d)" % (b["cpu"], b["degree"]))
            else:
                cells.append("%.2f s (%d facets)" % (b["cpu"], b["facets"]))
        out.append("| %.0e | " % t + " | ".join(cells) + " |")
    return "\n".join(out)


def parse_list(text):
    if ".." in text:
        a, b = text.split("..")
        return list(range(int(a), int(b) + 1))
    return [int(t) for t in text.split(",") if t]


def section_names(case, library):
    """The sections of scripts/docs.py that one case prints (generator evolver, docs/cmc_evolver_measurements.md)."""
    return ["evolver-%s-%s" % (case, t) for t in (["bezierpde", "library", "evolver", "time"] if library
                                                   else ["bezierpde", "evolver", "time"])]


def marked(name, table, machine_dependent):
    """A table between the section markers of scripts/docs.py (the timing columns machine-dependent)."""
    return "<!-- generated: %s; machine-dependent: %s -->\n%s\n<!-- end -->" % (name, ", ".join(machine_dependent),
                                                                              table)


def run_catenoid(bpde, evolver, case, args, work):
    """The catenoid-complex case: bpde over degrees x refines, Evolver over its levels, three sections."""
    brows = [run_bpde_catenoid(bpde, case, n, r, work, 20) for r in parse_list(args.catenoid_refines)
             for n in parse_list(args.catenoid_degrees)]
    erows = [run_evolver(evolver, case, k, False, work) for k in parse_list(args.catenoid_linear_levels)]
    erows += [run_evolver(evolver, case, k, True, work) for k in parse_list(args.catenoid_quadratic_levels)]
    names = dict(zip(["bezierpde", "evolver", "time"], section_names(case.name, False)))
    print("\n### %s, H = 0 (bezierpde)\n" % case.name)
    print(marked(names["bezierpde"], catenoid_bpde_table(brows), ["CPU s (process)", "solve s (report, wall)"]))
    print()
    print(marked(names["evolver"], catenoid_evolver_table(erows), ["CPU s"]))
    print()
    table = catenoid_time_table(brows, erows, [10.0 ** -k for k in range(3, 15)])
    print(marked(names["time"], table, ["bezierpde (least CPU s reached)", "Evolver linear", "Evolver quadratic",
                                        "bezierpde interpolated", "Evolver interpolated", "Evolver / bezierpde"]))
    with open(os.path.join(work, "rows-%s.json" % case.name), "w") as f:
        json.dump({"bpde": brows, "evolver": erows}, f, indent=1)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bpde", default="build/bpde")
    ap.add_argument("--evolver", default="evolver")
    ap.add_argument("--case", default="circle", choices=["circle", "sphere", "circle-complex", "catenoid-complex", "all"])
    ap.add_argument("--degrees", default="4,5,6,7,8,10,12")
    ap.add_argument("--linear-levels", default="1..8")
    ap.add_argument("--quadratic-levels", default="1..6")
    ap.add_argument("--catenoid-degrees", default="3..8", help="catenoid-complex: the degrees of the complex job")
    ap.add_argument("--catenoid-refines", default="0..1", help="catenoid-complex: the job's refine values")
    ap.add_argument("--catenoid-linear-levels", default="1..7",
                    help="catenoid-complex: Evolver's linear levels (level k: 12 * 4^k facets)")
    ap.add_argument("--catenoid-quadratic-levels", default="1..7", help="catenoid-complex: Evolver's quadratic levels")
    ap.add_argument("--example-job", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir,
                                                          "examples", "005-complex-exact", "catenoid.json"),
                    help="catenoid-complex: the complex job whose degree and refine the rows set")
    ap.add_argument("--grid", type=int, default=60, help="samples per side of the bezierpde error grid")
    ap.add_argument("--out", default=None,
                    help="keep the jobs, .fe and run.cmd files here (default: a temporary folder)")
    ap.add_argument("--tolerances", default="",
                    help="circle: also the library route at these first-variation tolerances (comma-separated)")
    ap.add_argument("--mc-tolerances", default="",
                    help="comma-separated mean_curvature_tolerance values in (0, 1): extra `bpde solve` rows of the "
                         "mean-curvature functional (both cases)")
    ap.add_argument("--area-dirichlet-start", action="store_true",
                    help="also the area functional with the job field \"start\": \"dirichlet\" (the D_H routes "
                         "without the mean-curvature start), in the same run")
    ap.add_argument("--library", default="build/example_004_cmc_area_tables",
                    help="the example program of the library route")
    ap.add_argument("--list", action="store_true",
                    help="print the names of the sections these arguments print (scripts/docs.py) and exit")
    args = ap.parse_args(argv)
    if args.list:
        for name in {"circle": ["circle"], "sphere": ["sphere"], "circle-complex": ["circle-complex"],
                     "catenoid-complex": ["catenoid-complex"],
                     "all": ["circle", "sphere", "circle-complex", "catenoid-complex"]}[args.case]:
            print("\n".join(section_names(name, bool(args.tolerances) and name == "circle")))
        return 0
    try:
        tolerances = [float(t) for t in args.tolerances.split(",") if t]
    except ValueError:
        tolerances = None
    if tolerances is None or not all(0 < t <= 1e-3 for t in tolerances):
        print("error: --tolerances must be comma-separated numbers in (0, 1e-3], got %r" % args.tolerances,
              file=sys.stderr)
        return 2
    try:
        mc_tolerances = [float(t) for t in args.mc_tolerances.split(",") if t]
    except ValueError:
        mc_tolerances = None
    if mc_tolerances is None or not all(0 < t < 1 for t in mc_tolerances):
        print("error: --mc-tolerances must be comma-separated numbers in (0, 1), got %r" % args.mc_tolerances,
              file=sys.stderr)
        return 2
    if tolerances and not (os.path.isfile(args.library) and os.access(args.library, os.X_OK)):
        print("error: %s is not an executable; build it with `cmake --build build --target "
              "example_004_cmc_area_tables`" % args.library, file=sys.stderr)
        return 2

    evolver = shutil.which(args.evolver)
    if evolver is None:
        print("error: Surface Evolver (`%s`) not found; %s" % (args.evolver, INSTALL_HINT), file=sys.stderr)
        return 2
    if not (os.path.isfile(args.bpde) and os.access(args.bpde, os.X_OK)):
        print("error: %s is not an executable bpde; build it with `cmake --build build --target bpde`" % args.bpde,
              file=sys.stderr)
        return 2
    bpde = os.path.abspath(args.bpde)
    cases = {"circle": [circle_case()], "sphere": [sphere_case()], "circle-complex": [circle_complex_case()],
             "catenoid-complex": [CatenoidCase(args.example_job)],
             "all": [circle_case(), sphere_case(), circle_complex_case(), CatenoidCase(args.example_job)]}[args.case]
    work = args.out or tempfile.mkdtemp(prefix="evolver_compare-")
    os.makedirs(work, exist_ok=True)
    print("machine: %s, load average at start %.2f %.2f %.2f; work folder %s" % (
        os.uname().nodename, *os.getloadavg(), work))
    for case in cases:
        if isinstance(case, CatenoidCase):
            run_catenoid(bpde, evolver, case, args, work)
            continue
        # the complex jobs up to n = 10 (the fan at n = 12 and above takes minutes per solve)
        degrees = [n for n in parse_list(args.degrees) if not case.complex_job or n <= 10]
        brows = [run_bpde(bpde, case, n, f, work, args.grid) for f in case.functionals for n in degrees]
        if "mean-curvature" in case.functionals:
            brows += [run_bpde(bpde, case, n, "mean-curvature", work, args.grid, t) for t in mc_tolerances
                      for n in degrees]
        if args.area_dirichlet_start and "area" in case.functionals and not case.complex_job:
            brows += [run_bpde(bpde, case, n, "area", work, args.grid, start="dirichlet") for n in degrees]
        lrows = [run_library(os.path.abspath(args.library), case, n, t, args.grid) for n in degrees for t in tolerances] \
            if case.name == "circle" else []
        erows = [run_evolver(evolver, case, k, False, work) for k in parse_list(args.linear_levels)]
        erows += [run_evolver(evolver, case, k, True, work) for k in parse_list(args.quadratic_levels)]
        names = dict(zip(["bezierpde", "library", "evolver", "time"] if lrows else ["bezierpde", "evolver", "time"],
                         section_names(case.name, bool(lrows))))
        print("\n### %s, H = %g (bezierpde)\n" % (case.name, case.H))
        print(marked(names["bezierpde"], bpde_table(case, brows), ["CPU s (process)", "solve s (report, wall)"]))
        print()
        if lrows:
            print("\n### %s, H = %g (bezierpde library, by tolerance)\n" % (case.name, case.H))
            print(marked(names["library"], library_table(lrows), ["CPU s (process)", "solve s (wall)"]))
            print()
        print(marked(names["evolver"], evolver_table(case, erows), ["CPU s"]))
        print()
        table = time_to_accuracy(case, brows, erows, [1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9], lrows)
        print(marked(names["time"], table, [c.strip() for c in table.split("\n")[0].strip("|").split("|")][1:]))
        with open(os.path.join(work, "rows-%s.json" % case.name), "w") as f:
            json.dump({"bpde": brows, "library": lrows, "evolver": erows}, f, indent=1)
    print("\nload average at the end %.2f %.2f %.2f" % os.getloadavg())
    return 0


if __name__ == "__main__":
    sys.exit(main())
