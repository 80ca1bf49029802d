#include "bezierpde/solvers/blend/bfs_element.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"

namespace bpde {

std::array<double, 4> hermite_cubic(double t, int r) {
  switch (r) {
    case 0:
      return {1 - 3 * t * t + 2 * t * t * t, t - 2 * t * t + t * t * t, 3 * t * t - 2 * t * t * t, -t * t + t * t * t};
    case 1:
      return {-6 * t + 6 * t * t, 1 - 4 * t + 3 * t * t, 6 * t - 6 * t * t, -2 * t + 3 * t * t};
    case 2:
      return {-6 + 12 * t, -4 + 6 * t, 6 - 12 * t, -2 + 6 * t};
    case 3:
      return {12, 6, -12, 6};
    default:
      if (r < 0) throw ParameterError("hermite_cubic: derivative order must be >= 0");
      return {0, 0, 0, 0};
  }
}

BfsSpace::BfsSpace(int k, int l) : k_(k), l_(l) {
  if (k < 1 || l < 1 || k > kMaxPartition || l > kMaxPartition)
    throw ParameterError("BFS partition: k and l must be in 1.." + std::to_string(kMaxPartition) + " (got " +
                         std::to_string(k) + " x " + std::to_string(l) + ")");
}

void BfsSpace::locate(double x, double y, int& i, int& j, double& t, double& s) const {
  if (!std::isfinite(x) || !std::isfinite(y) || x < -1e-12 || x > 1 + 1e-12 || y < -1e-12 || y > 1 + 1e-12)
    throw ParameterError("BFS evaluation: point (" + std::to_string(x) + ", " + std::to_string(y) +
                         ") is outside [0,1]^2");
  x = std::clamp(x, 0.0, 1.0);
  y = std::clamp(y, 0.0, 1.0);
  i = std::min(static_cast<int>(std::floor(x * k_)), k_ - 1);
  j = std::min(static_cast<int>(std::floor(y * l_)), l_ - 1);
  t = x * k_ - i;
  s = y * l_ - j;
}

std::array<int, 16> BfsSpace::element_dofs(int i, int j) const {
  std::array<int, 16> idx{};
  for (int di = 0; di < 2; ++di)
    for (int dj = 0; dj < 2; ++dj)
      for (int d = 0; d < 4; ++d) idx[4 * (2 * di + dj) + d] = dof(i + di, j + dj, d);
  return idx;
}

namespace {

/// Values of the 16 local basis functions at reference (t, s), derivative orders (rx, ry) with
/// respect to x and y (the chain-rule factors hx^-rx hy^-ry included).
std::array<double, 16> local_basis(double t, double s, int rx, int ry, double hx, double hy) {
  const auto Hx = hermite_cubic(t, rx), Hy = hermite_cubic(s, ry);
  const double fx = std::pow(hx, -rx), fy = std::pow(hy, -ry);
  std::array<double, 16> v{};
  for (int di = 0; di < 2; ++di)
    for (int dj = 0; dj < 2; ++dj)
      for (int d = 0; d < 4; ++d) {
        const int p = d & 1, q = d >> 1;
        const double bx = (p ? hx : 1.0) * Hx[2 * di + p] * fx;
        const double by = (q ? hy : 1.0) * Hy[2 * dj + q] * fy;
        v[4 * (2 * di + dj) + d] = bx * by;
      }
  return v;
}

}  // namespace

void BfsSpace::basis_at(double x, double y, int dx, int dy, std::array<int, 16>& index,
                        std::array<double, 16>& value) const {
  if (dx < 0 || dy < 0) throw ParameterError("BFS evaluation: derivative orders must be >= 0");
  int i, j;
  double t, s;
  locate(x, y, i, j, t, s);
  index = element_dofs(i, j);
  value = local_basis(t, s, dx, dy, hx(), hy());
}

Eigen::Matrix<double, 16, 16> BfsSpace::element_form(const SecondOrderForm& form) const {
  const QuadratureRule1D g = gauss_legendre01(4);
  Eigen::Matrix<double, 16, 16> K = Eigen::Matrix<double, 16, 16>::Zero();
  const double area = hx() * hy();
  for (int a = 0; a < g.x.size(); ++a)
    for (int b = 0; b < g.x.size(); ++b) {
      const double w = g.w(a) * g.w(b) * area;
      const auto bxx = local_basis(g.x(a), g.x(b), 2, 0, hx(), hy());
      const auto bxy = local_basis(g.x(a), g.x(b), 1, 1, hx(), hy());
      const auto byy = local_basis(g.x(a), g.x(b), 0, 2, hx(), hy());
      const Eigen::Map<const Eigen::Matrix<double, 16, 1>> vxx(bxx.data()), vxy(bxy.data()), vyy(byy.data());
      K.noalias() += w * (form.c_xx * vxx * vxx.transpose() + form.c_xy * vxy * vxy.transpose() +
                          form.c_yy * vyy * vyy.transpose());
    }
  return K;
}

Eigen::Matrix<double, 48, 16> BfsSpace::element_form_factor(const SecondOrderForm& form) const {
  if (!(form.c_xx >= 0 && form.c_xy >= 0 && form.c_yy >= 0))
    throw ParameterError("BfsSpace::element_form_factor: the coefficients of the form must be >= 0");
  const QuadratureRule1D g = gauss_legendre01(4);
  Eigen::Matrix<double, 48, 16> B;
  const double area = hx() * hy();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b) {
      const int q = 4 * a + b;
      const double w = g.w(a) * g.w(b) * area;
      const auto bxx = local_basis(g.x(a), g.x(b), 2, 0, hx(), hy());
      const auto bxy = local_basis(g.x(a), g.x(b), 1, 1, hx(), hy());
      const auto byy = local_basis(g.x(a), g.x(b), 0, 2, hx(), hy());
      const double sxx = std::sqrt(w * form.c_xx), sxy = std::sqrt(w * form.c_xy), syy = std::sqrt(w * form.c_yy);
      for (int c = 0; c < 16; ++c) {
        B(3 * q, c) = sxx * bxx[c];
        B(3 * q + 1, c) = sxy * bxy[c];
        B(3 * q + 2, c) = syy * byy[c];
      }
    }
  return B;
}

namespace {

// Summed in place into the final pattern (each dof couples with the 4 dofs of the at most 9 nodes
// around its own: 36 entries per column reserved), not through a triplet list of 256 entries per
// element, which at 128 x 128 elements took 67 MB plus the same again to sort it.
Eigen::SparseMatrix<double> assemble_uniform(const BfsSpace& V, const Eigen::Matrix<double, 16, 16>& K) {
  Eigen::SparseMatrix<double> R(V.num_dofs(), V.num_dofs());
  R.reserve(Eigen::VectorXi::Constant(V.num_dofs(), 36));
  for (int i = 0; i < V.k(); ++i)
    for (int j = 0; j < V.l(); ++j) {
      const auto idx = V.element_dofs(i, j);
      for (int c = 0; c < 16; ++c)
        for (int r = 0; r < 16; ++r) R.coeffRef(idx[r], idx[c]) += K(r, c);
    }
  R.makeCompressed();
  return R;
}

}  // namespace

Eigen::SparseMatrix<double> BfsSpace::assemble_form(const SecondOrderForm& form) const {
  return assemble_uniform(*this, element_form(form));
}

Eigen::SparseMatrix<double> BfsSpace::assemble_mass() const {
  const QuadratureRule1D g = gauss_legendre01(4);
  Eigen::Matrix<double, 16, 16> M = Eigen::Matrix<double, 16, 16>::Zero();
  for (int a = 0; a < g.x.size(); ++a)
    for (int b = 0; b < g.x.size(); ++b) {
      const auto v = local_basis(g.x(a), g.x(b), 0, 0, hx(), hy());
      const Eigen::Map<const Eigen::Matrix<double, 16, 1>> m(v.data());
      M.noalias() += g.w(a) * g.w(b) * hx() * hy() * m * m.transpose();
    }
  return assemble_uniform(*this, M);
}

Eigen::MatrixX3d BfsSpace::assemble_load(const std::function<Eigen::Vector3d(double, double)>& f, int q) const {
  const QuadratureRule1D g = gauss_legendre01(q);
  Eigen::MatrixX3d F = Eigen::MatrixX3d::Zero(num_dofs(), 3);
  std::vector<std::array<double, 16>> tab;
  for (int a = 0; a < q; ++a)
    for (int b = 0; b < q; ++b) tab.push_back(local_basis(g.x(a), g.x(b), 0, 0, hx(), hy()));
  for (int i = 0; i < k_; ++i)
    for (int j = 0; j < l_; ++j) {
      const auto idx = element_dofs(i, j);
      for (int a = 0; a < q; ++a)
        for (int b = 0; b < q; ++b) {
          const Eigen::Vector3d fv = f((i + g.x(a)) * hx(), (j + g.x(b)) * hy());
          if (!fv.allFinite())
            throw NonFiniteError("BFS load: f is not finite at (" + std::to_string((i + g.x(a)) * hx()) + ", " +
                                 std::to_string((j + g.x(b)) * hy()) + ")");
          const double w = g.w(a) * g.w(b) * hx() * hy();
          const auto& v = tab[a * q + b];
          for (int r = 0; r < 16; ++r) F.row(idx[r]) += (w * v[r]) * fv.transpose();
        }
    }
  return F;
}

Eigen::Vector3d BfsSpace::evaluate(const Eigen::MatrixX3d& coefficients, double x, double y, int dx, int dy) const {
  if (coefficients.rows() != num_dofs())
    throw SizeError("BFS evaluation: " + std::to_string(coefficients.rows()) + " coefficient rows, expected " +
                    std::to_string(num_dofs()));
  std::array<int, 16> idx;
  std::array<double, 16> val;
  basis_at(x, y, dx, dy, idx, val);
  Eigen::Vector3d r = Eigen::Vector3d::Zero();
  for (int c = 0; c < 16; ++c) r += val[c] * coefficients.row(idx[c]).transpose();
  return r;
}

Eigen::MatrixX3d BfsSpace::interpolate(const std::function<Eigen::Matrix<double, 4, 3>(double, double)>& jet) const {
  Eigen::MatrixX3d C(num_dofs(), 3);
  for (int i = 0; i <= k_; ++i)
    for (int j = 0; j <= l_; ++j) {
      const Eigen::Matrix<double, 4, 3> J = jet(i * hx(), j * hy());
      for (int d = 0; d < 4; ++d) C.row(dof(i, j, d)) = J.row(d);
    }
  return C;
}

BfsSpace::BSplineForm BfsSpace::to_bspline(const Eigen::MatrixX3d& coefficients) const {
  if (coefficients.rows() != num_dofs())
    throw SizeError("BFS to_bspline: " + std::to_string(coefficients.rows()) + " coefficient rows, expected " +
                    std::to_string(num_dofs()));
  auto knots = [](int n) {
    std::vector<double> t = {0, 0, 0, 0};
    for (int i = 1; i < n; ++i) {
      t.push_back(static_cast<double>(i) / n);
      t.push_back(static_cast<double>(i) / n);
    }
    t.insert(t.end(), {1, 1, 1, 1});
    return t;
  };
  // 1D map from (node i, p) to control point index: T(I, 2i + p).
  auto hermite_to_bspline = [](int n) {
    const double h = 1.0 / n;
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(2 * n + 2, 2 * n + 2);
    for (int i = 0; i <= n; ++i) {
      T(2 * i, 2 * i) = 1;
      T(2 * i + 1, 2 * i) = 1;
      if (i > 0) T(2 * i, 2 * i + 1) = -h / 3;
      if (i < n) T(2 * i + 1, 2 * i + 1) = h / 3;
    }
    return T;
  };
  const Eigen::MatrixXd Tx = hermite_to_bspline(k_), Ty = hermite_to_bspline(l_);
  const int nx = 2 * k_ + 2, ny = 2 * l_ + 2;
  BSplineForm out;
  out.knots_x = knots(k_);
  out.knots_y = knots(l_);
  out.points = Eigen::MatrixX3d::Zero(nx * ny, 3);
  // coefficient of (i, p) x (j, q) sits at dof(i, j, p + 2q)
  for (int I = 0; I < nx; ++I)
    for (int a = 0; a < nx; ++a) {
      if (Tx(I, a) == 0) continue;
      const int i = a / 2, p = a % 2;
      for (int J = 0; J < ny; ++J)
        for (int b = 0; b < ny; ++b) {
          if (Ty(J, b) == 0) continue;
          const int j = b / 2, q = b % 2;
          out.points.row(I * ny + J) += Tx(I, a) * Ty(J, b) * coefficients.row(dof(i, j, p + 2 * q));
        }
    }
  return out;
}

}  // namespace bpde
