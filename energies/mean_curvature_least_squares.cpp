#include "bezierpde/energies/mean_curvature_least_squares.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <ceres/jet.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/columns3.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"

namespace bpde {
namespace {

// r = √(w |N|) (H_x − H) from the jet (x_u, x_v, x_uu, x_uv, x_vv) = j[0..14]; N = x_u ∧ x_v and
// H_x = (⟨x_uu,N⟩G − 2⟨x_uv,N⟩F + ⟨x_vv,N⟩E) / (2|N|³) (core/differential_geometry.h, with the
// unit normal written as N/|N|).
template <class T>
T residual_from_jet(const T* j, double H, double w) {
  using std::sqrt;
  const T* xu = j;
  const T* xv = j + 3;
  const T N[3] = {xu[1] * xv[2] - xu[2] * xv[1], xu[2] * xv[0] - xu[0] * xv[2], xu[0] * xv[1] - xu[1] * xv[0]};
  auto dot = [](const T* a, const T* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const T n2 = dot(N, N), nn = sqrt(n2);
  const T E = dot(xu, xu), F = dot(xu, xv), G = dot(xv, xv);
  const T e = dot(j + 6, N), f = dot(j + 9, N), g = dot(j + 12, N);
  const T Hx = (e * G - 2.0 * f * F + g * E) / (2.0 * n2 * nn);
  return sqrt(w * nn) * (Hx - H);
}

// The rule's weights times the corner weight ρ = Π_c (1 − λ_c^8)^4 (mean_curvature_least_squares.h):
// λ_c the barycentric coordinates (u, v, 1 - u - v) on the triangle, the bilinear corner
// functions on the square.
Eigen::VectorXd weighted(const QuadratureRuleTriangle& rule, bool square) {
  Eigen::VectorXd w = rule.w;
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    const double u = rule.uv(i, 0), v = rule.uv(i, 1);
    const std::array<double, 4> lambda =
        square ? std::array<double, 4>{(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v}
               : std::array<double, 4>{u, v, 1.0 - u - v, 0.0};
    for (int c = 0; c < (square ? 4 : 3); ++c) {
      const double l2 = lambda[size_t(c)] * lambda[size_t(c)], l8 = (l2 * l2) * (l2 * l2);
      const double f = 1.0 - l8, f2 = f * f;
      w(i) *= f2 * f2;
    }
  }
  return w;
}

// A regular node: |x_u ∧ x_v| > 1e-14 |x_u||x_v| (a singular one contributes r = 0). Not finite
// derivatives are neither (their node gets r = NaN, so Φ is NaN, never a silent 0).
bool singular(const Eigen::Vector3d& xu, const Eigen::Vector3d& xv) {
  return xu.allFinite() && xv.allFinite() && !(xu.cross(xv).norm() > 1e-14 * xu.norm() * xv.norm());
}

// The rule with the corner weight, after the degree and q checks (the rule checks q <= 200).
QuadratureRuleTriangle checked_rule(bool square, int n, int m, int q, Eigen::VectorXd& w) {
  if (n < 2 || m < 2 || n > kMaxDegree || m > kMaxDegree)
    throw DegreeError(std::string("mean-curvature least squares: ") + (square ? "tensor degrees" : "triangular degree") +
                      " must be in 2.." + std::to_string(kMaxDegree));
  if (q < 2) throw ParameterError("mean-curvature least squares: q must be >= 2");
  const QuadratureRuleTriangle rule = square ? corner_collapsed_square_rule(q) : corner_collapsed_triangle_rule(q);
  w = weighted(rule, square);
  return rule;
}

}  // namespace

MeanCurvatureLeastSquares MeanCurvatureLeastSquares::triangular(int n, int q) {
  MeanCurvatureLeastSquares f;
  f.q_ = q;
  const QuadratureRuleTriangle rule = checked_rule(false, n, n, q, f.w_);
  const int du[5] = {1, 0, 2, 1, 0}, dv[5] = {0, 1, 0, 1, 2};
  for (size_t t = 0; t < 5; ++t) f.D_[t] = triangular_basis_table(n, rule.uv, du[t], dv[t]);
  return f;
}

MeanCurvatureLeastSquares MeanCurvatureLeastSquares::tensor(int n, int m, int q) {
  MeanCurvatureLeastSquares f;
  f.q_ = q;
  const QuadratureRuleTriangle rule = checked_rule(true, n, m, q, f.w_);
  const Eigen::VectorXd us = rule.uv.col(0), vs = rule.uv.col(1);
  std::array<Eigen::MatrixXd, 3> U, V;
  for (int d = 0; d <= 2; ++d) {
    U[size_t(d)] = bernstein_table(n, us, d);
    V[size_t(d)] = bernstein_table(m, vs, d);
  }
  const int du[5] = {1, 0, 2, 1, 0}, dv[5] = {0, 1, 0, 1, 2};
  for (size_t t = 0; t < 5; ++t) {
    f.D_[t].resize(rule.w.size(), (n + 1) * (m + 1));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j)
        f.D_[t].col(i * (m + 1) + j) = U[size_t(du[t])].col(i).cwiseProduct(V[size_t(dv[t])].col(j));
  }
  return f;
}

MeanCurvatureLeastSquares::NodeDerivatives MeanCurvatureLeastSquares::derivatives(const Eigen::MatrixX3d& P) const {
  if (P.rows() != size()) throw SizeError("mean-curvature least squares: the net has the wrong number of points");
  NodeDerivatives X;
  // Three matrix-vector products per table (core/columns3.h), not a GEMM that packs the
  // #nodes x #points table on every call for three columns.
  for (size_t t = 0; t < 5; ++t) X[t] = times(D_[t], P);
  return X;
}

double MeanCurvatureLeastSquares::node_residual(const NodeDerivatives& X, Eigen::Index q, double H,
                                                Eigen::Matrix<double, 15, 1>* dr) const {
  if (singular(X[0].row(q).transpose(), X[1].row(q).transpose())) {
    if (dr) dr->setZero();
    return 0.0;
  }
  if (dr) {
    using Jet = ceres::Jet<double, 15>;
    Jet jet[15];
    for (int t = 0; t < 5; ++t)
      for (int c = 0; c < 3; ++c) jet[3 * t + c] = Jet(X[size_t(t)](q, c), 3 * t + c);
    const Jet v = residual_from_jet(jet, H, w_(q));
    *dr = v.v;
    return v.a;
  }
  double jet[15];
  for (int t = 0; t < 5; ++t)
    for (int c = 0; c < 3; ++c) jet[3 * t + c] = X[size_t(t)](q, c);
  return residual_from_jet(jet, H, w_(q));
}

Eigen::VectorXd MeanCurvatureLeastSquares::h_derivative(const NodeDerivatives& X) const {
  Eigen::VectorXd d(nodes());
  for (Eigen::Index q = 0; q < nodes(); ++q) {
    const Eigen::Vector3d xu = X[0].row(q).transpose(), xv = X[1].row(q).transpose();
    d(q) = singular(xu, xv) ? 0.0 : -std::sqrt(w_(q) * xu.cross(xv).norm());
  }
  return d;
}

void MeanCurvatureLeastSquares::residuals(const Eigen::MatrixX3d& P, double H, Eigen::VectorXd* r,
                                          const std::vector<int>* idx, Eigen::MatrixXd* J, Eigen::VectorXd* dH) const {
  if (P.rows() != size()) throw SizeError("mean-curvature least squares: the net has the wrong number of points");
  if (J && !idx) throw ParameterError("mean-curvature least squares: the Jacobian needs the list of points idx");
  if (idx)
    for (int i : *idx)
      if (i < 0 || i >= size())
        throw ParameterError("mean-curvature least squares: point index " + std::to_string(i) + " out of range");
  const Eigen::Index M = nodes();
  const NodeDerivatives X = derivatives(P);
  Eigen::MatrixXd dr;
  if (J) dr.resize(M, 15);
  if (r) r->resize(M);
  Eigen::Matrix<double, 15, 1> d;
  for (Eigen::Index q = 0; q < M; ++q) {
    const double v = node_residual(X, q, H, J ? &d : nullptr);
    if (r) (*r)(q) = v;
    if (J) dr.row(q) = d.transpose();
  }
  if (dH) *dH = h_derivative(X);
  if (!J) return;
  const std::vector<int>& ix = *idx;
  J->setZero(M, 3 * Eigen::Index(ix.size()));
  for (size_t a = 0; a < ix.size(); ++a)
    for (int t = 0; t < 5; ++t)
      for (int c = 0; c < 3; ++c)
        J->col(3 * Eigen::Index(a) + c) += dr.col(3 * t + c).cwiseProduct(D_[size_t(t)].col(ix[a]));
}

double MeanCurvatureLeastSquares::value(const Eigen::MatrixX3d& P, double H) const {
  Eigen::VectorXd r;
  residuals(P, H, &r);
  return r.squaredNorm();
}

}  // namespace bpde
