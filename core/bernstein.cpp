#include "bezierpde/core/bernstein.h"

#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include "bezierpde/core/bernstein_ops.h"
#include "bezierpde/core/binomial.h"
#include "bezierpde/core/errors.h"

namespace bpde {

void bernstein_values(int n, double t, double* out) {
  const double s = 1.0 - t;
  out[0] = 1.0;
  for (int k = 1; k <= n; ++k) {
    double prev = 0.0;  // B_{i-1}^{k-1}
    for (int i = 0; i < k; ++i) {
      const double cur = out[i];
      out[i] = s * cur + t * prev;
      prev = cur;
    }
    out[k] = t * prev;
  }
}

Eigen::MatrixXd bernstein_table(int n, const Eigen::VectorXd& t, int d) {
  if (d > n || d < 0) return Eigen::MatrixXd::Zero(t.size(), n + 1);
  // d-th derivative of B_i^n: n!/(n-d)! * sum_k (-1)^(d-k) C(d,k) B_{i-k}^{n-d}.
  // The degree q = n-d values come from the product form C(q,j) t^j (1-t)^(q-j), accurate to
  // (q+2) ulp relative (all factors positive). The powers are built a column (one power, all
  // points) at a time, so the loops vectorise over the points: this table feeds every grid
  // evaluation.
  const int q = n - d;
  const Eigen::Index N = t.size();
  Eigen::ArrayXXd tp(N, q + 1), sp(N, q + 1);
  tp.col(0).setOnes();
  sp.col(0).setOnes();
  const Eigen::ArrayXd x = t.array(), y = 1.0 - t.array();
  for (int j = 1; j <= q; ++j) {
    tp.col(j) = tp.col(j - 1) * x;
    sp.col(j) = sp.col(j - 1) * y;
  }
  Eigen::MatrixXd table(N, n + 1);
  if (d == 0) {
    for (int j = 0; j <= q; ++j) table.col(j) = binomial(q, j) * (tp.col(j) * sp.col(q - j)).matrix();
    return table;
  }
  table.setZero();
  const double scale = factorial(n) / factorial(q);
  for (int j = 0; j <= q; ++j) {
    const Eigen::ArrayXd low = binomial(q, j) * tp.col(j) * sp.col(q - j);
    for (int k = 0; k <= d; ++k)
      table.col(j + k).array() += scale * (((d - k) % 2 == 0) ? 1.0 : -1.0) * binomial(d, k) * low;
  }
  return table;
}

Eigen::MatrixXd bernstein_derivative_operator(int n, int d) {
  if (d < 0 || d > n) throw DegreeError("bernstein_derivative_operator: need 0 <= d <= n");
  return rm_to_matrix<double>(derivative_operator_rm<double>(n, d), n - d + 1, n + 1);
}

Eigen::MatrixXd bernstein_elevation_operator(int n, int r) {
  if (n < 0 || r < 0) throw DegreeError("bernstein_elevation_operator: negative degree");
  return rm_to_matrix<double>(elevation_operator_rm<double>(n, r), n + r + 1, n + 1);
}

Eigen::MatrixXd bernstein_product_integrals(int n, int m) {
  Eigen::MatrixXd G(n + 1, m + 1);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) G(i, j) = binomial(n, i) * binomial(m, j) / ((n + m + 1) * binomial(n + m, i + j));
  return G;
}

Eigen::MatrixXd bernstein_derivative_integrals(int n, int a, int b) {
  if (a > n || b > n) return Eigen::MatrixXd::Zero(n + 1, n + 1);
  return bernstein_derivative_operator(n, a).transpose() * bernstein_product_integrals(n - a, n - b) *
         bernstein_derivative_operator(n, b);
}

Eigen::MatrixXd bernstein_to_power_matrix(int n) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i <= k; ++i) M(k, i) = (((k - i) % 2 == 0) ? 1.0 : -1.0) * binomial(n, k) * binomial(k, i);
  return M;
}

Eigen::MatrixXd power_to_bernstein_matrix(int n) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= i; ++k) M(i, k) = binomial(i, k) / binomial(n, k);
  return M;
}

}  // namespace bpde
