// solvers/complex/complex_extremal.h: the quadratic energies' extremals on a patch complex.
#include <gtest/gtest.h>

#include <random>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/complex/complex_extremal.h"
#include "tests/complex/complex_fixtures.h"

using namespace bpde;
using namespace bpde::test;

namespace {

class ExtremalKinds : public ::testing::TestWithParam<PatchKind> {};

/// Moves the free rows of c at random (the start the solve must not depend on).
void scramble_free_rows(PatchComplex& c, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-1, 1);
  for (int r = 0; r < c.points.rows(); ++r)
    if (!std::binary_search(c.fixed.begin(), c.fixed.end(), r))
      for (int k = 0; k < 3; ++k) c.points(r, k) = d(rng);
}

}  // namespace

TEST_P(ExtremalKinds, HarmonicPolynomialSurfaceIsReproducedByTheDirichletExtremal) {
  // Re z³ is harmonic in (x, y); every patch is a similarity image of its domain, where the
  // Dirichlet energy is invariant, so the complex's extremal is that surface
  const Layout L = grid_layout(GetParam(), 2);
  PatchComplex exact = complex_topology(L, 3);
  const SurfaceFn F = [](double x, double y) {
    const double X = x - 1, Y = y - 1;
    return Eigen::Vector3d(x, y, X * X * X - 3 * X * Y * Y);
  };
  set_from_function(exact, L, F);
  PatchComplex start = exact;
  scramble_free_rows(start, 5);
  const ComplexExtremal e = solve_complex_extremal(start, EnergySpec::dirichlet());
  EXPECT_TRUE(e.summary.converged) << e.summary.message;
  EXPECT_LT((e.complex.points - exact.points).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_NEAR(e.energy, complex_energy(exact, EnergySpec::dirichlet()), 1e-10);
  EXPECT_LT(e.energy, complex_energy(start, EnergySpec::dirichlet()));
}

TEST_P(ExtremalKinds, PlanarBoundaryGivesAPlanarComplex) {
  const Layout L = grid_layout(GetParam(), 3);
  PatchComplex c = complex_topology(L, 4);
  set_from_function(c, L, [](double x, double y) { return Eigen::Vector3d(x, y, 0.3 * x - 0.2 * y + 1); });
  scramble_free_rows(c, 9);
  const Eigen::Vector3d normal = Eigen::Vector3d(0.3, -0.2, -1).normalized();
  std::vector<EnergySpec> energies{EnergySpec::dirichlet()};
  if (GetParam() == PatchKind::tensor) energies.push_back(EnergySpec::biharmonic());  // regular on a grid
  for (const EnergySpec& energy : energies) {
    const ComplexExtremal e = solve_complex_extremal(c, energy);
    EXPECT_TRUE(e.summary.converged) << energy.name() << ": " << e.summary.message;
    const Eigen::VectorXd off = (e.complex.points * normal).array() - (Eigen::Vector3d(0, 0, 1).dot(normal));
    EXPECT_LT(off.cwiseAbs().maxCoeff(), 1e-12) << energy.name();
  }
}

TEST_P(ExtremalKinds, EnergyFallsMonotonicallyUnderPRefinementAndTheSeamsFlatten) {
  // boundary of z = x²y² (exact at degree 2 on squares): not harmonic, so every elevation gains
  const Layout L = grid_layout(GetParam(), 2);
  PatchComplex c = complex_topology(L, 4);
  set_from_function(c, L, [](double x, double y) { return Eigen::Vector3d(x, y, 0.25 * x * x * y * y); });
  double previous = std::numeric_limits<double>::infinity(), first_seam = 0, seam = 0;
  for (int n = 4; n <= 9; ++n) {
    const ComplexExtremal e = solve_complex_extremal(c, EnergySpec::dirichlet());
    ASSERT_TRUE(e.summary.converged) << e.summary.message;
    EXPECT_LT(e.energy, previous - 1e-9) << "degree " << n;
    previous = e.energy;
    seam = seam_angle_max(e.complex);
    if (n == 4) first_seam = seam;
    c = refine_p(e.complex, 1);
  }
  EXPECT_GT(first_seam, 0.01);
  EXPECT_LT(seam, first_seam / 4);
}

TEST_P(ExtremalKinds, HRefinementStaysC0AndLowersTheEnergy) {
  const Layout L = grid_layout(GetParam(), 2);
  PatchComplex c = complex_topology(L, 3);
  set_from_function(c, L, [](double x, double y) { return Eigen::Vector3d(x, y, std::sin(x) * std::cos(y)); });
  const ComplexExtremal coarse = solve_complex_extremal(c, EnergySpec::dirichlet());
  // the refined complex holds the coarse extremal exactly, with the same boundary: its extremal
  // can only be lower
  const PatchComplex h = refine_h(coarse.complex);
  EXPECT_NEAR(complex_energy(h, EnergySpec::dirichlet()), coarse.energy, 1e-12 * coarse.energy);
  const ComplexExtremal fine = solve_complex_extremal(h, EnergySpec::dirichlet());
  EXPECT_TRUE(fine.summary.converged);
  EXPECT_LT(fine.energy, coarse.energy);
  EXPECT_EQ(boundary_rows(fine.complex).size(), 16u * 3);  // still one C⁰ surface: every seam shared
  for (int r : fine.complex.fixed) EXPECT_EQ(fine.complex.points.row(r), h.points.row(r));
  EXPECT_LT(seam_angle_max(fine.complex), seam_angle_max(coarse.complex));
}

TEST(ComplexExtremal, FourthOrderEnergyWithPiecewiseAffineNullDirectionsIsRefused) {
  // a triangular complex with an inner vertex: the hat function there is affine on every patch
  const Layout L = grid_layout(PatchKind::triangular, 2);
  PatchComplex c = complex_topology(L, 3);
  set_from_function(c, L, [](double x, double y) { return Eigen::Vector3d(x, y, x * y); });
  EXPECT_THROW(solve_complex_extremal(c, EnergySpec::biharmonic()), ParameterError);
  EXPECT_NO_THROW(solve_complex_extremal(c, EnergySpec::dirichlet()));
  EXPECT_THROW(solve_complex_extremal(refine_p(c, 18), EnergySpec::dirichlet()), DegreeError);
}

INSTANTIATE_TEST_SUITE_P(Kinds, ExtremalKinds, ::testing::Values(PatchKind::triangular, PatchKind::tensor));
