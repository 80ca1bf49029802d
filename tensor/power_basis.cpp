#include "tensor/power_basis.h"

#include "core/bernstein.h"
#include "core/errors.h"

#include <string>

namespace bpde {
namespace {

// Apply (Mu kron Mv) to each coordinate of a row-major (n+1)(m+1) layout.
Eigen::MatrixX3d apply_tensor(const Eigen::MatrixXd& Mu, const Eigen::MatrixXd& Mv, const Eigen::MatrixX3d& X,
                              int n, int m) {
  Eigen::MatrixX3d out(X.rows(), 3);
  using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  for (int c = 0; c < 3; ++c) {
    const Eigen::Map<const RowMat> Xc(X.col(c).data(), n + 1, m + 1);
    Eigen::Map<RowMat>(out.col(c).data(), n + 1, m + 1) = Mu * Xc * Mv.transpose();
  }
  return out;
}

}  // namespace

Eigen::MatrixX3d to_power(const TensorNet& net) {
  return apply_tensor(bernstein_to_power_matrix(net.n()), bernstein_to_power_matrix(net.m()), net.points(), net.n(),
                      net.m());
}

namespace {
void check_rows(const TensorNet& shape, const Eigen::MatrixX3d& c, const char* what) {
  if (c.rows() != shape.size())
    throw SizeError(std::string(what) + ": degree [" + std::to_string(shape.n()) + ", " + std::to_string(shape.m()) +
                    "] needs " + std::to_string(shape.size()) + " coefficients, got " + std::to_string(c.rows()));
}
}  // namespace

TensorNet from_power(int n, int m, const Eigen::MatrixX3d& c) {
  TensorNet shape(n, m);  // validates degrees
  check_rows(shape, c, "from_power");
  return TensorNet(n, m, apply_tensor(power_to_bernstein_matrix(n), power_to_bernstein_matrix(m), c, n, m));
}

Eigen::MatrixX3d to_factorial_power(const TensorNet& net) {
  Eigen::MatrixX3d a = to_power(net);
  for (int k = 0; k <= net.n(); ++k)
    for (int l = 0; l <= net.m(); ++l) a.row(net.index(k, l)) *= factorial(k) * factorial(l);
  return a;
}

TensorNet from_factorial_power(int n, int m, const Eigen::MatrixX3d& a) {
  TensorNet shape(n, m);
  check_rows(shape, a, "from_factorial_power");
  Eigen::MatrixX3d c = a;
  for (int k = 0; k <= n; ++k)
    for (int l = 0; l <= m; ++l) c.row(shape.index(k, l)) /= factorial(k) * factorial(l);
  return from_power(n, m, c);
}

}  // namespace bpde
