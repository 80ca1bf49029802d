// 000-power-basis-accuracy: how many digits the Bernstein <-> power conversion loses with degree.
//
// For each degree n, 20 random (n,n) nets with coordinates in [-1, 1]:
//   roundtrip  max |P - from_power(to_power(P))|            (control points, absolute)
//   eval       max |x_power(u,v) - x_bernstein(u,v)| on an 11x11 grid, power form by Horner
//   cond       2-norm condition number of the 1-D Bernstein-to-power matrix
// Prints a Markdown table, the generated section "power-basis-accuracy" of docs/accuracy.md and of
// README.md (scripts/docs.sh). The errors are rounding amplified, whose digits depend on the
// machine and compiler: they are given as the power of ten above them.
#include "bezierpde/core/eigen.h"
#include <Eigen/SVD>
#include <cmath>
#include <cstdio>
#include <random>

#include "bezierpde/core/bernstein.h"
#include "examples/common/generated.h"
#include "bezierpde/tensor/power_basis.h"
#include "bezierpde/tensor/tensor_net.h"

int main() {
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> U(-1, 1);
  const bpde::examples::GeneratedSection section("power-basis-accuracy");
  std::printf("| n | round-trip error | evaluation error (power form) | cond(M_n) |\n|---|---|---|---|\n");
  for (int n : {2, 4, 6, 8, 10, 12, 15, 18, 20, 25, 30, 40}) {
    double rt = 0, ev = 0;
    for (int trial = 0; trial < 20; ++trial) {
      bpde::TensorNet net(n, n);
      for (int r = 0; r < net.size(); ++r) net.points().row(r) << U(rng), U(rng), U(rng);
      const Eigen::MatrixX3d c = bpde::to_power(net);
      rt = std::max(rt, (bpde::from_power(n, n, c).points() - net.points()).cwiseAbs().maxCoeff());
      for (int a = 0; a <= 10; ++a)
        for (int b = 0; b <= 10; ++b) {
          const double u = a / 10.0, v = b / 10.0;
          Eigen::Vector3d x = Eigen::Vector3d::Zero();
          for (int k = n; k >= 0; --k) {
            Eigen::Vector3d row = Eigen::Vector3d::Zero();
            for (int l = n; l >= 0; --l) row = row * v + c.row(k * (n + 1) + l).transpose();
            x = x * u + row;
          }
          ev = std::max(ev, (x - net.evaluate(u, v)).cwiseAbs().maxCoeff());
        }
    }
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(bpde::bernstein_to_power_matrix(n));
    const double cond = svd.singularValues()(0) / svd.singularValues()(n);
    // Above ~1e16 = 1/eps the double SVD does not resolve the smallest singular value (at n = 40
    // it printed 4.7e+19 portable, 9.1e+18 with -march=native): only the bound is printed there.
    char c[32];
    std::snprintf(c, sizeof c, cond > 1e16 ? "> 1e16" : "%.1e", cond);
    std::printf("| %d | %s | %s | %s |\n", n, bpde::examples::order_bound(rt).c_str(),
                bpde::examples::order_bound(ev).c_str(), c);
  }
  return 0;
}
