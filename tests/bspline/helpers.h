#pragma once
// Shared helpers of the test_bspline program: random nets, exact polynomial solutions of
// constant-coefficient PDEs, and nets that represent a polynomial exactly.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <complex>
#include <functional>
#include <random>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/tensor/bspline_net.h"
#include "bezierpde/tensor/bspline_ops.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde::testing {

using Field = std::function<Eigen::Vector3d(double, double)>;

inline std::vector<double> clamped(int k, std::vector<double> interior, double a = 0, double b = 1) {
  std::vector<double> K(static_cast<size_t>(k + 1), a);
  K.insert(K.end(), interior.begin(), interior.end());
  K.insert(K.end(), static_cast<size_t>(k + 1), b);
  return K;
}

inline std::vector<double> uniform(int count) {
  std::vector<double> K;
  for (int i = 0; i < count; ++i) K.push_back(i);
  return K;
}

inline BSplineNet random_net(int p, int q, const std::vector<double>& U, const std::vector<double>& V, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> R(-1, 1);
  const int nu = static_cast<int>(U.size()) - p - 1, nv = static_cast<int>(V.size()) - q - 1;
  Eigen::MatrixX3d P(nu * nv, 3);
  for (int r = 0; r < P.rows(); ++r) P.row(r) << R(rng), R(rng), R(rng);
  return BSplineNet(p, q, U, V, P);
}

/// The Bézier patch of degree (n, m) on [u0,u1] x [v0,v1] that interpolates f at a Chebyshev-like
/// grid: exact (to rounding) when f is a polynomial of bidegree <= (n, m).
inline TensorNet bezier_of(const Field& f, int n, int m, double u0, double u1, double v0, double v1) {
  Eigen::VectorXd su(n + 1), sv(m + 1);
  for (int i = 0; i <= n; ++i) su(i) = 0.5 - 0.5 * std::cos(M_PI * (i + 0.5) / (n + 1));
  for (int j = 0; j <= m; ++j) sv(j) = 0.5 - 0.5 * std::cos(M_PI * (j + 0.5) / (m + 1));
  const Eigen::MatrixXd Bu = bernstein_table(n, su), Bv = bernstein_table(m, sv);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(Bu), lv(Bv);
  TensorNet net(n, m);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd F(n + 1, m + 1);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) F(i, j) = f(u0 + (u1 - u0) * su(i), v0 + (v1 - v0) * sv(j))(c);
    // F = Bu C Bv^T
    const Eigen::MatrixXd C = lv.solve(lu.solve(F).transpose()).transpose();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) net.points()(net.index(i, j), c) = C(i, j);
  }
  return net;
}

/// The B-spline net of degree (p, q) over (U, V) that represents the polynomial f exactly.
inline BSplineNet spline_of(const Field& f, int p, int q, const std::vector<double>& U, const std::vector<double>& V) {
  const int nu = static_cast<int>(U.size()) - p - 1, nv = static_cast<int>(V.size()) - q - 1;
  const double u0 = U[static_cast<size_t>(p)], u1 = U[static_cast<size_t>(nu)];
  const double v0 = V[static_cast<size_t>(q)], v1 = V[static_cast<size_t>(nv)];
  return bspline_from_bezier(bezier_of(f, p, q, u0, u1, v0, v1), u0, u1, v0, v1, p, q, U, V);
}

/// Roots of c0 + c1 x + ... + cd x^d (cd != 0) by the companion matrix.
inline std::vector<std::complex<double>> roots(const std::vector<double>& c) {
  const int d = static_cast<int>(c.size()) - 1;
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(d, d);
  for (int i = 1; i < d; ++i) M(i, i - 1) = 1.0;
  for (int i = 0; i < d; ++i) M(i, d - 1) = -c[static_cast<size_t>(i)] / c[static_cast<size_t>(d)];
  const Eigen::EigenSolver<Eigen::MatrixXd> es(M);
  std::vector<std::complex<double>> out;
  for (int i = 0; i < d; ++i) out.push_back(es.eigenvalues()(i));
  return out;
}

/// Solutions of a constant-coefficient homogeneous PDE whose characteristic polynomial in lambda
/// (f(u + lambda v) is a solution for every polynomial f) has the root lam: the real and
/// imaginary parts of (u + lam v)^k.
inline double re_power(std::complex<double> lam, int k, double u, double v) { return std::pow(u + lam * v, k).real(); }
inline double im_power(std::complex<double> lam, int k, double u, double v) { return std::pow(u + lam * v, k).imag(); }

}  // namespace bpde::testing
