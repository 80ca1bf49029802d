// Extremals of quadratic energies against independent truths: polynomial reproduction (bilinear,
// harmonic and biharmonic polynomials), docs/errata.md (laplacian-squared vs biharmonic), energy
// minimality against perturbations, mould vs factored vs generic Bernstein path, and the errors.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/energies/quadratic_energy.h"
#include "bezierpde/energies/tensor_gram.h"
#include "bezierpde/solvers/extremal.h"
#include "tests/random_points.h"

namespace bpde {
namespace {

using testing::random_points;

// Net of the polynomial patch x(u,v) = Σ_kl C[c](k,l) u^k v^l (power coefficients per coordinate,
// each (n+1) x (m+1)), exactly via the power -> Bernstein matrices.
TensorNet polynomial_net(int n, int m, const std::array<Eigen::MatrixXd, 3>& C) {
  const Eigen::MatrixXd Mu = power_to_bernstein_matrix(n), Mv = power_to_bernstein_matrix(m);
  Eigen::MatrixX3d P((n + 1) * (m + 1), 3);
  for (int c = 0; c < 3; ++c) {
    const Eigen::MatrixXd B = Mu * C[static_cast<size_t>(c)] * Mv.transpose();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) P(i * (m + 1) + j, c) = B(i, j);
  }
  return TensorNet(n, m, P);
}

// x = (u, v, z(u,v)) with z given by power coefficients (list of (k, l, coefficient)).
TensorNet graph_net(int n, int m, const std::vector<std::tuple<int, int, double>>& z) {
  std::array<Eigen::MatrixXd, 3> C{Eigen::MatrixXd::Zero(n + 1, m + 1), Eigen::MatrixXd::Zero(n + 1, m + 1),
                                   Eigen::MatrixXd::Zero(n + 1, m + 1)};
  C[0](1, 0) = 1;
  C[1](0, 1) = 1;
  for (auto [k, l, a] : z) C[2](k, l) += a;
  return polynomial_net(n, m, C);
}

// Keep the fixed points of `truth`, scramble the others.
TensorNet scrambled(const TensorNet& truth, FixedSet fixed) {
  TensorNet t = truth;
  const Eigen::MatrixX3d R = random_points(truth.size(), 99);
  for (int I : truth.free_indices(fixed)) t.points().row(I) = R.row(I);
  return t;
}

double max_diff(const TensorNet& a, const TensorNet& b) { return (a.points() - b.points()).cwiseAbs().maxCoeff(); }

// Backward-stable accuracy of X_f = M X_b: rounding the data alone moves the exact answer by
// about eps * |M|_inf * |X_b|_max, and |M| grows fast with the degree (~3e6 at n = 20). Tolerance:
// 1e-13 * that bound (a few hundred ulps of the amplified data).
double stable_tolerance(const ExtremalSolver& s, const TensorNet& data) {
  double xb = 0;
  for (int I : s.fixed_indices()) xb = std::max(xb, data.points().row(I).cwiseAbs().maxCoeff());
  return 1e-13 * s.mould().rowwise().lpNorm<1>().maxCoeff() * xb;
}

TEST(Extremal, BilinearBoundaryGivesTheBilinearPatch) {
  // Corners of a skew quadrilateral; the bilinear patch is harmonic (Δ = 0), and its x_uu = x_vv = 0,
  // x_uv constant make it the extremal of every energy symmetric in that sense (weak form: ∫ φ_uv = 0
  // for φ vanishing on the boundary).
  const Eigen::Vector3d A(0, 0, 0), B(2, 0.3, 1), C(1.8, 2.1, -0.5), D(-0.2, 1.5, 0.7);
  for (auto [n, m] : std::vector<std::pair<int, int>>{{2, 2}, {5, 4}, {7, 9}}) {
    TensorNet bil(n, m);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j) {
        const double u = double(i) / n, v = double(j) / m;
        bil.set_point(i, j, (1 - u) * (1 - v) * A + u * (1 - v) * B + u * v * C + (1 - u) * v * D);
      }
    for (const auto& e :
         {EnergySpec::dirichlet(), EnergySpec::biharmonic(), EnergySpec::laplacian_squared(), EnergySpec::coons(),
          EnergySpec::modified_biharmonic(0.7), EnergySpec::second_order(2, 0, 3)}) {
      const ExtremalResult r = solve_extremal(scrambled(bil, FixedSet::Boundary), e, FixedSet::Boundary);
      EXPECT_LE(max_diff(r.net, bil), 1e-12) << e.name() << " n=" << n << " m=" << m;
      EXPECT_TRUE(r.summary.converged) << r.summary.message;
    }
  }
}

TEST(Extremal, HarmonicPolynomialIsTheDirichletExtremalUpToDegree20) {
  // z = u^3 - 3uv^2 + uv is harmonic: the Galerkin (Dirichlet) extremal reproduces it exactly at
  // any degree that contains it. Degree 20 is far beyond where the Bernstein-basis system is
  // numerically singular; the conditioned path must still be exact.
  for (int n : {3, 8, 14, 20}) {
    const TensorNet truth = graph_net(n, n, {{3, 0, 1.0}, {1, 2, -3.0}, {1, 1, 1.0}});
    ExtremalOptions cached;
    cached.use_cache = true;
    const ExtremalResult r =
        solve_extremal(scrambled(truth, FixedSet::Boundary), EnergySpec::dirichlet(), FixedSet::Boundary, cached);
    const double tol =
        stable_tolerance(*ExtremalSolver::cached(EnergySpec::dirichlet(), n, n, FixedSet::Boundary), truth);
    EXPECT_LE(tol, n <= 8 ? 1e-10 : 1e-4);  // the bound is not vacuous
    EXPECT_LE(max_diff(r.net, truth), tol) << n;
    // the surface itself is accurate far beyond the coefficients
    for (double u : {0.1, 0.5, 0.77})
      for (double v : {0.05, 0.4, 0.9})
        EXPECT_LE((r.net.evaluate(u, v) - truth.evaluate(u, v)).norm(), n <= 14 ? 1e-12 : 1e-9) << n;
    EXPECT_NEAR(r.energy, energy_value(truth, EnergySpec::dirichlet()), 1e-10);
  }
}

TEST(Extremal, BiharmonicPolynomialWithC1DataIsTheExtremalOfBothFourthOrderEnergies) {
  // z = u^4 - v^4 + u^3 v - 2 u v^3 satisfies Δ²z = 0. With the outer two rings fixed, both
  // biharmonic and laplacian-squared extremals reproduce it (same Euler–Lagrange operator, test
  // functions with zero C1 boundary data); up to degree 20.
  for (int n : {4, 6, 11, 20}) {
    const TensorNet truth = graph_net(n, n, {{4, 0, 1.0}, {0, 4, -1.0}, {3, 1, 1.0}, {1, 3, -2.0}});
    const TensorNet data = scrambled(truth, FixedSet::BoundaryAdjacent);
    const ExtremalSolver sb(EnergySpec::biharmonic(), n, n, FixedSet::BoundaryAdjacent);
    const ExtremalSolver sl(EnergySpec::laplacian_squared(), n, n, FixedSet::BoundaryAdjacent);
    EXPECT_LE(max_diff(sb.solve(data), truth), stable_tolerance(sb, truth)) << n;
    EXPECT_LE(max_diff(sl.solve(data), truth), stable_tolerance(sl, truth)) << n;
    EXPECT_LE(stable_tolerance(sb, truth), n <= 6 ? 1e-11 : 1e-4);
  }
}

TEST(Extremal, LaplacianSquaredAndBiharmonicDifferWithOnlyTheBoundaryFixed) {
  // docs/errata.md: with C0 data the two functionals have different extremals, and neither is the
  // biharmonic polynomial the data came from; the extremal has lower energy than that polynomial.
  const int n = 6;
  const TensorNet truth = graph_net(n, n, {{4, 0, 1.0}, {0, 4, -1.0}, {3, 1, 1.0}, {1, 3, -2.0}});
  const TensorNet data = scrambled(truth, FixedSet::Boundary);
  const ExtremalResult b = solve_extremal(data, EnergySpec::biharmonic(), FixedSet::Boundary);
  const ExtremalResult l = solve_extremal(data, EnergySpec::laplacian_squared(), FixedSet::Boundary);
  EXPECT_GT(max_diff(b.net, l.net), 1e-2);
  EXPECT_GT(max_diff(b.net, truth), 1e-2);
  EXPECT_LT(b.energy, energy_value(truth, EnergySpec::biharmonic()));
  EXPECT_LT(l.energy, energy_value(truth, EnergySpec::laplacian_squared()));
}

TEST(Extremal, EnergyIsMinimalAgainstPerturbationsOfTheFreePoints) {
  std::mt19937 g(5);
  std::normal_distribution<double> N01;
  for (const auto& e : {EnergySpec::biharmonic(), EnergySpec::laplacian_squared(), EnergySpec::gnorm(1.4, 1.0),
                        EnergySpec::fourth_order({1.0, 0.3, 2.2, -0.4, 0.8}), EnergySpec::second_order(1.0, 0.5, 2.0)})
    for (FixedSet fs : {FixedSet::Boundary, FixedSet::BoundaryAdjacent, FixedSet::UBoundaries}) {
      const int n = 6, m = 5;
      const TensorNet data(n, m, random_points((n + 1) * (m + 1), 17));
      const ExtremalResult r = solve_extremal(data, e, fs);
      const QuadraticEnergy E = QuadraticEnergy::tensor(e, n, m);
      EXPECT_NEAR(r.energy, E.value(r.net.points()), 1e-12 * std::max(1.0, r.energy));
      // gradient over the free points vanishes
      const Eigen::MatrixX3d G = E.gradient(r.net.points());
      for (int I : data.free_indices(fs))
        EXPECT_LE(G.row(I).cwiseAbs().maxCoeff(), 1e-9 * std::max(1.0, r.energy)) << e.name();
      for (int trial = 0; trial < 10; ++trial) {
        Eigen::MatrixX3d P = r.net.points();
        for (int I : data.free_indices(fs))
          for (int c = 0; c < 3; ++c) P(I, c) += 1e-3 * N01(g);
        EXPECT_GT(E.value(P), r.energy) << e.name() << " " << to_string(fs);
      }
      // fixed points untouched
      for (int I : data.fixed_indices(fs)) EXPECT_EQ(r.net.points().row(I), data.points().row(I));
    }
}

TEST(Extremal, MouldEqualsFactoredEqualsGenericBernsteinPath) {
  for (const auto& e : {EnergySpec::dirichlet(), EnergySpec::laplacian_squared(), EnergySpec::coons(),
                        EnergySpec::gnorm((Eigen::Matrix2d() << 1.0, 0.5, -0.3, 2.0).finished())})
    for (FixedSet fs : {FixedSet::Boundary, FixedSet::BoundaryAdjacent})
      for (auto [n, m] : std::vector<std::pair<int, int>>{{4, 4}, {7, 5}, {10, 10}}) {
        const Eigen::MatrixX3d P = random_points((n + 1) * (m + 1), 3);
        const ExtremalSolver s(e, n, m, fs);
        const TensorNet shape(n, m);
        const ExtremalSolver generic(tensor_gram(e, n, m), shape.fixed_indices(fs));
        ExtremalOptions bern;
        bern.conditioned_basis = false;
        const ExtremalSolver s2(e, n, m, fs, bern);
        const Eigen::MatrixX3d a = s.solve(P), b = s.solve_factored(P), c = generic.solve(P), d = s2.solve(P);
        const double scale = a.cwiseAbs().maxCoeff();
        EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-12 * scale);
        EXPECT_LE((a - c).cwiseAbs().maxCoeff(), 1e-8 * scale) << e.name() << " n=" << n;
        EXPECT_LE((c - d).cwiseAbs().maxCoeff(), 1e-12 * scale);
        EXPECT_EQ(s.mould().rows(), static_cast<Eigen::Index>(s.free_indices().size()));
        EXPECT_EQ(s.mould().cols(), static_cast<Eigen::Index>(s.fixed_indices().size()));
      }
}

TEST(Extremal, HighDegreeIsAcceptedAndStaysFinite) {
  // One boundary curve (degree 8 net, elevated): the spaces are nested, so the extremal energy
  // decreases as the degree grows; it stays positive even where the Bernstein coefficients reach
  // 1e9 and the Bernstein-sum energy cancels away.
  TensorNet base(8, 8);
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double u = i / 8.0, v = j / 8.0;
      base.set_point(i, j, Eigen::Vector3d(u, v, std::sin(3 * u) + std::cos(2 * v + 1) * u));
    }
  double previous = 1e300;
  for (int n : {8, 12, 16, 20, 30}) {
    const TensorNet data = base.elevated(n - 8, n - 8);
    const ExtremalResult r = solve_extremal(data, EnergySpec::biharmonic(), FixedSet::Boundary);
    EXPECT_TRUE(r.summary.converged) << n << " " << r.summary.message;
    EXPECT_EQ(r.summary.status, Status::Converged) << n;
    EXPECT_LE(r.summary.residual, 1e-14);
    EXPECT_TRUE(r.net.points().allFinite());
    EXPECT_GT(r.energy, 0.0);
    EXPECT_LE(r.energy, previous * (1 + 1e-12)) << n;
    if (n <= 12) {
      EXPECT_NEAR(r.energy, energy_value(r.net, EnergySpec::biharmonic()), 1e-10 * r.energy);
    }
    previous = r.energy;
  }
  // The generic Bernstein path refuses rather than return garbage at degree 20.
  const TensorNet shape(20, 20);
  EXPECT_THROW(ExtremalSolver(tensor_gram(EnergySpec::biharmonic(), 20, 20), shape.fixed_indices(FixedSet::Boundary)),
               ParameterError);
}

TEST(Extremal, SingularOrIndefiniteReducedSystemsAreRejected) {
  // x_vv only, u-boundaries: x = v * g(u) with g vanishing at u = 0, 1 has zero energy.
  EXPECT_THROW(ExtremalSolver(EnergySpec::fourth_order({0, 0, 0, 0, 1}), 5, 5, FixedSet::UBoundaries), ParameterError);
  EXPECT_THROW(ExtremalSolver(EnergySpec::second_order(0, 0, 1), 5, 4, FixedSet::UBoundaries), ParameterError);
  // the zero energy
  EXPECT_THROW(ExtremalSolver(EnergySpec::fourth_order({0, 0, 0, 0, 0}), 4, 4, FixedSet::Boundary), ParameterError);
  // non-elliptic: symbol ξ⁴ - 3ξ²η² + η⁴ < 0 at ξ = η; second order with b² > 4ac
  for (int n : {4, 8, 16})
    EXPECT_THROW(ExtremalSolver(EnergySpec::fourth_order({1, 0, -3, 0, 1}), n, n, FixedSet::Boundary), ParameterError)
        << n;
  // (a - b + c < 0: oscillations along u = -v have negative energy; degree 4 is still too coarse
  // to contain one, degree 6 is not)
  EXPECT_NO_THROW(ExtremalSolver(EnergySpec::second_order(1, 3, 1), 4, 4, FixedSet::Boundary));
  for (int n : {6, 8, 12, 20})
    EXPECT_THROW(ExtremalSolver(EnergySpec::second_order(1, 3, 1), n, n, FixedSet::Boundary), ParameterError) << n;
  const TensorNet shape(6, 6);
  EXPECT_THROW(
      ExtremalSolver(tensor_gram(EnergySpec::second_order(1, 3, 1), 6, 6), shape.fixed_indices(FixedSet::Boundary)),
      ParameterError);
  // but x_uu only with u-boundaries is fine: x = a(v) + u b(v) vanishing at u = 0, 1 is zero
  EXPECT_NO_THROW(ExtremalSolver(EnergySpec::fourth_order({1, 0, 0, 0, 0}), 5, 5, FixedSet::UBoundaries));
  // and coons is positive definite with the boundary fixed, even at the lowest degree
  EXPECT_NO_THROW(ExtremalSolver(EnergySpec::coons(), 2, 2, FixedSet::Boundary));
}

TEST(Extremal, MinimumDegreesAndBadInput) {
  EXPECT_THROW(ExtremalSolver(EnergySpec::dirichlet(), 1, 3, FixedSet::Boundary), DegreeError);
  EXPECT_THROW(ExtremalSolver(EnergySpec::biharmonic(), 3, 5, FixedSet::BoundaryAdjacent), DegreeError);
  EXPECT_THROW(ExtremalSolver(EnergySpec::biharmonic(), 5, 3, FixedSet::BoundaryAdjacent), DegreeError);
  EXPECT_NO_THROW(ExtremalSolver(EnergySpec::biharmonic(), 4, 4, FixedSet::BoundaryAdjacent));
  EXPECT_NO_THROW(ExtremalSolver(EnergySpec::biharmonic(), 2, 2, FixedSet::Boundary));
  EXPECT_THROW(ExtremalSolver(EnergySpec::dirichlet(), 65, 3, FixedSet::Boundary), DegreeError);
  ExtremalOptions bad;
  bad.singular_tolerance = -1;
  EXPECT_THROW(ExtremalSolver(EnergySpec::dirichlet(), 3, 3, FixedSet::Boundary, bad), ParameterError);
  const ExtremalSolver s(EnergySpec::dirichlet(), 3, 3, FixedSet::Boundary);
  EXPECT_THROW(s.solve(Eigen::MatrixX3d::Zero(15, 3)), SizeError);
  EXPECT_THROW(ExtremalSolver(Eigen::MatrixXd::Identity(4, 4), {0, 4}), SizeError);
  EXPECT_THROW(ExtremalSolver(Eigen::MatrixXd::Identity(4, 4), {0, 0}), SizeError);
  EXPECT_THROW(ExtremalSolver(Eigen::MatrixXd::Identity(4, 4), {0, 1, 2, 3}), ParameterError);
  EXPECT_THROW(ExtremalSolver(Eigen::MatrixXd::Identity(4, 3), {0}), SizeError);
}

TEST(Extremal, CacheReturnsTheSameSolver) {
  const auto a = ExtremalSolver::cached(EnergySpec::biharmonic(), 6, 5, FixedSet::Boundary);
  const auto b = ExtremalSolver::cached(EnergySpec::biharmonic(), 6, 5, FixedSet::Boundary);
  const auto c = ExtremalSolver::cached(EnergySpec::laplacian_squared(), 6, 5, FixedSet::Boundary);
  EXPECT_EQ(a.get(), b.get());
  EXPECT_NE(a.get(), c.get());
  ExtremalOptions o;
  o.use_cache = true;
  const TensorNet data(6, 5, random_points(42, 8));
  EXPECT_LE(max_diff(solve_extremal(data, EnergySpec::biharmonic(), FixedSet::Boundary, o).net,
                     solve_extremal(data, EnergySpec::biharmonic(), FixedSet::Boundary).net),
            1e-14);
}

// The triangular one-off solve: an affine surface is the extremal of every energy for its own
// boundary (its energy density is constant, all Euler–Lagrange operators vanish on it), so the
// interior points come back as the affine images of their Greville parameters (i/n, j/n).
TEST(Extremal, TriangularSolveReproducesAffineSurfaces) {
  const Eigen::Vector3d b(0.5, -1.0, 2.0), a_u(1.0, 0.25, -0.5), a_v(-0.3, 1.0, 0.75);
  for (int n : {3, 5, 8}) {
    TriangularNet data(n);
    Eigen::MatrixX3d exact(data.points().rows(), 3);
    int row = 0;
    for (int i = n; i >= 0; --i)
      for (int j = n - i; j >= 0; --j) exact.row(row++) = (b + a_u * i / n + a_v * j / n).transpose();
    data.points() = exact;
    TriangularNet boundary_only = data;  // the free points are ignored: scramble them
    for (int I : boundary_only.free_indices(FixedSet::Boundary)) boundary_only.points().row(I).setConstant(9.0);
    for (const EnergySpec& e : {EnergySpec::dirichlet(), EnergySpec::biharmonic()}) {
      const TriangularExtremalResult r = solve_extremal(boundary_only, e, FixedSet::Boundary);
      EXPECT_LE((r.net.points() - exact).cwiseAbs().maxCoeff(), 1e-12) << n << " " << e.name();
      EXPECT_TRUE(r.summary.converged);
      EXPECT_EQ(r.summary.status, Status::Converged);
      EXPECT_LE(r.summary.residual, kConvergenceTolerance);
      EXPECT_GE(r.summary.seconds, 0.0);
      EXPECT_TRUE(std::isfinite(r.energy));
    }
  }
  // Zero boundary data: the zero net, of energy exactly 0.
  TriangularNet d(4);
  const TriangularExtremalResult r = solve_extremal(d, EnergySpec::dirichlet(), FixedSet::Boundary);
  EXPECT_EQ(r.energy, 0.0);
  EXPECT_LE(r.net.points().cwiseAbs().maxCoeff(), 0.0);
  ExtremalOptions bad;
  bad.singular_tolerance = 2.0;
  EXPECT_THROW(solve_extremal(d, EnergySpec::dirichlet(), FixedSet::Boundary, bad), ParameterError);
  // degree 5 with C1 data has no free point
  EXPECT_THROW(solve_extremal(TriangularNet(5), EnergySpec::biharmonic(), FixedSet::BoundaryAdjacent), ParameterError);
}

}  // namespace
}  // namespace bpde
