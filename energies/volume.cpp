#include "energies/volume.h"

#include <Eigen/Geometry>
#include <cmath>
#include <string>

#include "core/bernstein.h"
#include "core/errors.h"
#include "core/quadrature.h"
#include "energies/triangular_gram.h"
#include "tensor/tensor_net.h"
#include "triangular/triangular_net.h"

namespace bpde {
namespace {

// Row-wise cross products of two #nodes x 3 matrices.
Eigen::MatrixX3d cross_rows(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  Eigen::MatrixX3d c(a.rows(), 3);
  c.col(0) = a.col(1).cwiseProduct(b.col(2)) - a.col(2).cwiseProduct(b.col(1));
  c.col(1) = a.col(2).cwiseProduct(b.col(0)) - a.col(0).cwiseProduct(b.col(2));
  c.col(2) = a.col(0).cwiseProduct(b.col(1)) - a.col(1).cwiseProduct(b.col(0));
  return c;
}

double multinomial(int n, int i, int j) { return binomial(n, i) * binomial(n - i, j); }

}  // namespace

VolumeForm VolumeForm::triangular(int n) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError("VolumeForm: triangular degree " + std::to_string(n) + " is outside 1.." +
                      std::to_string(kMaxDegree));
  const int q = (3 * n + 1) / 2;  // exact for total degree 2q-2 >= 3n-2
  const QuadratureRuleTriangle rule = gauss_triangle(q);
  VolumeForm f;
  f.w_ = rule.w;
  f.B_ = triangular_basis_table(n, rule.uv, 0, 0);
  f.Bu_ = triangular_basis_table(n, rule.uv, 1, 0);
  f.Bv_ = triangular_basis_table(n, rule.uv, 0, 1);
  return f;
}

VolumeForm VolumeForm::tensor(int n, int m) {
  if (n < 1 || n > kMaxDegree || m < 1 || m > kMaxDegree)
    throw DegreeError("VolumeForm: tensor degree (" + std::to_string(n) + ", " +
                      std::to_string(m) + ") is outside 1.." + std::to_string(kMaxDegree));
  // Bidegree (3n-1, 3m-1): Gauss-Legendre with q points is exact to degree 2q-1.
  const QuadratureRule1D gu = gauss_legendre01((3 * n + 1) / 2);
  const QuadratureRule1D gv = gauss_legendre01((3 * m + 1) / 2);
  const Eigen::MatrixXd Tu[2] = {bernstein_table(n, gu.x, 0), bernstein_table(n, gu.x, 1)};
  const Eigen::MatrixXd Tv[2] = {bernstein_table(m, gv.x, 0), bernstein_table(m, gv.x, 1)};
  const Eigen::Index qu = gu.x.size(), qv = gv.x.size(), N = (n + 1) * (m + 1);
  VolumeForm f;
  f.w_.resize(qu * qv);
  f.B_.resize(qu * qv, N);
  f.Bu_.resize(qu * qv, N);
  f.Bv_.resize(qu * qv, N);
  for (Eigen::Index a = 0; a < qu; ++a)
    for (Eigen::Index b = 0; b < qv; ++b) {
      const Eigen::Index s = a * qv + b;
      f.w_(s) = gu.w(a) * gv.w(b);
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= m; ++j) {
          const Eigen::Index c = i * (m + 1) + j;
          f.B_(s, c) = Tu[0](a, i) * Tv[0](b, j);
          f.Bu_(s, c) = Tu[1](a, i) * Tv[0](b, j);
          f.Bv_(s, c) = Tu[0](a, i) * Tv[1](b, j);
        }
    }
  return f;
}

std::size_t VolumeForm::memory_bytes() const {
  return sizeof(double) * static_cast<std::size_t>(w_.size() + B_.size() + Bu_.size() + Bv_.size());
}

void VolumeForm::check(const Eigen::MatrixX3d& P) const {
  if (P.rows() != B_.cols())
    throw SizeError("VolumeForm: " + std::to_string(P.rows()) + " points given, the net has " +
                    std::to_string(B_.cols()));
}

double VolumeForm::value(const Eigen::MatrixX3d& P) const {
  check(P);
  const Eigen::MatrixX3d X = B_ * P, Xu = Bu_ * P, Xv = Bv_ * P;
  const Eigen::MatrixX3d N = cross_rows(Xu, Xv);
  return w_.dot(N.cwiseProduct(X).rowwise().sum()) / 3.0;
}

double VolumeForm::value_scale(const Eigen::MatrixX3d& P) const {
  check(P);
  const Eigen::MatrixX3d X = B_ * P, Xu = Bu_ * P, Xv = Bv_ * P;
  const Eigen::MatrixX3d N = cross_rows(Xu, Xv);
  return w_.dot(N.cwiseProduct(X).rowwise().sum().cwiseAbs()) / 3.0;
}

Eigen::MatrixX3d VolumeForm::gradient(const Eigen::MatrixX3d& P) const {
  check(P);
  const Eigen::MatrixX3d X = B_ * P, Xu = Bu_ * P, Xv = Bv_ * P;
  const Eigen::MatrixX3d a = w_.asDiagonal() * cross_rows(Xv, X);
  const Eigen::MatrixX3d b = w_.asDiagonal() * cross_rows(X, Xu);
  const Eigen::MatrixX3d c = w_.asDiagonal() * cross_rows(Xu, Xv);
  return (Bu_.transpose() * a + Bv_.transpose() * b + B_.transpose() * c) / 3.0;
}

Eigen::MatrixX3d VolumeForm::gradient_scale(const Eigen::MatrixX3d& P) const {
  check(P);
  const Eigen::MatrixX3d X = B_ * P, Xu = Bu_ * P, Xv = Bv_ * P;
  const Eigen::MatrixX3d a = w_.asDiagonal() * cross_rows(Xv, X).cwiseAbs();
  const Eigen::MatrixX3d b = w_.asDiagonal() * cross_rows(X, Xu).cwiseAbs();
  const Eigen::MatrixX3d c = w_.asDiagonal() * cross_rows(Xu, Xv).cwiseAbs();
  return (Bu_.cwiseAbs().transpose() * a + Bv_.cwiseAbs().transpose() * b +
          B_.cwiseAbs().transpose() * c) /
         3.0;
}

Eigen::MatrixXd VolumeForm::hessian(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  check(P);
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
  const Eigen::Index q = w_.size();
  Eigen::MatrixXd Bs(q, k), Bus(q, k), Bvs(q, k);
  for (Eigen::Index a = 0; a < k; ++a) {
    const int c = idx[static_cast<size_t>(a)];
    if (c < 0 || c >= B_.cols()) throw SizeError("VolumeForm::hessian: index out of range");
    Bs.col(a) = B_.col(c);
    Bus.col(a) = Bu_.col(c);
    Bvs.col(a) = Bv_.col(c);
  }
  const Eigen::MatrixX3d X = B_ * P, Xu = Bu_ * P, Xv = Bv_ * P;
  Eigen::MatrixXd Hs = Eigen::MatrixXd::Zero(3 * k, 3 * k);
  Eigen::MatrixXd tmp(q, k);
  for (int c = 0; c < 3; ++c) {
    // M_c(I,L) = ∫ (B_I)_v x_c (B_L)_u + (B_I)_u (x_v)_c B_L + B_I (x_u)_c (B_L)_v;  A = (M - M^T)/3.
    tmp = (w_.cwiseProduct(X.col(c))).asDiagonal() * Bus;
    Eigen::MatrixXd M = Bvs.transpose() * tmp;
    tmp = (w_.cwiseProduct(Xv.col(c))).asDiagonal() * Bs;
    M.noalias() += Bus.transpose() * tmp;
    tmp = (w_.cwiseProduct(Xu.col(c))).asDiagonal() * Bvs;
    M.noalias() += Bs.transpose() * tmp;
    const Eigen::MatrixXd A = (M - M.transpose()) / 3.0;
    // [a]_x = [[0,-a3,a2],[a3,0,-a1],[-a2,a1,0]]: component c sits at (r, s) with r, s != c.
    const int r = (c + 2) % 3, s = (c + 1) % 3;  // [a]_x(r,s) = +a_c when (r,s) = (c+2, c+1)
    for (Eigen::Index I = 0; I < k; ++I)
      for (Eigen::Index L = 0; L < k; ++L) {
        Hs(3 * I + r, 3 * L + s) += A(I, L);
        Hs(3 * I + s, 3 * L + r) -= A(I, L);
      }
  }
  return Hs;
}

double volume(const TriangularNet& net) {
  return VolumeForm::triangular(net.n()).value(net.points());
}

double volume(const TensorNet& net) {
  return VolumeForm::tensor(net.n(), net.m()).value(net.points());
}

double volume_coefficient(int n, const std::array<int, 3>& I, const std::array<int, 3>& J,
                          const std::array<int, 3>& K) {
  int S[3];
  for (int r = 0; r < 3; ++r) S[r] = I[r] + J[r] + K[r];
  auto d = [&](int r, int s) {
    const double num = static_cast<double>(I[r]) * J[s] - static_cast<double>(J[r]) * I[s];
    if (num == 0.0) return 0.0;
    return num / (static_cast<double>(S[r]) * S[s]);
  };
  const double ratio = multinomial(n, I[0], I[1]) * multinomial(n, J[0], J[1]) *
                       multinomial(n, K[0], K[1]) / multinomial(3 * n, S[0], S[1]);
  return ratio * (d(0, 1) + d(1, 2) - d(0, 2));
}

double volume_closed_form(int n, const Eigen::MatrixX3d& P) {
  const auto I = triangular_multi_indices(n);
  const Eigen::Index N = static_cast<Eigen::Index>(I.size());
  if (P.rows() != N) throw SizeError("volume_closed_form: wrong number of points");
  double V = 0;
  for (Eigen::Index a = 0; a < N; ++a)
    for (Eigen::Index b = 0; b < N; ++b) {
      if (a == b) continue;  // C_IIK = 0
      const Eigen::Vector3d cr = P.row(a).transpose().cross(P.row(b).transpose());
      for (Eigen::Index c = 0; c < N; ++c) {
        const double C = volume_coefficient(n, I[static_cast<size_t>(a)], I[static_cast<size_t>(b)],
                                            I[static_cast<size_t>(c)]);
        V += C * cr.dot(P.row(c).transpose());
      }
    }
  return V / 6.0;
}

}  // namespace bpde
