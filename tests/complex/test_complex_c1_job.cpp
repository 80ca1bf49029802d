// The "continuity" option of complex jobs (FORMATS.md "Patch complexes"): parsed, passed to the
// solve, reported; the cases it refuses.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/jobs/run_job.h"

using namespace bpde;

namespace {

/// A saddle polygon of k segments over the unit circle, z = 0.4 cos 2θ at its vertices.
Json saddle_polygon(int k) {
  Json loop = Json::array();
  auto pt = [&](int j) {
    const double t = 2 * std::numbers::pi * j / k;
    return Json::array({std::cos(t), std::sin(t), 0.4 * std::cos(2 * t)});
  };
  for (int i = 0; i < k; ++i) loop.push_back({{"type", "segment"}, {"from", pt(i)}, {"to", pt(i + 1)}});
  return Json::array({loop});
}

Json complex_job(const std::string& patch, int n, const std::string& continuity,
                 const std::string& problem = "extremal") {
  Json boundary = {{"type", "complex"}, {"patch", patch}, {"degree", n}, {"loops", saddle_polygon(8)}};
  if (!continuity.empty()) boundary["continuity"] = continuity;
  Json job = {{"boundary", boundary}, {"samples", 8}};
  if (problem == "extremal")
    job["problem"] = {{"kind", "extremal"}, {"energy", {{"name", "dirichlet"}}}};
  else
    job["problem"] = {{"kind", "cmc"}, {"H", 0.0}, {"functional", "dirichlet"}};
  job["fixed"] = "boundary";
  return job;
}

}  // namespace

TEST(ComplexC1Job, C1ClosesTheSeamsThatC0LeavesOpen) {
  const SolveOutcome c0 = run_job(job_from_json(complex_job("triangular", 5, "")));
  ASSERT_TRUE(c0.converged);
  EXPECT_EQ(c0.report["continuity"], "C0");
  EXPECT_GT(c0.report["seam_angle_max"].get<double>(), 1e-3);
  EXPECT_FALSE(c0.report.contains("c1_residual"));
  const SolveOutcome c1 = run_job(job_from_json(complex_job("triangular", 5, "C1")));
  ASSERT_TRUE(c1.converged) << c1.report.dump();
  EXPECT_EQ(c1.report["continuity"], "C1");
  EXPECT_LT(c1.report["seam_angle_max"].get<double>(), 1e-8);
  EXPECT_LT(c1.report["c1_residual"].get<double>(), 1e-10);
  // h refinement: the domain refined with the complex
  Json refined = complex_job("triangular", 4, "C1");
  refined["boundary"]["refine"] = 1;
  const SolveOutcome r = run_job(job_from_json(refined));
  ASSERT_TRUE(r.converged) << r.report.dump();
  EXPECT_EQ(r.report["patches"], 32);
  EXPECT_LT(r.report["seam_angle_max"].get<double>(), 1e-8);
}

TEST(ComplexC1Job, DegreeTooLowIsNoSolutionAndBadOptionsAreBadInput) {
  // n = 2: each seam's one inner point is over-determined by the C1 conditions at both its ends
  const SolveOutcome low = run_job(job_from_json(complex_job("triangular", 2, "C1")));
  EXPECT_FALSE(low.converged);
  EXPECT_EQ(low.status, Status::Incompatible);
  EXPECT_EQ(exit_code(low.status), 1);
  EXPECT_THROW(job_from_json(complex_job("tensor", 4, "C1")), ParameterError);
  EXPECT_THROW(job_from_json(complex_job("triangular", 4, "C2")), ParseError);
  EXPECT_THROW(run_job(job_from_json(complex_job("triangular", 4, "C1", "cmc"))), ParameterError);
}
