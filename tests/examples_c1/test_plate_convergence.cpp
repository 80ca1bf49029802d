// examples/000-plate-convergence (Centella et al. §6): the facts its README states, from the library
// function behind `bpde plate`. The 90-digit references for every (n, a) are checked in tests/c1.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "bezierpde/solvers/c1/clamped_plate.h"

namespace {

using M = bpde::ClampedPlateOptions::Method;
constexpr std::array<double, 5> kAspects = {1.0, 1.3, 1.5, 1.7, 2.0};
constexpr std::array<double, 5> kPaper11 = {0.00126654, 0.00191234, 0.00218658, 0.00234867, 0.00246161};
constexpr std::array<double, 5> kPaper15 = {0.00126628, 0.00191027, 0.00219831, 0.00239123, 0.00254655};
constexpr std::array<double, 5> kBloorWilson = {0.00126532, 0.00191168, 0.00219655, 0.00238207, 0.00253297};

double plate(double a, int n, M m) {
  bpde::ClampedPlateOptions o;
  o.aspect = a;
  o.degree = n;
  o.method = m;
  return bpde::solve_clamped_plate(o).center_deflection;
}

}  // namespace

// The paper's printed digits (8 decimals: half a unit of the last place is 5e-9).
TEST(PlateConvergence, PaperValuesAtDegrees7_9_11) {
  EXPECT_NEAR(plate(1.0, 7, M::AdmissibleLoad), 0.00096377, 5e-9);
  EXPECT_NEAR(plate(1.0, 9, M::AdmissibleLoad), 0.00122758, 5e-9);
  for (size_t k = 0; k < kAspects.size(); ++k)
    EXPECT_NEAR(plate(kAspects[k], 11, M::AdmissibleLoad), kPaper11[k], 5e-9) << "a = " << kAspects[k];
}

// n = 15: the paper's column is round-off corrupted (docs/errata.md); ours is within 1e-4 relative of
// it but not equal to it at every aspect.
TEST(PlateConvergence, PaperColumn15IsCloseButNotExact) {
  int differ = 0;
  for (size_t k = 0; k < kAspects.size(); ++k) {
    const double w = plate(kAspects[k], 15, M::AdmissibleLoad);
    EXPECT_NEAR(w / kPaper15[k], 1.0, 1e-4) << "a = " << kAspects[k];
    differ += std::abs(w - kPaper15[k]) > 5e-9;
  }
  EXPECT_GE(differ, 4);
}

// Ritz converges: successive even degrees agree to 1e-9 relative at n = 28 -> 30, and the limit
// matches Bloor–Wilson to their 4–5 digits (7e-7 for the square).
TEST(PlateConvergence, RitzConvergesToTheLiterature) {
  for (size_t k = 0; k < kAspects.size(); ++k) {
    SCOPED_TRACE(kAspects[k]);
    const double w30 = plate(kAspects[k], 30, M::Ritz);
    EXPECT_NEAR(plate(kAspects[k], 28, M::Ritz) / w30, 1.0, 1e-9);
    EXPECT_NEAR(plate(kAspects[k], 20, M::Ritz) / w30, 1.0, 1e-8);
    EXPECT_NEAR(w30 / kBloorWilson[k], 1.0, 3e-5);
  }
  EXPECT_NEAR(plate(1.0, 30, M::Ritz), 0.00126532, 5e-9);
  // Timoshenko's 0.00254 at a = 2 is a rounding slip: the converged value is 0.0025330.
  EXPECT_NEAR(plate(2.0, 30, M::Ritz), 0.002533, 5e-7);
  EXPECT_GT(std::abs(plate(2.0, 30, M::Ritz) - 0.00254), 5e-6);
}

// Admissible-load stalls at 3–4 digits: for 24 <= n <= 30 it stays between 1e-5 and 2e-3
// relative from the converged value at every aspect ratio, never settling.
TEST(PlateConvergence, AdmissibleLoadStallsAtThreeToFourDigits) {
  for (size_t k = 0; k < kAspects.size(); ++k) {
    SCOPED_TRACE(kAspects[k]);
    const double w = plate(kAspects[k], 30, M::Ritz);
    double worst = 0;
    for (int n = 24; n <= 30; ++n) worst = std::max(worst, std::abs(plate(kAspects[k], n, M::AdmissibleLoad) / w - 1));
    EXPECT_GT(worst, 1e-4);
    EXPECT_LT(worst, 2e-3);
  }
}
