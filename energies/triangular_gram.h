#pragma once
// Exact Gram matrices of quadratic energies on triangular Bézier nets, and the Bernstein tables on
// the triangle they are built from.
//
// Arnal, Lluch, Monterde (triangular CMC), Prop. 2, eqs. (2)–(4): the Dirichlet functional
//   D(x) = 1/2 ∫_T |x_u|^2 + |x_v|^2 = 1/2 sum_c P_c^T C P_c,
//   C_{I0 I} = [n!/I0!][n!/I!] / [(2n)!/(I0+I)!] * (a_1 + a_2 + 2 a_3 - b_13 - b_23),
//   a_r  = I0^r I^r / ((I0^r + I^r)(I0^r + I^r - 1)),   0 when I0^r I^r = 0      (docs/errata.md),
//   b_rs = (I0^r I^s + I0^s I^r) / ((I0^r + I^r)(I0^s + I^s)), 0 when its numerator is 0.
// The production route does not use the closed form: it builds every Gram from derivative nets
// and the exact product integral on T (below); dirichlet_gram_closed_form is kept as the paper's
// formula and is tested against it.
//
// Conventions (triangular/triangular_net.h, FORMATS.md): x(u,v) = sum_{|I|=n} P_I B_I^n(u,v,w),
// w = 1-u-v, B_I^n = n!/(i!j!k!) u^i v^j w^k; the third index belongs to w. Rows/columns of every
// matrix below follow the barycentric order of TriangularNet (i from n down to 0, then j from n-i
// down to 0): row of (i,j,k) = s(s+1)/2 + (s-j), s = n-i. Derivatives are with respect to the two
// free parameters u and v (w = 1-u-v), so d/du B_I^n = n (B_{I-e1}^{n-1} - B_{I-e3}^{n-1}).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <array>
#include <vector>

#include "bezierpde/energies/energy_spec.h"

namespace bpde {

/// Multi-indices (i, j, k) of a degree-n triangular net in barycentric (row) order.
std::vector<std::array<int, 3>> triangular_multi_indices(int n);

/// count(n-du-dv) by count(n) matrix D with (D P) the control points of d^{du+dv}x/du^du dv^dv
/// (degree n-du-dv). A zero-row matrix when du+dv > n. Requires du, dv >= 0.
Eigen::MatrixXd triangular_derivative_operator(int n, int du, int dv);

/// count(p) by count(q) matrix of exact integrals  ∫_T B_J^p B_K^q du dv
///   = [p!/J!][q!/K!] / [(p+q)!/(J+K)!] / ((p+q+1)(p+q+2)).
Eigen::MatrixXd triangular_product_integrals(int p, int q);

/// count(n) by count(n) matrix K with K(I,J) = ∫_T d^a B_I^n * d^b B_J^n, a = (au, av),
/// b = (bu, bv): D_a^T * triangular_product_integrals(n-|a|, n-|b|) * D_b. Not symmetric in
/// general; zero when |a| > n or |b| > n.
Eigen::MatrixXd triangular_derivative_integrals(int n, int au, int av, int bu, int bv);

/// Gram (Hessian per coordinate) Q = sum_t w_t sym(K_{a_t b_t}) of the energy
/// E = ∫_T 1/2 sum_t w_t <d^a x, d^b x>  (energies/energy_spec.h), so E = 1/2 sum_c P_c^T Q P_c.
/// Exact (rational arithmetic in doubles). Throws DegreeError unless 1 <= n <= kMaxDegree.
Eigen::MatrixXd triangular_gram(int n, const std::vector<QuadraticTerm>& terms);
Eigen::MatrixXd triangular_gram(int n, const EnergySpec& energy);

/// Dirichlet Gram C of triangular CMC eq. (2): C(I,J) = ∫_T (B_I)_u (B_J)_u + (B_I)_v (B_J)_v.
Eigen::MatrixXd triangular_dirichlet_gram(int n);

/// The same matrix from the paper's closed form, eqs. (3)–(4), with the case split of
/// docs/errata.md (triangular CMC eq. (2)–(4)).
Eigen::MatrixXd dirichlet_gram_closed_form(int n);

/// #uv by count(n) table of d^{du+dv} B_I^n / du^du dv^dv at the parameter points (rows (u,v)).
Eigen::MatrixXd triangular_basis_table(int n, const Eigen::MatrixX2d& uv, int du = 0, int dv = 0);

}  // namespace bpde
