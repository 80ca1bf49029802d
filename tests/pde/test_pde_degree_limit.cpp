// converged of the tensor PDE solvers past the degree they can deliver
// (docs/pde_accuracy.md "Numerical limit").
#include <gtest/gtest.h>

#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/solvers/pde/pde_residual.h"
#include "tests/pde/exact_polynomials.h"

using namespace bpde;
using bpde::testing::perturbed_grid_net;

TEST(PdeDegreeLimit, AboveTheLimitBothMethodsReportTheNumericalLimit) {
  for (int n : {kMaxPdeDegree + 1, 25, 64}) {
    const TensorNet data = perturbed_grid_net(n, n, 5u + n);
    const PdeSolution e = solve_pde_explicit(data, EnergySpec::biharmonic());
    const PdeSolution l = solve_pde_lu(data, EnergySpec::biharmonic());
    for (const PdeSolution* s : {&e, &l}) {
      EXPECT_FALSE(s->summary.converged) << "n=" << n;
      EXPECT_EQ(s->summary.status, Status::NumericalLimit) << "n=" << n << ": " << s->summary.message;
      EXPECT_FALSE(s->summary.message.empty());
    }
  }
  // The check itself, as the Bernstein route of lu (n != m) calls it: either degree counts, and a
  // solve that already failed keeps its own status.
  Summary s;
  s.set_converged();
  check_pde_degree_limit(kMaxPdeDegree + 1, 6, "lu", s);
  EXPECT_EQ(s.status, Status::NumericalLimit);
  EXPECT_NE(s.message.find("numerical limit"), std::string::npos) << s.message;
  Summary ok;
  ok.set_converged();
  check_pde_degree_limit(6, kMaxPdeDegree, "lu", ok);
  EXPECT_TRUE(ok.converged);
  Summary failed;
  failed.set_failed(Status::NotUnique, "not unique");
  check_pde_degree_limit(30, 30, "lu", failed);
  EXPECT_EQ(failed.status, Status::NotUnique);
}

TEST(PdeDegreeLimit, AtTheLimitTheMethodsStillAgree) {
  const TensorNet data = perturbed_grid_net(kMaxPdeDegree, kMaxPdeDegree, 11);
  const PdeSolution e = solve_pde_explicit(data, EnergySpec::biharmonic());
  const PdeSolution l = solve_pde_lu(data, EnergySpec::biharmonic());
  ASSERT_TRUE(e.summary.converged) << e.summary.message;
  ASSERT_TRUE(l.summary.converged) << l.summary.message;
  const double scale = l.net.points().cwiseAbs().maxCoeff();
  EXPECT_LT((e.net.points() - l.net.points()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}
