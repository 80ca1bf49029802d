// The area functional of the cmc problem (solvers/cmc/cmc.h, "The area functional"): measured
// targets against closed forms.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "cmc_test_util.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace bpde {
namespace {

// max over a sample grid (every sample, corners included) of | |x - c| - R |.
double sphere_distance(const TriangularNet& net, const Eigen::Vector3d& c, double R, int N = 40) {
  double d = 0;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N - a; ++b)
      d = std::max(d, std::abs((net.evaluate(double(a) / N, double(b) / N) - c).norm() - R));
  return d;
}

CmcOptions area_options(double H) {
  CmcOptions o;
  o.H = H;
  o.functional = CmcFunctionalKind::Area;
  return o;
}

// Fig. 1 of Arnal–Lluch–Monterde: the unit circle in three arcs parametrised by angle (not
// conformal). The area functional's critical point lies on the exact sphere of radius 1/|H|
// through the circle (the small cap, centre below the plane for H < 0), corners included; the
// D_H critical point does not.
TEST(CmcArea, CircleInThreeArcsLiesOnTheExactSphere) {
  const double H = -0.5, R = 1 / std::abs(H);
  const Eigen::Vector3d c(0, 0, -std::sqrt(R * R - 1));
  const TriangularNet data = testing::circle_three_arcs(10);
  const CmcResult<TriangularNet> r = solve_cmc(data, area_options(H));
  EXPECT_LE(r.summary.residual, 1e-9) << r.summary.message;
  // The truncated Newton phase after the ε-continuation brings the first variation to the
  // tolerance (measured 5.9e-12; 8.3e-10 with the ε-continuation alone).
  EXPECT_EQ(r.summary.status, Status::Converged) << r.summary.message;
  EXPECT_LE(r.summary.residual, kConvergenceTolerance);
  EXPECT_LE(sphere_distance(r.net, c, R), 1e-6);
  const MeanCurvatureStats s = mean_curvature_stats(r.net, 40, 0.1);
  EXPECT_LE(std::max(std::abs(s.min - H), std::abs(s.max - H)), 5e-4);
  EXPECT_NEAR(r.energy, r.A + 2 * H * r.V, 1e-12 * r.A);
  EXPECT_EQ(r.functional, CmcFunctionalKind::Area);
  // The cap's area and volume in closed form: A = 2πR h, cone volume from the origin = the cap's
  // volume above z = 0 (the base disc contributes nothing): πh²(3R - h)/3, h = R - √(R² - 1).
  const double hc = R - std::sqrt(R * R - 1);
  EXPECT_NEAR(r.A, 2 * std::numbers::pi * R * hc, 1e-6);
  EXPECT_NEAR(r.V, std::numbers::pi * hc * hc * (3 * R - hc) / 3, 1e-6);
  // The paper's functional on the same data stays far from the sphere.
  CmcOptions od;
  od.H = H;
  const CmcResult<TriangularNet> d = solve_cmc(data, od);
  EXPECT_GT(sphere_distance(d.net, c, R), 1e-2);
}

// The degrees below and above n = 10, the demo's n = 8 among them: every one reaches the
// tolerance (before the truncated Newton phase: 2.8e-08 at n = 6, 2.7e-09 at n = 8).
TEST(CmcArea, CircleInThreeArcsConvergesAtLowDegrees) {
  const double H = -0.5, R = 1 / std::abs(H);
  const Eigen::Vector3d c(0, 0, -std::sqrt(R * R - 1));
  for (int n : {6, 8}) {
    const CmcResult<TriangularNet> r = solve_cmc(testing::circle_three_arcs(n), area_options(H));
    EXPECT_EQ(r.summary.status, Status::Converged) << n << ": " << r.summary.message;
    EXPECT_LE(r.summary.residual, kConvergenceTolerance) << n;
    // measured: 1.8e-06 (n = 6), 7.2e-08 (n = 8)
    EXPECT_LE(sphere_distance(r.net, c, R), n == 6 ? 5e-6 : 3e-7) << n;
  }
}

// Conformal data (the inverse stereographic sphere patch, H = 1): D ≥ A with equality for
// conformal maps, so both functionals give (nearly) the same surface, near the unit sphere, with
// the same area. The nets differ by a reparametrisation (measured max |x_A - x_D| 0.08 at n = 6),
// so the comparison is geometric. (The area route stops at its numerical limit here, first
// variation 8.9e-08 at n = 6 and 1.1e-09 at n = 8: not asserted.)
TEST(CmcArea, AgreesWithDirichletOnConformalData) {
  for (int n : {6, 8}) {
    const TriangularNet data = testing::triangular_boundary(n, testing::sphere_triangle);
    const CmcResult<TriangularNet> a = solve_cmc(data, area_options(1.0));
    CmcOptions od;
    od.H = 1.0;
    const CmcResult<TriangularNet> d = solve_cmc(data, od);
    ASSERT_TRUE(d.summary.converged) << d.summary.message;
    double da = 0, dd = 0;
    for (int i = 0; i <= 30; ++i)
      for (int j = 0; i + j <= 30; ++j) {
        da = std::max(da, std::abs(a.net.evaluate(i / 30.0, j / 30.0).norm() - 1));
        dd = std::max(dd, std::abs(d.net.evaluate(i / 30.0, j / 30.0).norm() - 1));
      }
    // measured: sphere distance 5.2e-04 / 6.5e-04 (n = 6), 5.0e-05 / 5.6e-05 (n = 8);
    // A of the area result against D of the Dirichlet one: 4.9e-05 (n = 6), 8.3e-07 (n = 8)
    const double sphere_tol = n == 6 ? 1e-3 : 1e-4, area_tol = n == 6 ? 1e-4 : 2e-6;
    EXPECT_LE(da, sphere_tol) << n;
    EXPECT_LE(dd, sphere_tol) << n;
    EXPECT_NEAR(a.A, d.D, area_tol) << n;
    EXPECT_LE(a.summary.residual, 1e-6) << n;
  }
}

TEST(CmcArea, BadInput) {
  const TriangularNet data = testing::circle_three_arcs(4);
  CmcOptions o = area_options(-0.5);
  o.solver = CmcSolver::NLopt;
  EXPECT_THROW(solve_cmc(data, o), UnsupportedProblem);
  o = area_options(-0.5);
  o.V = 1.0;
  o.solver = CmcSolver::Ceres;
  EXPECT_THROW(solve_cmc(data, o), UnsupportedProblem);
  o = area_options(-0.5);
  o.fixed = FixedSet::UBoundaries;
  EXPECT_THROW(solve_cmc(TensorNet(3, 3), o), UnsupportedProblem);
  EXPECT_THROW(parse_cmc_functional("areal"), ParameterError);
  EXPECT_EQ(parse_cmc_functional("area"), CmcFunctionalKind::Area);
  EXPECT_EQ(to_string(CmcFunctionalKind::Dirichlet), "dirichlet");
}

// H = 0 on a tensor net: a piece of the helicoid (s cos t, s sin t, t), s in [0.3, 1], t in
// [0, 1.2], whose boundary is given in the helicoid's own (non-conformal) parametrisation. The
// minimal surface is the helicoid piece: |x sin z - y cos z| (≈ the distance) over the samples.
TEST(CmcArea, MinimalSurfaceIsTheHelicoidPiece) {
  auto helicoid = [](double u, double v) {
    const double s = 0.3 + 0.7 * u, t = 1.2 * v;
    return Eigen::Vector3d(s * std::cos(t), s * std::sin(t), t);
  };
  const TensorNet data = tensor_boundary(8, helicoid);
  CmcOptions o = area_options(0.0);
  const CmcResult<TensorNet> r = solve_cmc(data, o);
  CmcOptions od;
  const CmcResult<TensorNet> d = solve_cmc(data, od);
  auto off = [](const TensorNet& net) {
    double e = 0;
    for (int a = 0; a <= 30; ++a)
      for (int b = 0; b <= 30; ++b) {
        const Eigen::Vector3d x = net.evaluate(a / 30.0, b / 30.0);
        e = std::max(e, std::abs(x(0) * std::sin(x(2)) - x(1) * std::cos(x(2))));
      }
    return e;
  };
  EXPECT_TRUE(r.summary.converged) << r.summary.message;  // measured: residual 1.9e-12
  EXPECT_LE(off(r.net), 1e-7);                            // measured: 8.9e-9 at n = 8
  EXPECT_GT(off(d.net), 1e-3);                            // the Dirichlet extremal: 8.2e-3
}

}  // namespace
}  // namespace bpde
