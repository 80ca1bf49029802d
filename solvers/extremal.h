#pragma once
// Extremals of quadratic energies: the minimiser of E(P) = 1/2 Σ_c P_c^T Q P_c over the free
// control points, the fixed ones prescribed (FORMATS.md problem "extremal"; seed 001 §2 states the
// energies, NOTES.md "The minimisation claim ... is false when only the boundary is fixed").
//
// With f the free and b the fixed indices, the optimality condition ∂E/∂P_f = 0 is the reduced
// symmetric system
//     Q_ff X_f = -Q_fb X_b,     so  X_f = M X_b,   M = -Q_ff^{-1} Q_fb   (the "mould"),
// the same for the three coordinates. Q_ff must be positive definite (the energy is strictly
// convex over the free points); a singular or indefinite Q_ff is bad input (ParameterError),
// never a NaN.
//
// ExtremalSolver factors once and precomputes the mould (#free x #fixed); each solve is then one
// matrix product. Two ways to build it:
//  - generic, from any Gram matrix Q and a fixed index list (tensor, triangular, B-spline nets).
//    The reduced system is Jacobi-scaled to unit diagonal and Cholesky-factored; a reciprocal
//    condition estimate below ExtremalOptions::singular_tolerance means singular, a failed
//    factorisation indefinite (classified by a pivoted LDLT). Note: in the Bernstein basis Q_ff is exponentially
//    ill-conditioned in the degree (about 1e15 at tensor degree 16, numerically singular from
//    about 17), so at high degree this path refuses (ParameterError) rather than return garbage;
//  - tensor, from (EnergySpec, n, m, FixedSet). Because the energy is a sum of Kronecker products
//    and every fixed set is the complement of a tensor product of 1-D index ranges, the reduced
//    system is assembled directly in a well-conditioned tensor basis φ_k(u) ψ_l(v) of the free
//    space: φ_k = (t(1-t))^s C_k^(2s+1/2)(2t-1) (Gegenbauer, L2-orthonormal; s = 1 for boundary,
//    2 for boundary+adjacent, 0 in v for u-boundaries), with the 1-D integrals by Gauss quadrature
//    and the Bernstein coefficients of φ_k by the Gegenbauer recurrence in Bernstein form. Its
//    condition number grows only polynomially, so the singularity test is meaningful at every
//    degree (checked to 30) and the solve is backward stable in those coordinates.
//
// Accuracy (measured against a 50-digit solve): the map X_b -> X_f itself is ill-conditioned in
// Bernstein coordinates (|M|_inf ~ 1e6 at degree 20 for biharmonic), so the control points carry
// an error of about eps * |M|_inf * |X_b| (1e-11 relative at n = 20); the surface is accurate to
// ~1e-10 at n = 20, against ~1e-7 for a double Bernstein-basis solve. The Bernstein residual
// |Q_f P| is NOT a useful convergence measure beyond degree ~16 (iterative refinement on it drives
// it to 1e-16 while the net diverges); Summary::residual is therefore the residual of the reduced
// system in the conditioned coordinates (reduced_residual), and the energy of the extremal is
// evaluated there too (extremal_energy).
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "core/fixed_set.h"
#include "energies/energy_spec.h"
#include "solvers/summary.h"
#include "solvers/requirements.h"
#include "tensor/tensor_net.h"

namespace bpde {

struct ExtremalOptions {
  /// Smallest accepted reciprocal condition number (1-norm estimate) of the unit-diagonal
  /// (Jacobi-scaled) reduced system; below it the system counts as singular. A failed Cholesky
  /// factorisation means indefinite (or exactly singular). Default 1e-13. Must be in [0, 1).
  double singular_tolerance = 1e-13;
  /// Tensor nets: assemble in the well-conditioned Gegenbauer basis (default true). False uses the
  /// generic Bernstein path (for comparisons; refuses high degrees, see the header comment).
  bool conditioned_basis = true;
  /// solve_extremal: reuse a process-wide cache of solvers per (energy terms, n, m, fixed,
  /// options) (default false: assemble and factor for this call).
  bool use_cache = false;
  /// Throws ParameterError naming the bad field.
  void validate() const;
};

/// The FORMATS.md "extremal" problem on tensor nets (the tensor constructor) and triangular nets
/// (the generic constructor with the triangular Gram matrix): any fixed set the net defines;
/// tensor n, m >= 2 with C0 data and >= 4 with C1 data, triangular n >= 3 and >= 6.
inline SolverRequirements extremal_requirements() {
  SolverRequirements r;
  r.problem = "problem \"extremal\"";
  r.nets = {NetKind::Tensor, NetKind::Triangular};
  r.fixed = {FixedSet::Boundary, FixedSet::BoundaryAdjacent, FixedSet::UBoundaries};
  r.min_degrees = {{NetKind::Tensor, FixedSet::Boundary, 2},     {NetKind::Tensor, FixedSet::BoundaryAdjacent, 4},
                   {NetKind::Tensor, FixedSet::UBoundaries, 2},  {NetKind::Triangular, FixedSet::Boundary, 3},
                   {NetKind::Triangular, FixedSet::BoundaryAdjacent, 6}};
  return r;
}

class ExtremalSolver {
 public:
  /// Generic: Q is N x N symmetric (SizeError if not square, NonFiniteError if not finite);
  /// fixed lists the prescribed indices (each in 0..N-1, no repeats: SizeError otherwise); the
  /// others are free, in increasing order. Throws ParameterError if there is no free index or
  /// Q_ff is singular or indefinite (message says which).
  ExtremalSolver(const Eigen::MatrixXd& Q, std::vector<int> fixed, const ExtremalOptions& options = {});

  /// Tensor nets of degree (n,m) with the prescribed set `fixed`. Throws DegreeError below the
  /// FORMATS.md minimum degrees (n, m >= 2 for boundary, >= 4 for boundary+adjacent, n >= 2 for
  /// u-boundaries), ParameterError for a singular or indefinite reduced system.
  ExtremalSolver(const EnergySpec& energy, int n, int m, FixedSet fixed,
                 const ExtremalOptions& options = {});

  /// A shared solver from a process-wide cache (thread-safe; the cache keeps the 32 most recent).
  static std::shared_ptr<const ExtremalSolver> cached(const EnergySpec& energy, int n, int m, FixedSet fixed,
                                                      const ExtremalOptions& options = {});

  int size() const { return N_; }
  const std::vector<int>& fixed_indices() const { return fixed_; }
  const std::vector<int>& free_indices() const { return free_; }
  /// The mould M (#free x #fixed): X_f = M X_b, rows in free_indices() order, columns in
  /// fixed_indices() order.
  const Eigen::MatrixXd& mould() const { return mould_; }

  /// The extremal with the fixed rows of `points` (N x 3) prescribed: one product with the mould.
  /// The free rows of the input are ignored. SizeError on a wrong row count.
  Eigen::MatrixX3d solve(const Eigen::MatrixX3d& points) const;
  /// Same for a tensor net (SizeError if its size differs from size()).
  TensorNet solve(const TensorNet& net) const;
  /// Same result through the stored factorisation (two triangular solves) instead of the mould.
  Eigen::MatrixX3d solve_factored(const Eigen::MatrixX3d& points) const;

  /// Relative optimality residual of a net (N x 3) in Bernstein coordinates: max over free rows
  /// and coordinates of |(Q P)_I| / Σ_J |Q_IJ| |P_J| (0 when the denominator is 0). Meaningful up
  /// to degree ~16; beyond, Q_ff is numerically singular and this number says little (the exact
  /// extremal rounded to double has residual ~1e-16, but so do far-off nets).
  double optimality_residual(const Eigen::MatrixX3d& points) const;
  /// The optimality condition in the solver's (conditioned) coordinates X_f = S Y for the fixed
  /// data of `points`: Y from the factorisation, then max |A Y + A_fb X_b| / (|A| |Y| + |A_fb| |X_b|)
  /// componentwise. This is what solve_extremal reports as Summary::residual.
  double reduced_residual(const Eigen::MatrixX3d& points) const;
  /// The energy 1/2 Σ_c P_c^T Q P_c of any net (N x 3). At high degree the extremal's Bernstein
  /// coefficients are large and this sum cancels badly: use extremal_energy for the extremal.
  double energy(const Eigen::MatrixX3d& points) const;
  /// The energy of the extremal with the fixed data of `points`, evaluated in the solver's
  /// coordinates: 1/2 Σ_c (Y^T A Y + 2 Y^T A_fb X_b + X_b^T Q_bb X_b); accurate relative to the
  /// size of the boundary data at every degree.
  double extremal_energy(const Eigen::MatrixX3d& points) const;
  /// The full Gram matrix Q.
  const Eigen::MatrixXd& gram() const { return Q_; }

 private:
  void check_rows(Eigen::Index rows) const;
  void factor(const Eigen::MatrixXd& A_ff, const Eigen::MatrixXd& A_fb, const ExtremalOptions& options,
              const std::string& what);
  Eigen::MatrixXd apply_basis(const Eigen::MatrixXd& Y) const;

  int N_ = 0;
  Eigen::MatrixXd Q_;
  std::vector<int> fixed_, free_;
  // X_f = S Y with A_ff Y = -A_fb X_b, S = kron(Tu, Tv) diag(scale) (Tu, Tv empty: S = diag(scale)).
  Eigen::VectorXd scale_;
  Eigen::MatrixXd Tu_, Tv_;
  Eigen::MatrixXd A_ff_, A_fb_;
  struct Factor;
  std::shared_ptr<const Factor> factor_;
  Eigen::MatrixXd mould_;
};

/// Result of a one-off extremal solve.
struct ExtremalResult {
  TensorNet net;
  double energy = 0.0;  ///< the energy of the extremal
  Summary summary;      ///< residual = ExtremalSolver::reduced_residual; converged = residual <= 1e-11
};

/// The extremal of `energy` with the `fixed` points of `net` prescribed (its other points are
/// ignored). Throws as the tensor ExtremalSolver constructor and ExtremalOptions::validate.
ExtremalResult solve_extremal(const TensorNet& net, const EnergySpec& energy, FixedSet fixed,
                              const ExtremalOptions& options = {});

}  // namespace bpde
