"""bezierpde: Bézier surfaces from boundary data by energies and PDEs.

The command contract of ``bpde`` from Python, with the same JSON (dicts) as the command:

    >>> import bezierpde
    >>> net, report = bezierpde.solve(job)          # job: the dict of a JOB.json file
    >>> V, F, H = bezierpde.sample(net, samples=50) # numpy arrays
    >>> bezierpde.energy(net, "dirichlet"), bezierpde.check(net)
    >>> bezierpde.plate(1.0, 11, "admissible-load"), bezierpde.blend(config)
    >>> table = bezierpde.sweep(spec, client=None)  # a pandas DataFrame (or a list of rows)

Nets are ``TensorNet``, ``TriangularNet`` and ``BSplineNet`` (``points``: an N x 3 numpy view of
the net), and the solver entry points take their Options and return a ``Summary`` (status,
message, iterations, residual, seconds): ``solve_pde_explicit``, ``solve_pde_lu``, ``solve_cmc``,
``solve_tetraharmonic``, ``solve_clamped_plate``, ``solve_extremal`` (tensor and triangular; and
``ExtremalSolver``, factored once), ``solve_bspline_extremal``, ``solve_bspline_pde`` and
``solve_smoothing_spline`` (``SmoothingSplineProblem``, ``SmoothingSplineSolver``). Each returns
the same numbers as ``solve``/``blend`` on the equivalent job, to the last bit.

Errors: ``bezierpde.InvalidInput`` (a ValueError) and its subclasses ``ParseError``,
``FileError``, ``DegreeError``, ``SizeError``, ``NonFiniteError``, ``ParameterError``,
``UnsupportedProblem`` for bad input (the command's exit 2); ``bezierpde.InternalError`` (a
RuntimeError) for a broken invariant (exit 3); both derive from ``bezierpde.Error``.
"""

from ._core import (  # noqa: F401
    __version__,
    Error,
    InvalidInput,
    ParseError,
    FileError,
    DegreeError,
    SizeError,
    NonFiniteError,
    ParameterError,
    UnsupportedProblem,
    InternalError,
    Status,
    Summary,
    TensorNet,
    TriangularNet,
    BSplineNet,
    net_from_dict,
    sample,
    energy,
    check,
    check_mesh,
    plate,
    solve_result,
    blend_result,
    PdeExplicitOptions,
    PdeLuOptions,
    solve_pde_explicit,
    solve_pde_lu,
    CmcOptions,
    solve_cmc,
    TetraharmonicOptions,
    solve_tetraharmonic,
    ClampedPlateOptions,
    solve_clamped_plate,
    ExtremalOptions,
    ExtremalResult,
    TriangularExtremalResult,
    ExtremalSolver,
    solve_extremal,
    BSplineExtremalOptions,
    BSplineExtremalResult,
    solve_bspline_extremal,
    BSplinePdeOptions,
    BSplinePdeResult,
    solve_bspline_pde,
    SmoothingSplineProblem,
    SmoothingSplineOptions,
    SmoothingSpline,
    SmoothingSplineResult,
    SmoothingSplineSolver,
    solve_smoothing_spline,
    expand_sweep,
    sweep_boundary_names,
    PatchComplex,
    complex_from_boundary,
    ComplexExtremalResult,
    solve_complex_extremal,
    CmcResultComplex,
    sample_complex,
)
from .sweep import sweep  # noqa: F401


def solve(job, out=None):
    """``bpde solve`` for a JOB dict: ``(net, report)``, the "net" and "report" of result.json.

    With ``out`` the job folder is written as the command writes it (result.json, surface.obj,
    surface.ply, net.obj). A valid job without a solution returns ``report["converged"] == False``
    with ``report["message"]`` (the command's exit 1); bad input raises ``InvalidInput``.
    """
    result = solve_result(job, out)
    return result["net"], result["report"]


def blend(config, out=None):
    """``bpde blend`` for a CONFIG dict: ``(net, report)`` of its result.json."""
    result = blend_result(config, out)
    return result["net"], result["report"]


def points(net):
    """The control points of a NET dict (or a net object) as an N x 3 float64 array."""
    import numpy as np

    if isinstance(net, dict):
        return np.asarray(net["points"], dtype=np.float64).reshape(-1, 3)
    return np.asarray(net.points)
