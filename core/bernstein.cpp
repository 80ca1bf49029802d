#include "core/bernstein.h"

#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <vector>

#include "core/errors.h"

namespace bpde {
namespace {

constexpr int kTable = 1024;

const std::vector<double>& pascal() {
  static const std::vector<double> table = [] {
    std::vector<double> t(static_cast<size_t>(kTable + 1) * (kTable + 1), 0.0);
    for (int n = 0; n <= kTable; ++n) {
      t[static_cast<size_t>(n) * (kTable + 1)] = 1.0;
      for (int k = 1; k <= n; ++k) {
        const double a = t[static_cast<size_t>(n - 1) * (kTable + 1) + k - 1];
        const double b = (k <= n - 1) ? t[static_cast<size_t>(n - 1) * (kTable + 1) + k] : 0.0;
        t[static_cast<size_t>(n) * (kTable + 1) + k] = a + b;
      }
    }
    return t;
  }();
  return table;
}

}  // namespace

double binomial(int n, int k) {
  if (k < 0 || n < 0 || k > n) return 0.0;
  if (n > kTable) throw DegreeError("binomial: n = " + std::to_string(n) + " exceeds the table");
  return pascal()[static_cast<size_t>(n) * (kTable + 1) + k];
}

double factorial(int n) {
  // The same left-to-right products as the plain loop, tabulated (171! overflows to inf).
  static const std::array<double, 171> table = [] {
    std::array<double, 171> t{};
    t[0] = 1.0;
    for (int i = 1; i <= 170; ++i) t[static_cast<size_t>(i)] = i == 1 ? 1.0 : t[static_cast<size_t>(i - 1)] * i;
    return t;
  }();
  if (n < 0) return 1.0;
  if (n > 170) return std::numeric_limits<double>::infinity();
  return table[static_cast<size_t>(n)];
}

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
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n - d + 1, n + 1);
  const double scale = factorial(n) / factorial(n - d);
  for (int j = 0; j <= n - d; ++j)
    for (int k = 0; k <= d; ++k) {
      const double sign = ((d - k) % 2 == 0) ? 1.0 : -1.0;
      D(j, j + k) = scale * sign * binomial(d, k);
    }
  return D;
}

Eigen::MatrixXd bernstein_elevation_operator(int n, int r) {
  if (n < 0 || r < 0) throw DegreeError("bernstein_elevation_operator: negative degree");
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n + r + 1, n + 1);
  // B_i^n = sum_j C(n,i) C(r,j-i) / C(n+r,j) B_j^{n+r}
  for (int i = 0; i <= n; ++i)
    for (int j = i; j <= i + r; ++j)
      E(j, i) = binomial(n, i) * binomial(r, j - i) / binomial(n + r, j);
  return E;
}

Eigen::MatrixXd bernstein_product_integrals(int n, int m) {
  Eigen::MatrixXd G(n + 1, m + 1);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      G(i, j) = binomial(n, i) * binomial(m, j) / ((n + m + 1) * binomial(n + m, i + j));
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
    for (int i = 0; i <= k; ++i)
      M(k, i) = (((k - i) % 2 == 0) ? 1.0 : -1.0) * binomial(n, k) * binomial(k, i);
  return M;
}

Eigen::MatrixXd power_to_bernstein_matrix(int n) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int i = 0; i <= n; ++i)
    for (int k = 0; k <= i; ++k) M(i, k) = binomial(i, k) / binomial(n, k);
  return M;
}

}  // namespace bpde
