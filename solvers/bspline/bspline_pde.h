#pragma once
// B-spline solutions of the general second- and fourth-order Euler–Lagrange equations
// (Sun, Zhu, "B-spline solutions of general Euler–Lagrange equations", eqs. (2) and (4),
// Algorithms 1–2), corrected as in docs/errata.md (B-spline Euler–Lagrange):
//
//   second order:  a x_uu + b x_uv + c x_vv = 0                          (eq. (2))
//   fourth order:  A x_uuuu + B x_uuuv + C x_uuvv + D x_uvvv + E x_vvvv = 0 (eq. (4))
//
// The operator is the Euler–Lagrange operator of an EnergySpec (energies/energy_spec.h):
// dirichlet -> (1,0,1), second-order [a,b,c] -> (a,b,c), any fourth-order energy -> its [A..E].
//
// x is a tensor B-spline (tensor/bspline_net.h, standard indexing), so Lx = 0 means: on every
// non-empty knot span, every Bernstein coefficient of Lx (in local span variables) vanishes. The
// equations are built span by span, and their rank is computed, never taken from the paper's
// equation counts (how: docs/bspline.md, "PDE solutions").
//
// With the prescribed control points X_c moved to the right-hand side, A_f X_f = -A_c X_c is
// solved by a rank-revealing SVD (singular values below rank_tolerance·σ_max count as zero):
//   - inconsistent data (relative residual of the least-squares solution above
//     consistency_tolerance): NO solution. The result is converged = false with a message, and
//     its net is the input net unchanged (not a least-squares net). On a multi-span net with
//     A != 0 and E != 0 every solution is one global polynomial, so generic boundary data have no
//     solution (docs/errata.md, B-spline Euler–Lagrange, "Multi-span nets");
//   - consistent data and full column rank: the unique solution;
//   - consistent data with free parameters (degenerate operators such as x_uuuu = 0, or few fixed
//     points): the member of the solution affine space that minimises the energy whose
//     Euler–Lagrange operator L is (the EnergySpec's own functional, solvers/bspline/bspline_extremal.h),
//     flagged by minimum_energy_member.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

#include "bezierpde/core/fixed_set.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/pde/pde_residual.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/bspline_net.h"

namespace bpde {

struct BSplinePdeOptions {
  /// Which control points are prescribed (FORMATS.md "fixed"). Default: boundary. Any order takes
  /// "boundary" and "boundary+adjacent" (C1 data: the outer two rings; the ranks, free parameters
  /// and compatibility conditions are computed for the set as for any other); "u-boundaries" is
  /// accepted for second-order operators only (UnsupportedProblem otherwise).
  FixedSet fixed = FixedSet::Boundary;
  /// Singular values below rank_tolerance * (largest) count as zero. Default 1e-10.
  double rank_tolerance = 1e-10;
  /// Data are inconsistent when max|A_f X_f + A_c X_c| > consistency_tolerance *
  /// max(|A_f||X_f| + |A_c||X_c|) (over all rows and coordinates). Default 1e-10 (the values
  /// that compatible and perturbed data give: docs/bspline.md).
  double consistency_tolerance = 1e-10;
  /// Throws ParameterError unless both tolerances are in (0, 1).
  void validate() const;
};

/// The FORMATS.md "pde" problem on B-spline nets (method "lu" only): a fourth-order operator with
/// "boundary" or "boundary+adjacent" data (the prescribed points go to the right-hand side, the
/// ranks are computed: any prescribed set works), a second-order one with "u-boundaries". No
/// minimum degree beyond the operator's own (bspline_pde_equations).
inline SolverRequirements bspline_pde_requirements(const EnergySpec& op) {
  SolverRequirements r;
  r.problem = "problem \"pde\"";
  r.nets = {NetKind::BSpline};
  if (op.order() == 4) {
    r.fixed = {FixedSet::Boundary, FixedSet::BoundaryAdjacent};
    r.fixed_reason = "a fourth-order pde (" + op.name() +
                     ") on a bspline net takes \"fixed\": \"boundary\" or \"boundary+adjacent\"";
  } else {
    r.fixed = {FixedSet::UBoundaries};
    r.fixed_reason = "a second-order pde (" + op.name() + ") takes \"fixed\": \"u-boundaries\"";
  }
  r.methods = {"lu"};
  r.method_reason = "problem \"pde\" on a bspline net has no explicit method; use \"method\": \"lu\"";
  return r;
}

struct BSplinePdeResult {
  BSplineNet net;  ///< the solution (or the input net unchanged when converged = false)
  /// residual: the relative residual of the equations (see Options); status Incompatible when the
  /// data miss the compatibility conditions, NumericalLimit when rounding spoils the solution.
  Summary summary;
  int equations = 0;                   ///< number of equations (Bernstein coefficients of Lx over all spans)
  int rank = 0;                        ///< rank of the equations over ALL control points (paper's count)
  int rank_free = 0;                   ///< rank of the equations over the free control points
  int free_parameters = 0;             ///< dimension of the solution set (per coordinate) with the data fixed
  int compatibility_conditions = 0;    ///< independent linear conditions the prescribed data must meet
  bool minimum_energy_member = false;  ///< free parameters were fixed by minimising the energy
  double energy = 0.0;                 ///< the energy of the returned net (EnergySpec's functional)
};

/// The equations over all control points: a (#equations x nu*nv) matrix whose product with the
/// points (one column per coordinate) lists the scaled Bernstein coefficients of Lx on every
/// span (span by span, su * Sv + sv; within a span a * (dv+1) + b). Throws ParameterError for an
/// operator with all coefficients zero, DegreeError if a term of the operator differentiates
/// more often than the degree in that direction (it would vanish identically), and the knot
/// checks of BSplineNet.
Eigen::MatrixXd bspline_pde_equations(int p, int q, const std::vector<double>& U, const std::vector<double>& V,
                                      const EnergySpec& op);

/// Size limit of the solve: the equations are compressed strip by strip (one u-span at a time) to
/// an N x N triangle, whose SVD is dense, so at most kMaxDensePdeUnknowns control points; larger
/// requests throw UnsupportedProblem instead of running for minutes.
inline constexpr int kMaxDensePdeUnknowns = 1500;

/// Solve with the fixed set of the options (first overload) or an explicit strictly increasing
/// list of fixed point indices i*nv + j (second overload; e.g. the paper's Example 1 fixes the
/// row i = 0 only).
BSplinePdeResult solve_bspline_pde(const BSplineNet& data, const EnergySpec& op, const BSplinePdeOptions& options = {});
BSplinePdeResult solve_bspline_pde(const BSplineNet& data, const EnergySpec& op, const std::vector<int>& fixed,
                                   const BSplinePdeOptions& options = {});

/// FORMATS.md `pde_residual`: max over the (N+1)^2 sample grid of |Lx| divided by the max over the
/// grid of Σ_k |c_k| |∂^k x|, the grid mapped onto the knot domain. As in solvers/pde/pde_residual.h,
/// the denominator is floored at 1e-8 Σ_k |c_k| p!/(p-k_u)! q!/(q-k_v)! h_u^-k_u h_v^-k_v max|P_ij|
/// (h = the shortest span), so that an exact solution whose terms all vanish does not read
/// rounding / rounding = O(1); 0 when everything vanishes.
double bspline_pde_residual(const BSplineNet& net, const EnergySpec& op, int samples = 50);

/// max |A P| / max (|A| |P|) of the equations above for a given net (its relative equation
/// residual; 0 means the net solves the PDE on every span to rounding).
double bspline_pde_equation_residual(const BSplineNet& net, const EnergySpec& op);

}  // namespace bpde
