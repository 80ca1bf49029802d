#include "bezierpde/tensor/power_basis.h"

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/keyed_cache.h"
#include "bezierpde/core/row_major_product.h"

#include <string>

namespace bpde {
namespace {

// Apply (Mu kron Mv) to each coordinate of a row-major (n+1)(m+1) layout: out_c = Mu X_c Mv^T,
// two small row-major products per coordinate (core/row_major_product.h).
Eigen::MatrixX3d apply_tensor(const Eigen::MatrixXd& Mu, const Eigen::MatrixXd& Mv, const Eigen::MatrixX3d& X, int n,
                              int m) {
  Eigen::MatrixX3d out(X.rows(), 3);
  using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const RowMat MuR = Mu;  // (n+1) x (n+1) row-major
  // Mv^T read row-major is Mv's column-major storage.
  RowMat Y(n + 1, m + 1);
  for (int c = 0; c < 3; ++c) {
    row_major_product(MuR.data(), n + 1, n + 1, n + 1, X.col(c).data(), m + 1, m + 1, Y.data(), m + 1);
    row_major_product(Y.data(), n + 1, m + 1, m + 1, Mv.data(), m + 1, m + 1, out.col(c).data(), m + 1);
  }
  return out;
}

struct Conversions {
  Eigen::MatrixXd to, from;  // F M and N F^-1 (see power_basis.h)
};

// Per degree, built once (thread-safe) and kept: these matrices are on the path of every explicit
// PDE solve and of the lu route (solvers/pde/pde_lu.h).
const Conversions& conversions(int n) {
  static DegreeCache<Conversions> cache;  // holds every degree: the reference stays valid
  return *cache.get(
      n,
      [](int d) {
        Eigen::MatrixXd to = bernstein_to_power_matrix(d), from = power_to_bernstein_matrix(d);
        for (int r = 0; r <= d; ++r) {
          to.row(r) *= factorial(r);
          from.col(r) /= factorial(r);
        }
        return Conversions{std::move(to), std::move(from)};
      },
      "power basis");
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
  return apply_tensor(conversions(net.n()).to, conversions(net.m()).to, net.points(), net.n(), net.m());
}

TensorNet from_factorial_power(int n, int m, const Eigen::MatrixX3d& a) {
  TensorNet shape(n, m);
  check_rows(shape, a, "from_factorial_power");
  return TensorNet(n, m, apply_tensor(conversions(n).from, conversions(m).from, a, n, m));
}

const Eigen::MatrixXd& bernstein_to_factorial_power_matrix(int n) { return conversions(n).to; }
const Eigen::MatrixXd& factorial_power_to_bernstein_matrix(int n) { return conversions(n).from; }

}  // namespace bpde
