// The CMC solves on complexes (solvers/cmc/complex_cmc.h) against exact answers.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "bezierpde/complex/refine.h"
#include "bezierpde/energies/complex_functionals.h"
#include "bezierpde/solvers/cmc/cmc_problem.h"
#include "bezierpde/solvers/cmc/complex_cmc.h"
#include "bezierpde/solvers/cmc/complex_net.h"
#include "tests/cmc/cmc_test_util.h"
#include "tests/cmc/complex_test_util.h"

namespace bpde::testing {
namespace {

// The cap of the sphere of radius 2 over the unit circle, bulging to +z (H = −1/2): centre
// (0, 0, −√3); its area 2πRh and its volume over the disc (the cone from the origin, which lies
// in the circle's plane).
constexpr double kCapArea = 3.36714885790773, kCapVolume = 0.430966541037603;
const Eigen::Vector3d kCapCentre(0, 0, -std::sqrt(3.0));

// max | |x − c| − 2 | over each patch's triangular sample grid (every sample).
double cap_distance(const PatchComplex& c) {
  double d = 0.0;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p)
    d = std::max(d, sphere_distance(triangular_patch(c, p), kCapCentre, 2.0, 20));
  return d;
}

// Measured on the fan of K = 6 triangular patches (area functional, H form, newton; Release, 2 cores;
// from mean-curvature-start):
//   n   A − A_cap    V − V_cap    max ||x − c| − 2|   H range on the samples   max seam angle   time
//   4   −9.9e-06     −2.5e-06     4.8e-06             [−0.50391, −0.49775]     2.6e-04 rad     0.8 s
//   5    1.9e-07      4.7e-08     8.9e-07             [−0.50006, −0.49992]     1.9e-05 rad     2.4 s
//   6    2.6e-09      6.5e-10     2.0e-07             [−0.50008, −0.49996]     4.4e-06 rad     3.2 s
//   8   −6.6e-13      5.0e-14     5.1e-09             [−0.50001, −0.49999]     2.7e-07 rad     2.5 s
// The Dirichlet functional's critical points (D_H, newton) stay off the sphere: A − A_cap = −1.4e-2,
// −1.1e-2, −9.2e-3, −7.6e-3 at n = 4, 5, 6, 8 (the fan's parametrisation is not conformal), with
// seam angles 8.7e-2, 5.6e-2, 4.4e-2, 2.9e-2 rad.
struct CapSolve {
  CmcResult<PatchComplex> r;
  double dA, dV, dist, seam;
};

CapSolve solve_cap(int n, CmcFunctionalKind f) {
  CapSolve s{solve_cmc(circle_fan(6, n), cmc_options(f, -0.5)), 0, 0, 0, 0};
  s.dA = std::abs(s.r.A - kCapArea);
  s.dV = std::abs(s.r.V - kCapVolume);
  s.dist = cap_distance(s.r.net);
  s.seam = max_seam_angle(s.r.net);
  return s;
}

TEST(ComplexCmc, CapFanByTheAreaFunctionalAtDegree4) {
  const CapSolve s = solve_cap(4, CmcFunctionalKind::Area);
  ASSERT_TRUE(s.r.summary.converged) << s.r.summary.message;
  EXPECT_TRUE(s.r.parametrisation.regular);
  EXPECT_LT(s.dA, 2e-5);
  EXPECT_LT(s.dV, 5e-6);
  EXPECT_LT(s.dist, 2e-5);
  const MeanCurvatureStats h = mean_curvature_stats(s.r.net);
  EXPECT_GT(h.count, 6 * 1000);
  EXPECT_LT(std::max(std::abs(h.min + 0.5), std::abs(h.max + 0.5)), 1e-2);
  EXPECT_LT(s.seam, 5e-4);
  // The fixed rows are the data, unchanged; the centre moved up to the cap's top (2 − √3).
  const PatchComplex data = circle_fan(6, 4);
  for (int r : data.fixed) EXPECT_EQ(s.r.net.points.row(r), data.points.row(r));
  EXPECT_NEAR(s.r.net.points(0, 2), 2 - std::sqrt(3.0), 1e-4);
  // The solve comes from the least-squares mean-curvature surface (mean-curvature-start).
  const AreaRouteRecord* mc = s.r.routes.find(AreaRoute::MeanCurvatureStart);
  ASSERT_NE(mc, nullptr);
  EXPECT_TRUE(mc->tried);
  ASSERT_TRUE(s.r.routes.reported.has_value());
  EXPECT_EQ(*s.r.routes.reported, AreaRoute::MeanCurvatureStart);
}

TEST(ComplexCmc, CapFanByTheDirichletFunctionalStaysOffTheSphere) {
  const CapSolve d = solve_cap(4, CmcFunctionalKind::Dirichlet);
  ASSERT_TRUE(d.r.summary.converged) << d.r.summary.message;
  EXPECT_NEAR(d.r.H, -0.5, 0.0);
  EXPECT_NEAR(d.r.DH, d.r.D + 2 * d.r.H * d.r.V, 1e-12);
  // A critical point of D_H over a non-conformal fan: near the cap, not on it.
  EXPECT_GT(d.dA, 1e-3);
  EXPECT_LT(d.dA, 5e-2);
  EXPECT_GT(d.seam, 1e-2);
}

TEST(ComplexCmc, CapFanConvergesWithDegreeAndTheSeamsClose) {
  double dA = 1, dV = 1, dist = 1, seam = 1;
  for (int n : {4, 5, 6}) {
    const CapSolve s = solve_cap(n, CmcFunctionalKind::Area);
    ASSERT_TRUE(s.r.summary.converged) << "n = " << n << ": " << s.r.summary.message;
    EXPECT_LT(s.dA, dA / 20) << "n = " << n;
    EXPECT_LT(s.dV, dV / 20) << "n = " << n;
    EXPECT_LT(s.dist, dist / 2) << "n = " << n;
    EXPECT_LT(s.seam, seam / 1.5) << "n = " << n;
    dA = s.dA;
    dV = s.dV;
    dist = s.dist;
    seam = s.seam;
  }
  EXPECT_LT(dA, 5e-9);
  EXPECT_LT(dV, 1.1e-9);
  EXPECT_LT(dist, 2e-6);
  EXPECT_LT(seam, 5e-5);
}

TEST(ComplexCmc, CapFanVolumeFormsReturnTheCapsH) {
  // The V form at the cap's volume: the area functional's multiplier is the cap's H = −1/2; the
  // Dirichlet functional's (nlopt) the D_H multiplier near it.
  CmcOptions o = cmc_options(CmcFunctionalKind::Area, 0.0);
  o.V = kCapVolume;
  const CmcResult<PatchComplex> a = solve_cmc(circle_fan(6, 4), o);
  ASSERT_TRUE(a.summary.converged) << a.summary.message;
  EXPECT_NEAR(a.V, kCapVolume, 1e-10);
  EXPECT_NEAR(a.H, -0.5, 2e-3);
  EXPECT_LT(std::abs(a.A - kCapArea), 2e-5);
  o.functional = CmcFunctionalKind::Dirichlet;
  o.solver = CmcSolver::NLopt;
  const CmcResult<PatchComplex> d = solve_cmc(circle_fan(6, 4), o);
  ASSERT_TRUE(d.summary.converged) << d.summary.message;
  EXPECT_NEAR(d.V, kCapVolume, 1e-9);
  EXPECT_NEAR(d.H, -0.5, 0.1);
  EXPECT_GT(d.A, a.A);  // the area's minimiser at V0 has the smaller area
}

TEST(ComplexCmc, UnsupportedRequestsAreRefused) {
  const PatchComplex c = circle_fan(5, 4);
  CmcOptions o = cmc_options(CmcFunctionalKind::MeanCurvature, -0.5);
  o.solver = CmcSolver::Ceres;  // the mean-curvature functional takes newton on a complex
  EXPECT_THROW(solve_cmc(c, o), UnsupportedProblem);
  o = cmc_options(CmcFunctionalKind::Dirichlet, -0.5);
  o.fixed = FixedSet::BoundaryAdjacent;
  o.solver = CmcSolver::Newton;
  EXPECT_THROW(solve_cmc(c, o), InvalidInput);
  EXPECT_THROW(solve_cmc(circle_fan(5, 2), cmc_options(CmcFunctionalKind::Dirichlet, -0.5)), DegreeError);
  PatchComplex bad = c;
  bad.patches[0].points.pop_back();
  EXPECT_THROW(solve_cmc(bad, cmc_options(CmcFunctionalKind::Area, -0.5)), SizeError);
  bad = c;
  bad.points(0, 0) = std::nan("");
  EXPECT_THROW(solve_cmc(bad, cmc_options(CmcFunctionalKind::Area, -0.5)), NonFiniteError);
}

TEST(ComplexCmc, SeamAngleOfAKnownKink) {
  // Two flat triangles folded along their shared edge by a right angle: the seam angle is π/2.
  PatchComplex c;
  c.points.resize(4, 3);
  c.points << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  // Degree 1: patch 0 (P_100, P_010, P_001) = rows (1, 2, 0) in the plane z = 0 (normal +z);
  // patch 1 = rows (3, 0, 2) shares the edge between rows 2 and 0, in the opposite direction, and
  // lies in the plane x = 0 (normal +x).
  c.patches = {{PatchKind::triangular, 1, {1, 2, 0}}, {PatchKind::triangular, 1, {3, 0, 2}}};
  EXPECT_NEAR(max_seam_angle(c), std::numbers::pi / 2, 1e-12);
  c.points.row(3) << -1, 0, 0;  // unfolded into the plane: no kink
  EXPECT_NEAR(max_seam_angle(c), 0.0, 1e-7);
}

// The catenoid between the unit circles at z = ∓1/2 (its stable branch ρ = a cosh(z/a),
// a cosh(1/(2a)) = 1, a = 0.848337938095): a ring of four tensor patches, area functional, H = 0.
// Measured (Release, 2 cores):
//   n   A − A_cat    max |ρ − a cosh(z/a)|   H range on the samples     max seam angle   time
//   4    2.4e-04     1.4e-04                 [−6.2e-03, 2.5e-03]        3.3e-03 rad      0.2 s
//   6   −1.0e-06     9.1e-07                 [−1.0e-04, 2.1e-04]        2.5e-05 rad     16 s
//   8    3.0e-09     3.3e-09                 [−3.3e-06, 3.7e-06]        1.3e-07 rad      4 s
// (n = 8 from mean-curvature-start; n = 4 from the minimal-surface route.)
struct CatenoidSolve {
  CmcResult<PatchComplex> r;
  double dA, dist, seam;
};

CatenoidSolve solve_catenoid(int n) {
  double a = 0.8;  // Newton on a cosh(1/(2a)) = 1 from the stable side
  for (int it = 0; it < 50; ++it) a -= (a * std::cosh(0.5 / a) - 1) / (std::cosh(0.5 / a) - 0.5 / a * std::sinh(0.5 / a));
  CatenoidSolve s{solve_cmc(circle_ring(4, n, 0.5), cmc_options(CmcFunctionalKind::Area, 0.0)), 0, 0, 0};
  s.dA = std::abs(s.r.A - 5.99179697580228);
  for (int p = 0; p < 4; ++p) {
    const TensorNet net = tensor_patch(s.r.net, p);
    for (int i = 0; i <= 20; ++i)
      for (int j = 0; j <= 20; ++j) {
        const Eigen::Vector3d x = net.evaluate(i / 20.0, j / 20.0);
        s.dist = std::max(s.dist, std::abs(std::hypot(x(0), x(1)) - a * std::cosh(x(2) / a)));
      }
  }
  s.seam = max_seam_angle(s.r.net);
  return s;
}

TEST(ComplexCmc, CatenoidRingByTheAreaFunctional) {
  const CatenoidSolve s4 = solve_catenoid(4), s8 = solve_catenoid(8);
  ASSERT_TRUE(s4.r.summary.converged) << s4.r.summary.message;
  ASSERT_TRUE(s8.r.summary.converged) << s8.r.summary.message;
  EXPECT_LT(s4.dA, 5e-4);
  EXPECT_LT(s8.dA, 6e-9);
  EXPECT_LT(s8.dist, 7e-9);
  EXPECT_LT(s8.seam, 3e-7);
  EXPECT_LT(s8.seam, s4.seam / 1000);
  const MeanCurvatureStats h = mean_curvature_stats(s8.r.net);
  // 672 free coordinates at n = 8, above the 600 of mean-curvature-start (tuning.h): the
  // minimal-surface route's end, |H| on the samples up to 6.3e-7 (measured; from the least-squares
  // mean-curvature surface 3.7e-6, in 7 times the time).
  EXPECT_LT(std::max(std::abs(h.min), std::abs(h.max)), 2e-6);
  EXPECT_EQ(s8.r.routes.reported, AreaRoute::MinimalSurface);
}

// The same catenoid on the ring refined once at n = 8 (16 patches, 2880 free coordinates): above
// 1500 the solve runs on sparse matrices (docs/cmc_algorithm.md, "Surfaces of several patches").
// Measured: converged from the Dirichlet extremal in 2 corrector iterations, A − A_cat within
// 6e-9, |H| on the samples up to 1.4e-5 (next to the seams), about 1 s.
TEST(ComplexCmc, CatenoidOnTheRefinedRingSolvesOnSparseMatrices) {
  const PatchComplex c = refine_h(circle_ring(4, 8, 0.5));
  ASSERT_GT(3 * complex_free_rows(c).size(), 1500u);
  const CmcResult<PatchComplex> r = solve_cmc(c, cmc_options(CmcFunctionalKind::Area, 0.0));
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.routes.reported, AreaRoute::MinimalSurface);
  EXPECT_LT(std::abs(r.A - 5.99179697580228), 6e-9);
  const MeanCurvatureStats h = mean_curvature_stats(r.net);
  EXPECT_LT(std::max(std::abs(h.min), std::abs(h.max)), 5e-5);  // measured 1.4e-5 (1/R ~ 1)
}

// The sparse start of a complex (cmc_problem.h, dirichlet_solve_sparse: the complex's sparse Gram,
// CHOLMOD) against the dense one (the assembled Gram, dense Cholesky) on mid-size complexes: the
// same Dirichlet extremal and the same solves with the free Gram (the tangent at H = 0).
void expect_sparse_start_matches_dense(const PatchComplex& c) {
  const ComplexNet net(c);
  const std::vector<int> fixed = net.fixed_indices(FixedSet::Boundary);
  cmc_detail::CmcProblem dense{net.functional(), net.free_indices(FixedSet::Boundary), net.points()};
  for (int r : dense.free) dense.P.row(r).setZero();
  cmc_detail::CmcProblem sparse = dense;
  const cmc_detail::DirichletFactor fd = cmc_detail::dirichlet_solve(dense, fixed);
  const cmc_detail::DirichletFactor fs = cmc_detail::dirichlet_solve_sparse(sparse, fixed, c);
  ASSERT_TRUE(fs.sparse);
  EXPECT_FALSE(fs.gram);
  EXPECT_TRUE(fd.cholesky());
  EXPECT_TRUE(fs.cholesky());
  const double size = dense.P.cwiseAbs().maxCoeff();
  EXPECT_GT(size, 0.5);
  EXPECT_LT((sparse.P - dense.P).cwiseAbs().maxCoeff(), 1e-11 * size);
  // the extremal: the free rows of ∇D vanish (to rounding of the terms' size)
  EXPECT_LT(dense.residual(0.0), 1e-11);
  EXPECT_LT(sparse.residual(0.0), 1e-11);
  // the free Gram's solves agree (the tangent at H = 0, initial_tangent)
  const Eigen::MatrixX3d B = Eigen::MatrixX3d::Random(dense.k(), 3);
  const Eigen::MatrixX3d Xd = fd.solve(B), Xs = fs.solve(B);
  EXPECT_LT((Xs - Xd).cwiseAbs().maxCoeff(), 1e-9 * Xd.cwiseAbs().maxCoeff());
  // and the preconditioner formed on demand is a Cholesky factor of the free Gram
  cmc_detail::DirichletFactor fl = cmc_detail::dirichlet_solve_sparse(sparse, fixed, c);
  const Eigen::MatrixXd& L = cmc_detail::preconditioner(fl, sparse);
  const Eigen::MatrixXd Cff = net.functional()->gram()(dense.free, dense.free);
  EXPECT_LT((L * L.transpose() - Cff).cwiseAbs().maxCoeff(), 1e-12 * Cff.cwiseAbs().maxCoeff());
}

TEST(ComplexCmc, SparseAndDenseStartsAgreeOnTheRefinedRing) {
  const PatchComplex c = refine_h(refine_h(circle_ring(4, 4, 0.5)));  // 64 tensor patches
  ASSERT_GT(3 * complex_free_rows(c).size(), 1500u);
  expect_sparse_start_matches_dense(c);
}

TEST(ComplexCmc, SparseAndDenseStartsAgreeOnTheRefinedFan) {
  expect_sparse_start_matches_dense(refine_h(circle_fan(6, 6)));  // 24 triangular patches
}

// The D_H route above the sparse threshold (the ring of 4 patches at degree 12, 1584 free
// coordinates): the continuation starts from the sparse factor's tangent, and the Newton and the
// NLopt correctors (the latter with the preconditioner formed on demand) reach the same critical
// point, away from the H = 0 extremal.
TEST(ComplexCmc, DirichletFunctionalFromTheSparseStartAgreesAcrossCorrectors) {
  const PatchComplex c = circle_ring(4, 12, 0.5);
  ASSERT_GT(3 * complex_free_rows(c).size(), 1500u);
  CmcOptions o = cmc_options(CmcFunctionalKind::Dirichlet, 0.3);
  o.tolerance = 1e-12;
  o.solver = CmcSolver::Newton;
  const CmcResult<PatchComplex> rn = solve_cmc(c, o);
  o.solver = CmcSolver::NLopt;
  const CmcResult<PatchComplex> rl = solve_cmc(c, o);
  ASSERT_TRUE(rn.summary.converged) << rn.summary.message;
  ASSERT_TRUE(rl.summary.converged) << rl.summary.message;
  EXPECT_GT(rn.continuation_steps, 0);
  // measured: V and D agree to 3e-12, the points to 1.7e-6 (the degree-12 Gram's soft modes)
  EXPECT_NEAR(rn.V, rl.V, 1e-9);
  EXPECT_NEAR(rn.D, rl.D, 1e-9);
  EXPECT_LT((rn.net.points - rl.net.points).cwiseAbs().maxCoeff(), 2e-5);
  EXPECT_GT(std::abs(rn.V - solve_cmc(c, cmc_options(CmcFunctionalKind::Dirichlet, 0.0)).V), 1e-3);
}

}  // namespace
}  // namespace bpde::testing
