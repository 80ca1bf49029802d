// complex/refine.h: h and p refinement describe the same surface, and shared edges stay shared.
#include <gtest/gtest.h>

#include <random>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/refine.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "tests/complex/complex_fixtures.h"

using namespace bpde;
using namespace bpde::test;

namespace {

class RefineKinds : public ::testing::TestWithParam<PatchKind> {};

/// A 2 x 2 grid layout of degree n with every control point moved at random (a surface that is
/// no polynomial of lower degree, with creases at the seams).
PatchComplex random_complex(PatchKind kind, int n, unsigned seed) {
  PatchComplex c = complex_topology(grid_layout(kind, 2), n);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> d(-0.3, 0.3);
  for (int r = 0; r < c.points.rows(); ++r)
    for (int k = 0; k < 3; ++k) c.points(r, k) += d(rng);
  return c;
}

/// The largest distance from a vertex of `fine` to the nearest vertex of `coarse`.
double farthest_vertex(const Eigen::MatrixX3d& fine, const Eigen::MatrixX3d& coarse) {
  double worst = 0;
  for (int r = 0; r < fine.rows(); ++r)
    worst = std::max(worst, (coarse.rowwise() - fine.row(r)).rowwise().norm().minCoeff());
  return worst;
}

}  // namespace

TEST_P(RefineKinds, HRefinementIsTheSameSurfaceWithSharedEdges) {
  const int n = 4, M = 3;
  const PatchComplex c = random_complex(GetParam(), n, 7);
  const PatchComplex h = refine_h(c);
  ASSERT_NO_THROW(validate(h));
  EXPECT_EQ(h.patches.size(), 4 * c.patches.size());
  // the boundary doubles its edges, so its rows: 8 edges of degree n -> 16 (a seam left unshared
  // would add its rows to the boundary)
  EXPECT_EQ(boundary_rows(c).size(), 8u * n);
  EXPECT_EQ(boundary_rows(h).size(), 16u * n);
  EXPECT_EQ(h.fixed, boundary_rows(h));
  // every patch's samples at M are the parent's at 2M: the welded meshes have the same vertices
  const ComplexMesh coarse = sample_complex(c, 2 * M), fine = sample_complex(h, M);
  EXPECT_EQ(fine.mesh.V.rows(), coarse.mesh.V.rows());
  EXPECT_LT(farthest_vertex(fine.mesh.V, coarse.mesh.V), 1e-13);
  EXPECT_LT(farthest_vertex(coarse.mesh.V, fine.mesh.V), 1e-13);
  // twice: 64 patches, the same surface still
  const PatchComplex hh = refine_h(h);
  EXPECT_EQ(hh.patches.size(), 16 * c.patches.size());
  EXPECT_LT(farthest_vertex(sample_complex(hh, M).mesh.V, sample_complex(c, 4 * M).mesh.V), 1e-13);
}

TEST_P(RefineKinds, PRefinementIsTheSameSurfaceWithSharedEdges) {
  const int n = 3, r = 2, N = 7;
  const PatchComplex c = random_complex(GetParam(), n, 11);
  const PatchComplex p = refine_p(c, r);
  ASSERT_NO_THROW(validate(p));
  EXPECT_EQ(p.patches.front().degree, n + r);
  EXPECT_EQ(boundary_rows(p).size(), 8u * (n + r));
  EXPECT_EQ(p.fixed, boundary_rows(p));
  const ComplexMesh a = sample_complex(c, N), b = sample_complex(p, N);
  ASSERT_EQ(a.mesh.V.rows(), b.mesh.V.rows());
  EXPECT_LT((a.mesh.V - b.mesh.V).cwiseAbs().maxCoeff(), 1e-13);
  const PatchComplex same = refine_p(c, 0);
  EXPECT_EQ(same.points.rows(), c.points.rows());
  EXPECT_LT((sample_complex(same, N).mesh.V - a.mesh.V).cwiseAbs().maxCoeff(), 1e-15);
}

TEST_P(RefineKinds, RefinementRespectsTheLimits) {
  const PatchComplex c = random_complex(GetParam(), 3, 3);
  EXPECT_THROW(refine_p(c, -1), DegreeError);
  EXPECT_THROW(refine_p(c, kMaxDegree), DegreeError);
  const int k = GetParam() == PatchKind::tensor ? 33 : 23;  // 1089 or 1058 patches: 4x is past the limit
  const PatchComplex big = complex_topology(grid_layout(GetParam(), k), 1);
  EXPECT_THROW(refine_h(big), SizeError);
}

INSTANTIATE_TEST_SUITE_P(Kinds, RefineKinds, ::testing::Values(PatchKind::triangular, PatchKind::tensor));
