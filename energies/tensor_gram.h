#pragma once
// Exact Gram (Hessian) matrix of a quadratic energy of a tensor-product Bézier patch.
//
// An energy (energies/energy_spec.h) is  E(x) = ∫ 1/2 Σ_t w_t <∂^{a_t} x, ∂^{b_t} x>  over the
// domain. For x(u,v) = Σ_I B_I(u,v) P_I with B_I = B_i^n(u) B_j^m(v), I = i*(m+1) + j
// (FORMATS.md order), this is
//     E = 1/2 Σ_{c=x,y,z} P_c^T Q P_c,     Q = Σ_t w_t * sym(K_{a_t b_t}),   sym(K) = (K + K^T)/2,
//     K_ab[I,J] = ∫ ∂^a B_I ∂^b B_J = Ku(au,bu)[i,k] * Kv(av,bv)[j,l]   (J = k*(m+1) + l),
// i.e. K_ab = kron(Ku, Kv) with the exact 1-D integrals Ku(a,b)[i,k] = ∫_0^1 (B_i^n)^(a) (B_k^n)^(b)
// from core/bernstein.h (bernstein_derivative_integrals). No quadrature is involved.
//
// The same formula covers every FORMATS.md energy: dirichlet, second-order, biharmonic,
// laplacian-squared (with its <x_uu, x_vv> term, which is not symmetric per term: hence the sym),
// coons, modified-biharmonic, fourth-order (Sun–Zhu), gnorm (Arnal–Monterde–Ugail eq. (1), read as in
// docs/errata.md, explicit PDE solutions §2).
//
// Span scaling (for B-spline spans and other rectangles): if the patch is parametrised over
// [u0,u0+hu] x [v0,v0+hv] by the affine map u = u0 + hu*s, v = v0 + hv*t of the reference square,
// then ∂_u = ∂_s / hu, ∂_v = ∂_t / hv and du dv = hu hv ds dt, so each term is scaled by
//     hu^(1 - au - bu) * hv^(1 - av - bv).
// With hu = hv = 1 this is the Bézier patch on [0,1]^2.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

#include "bezierpde/energies/energy_spec.h"

namespace bpde {

/// Gram matrix of an energy of a degree-(n,m) tensor Bézier patch on [0,1]^2:
/// (n+1)(m+1) square, symmetric, row/column I = i*(m+1) + j. Throws DegreeError unless
/// 1 <= n, m <= kMaxDegree. Derivatives of order above the degree are zero (their terms vanish).
Eigen::MatrixXd tensor_gram(const EnergySpec& energy, int n, int m);

/// Same from an explicit list of terms, over the rectangle of side lengths hu, hv (see the header
/// comment; hu, hv > 0 and finite, ParameterError otherwise). Terms with negative derivative
/// orders throw ParameterError; non-finite weights throw NonFiniteError.
Eigen::MatrixXd tensor_gram(int n, int m, const std::vector<QuadraticTerm>& terms, double hu = 1.0, double hv = 1.0);

}  // namespace bpde
