// One contract for every solver entry point (solvers/summary.h):
//   - invalid options -> ParameterError;
//   - non-finite data -> NonFiniteError;
//   - the prescribed points are returned bit-exact;
//   - converged == false => a non-Converged status and a message; seconds >= 0;
//   - status == Converged exactly when converged (ConformanceStatus).
// Each case runs small problems: one that converges and, where the problem has a failure mode, one
// that does not.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/blend/smoothing_spline.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/solvers/bspline/bspline_pde.h"
#include "bezierpde/solvers/c1/biharmonic_load.h"
#include "bezierpde/solvers/c1/clamped_plate.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/solvers/extremal.h"
#include "bezierpde/solvers/pde/harmonic_pde.h"
#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/solvers/summary.h"
#include "tests/random_points.h"

using namespace bpde;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One solve: its summary, whether the prescribed points came back bit-exact, and whether this
// set-up is meant to converge (so that both branches of the contract are exercised).
struct Solve {
  std::string what;
  Summary summary;
  bool prescribed_exact = true;
  bool expect_converged = true;
};

struct Case {
  std::string name;
  std::function<void()> invalid_options;  // must throw ParameterError
  std::function<void()> non_finite;       // must throw NonFiniteError
  std::function<std::vector<Solve>()> runs;
};

// Rows `idx` of two point sets are equal, bit for bit.
bool rows_equal(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b, const std::vector<int>& idx) {
  if (a.rows() != b.rows()) return false;
  for (int r : idx)
    for (int c = 0; c < 3; ++c)
      if (!(a(r, c) == b(r, c))) return false;
  return true;
}

// Bernstein coefficients of x = (u, v, u^2 - v^2) on a degree (n, m) tensor net: a harmonic and
// biharmonic polynomial, so every PDE solver has it as its answer.
Eigen::MatrixX3d polynomial_points(int n, int m) {
  Eigen::MatrixX3d P((n + 1) * (m + 1), 3);
  auto sq = [](int i, int k) { return k < 2 ? 0.0 : i * (i - 1) / double(k * (k - 1)); };  // u^2 at degree k
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) P.row(i * (m + 1) + j) << double(i) / n, double(j) / m, sq(i, n) - sq(j, m);
  return P;
}

TensorNet polynomial_net(int n, int m) { return TensorNet(n, m, polynomial_points(n, m)); }
TensorNet random_net(int n, int m, unsigned seed) {
  return TensorNet(n, m, bpde::testing::random_points((n + 1) * (m + 1), seed));
}

// `net` with a NaN in its first prescribed point.
template <class Net>
Net with_nan(Net net, FixedSet fixed) {
  net.points()(net.fixed_indices(fixed).front(), 2) = kNaN;
  return net;
}

template <class Net, class Result>
Solve run_of(const std::string& what, const Net& data, const Result& r, FixedSet fixed, bool expect_converged = true) {
  return {what, r.summary, rows_equal(r.net.points(), data.points(), data.fixed_indices(fixed)), expect_converged};
}

std::vector<double> clamped(int p) {
  std::vector<double> k(static_cast<size_t>(2 * (p + 1)), 0.0);
  for (int i = p + 1; i < 2 * (p + 1); ++i) k[static_cast<size_t>(i)] = 1.0;
  return k;
}
// The same polynomial as a one-span B-spline net (its Bernstein form).
BSplineNet polynomial_bspline(int p) { return BSplineNet(p, p, clamped(p), clamped(p), polynomial_points(p, p)); }
// Biquintic, 2 x 2 spans, generic data: the biharmonic PDE has no spline solution.
BSplineNet generic_bspline() {
  const std::vector<double> K = {0, 0, 0, 0, 0, 0, 0.5, 1, 1, 1, 1, 1, 1};
  return BSplineNet(5, 5, K, K, bpde::testing::random_points(49, 7));
}

SmoothingSplineProblem blend_problem() {
  SmoothingSplineProblem p;
  p.k = 2;
  p.l = 2;
  p.y0_value.resize(3, 3);
  p.y0_dy.resize(3, 3);
  p.y1_value.resize(3, 3);
  p.y1_dy.resize(3, 3);
  for (int i = 0; i <= 2; ++i) {
    const double x = i / 2.0;
    p.y0_value.row(i) << x, 0, 0.3 * x * x;
    p.y0_dy.row(i) << 0, 1, 0.2;
    p.y1_value.row(i) << x, 1, 0.1 + x;
    p.y1_dy.row(i) << 0.1, 1, -0.2 * x;
  }
  return p;
}

std::vector<Case> cases() {
  const EnergySpec bih = EnergySpec::biharmonic();
  const EnergySpec not_unique = EnergySpec::pde_operator({1, 2, 2, 2, 1});  // G-norm rho = 1, t = 0
  std::vector<Case> c;

  c.push_back({"pde_explicit",
               [=] {
                 PdeExplicitOptions o;
                 o.singular_tolerance = 0;
                 solve_pde_explicit(polynomial_net(4, 4), bih, o);
               },
               [=] { solve_pde_explicit(with_nan(polynomial_net(4, 4), FixedSet::Boundary), bih); },
               [=] {
                 const TensorNet d = polynomial_net(5, 5), r = random_net(5, 5, 3);
                 return std::vector<Solve>{
                     run_of("biharmonic", d, solve_pde_explicit(d, bih), FixedSet::Boundary),
                     run_of("not unique", r, solve_pde_explicit(r, not_unique), FixedSet::Boundary, false)};
               }});
  c.push_back({"pde_lu",
               [=] {
                 PdeLuOptions o;
                 o.rank_tolerance = 2;
                 solve_pde_lu(polynomial_net(4, 4), bih, o);
               },
               [=] { solve_pde_lu(with_nan(polynomial_net(4, 4), FixedSet::Boundary), bih); },
               [=] {
                 const TensorNet d = polynomial_net(5, 5), e = polynomial_net(4, 6), r = random_net(5, 5, 3);
                 return std::vector<Solve>{
                     run_of("biharmonic", d, solve_pde_lu(d, bih), FixedSet::Boundary),
                     run_of("biharmonic, n != m", e, solve_pde_lu(e, bih), FixedSet::Boundary),
                     run_of("not unique", r, solve_pde_lu(r, not_unique), FixedSet::Boundary, false)};
               }});
  c.push_back({"pde_harmonic",
               [] {
                 PdeLuOptions o;
                 o.compatibility_tolerance = 0;
                 solve_harmonic_pde(polynomial_net(3, 3), EnergySpec::dirichlet(), o);
               },
               [] { solve_harmonic_pde(with_nan(polynomial_net(3, 3), FixedSet::UBoundaries)); },
               [] {
                 const TensorNet d = polynomial_net(3, 3), r = random_net(2, 2, 5);
                 return std::vector<Solve>{
                     run_of("odd degree", d, solve_harmonic_pde(d), FixedSet::UBoundaries),
                     run_of("even degree, incompatible rows", r, solve_harmonic_pde(r), FixedSet::UBoundaries, false)};
               }});
  c.push_back({"extremal",
               [=] {
                 ExtremalOptions o;
                 o.singular_tolerance = 1;
                 solve_extremal(random_net(4, 4, 1), bih, FixedSet::Boundary, o);
               },
               [=] { solve_extremal(with_nan(random_net(4, 4, 1), FixedSet::Boundary), bih, FixedSet::Boundary); },
               [=] {
                 std::vector<Solve> runs;
                 for (FixedSet f : {FixedSet::Boundary, FixedSet::BoundaryAdjacent, FixedSet::UBoundaries}) {
                   const TensorNet d = random_net(5, 6, 2);
                   runs.push_back(run_of("extremal " + to_string(f), d, solve_extremal(d, bih, f), f));
                 }
                 return runs;
               }});
  c.push_back({"tetraharmonic",
               [] {
                 TetraharmonicOptions o;
                 o.method = static_cast<TetraharmonicOptions::Method>(7);
                 solve_tetraharmonic(random_net(4, 4, 1), o);
               },
               [] { solve_tetraharmonic(with_nan(random_net(4, 4, 1), FixedSet::BoundaryAdjacent)); },
               [] {
                 std::vector<Solve> runs;
                 for (auto m : {TetraharmonicOptions::Method::Explicit, TetraharmonicOptions::Method::LU}) {
                   TetraharmonicOptions o;
                   o.method = m;
                   const TensorNet d = random_net(6, 6, 4);
                   runs.push_back(run_of("tetraharmonic", d, solve_tetraharmonic(d, o), FixedSet::BoundaryAdjacent));
                 }
                 return runs;
               }});
  // BiharmonicLoadOptions has no field to get wrong: invalid options cannot be written.
  c.push_back({"biharmonic_load", nullptr,
               [] { solve_biharmonic_load(with_nan(random_net(5, 5, 1), FixedSet::BoundaryAdjacent)); },
               [] {
                 const TensorNet d = random_net(6, 6, 4);
                 return std::vector<Solve>{
                     run_of("biharmonic load", d, solve_biharmonic_load(d), FixedSet::BoundaryAdjacent)};
               }});
  c.push_back({"clamped_plate",
               [] {
                 ClampedPlateOptions o;
                 o.aspect = 1000;
                 solve_clamped_plate(o);
               },
               [] {
                 ClampedPlateOptions o;
                 o.aspect = kNaN;
                 solve_clamped_plate(o);
               },
               [] {
                 std::vector<Solve> runs;
                 for (auto m : {ClampedPlateOptions::Method::AdmissibleLoad, ClampedPlateOptions::Method::Ritz}) {
                   ClampedPlateOptions o;
                   o.degree = 7;
                   o.method = m;
                   const ClampedPlateResult r = solve_clamped_plate(o);
                   // prescribed: w and its gradient vanish on the edges, i.e. the outer two rings are 0
                   bool exact = true;
                   for (int k : r.net.fixed_indices(FixedSet::BoundaryAdjacent))
                     exact = exact && r.net.points()(k, 2) == 0.0;
                   runs.push_back({"plate", r.summary, exact, true});
                 }
                 return runs;
               }});
  for (CmcSolver s : {CmcSolver::Newton, CmcSolver::Ceres, CmcSolver::NLopt}) {
    c.push_back({"cmc_" + to_string(s),
                 [s] {
                   CmcOptions o;
                   o.solver = s;
                   o.H = -1;
                   o.tolerance = 1;
                   solve_cmc(circle_three_arcs(4), o);
                 },
                 [s] {
                   CmcOptions o;
                   o.solver = s;
                   o.H = -1;
                   solve_cmc(with_nan(circle_three_arcs(4), FixedSet::Boundary), o);
                 },
                 [s] {
                   CmcOptions o;
                   o.solver = s;
                   o.H = -1;
                   const TriangularNet d = circle_three_arcs(4);
                   std::vector<Solve> runs{run_of("H = -1", d, solve_cmc(d, o), FixedSet::Boundary)};
                   const TensorNet t = polynomial_net(3, 3);
                   o.H = 0.5;
                   runs.push_back(run_of("tensor, H = 0.5", t, solve_cmc(t, o), FixedSet::Boundary));
                   if (s == CmcSolver::Newton) {  // far past the fold (|H| ~ 1.56): no critical point
                     o.H = -5;
                     runs.push_back(run_of("past the fold", d, solve_cmc(d, o), FixedSet::Boundary, false));
                   }
                   return runs;
                 }});
  }
  c.push_back({"bspline_extremal",
               [=] {
                 BSplineExtremalOptions o;
                 o.tolerance = 0;
                 solve_bspline_extremal(generic_bspline(), bih, o);
               },
               [=] { solve_bspline_extremal(with_nan(generic_bspline(), FixedSet::Boundary), bih); },
               [=] {
                 std::vector<Solve> runs;
                 for (FixedSet f : {FixedSet::Boundary, FixedSet::BoundaryAdjacent}) {
                   BSplineExtremalOptions o;
                   o.fixed = f;
                   const BSplineNet d = generic_bspline();
                   runs.push_back(run_of("bspline extremal " + to_string(f), d, solve_bspline_extremal(d, bih, o), f));
                 }
                 return runs;
               }});
  c.push_back({"bspline_pde",
               [=] {
                 BSplinePdeOptions o;
                 o.rank_tolerance = 0;
                 solve_bspline_pde(polynomial_bspline(4), bih, o);
               },
               [=] { solve_bspline_pde(with_nan(polynomial_bspline(4), FixedSet::Boundary), bih); },
               [=] {
                 const BSplineNet d = polynomial_bspline(4), g = generic_bspline();
                 return std::vector<Solve>{
                     run_of("polynomial data", d, solve_bspline_pde(d, bih), FixedSet::Boundary),
                     run_of("generic data, 2 x 2 spans", g, solve_bspline_pde(g, bih), FixedSet::Boundary, false)};
               }});
  c.push_back({"smoothing_spline",
               [] {
                 SmoothingSplineOptions o;
                 o.load_quadrature = 0;
                 solve_smoothing_spline(blend_problem(), o);
               },
               [] {
                 SmoothingSplineProblem p = blend_problem();
                 p.y0_value(1, 2) = kNaN;
                 solve_smoothing_spline(p);
               },
               [] {
                 std::vector<Solve> runs;
                 for (auto m : {SmoothingSplineOptions::Method::kKktLu, SmoothingSplineOptions::Method::kElimination}) {
                   const SmoothingSplineProblem p = blend_problem();
                   SmoothingSplineOptions o;
                   o.method = m;
                   const SmoothingSplineResult r = solve_smoothing_spline(p, o);
                   // prescribed: u and u_y at the nodes of y = 0 and y = 1 (BFS dofs 0 and 2)
                   const BfsSpace& s = r.spline.space();
                   const Eigen::MatrixX3d& a = r.spline.coefficients();
                   bool exact = true;
                   for (int i = 0; i <= p.k; ++i)
                     exact = exact && a.row(s.dof(i, 0, 0)) == p.y0_value.row(i) &&
                             a.row(s.dof(i, 0, 2)) == p.y0_dy.row(i) && a.row(s.dof(i, p.l, 0)) == p.y1_value.row(i) &&
                             a.row(s.dof(i, p.l, 2)) == p.y1_dy.row(i);
                   runs.push_back({m == SmoothingSplineOptions::Method::kKktLu ? "kkt lu" : "elimination", r.summary,
                                   exact, true});
                 }
                 return runs;
               }});
  return c;
}

// gtest prints a parameter on failure: its name, not its bytes.
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class Conformance : public ::testing::TestWithParam<Case> {};
class ConformanceStatus : public ::testing::TestWithParam<Case> {};

TEST_P(Conformance, InvalidOptionsAreParameterErrors) {
  if (!GetParam().invalid_options) GTEST_SKIP() << GetParam().name << " has no option to get wrong";
  EXPECT_THROW(GetParam().invalid_options(), ParameterError);
}

TEST_P(Conformance, NonFiniteDataAreNonFiniteErrors) { EXPECT_THROW(GetParam().non_finite(), NonFiniteError); }

TEST_P(Conformance, PrescribedPointsSecondsAndFailures) {
  for (const Solve& r : GetParam().runs()) {
    SCOPED_TRACE(GetParam().name + ": " + r.what);
    EXPECT_TRUE(r.prescribed_exact) << "the prescribed points must come back bit-exact";
    EXPECT_GE(r.summary.seconds, 0.0);
    EXPECT_TRUE(std::isfinite(r.summary.seconds));
    EXPECT_EQ(r.summary.converged, r.expect_converged) << r.summary.message;
    if (!r.summary.converged) {
      EXPECT_NE(r.summary.status, Status::Converged);
      EXPECT_FALSE(r.summary.message.empty()) << "a failed solve says why";
    }
  }
}

// Status == Converged exactly when converged, for every solver (Summary::set_converged /
// set_failed keep the two together).
TEST_P(ConformanceStatus, StatusIsConvergedExactlyWhenConverged) {
  for (const Solve& r : GetParam().runs()) {
    SCOPED_TRACE(GetParam().name + ": " + r.what);
    EXPECT_EQ(r.summary.status == Status::Converged, r.summary.converged)
        << "status " << to_string(r.summary.status) << ", converged " << r.summary.converged;
  }
}

std::string case_name(const ::testing::TestParamInfo<Case>& info) { return info.param.name; }

INSTANTIATE_TEST_SUITE_P(Solvers, Conformance, ::testing::ValuesIn(cases()), case_name);
INSTANTIATE_TEST_SUITE_P(Solvers, ConformanceStatus, ::testing::ValuesIn(cases()), case_name);

}  // namespace
