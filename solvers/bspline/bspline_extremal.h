#pragma once
// Extremals of the quadratic energies of FORMATS.md on tensor-product B-spline nets
// (Sun–Zhu, B-spline Euler–Lagrange, §2 and §5: the functionals L_{a,b,c} of eq. (1) and L_{a,b,c,d,e} of §2,
// whose Euler–Lagrange equations are eqs. (2) and (4)). docs/errata.md (B-spline Euler–Lagrange): these extremals
// exist for any boundary, unlike the B-spline PDE solutions of solvers/bspline/bspline_pde.h.
//
// An energy is E(x) = ∫ over the knot domain of ½ Σ_t w_t <∂^{a_t} x, ∂^{b_t} x>
// (energies/energy_spec.h). With x = Σ_I N_I P_I (N_I = N_i(u) N_j(v), I = i*nv + j):
//   E = ½ Σ_c P_c^T Q P_c,  Q = Σ_t w_t sym(K^u_{a_u b_u} ⊗ K^v_{a_v b_v}),
//   K^u_{ab}[i,i'] = ∫ N_i^(a)(u) N_{i'}^(b)(u) du over [U_p, U_nu],
// and each 1-D integral is summed over the knot spans with a (p+1)-point Gauss–Legendre rule per
// span, exact for these piecewise polynomials of degree <= 2p. Q is sparse: |i-i'| <= p and
// |j-j'| <= q.
//
// The extremal keeps the fixed control points and solves the reduced system
//   Q_ff X_f = -Q_fc X_c   (one right-hand side per coordinate),
// by sparse Cholesky when Q_ff is positive definite. When it is not (an energy that is only
// semi-definite or indefinite on the free points, e.g. Coons with "u-boundaries"), a dense
// complete orthogonal decomposition returns the minimum-norm solution of the reduced system and
// the Summary message says so.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "bezierpde/core/fixed_set.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/bspline_net.h"

namespace bpde {

/// n x n matrix K[i,i'] = ∫_{K_k}^{K_n} N_i^(a) N_{i'}^(b) dt for one direction (degree k,
/// knots K, n = len(K)-k-1), exact (Gauss–Legendre with k+1 points per span). Zero if a or b > k.
Eigen::MatrixXd bspline_derivative_integrals(int k, const std::vector<double>& K, int a, int b);

/// The Gram matrix Q (N x N, N = nu*nv, symmetric, sparse) of the energy on nets of degree
/// (p, q) over the knots (U, V). Throws the knot checks of BSplineNet.
Eigen::SparseMatrix<double> bspline_gram(int p, int q, const std::vector<double>& U, const std::vector<double>& V,
                                         const EnergySpec& energy);

/// E(x) = ½ Σ_c P_c^T Q P_c of the net.
double bspline_energy(const BSplineNet& net, const EnergySpec& energy);

struct BSplineExtremalOptions {
  /// Which control points are prescribed (FORMATS.md "fixed"). Default: boundary.
  FixedSet fixed = FixedSet::Boundary;
  /// Relative residual of the reduced system above which the solve counts as failed. Default 1e-11.
  double tolerance = kConvergenceTolerance;
  /// Throws ParameterError if tolerance is not in (0, 1).
  void validate() const;
};

/// The FORMATS.md "extremal" problem on B-spline nets: any fixed set; degrees p, q >= 2 with C0
/// data and >= 4 with C1 data.
inline SolverRequirements bspline_extremal_requirements() {
  SolverRequirements r;
  r.problem = "problem \"extremal\"";
  r.nets = {NetKind::BSpline};
  r.fixed = {FixedSet::Boundary, FixedSet::BoundaryAdjacent, FixedSet::UBoundaries};
  r.min_degrees = {{NetKind::BSpline, FixedSet::Boundary, 2},
                   {NetKind::BSpline, FixedSet::BoundaryAdjacent, 4},
                   {NetKind::BSpline, FixedSet::UBoundaries, 2}};
  return r;
}

struct BSplineExtremalResult {
  BSplineNet net;  ///< the input net with its free points replaced by the extremal's
  double energy = 0.0;
  /// residual: max |Q_ff X_f + Q_fc X_c| / max(|Q_ff||X_f| + |Q_fc||X_c|); when above the
  /// tolerance, status NotUnique (Q_ff singular) or NumericalLimit.
  Summary summary;
};

/// The extremal with the fixed points of `data` given by options.fixed (or, in the second
/// overload, the explicit increasing list of fixed point indices i*nv + j; the free points are the
/// rest). Needs at least one free point (SizeError otherwise).
BSplineExtremalResult solve_bspline_extremal(const BSplineNet& data, const EnergySpec& energy,
                                             const BSplineExtremalOptions& options = {});
BSplineExtremalResult solve_bspline_extremal(const BSplineNet& data, const EnergySpec& energy,
                                             const std::vector<int>& fixed, const BSplineExtremalOptions& options = {});

/// The factored reduced system for one (degrees, knots, energy, fixed set): build once, then solve
/// for many boundary data ("mould" in the language of ARCHITECTURE.md).
class BSplineExtremalSolver {
 public:
  BSplineExtremalSolver(int p, int q, const std::vector<double>& U, const std::vector<double>& V,
                        const EnergySpec& energy, const std::vector<int>& fixed,
                        double tolerance = kConvergenceTolerance);
  ~BSplineExtremalSolver();
  BSplineExtremalSolver(BSplineExtremalSolver&&) noexcept;
  BSplineExtremalSolver& operator=(BSplineExtremalSolver&&) noexcept;

  /// Solve for the data net (its degrees and knots must be the ones given to the constructor,
  /// SizeError/ParameterError otherwise).
  BSplineExtremalResult solve(const BSplineNet& data) const;

  const Eigen::SparseMatrix<double>& gram() const;
  const std::vector<int>& fixed() const;
  const std::vector<int>& free() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bpde
