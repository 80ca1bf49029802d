#pragma once
// The report quantity `pde_residual` of FORMATS.md ("Results"), and the differential operator of an
// energy as a list of terms.
//
// For an operator L x = sum_k c_k d^{k} x (d^{k} = d^{du_k}/du^{du_k} d^{dv_k}/dv^{dv_k}),
//
//   pde_residual = max_grid |L x| / max_grid sum_k |c_k| |d^{k} x|,
//
// both maxima over the (N+1)^2 grid u = a/N, v = b/N (a, b = 0..N), |.| the Euclidean norm in R^3.
// Guard: the denominator is floored at 1e-8 * sum_k |c_k| n!/(n-du_k)! m!/(m-dv_k)! max|P_ij|
// (the size a k-th derivative of this net can have). Without it, a solution whose derivative
// terms all vanish exactly (a plane; the biharmonic solution at n = 3, where only x_uuvv exists
// and is 0) reads rounding noise / rounding noise = O(1). Where the terms are not negligible the
// value is exactly the FORMATS.md ratio. It is 0 when everything vanishes.
//
// Operators (energies/energy_spec.h, Arnal–Monterde–Ugail eq. (2), docs/errata.md):
//   order 4: A x_uuuu + B x_uuuv + C x_uuvv + D x_uvvv + E x_vvvv   ([A..E] = operator_coeffs())
//   order 2: a x_uu + b x_uv + c x_vv                                ([a,b,c] = second_order_coeffs();
//            the Euler–Lagrange operator is minus this, which does not change the residual)
#include <vector>

#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

/// One term c * d^{du+dv} x / du^{du} dv^{dv} of a linear differential operator.
struct PdeTerm {
  int du = 0, dv = 0;
  double c = 0.0;
};

/// The terms of the energy's Euler–Lagrange operator (zero coefficients omitted), in the order
/// (4,0),(3,1),(2,2),(1,3),(0,4) for order 4 and (2,0),(1,1),(0,2) for order 2.
std::vector<PdeTerm> pde_operator_terms(const EnergySpec& op);

/// pde_residual of the patch (see above) on the (samples+1)^2 grid. Throws ParameterError if
/// samples < 1. Uses TensorNet::evaluate_grid with derivative orders (one small matrix product per
/// term and coordinate).
double pde_residual(const TensorNet& net, const EnergySpec& op, int samples = 50);

/// The same quantity for an operator given as terms.
double pde_residual(const TensorNet& net, const std::vector<PdeTerm>& terms, int samples = 50);

/// The highest degree (per direction) at which the tensor PDE solvers (`explicit`, `lu`) deliver
/// the solution in double precision (docs/pde_accuracy.md, "Numerical limit"): rounding the
/// prescribed ring to double alone moves the interior by the data-rounding floor, 6.4e-3 of the
/// solution at n = 20 and ~30x more per degree above, so past 20 no digit of the interior is
/// determined by double data (the two methods then differ by O(1) on generic data, and
/// pde_residual is no longer small).
inline constexpr int kMaxPdeDegree = 20;

/// The check behind `converged` of the tensor PDE solvers: if `summary` says converged but the
/// degree (n, m) exceeds kMaxPdeDegree, set Status::NumericalLimit with a message naming the limit,
/// the degree and the method (the computed net is kept). Measured, not guessed: see
/// docs/pde_accuracy.md.
void check_pde_degree_limit(int n, int m, const char* method, Summary& summary);

}  // namespace bpde
