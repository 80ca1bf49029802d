// The least-squares mean-curvature functional Φ = ∫ ρ (H_x − H)² dA
// (energies/mean_curvature_least_squares.h) and its solve (solvers/cmc/cmc.h, functional
// "mean-curvature"): the value against independent quadratures, the Jacobian against finite
// differences, and the solve against closed-form surfaces.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/energies/mean_curvature_least_squares.h"
#include "cmc_test_util.h"

namespace bpde {
namespace {

// ρ of the header, written out independently: Π_c (1 − λ_c⁸)⁴.
double rho(const std::array<double, 4>& l, int corners) {
  double r = 1;
  for (int c = 0; c < corners; ++c) r *= std::pow(1 - std::pow(l[size_t(c)], 8), 4);
  return r;
}

TriangularNet perturbed_sphere_triangle(int n, unsigned seed) {
  TriangularNet net(n);
  for (int r = 0; r < net.size(); ++r) {
    const MultiIndex I = TriangularNet::multi_index(n, r);
    net.points().row(r) = sphere_triangle(double(I[0]) / n, double(I[1]) / n).transpose();
  }
  net.points() += testing::random_points(net.size(), seed, 0.05);
  return net;
}

TensorNet perturbed_sphere_tensor(int n, int m, unsigned seed) {
  TensorNet net(n, m);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) net.set_point(i, j, sphere_square(double(i) / n, double(j) / m));
  net.points() += testing::random_points(net.size(), seed, 0.05);
  return net;
}

// Φ(H) = a − 2bH + cH² with a = ∫ρH_x² dA, b = ∫ρH_x dA, c = ∫ρ dA. Three values of Φ give a, b
// and c; each is compared with a plain Gauss rule (no collapse) with H_x from the fundamental
// forms (core/differential_geometry.h) at its nodes, on a smooth regular patch.
TEST(MeanCurvatureLeastSquares, ValueIsTheWeightedSquaredDeviationTriangular) {
  const int n = 5;
  const TriangularNet net = perturbed_sphere_triangle(n, 21);
  const MeanCurvatureLeastSquares f = MeanCurvatureLeastSquares::triangular(n, 40);
  const double p0 = f.value(net.points(), 0.0), p1 = f.value(net.points(), 1.0), m1 = f.value(net.points(), -1.0);
  const double b = (m1 - p1) / 4, c = (p1 + m1) / 2 - p0;
  const QuadratureRuleTriangle g = gauss_triangle(60);
  double A = 0, B = 0, Cc = 0;
  for (Eigen::Index k = 0; k < g.w.size(); ++k) {
    const double u = g.uv(k, 0), v = g.uv(k, 1);
    const FundamentalForms ff = net.geometry(u, v);
    ASSERT_TRUE(ff.regular);
    const double dA =
        g.w(k) * net.derivative(u, v, 1, 0).cross(net.derivative(u, v, 0, 1)).norm() * rho({u, v, 1 - u - v, 0}, 3);
    A += ff.H * ff.H * dA;
    B += ff.H * dA;
    Cc += dA;
  }
  ASSERT_GT(std::abs(B), 0.1 * Cc);  // a curved patch: H_x far from 0
  EXPECT_NEAR(p0, A, 1e-10 * A);
  EXPECT_NEAR(b, B, 1e-10 * std::abs(B));
  EXPECT_NEAR(c, Cc, 1e-10 * Cc);
}

TEST(MeanCurvatureLeastSquares, ValueIsTheWeightedSquaredDeviationTensor) {
  const int n = 4, m = 5;
  const TensorNet net = perturbed_sphere_tensor(n, m, 22);
  const MeanCurvatureLeastSquares f = MeanCurvatureLeastSquares::tensor(n, m, 40);
  const double p0 = f.value(net.points(), 0.0), p1 = f.value(net.points(), 1.0), m1 = f.value(net.points(), -1.0);
  const double b = (m1 - p1) / 4, c = (p1 + m1) / 2 - p0;
  const QuadratureRule1D g = gauss_legendre01(80);
  double A = 0, B = 0, Cc = 0;
  for (Eigen::Index i = 0; i < g.x.size(); ++i)
    for (Eigen::Index j = 0; j < g.x.size(); ++j) {
      const double u = g.x(i), v = g.x(j);
      const FundamentalForms ff = net.geometry(u, v);
      ASSERT_TRUE(ff.regular);
      const double dA = g.w(i) * g.w(j) * net.derivative(u, v, 1, 0).cross(net.derivative(u, v, 0, 1)).norm() *
                        rho({(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v}, 4);
      A += ff.H * ff.H * dA;
      B += ff.H * dA;
      Cc += dA;
    }
  ASSERT_GT(std::abs(B), 0.1 * Cc);
  EXPECT_NEAR(p0, A, 1e-10 * A);
  EXPECT_NEAR(b, B, 1e-10 * std::abs(B));
  EXPECT_NEAR(c, Cc, 1e-10 * Cc);
}

// A planar affine patch has H_x = 0 and a constant |x_u ∧ x_v|, so Φ(H) = H² |N| ∫ρ du dv exactly,
// with ∫ρ (a polynomial of degree 96) by a Gauss rule that is exact for it.
TEST(MeanCurvatureLeastSquares, PlanarPatchGivesHSquaredTimesTheWeightedArea) {
  const int n = 4;
  TriangularNet net(n);
  const Eigen::Vector3d a(1.0, 0.2, -0.3), b(0.1, 0.8, 0.5), o(0.3, -0.2, 1.0);
  for (int r = 0; r < net.size(); ++r) {
    const MultiIndex I = TriangularNet::multi_index(n, r);
    net.points().row(r) = (o + a * (double(I[0]) / n) + b * (double(I[1]) / n)).transpose();
  }
  const QuadratureRuleTriangle g = gauss_triangle(60);
  double w = 0;
  for (Eigen::Index k = 0; k < g.w.size(); ++k)
    w += g.w(k) * rho({g.uv(k, 0), g.uv(k, 1), 1 - g.uv(k, 0) - g.uv(k, 1), 0}, 3);
  const double H = 0.7, expected = H * H * a.cross(b).norm() * w;
  EXPECT_NEAR(MeanCurvatureLeastSquares::triangular(n, 60).value(net.points(), H), expected, 1e-13 * expected);
  EXPECT_LT(MeanCurvatureLeastSquares::triangular(n, 60).value(net.points(), 0.0), 1e-25);
}

TEST(MeanCurvatureLeastSquares, JacobianAgainstFiniteDifferences) {
  auto check = [](const MeanCurvatureLeastSquares& f, const Eigen::MatrixX3d& P, const std::vector<int>& idx) {
    const double H = -0.4;
    Eigen::VectorXd r;
    Eigen::MatrixXd J;
    f.residuals(P, H, &r, &idx, &J);
    ASSERT_EQ(J.rows(), f.nodes());
    ASSERT_EQ(J.cols(), 3 * Eigen::Index(idx.size()));
    const double h = 1e-6, js = J.cwiseAbs().maxCoeff();
    ASSERT_GT(js, 1e-3);
    for (size_t a = 0; a < idx.size(); ++a)
      for (int c = 0; c < 3; ++c) {
        Eigen::MatrixX3d Pp = P, Pm = P;
        Pp(idx[a], c) += h;
        Pm(idx[a], c) -= h;
        Eigen::VectorXd rp, rm;
        f.residuals(Pp, H, &rp);
        f.residuals(Pm, H, &rm);
        const Eigen::VectorXd fd = (rp - rm) / (2 * h);
        EXPECT_LT((J.col(3 * Eigen::Index(a) + c) - fd).cwiseAbs().maxCoeff(), 1e-7 * js) << idx[a] << "." << c;
      }
    // Node by node, as the Ceres route's residual blocks assemble it: r_q from the node
    // derivatives, and its row from ∂r_q/∂(jet) times the basis derivatives.
    const MeanCurvatureLeastSquares::NodeDerivatives X = f.derivatives(P);
    Eigen::Matrix<double, 15, 1> dr;
    for (Eigen::Index q = 0; q < f.nodes(); ++q) {
      EXPECT_EQ(f.node_residual(X, q, H, &dr), r(q));
      // without the Jacobian: the plain double evaluation, equal up to rounding (FMA contraction)
      EXPECT_NEAR(f.node_residual(X, q, H, nullptr), r(q), 1e-14 * std::max(1.0, std::abs(r(q))));
      for (size_t a = 0; a < idx.size(); ++a)
        for (int c = 0; c < 3; ++c) {
          double row = 0;
          for (int t = 0; t < 5; ++t) row += dr(3 * t + c) * f.basis_derivative(t)(q, idx[a]);
          EXPECT_NEAR(row, J(q, 3 * Eigen::Index(a) + c), 1e-12 * js);
        }
    }
    // ∂r/∂H (the V form's extra column): r is affine in H, so a difference quotient is exact.
    Eigen::VectorXd r2;
    f.residuals(P, H + 0.5, &r2);
    const Eigen::VectorXd dH = f.h_derivative(X);
    ASSERT_EQ(dH.size(), f.nodes());
    EXPECT_LT(((r2 - r) / 0.5 - dH).cwiseAbs().maxCoeff(), 1e-12 * dH.cwiseAbs().maxCoeff());
    EXPECT_LT(dH.maxCoeff(), 0.0);
  };
  const TriangularNet t = perturbed_sphere_triangle(5, 23);
  check(MeanCurvatureLeastSquares::triangular(5, 8), t.points(), t.free_indices(FixedSet::Boundary));
  const TensorNet s = perturbed_sphere_tensor(4, 3, 24);
  check(MeanCurvatureLeastSquares::tensor(4, 3, 6), s.points(), s.free_indices(FixedSet::Boundary));
}

CmcOptions mc_options(double H, CmcSolver solver = CmcSolver::Newton) {
  CmcOptions o = testing::cmc_options(CmcFunctionalKind::MeanCurvature, H);
  o.solver = solver;
  return o;
}

// Both minimisers of Φ: the library's own Levenberg–Marquardt loop (newton) and ceres::Solve with
// one residual block per node (ceres); every target below holds for each.
constexpr CmcSolver kSolvers[] = {CmcSolver::Newton, CmcSolver::Ceres};

// The mean-curvature target at degree 10 (Arnal–Lluch–Monterde's Fig. 1 circle, three arcs by angle):
// on the sphere of radius 1/|H| to 1e-6, corners included, and H within 5e-4 away from the
// corners. The area route meets the first and misses the second at H = -0.9 (5.3e-3,
// CmcArea.CircleInThreeArcsAtHMinus09). Measured here: H = -0.5: 1.6e-8 from the sphere, H within
// 1.5e-5; H = -0.9: 1.1e-8 and 1.1e-5; the cap's area to 2e-9.
TEST(CmcMeanCurvature, CircleInThreeArcsAtDegree10MeetsBothTargets) {
  for (const CmcSolver solver : kSolvers)
    for (double H : {-0.5, -0.9}) {
      SCOPED_TRACE(to_string(solver));
      const double R = 1 / std::abs(H), hc = R - std::sqrt(R * R - 1);
      const Eigen::Vector3d c(0, 0, -std::sqrt(R * R - 1));
      const CmcResult<TriangularNet> r = solve_cmc(testing::circle_three_arcs(10), mc_options(H, solver));
      EXPECT_EQ(r.summary.status, Status::Converged) << H << ": " << r.summary.message;
      EXPECT_EQ(r.functional, CmcFunctionalKind::MeanCurvature);
      EXPECT_LE(r.summary.residual, 1e-6) << H;
      // Φ is resolved by the check rule: a much finer one agrees (measured: to 0.2 %; the rule
      // minimised, q = 9, reads 15–22 % lower, which is why a finer one decides).
      const double fine = MeanCurvatureLeastSquares::triangular(10, 30).value(r.net.points(), H);
      EXPECT_NEAR(fine, r.energy, 0.1 * r.energy) << H;
      EXPECT_LE(testing::sphere_distance(r.net, c, R), 1e-7) << H;
      const MeanCurvatureStats s = mean_curvature_stats(r.net, 40, 0.1);
      EXPECT_LE(std::max(std::abs(s.min - H), std::abs(s.max - H)), 5e-5) << H;
      EXPECT_NEAR(r.A, 2 * std::numbers::pi * R * hc, 1e-7) << H;
      EXPECT_NEAR(r.V, std::numbers::pi * hc * hc * (3 * R - hc) / 3, 1e-7) << H;
    }
}

// The V form: minimise Φ over the free points and H at V = V0. With V0 the volume of the exact
// cap of H over the circle, it returns that H, the cap and V0 (the same targets as the H form).
// Both solvers: newton (the KKT step of levenberg_marquardt.h) and ceres (the free points on the
// manifold V = V0, mean_curvature_ceres.cpp).
TEST(CmcMeanCurvature, VolumeFormReturnsTheCapAndItsH) {
  for (const CmcSolver solver : kSolvers)
  for (double H : {-0.5, -0.9}) {
    SCOPED_TRACE(to_string(solver) + " H = " + std::to_string(H));
    const double R = 1 / std::abs(H), hc = R - std::sqrt(R * R - 1);
    const double V0 = std::numbers::pi * hc * hc * (3 * R - hc) / 3;
    CmcOptions o = mc_options(0.0, solver);
    o.V = V0;
    const CmcResult<TriangularNet> r = solve_cmc(testing::circle_three_arcs(10), o);
    EXPECT_EQ(r.summary.status, Status::Converged) << r.summary.message;
    EXPECT_LE(r.summary.residual, 1e-6);
    EXPECT_NEAR(r.V, V0, 1e-12);
    EXPECT_NEAR(r.H, H, 1e-5);
    EXPECT_LE(testing::sphere_distance(r.net, Eigen::Vector3d(0, 0, -std::sqrt(R * R - 1)), R), 1e-7);
    const MeanCurvatureStats s = mean_curvature_stats(r.net, 40, 0.1);
    EXPECT_LE(std::max(std::abs(s.min - H), std::abs(s.max - H)), 5e-5);
    // The H reported is the best for the surface: Φ is quadratic in H, ∂Φ/∂H = −2⟨∂r/∂H, r⟩, so
    // its minimiser is H − ⟨∂r/∂H, r⟩/‖∂r/∂H‖² on the rule minimised (q = ⌈n/2⌉ + 4); the H reported
    // is that to rounding. The loops' own last H was 5.8e-9 … 1.4e-7 away from it.
    const MeanCurvatureLeastSquares f = MeanCurvatureLeastSquares::triangular(10, 9);
    Eigen::VectorXd rr, dH;
    f.residuals(r.net.points(), r.H, &rr, nullptr, nullptr, &dH);
    EXPECT_LE(std::abs(dH.dot(rr)) / dH.squaredNorm(), 1e-13);
  }
}

// Past the hemisphere (V > 2π/3 over the unit circle) the H form has no answer (|H| > 1 has no
// cap, and the D_H branch folds first), the V form does: the larger cap of radius 1/|H|. n = 10,
// H = -0.99: converged from the minimiser of D at V0, H to 1e-9, 2e-8 from the sphere (measured).
// A larger cap (H = -0.7, V = 11.5): from the minimiser of D at V0 the degree-10 parametrisation
// folds; with max_continuation_steps = 1 the continuation in V starts at V1 (which converges
// there) but stops after its one step attempt, and the folded surface is reported as degenerate,
// never as a CMC surface. V0 = 0 gives the flat disk (H = 0, Φ = 0 at the
// start). The default continuation in V reaching H = -0.7 is the next test.
TEST(CmcMeanCurvature, VolumeFormPastTheHemisphere) {
  const TriangularNet data = testing::circle_three_arcs(10);
  auto big_cap = [](double H) {
    const double R = 1 / std::abs(H), hb = R + std::sqrt(R * R - 1);
    return std::make_pair(std::numbers::pi * hb * hb * (3 * R - hb) / 3, Eigen::Vector3d(0, 0, std::sqrt(R * R - 1)));
  };
  CmcOptions o = mc_options(0.0);
  const auto [V0, c] = big_cap(-0.99);
  EXPECT_GT(V0, 2 * std::numbers::pi / 3);
  o.V = V0;
  const CmcResult<TriangularNet> r = solve_cmc(data, o);
  EXPECT_EQ(r.summary.status, Status::Converged) << r.summary.message;
  EXPECT_EQ(r.continuation_steps, 0) << r.summary.message;  // not continued in V
  EXPECT_NEAR(r.H, -0.99, 1e-7);
  EXPECT_NEAR(r.V, V0, 1e-11);
  EXPECT_LE(testing::sphere_distance(r.net, c, 1 / 0.99), 1e-7);
  o.V = big_cap(-0.7).first;
  o.max_continuation_steps = 1;
  const CmcResult<TriangularNet> folded = solve_cmc(data, o);
  EXPECT_EQ(folded.summary.status, Status::NoConvergence);
  EXPECT_TRUE(folded.parametrisation.checked);
  EXPECT_FALSE(folded.parametrisation.regular) << folded.summary.message;
  EXPECT_EQ(folded.continuation_steps, 0) << folded.summary.message;  // the continuation in V stopped
  o = mc_options(0.0);
  o.V = 0.0;
  const CmcResult<TriangularNet> flat = solve_cmc(data, o);
  EXPECT_EQ(flat.summary.status, Status::Converged) << flat.summary.message;
  EXPECT_EQ(flat.H, 0.0);
  EXPECT_FALSE(std::signbit(flat.H));
  EXPECT_LE(flat.summary.residual, 1e-12);
}

// The larger cap of H = -0.7 (V = 11.5 over the unit circle) at n = 10, by the continuation in V
// (cmc_mean_curvature.cpp, continue_in_volume): the minimiser of Φ at V1 = Vref + (V0 − Vref)/4,
// Vref the volume of the Dirichlet extremal, then steps in V to V0. The circle is moved off the
// origin by (0.3, -0.2, 2), which shifts every V by the same constant: V1 follows Vref (V0/4 would
// start below the disk). Measured on the centred circle: converged by both solvers in 6 and 7
// steps, 1.0–1.2 s and 2.2–3.6 s, 2.7e-8 and 3.0e-8 from the sphere (before the continuation: a
// degenerate parametrisation).
TEST(CmcMeanCurvature, VolumeFormReachesTheLargerCapByContinuationInV) {
  const double H = -0.7;
  const testing::LargerCapOffTheOrigin cap = testing::larger_cap_off_the_origin(10, H, Eigen::Vector3d(0.3, -0.2, 2.0));
  for (const CmcSolver solver : kSolvers) {
    SCOPED_TRACE(to_string(solver));
    CmcOptions o = mc_options(0.0, solver);
    o.V = cap.V0;
    const CmcResult<TriangularNet> r = solve_cmc(cap.data, o);
    EXPECT_EQ(r.summary.status, Status::Converged) << r.summary.message;
    const size_t at = r.summary.message.find("continued in V from V1 = ");
    ASSERT_NE(at, std::string::npos) << r.summary.message;
    EXPECT_NEAR(std::stod(r.summary.message.substr(at + 25)), cap.Vflat + (cap.V0 - cap.Vflat) / 4, 1e-4);
    EXPECT_GT(r.continuation_steps, 0);
    EXPECT_LE(r.summary.residual, 1e-6);
    EXPECT_NEAR(r.V, cap.V0, 1e-11);
    EXPECT_NEAR(r.H, H, 1e-6);
    EXPECT_LE(testing::sphere_distance(r.net, cap.centre, cap.R), 1e-6);
    const MeanCurvatureStats s = mean_curvature_stats(r.net, 40, 0.1);
    EXPECT_LE(std::max(std::abs(s.min - H), std::abs(s.max - H)), 5e-4);
  }
}

// Below the degree the tolerance needs: reported not converged, with the reason, and the net is
// still the least-squares surface (n = 6, H = -0.5: √Φ stalls at 9.5e-5; 1.8e-6 from the sphere,
// like the area route's 1.8e-6).
TEST(CmcMeanCurvature, TooLowADegreeForTheToleranceIsReportedAsSuch) {
  for (const CmcSolver solver : kSolvers) {
    SCOPED_TRACE(to_string(solver));
    const double H = -0.5, R = 2;
    const CmcResult<TriangularNet> r = solve_cmc(testing::circle_three_arcs(6), mc_options(H, solver));
    EXPECT_FALSE(r.summary.converged);
    EXPECT_EQ(r.summary.status, Status::NoConvergence);
    EXPECT_NE(r.summary.message.find("degree is too low"), std::string::npos) << r.summary.message;
    EXPECT_GT(r.summary.residual, 1e-6);
    EXPECT_LE(testing::sphere_distance(r.net, Eigen::Vector3d(0, 0, -std::sqrt(3.0)), R), 5e-6);
    // A looser tolerance is met at the same degree.
    CmcOptions o = mc_options(H, solver);
    o.mean_curvature_tolerance = 1e-3;
    EXPECT_TRUE(solve_cmc(testing::circle_three_arcs(6), o).summary.converged);
  }
}

// H = 0, tensor: the helicoid piece from its own (non-conformal) parametrisation (as
// CmcArea.MinimalSurfaceIsTheHelicoidPiece). Measured at n = 6: converged, 1.6e-7 off the
// helicoid (the area route: 1.6e-7), |H_x| ≤ 8.8e-6 away from the corners (the area route: 1.8e-4).
TEST(CmcMeanCurvature, MinimalSurfaceIsTheHelicoidPiece) {
  for (const CmcSolver solver : kSolvers) {
    SCOPED_TRACE(to_string(solver));
    const CmcResult<TensorNet> r = solve_cmc(testing::tensor_boundary(6, testing::helicoid), mc_options(0.0, solver));
    EXPECT_EQ(r.summary.status, Status::Converged) << r.summary.message;
    const double off = testing::helicoid_off(r.net);
    EXPECT_LE(off, 5e-7);
    const MeanCurvatureStats s = mean_curvature_stats(r.net, 40, 0.1);
    EXPECT_LE(std::max(std::abs(s.min), std::abs(s.max)), 5e-5);
  }
}

// C¹ data (boundary+adjacent) with the answer in closed form: the helicoid piece, its outer two
// rings from the tensor interpolant of its parametrisation (as
// CmcArea.C1DataMinimalSurfaceIsTheHelicoidPiece, where the area route is 1.6e-7 off at n = 6;
// this route 1.9e-7, in 20 ms instead of 3 s).
TEST(CmcMeanCurvature, C1DataMinimalSurfaceIsTheHelicoidPiece) {
  const TensorNet data = testing::tensor_interpolant(6, testing::helicoid);
  for (const CmcSolver solver : kSolvers) {
    SCOPED_TRACE(to_string(solver));
    CmcOptions o = mc_options(0.0, solver);
    o.fixed = FixedSet::BoundaryAdjacent;
    o.mean_curvature_tolerance = 1e-5;  // n = 6 with C¹ data stops at √Φ = 2.6e-6 (measured)
    const CmcResult<TensorNet> r = solve_cmc(data, o);
    EXPECT_EQ(r.summary.status, Status::Converged) << r.summary.message;
    const double off = testing::helicoid_off(r.net);
    EXPECT_LE(off, 3e-7) << off;  // measured 1.9e-7
    EXPECT_LE(r.summary.residual, 1e-5);
    // the outer two rings are the data's
    for (int i = 0; i <= 6; ++i)
      for (int j = 0; j <= 6; ++j)
        if (std::min({i, j, 6 - i, 6 - j}) <= 1) {
          EXPECT_EQ((r.net.point(i, j) - data.point(i, j)).norm(), 0.0);
        }
  }
}

// Conformal data (the sphere triangle, H = 1) at n = 10: Φ's floor at this degree is about 6.8e-6
// (rules of q = 28 … 60 agree on the result), above the default tolerance. With the rule minimised
// alone (q = 9) the iterate went on lowering that rule's Φ by folding the parametrisation near a
// corner, between its nodes: after 822 steps the check rule read 1.4e-2 and the result was
// reported as a degenerate parametrisation. The rule check (every 10 steps) catches the
// disagreement and refines the rules (q = 14) from the last agreed point; the result is a regular
// surface at the floor, not converged (newton: "no longer falls"; ceres: the iteration limit).
TEST(CmcMeanCurvature, RuleCheckKeepsTheParametrisationRegularOnConformalData) {
  const TriangularNet data = testing::triangular_boundary(10, testing::sphere_triangle);
  for (const CmcSolver solver : kSolvers) {
    SCOPED_TRACE(to_string(solver));
    const CmcResult<TriangularNet> r = solve_cmc(data, mc_options(1.0, solver));
    EXPECT_EQ(r.summary.status, Status::NoConvergence);
    EXPECT_TRUE(r.parametrisation.regular) << r.summary.message;
    EXPECT_GT(r.quadrature_points, 9) << r.summary.message;  // the rule refined from q = ⌈n/2⌉ + 4 = 9
    EXPECT_LE(r.summary.residual, 1e-5);  // the check rule's √Φ: at the floor, not a fold
    EXPECT_GT(r.summary.residual, 1e-6);
    EXPECT_LE(testing::sphere_distance(r.net, Eigen::Vector3d::Zero(), 1.0), 1e-5);
  }
}

// The rule minimised reaches its target (0.7 × the tolerance) while the finer check rule reads just
// above the tolerance: the V form on the circle at n = 12, H = −0.9 (newton: 1.04e-6 against 7e-7
// before) and the H form at n = 14, H = −0.5, tolerance 1e-8 (1.0e-8). The two rules disagree by
// less than the fold test's 2×; the solve goes on with the next finer pair of rules from the point
// reached and converges (measured: √Φ 6.6e-7 and 6.9e-9, 12 and 4 more iterations), on the sphere.
TEST(CmcMeanCurvature, CheckRuleMissRefinesTheRules) {
  const double H = -0.9, R = 1 / std::abs(H), hc = R - std::sqrt(R * R - 1);
  CmcOptions o = mc_options(0.0);
  o.V = std::numbers::pi * hc * hc * (3 * R - hc) / 3;
  const CmcResult<TriangularNet> v = solve_cmc(testing::circle_three_arcs(12), o);
  EXPECT_EQ(v.summary.status, Status::Converged) << v.summary.message;
  EXPECT_LE(v.summary.residual, 1e-6);
  EXPECT_GT(v.quadrature_points, 10) << v.summary.message;  // refined from q = ⌈n/2⌉ + 4 = 10
  // why: the check rule missed, not a fold (no typed field tells the two apart)
  EXPECT_NE(v.summary.message.find("the check rule read above the tolerance where the coarser one met it"),
            std::string::npos)
      << v.summary.message;
  EXPECT_NEAR(v.H, H, 1e-6);
  EXPECT_LE(testing::sphere_distance(v.net, Eigen::Vector3d(0, 0, -std::sqrt(R * R - 1)), R), 1e-7);

  CmcOptions t = mc_options(-0.5);
  t.mean_curvature_tolerance = 1e-8;
  const CmcResult<TriangularNet> h = solve_cmc(testing::circle_three_arcs(14), t);
  EXPECT_EQ(h.summary.status, Status::Converged) << h.summary.message;
  EXPECT_LE(h.summary.residual, 1e-8);
  EXPECT_GT(h.quadrature_points, 11) << h.summary.message;  // the rules refined from q = ⌈n/2⌉ + 4 = 11
  EXPECT_LE(testing::sphere_distance(h.net, Eigen::Vector3d(0, 0, -std::sqrt(3.0)), 2.0), 1e-9);
}

TEST(CmcMeanCurvature, BadInput) {
  const TriangularNet data = testing::circle_three_arcs(6);
  CmcOptions o = mc_options(-0.5);
  o.V = 1.0;
  o.solver = CmcSolver::NLopt;  // the V form too: newton or ceres
  EXPECT_THROW(solve_cmc(data, o), UnsupportedProblem);
  o.solver = CmcSolver::Newton;
  o.V = std::nan("");
  EXPECT_THROW(solve_cmc(data, o), NonFiniteError);
  o = mc_options(-0.5);
  o.mean_curvature_tolerance = 0.0;
  EXPECT_THROW(solve_cmc(data, o), ParameterError);
  o = mc_options(-0.5);
  o.max_least_squares_iterations = 0;
  EXPECT_THROW(solve_cmc(data, o), ParameterError);
  o = mc_options(std::nan(""));
  EXPECT_THROW(solve_cmc(data, o), NonFiniteError);
  o = mc_options(-0.5);
  o.mean_curvature_tolerance = 1.0;
  EXPECT_THROW(solve_cmc(data, o), ParameterError);
  o.mean_curvature_tolerance = std::nan("");
  EXPECT_THROW(solve_cmc(data, o), ParameterError);
  o = mc_options(-0.5);
  o.solver = CmcSolver::NLopt;
  EXPECT_THROW(solve_cmc(data, o), UnsupportedProblem);
  // its options are checked whatever the functional
  o = testing::cmc_options(CmcFunctionalKind::Area, -0.5);
  o.mean_curvature_tolerance = -1.0;
  EXPECT_THROW(solve_cmc(data, o), ParameterError);
  o = mc_options(-0.5);
  o.fixed = FixedSet::UBoundaries;
  EXPECT_THROW(solve_cmc(testing::tensor_boundary(4, sphere_square), o), UnsupportedProblem);
  EXPECT_THROW(solve_cmc(testing::circle_three_arcs(2), mc_options(-0.5)), DegreeError);
  EXPECT_EQ(parse_cmc_functional("mean-curvature"), CmcFunctionalKind::MeanCurvature);
  EXPECT_EQ(to_string(CmcFunctionalKind::MeanCurvature), "mean-curvature");
  EXPECT_THROW(MeanCurvatureLeastSquares::triangular(1, 5), DegreeError);
  EXPECT_THROW(MeanCurvatureLeastSquares::triangular(kMaxDegree + 1, 5), DegreeError);
  EXPECT_THROW(MeanCurvatureLeastSquares::tensor(4, kMaxDegree + 1, 5), DegreeError);
  EXPECT_THROW(MeanCurvatureLeastSquares::triangular(4, 201), ParameterError);
  EXPECT_THROW(MeanCurvatureLeastSquares::tensor(4, 4, 1), ParameterError);
  const MeanCurvatureLeastSquares f = MeanCurvatureLeastSquares::triangular(4, 5);
  EXPECT_THROW(f.value(Eigen::MatrixX3d::Zero(3, 3), 0.0), SizeError);
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  const Eigen::MatrixX3d P = Eigen::MatrixX3d::Random(15, 3);
  EXPECT_THROW(f.residuals(P, 0.0, &r, nullptr, &J), ParameterError);
  const std::vector<int> bad_idx = {3, 15};
  EXPECT_THROW(f.residuals(P, 0.0, &r, &bad_idx, &J), ParameterError);
}

// A node where the parametrisation is singular contributes 0 (a net on a line: every node), and
// a net that is not finite gives a Φ that is not finite, never a silent 0.
TEST(MeanCurvatureLeastSquares, SingularNodesAndNonFiniteNets) {
  const MeanCurvatureLeastSquares f = MeanCurvatureLeastSquares::triangular(4, 5);
  Eigen::MatrixX3d P(15, 3);
  for (int r = 0; r < 15; ++r) {
    const MultiIndex I = TriangularNet::multi_index(4, r);
    const double s = 0.3 * I[0] + 0.7 * I[1];
    P.row(r) = Eigen::RowVector3d(s, 2 * s, -s);
  }
  EXPECT_EQ(f.value(P, 0.5), 0.0);
  P(7, 1) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(std::isfinite(f.value(P, 0.5)));
  P(7, 1) = std::nan("");
  EXPECT_FALSE(std::isfinite(f.value(P, 0.5)));
}

// The iteration limit is reported as such (not as a stall), and the net is the one reached.
TEST(CmcMeanCurvature, IterationLimitIsReportedAsSuch) {
  for (const CmcSolver solver : kSolvers) {
    SCOPED_TRACE(to_string(solver));
    CmcOptions o = mc_options(-0.9, solver);
    o.max_least_squares_iterations = 1;
    const CmcResult<TriangularNet> r = solve_cmc(testing::circle_three_arcs(10), o);
    EXPECT_FALSE(r.summary.converged);
    EXPECT_EQ(r.summary.status, Status::NoConvergence);
    EXPECT_NE(r.summary.message.find("max_least_squares_iterations = 1"), std::string::npos) << r.summary.message;
    EXPECT_TRUE(r.net.points().allFinite());
    // The net reached is the start moved by one step: Φ is below the D_H start's.
    CmcOptions od = o;
    od.functional = CmcFunctionalKind::Dirichlet;
    const CmcResult<TriangularNet> start = solve_cmc(testing::circle_three_arcs(10), od);
    const MeanCurvatureLeastSquares f = MeanCurvatureLeastSquares::triangular(10, 14);
    EXPECT_LT(f.value(r.net.points(), -0.9), 0.9 * f.value(start.net.points(), -0.9));
  }
}

// Geodesic acceleration (Transtrum and Sethna; CmcOptions::geodesic_acceleration, the newton
// solver's default) off: plain Levenberg–Marquardt still meets the tolerance on the circle, on the
// same sphere (it crawls along the curved valley of Φ: measured n = 8, H = -0.5: 384 iterations
// plain, 83 accelerated; the contrast is bench/bench_cmc.cpp's
// CmcMeanCurvature/{newton,newton-plain}/circle/<n>).
TEST(CmcMeanCurvature, PlainLevenbergMarquardtConvergesToo) {
  const double H = -0.5, R = 1 / std::abs(H);
  const Eigen::Vector3d c(0, 0, -std::sqrt(R * R - 1));
  CmcOptions o = mc_options(H);
  ASSERT_TRUE(o.geodesic_acceleration);  // the default
  o.geodesic_acceleration = false;
  const CmcResult<TriangularNet> plain = solve_cmc(testing::circle_three_arcs(8), o);
  ASSERT_EQ(plain.summary.status, Status::Converged) << plain.summary.message;
  EXPECT_LE(plain.summary.residual, o.mean_curvature_tolerance);
  EXPECT_LE(testing::sphere_distance(plain.net, c, R), 1e-7);
}

}  // namespace
}  // namespace bpde
