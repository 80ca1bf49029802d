#pragma once
// Extremals of quadratic energies: the minimiser of E(P) = 1/2 Σ_c P_c^T Q P_c over the free
// control points, the fixed ones prescribed (FORMATS.md problem "extremal"). The energies are
// those of Arnal, Monterde, Ugail (explicit PDE solutions) §2 and Sun, Zhu (B-spline
// Euler–Lagrange); with only the boundary fixed, the extremal is not the PDE solution
// (docs/errata.md, explicit PDE solutions §2).
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
//  - generic, from any Gram matrix Q and a fixed index list (tensor, triangular, B-spline nets),
//    factored in the Bernstein basis. Q_ff is exponentially ill-conditioned there, so at high
//    degree this path refuses (ParameterError) rather than return garbage;
//  - tensor, from (EnergySpec, n, m, FixedSet), assembled in a well-conditioned tensor basis of
//    the free space, so the singularity test is meaningful at every degree.
// Summary::residual is the residual of the reduced system in the solver's conditioned
// coordinates (reduced_residual), not the Bernstein residual.
//
// The bases, the conditioning and the measured accuracy (against a 50-digit solve):
// docs/accuracy.md, "Extremals".
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "bezierpde/core/fixed_set.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

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
/// Largest degree of a triangular extremal job (the generic Bernstein path): its reduced Gram
/// system loses about a digit per degree. Measured (boundary data of a plane, whose extremal is
/// the plane): the free points are off by 1e-7 at n = 20, 3e-5 at n = 24, and at n = 25 the
/// Dirichlet and biharmonic systems are numerically singular (reciprocal condition < 1e-13).
inline constexpr int kMaxTriangularExtremalDegree = 20;

inline SolverRequirements extremal_requirements() {
  SolverRequirements r;
  r.problem = "problem \"extremal\"";
  r.max_degrees = {{NetKind::Triangular, kMaxTriangularExtremalDegree,
                    "the Bernstein Gram system of a triangular net is numerically singular from about 25 and "
                    "loses a digit per degree before"}};
  r.nets = {NetKind::Tensor, NetKind::Triangular};
  r.fixed = {FixedSet::Boundary, FixedSet::BoundaryAdjacent, FixedSet::UBoundaries};
  r.min_degrees = {{NetKind::Tensor, FixedSet::Boundary, 2},
                   {NetKind::Tensor, FixedSet::BoundaryAdjacent, 4},
                   {NetKind::Tensor, FixedSet::UBoundaries, 2},
                   {NetKind::Triangular, FixedSet::Boundary, 3},
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
  ExtremalSolver(const EnergySpec& energy, int n, int m, FixedSet fixed, const ExtremalOptions& options = {});

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

/// Result of a one-off extremal solve on a triangular net.
struct TriangularExtremalResult {
  TriangularNet net;
  double energy = 0.0;  ///< ExtremalSolver::extremal_energy of the data
  Summary summary;      ///< residual = ExtremalSolver::reduced_residual; converged = residual <= 1e-11
};

/// The extremal of `energy` on a triangular net of degree n with the `fixed` points of `net`
/// prescribed (its other points are ignored): the generic ExtremalSolver on the triangular Gram
/// matrix (energies/triangular_gram.h), factored in the Bernstein basis (options.conditioned_basis
/// and options.use_cache do not apply). Throws ParameterError (ExtremalOptions::validate, a
/// singular or indefinite reduced system: e.g. n < 3 with C0 data or n < 6 with C1 data, or a
/// degree far beyond kMaxTriangularExtremalDegree) and the errors of triangular_gram. What
/// `bpde solve` runs for the FORMATS.md "extremal" problem on a triangular net.
TriangularExtremalResult solve_extremal(const TriangularNet& net, const EnergySpec& energy, FixedSet fixed,
                                        const ExtremalOptions& options = {});

}  // namespace bpde
