#pragma once
// Tetraharmonic Bézier surfaces from C¹ boundary data (seed 000: Centella, Monterde, Moreno,
// Oset, "Two C¹-methods to generate Bézier surfaces from the boundary", §3 Theorem 1, Annex A).
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
// 8n - 8 (§3; NOTES.md: holds for n >= 3).
//
// Methods:
//   Explicit: the constructive proof of Annex A: a_0j, a_1j, a_i0, a_i1 from the data
//     (eqs. (17), (18), (21), (22)); then for k = n, n-1, ..., 2 the 2x2 systems S^k, S_k
//     (eqs. (19), (20), (23), (24)) give a_2k, a_3k, a_k2, a_k3, and Lemma 2's pentadiagonal
//     (1,4,6,4,1) systems give the diagonal i + j = k + 3 (i, j >= 4); a_ij = 0 for
//     i + j >= n + 4 (Remark 4). Works in the (factorial) power basis.
//   LU (default): least squares of the (n+1)^2 Bernstein coefficients (at degree (n,n)) of Δ⁴x
//     over the interior points. The data always admit an exact solution (Theorem 1), so the
//     least-squares residual is zero up to rounding. The matrix is ill-conditioned
//     (cond ~3e6 at n = 12, ~5e13 at n = 20), so the solution operator (interior = G * data) is
//     computed by a long-double Householder QR refined with residuals evaluated in binary128 from
//     exact entries; it is computed once per degree and cached (thread-safe; ~0.1 s at n = 12,
//     ~1-2 s at n = 20). A solve is one (n-3)^2 x (8n-8) product; when its relative Δ⁴ residual
//     exceeds 1e-12 (G * data cancels: a small solution from a large G, typically n >= 16), the
//     solve is refined in binary128 with the cached QR (up to 3 steps, ~10-40 ms at n = 16-20),
//     which brings the residual to ~1e-17 (tested to n = 24).
//   Accuracy: the problem itself amplifies data rounding (the interior grows like ~1e9 x the data
//     at n = 20, NOTES.md), so both methods recover an exact tetraharmonic polynomial to about
//     1e-14 (n = 8), 1e-12 (n = 12), 1e-9 (n = 16), 1e-8 (n = 18) relative; see docs/c1.md.
#include <Eigen/Core>
#include <string>

#include "solvers/summary.h"
#include "solvers/requirements.h"
#include "tensor/tensor_net.h"

namespace bpde {

struct TetraharmonicOptions {
  enum class Method { Explicit, LU };
  Method method = Method::LU;  ///< default LU (FORMATS.md "method" defaults to "lu")
  void validate() const;       ///< throws ParameterError for a method value out of the enum
};

/// The FORMATS.md "tetraharmonic" problem: tensor nets, C1 data, n = m >= 4; methods explicit, lu.
inline SolverRequirements tetraharmonic_requirements() {
  SolverRequirements r;
  r.problem = "problem \"tetraharmonic\"";
  r.nets = {NetKind::Tensor};
  r.fixed = {FixedSet::BoundaryAdjacent};
  r.fixed_reason = r.problem + " takes C1 data: \"fixed\": \"boundary+adjacent\"";
  r.square = true;
  r.min_degrees = {{NetKind::Tensor, FixedSet::BoundaryAdjacent, 4}};
  r.methods = {"explicit", "lu"};
  return r;
}

/// "explicit" or "lu" -> Method; anything else throws ParameterError naming the value.
TetraharmonicOptions::Method parse_tetraharmonic_method(const std::string& name);

struct TetraharmonicResult {
  TensorNet net;   ///< degree (n,n); outer two rings copied from the data
  Summary summary; ///< residual: max |Bernstein coefficient of Δ⁴x| / max over the five terms
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
