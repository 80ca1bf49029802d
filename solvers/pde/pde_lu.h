#pragma once
// Polynomial solutions of linear homogeneous PDEs with prescribed boundary control points, by a
// linear solve: the "lu" method of Arnal, Monterde, Ugail, "Explicit polynomial solutions of
// fourth order linear elliptic PDEs for boundary based smooth surface generation" (§3, §7
// Table 1). The Bernstein form below is also the engine of the harmonic PDE from u-boundaries
// (solvers/pde/harmonic_pde.h).
//
// Problem. x(u,v) = sum_{i<=n, j<=m} B_i^n(u) B_j^m(v) P_ij (FORMATS.md layout, row i*(m+1)+j).
// Given the prescribed points (FixedSet::Boundary: the outer ring; FixedSet::UBoundaries: rows
// i = 0 and i = n), find the free points such that L x = 0 with
//   order 4: L = A d4u + B d3u dv + C d2u d2v + D du d3v + E d4v   (eq. (2); B and D multiply
//            x_uuuv and x_uvvv: docs/errata.md, explicit PDE solutions eq. (2))
//   order 2: L = a d2u + b du dv + c d2v                           (harmonic: [1,0,1])
//
// Two formulations of the same equations (how each works: docs/pde_accuracy.md, "How the
// solvers work"):
//  - solve_pde_lu, n = m and fixed = boundary: block-triangular elimination along the
//    anti-diagonals k + l = s of the factorial-scaled monomial coefficients a_kl (eq. (4),
//    (5)–(9)), O(n^3);
//  - PdeMould, and solve_pde_lu for n != m: the least-squares system in the Bernstein basis,
//    O(n^6), which the mould factors once per (operator, degree, fixed set).
//
// Outcomes. Uniqueness and compatibility are decided structurally, from the small monomial
// blocks of the anti-diagonals (analyse_pde_structure). The solution is not unique: converged =
// false, the data returned unchanged. The data violate a compatibility condition (relative
// tolerance PdeLuOptions::compatibility_tolerance; for example the harmonic PDE from
// u-boundaries at even n, docs/errata.md): converged = false, the least-squares net returned.
// Bad input throws the typed errors named at each function.
//
// The solution amplifies boundary data (docs/errata.md, explicit PDE solutions, "Conditioning"),
// so errors are meaningful relative to the solution's own size. Measured errors against exact
// solutions and timings: docs/pde_accuracy.md.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <string>
#include <vector>

#include "bezierpde/core/fixed_set.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/pde/pde_residual.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

struct PdeLuOptions {
  /// Which formulation solve_pde_lu uses for square degrees (n != m always uses Bernstein):
  ///  - AntiDiagonal: the block-triangular LU on the monomial anti-diagonals, O(n^3) (default);
  ///  - Bernstein: the dense least-squares system in the Bernstein basis, O(n^6), the classical
  ///    "linear system" baseline of Table 1 (what PdeMould factors once).
  enum class Formulation { AntiDiagonal, Bernstein };
  Formulation formulation = Formulation::AntiDiagonal;
  /// A compatibility condition c . x_B = 0 on the prescribed points holds when
  /// |c . x_B| <= compatibility_tolerance * sum_j |c_j| |x_Bj| (per coordinate). Default 1e-8.
  double compatibility_tolerance = 1e-8;
  /// Rank threshold of the small monomial blocks (entries O(1)): relative singular values in the
  /// structure analysis, pivots in the anti-diagonal block LU. Default 1e-10.
  double rank_tolerance = 1e-10;
  /// Throws ParameterError unless both tolerances are finite and in (0, 1).
  void validate() const;
};

/// The FORMATS.md "pde" problem with method "lu" on tensor nets (solve_pde_lu): a fourth-order
/// operator with "boundary" data, degrees n, m >= 2. (Second-order operators: harmonic_pde.h.)
inline SolverRequirements pde_lu_requirements(const EnergySpec& op) {
  SolverRequirements r;
  r.problem = "problem \"pde\"";
  r.nets = {NetKind::Tensor};
  if (op.order() == 4) {
    r.fixed = {FixedSet::Boundary};
    r.fixed_reason = "a fourth-order pde (" + op.name() + ") takes \"fixed\": \"boundary\"";
  } else {
    r.fixed_reason = "a second-order pde (" + op.name() + ") takes \"fixed\": \"u-boundaries\"";
  }
  r.min_degrees = {{NetKind::Tensor, FixedSet::Boundary, 2}};
  r.methods = {"lu"};
  return r;
}

/// A net and how it was obtained.
struct PdeSolution {
  TensorNet net;
  Summary summary;
};

/// Structure of the problem (operator, degrees, fixed set), from the monomial block analysis.
struct PdeStructure {
  bool unique = true;     ///< every anti-diagonal block has full column rank
  int conditions = 0;     ///< number of linear compatibility conditions on the data
  std::string diagnosis;  ///< human-readable reason when !unique or conditions > 0
};

/// Monomial anti-diagonal analysis (see the header comment). `coeffs` are the operator's
/// coefficients c_j of d^{p-j}_u d^j_v, j = 0..p (p = 2 or 4).
PdeStructure analyse_pde_structure(const std::vector<double>& coeffs, int n, int m, FixedSet fixed,
                                   double rank_tolerance = 1e-10);

/// The "mould" of Table 1: for one (operator, n, m, fixed set) it factors the Bernstein system
/// once and stores the matrix S with  x_free = S x_fixed  (#free x #fixed) and the compatibility
/// functionals. Each solve is then one matrix product (plus one small product for the checks).
class PdeMould {
 public:
  /// Fourth-order operators need FixedSet::Boundary, second-order ones FixedSet::UBoundaries
  /// (else UnsupportedProblem). Degrees 1..kMaxDegree (DegreeError). Options are validated.
  PdeMould(const EnergySpec& op, int n, int m, FixedSet fixed = FixedSet::Boundary, const PdeLuOptions& options = {});

  int n() const { return n_; }
  int m() const { return m_; }
  FixedSet fixed() const { return fixed_; }
  const PdeStructure& structure() const { return structure_; }
  const std::vector<int>& fixed_indices() const { return fixed_idx_; }
  const std::vector<int>& free_indices() const { return free_idx_; }
  /// x_free = S x_fixed (rows follow free_indices(), columns fixed_indices()). Empty if not unique.
  const Eigen::MatrixXd& interior_from_boundary() const { return S_; }
  /// Compatibility functionals (structure().conditions rows, #fixed columns, unit rows).
  const Eigen::MatrixXd& conditions() const { return W_; }

  /// Solve for the data's prescribed points (its other points are ignored). The data's degree
  /// must be (n, m) (DegreeError). converged = false with a message when the solution is not unique
  /// (the data are returned unchanged) or the data violate a compatibility condition (the
  /// least-squares net is returned). summary.residual = compatibility_violation(data).
  PdeSolution solve(const TensorNet& data) const;

  /// The product only: out's free points = S * data's fixed points, out's fixed points = data's.
  /// Both nets must have degree (n, m) (DegreeError); UnsupportedProblem if the solution is not
  /// unique. No compatibility check (see compatibility_violation).
  void apply(const TensorNet& data, TensorNet& out) const;

  /// Largest relative violation of the compatibility conditions by the data (0 if none).
  double compatibility_violation(const TensorNet& data) const;

 private:
  int n_, m_;
  FixedSet fixed_;
  PdeLuOptions options_;
  PdeStructure structure_;
  std::vector<int> fixed_idx_, free_idx_;
  Eigen::MatrixXd S_, W_;
};

/// One-shot solve, nothing cached but the basis-change tables: the "lu" method. Fourth-order
/// operators with FixedSet::Boundary; n = m by the anti-diagonal block LU, n != m by the Bernstein
/// least-squares system (see the header comment). Same outcomes as PdeMould::solve.
PdeSolution solve_pde_lu(const TensorNet& data, const EnergySpec& op, const PdeLuOptions& options = {});

}  // namespace bpde
