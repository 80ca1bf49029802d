// Tests of the discrete smoothing PDE spline (Pasadas–Rodríguez; solvers/blend/smoothing_spline.h).
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>
#include <numbers>
#include <random>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/solvers/blend/smoothing_spline.h"

namespace bpde {
namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

/// Edges of the problem from a function U with its y-derivative.
SmoothingSplineProblem problem_from(int k, int l, double a, double eps,
                                    const std::function<Eigen::Vector3d(double, double)>& U,
                                    const std::function<Eigen::Vector3d(double, double)>& Uy) {
  SmoothingSplineProblem p;
  p.k = k;
  p.l = l;
  p.a = a;
  p.epsilon = eps;
  p.y0_value.resize(k + 1, 3);
  p.y0_dy.resize(k + 1, 3);
  p.y1_value.resize(k + 1, 3);
  p.y1_dy.resize(k + 1, 3);
  for (int i = 0; i <= k; ++i) {
    const double x = static_cast<double>(i) / k;
    p.y0_value.row(i) = U(x, 0).transpose();
    p.y0_dy.row(i) = Uy(x, 0).transpose();
    p.y1_value.row(i) = U(x, 1).transpose();
    p.y1_dy.row(i) = Uy(x, 1).transpose();
  }
  p.points.resize(0, 2);
  p.data.resize(0, 3);
  return p;
}

/// Smoothing PDE splines §6: cylinders f and g, blend from f's edge y = 1 to g's edge y = 0 (docs/errata.md),
/// optionally with the nine points (i/9, 0.5) and data h(i/9, 0.5).
SmoothingSplineProblem cylinders(double a, double eps, bool with_points) {
  SmoothingSplineProblem p;
  p.k = 8;
  p.l = 4;
  p.a = a;
  p.epsilon = eps;
  p.y0_value.resize(9, 3);
  p.y0_dy.resize(9, 3);
  p.y1_value.resize(9, 3);
  p.y1_dy.resize(9, 3);
  for (int i = 0; i <= 8; ++i) {
    const double x = i / 8.0;
    p.y0_value.row(i) << 1, 2 * std::cos(kTwoPi * x), 2 * std::sin(kTwoPi * x);  // f(x, 1)
    p.y0_dy.row(i) << 2, 0, 0;                                                   // f_y(x, 1)
    p.y1_value.row(i) << 1, std::cos(kTwoPi * x), std::sin(kTwoPi * x);          // g(x, 0)
    p.y1_dy.row(i) << 2, 0, 0;                                                   // g_y(x, 0)
  }
  const int m = with_points ? 9 : 0;
  p.points.resize(m, 2);
  p.data.resize(m, 3);
  for (int i = 0; i < m; ++i) {
    p.points.row(i) << i / 9.0, 0.5;
    p.data.row(i) << 0, 0.5 * std::cos(kTwoPi * i / 9.0), 0.5 * std::sin(kTwoPi * i / 9.0);
  }
  return p;
}

/// J of eq. (6) computed independently of the assembled matrices: point evaluations and a 5x5
/// Gauss rule per element on the spline's derivatives.
double functional_by_quadrature(const SmoothingSpline& s, const SmoothingSplineProblem& p) {
  double misfit = 0;
  for (Eigen::Index i = 0; i < p.points.rows(); ++i)
    misfit += (s.evaluate(p.points(i, 0), p.points(i, 1)) - p.data.row(i).transpose()).squaredNorm();
  const auto g = gauss_legendre01(5);
  double energy = 0, load = 0;
  for (int i = 0; i < p.k; ++i)
    for (int j = 0; j < p.l; ++j)
      for (int a = 0; a < 5; ++a)
        for (int b = 0; b < 5; ++b) {
          const double x = (i + g.x(a)) / p.k, y = (j + g.x(b)) / p.l;
          const double w = g.w(a) * g.w(b) / (p.k * p.l);
          energy += w * (s.evaluate(x, y, 2, 0).squaredNorm() + 2 * p.a * s.evaluate(x, y, 1, 1).squaredNorm() +
                         p.a * p.a * s.evaluate(x, y, 0, 2).squaredNorm());
          if (p.load) load += w * p.load(x, y).dot(s.evaluate(x, y));
        }
  return misfit + p.epsilon * (energy - 2 * load);
}

TEST(SmoothingSpline, ReproducesDataFromSpanOneXYXYExactly) {
  auto U = [](double x, double y) { return Eigen::Vector3d(1 + 2 * x - y + 3 * x * y, -x + 0.5 * y, 2 - x * y); };
  auto Uy = [](double x, double) { return Eigen::Vector3d(-1 + 3 * x, 0.5, -x); };
  for (double a : {1.0, 10.0})
    for (double eps : {1.0, 1e-3}) {
      for (auto method : {SmoothingSplineOptions::Method::kKktLu, SmoothingSplineOptions::Method::kElimination}) {
        SmoothingSplineOptions o;
        o.method = method;
        const auto p = problem_from(6, 3, a, eps, U, Uy);
        const auto r = solve_smoothing_spline(p, o);
        ASSERT_TRUE(r.summary.converged) << r.summary.message;
        EXPECT_LT(r.summary.residual, 1e-12);
        for (double x : {0.0, 0.13, 0.5, 0.77, 1.0})
          for (double y : {0.0, 0.31, 0.5, 0.9, 1.0}) {
            EXPECT_LT((r.spline.evaluate(x, y) - U(x, y)).norm(), 1e-11) << x << " " << y;
            EXPECT_LT((r.spline.evaluate(x, y, 1, 1) - Eigen::Vector3d(3, 0, -1)).norm(), 1e-9);
          }
        // the energy of U: (2a) ∫ |U_xy|² = 2a * 10
        EXPECT_NEAR(r.energy, 2 * a * 10, 1e-9 * a);
      }
    }
}

TEST(SmoothingSpline, AffineDataAtPointsIsStillReproduced) {
  auto U = [](double x, double y) { return Eigen::Vector3d(x - 2 * y, 3 * x * y, 1); };
  auto Uy = [](double x, double) { return Eigen::Vector3d(-2, 3 * x, 0); };
  auto p = problem_from(5, 4, 2.0, 1e-2, U, Uy);
  p.points.resize(3, 2);
  p.points << 0.3, 0.4, 0.7, 0.2, 0.5, 0.5;
  p.data.resize(3, 3);
  for (int i = 0; i < 3; ++i) p.data.row(i) = U(p.points(i, 0), p.points(i, 1)).transpose();
  const auto r = solve_smoothing_spline(p);
  ASSERT_TRUE(r.summary.converged);
  EXPECT_LT(r.max_data_error, 1e-12);
  EXPECT_LT((r.spline.evaluate(0.9, 0.65) - U(0.9, 0.65)).norm(), 1e-12);
}

TEST(SmoothingSpline, BicubicSolutionsOfThePdeAreNotReproduced) {
  // U = (x^3, x^2 y, 0) satisfies ∂⁴_x + 2a∂²_x∂²_y + a²∂⁴_y U = 0 and lies in the space, but
  // (docs/errata.md) the spline beats it: the natural conditions on x = 0, 1 and the free ∂x, ∂xy at
  // the boundary nodes give a strictly smaller energy.
  auto U = [](double x, double y) { return Eigen::Vector3d(x * x * x, x * x * y, 0); };
  auto Uy = [](double x, double) { return Eigen::Vector3d(0, x * x, 0); };
  const auto p = problem_from(4, 4, 1.0, 1.0, U, Uy);
  const auto r = solve_smoothing_spline(p);
  ASSERT_TRUE(r.summary.converged);
  // |U|_L² = ∫ (6x)² + 2 (2x)² + 0 = 12 + 8/3
  const double energy_U = 12 + 8.0 / 3;
  EXPECT_LT(r.energy, energy_U * (1 - 1e-3));
  EXPECT_GT((r.spline.evaluate(0.5, 0.5) - U(0.5, 0.5)).norm(), 1e-4);
  // and the boundary data is still met
  EXPECT_LT((r.spline.evaluate(0.25, 1.0) - U(0.25, 1.0)).norm(), 1e-12);
}

TEST(SmoothingSpline, InterpolatesBoundaryValuesAndDyAtTheNodes) {
  std::mt19937 rng(1);
  SmoothingSplineProblem p = cylinders(3.0, 0.1, true);
  p.y0_value = Eigen::MatrixX3d::Random(9, 3);
  p.y0_dy = Eigen::MatrixX3d::Random(9, 3);
  p.y1_value = Eigen::MatrixX3d::Random(9, 3);
  p.y1_dy = Eigen::MatrixX3d::Random(9, 3);
  const auto r = solve_smoothing_spline(p);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.summary.status, Status::Converged);
  EXPECT_GE(r.summary.seconds, 0.0);
  for (int i = 0; i <= 8; ++i) {
    const double x = i / 8.0;
    EXPECT_LT((r.spline.evaluate(x, 0) - p.y0_value.row(i).transpose()).norm(), 1e-12);
    EXPECT_LT((r.spline.evaluate(x, 0, 0, 1) - p.y0_dy.row(i).transpose()).norm(), 1e-11);
    EXPECT_LT((r.spline.evaluate(x, 1) - p.y1_value.row(i).transpose()).norm(), 1e-12);
    EXPECT_LT((r.spline.evaluate(x, 1, 0, 1) - p.y1_dy.row(i).transpose()).norm(), 1e-11);
  }
  // between nodes the edge is only approximated (generic data)
  EXPECT_GT((r.spline.evaluate(1.0 / 16, 0) - 0.5 * (p.y0_value.row(0) + p.y0_value.row(1)).transpose()).norm(), 0.0);
}

TEST(SmoothingSpline, KktAndEliminationAgree) {
  for (double eps : {1.0, 1e-3, 1e-5})
    for (double a : {1.0, 10.0}) {
      SmoothingSplineProblem p = cylinders(a, eps, true);
      p.load = [](double x, double y) { return Eigen::Vector3d(x * y, 1.0, std::sin(3 * x)); };
      SmoothingSplineOptions kkt, elim;
      elim.method = SmoothingSplineOptions::Method::kElimination;
      const auto r1 = solve_smoothing_spline(p, kkt), r2 = solve_smoothing_spline(p, elim);
      ASSERT_TRUE(r1.summary.converged) << r1.summary.message;
      ASSERT_TRUE(r2.summary.converged) << r2.summary.message;
      const double scale = r1.spline.coefficients().cwiseAbs().maxCoeff();
      EXPECT_LT((r1.spline.coefficients() - r2.spline.coefficients()).cwiseAbs().maxCoeff(), 1e-9 * scale)
          << eps << " " << a;
      EXPECT_LT((r1.multipliers - r2.multipliers).cwiseAbs().maxCoeff(),
                1e-8 * (1 + r1.multipliers.cwiseAbs().maxCoeff()));
      EXPECT_NEAR(r1.functional, r2.functional, 1e-10 * std::abs(r1.functional) + 1e-14);
    }
}

TEST(SmoothingSpline, ThreadedAndSerialFactorisationsGiveTheKktSpline) {
  // The elimination route orders C_ff itself and runs CHOLMOD's OpenMP regions serially unless
  // threaded_factorization; on a partition large enough for CHOLMOD's parallel loops (40 x 40,
  // 6.7k dofs) both settings must give the spline of the KKT LU, an independent route.
  const SmoothingSplineProblem p = problem_from(
      40, 40, 2.0, 1e-2, [](double x, double y) { return Eigen::Vector3d(x, y, std::sin(3 * x) * std::cos(2 * y)); },
      [](double x, double y) { return Eigen::Vector3d(0, 1, -2 * std::sin(3 * x) * std::sin(2 * y)); });
  SmoothingSplineOptions kkt, serial, threaded;
  kkt.method = SmoothingSplineOptions::Method::kKktLu;
  threaded.threaded_factorization = true;
  const auto r0 = solve_smoothing_spline(p, kkt), r1 = solve_smoothing_spline(p, serial),
             r2 = solve_smoothing_spline(p, threaded);
  ASSERT_TRUE(r0.summary.converged) << r0.summary.message;
  ASSERT_TRUE(r1.summary.converged) << r1.summary.message;
  ASSERT_TRUE(r2.summary.converged) << r2.summary.message;
  const double scale = r0.spline.coefficients().cwiseAbs().maxCoeff();
  // (KKT LU against elimination: 8.6e-8 relative at this size and epsilon, the same with the
  // elimination of the previous build, METIS-ordered: the conditioning of the system.)
  for (const auto* r : {&r1, &r2}) {
    EXPECT_LT((r->spline.coefficients() - r0.spline.coefficients()).cwiseAbs().maxCoeff(), 1e-6 * scale);
    EXPECT_NEAR(r->functional, r0.functional, 1e-10 * std::abs(r0.functional));
  }
  EXPECT_LT((r1.spline.coefficients() - r2.spline.coefficients()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}

TEST(SmoothingSpline, EnergyWithoutRIsTheAssembledQuadraticForm) {
  // The solver keeps neither R nor the upper triangle of C: its energy, summed element by element,
  // must be tr(σᵀRσ) of the assembled R, and the matrices built on demand must be those of eq. (8).
  for (double eps : {1.0, 1e-3, 1e-5})
    for (double a : {1.0, 10.0}) {
      SmoothingSplineProblem p = cylinders(a, eps, true);
      p.load = [](double x, double y) { return Eigen::Vector3d(x * y, 1.0, std::sin(3 * x)); };
      for (auto method : {SmoothingSplineOptions::Method::kElimination, SmoothingSplineOptions::Method::kKktLu}) {
        SmoothingSplineOptions o;
        o.method = method;
        SmoothingSplineSolver solver(p, o);
        const auto r = solver.solve(p);
        ASSERT_TRUE(r.summary.converged) << r.summary.message;
        const Eigen::SparseMatrix<double> R = solver.form_matrix();
        const Eigen::MatrixX3d& c = r.spline.coefficients();
        const double assembled = (c.transpose() * (R * c)).trace();
        EXPECT_GT(assembled, 0.0);
        EXPECT_NEAR(r.energy, assembled, 1e-12 * assembled) << eps << " " << a;
        // C = εR + AᵀA with both triangles, A the point evaluations
        Eigen::MatrixXd AtA = Eigen::MatrixXd::Zero(R.rows(), R.cols());
        for (Eigen::Index i = 0; i < p.points.rows(); ++i) {
          std::array<int, 16> idx;
          std::array<double, 16> val;
          solver.space().basis_at(p.points(i, 0), p.points(i, 1), 0, 0, idx, val);
          for (int s = 0; s < 16; ++s)
            for (int t = 0; t < 16; ++t) AtA(idx[s], idx[t]) += val[s] * val[t];
        }
        const Eigen::MatrixXd Cexpect = eps * Eigen::MatrixXd(R) + AtA;
        const Eigen::MatrixXd C = Eigen::MatrixXd(solver.system_matrix());
        EXPECT_LT((C - Cexpect).cwiseAbs().maxCoeff(), 1e-13 * Cexpect.cwiseAbs().maxCoeff());
        EXPECT_EQ((C - C.transpose()).cwiseAbs().maxCoeff(), 0.0);
      }
    }
}

TEST(SmoothingSpline, IsTheMinimiserOfEq6OverTheConstrainedSpace) {
  SmoothingSplineProblem p = cylinders(10.0, 1e-3, true);
  p.load = [](double x, double y) { return Eigen::Vector3d(1.0 + x, y * y, -2.0); };
  const auto r = solve_smoothing_spline(p);
  ASSERT_TRUE(r.summary.converged);
  const double J0 = functional_by_quadrature(r.spline, p);
  EXPECT_NEAR(r.functional, J0, 1e-10 * std::abs(J0));
  const BfsSpace& V = r.spline.space();
  std::mt19937 rng(2);
  for (int trial = 0; trial < 3; ++trial) {
    Eigen::MatrixX3d dv = Eigen::MatrixX3d::Random(V.num_dofs(), 3);
    for (int i = 0; i <= V.k(); ++i)
      for (int j : {0, V.l()})
        for (int d : {0, 2}) dv.row(V.dof(i, j, d)).setZero();  // stay in H_h
    const SmoothingSpline plus(V, r.spline.coefficients() + dv), minus(V, r.spline.coefficients() - dv);
    const double Jp = functional_by_quadrature(plus, p), Jm = functional_by_quadrature(minus, p);
    const double first = 0.5 * (Jp - Jm), second = 0.5 * (Jp + Jm) - J0;
    EXPECT_GT(second, 0);
    EXPECT_LT(std::abs(first), 1e-9 * (std::abs(J0) + second)) << first << " " << second;
  }
}

TEST(SmoothingSpline, ApproachesTheDataLinearlyInEpsilon) {
  // Paper data, a = 10: error/eps -> 3667 (2815 at eps = 1e-4, 3655 at 1e-6): linear in eps
  // once eps is small.
  double prev = 0, prev_ratio = 0;
  for (double eps : {1e-6, 1e-7, 1e-8}) {
    const auto r = solve_smoothing_spline(cylinders(10.0, eps, true));
    ASSERT_TRUE(r.summary.converged) << eps << ": " << r.summary.message;
    EXPECT_GT(r.max_data_error, 0);
    const double ratio = r.max_data_error / eps;
    if (prev > 0) {
      EXPECT_NEAR(prev / r.max_data_error, 10.0, 0.05) << eps;
      EXPECT_NEAR(ratio / prev_ratio, 1.0, 0.005) << eps;
    }
    prev = r.max_data_error;
    prev_ratio = ratio;
  }
  // with eps = 1 (paper's A = ∅ sets use eps = 1) the points are far from the data
  const auto far = solve_smoothing_spline(cylinders(10.0, 1.0, true));
  EXPECT_GT(far.max_data_error, 0.1);
}

TEST(SmoothingSpline, NumericallySingularProblemsAreReportedNotConverged) {
  // eps = 1e-300: the data term swamps the energy; the reduced system is singular in doubles.
  for (auto method : {SmoothingSplineOptions::Method::kKktLu, SmoothingSplineOptions::Method::kElimination}) {
    SmoothingSplineOptions o;
    o.method = method;
    const auto r = solve_smoothing_spline(cylinders(10.0, 1e-300, true), o);
    EXPECT_FALSE(r.summary.converged);
    EXPECT_TRUE(r.summary.status == Status::NotUnique || r.summary.status == Status::NumericalLimit)
        << to_string(r.summary.status);
    EXPECT_FALSE(r.summary.message.empty());
    EXPECT_TRUE(std::isfinite(r.functional));
    EXPECT_TRUE(r.spline.coefficients().allFinite());
  }
}

TEST(SmoothingSpline, SolverReusesItsFactorisation) {
  SmoothingSplineProblem p = cylinders(1.0, 1e-3, true);
  SmoothingSplineSolver solver(p);
  const auto r1 = solver.solve(p);
  SmoothingSplineProblem q = p;
  q.data *= 2.0;
  q.y0_value *= 2.0;
  q.y1_value *= 2.0;
  q.y0_dy *= 2.0;
  q.y1_dy *= 2.0;
  const auto r2 = solver.solve(q);  // linear in the data
  EXPECT_LT((r2.spline.coefficients() - 2.0 * r1.spline.coefficients()).cwiseAbs().maxCoeff(), 1e-11);
  SmoothingSplineProblem other = p;
  other.epsilon = 1.0;
  EXPECT_THROW(solver.solve(other), ParameterError);
  EXPECT_EQ(static_cast<int>(solver.constrained_dofs().size()), 4 * 9);
}

TEST(SmoothingSpline, SampleOrderTrianglesAndMeanCurvature) {
  // The paraboloid (x, y, x² + y²) is bicubic, so a BFS field holds it exactly.
  const BfsSpace V(3, 2);
  const Eigen::MatrixX3d C = V.interpolate([](double x, double y) {
    Eigen::Matrix<double, 4, 3> J;
    J << x, y, x * x + y * y,  //
        1, 0, 2 * x,           //
        0, 1, 2 * y,           //
        0, 0, 0;
    return J;
  });
  const SmoothingSpline s(V, C);
  const int N = 6;
  const TriangleMesh m = s.sample(N);
  ASSERT_EQ(m.V.rows(), 49);
  ASSERT_EQ(m.F.rows(), 72);
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N; ++b) {
      const double x = static_cast<double>(a) / N, y = static_cast<double>(b) / N;
      const int id = a * (N + 1) + b;
      EXPECT_LT((m.V.row(id).transpose() - Eigen::Vector3d(x, y, x * x + y * y)).norm(), 1e-13);
      const double fx = 2 * x, fy = 2 * y;
      const double H = ((1 + fy * fy) * 2 + (1 + fx * fx) * 2) / (2 * std::pow(1 + fx * fx + fy * fy, 1.5));
      EXPECT_NEAR(m.H(id), H, 1e-12);
    }
  EXPECT_NEAR(m.H(0), 2.0, 1e-12);
  // counter-clockwise: normals of the first triangle point to +z
  const Eigen::Vector3d p0 = m.V.row(m.F(0, 0)), p1 = m.V.row(m.F(0, 1)), p2 = m.V.row(m.F(0, 2));
  EXPECT_GT((p1 - p0).cross(p2 - p0).z(), 0);
  EXPECT_THROW(s.sample(0), ParameterError);
}

TEST(SmoothingSpline, BSplineNetOfTheSolutionMatches) {
  const auto r = solve_smoothing_spline(cylinders(1.0, 1.0, false));
  const auto B = r.spline.to_bspline();
  EXPECT_EQ(B.points.rows(), 18 * 10);
  // the clamped corners are the surface's corners
  EXPECT_LT((B.points.row(0).transpose() - r.spline.evaluate(0, 0)).norm(), 1e-14);
  EXPECT_LT((B.points.row(18 * 10 - 1).transpose() - r.spline.evaluate(1, 1)).norm(), 1e-14);
  // the project's B-spline class evaluates it to the same surface, derivatives included
  const BSplineNet net = r.spline.to_bspline_net();
  for (double x : {0.0, 0.1, 0.37, 0.5, 0.93, 1.0})
    for (double y : {0.0, 0.2, 0.61, 1.0})
      for (int d = 0; d < 3; ++d) {
        const int dx = d == 1, dy = d == 2;
        EXPECT_LT((net.derivative(x, y, dx, dy) - r.spline.evaluate(x, y, dx, dy)).norm(), 1e-11)
            << x << " " << y << " " << d;
      }
  // and the spline's sampler (the tabulated B-spline grid) gives the mesh of the spline's own
  // per-point jets (BfsSpace basis values, independent of the B-spline form)
  const int N = 20;
  const TriangleMesh a = r.spline.sample(N), b = sample_mesh(net, N);
  ASSERT_EQ(a.V.rows(), (N + 1) * (N + 1));
  EXPECT_EQ(a.F, b.F);
  double hmax = 0;
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j <= N; ++j) hmax = std::max(hmax, std::abs(a.H(i * (N + 1) + j)));
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j <= N; ++j) {
      const double x = double(i) / N, y = double(j) / N;
      const int id = i * (N + 1) + j;
      const SurfaceJet jet = r.spline.jet(x, y);
      EXPECT_LT((a.V.row(id).transpose() - jet.x).norm(), 1e-12) << x << " " << y;
      const FundamentalForms f = fundamental_forms(jet);
      if (f.regular) {
        EXPECT_NEAR(a.H(id), f.H, 1e-8 * (1 + hmax)) << x << " " << y;
      }
    }
}

TEST(SmoothingSpline, BadProblemsThrowTypedErrors) {
  const SmoothingSplineProblem good = cylinders(1.0, 1.0, true);
  auto bad = good;
  bad.epsilon = 0;
  EXPECT_THROW(solve_smoothing_spline(bad), ParameterError);
  bad = good;
  bad.epsilon = -1;
  EXPECT_THROW(solve_smoothing_spline(bad), ParameterError);
  bad = good;
  bad.a = 0;
  EXPECT_THROW(solve_smoothing_spline(bad), ParameterError);
  bad = good;
  bad.a = 2e6;
  EXPECT_THROW(solve_smoothing_spline(bad), ParameterError);
  bad = good;
  bad.data *= 1e300;  // finite, but J overflows
  EXPECT_THROW(solve_smoothing_spline(bad), NonFiniteError);
  bad = good;
  bad.epsilon = std::numeric_limits<double>::infinity();
  EXPECT_THROW(solve_smoothing_spline(bad), NonFiniteError);
  bad = good;
  bad.k = 0;
  EXPECT_THROW(solve_smoothing_spline(bad), ParameterError);
  bad = good;
  bad.y1_dy = Eigen::MatrixX3d::Zero(8, 3);
  EXPECT_THROW(solve_smoothing_spline(bad), SizeError);
  bad = good;
  bad.data = Eigen::MatrixX3d::Zero(8, 3);
  EXPECT_THROW(solve_smoothing_spline(bad), SizeError);
  bad = good;
  bad.points(3, 1) = 1.5;
  EXPECT_THROW(solve_smoothing_spline(bad), ParameterError);
  bad = good;
  bad.data(2, 2) = std::nan("");
  EXPECT_THROW(solve_smoothing_spline(bad), NonFiniteError);
  bad = good;
  bad.load = [](double, double) { return Eigen::Vector3d(0, 0, std::nan("")); };
  EXPECT_THROW(solve_smoothing_spline(bad), NonFiniteError);
  SmoothingSplineOptions o;
  o.load_quadrature = 0;
  EXPECT_THROW(solve_smoothing_spline(good, o), ParameterError);
}

}  // namespace
}  // namespace bpde
