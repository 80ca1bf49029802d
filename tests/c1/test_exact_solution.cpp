// Centella et al. §4.1: the exact biharmonic solution f(u,v) = u cos(u) e^v on [0,1]^2, approximated
// from degree-7 C¹ boundary data by both C¹ methods. The paper reports max |x - f| = 2.499e-6
// (admissible load) and 9.108e-6 (tetraharmonic). This test prints our numbers (docs/c1.md)
// and checks they are of that order.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/solvers/c1/biharmonic_load.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"

namespace bpde {
namespace {

double f(double u, double v) { return u * std::cos(u) * std::exp(v); }

// Net (u_i, v_j, W_ij) of degree n with W given as an (n+1) x (n+1) matrix.
TensorNet graph_net(const Eigen::MatrixXd& W) {
  const int n = static_cast<int>(W.rows()) - 1;
  TensorNet net(n, n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) net.set_point(i, j, Eigen::Vector3d(i / double(n), j / double(n), W(i, j)));
  return net;
}

// (A) Tensor interpolation of f at the Chebyshev–Lobatto points t_s = (1 - cos(s pi/n))/2. Its
// boundary curves interpolate f on the edges and its cross derivatives approximate f's.
Eigen::MatrixXd chebyshev_interpolant(int n) {
  Eigen::VectorXd t(n + 1);
  for (int s = 0; s <= n; ++s) t(s) = 0.5 * (1.0 - std::cos(s * std::numbers::pi / n));
  const Eigen::MatrixXd V = bernstein_table(n, t);
  Eigen::MatrixXd F(n + 1, n + 1);
  for (int a = 0; a <= n; ++a)
    for (int b = 0; b <= n; ++b) F(a, b) = f(t(a), t(b));
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(V);
  return lu.solve(lu.solve(F).transpose()).transpose();  // V^-1 F V^-T
}

// (B) L² projection of f onto bidegree n (exact Bernstein Gram matrix, Gauss quadrature).
Eigen::MatrixXd l2_projection(int n) {
  const QuadratureRule1D g = gauss_legendre01(30);
  const Eigen::MatrixXd B = bernstein_table(n, g.x);  // q x (n+1)
  Eigen::MatrixXd F(g.x.size(), g.x.size());
  for (Eigen::Index a = 0; a < g.x.size(); ++a)
    for (Eigen::Index b = 0; b < g.x.size(); ++b) F(a, b) = f(g.x(a), g.x(b));
  const Eigen::MatrixXd rhs = B.transpose() * g.w.asDiagonal() * F * g.w.asDiagonal() * B;
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(bernstein_product_integrals(n, n));
  return lu.solve(lu.solve(rhs).transpose()).transpose();
}

double max_error(const TensorNet& net) {
  double e = 0.0;
  const int N = 200;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N; ++b) {
      const double u = a / double(N), v = b / double(N);
      e = std::max(e, std::abs(net.evaluate(u, v)(2) - f(u, v)));
    }
  return e;
}

TEST(ExactSolution41, BothC1MethodsApproximateUCosUExpV) {
  for (int n : {7, 9}) {
    for (int data = 0; data < 2; ++data) {
      const TensorNet approx = graph_net(data == 0 ? chebyshev_interpolant(n) : l2_projection(n));
      const auto load = solve_biharmonic_load(approx);
      const auto tetra = solve_tetraharmonic(approx);
      TetraharmonicOptions ex;
      ex.method = TetraharmonicOptions::Method::Explicit;
      const auto tetra_ex = solve_tetraharmonic(approx, ex);
      const double e_data = max_error(approx), e_load = max_error(load.net), e_tetra = max_error(tetra.net),
                   e_tetra_ex = max_error(tetra_ex.net);
      std::printf(
          "n = %d, data = %s: |data patch - f| = %.3e, biharmonic-load %.3e, tetraharmonic lu %.3e, "
          "explicit %.3e\n",
          n, data == 0 ? "Chebyshev-Lobatto interpolation" : "L2 projection", e_data, e_load, e_tetra, e_tetra_ex);
      // The paper's 2.499e-6 and 9.108e-6 at n = 7 (its data approximation is not stated; ours
      // gives 2.38e-6..2.47e-6 and 9.09e-6..9.14e-6). Much smaller at n = 9.
      if (n == 7) {
        EXPECT_NEAR(e_load, 2.499e-6, 0.25e-6);
        EXPECT_NEAR(e_tetra, 9.108e-6, 0.3e-6);
      } else {
        EXPECT_LT(e_load, 1e-7);
        EXPECT_LT(e_tetra, 5e-7);
      }
      EXPECT_LT(e_load, e_tetra);
      EXPECT_NEAR(e_tetra_ex, e_tetra, 1e-3 * e_tetra);
      // x and y are reproduced exactly (u and v are biharmonic and tetraharmonic).
      EXPECT_NEAR(load.net.evaluate(0.3, 0.8)(0), 0.3, 1e-13);
      EXPECT_NEAR(tetra.net.evaluate(0.3, 0.8)(1), 0.8, 1e-13);
    }
  }
}

}  // namespace
}  // namespace bpde
