// CmcOptions::progress (core/progress.h): called once per accepted continuation step with the
// |H| reached out of |H| requested, ending at the target; never called when not set; and, for the
// mean-curvature functional, once per least-squares iteration.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cmc_test_util.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace bpde {
namespace {

TEST(CmcProgress, ReportsTheHReachedPerContinuationStepUpToTheTarget) {
  const TriangularNet data = testing::triangular_boundary(5, testing::planar_triangle);
  CmcOptions o;
  o.H = -2.0;
  std::vector<double> done;
  o.progress = [&](std::string_view stage, double d, double total) {
    EXPECT_EQ(std::string(stage), "cmc continuation");
    EXPECT_DOUBLE_EQ(total, 2.0);
    done.push_back(d);
  };
  const auto r = solve_cmc(data, o);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  ASSERT_EQ(static_cast<int>(done.size()), r.continuation_steps);  // one call per accepted step
  for (size_t i = 1; i < done.size(); ++i) EXPECT_GT(done[i], done[i - 1]);
  EXPECT_DOUBLE_EQ(done.back(), 2.0);  // the stage ends at the target: done == total
  // The same solve without a callback: the same result (progress observes only).
  CmcOptions quiet = o;
  quiet.progress = nullptr;
  EXPECT_EQ(solve_cmc(data, quiet).net.points(), r.net.points());
}

// The mean-curvature functional: its continuation (the D_H start), then the least squares, whose
// fraction (the log-scale way from the start's √Φ to the target) lies in [0, 1], never falls, and
// ends at 1.
TEST(CmcProgress, MeanCurvatureReportsTheLeastSquaresStage) {
  CmcOptions o = testing::cmc_options(CmcFunctionalKind::MeanCurvature, -0.5);
  std::vector<double> ls;
  int continuation = 0;
  o.progress = [&](std::string_view stage, double d, double total) {
    if (stage == "cmc continuation") {
      ++continuation;
      return;
    }
    EXPECT_EQ(std::string(stage), "cmc least squares");
    EXPECT_DOUBLE_EQ(total, 1.0);
    EXPECT_TRUE(d >= 0 && d <= 1) << d;
    ls.push_back(d);
  };
  const auto r = solve_cmc(testing::circle_three_arcs(10), o);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_GT(continuation, 0);
  ASSERT_GE(ls.size(), 3u);
  EXPECT_EQ(ls.front(), 0.0);
  EXPECT_EQ(ls.back(), 1.0);
  for (size_t i = 1; i < ls.size(); ++i) EXPECT_GE(ls[i], ls[i - 1]);  // Φ never rises in LM
}

// The area functional from the D_H critical point (mean-curvature-start off): after
// its D_H start ("cmc continuation"), the stage "cmc area" reports the decades of the Dirichlet
// regulariser removed (out of 12), never falling, from 0 to 1; the same for the V form (its start
// is the nlopt minimiser of D).
TEST(CmcProgress, AreaReportsTheRegulariserStages) {
  for (bool volume : {false, true}) {
    SCOPED_TRACE(volume ? "V form" : "H form");
    CmcOptions o = testing::cmc_options(CmcFunctionalKind::Area, -0.5);
    o.area_start = AreaStart::Dirichlet;
    if (volume) {
      const double R = 2.0, h = R - std::sqrt(R * R - 1);
      o.V = std::acos(-1.0) * h * h * (3 * R - h) / 3;
      o.H = 0.0;
    }
    std::vector<double> area;
    o.progress = [&](std::string_view stage, double d, double total) {
      if (stage != "cmc area") return;
      EXPECT_DOUBLE_EQ(total, 1.0);
      EXPECT_TRUE(d >= 0 && d <= 1) << d;
      area.push_back(d);
    };
    const auto r = solve_cmc(testing::circle_three_arcs(8), o);
    ASSERT_TRUE(r.summary.converged) << r.summary.message;
    ASSERT_GE(area.size(), 3u);
    EXPECT_EQ(area.front(), 0.0);
    EXPECT_EQ(area.back(), 1.0);
    for (size_t i = 1; i < area.size(); ++i) EXPECT_GE(area[i], area[i - 1]);
    // Every residual evaluation repeats the fraction (AreaProblem::progress), so the reports
    // outnumber the distinct fractions: a progress line keeps showing the time in the final phases.
    EXPECT_GT(area.size(), 2 * static_cast<size_t>(std::unique(area.begin(), area.end()) - area.begin()));
  }
}

// mean-curvature-start's least squares (the triangular catenoid at n = 12, H = 0, where they stop
// at their 300 iterations and refine their rule once on the way, measured) report one stage "cmc
// least squares": its fraction starts at 0, never falls, lies in [0, 1] and reaches 1 once, at their
// end (before, each minimisation of a refinement reported its own way from 0 to 1).
TEST(CmcProgress, AreaRouteZeroReportsTheLeastSquaresStage) {
  auto catenoid = [](double u, double v) {
    const double th = 1.2 * u + 0.4 * v, rho = 1.1 + 0.8 * v;
    return Eigen::Vector3d(rho * std::cos(th), rho * std::sin(th), std::acosh(rho));
  };
  CmcOptions o = testing::cmc_options(CmcFunctionalKind::Area, 0.0);
  std::vector<double> ls;
  int area_before_end = 0;  // "cmc area" reports before its end: here no ε-homotopy runs (H = 0,
                            // mean-curvature-start kept), so only the residual evaluations report it
  o.progress = [&](std::string_view stage, double d, double total) {
    if (stage == "cmc area" && d < total) ++area_before_end;
    if (stage != "cmc least squares") return;
    EXPECT_DOUBLE_EQ(total, 1.0);
    EXPECT_TRUE(d >= 0 && d <= 1) << d;
    ls.push_back(d);
  };
  const auto r = solve_cmc(testing::triangular_boundary(12, catenoid), o);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  ASSERT_EQ(testing::kept_route(r.routes), AreaRoute::MeanCurvatureStart) << full_report(r.routes);
  ASSERT_GE(ls.size(), 3u);
  EXPECT_EQ(ls.front(), 0.0);
  EXPECT_EQ(ls.back(), 1.0);
  EXPECT_EQ(std::count(ls.begin(), ls.end(), 1.0), 1);
  for (size_t i = 1; i < ls.size(); ++i) EXPECT_GE(ls[i], ls[i - 1]);
  EXPECT_GT(area_before_end, 0);
}

// The area functional solves the D_H critical point once (the stage "cmc continuation" ends once):
// the gate of mean-curvature-start, its least squares (their start) and the routes from the D_H point
// share it (the circle at n = 10, H = -0.5, where mean-curvature-start is tried and kept). Before, the
// least squares solved it again.
TEST(CmcProgress, AreaSolvesTheDirichletStartOnce) {
  CmcOptions o = testing::cmc_options(CmcFunctionalKind::Area, -0.5);
  int ended = 0;
  o.progress = [&](std::string_view stage, double d, double total) {
    if (stage == "cmc continuation" && total > 0 && d == total) ++ended;
  };
  const auto r = solve_cmc(testing::circle_three_arcs(10), o);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  ASSERT_EQ(testing::kept_route(r.routes), AreaRoute::MeanCurvatureStart) << full_report(r.routes);
  EXPECT_EQ(ended, 1);
}

// The continuation routes of the area solve report their own stage: the way to the target, |H|
// reached out of |H| (h-continuation) or V − V_s out of V_0 − V_s (v-continuation), from 0, never
// falling, in [0, 1], ending once at 1; and "cmc area" reports no fraction while they run. The
// circle from the minimal surface ("start": "minimal-surface"), at H = −0.5 and at the volume of
// that cap (n = 6 and 8, one and two steps: measured).
TEST(CmcProgress, AreaContinuationRoutesReportTheirWayToTheTarget) {
  for (bool volume : {false, true}) {
    SCOPED_TRACE(volume ? "v-continuation" : "h-continuation");
    CmcOptions o = testing::cmc_options(CmcFunctionalKind::Area, -0.5);
    o.area_start = AreaStart::MinimalSurface;
    const std::string route_stage = volume ? "cmc area v-continuation" : "cmc area h-continuation";
    if (volume) {
      const double R = 2.0, h = R - std::sqrt(R * R - 1);
      o.V = std::acos(-1.0) * h * h * (3 * R - h) / 3;
      o.H = 0.0;
    }
    std::vector<double> way;
    std::vector<std::string> stages;
    o.progress = [&](std::string_view stage, double d, double total) {
      if (stages.empty() || stages.back() != stage) stages.emplace_back(stage);
      if (stage != route_stage) return;
      EXPECT_DOUBLE_EQ(total, 1.0);
      EXPECT_TRUE(d >= 0 && d <= 1) << d;
      way.push_back(d);
    };
    const auto r = solve_cmc(testing::circle_three_arcs(volume ? 8 : 6), o);
    ASSERT_TRUE(r.summary.converged) << r.summary.message;
    ASSERT_GE(r.continuation_steps, 1);
    ASSERT_GE(way.size(), 2u);
    EXPECT_EQ(way.front(), 0.0);
    EXPECT_EQ(way.back(), 1.0);
    EXPECT_EQ(std::count(way.begin(), way.end(), 1.0), 1);
    for (size_t i = 1; i < way.size(); ++i) EXPECT_GE(way[i], way[i - 1]);
    // the route's stage runs once, between the solve's own reports
    EXPECT_EQ(std::count(stages.begin(), stages.end(), route_stage), 1) << ::testing::PrintToString(stages);
    EXPECT_EQ(stages.back(), "cmc area");
  }
}

}  // namespace
}  // namespace bpde
