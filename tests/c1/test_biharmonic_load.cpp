// The nonhomogeneous biharmonic method (Centella et al. §4, Theorems 2-3, Prop. 2 / eq. (37)).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

#include "c1_polynomials.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/c1/biharmonic_load.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"

namespace bpde {
namespace {

using namespace testing;

// Smooth, non-polynomial C¹ data: the outer two rings of the net of (u, v, sin(2u) cosh(v) + u v²)
// sampled at the Greville points (any values would do: every data set has a solution).
TensorNet smooth_data(int n) {
  TensorNet d(n, n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double u = i / double(n), v = j / double(n);
      d.set_point(i, j, Eigen::Vector3d(u + 0.1 * v * v, v - 0.2 * u * v, std::sin(2 * u) * std::cosh(v) + u * v * v));
    }
  return d;
}

Eigen::Vector3d bilaplacian_at(const TensorNet& x, double u, double v, double* magnitude) {
  const Eigen::Vector3d a = x.derivative(u, v, 4, 0), b = x.derivative(u, v, 2, 2), c = x.derivative(u, v, 0, 4);
  *magnitude = std::max({a.cwiseAbs().maxCoeff(), 2 * b.cwiseAbs().maxCoeff(), c.cwiseAbs().maxCoeff()});
  return a + 2.0 * b + c;
}

TEST(BiharmonicLoad, SolvesDelta2xEqualsPWithVanishingInteriorLoad) {
  for (int n = 4; n <= 14; ++n) {
    const TensorNet data = smooth_data(n);
    const auto r = solve_biharmonic_load(data);
    EXPECT_TRUE(r.summary.converged) << r.summary.message;
    EXPECT_EQ(r.summary.status, Status::Converged);
    // Outer two rings are the data, exactly.
    for (int idx : data.fixed_indices(FixedSet::BoundaryAdjacent))
      EXPECT_EQ(r.net.points().row(idx), data.points().row(idx));
    // The load net is zero at 2 <= i, j <= n-2, relative to a bound of the terms that cancel:
    // |T4| row sums <= 16 n!/(n-4)!, weights 1 + 2 + 1.
    const double lmax = r.load.points().cwiseAbs().maxCoeff();
    const double bound = 4.0 * 16.0 * n * (n - 1) * (n - 2) * (n - 3) * r.net.points().cwiseAbs().maxCoeff();
    EXPECT_LT(r.summary.residual, 1e-13) << n;
    for (int i = 2; i <= n - 2; ++i)
      for (int j = 2; j <= n - 2; ++j) EXPECT_LT(r.load.point(i, j).cwiseAbs().maxCoeff(), 1e-14 * bound) << n;
    // Δ²x = p at sample points, with derivatives of the surface (an independent evaluation).
    for (double u : {0.0, 0.37, 0.81})
      for (double v : {0.13, 0.5, 1.0}) {
        double mag = 0;
        const Eigen::Vector3d lhs = bilaplacian_at(r.net, u, v, &mag), p = r.load.evaluate(u, v);
        EXPECT_LT((lhs - p).cwiseAbs().maxCoeff(), 1e-10 * (mag + lmax)) << "n = " << n << " at " << u << ", " << v;
      }
  }
}

TEST(BiharmonicLoad, ReproducesBiharmonicPolynomialsWithZeroLoad) {
  // Re(zbar z^b), Im(zbar z^b), Re z^b are biharmonic: their load is 0 and both C¹ methods
  // must return them.
  for (int n : {5, 7, 9, 11}) {
    const int b = std::min(n - 1, 6);
    const std::vector<std::vector<double>> U = {{0.0}, {1.0}}, V = {{0.0, 1.0}};
    const TensorNet exact = net_from_tables(n, {add(U, re(zbar_z(1, b, 0.3, 0.6), 0.5)),
                                                add(V, im(zbar_z(1, b, 0.3, 0.6))), re(zbar_z(0, b + 1, 0.3, 0.6))});
    TensorNet data = exact;
    for (int idx : exact.free_indices(FixedSet::BoundaryAdjacent)) data.points().row(idx).setConstant(-3.0);
    const auto r = solve_biharmonic_load(data);
    EXPECT_LT(relative_difference(r.net, exact), 1e-13) << n;
    EXPECT_LT(r.load.points().cwiseAbs().maxCoeff(), 1e-9 * std::pow(3.0, n - 5)) << n;
    const auto t = solve_tetraharmonic(data);
    EXPECT_LT(relative_difference(t.net, exact), 1e-12 * std::pow(3.0, n - 5)) << n;
  }
}

// Prop. 2: the loads of solutions satisfy eq. (37); a generic load net does not.
TEST(BiharmonicLoad, LoadsSatisfyEquation37) {
  for (int n = 4; n <= 9; ++n) {
    const auto r = solve_biharmonic_load(smooth_data(n));
    EXPECT_LT(admissibility_defect(r.load), 1e-10) << n;
    TensorNet bad = r.load;
    bad.points()(bad.index(n, n - 1), 2) += 1.0;  // perturb one coefficient entering (37)
    EXPECT_GT(admissibility_defect(bad), 1e-4) << n;
    // Any Δ² of a bidegree-n polynomial is admissible: a random net's load net satisfies (37).
    TensorNet x(n, n);
    x.points().setRandom();
    EXPECT_LT(admissibility_defect(bilaplacian_load_net(x)), 1e-10) << n;
    TensorNet random_load(n, n);
    random_load.points().setRandom();
    EXPECT_GT(admissibility_defect(random_load), 1e-3) << n;
  }
}

// Theorem 2: the non-boundary points of an admissible load determine its boundary ring.
TEST(BiharmonicLoad, Theorem2CompletesTheBoundaryOfALoad) {
  for (int n : {4, 6, 8, 10}) {
    const auto r = solve_biharmonic_load(smooth_data(n));
    TensorNet cleared = r.load;
    for (int idx : cleared.boundary_indices()) cleared.points().row(idx).setConstant(123.0);
    const TensorNet completed = complete_admissible_load(cleared);
    // The completion is ill-conditioned in n (the load's interior carries the rounding of the
    // solve): ~1e-13 at n = 4, ~1e-7 at n = 10.
    EXPECT_LT(relative_difference(completed, r.load), 1e-12 * std::pow(10.0, n - 4)) << n;
    // A random interior completes to an admissible load (eq. (37) holds).
    TensorNet random_load(n, n);
    random_load.points().setRandom();
    if (n <= 8) {
      EXPECT_LT(admissibility_defect(complete_admissible_load(random_load)), 1e-9) << n;
    }
  }
}

TEST(BiharmonicLoad, LoadNetOfKnownPolynomial) {
  // x = u^4 v^4: Δ²x = 24 v^4 + 2*144 u^2 v^2 + 24 u^4; check against evaluation of the load net.
  const int n = 6;
  Eigen::MatrixX3d c = Eigen::MatrixX3d::Zero((n + 1) * (n + 1), 3);
  c(4 * (n + 1) + 4, 2) = 1.0;
  const TensorNet x = from_power(n, n, c);
  const TensorNet p = bilaplacian_load_net(x);
  for (double u : {0.1, 0.6})
    for (double v : {0.3, 0.95})
      EXPECT_NEAR(p.evaluate(u, v)(2), 24 * std::pow(v, 4) + 288 * u * u * v * v + 24 * std::pow(u, 4), 1e-11);
}

TEST(BiharmonicLoad, BadInput) {
  EXPECT_THROW(solve_biharmonic_load(TensorNet(3, 3)), DegreeError);
  EXPECT_THROW(solve_biharmonic_load(TensorNet(6, 5)), DegreeError);
  TensorNet d(7, 7);
  d.points()(d.index(1, 4), 2) = std::numeric_limits<double>::infinity();
  EXPECT_THROW(solve_biharmonic_load(d), NonFiniteError);
  EXPECT_THROW(complete_admissible_load(TensorNet(3, 3)), DegreeError);
  EXPECT_THROW(admissibility_defect(TensorNet(4, 5)), DegreeError);
}

}  // namespace
}  // namespace bpde
