// Arnal–Monterde–Ugail PDE solvers: explicit closed forms vs the Bernstein linear solve vs exact solutions.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bezierpde/core/errors.h"
#include "exact_polynomials.h"
#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/solvers/pde/pde_residual.h"
#include "bezierpde/tensor/power_basis.h"

namespace bpde {
namespace {

using namespace bpde::testing;
const double kPi = std::acos(-1.0);

// Relative tolerance for exact recovery at degree n <= 15 for the general operator below, where
// no mould is built: above the measured errors, far below the O(1) error of a wrong solve.
double tol(int n) { return 1e-13 * std::pow(10.0, std::max(0, n - 8)); }

struct OpCase {
  const char* name;
  EnergySpec op;
  std::vector<Root> roots;
};

std::vector<OpCase> operator_cases() {
  Eigen::Matrix2d G;
  G << 1.0, 0.4, -0.3, 0.8;  // columns e1 = (1, -0.3), e2 = (0.4, 0.8)
  const EnergySpec g = EnergySpec::gnorm(G);
  const auto& c = g.operator_coeffs();
  const double rho = std::sqrt(c[0] / c[4]), t = std::acos(c[1] / (2 * std::sqrt(c[0] * c[4])));
  return {
      {"biharmonic", EnergySpec::biharmonic(), biharmonic_roots()},
      {"laplacian-squared", EnergySpec::laplacian_squared(), biharmonic_roots()},
      {"modified-biharmonic 0.7", EnergySpec::modified_biharmonic(0.7), modified_biharmonic_roots(0.7)},
      {"modified-biharmonic 1.6", EnergySpec::modified_biharmonic(1.6), modified_biharmonic_roots(1.6)},
      {"gnorm 0.6 1.1", EnergySpec::gnorm(0.6, 1.1), gnorm_roots(0.6, 1.1)},
      {"gnorm 1.8 2.3", EnergySpec::gnorm(1.8, 2.3), gnorm_roots(1.8, 2.3)},
      {"gnorm 1.3 pi/2 (orthogonal)", EnergySpec::gnorm(1.3, kPi / 2), gnorm_roots(1.3, kPi / 2)},
      {"gnorm G matrix", g, gnorm_roots(rho, t)},
      {"operator 3 x gnorm(0.8, 0.7)",
       EnergySpec::pde_operator({3 * 0.64, 3 * 1.6 * std::cos(0.7), 3 * 1.64, 3 * 1.6 * std::cos(0.7), 3.0}),
       gnorm_roots(0.8, 0.7)},
      {"operator 2 x modified(1.2)", EnergySpec::pde_operator({2.0, 0.0, 2 * 2 * 1.44, 0.0, 2 * 1.44 * 1.44}),
       modified_biharmonic_roots(1.2)},
  };
}

TEST(PdeExplicitAndLu, RecoverExactSolutionsFromTheirBoundary) {
  for (const OpCase& c : operator_cases()) {
    for (int n : {5, 6, 7, 8, 9, 10, 12, 15, 20}) {
      const TensorNet exact = exact_solution(c.roots, n, 1000u + n);
      const TensorNet data = boundary_only(exact);
      const PdeSolution e = solve_pde_explicit(data, c.op);
      const PdeSolution l = solve_pde_lu(data, c.op);
      // The mould (the Bernstein system, factored once) gives the data-rounding floor.
      const PdeMould mould(c.op, n, n);
      const PdeSolution s = mould.solve(data);
      const double tolerance = floor_tolerance(floor_error(mould, exact));
      ASSERT_TRUE(e.summary.converged) << c.name << " n=" << n << ": " << e.summary.message;
      ASSERT_TRUE(l.summary.converged) << c.name << " n=" << n << ": " << l.summary.message;
      ASSERT_TRUE(s.summary.converged) << c.name << " n=" << n << ": " << s.summary.message;
      EXPECT_LT(relative_error(e.net, exact), tolerance) << c.name << " explicit n=" << n;
      EXPECT_LT(relative_error(l.net, exact), tolerance) << c.name << " lu n=" << n;
      EXPECT_LT(relative_error(s.net, exact), tolerance) << c.name << " mould n=" << n;
      if (n <= 8) {  // fourth derivatives at high degree cancel ~n^4 2^n-fold: check low n only
        EXPECT_LT(pde_residual(e.net, c.op, 20), 1e-10) << c.name << " n=" << n;
        EXPECT_LT(pde_residual(l.net, c.op, 20), 1e-10) << c.name << " n=" << n;
        EXPECT_LT(pde_residual(s.net, c.op, 20), 1e-10) << c.name << " n=" << n;
      }
      // The prescribed ring is returned exactly.
      for (int idx : data.boundary_indices()) {
        EXPECT_EQ(e.net.points().row(idx), data.points().row(idx));
        EXPECT_EQ(l.net.points().row(idx), data.points().row(idx));
        EXPECT_EQ(s.net.points().row(idx), data.points().row(idx));
      }
    }
  }
}

TEST(PdeExplicitAndLu, AgreeOnGenericBoundaries) {
  // Generic data: solutions are amplified (docs/errata.md), compare relative to the solution's size.
  for (const OpCase& c : operator_cases()) {
    for (int n : {4, 5, 7, 9, 11, 13}) {
      const TensorNet data = perturbed_grid_net(n, n, 77u + n);
      const PdeSolution e = solve_pde_explicit(data, c.op);
      const PdeSolution l = solve_pde_lu(data, c.op);
      ASSERT_TRUE(e.summary.converged && l.summary.converged) << c.name;
      EXPECT_LT(relative_error(e.net, l.net), 1e-12 * std::pow(4.0, n - 4)) << c.name << " n=" << n;
      EXPECT_LT(pde_residual(l.net, c.op, 20), 1e-9) << c.name << " n=" << n;
    }
  }
}

TEST(PdeExplicitAndLu, SmallDegrees) {
  for (int n = 1; n <= 4; ++n) {
    const TensorNet data = perturbed_grid_net(n, n, 5u + n);
    const PdeSolution e = solve_pde_explicit(data, EnergySpec::biharmonic());
    const PdeSolution l = solve_pde_lu(data, EnergySpec::biharmonic());
    ASSERT_TRUE(e.summary.converged && l.summary.converged) << n;
    EXPECT_LT(relative_error(e.net, l.net), 1e-13) << n;
    // n = 3: only x_uuvv exists and it vanishes; the residual's floor (pde_residual.h) keeps the
    // value at noise / (1e-8 x natural scale) instead of noise / noise.
    EXPECT_LT(pde_residual(l.net, EnergySpec::biharmonic(), 10), 1e-6) << n;
    EXPECT_LT(pde_residual(e.net, EnergySpec::biharmonic(), 10), 1e-6) << n;
  }
}

TensorNet coons_patch(const TensorNet& d) {
  // docs/errata.md: x = (1-u)x(0,v) + u x(1,v) + (1-v)x(u,0) + v x(u,1) - bilinear corners, at degree n.
  const int n = d.n(), m = d.m();
  TensorNet out(n, m);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      const double a = double(i) / n, b = double(j) / m;
      const Eigen::Vector3d p = (1 - a) * d.point(0, j) + a * d.point(n, j) + (1 - b) * d.point(i, 0) +
                                b * d.point(i, m) -
                                ((1 - a) * (1 - b) * d.point(0, 0) + (1 - a) * b * d.point(0, m) +
                                 a * (1 - b) * d.point(n, 0) + a * b * d.point(n, m));
      out.set_point(i, j, p);
    }
  return out;
}

TEST(PdeExplicitAndLu, CoonsEqualsTheBilinearlyBlendedPatch) {
  for (int n : {2, 3, 5, 8, 12, 16, 20}) {
    const TensorNet data = perturbed_grid_net(n, n, 300u + n);
    const TensorNet truth = coons_patch(data);
    const PdeSolution e = solve_pde_explicit(data, EnergySpec::coons());
    const PdeSolution l = solve_pde_lu(data, EnergySpec::coons());
    const PdeSolution o = solve_pde_explicit(data, EnergySpec::pde_operator({0, 0, 2.5, 0, 0}));
    ASSERT_TRUE(e.summary.converged && l.summary.converged && o.summary.converged);
    // The Coons map is well conditioned; both routes still go through the power basis, whose
    // conversion matrices grow like 3^n: the explicit route in double, lu in long double (2^-64).
    EXPECT_LT(relative_error(e.net, truth), 1e-15 * std::pow(3.0, n)) << n;
    EXPECT_LT(relative_error(o.net, truth), 1e-15 * std::pow(3.0, n)) << n;
    EXPECT_LT(relative_error(l.net, truth), std::max(1e-15, 1e-19 * std::pow(3.0, n))) << n;
  }
}

TEST(PdeExplicit, DegenerateParametersGiveFiniteAnswersEqualToLu) {
  struct P {
    double rho, t;
  };
  // t = 0, pi: csc t in eq. (12); rho = 1 at t = pi/2: biharmonic limit of §5.2.4; near-misses of
  // both; rho > 1 (transposed route).
  const std::vector<P> params = {{2.0, 0.0},  {0.5, kPi},        {1.0, kPi / 2},        {1.0 + 1e-9, kPi / 2},
                                 {0.7, 1e-9}, {1.4, kPi - 1e-9}, {1.0, kPi / 2 - 1e-7}, {1.0 - 1e-7, kPi / 2 + 1e-6},
                                 {3.0, 0.3},  {0.3, 2.9}};
  for (const P& p : params) {
    const EnergySpec op = gnorm_operator(p.rho, p.t);  // t = 0, pi: a singular G, a valid operator
    for (int n : {4, 7, 10}) {
      const TensorNet data = perturbed_grid_net(n, n, 900u + n);
      const PdeSolution e = solve_pde_explicit(data, op);
      const PdeSolution l = solve_pde_lu(data, op);
      ASSERT_TRUE(e.summary.converged) << p.rho << " " << p.t << " n=" << n << ": " << e.summary.message;
      ASSERT_TRUE(l.summary.converged) << p.rho << " " << p.t << " n=" << n << ": " << l.summary.message;
      ASSERT_TRUE(e.net.points().allFinite());
      EXPECT_LT(relative_error(e.net, l.net), 1e-9) << p.rho << " " << p.t << " n=" << n;
    }
  }
  // rho = 1 in the orthogonal formula equals the biharmonic solution.
  const TensorNet data = perturbed_grid_net(9, 9, 4);
  EXPECT_LT(relative_error(solve_pde_explicit(data, EnergySpec::gnorm(1.0, kPi / 2)).net,
                           solve_pde_explicit(data, EnergySpec::biharmonic()).net),
            1e-14);
}

TEST(PdeExplicitAndLu, RhoOneNonOrthogonalIsNotUnique) {
  // rho = 1, t = 0: L = (d_u^2 + d_v^2)(d_u + d_v)^2 kills u^2 v^2 (u - v), which vanishes on the
  // boundary ring from n = 4 on: no unique solution. Both methods must say so, not return noise.
  const EnergySpec op = gnorm_operator(1.0, 0.0);
  for (int n : {4, 6}) {
    const TensorNet data = perturbed_grid_net(n, n, 3);
    const PdeSolution e = solve_pde_explicit(data, op);
    const PdeSolution l = solve_pde_lu(data, op);
    EXPECT_FALSE(e.summary.converged);
    EXPECT_FALSE(l.summary.converged);
    EXPECT_EQ(e.summary.status, Status::NotUnique) << e.summary.message;
    EXPECT_EQ(l.summary.status, Status::NotUnique) << l.summary.message;
    EXPECT_FALSE(e.summary.message.empty());
    EXPECT_FALSE(l.summary.message.empty());
  }
  // Check the kernel claim itself with pde_residual: x = u^2 v^2 (u - v) has L x = 0.
  Eigen::MatrixX3d c = Eigen::MatrixX3d::Zero(16, 3);
  c(3 * 4 + 2, 0) = 1;   // u^3 v^2
  c(2 * 4 + 3, 0) = -1;  // - u^2 v^3
  EXPECT_LT(pde_residual(from_power(3, 3, c), op, 10), 1e-14);
  // t = pi/4 with rho = 1: the anti-diagonal blocks k + l = 8, 9, 10 are singular (M_s = 0), which
  // the anti-diagonal analysis sees from n = 6 on (block 8 lies inside the (6,6) box).
  EXPECT_TRUE(solve_pde_lu(perturbed_grid_net(5, 5, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.converged);
  EXPECT_FALSE(solve_pde_lu(perturbed_grid_net(6, 6, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.converged);
  EXPECT_FALSE(solve_pde_lu(perturbed_grid_net(7, 7, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.converged);
  EXPECT_EQ(solve_pde_lu(perturbed_grid_net(6, 6, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.status,
            Status::NotUnique);
  EXPECT_TRUE(solve_pde_explicit(perturbed_grid_net(5, 5, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.converged);
  EXPECT_FALSE(solve_pde_explicit(perturbed_grid_net(6, 6, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.converged);
  EXPECT_FALSE(solve_pde_explicit(perturbed_grid_net(7, 7, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.converged);
  EXPECT_EQ(solve_pde_explicit(perturbed_grid_net(7, 7, 1), EnergySpec::gnorm(1.0, kPi / 4)).summary.status,
            Status::NotUnique);
  // Off rho = 1 the solution is unique again (and both routes agree).
  const TensorNet d = perturbed_grid_net(8, 8, 2);
  const PdeSolution e8 = solve_pde_explicit(d, EnergySpec::gnorm(1.05, kPi / 4));
  const PdeSolution l8 = solve_pde_lu(d, EnergySpec::gnorm(1.05, kPi / 4));
  ASSERT_TRUE(e8.summary.converged && l8.summary.converged);
  EXPECT_LT(relative_error(e8.net, l8.net), 1e-9);
}

TEST(PdeExplicit, WrongOperatorsAreUnsupported) {
  const TensorNet data = perturbed_grid_net(6, 6, 1);
  try {
    solve_pde_explicit(data, EnergySpec::pde_operator({1.0, 0.5, 3.0, -0.7, 2.0}));
    FAIL() << "expected UnsupportedProblem";
  } catch (const UnsupportedProblem& e) {
    EXPECT_NE(std::string(e.what()).find("\"lu\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(solve_pde_explicit(data, EnergySpec::fourth_order({1, 0, 1, 0, 1})), UnsupportedProblem);
  EXPECT_THROW(solve_pde_explicit(data, EnergySpec::dirichlet()), UnsupportedProblem);
  EXPECT_THROW(solve_pde_explicit(perturbed_grid_net(5, 6, 1), EnergySpec::biharmonic()), DegreeError);
  EXPECT_THROW(solve_pde_lu(data, EnergySpec::dirichlet()), UnsupportedProblem);
  // Non-elliptic: modified biharmonic with alpha = 0 is x_uuuu = 0.
  EXPECT_THROW(solve_pde_explicit(data, EnergySpec::modified_biharmonic(0.0)), ParameterError);
  const PdeSolution flat = solve_pde_lu(data, EnergySpec::modified_biharmonic(0.0));
  EXPECT_FALSE(flat.summary.converged);
  EXPECT_EQ(flat.summary.status, Status::NotUnique) << flat.summary.message;
  EXPECT_FALSE(flat.summary.message.empty());
  TensorNet out(6, 6);
  EXPECT_THROW(PdeMould(EnergySpec::modified_biharmonic(0.0), 6, 6).apply(data, out), UnsupportedProblem);
  PdeExplicitOptions bad;
  bad.singular_tolerance = 0;
  EXPECT_THROW(solve_pde_explicit(data, EnergySpec::biharmonic(), bad), ParameterError);
}

TEST(PdeLu, GeneralEllipticOperatorRecoversExactSolutions) {
  // An operator with no closed form, built from two root pairs mu1, mu2:
  // A + B mu + C mu^2 + D mu^3 + E mu^4 = |mu - mu1|^2 |mu - mu2|^2 (as polynomials).
  const std::complex<double> m1(0.3, 1.1), m2(-0.8, 0.6);
  const double s1 = 2 * m1.real(), p1 = std::norm(m1), s2 = 2 * m2.real(), p2 = std::norm(m2);
  // (mu^2 - s1 mu + p1)(mu^2 - s2 mu + p2)
  const std::array<double, 5> c = {p1 * p2, -(s1 * p2 + s2 * p1), p1 + p2 + s1 * s2, -(s1 + s2), 1.0};
  const EnergySpec op = EnergySpec::pde_operator(c);
  const std::vector<Root> roots = {{cld(m1.real(), m1.imag()), false}, {cld(m2.real(), m2.imag()), false}};
  for (int n : {4, 6, 9, 12, 15}) {
    const TensorNet exact = exact_solution(roots, n, 50u + n);
    const PdeSolution l = solve_pde_lu(boundary_only(exact), op);
    ASSERT_TRUE(l.summary.converged) << l.summary.message;
    EXPECT_LT(relative_error(l.net, exact), tol(n)) << n;
  }
}

TEST(PdeLu, UnequalDegrees) {
  // Bidegree (n, m), n != m: the data must meet compatibility conditions. Boundaries of an exact
  // solution of total degree <= min(n, m) meet them; generic data do not.
  for (auto [n, m] : {std::pair{6, 8}, std::pair{9, 5}}) {
    const auto mono = exact_monomials(biharmonic_roots(), std::min(n, m), 11);
    const TensorNet exact = exact_net(mono, n, m);
    const PdeMould mould(EnergySpec::biharmonic(), n, m);
    EXPECT_TRUE(mould.structure().unique);
    EXPECT_GT(mould.structure().conditions, 0);
    const PdeSolution ok = mould.solve(boundary_only(exact));
    ASSERT_TRUE(ok.summary.converged) << ok.summary.message;
    EXPECT_EQ(ok.summary.status, Status::Converged);
    EXPECT_LT(relative_error(ok.net, exact), 1e-10);
    const PdeSolution l = solve_pde_lu(boundary_only(exact), EnergySpec::biharmonic());
    ASSERT_TRUE(l.summary.converged) << l.summary.message;
    EXPECT_LT(relative_error(l.net, exact), 1e-10);
    const PdeSolution bad = mould.solve(perturbed_grid_net(n, m, 2));
    EXPECT_FALSE(bad.summary.converged);
    EXPECT_EQ(bad.summary.status, Status::Incompatible) << bad.summary.message;
    EXPECT_FALSE(bad.summary.message.empty());
  }
}

TEST(PdeMould, OneProductPerSolveEqualsTheOneShotSolve) {
  const int n = 11;
  const PdeMould mould(EnergySpec::gnorm(0.7, 1.0), n, n);
  EXPECT_EQ(mould.interior_from_boundary().rows(), (n - 1) * (n - 1));
  EXPECT_EQ(mould.interior_from_boundary().cols(), 4 * n);
  for (unsigned seed = 0; seed < 3; ++seed) {
    const TensorNet data = perturbed_grid_net(n, n, seed);
    const PdeSolution a = mould.solve(data);
    const PdeSolution b = solve_pde_lu(data, EnergySpec::gnorm(0.7, 1.0));  // anti-diagonal blocks
    PdeLuOptions dense;
    dense.formulation = PdeLuOptions::Formulation::Bernstein;
    const PdeSolution c = solve_pde_lu(data, EnergySpec::gnorm(0.7, 1.0), dense);
    ASSERT_TRUE(a.summary.converged && b.summary.converged && c.summary.converged);
    EXPECT_LT(relative_error(a.net, b.net), 1e-12);
    EXPECT_LT(relative_error(c.net, b.net), 1e-12);
    TensorNet out(n, n);
    mould.apply(data, out);
    EXPECT_EQ(out.points(), a.net.points());
  }
  EXPECT_THROW(mould.solve(perturbed_grid_net(n, n - 1, 1)), DegreeError);
}

TEST(PdeExplicit, Lemma1ClosedFormMatchesItsRecurrence) {
  for (auto [rho, t] : {std::pair{0.6, 1.1}, std::pair{1.7, 0.9}, std::pair{0.9, 2.8}, std::pair{1.0, 1.0}}) {
    const Eigen::MatrixXd a = lemma1_sequences(rho, t, 24, true), b = lemma1_sequences(rho, t, 24, false);
    // Initial values are the unit vectors.
    EXPECT_LT((a.leftCols(4) - Eigen::MatrixXd::Identity(4, 4)).cwiseAbs().maxCoeff(), 1e-14);
    for (int l = 0; l <= 24; ++l)
      EXPECT_LT((a.col(l) - b.col(l)).cwiseAbs().maxCoeff(), 1e-12 * (1 + b.col(l).cwiseAbs().maxCoeff()))
          << rho << " " << t << " l=" << l;
  }
  EXPECT_THROW(lemma1_sequences(1.0, 0.0, 10, true), ParameterError);
}

TEST(PdeExplicit, ModifiedBiharmonicExponentIsFloorKOver2) {
  // docs/errata.md: (-alpha^2)^{floor(k/2)}, not floor(l/2); the printed version is wrong from n = 7.
  // Exact recovery above already covers it; here check directly that n = 7 and 8 are exact with
  // alpha far from 1 (where the two exponents differ most).
  for (int n : {7, 8}) {
    const TensorNet exact = exact_solution(modified_biharmonic_roots(2.5), n, 3);
    const PdeSolution e = solve_pde_explicit(boundary_only(exact), EnergySpec::modified_biharmonic(2.5));
    EXPECT_LT(relative_error(e.net, exact), 1e-11) << n;
  }
}

TEST(PdeLu, BlockRankDecisionsMatchTheStructureAnalysis) {
  // Two independent uniqueness decisions: pivots of the anti-diagonal block LU (solve_pde_lu,
  // n = m) and singular values of the monomial blocks (analyse_pde_structure, used by the mould).
  // The G-norm with rho = 1 puts every characteristic root on the unit circle, where blocks
  // become singular at degree-dependent anti-diagonals (docs/pde_accuracy.md).
  int singular = 0, unique = 0;
  for (double t : {0.0, kPi / 6, kPi / 4, kPi / 3, kPi / 2, 2.0})
    for (int n = 4; n <= 14; ++n) {
      const EnergySpec op = gnorm_operator(1.0, t);
      const auto& c = op.operator_coeffs();
      const PdeStructure st = analyse_pde_structure({c[0], c[1], c[2], c[3], c[4]}, n, n, FixedSet::Boundary);
      const PdeSolution l = solve_pde_lu(perturbed_grid_net(n, n, 9u + n), op);
      EXPECT_EQ(l.summary.converged, st.unique) << "t=" << t << " n=" << n << ": " << l.summary.message;
      EXPECT_EQ(l.summary.status, st.unique ? Status::Converged : Status::NotUnique) << "t=" << t << " n=" << n;
      (st.unique ? unique : singular) += 1;
    }
  // The sweep must exercise both outcomes, or it proves nothing.
  EXPECT_GT(singular, 5);
  EXPECT_GT(unique, 5);
}

}  // namespace
}  // namespace bpde
