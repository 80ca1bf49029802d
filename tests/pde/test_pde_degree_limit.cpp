// converged of the tensor PDE solvers past the degree they can deliver (issue 14;
// docs/pde_accuracy.md "Numerical limit").
#include <gtest/gtest.h>

#include <random>

#include "solvers/pde/pde_explicit.h"
#include "solvers/pde/pde_lu.h"
#include "solvers/pde/pde_residual.h"

using namespace bpde;

namespace {
TensorNet generic_ring(int n, int m, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  TensorNet net(n, m);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      net.set_point(i, j, Eigen::Vector3d(double(i) / n + 0.1 * U(gen), double(j) / m + 0.1 * U(gen), 0.5 * U(gen)));
  return net;
}
}  // namespace

TEST(PdeDegreeLimit, AboveTheLimitBothMethodsReportTheNumericalLimit) {
  for (int n : {kMaxPdeDegree + 1, 25, 64}) {
    const TensorNet data = generic_ring(n, n, 5u + n);
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
  const TensorNet data = generic_ring(kMaxPdeDegree, kMaxPdeDegree, 11);
  const PdeSolution e = solve_pde_explicit(data, EnergySpec::biharmonic());
  const PdeSolution l = solve_pde_lu(data, EnergySpec::biharmonic());
  ASSERT_TRUE(e.summary.converged) << e.summary.message;
  ASSERT_TRUE(l.summary.converged) << l.summary.message;
  const double scale = l.net.points().cwiseAbs().maxCoeff();
  EXPECT_LT((e.net.points() - l.net.points()).cwiseAbs().maxCoeff(), 1e-12 * scale);
}
