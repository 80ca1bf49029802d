// solvers/bspline/bspline_extremal against independent Bézier computations, exact polynomial
// reproduction and finite differences of an independently assembled energy.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>

#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "tests/bspline/helpers.h"

using namespace bpde;
using namespace bpde::testing;

namespace {

std::vector<EnergySpec> energies() {
  return {EnergySpec::dirichlet(),
          EnergySpec::second_order(2.0, 0.7, 0.5),
          EnergySpec::biharmonic(),
          EnergySpec::laplacian_squared(),
          EnergySpec::coons(),
          EnergySpec::modified_biharmonic(1.3),
          EnergySpec::fourth_order({1.5, 0.4, 2.5, -0.3, 0.8}),
          EnergySpec::gnorm(0.7, 1.1)};
}

// Independent Bézier Gram on [u0,u1] x [v0,v1]: kron of exact 1-D Bernstein derivative integrals,
// with the chain-rule factors h^(1-a-b) of the affine map to [0,1].
Eigen::MatrixXd bezier_gram(int n, int m, double hu, double hv, const EnergySpec& e) {
  const int N = (n + 1) * (m + 1);
  Eigen::MatrixXd Q = Eigen::MatrixXd::Zero(N, N);
  for (const QuadraticTerm& t : e.terms()) {
    const Eigen::MatrixXd Ku = bernstein_derivative_integrals(n, t.au, t.bu) * std::pow(hu, 1 - t.au - t.bu);
    const Eigen::MatrixXd Kv = bernstein_derivative_integrals(m, t.av, t.bv) * std::pow(hv, 1 - t.av - t.bv);
    Eigen::MatrixXd K(N, N);
    for (int i = 0; i <= n; ++i)
      for (int i2 = 0; i2 <= n; ++i2)
        for (int j = 0; j <= m; ++j)
          for (int j2 = 0; j2 <= m; ++j2) K(i * (m + 1) + j, i2 * (m + 1) + j2) = Ku(i, i2) * Kv(j, j2);
    Q += 0.5 * t.w * (K + K.transpose());
  }
  return Q;
}

// Energy of a B-spline net summed over its Bézier patches (independent of bspline_gram).
double energy_by_patches(const BSplineNet& net, const EnergySpec& e) {
  double E = 0;
  for (const BezierPatch& b : bezier_patches(net)) {
    const Eigen::MatrixXd Q = bezier_gram(net.p(), net.q(), b.u1 - b.u0, b.v1 - b.v0, e);
    E += 0.5 * (b.net.points().transpose() * Q * b.net.points()).trace();
  }
  return E;
}

}  // namespace

TEST(BSplineExtremal, DerivativeIntegralsOfOneSpanAreTheBernsteinOnes) {
  // Knots [2^(k+1), 5^(k+1)]: N_i = B_i^k((t-2)/3), so K_ab = 3^(1-a-b) * Bernstein integrals.
  for (int k : {2, 5}) {
    std::vector<double> K(static_cast<size_t>(k + 1), 2.0);
    K.insert(K.end(), static_cast<size_t>(k + 1), 5.0);
    for (int a = 0; a <= 2; ++a)
      for (int b = 0; b <= 2; ++b) {
        const Eigen::MatrixXd ex = bernstein_derivative_integrals(k, a, b) * std::pow(3.0, 1 - a - b);
        EXPECT_LT((bspline_derivative_integrals(k, K, a, b) - ex).cwiseAbs().maxCoeff(),
                  1e-13 * (1 + ex.cwiseAbs().maxCoeff()));
      }
  }
}

TEST(BSplineExtremal, SingleSpanEqualsIndependentBezierSolve) {
  const int n = 5, m = 4;
  const double u0 = -1, u1 = 1.5, v0 = 0.5, v1 = 1.25;
  const BSplineNet data = random_net(n, m, clamped(n, {}, u0, u1), clamped(m, {}, v0, v1), 21);
  for (FixedSet fx : {FixedSet::Boundary, FixedSet::BoundaryAdjacent}) {
    const std::vector<int> fixed = data.fixed_indices(fx), free = data.free_indices(fx);
    for (const EnergySpec& e : energies()) {
      const Eigen::MatrixXd Q = bezier_gram(n, m, u1 - u0, v1 - v0, e);
      Eigen::MatrixXd Qff(free.size(), free.size()), Qfc(free.size(), fixed.size()), Xc(fixed.size(), 3);
      for (size_t a = 0; a < free.size(); ++a) {
        for (size_t b = 0; b < free.size(); ++b) Qff(a, b) = Q(free[a], free[b]);
        for (size_t b = 0; b < fixed.size(); ++b) Qfc(a, b) = Q(free[a], fixed[b]);
      }
      for (size_t b = 0; b < fixed.size(); ++b) Xc.row(b) = data.points().row(fixed[b]);
      const Eigen::MatrixXd Xf = Qff.fullPivLu().solve(-Qfc * Xc);
      const BSplineExtremalResult r = solve_bspline_extremal(data, e, BSplineExtremalOptions{fx});
      ASSERT_TRUE(r.summary.converged) << e.name() << ": " << r.summary.message;
      EXPECT_LT(r.summary.residual, 1e-12);
      double err = 0;
      for (size_t a = 0; a < free.size(); ++a) err = std::max(err, (r.net.points().row(free[a]) - Xf.row(a)).norm());
      EXPECT_LT(err, 1e-10 * (1 + Xf.cwiseAbs().maxCoeff())) << e.name() << " " << to_string(fx);
      for (size_t b = 0; b < fixed.size(); ++b) EXPECT_EQ(r.net.points().row(fixed[b]), data.points().row(fixed[b]));
      const Eigen::MatrixX3d P = r.net.points();
      EXPECT_NEAR(r.energy, 0.5 * (P.transpose() * Q * P).trace(), 1e-11 * (1 + std::abs(r.energy)));
    }
  }
}

TEST(BSplineExtremal, MultiSpanEnergyAndGramAgreeWithPatchSums) {
  const BSplineNet net = random_net(4, 3, clamped(4, {0.3, 0.3, 0.7}), uniform(9), 4);
  for (const EnergySpec& e : energies()) {
    const double a = bspline_energy(net, e), b = energy_by_patches(net, e);
    EXPECT_NEAR(a, b, 1e-11 * (1 + std::abs(b))) << e.name();
  }
}

TEST(BSplineExtremal, MultiSpanExtremalIsStationaryForTheIndependentEnergy) {
  // Central differences of the patch-summed energy are exact for a quadratic: the gradient at the
  // extremal must vanish on every free point and coordinate, and be non-zero on fixed points.
  const BSplineNet data = random_net(5, 4, clamped(5, {0.4, 0.55}), clamped(4, {0.3, 0.3, 0.8}, -1, 1), 9);
  for (const EnergySpec& e : {EnergySpec::biharmonic(), EnergySpec::dirichlet(), EnergySpec::laplacian_squared(),
                              EnergySpec::fourth_order({1.5, 0.4, 2.5, -0.3, 0.8})}) {
    const BSplineExtremalResult r = solve_bspline_extremal(data, e);
    ASSERT_TRUE(r.summary.converged) << r.summary.message;
    const double h = 1e-3, scale = energy_by_patches(r.net, e) + 1;
    double gfree = 0, gfixed = 0;
    for (int idx = 0; idx < data.size(); ++idx)
      for (int c = 0; c < 3; ++c) {
        BSplineNet a = r.net, b = r.net;
        a.points()(idx, c) += h;
        b.points()(idx, c) -= h;
        const double g = std::abs(energy_by_patches(a, e) - energy_by_patches(b, e)) / (2 * h);
        const auto fixed = data.fixed_indices(FixedSet::Boundary);
        if (std::binary_search(fixed.begin(), fixed.end(), idx))
          gfixed = std::max(gfixed, g);
        else
          gfree = std::max(gfree, g);
      }
    EXPECT_LT(gfree, 1e-9 * scale) << e.name();
    EXPECT_GT(gfixed, 1e-3 * scale) << e.name();
  }
}

TEST(BSplineExtremal, ReproducesHarmonicAndBiharmonicPolynomialsOnMultiSpanNets) {
  // Galerkin orthogonality: a harmonic polynomial in the spline space with the boundary fixed is
  // the Dirichlet extremal; a biharmonic one with the outer two rings fixed is the biharmonic
  // (and laplacian-squared) extremal. Clamped, non-uniform knots with 3 x 2 spans.
  const std::vector<double> U = clamped(4, {0.3, 0.65}, -0.5, 1.0), V = clamped(4, {0.2}, 0.0, 1.2);
  const Field harmonic = [](double u, double v) {
    return Eigen::Vector3d(u + 0.1 * v, u * u - v * v + 0.3 * u * v, u * u * u - 3 * u * v * v);
  };
  const BSplineNet h = spline_of(harmonic, 4, 4, U, V);
  BSplineNet data = h;
  for (int idx : data.free_indices(FixedSet::Boundary)) data.points().row(idx).setZero();
  const BSplineExtremalResult rh = solve_bspline_extremal(data, EnergySpec::dirichlet());
  ASSERT_TRUE(rh.summary.converged);
  EXPECT_LT((rh.net.points() - h.points()).cwiseAbs().maxCoeff(), 1e-12);

  const Field biharmonic = [](double u, double v) {
    return Eigen::Vector3d(u * u * u * u - 6 * u * u * v * v + v * v * v * v + u, (u * u + v * v) * (u * u - v * v),
                           (u * u + v * v) * u * v + v);
  };
  const BSplineNet b = spline_of(biharmonic, 4, 4, U, V);
  data = b;
  for (int idx : data.free_indices(FixedSet::BoundaryAdjacent)) data.points().row(idx).setZero();
  for (const EnergySpec& e : {EnergySpec::biharmonic(), EnergySpec::laplacian_squared()}) {
    const BSplineExtremalResult rb =
        solve_bspline_extremal(data, e, BSplineExtremalOptions{FixedSet::BoundaryAdjacent});
    ASSERT_TRUE(rb.summary.converged);
    EXPECT_LT((rb.net.points() - b.points()).cwiseAbs().maxCoeff(), 1e-11) << e.name();
  }
}

TEST(BSplineExtremal, ExtremalIsSmoothAcrossSimpleKnots) {
  // C^{p-1} at the simple knot 0.5 of a biquintic extremal, and a genuine jump in the 5th derivative.
  const BSplineNet data = random_net(5, 5, clamped(5, {0.5}), clamped(5, {0.5}), 31);
  const BSplineExtremalResult r = solve_bspline_extremal(data, EnergySpec::biharmonic());
  const std::vector<BezierPatch> P = bezier_patches(r.net);  // order su*2 + sv
  const BezierPatch &a = P[0], &b = P[2];                    // (0,0) and (1,0): across u = 0.5
  for (double t : {0.2, 0.6}) {
    for (int du = 0; du <= 5; ++du) {
      const Eigen::Vector3d da = a.net.derivative(1.0, t, du, 0) / std::pow(0.5, du);
      const Eigen::Vector3d db = b.net.derivative(0.0, t, du, 0) / std::pow(0.5, du);
      if (du < 5)
        EXPECT_LT((da - db).norm(), 1e-9 * (1 + da.norm())) << du;
      else
        EXPECT_GT((da - db).norm(), 1e-3 * (1 + da.norm()));
    }
  }
}

TEST(BSplineExtremal, SemidefiniteEnergyFallsBackToMinimumNorm) {
  // Coons energy with only the u-boundaries fixed: x = f(u) with f zero at both ends has zero
  // energy, so Q_ff is singular; the solver still returns a minimiser (residual ~ 0) and says so.
  const BSplineNet data = random_net(3, 3, clamped(3, {0.5}), clamped(3, {}), 8);
  const BSplineExtremalResult r =
      solve_bspline_extremal(data, EnergySpec::coons(), BSplineExtremalOptions{FixedSet::UBoundaries});
  EXPECT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.summary.status, Status::Converged);
  EXPECT_NE(r.summary.message.find("not positive definite"), std::string::npos);
  EXPECT_LT(r.summary.residual, 1e-11);
}

TEST(BSplineExtremal, SolverIsReusableAndChecksItsNet) {
  const std::vector<double> U = clamped(3, {0.5}), V = clamped(3, {0.25, 0.75});
  const BSplineNet d1 = random_net(3, 3, U, V, 1), d2 = random_net(3, 3, U, V, 2);
  const BSplineExtremalSolver s(3, 3, U, V, EnergySpec::biharmonic(), d1.fixed_indices(FixedSet::Boundary));
  const BSplineExtremalResult r1 = s.solve(d1), r2 = s.solve(d2);
  EXPECT_LT((r1.net.points() - solve_bspline_extremal(d1, EnergySpec::biharmonic()).net.points()).norm(), 1e-12);
  EXPECT_LT((r2.net.points() - solve_bspline_extremal(d2, EnergySpec::biharmonic()).net.points()).norm(), 1e-12);
  EXPECT_THROW(s.solve(random_net(3, 3, U, clamped(3, {0.5}), 3)), ParameterError);
  EXPECT_THROW(solve_bspline_extremal(d1, EnergySpec::dirichlet(), std::vector<int>{3, 2}), ParameterError);
  EXPECT_THROW(solve_bspline_extremal(d1, EnergySpec::dirichlet(), std::vector<int>{0, 999}), SizeError);
  BSplineExtremalOptions bad;
  bad.tolerance = 0;
  EXPECT_THROW(solve_bspline_extremal(d1, EnergySpec::dirichlet(), bad), ParameterError);
}
