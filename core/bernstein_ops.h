#pragma once
// The Bernstein derivative and degree-elevation operators on [0,1], in any scalar T of
// core/scalar_types.h (double, long double, quad). The one implementation: core/bernstein.h's
// double operators, the long-double PDE matrices and the binary128 C1 systems all call these.
//
// Convention (core/bernstein.h): p (length n+1) represents sum_i p_i B_i^n(t). A matrix below is
// a dense row-major std::vector<T> (binary128 has no Eigen support) with its shape stated; the
// Eigen forms (double, long double) are the same entries.
//
//   derivative  D_{n,d}: (n-d+1) x (n+1), D(j, j+k) = n!/(n-d)! (-1)^(d-k) C(d,k), the falling
//               factorial n (n-1) .. (n-d+1) as a product in T;
//   elevation   E_{n,r}: (n+r+1) x (n+1), E(j, i) = C(n,i) C(r,j-i) / C(n+r,j) (one division);
//   at degree   T_{n,d} = E_{n-d,d} D_{n,d}: (n+1) x (n+1), the d-th derivative written back at
//               degree n; the zero matrix when d > n. Each entry is the sum over i ascending of
//               E(r,i) D(i,c), in T.
// The entries of D are integers, exact while they fit the mantissa (all n <= 64, d <= 8 in
// double); E and T carry one rounding per product and sum.
//
// Errors: DegreeError for negative degrees or orders, and for d > n in the derivative operator.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <vector>

#include "bezierpde/core/binomial.h"
#include "bezierpde/core/errors.h"

namespace bpde {

/// D_{n,d}, row-major (n-d+1) x (n+1).
template <class T>
std::vector<T> derivative_operator_rm(int n, int d) {
  if (n < 0 || d < 0 || d > n) throw DegreeError("bernstein derivative operator: need 0 <= d <= n");
  std::vector<T> D(static_cast<size_t>((n - d + 1) * (n + 1)), T(0));
  T s = 1;
  for (int k = 0; k < d; ++k) s *= T(n - k);
  for (int j = 0; j <= n - d; ++j)
    for (int k = 0; k <= d; ++k)
      D[static_cast<size_t>(j * (n + 1) + j + k)] = (((d - k) % 2) ? -s : s) * binomial<T>(d, k);
  return D;
}

/// E_{n,r}, row-major (n+r+1) x (n+1).
template <class T>
std::vector<T> elevation_operator_rm(int n, int r) {
  if (n < 0 || r < 0) throw DegreeError("bernstein elevation operator: negative degree");
  std::vector<T> E(static_cast<size_t>((n + r + 1) * (n + 1)), T(0));
  for (int j = 0; j <= n + r; ++j)
    for (int i = std::max(0, j - r); i <= std::min(n, j); ++i)
      E[static_cast<size_t>(j * (n + 1) + i)] = binomial<T>(n, i) * binomial<T>(r, j - i) / binomial<T>(n + r, j);
  return E;
}

/// T_{n,d} = E_{n-d,d} D_{n,d}, row-major (n+1) x (n+1); zero if d > n.
template <class T>
std::vector<T> derivative_at_degree_rm(int n, int d) {
  if (n < 0 || d < 0) throw DegreeError("derivative_at_degree: needs n >= 0 and d >= 0");
  const size_t n1 = static_cast<size_t>(n + 1);
  std::vector<T> out(n1 * n1, T(0));
  if (d > n) return out;
  const std::vector<T> D = derivative_operator_rm<T>(n, d), E = elevation_operator_rm<T>(n - d, d);
  const size_t nd1 = static_cast<size_t>(n - d + 1);
  for (size_t r = 0; r < n1; ++r)
    for (size_t i = 0; i < nd1; ++i) {
      const T e = E[r * nd1 + i];
      if (e == T(0)) continue;
      for (size_t c = 0; c < n1; ++c) out[r * n1 + c] += e * D[i * n1 + c];
    }
  return out;
}

/// A row-major table as a (column-major) Eigen matrix (T = double or long double).
template <class T>
Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> rm_to_matrix(const std::vector<T>& a, Eigen::Index rows,
                                                              Eigen::Index cols) {
  return Eigen::Map<const Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(a.data(), rows, cols);
}

/// T_{n,d} as an Eigen matrix (T = double or long double).
template <class T = double>
Eigen::Matrix<T, Eigen::Dynamic, Eigen::Dynamic> derivative_at_degree_matrix(int n, int d) {
  return rm_to_matrix<T>(derivative_at_degree_rm<T>(n, d), n + 1, n + 1);
}

/// Coefficients at degree n + r of the polynomial with coefficients p (degree n = p.size()-1):
/// E_{n,r} p, each entry summed over i ascending (T = double or long double).
template <class T>
Eigen::Matrix<T, Eigen::Dynamic, 1> elevate(const Eigen::Matrix<T, Eigen::Dynamic, 1>& p, int r) {
  if (r < 0) throw DegreeError("elevate: negative elevation");
  if (r == 0) return p;
  const int n = static_cast<int>(p.size()) - 1;
  Eigen::Matrix<T, Eigen::Dynamic, 1> g = Eigen::Matrix<T, Eigen::Dynamic, 1>::Zero(n + r + 1);
  for (int j = 0; j <= n + r; ++j) {
    const T den = binomial<T>(n + r, j);
    for (int i = std::max(0, j - r); i <= std::min(n, j); ++i)
      g(j) += binomial<T>(n, i) * binomial<T>(r, j - i) / den * p(i);
  }
  return g;
}

}  // namespace bpde
