// CmcOptions::progress (core/progress.h): called once per accepted continuation step with the
// |H| reached out of |H| requested, ending at the target; never called when not set.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace bpde
