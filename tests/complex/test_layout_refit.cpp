// complex/layout_loops.h: the annulus's inner-loop orientation rule and refit_boundary (the
// boundary of a complex refined in h fitted again on the refined layout).
#include "bezierpde/core/eigen.h"
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/complex/refine.h"

using namespace bpde;

namespace {

const double kPi = std::numbers::pi;

/// The unit circle at height z as k arcs, counter-clockwise about +z (reverse: the other way,
/// the arcs in reverse order, each reversed).
Loop arcs(int k, double z, bool reverse = false) {
  Loop loop;
  for (int i = 0; i < k; ++i) {
    const double a = 2 * kPi * i / k, b = 2 * kPi * (i + 1) / k;
    loop.push_back(reverse ? BoundaryCurve::arc({0, 0, z}, {0, 0, 1}, 1, 2 * kPi - a, 2 * kPi - b)
                           : BoundaryCurve::arc({0, 0, z}, {0, 0, 1}, 1, a, b));
  }
  return loop;
}

double circle_distance(const Eigen::Vector3d& x) { return std::abs(std::hypot(x(0), x(1)) - 1.0); }

class RefitKinds : public ::testing::TestWithParam<PatchKind> {};

}  // namespace

TEST_P(RefitKinds, AnnulusInnerLoopMustRunTheOtherWayRound) {
  const Loop top{BoundaryCurve::circle({0, 0, 0.5}, {0, 0, 1}, 1.0)};
  const Loop bottom_opposite{BoundaryCurve::circle({0, 0, -0.5}, {0, 0, -1}, 1.0)};
  const Loop bottom_same{BoundaryCurve::circle({0, 0, -0.5}, {0, 0, 1}, 1.0)};
  EXPECT_NO_THROW(loop_complex(GetParam(), 4, {top, bottom_opposite}));
  EXPECT_THROW(loop_complex(GetParam(), 4, {top, bottom_same}), LoopOrientationError);
  // loops of several curves: the inner one's arcs reversed in order and direction is accepted
  EXPECT_NO_THROW(loop_complex(GetParam(), 4, {arcs(5, 0.5), arcs(3, -0.5, true)}));
  EXPECT_THROW(loop_complex(GetParam(), 4, {arcs(5, 0.5), arcs(3, -0.5)}), LoopOrientationError);
  // a flat ring (both loops in one plane): the inner circle clockwise about +z
  const Loop outer{BoundaryCurve::circle({0, 0, 0}, {0, 0, 1}, 2.0)};
  EXPECT_NO_THROW(loop_complex(GetParam(), 4, {outer, {BoundaryCurve::circle({0, 0, 0}, {0, 0, -1}, 1.0)}}));
  EXPECT_THROW(loop_complex(GetParam(), 4, {outer, {BoundaryCurve::circle({0, 0, 0}, {0, 0, 1}, 1.0)}}),
               LoopOrientationError);
}

TEST_P(RefitKinds, RefitBoundaryErrorFallsAsHToTheDegreePlusOne) {
  // the unit circle at degree 3, Chebyshev interpolation of arcs of angle θ: error ∝ θ⁴
  const int n = 3;
  const std::vector<Loop> loops{{BoundaryCurve::circle({0, 0, 0}, {0, 0, 1}, 1.0)}};
  const LoopComplex coarse = loop_complex(GetParam(), n, loops);
  PatchComplex refined = coarse.complex;
  double previous = 0;
  for (const EdgeFit& f : coarse.fits) previous = std::max(previous, f.max_error);
  EXPECT_EQ(refit_boundary(refined, coarse, 0, loops).size(), coarse.fits.size());
  for (int r = 1; r <= 3; ++r) {
    refined = refine_h(refined);
    PatchComplex refit = refined;
    const std::vector<EdgeFit> fits = refit_boundary(refit, coarse, r, loops);
    ASSERT_EQ(fits.size(), coarse.fits.size());
    double error = 0;
    for (const EdgeFit& f : fits) error = std::max(error, f.max_error);
    EXPECT_GT(previous / error, 12.0) << "r = " << r;  // 2⁴ = 16
    EXPECT_LT(previous / error, 20.0) << "r = " << r;
    // every boundary row of the refit complex: on the circle (vertices) or within the error of
    // the fit of its control polygon (a degree-3 arc's inner control points lie off the circle
    // by about θ²/8, the distance the coarse fit's rows have too)
    double vertex_distance = 0;
    for (int row : refit.fixed)
      if (row < static_cast<int>(refit.points.rows()) && std::abs(refit.points(row, 2)) > 1e-15) ADD_FAILURE() << row;
    for (const ComplexPatch& p : refit.patches)
      for (int e = 0; e < patch_edge_count(p.kind); ++e) {
        const std::vector<int> local = patch_edge_local_rows(p.kind, n, e);
        const int a = p.points[local.front()], b = p.points[local.back()];
        if (std::binary_search(refit.fixed.begin(), refit.fixed.end(), a) &&
            std::binary_search(refit.fixed.begin(), refit.fixed.end(), b) &&
            std::binary_search(refit.fixed.begin(), refit.fixed.end(), p.points[local[1]]))
          vertex_distance = std::max({vertex_distance, circle_distance(refit.points.row(a).transpose()),
                                      circle_distance(refit.points.row(b).transpose())});
      }
    EXPECT_LT(vertex_distance, 1e-14) << "r = " << r;
    // the subdivided complex's boundary was the coarse fit; refit moved it towards the circle
    EXPECT_GT((refit.points - refined.points).cwiseAbs().maxCoeff(), error);
    previous = error;
  }
}

TEST_P(RefitKinds, RefitOfAPolygonChangesNothing) {
  // segments are fitted exactly: the subdivided complex already is the refit one
  Loop pentagon;
  for (int i = 0; i < 5; ++i) {
    const double a = 2 * kPi * i / 5, b = 2 * kPi * (i + 1) / 5;
    pentagon.push_back(BoundaryCurve::segment({std::cos(a), std::sin(a), 0}, {std::cos(b), std::sin(b), 0}));
  }
  const LoopComplex coarse = loop_complex(GetParam(), 4, {pentagon});
  const PatchComplex refined = refine_h(refine_h(coarse.complex));
  PatchComplex refit = refined;
  refit_boundary(refit, coarse, 2, {pentagon});
  EXPECT_LT((refit.points - refined.points).cwiseAbs().maxCoeff(), 1e-14);
  PatchComplex wrong = refine_h(coarse.complex);
  EXPECT_THROW(refit_boundary(wrong, coarse, 3, {pentagon}), SizeError);
}

INSTANTIATE_TEST_SUITE_P(Kinds, RefitKinds, ::testing::Values(PatchKind::triangular, PatchKind::tensor));
