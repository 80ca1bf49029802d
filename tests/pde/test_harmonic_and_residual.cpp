// Harmonic PDE from the u-boundaries, and the pde_residual report quantity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bezierpde/core/errors.h"
#include "exact_polynomials.h"
#include "bezierpde/solvers/pde/harmonic_pde.h"
#include "bezierpde/solvers/pde/pde_residual.h"
#include "bezierpde/tensor/power_basis.h"

namespace bpde {
namespace {

using namespace bpde::testing;

TensorNet random_rows(int n, int m, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  TensorNet net(n, m);
  for (int i : {0, n})
    for (int j = 0; j <= m; ++j) net.set_point(i, j, Eigen::Vector3d(U(gen), U(gen), U(gen)));
  return net;
}

TEST(HarmonicPde, RecoversHarmonicPolynomials) {
  // Re/Im of z^k, z = u + i v, k <= n: harmonic, bidegree (n, n).
  for (int n = 2; n <= 16; ++n) {
    const TensorNet exact = exact_solution({{cld(0, 1), false}}, n, 10u + n);
    const PdeSolution s = solve_harmonic_pde(boundary_only(exact, true));
    ASSERT_TRUE(s.summary.converged) << n << ": " << s.summary.message;
    const PdeMould mould(EnergySpec::dirichlet(), n, n, FixedSet::UBoundaries);
    EXPECT_LT(relative_error(s.net, exact), floor_tolerance(floor_error(mould, exact))) << n;
    if (n <= 10) {
      EXPECT_LT(pde_residual(s.net, EnergySpec::dirichlet(), 20), 1e-10) << n;
    }
  }
}

TEST(HarmonicPde, OddDegreeIsUniqueEvenDegreeNeedsOneCondition) {
  for (int n = 3; n <= 12; ++n) {
    const PdeMould mould(EnergySpec::dirichlet(), n, n, FixedSet::UBoundaries);
    EXPECT_TRUE(mould.structure().unique) << n;
    EXPECT_EQ(mould.structure().conditions, n % 2 == 0 ? 1 : 0) << n;
    const PdeSolution s = solve_harmonic_pde(random_rows(n, n, 7u + n));
    if (n % 2 == 1) {
      EXPECT_TRUE(s.summary.converged) << n << ": " << s.summary.message;
      EXPECT_LT(pde_residual(s.net, EnergySpec::dirichlet(), 20), 1e-9) << n;
    } else {
      EXPECT_FALSE(s.summary.converged) << n;
      EXPECT_EQ(s.summary.status, Status::Incompatible) << s.summary.message;
      EXPECT_FALSE(s.summary.message.empty()) << n;
    }
  }
}

TEST(HarmonicPde, EvenDegreeConditionIsEqualLeadingCoefficients) {
  // For Δ at even n the condition is: x(1,v) - x(0,v) has no v^n term (equal n-th differences of
  // the two rows). Make random rows satisfy it, then break it slightly.
  const int n = 8;
  TensorNet d = random_rows(n, n, 3);
  Eigen::Vector3d diff = Eigen::Vector3d::Zero();
  for (int l = 0; l <= n; ++l)
    diff += ((n - l) % 2 ? -1.0 : 1.0) * binom_ld(n, l) * (d.point(n, l) - d.point(0, l)).eval();
  // Adjust P_{n,n} (coefficient C(n,n) = 1 in the n-th difference) to cancel it.
  d.set_point(n, n, d.point(n, n) - diff);
  const PdeSolution ok = solve_harmonic_pde(d);
  ASSERT_TRUE(ok.summary.converged) << ok.summary.message;
  EXPECT_EQ(ok.summary.status, Status::Converged);
  EXPECT_LT(pde_residual(ok.net, EnergySpec::dirichlet(), 20), 1e-9);
  d.set_point(n, n, d.point(n, n) + Eigen::Vector3d(1e-5, 0, 0));
  const PdeSolution broken = solve_harmonic_pde(d);
  EXPECT_FALSE(broken.summary.converged);
  EXPECT_EQ(broken.summary.status, Status::Incompatible) << broken.summary.message;
}

TEST(HarmonicPde, GeneralSecondOrder) {
  // a x_uu + b x_uv + c x_vv with roots a + b mu + c mu^2 = 0.
  const double a = 1.0, b = 0.6, c = 2.0;
  const std::complex<double> mu = (-b + std::sqrt(std::complex<double>(b * b - 4 * a * c))) / (2 * c);
  const EnergySpec op = EnergySpec::second_order(a, b, c);
  for (int n : {3, 5, 7, 9}) {  // with b != 0 the condition at n = m is generic: test n > m (unique)
    const int m = n - 1;
    const auto mono = exact_monomials({{cld(mu.real(), mu.imag()), false}}, m, 5u + n);
    const TensorNet exact = exact_net(mono, n, m);
    const PdeMould mould(op, n, m, FixedSet::UBoundaries);
    EXPECT_TRUE(mould.structure().unique);
    EXPECT_EQ(mould.structure().conditions, 0);
    const PdeSolution s = solve_harmonic_pde(boundary_only(exact, true), op);
    ASSERT_TRUE(s.summary.converged) << s.summary.message;
    EXPECT_LT(relative_error(s.net, exact), 1e-11) << n;
  }
  EXPECT_THROW(solve_harmonic_pde(random_rows(4, 4, 1), EnergySpec::biharmonic()), UnsupportedProblem);
  EXPECT_THROW(solve_harmonic_pde(random_rows(4, 4, 1), EnergySpec::second_order(0, 1, 1)), ParameterError);
}

TensorNet power_net(int n, int m, std::initializer_list<std::tuple<int, int, double>> terms) {
  Eigen::MatrixX3d c = Eigen::MatrixX3d::Zero((n + 1) * (m + 1), 3);
  for (auto [k, l, v] : terms) c(k * (m + 1) + l, 0) = v;
  return from_power(n, m, c);
}

TEST(PdeResidual, MatchesHandComputedValues) {
  const EnergySpec bih = EnergySpec::biharmonic();  // x_uuuu + 2 x_uuvv + x_vvvv
  // u^4: L = 24, scale = 24 -> 1.
  EXPECT_NEAR(pde_residual(power_net(4, 4, {{4, 0, 1.0}}), bih, 10), 1.0, 1e-12);
  // u^4 - u^2 v^2: L = 24 - 2*4 = 16, scale = 24 + 2*4 = 32 -> 0.5.
  EXPECT_NEAR(pde_residual(power_net(4, 4, {{4, 0, 1.0}, {2, 2, -1.0}}), bih, 10), 0.5, 1e-12);
  // u^4 - 3 u^2 v^2 is biharmonic: 0.
  EXPECT_LT(pde_residual(power_net(4, 4, {{4, 0, 1.0}, {2, 2, -3.0}}), bih, 10), 1e-13);
  // u^3 v under B x_uuuv with [1, 3, 0, 0, 0]: L = 3*6 = 18 where u^4 terms vanish -> 1.
  EXPECT_NEAR(pde_residual(power_net(4, 4, {{3, 1, 1.0}}), EnergySpec::pde_operator({1, 3, 0, 0, 0}), 10), 1.0, 1e-12);
  // Dirichlet: u^2 - v^2 harmonic; u^2 + v^2 gives |2 + 2| / (2 + 2) = 1; u^2 gives 1.
  EXPECT_LT(pde_residual(power_net(2, 2, {{2, 0, 1.0}, {0, 2, -1.0}}), EnergySpec::dirichlet(), 10), 1e-14);
  EXPECT_NEAR(pde_residual(power_net(2, 2, {{2, 0, 1.0}, {0, 2, 1.0}}), EnergySpec::dirichlet(), 10), 1.0, 1e-13);
  // Bilinear patch under a fourth-order operator: denominator 0 -> 0.
  EXPECT_EQ(pde_residual(power_net(1, 1, {{1, 1, 1.0}}), bih, 10), 0.0);
  EXPECT_THROW(pde_residual(power_net(1, 1, {{1, 1, 1.0}}), bih, 0), ParameterError);
}

}  // namespace
}  // namespace bpde
