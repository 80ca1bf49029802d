#pragma once
// Tetraharmonic Bézier surfaces from C¹ boundary data (Centella, Monterde, Moreno, Oset, "Two
// C¹-methods to generate Bézier surfaces from the boundary", §3 Theorem 1, Annex A).
//
// Conventions (FORMATS.md):
//   x(u,v) = sum_{i,j=0..n} B_i^n(u) B_j^n(v) P_ij = sum a_ij/(i! j!) u^i v^j on [0,1]^2,
//   P_ij is row i*(n+1)+j; a_ij are the factorial-power coefficients of Annex A.
//   Δ⁴ = ∂⁸_u + 4∂⁶_u∂²_v + 6∂⁴_u∂⁴_v + 4∂²_u∂⁶_v + ∂⁸_v (eq. (6)); in the a_ij, Δ⁴x = 0 is
//   eq. (7): a_{i+8,j} + 4a_{i+6,j+2} + 6a_{i+4,j+4} + 4a_{i+2,j+6} + a_{i,j+8} = 0.
//   Data: the outer two rings, TensorNet::fixed_indices(FixedSet::BoundaryAdjacent) (the points
//   with min(i, n-i, j, n-j) <= 1, 8n - 8 of them). Unknowns: the (n-3)^2 points 2 <= i,j <= n-2.
//
// Theorem 1: for n >= 4 there is exactly one polynomial of bidegree (n,n) with Δ⁴x = 0 and the
// given outer two rings; the tetraharmonic polynomials of bidegree n form a space of dimension
// 8n - 8 (§3; docs/errata.md, C¹ methods Theorem 1: holds for n >= 3).
//
// Methods:
//   Explicit: the constructive proof of Annex A (eqs. (17)–(24), Lemma 2, Remark 4), in the
//     (factorial) power basis; it loses accuracy at high degree (see the converged flag below).
//   LU (default): least squares of the (n+1)^2 Bernstein coefficients (at degree (n,n)) of Δ⁴x
//     over the interior points, by a solution operator computed once per degree and cached
//     (thread-safe). The data always admit an exact solution (Theorem 1).
// The problem itself amplifies data rounding, so errors are relative to the solution's size.
// How each method works, its accuracy and its timings: docs/c1.md, "How the C¹ solvers work".
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <string>

#include "bezierpde/solvers/c1/c1_requirements.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

struct TetraharmonicOptions {
  enum class Method { Explicit, LU };
  Method method = Method::LU;  ///< default LU (FORMATS.md "method" defaults to "lu")
  /// LU only: refine a solution whose relative residual exceeds 1e-12 (the coordinates that need
  /// it, towards 1e-16, at most 3 steps). Default true; false shows what the refinement buys
  /// (bench Tetraharmonic/lu-unrefined, docs/performance.md).
  bool refine = true;
  void validate() const;  ///< throws ParameterError for a method value out of the enum
};

/// The FORMATS.md "tetraharmonic" problem: tensor nets, C1 data, n = m >= 4; methods explicit, lu.
inline SolverRequirements tetraharmonic_requirements() {
  SolverRequirements r = c1_data_requirements("problem \"tetraharmonic\"");
  r.methods = {"explicit", "lu"};
  return r;
}

/// "explicit" or "lu" -> Method; anything else throws ParameterError naming the value.
TetraharmonicOptions::Method parse_tetraharmonic_method(const std::string& name);

struct TetraharmonicResult {
  TensorNet net;    ///< degree (n,n); outer two rings copied from the data
  Summary summary;  ///< residual: max |Bernstein coefficient of Δ⁴x| / max over the five terms
                    ///< of eq. (6) of their coefficients; converged iff residual <= 1e-11
};

/// Theorem 1. `data`: degree (n,n) net, n >= 4; only its outer two rings are read.
/// Throws DegreeError (n != m or n < 4), NonFiniteError (non-finite data point).
/// A result whose residual exceeds 1e-11 (the explicit method at high degree) is returned with
/// converged = false and a message suggesting "lu".
TetraharmonicResult solve_tetraharmonic(const TensorNet& data, const TetraharmonicOptions& options = {});

/// The (n+1)^2 by (n+1)^2 matrix mapping a scalar net (row-major, index i*(n+1)+j) to the
/// Bernstein coefficients at degree (n,n) of its Δ⁴. Its null space is the tetraharmonic space.
Eigen::MatrixXd tetraharmonic_operator(int n);

/// Pieces of Annex A exposed for tests.
namespace tetraharmonic_detail {
/// Lemma 2's k x k pentadiagonal Toeplitz matrix with rows (1, 4, 6, 4, 1).
Eigen::MatrixXd lemma2_matrix(int k);
/// Lemma 2's closed form det M_k = (12 + 28k + 23k² + 8k³ + k⁴) / 12.
double lemma2_determinant(int k);
/// Factorial-power coefficients a_ij ((n+1)^2 by 3, row i*(n+1)+j) by the explicit recursion.
Eigen::MatrixX3d explicit_coefficients(const TensorNet& data);
}  // namespace tetraharmonic_detail

}  // namespace bpde
