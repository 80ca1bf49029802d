#pragma once
// Bernstein polynomials on [0,1]: basis values, derivative and elevation operators, exact product
// integrals, and conversion to and from the power basis.
//
// Convention: B_i^n(t) = C(n,i) t^i (1-t)^(n-i), i = 0..n. A coefficient vector p (length n+1)
// represents f(t) = sum_i p_i B_i^n(t). Every operator below acts on such vectors (or on the rows
// of an (n+1) x k matrix, one column per coordinate).
//
// These are the building blocks that every net (tensor/, triangular/) and every energy
// (energies/) reuses. Binomials: core/binomial.h; other precisions: core/bernstein_ops.h.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

namespace bpde {

/// Largest degree accepted in files and by the net constructors (FORMATS.md: 1 <= degree <= 64).
inline constexpr int kMaxDegree = 64;

/// binomial<double>(n, k) of core/binomial.h (0 if k < 0 or k > n): exact for n <= 56, relative
/// error below n ulp up to n = 1024 (Pascal's triangle in double, positive additions only).
double binomial(int n, int k);

/// n! as a double (exact for n <= 22).
double factorial(int n);

/// Values B_0^n(t) .. B_n^n(t) written to out[0..n], by the stable (all-positive) recurrence
/// B_i^k = (1-t) B_i^(k-1) + t B_(i-1)^(k-1). O(n^2) but exact partition of unity to rounding.
void bernstein_values(int n, double t, double* out);

/// #t by (n+1) table whose entry (s, i) is the d-th derivative of B_i^n at t(s). Zero for d > n.
Eigen::MatrixXd bernstein_table(int n, const Eigen::VectorXd& t, int d = 0);

/// (n-d+1) by (n+1) matrix D with (D p) the Bernstein coefficients (degree n-d) of the d-th
/// derivative of sum p_i B_i^n. Requires 0 <= d <= n.
Eigen::MatrixXd bernstein_derivative_operator(int n, int d);

/// (n+r+1) by (n+1) matrix E with (E p) the coefficients of the same polynomial at degree n+r.
Eigen::MatrixXd bernstein_elevation_operator(int n, int r);

/// (n+1) by (m+1) matrix of exact integrals  int_0^1 B_i^n(t) B_j^m(t) dt
///   = C(n,i) C(m,j) / ((n+m+1) C(n+m, i+j)).
Eigen::MatrixXd bernstein_product_integrals(int n, int m);

/// (n+1) by (n+1) matrix of exact integrals  int_0^1 (B_i^n)^(a)(t) (B_j^n)^(b)(t) dt,
/// built as D_a^T * bernstein_product_integrals(n-a, n-b) * D_b. Zero matrix if a > n or b > n.
Eigen::MatrixXd bernstein_derivative_integrals(int n, int a, int b);

/// (n+1) by (n+1) matrix M with c = M p the monomial coefficients (f = sum_k c_k t^k) of the
/// Bernstein coefficients p:  M(k, i) = (-1)^(k-i) C(n,k) C(k,i) for i <= k.
/// Conditioning grows like 2^n-3^n: see docs/accuracy.md for the measured round-trip error.
Eigen::MatrixXd bernstein_to_power_matrix(int n);

/// Inverse of bernstein_to_power_matrix: p_i = sum_{k<=i} C(i,k)/C(n,k) c_k.
Eigen::MatrixXd power_to_bernstein_matrix(int n);

}  // namespace bpde
