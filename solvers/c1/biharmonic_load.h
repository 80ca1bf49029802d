#pragma once
// The nonhomogeneous biharmonic method with an admissible load (Centella, Monterde, Moreno, Oset,
// "Two C¹-methods to generate Bézier surfaces from the boundary", §4, Theorems 2–3,
// Proposition 2 and eq. (37) of Annex B).
//
// Conventions (FORMATS.md):
//   x(u,v) = sum_{i,j=0..n} B_i^n(u) B_j^n(v) P_ij on [0,1]^2, P_ij is row i*(n+1)+j.
//   The load of x is p = Δ²x = x_uuuu + 2 x_uuvv + x_vvvv. Its "load net" is the (n+1)^2 by 3
//   matrix of the Bernstein coefficients of p written at degree (n,n) (each term is a polynomial
//   of bidegree at most (n,n) and is degree-elevated there), in the same layout as the points.
//   "Outer two rings" = TensorNet::fixed_indices(FixedSet::BoundaryAdjacent): the points with
//   min(i, n-i, j, n-j) <= 1. The interior = 2 <= i, j <= n-2, (n-3)^2 points.
//
// Theorem 3: for every outer-two-ring data of a degree (n,n) net, n >= 4, there is exactly one
// x with those outer rings whose load net vanishes on the interior. The paper checks the
// uniqueness lemma symbolically for n <= 20; bezierpde solves the square Bernstein system
// ((n-3)^2 unknowns and equations) and reports the residual. How the solve works and how accurate
// it is: docs/c1.md, "How the C¹ solvers work".
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

#include "bezierpde/solvers/c1/c1_requirements.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

/// (n+1) by (n+1) matrix T with (T p) the Bernstein coefficients, written at degree n, of the
/// d-th derivative of sum_i p_i B_i^n (i.e. elevation(n-d -> n) * derivative(n -> n-d)).
/// Zero matrix when d > n. Requires n >= 1 and d >= 0 (DegreeError otherwise).
Eigen::MatrixXd derivative_at_degree(int n, int d);

/// Load net (degree (n,n), layout of the points) of the operator
///   c40 ∂⁴_u + c22 ∂²_u∂²_v + c04 ∂⁴_v   applied to `net` (degree (n,n), n >= 1).
/// With the default coefficients it is the load net p = Δ²x of FORMATS.md. Throws DegreeError
/// if net.n() != net.m().
TensorNet bilaplacian_load_net(const TensorNet& net, double c40 = 1.0, double c22 = 2.0, double c04 = 1.0);

struct BiharmonicLoadOptions {
  /// No tunable parameter today; kept for the uniform solver interface.
  void validate() const {}
};

/// The FORMATS.md "biharmonic-load" problem: tensor nets, C1 data, n = m >= 4.
inline SolverRequirements biharmonic_load_requirements() { return c1_data_requirements("problem \"biharmonic-load\""); }

struct BiharmonicLoadResult {
  TensorNet net;    ///< degree (n,n); outer two rings copied from the data
  TensorNet load;   ///< load net of net (degree (n,n)); zero (to rounding) at 2 <= i,j <= n-2
  Summary summary;  ///< residual = max |load interior| / max over the three terms' load nets
};

/// Theorem 3. `data` is a degree (n,n) net, n >= 4; only its outer two rings are read.
/// Throws DegreeError (n != m or n < 4) or NonFiniteError (non-finite data point).
BiharmonicLoadResult solve_biharmonic_load(const TensorNet& data, const BiharmonicLoadOptions& options = {});

/// Theorem 2: given a load net whose non-boundary points (1 <= i,j <= n-1) are prescribed,
/// return the same net with the unique boundary ring (min(i,n-i,j,n-j) = 0) that makes the load
/// admissible, i.e. the image under Δ² of a polynomial of bidegree (n,n). Computed as the square
/// Bernstein system  Δ²x - R_boundary = R_interior  with x's outer ring zero ((n+1)^2 unknowns).
/// Throws DegreeError (n != m or n < 4), NonFiniteError.
TensorNet complete_admissible_load(const TensorNet& load);

/// Proposition 2, eq. (37): with p = sum p_ij/(i! j!) u^i v^j the factorial-power form of the
/// load, the load is admissible iff for m in {n-1, n} and i = 0..n
///   p_{i,m} = (1/K) sum_{l=1}^{K-1} (-1)^(l-1) (K-l) p_{i+2l, m-2l},  K = floor((n-i)/2),
/// and the same with the indices swapped (K = 0 reads p_{i,m} = 0; never divides by zero).
/// Returns max |lhs - rhs| over all those equations and the 3 coordinates, divided by the
/// largest rounding scale of those equations (sum of |terms|, each |p_ij| bounded by
/// i! j! (|M| |R| |M|^T)_ij with M the Bernstein-to-power matrix); 0 for the zero load.
/// Admissible loads give ~1e-15..1e-12; a generic net gives O(1e-3..1). Goes through the power
/// basis: meaningful up to n ~ 15.
double admissibility_defect(const TensorNet& load);

}  // namespace bpde
