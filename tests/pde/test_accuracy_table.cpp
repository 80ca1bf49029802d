// Max relative error of the PDE solvers against exact polynomial solutions, per degree and method.
// Regenerates the table of docs/pde_accuracy.md:
//   ./build/test_pde --gtest_filter='PdeAccuracy.*' 2>/dev/null | sed -n '/^|/p'
// The test also asserts an error envelope, so a regression in accuracy fails it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "exact_polynomials.h"
#include "bezierpde/solvers/pde/pde_explicit.h"
#include "bezierpde/solvers/pde/pde_lu.h"

namespace bpde {
namespace {

using namespace bpde::testing;

struct Case {
  std::string name;
  EnergySpec op;
  std::vector<Root> roots;
};

std::vector<Case> cases() {
  return {
      {"biharmonic", EnergySpec::biharmonic(), biharmonic_roots()},
      {"modified-biharmonic a=0.7", EnergySpec::modified_biharmonic(0.7), modified_biharmonic_roots(0.7)},
      {"gnorm rho=0.6 t=1.1", EnergySpec::gnorm(0.6, 1.1), gnorm_roots(0.6, 1.1)},
      {"gnorm rho=2 t=0", gnorm_operator(2.0, 0.0), gnorm_roots(2.0, 0.0)},
  };
}

TEST(PdeAccuracy, Table) {
  std::printf("| operator | n | data-rounding floor | explicit | lu | mould |\n|---|---|---|---|---|---|\n");
  for (const Case& c : cases()) {
    for (int n = 4; n <= 20; ++n) {
      double worst[3] = {0, 0, 0}, floor = 0;
      const PdeMould mould(c.op, n, n);
      for (unsigned seed = 1; seed <= 2; ++seed) {
        const TensorNet exact = exact_solution(c.roots, n, seed + 100 * n);
        const TensorNet data = boundary_only(exact);
        const PdeSolution e = solve_pde_explicit(data, c.op);
        const PdeSolution l = solve_pde_lu(data, c.op);
        floor = std::max(floor, floor_error(mould, exact));
        const PdeSolution m = mould.solve(data);
        ASSERT_TRUE(e.summary.converged) << e.summary.message;
        ASSERT_TRUE(l.summary.converged) << l.summary.message;
        ASSERT_TRUE(m.summary.converged) << m.summary.message;
        worst[0] = std::max(worst[0], relative_error(e.net, exact));
        worst[1] = std::max(worst[1], relative_error(l.net, exact));
        worst[2] = std::max(worst[2], relative_error(m.net, exact));
      }
      std::printf("| %s | %d | %.1e | %.1e | %.1e | %.1e |\n", c.name.c_str(), n, floor, worst[0], worst[1], worst[2]);
      EXPECT_LT(worst[0], floor_tolerance(floor)) << c.name << " explicit n=" << n;
      EXPECT_LT(worst[1], floor_tolerance(floor)) << c.name << " lu n=" << n;
      EXPECT_LT(worst[2], floor_tolerance(floor)) << c.name << " mould n=" << n;
    }
  }
}

}  // namespace
}  // namespace bpde
