// complex/layout_loops.h and the curve pieces of boundaries/boundary_curves.h: complexes from
// boundary loops (discs, annuli, user layouts) and their bad input.
#include "bezierpde/core/eigen.h"
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/complex/layout_loops.h"
#include "bezierpde/solvers/complex/complex_extremal.h"

using namespace bpde;

namespace {

const double kPi = std::numbers::pi;

class LoopKinds : public ::testing::TestWithParam<PatchKind> {};

double mesh_area(const TriangleMesh& m) {
  double a = 0;
  for (int f = 0; f < m.F.rows(); ++f) {
    const Eigen::Vector3d p = m.V.row(m.F(f, 0)), q = m.V.row(m.F(f, 1)), r = m.V.row(m.F(f, 2));
    a += 0.5 * (q - p).cross(r - p).norm();
  }
  return a;
}

/// The regular polygon of k segments on the unit circle, counter-clockwise about +z.
Loop polygon(int k, double z = 0) {
  Loop loop;
  for (int i = 0; i < k; ++i) {
    const double a = 2 * kPi * i / k, b = 2 * kPi * (i + 1) / k;
    loop.push_back(BoundaryCurve::segment({std::cos(a), std::sin(a), z}, {std::cos(b), std::sin(b), z}));
  }
  return loop;
}

double distance_to_polygon(const Eigen::Vector3d& x, const Loop& loop) {
  double d = INFINITY;
  for (const BoundaryCurve& c : loop) {
    const Eigen::Vector3d a = c.start(), b = c.end();
    const double t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    d = std::min(d, (a + t * (b - a) - x).norm());
  }
  return d;
}

}  // namespace

TEST(CurvePieces, PiecesAreTheSameCurveReparametrised) {
  const BoundaryCurve circle = BoundaryCurve::circle({1, 2, 3}, {0, 0, 1}, 2.0);
  EXPECT_EQ(circle.kind(), "circle");
  EXPECT_EQ(circle.start(), circle.end());
  Eigen::MatrixX3d P(4, 3);
  P << 0, 0, 0, 1, 2, 0, 3, -1, 1, 4, 0, 2;
  Eigen::MatrixX3d S(5, 3);
  S << 0, 0, 0, 1, 0.2, 0, 2, 0.1, 0, 3, 0.3, 0, 4, 0, 0;
  for (const BoundaryCurve& c : {circle, BoundaryCurve::bezier(P), BoundaryCurve::samples(S),
                                 BoundaryCurve::helix({0, 0, 0}, {0, 0, 1}, 1, 0, 3, 0.5)}) {
    const BoundaryCurve p = c.piece(0.2, 0.7);
    for (double s : {0.0, 0.1, 0.5, 0.9, 1.0})
      EXPECT_LT((p.evaluate(s) - c.evaluate(0.2 + 0.5 * s)).norm(), 1e-13) << c.kind() << " " << s;
  }
  EXPECT_EQ(circle.piece(0.5, 1.0).end(), circle.start());  // the closing point exactly
  EXPECT_EQ(BoundaryCurve::bezier(P).piece(0.3, 0.6).kind(), "bezier");
  EXPECT_THROW(circle.piece(0.5, 0.5), ParameterError);
  const BoundaryCurve closed = BoundaryCurve::closed_samples(S.topRows(4));
  EXPECT_EQ(closed.start(), closed.end());
}

TEST_P(LoopKinds, OneCircleGivesAPlanarDiscWithTwoPatchesAtEveryBoundaryVertex) {
  const LoopComplex lc = loop_complex(GetParam(), 8, {{BoundaryCurve::circle({0, 0, 0}, {0, 0, 1}, 1.0)}});
  EXPECT_EQ(lc.complex.patches.size(), GetParam() == PatchKind::triangular ? 6u : 5u);
  ASSERT_NO_THROW(validate(lc.complex));
  for (const EdgeFit& f : lc.fits) EXPECT_LT(f.max_error, 1e-6);  // a sixth or a quarter of the circle at n = 8
  for (const auto& loop : layout_boundary_loops(lc.layout))
    for (int v : loop) {
      int faces = 0;
      for (const auto& face : lc.layout.faces) faces += std::count(face.begin(), face.end(), v);
      EXPECT_EQ(faces, 2) << "boundary vertex " << v;
    }
  const ComplexExtremal e = solve_complex_extremal(lc.complex, EnergySpec::dirichlet());
  ASSERT_TRUE(e.summary.converged);
  EXPECT_LT(e.complex.points.col(2).cwiseAbs().maxCoeff(), 1e-14);
  const ComplexMesh m = sample_complex(e.complex, 32);
  const int segments = static_cast<int>(lc.boundary.size()) * 32;
  // the welded mesh is the disc less the circle's segments: the inscribed polygon's area
  EXPECT_NEAR(mesh_area(m.mesh), 0.5 * segments * std::sin(2 * kPi / segments), 1e-5);
}

TEST_P(LoopKinds, PolygonsOfFiveAndEightSidesAndTheirPatchCounts) {
  for (int k : {5, 8}) {
    const Loop loop = polygon(k);
    const LoopComplex lc = loop_complex(GetParam(), 4, {loop});
    const std::size_t expected = GetParam() == PatchKind::triangular ? k : k == 5 ? 9 : 12;
    EXPECT_EQ(lc.complex.patches.size(), expected) << k;
    for (int r : lc.complex.fixed) EXPECT_LT(distance_to_polygon(lc.complex.points.row(r).transpose(), loop), 1e-15);
    EXPECT_EQ(lc.complex.fixed, boundary_rows(lc.complex));
    const ComplexExtremal e = solve_complex_extremal(lc.complex, EnergySpec::dirichlet());
    EXPECT_TRUE(e.summary.converged);
    // a polygon of segments is spanned by its plane: the mesh area is the polygon's
    EXPECT_NEAR(mesh_area(sample_complex(e.complex, 8).mesh), 0.5 * k * std::sin(2 * kPi / k), 1e-12) << k;
  }
}

TEST_P(LoopKinds, TwoCirclesGiveAnAnnulus) {
  const Loop top{BoundaryCurve::circle({0, 0, 0.5}, {0, 0, 1}, 1.0)};
  const Loop bottom{BoundaryCurve::circle({0, 0, -0.5}, {0, 0, -1}, 1.0)};
  const LoopComplex lc = loop_complex(GetParam(), 8, {top, bottom});
  EXPECT_EQ(lc.complex.patches.size(), GetParam() == PatchKind::triangular ? 8u : 4u);
  EXPECT_EQ(layout_boundary_loops(lc.layout).size(), 2u);
  for (int r : lc.complex.fixed) {
    const Eigen::Vector3d x = lc.complex.points.row(r);
    EXPECT_NEAR(std::abs(x(2)), 0.5, 1e-13);
  }
  const ComplexExtremal e = solve_complex_extremal(lc.complex, EnergySpec::dirichlet());
  ASSERT_TRUE(e.summary.converged);
  // a tube: every sample between the planes, and its mean radius near 1 (the harmonic tube
  // of this parametrisation narrows in the middle, it is no cylinder)
  const ComplexMesh m = sample_complex(e.complex, 8);
  EXPECT_LE(m.mesh.V.col(2).cwiseAbs().maxCoeff(), 0.5 + 1e-12);
  const Eigen::VectorXd radius = m.mesh.V.leftCols(2).rowwise().norm();
  EXPECT_GT(radius.minCoeff(), 0.5);
  EXPECT_LT(radius.maxCoeff(), 1.0 + 1e-6);
}

TEST(LoopComplex, BadLoopsAreRefusedWithTheirTypes) {
  const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_THROW(loop_complex(PatchKind::triangular, 3, {{BoundaryCurve::segment(a, b), BoundaryCurve::segment(b, c)}}),
               LoopNotClosedError);
  EXPECT_THROW(loop_complex(PatchKind::triangular, 3,
                            {{BoundaryCurve::segment(a, b), BoundaryCurve::segment(c, a), BoundaryCurve::segment(b, c)}}),
               CurvesOutOfOrderError);
  EXPECT_THROW(loop_complex(PatchKind::triangular, 3,
                            {{BoundaryCurve::segment(a, b), BoundaryCurve::segment(c, b), BoundaryCurve::segment(c, a)}}),
               CurvesOutOfOrderError);
  const Loop open_arc{BoundaryCurve::arc({0, 0, 0}, {0, 0, 1}, 1, 0, 6)};
  EXPECT_THROW(loop_complex(PatchKind::tensor, 3, {open_arc}), LoopNotClosedError);
  EXPECT_THROW(loop_complex(PatchKind::tensor, 3, {}), SizeError);
  EXPECT_THROW(loop_complex(PatchKind::tensor, 3, {polygon(3), polygon(4, 1), polygon(5, 2)}), SizeError);
  EXPECT_THROW(loop_complex(PatchKind::tensor, 0, {polygon(4)}), DegreeError);
}

TEST(LoopComplex, UserLayoutFollowsItsCurvesAndRefusesMismatches) {
  // the square [0,2]² as four segments, laid out as 2 x 2 quads; each side is two layout edges
  const Eigen::Vector3d p0(0, 0, 0), p1(2, 0, 0), p2(2, 2, 0), p3(0, 2, 0);
  const Loop square{BoundaryCurve::segment(p0, p1), BoundaryCurve::segment(p1, p2), BoundaryCurve::segment(p2, p3),
                    BoundaryCurve::segment(p3, p0)};
  Layout L;
  L.kind = PatchKind::tensor;
  L.vertices = Eigen::MatrixX3d::Zero(9, 3);  // vertex 3i + j at (i, j); boundary positions come from the curves
  L.vertices.row(4) << 1.2, 0.9, 0.3;         // the inner vertex: a start only
  L.faces = {{0, 3, 4, 1}, {3, 6, 7, 4}, {4, 7, 8, 5}, {1, 4, 5, 2}};
  std::vector<LayoutBoundaryEdge> boundary{{0, 3, {0, 0, 0, 0.5}}, {3, 6, {0, 0, 0.5, 1}}, {6, 7, {0, 1, 0, 0.5}},
                                           {7, 8, {0, 1, 0.5, 1}}, {8, 5, {0, 2, 0, 0.5}}, {5, 2, {0, 2, 0.5, 1}},
                                           {2, 1, {0, 3, 0, 0.5}}, {1, 0, {0, 3, 0.5, 1}}};
  const LoopComplex lc = layout_complex(L, 3, {square}, boundary);
  EXPECT_EQ(lc.complex.points.row(8), Eigen::RowVector3d(2, 2, 0));
  EXPECT_EQ(lc.complex.points.row(7), Eigen::RowVector3d(2, 1, 0));
  const ComplexExtremal e = solve_complex_extremal(lc.complex, EnergySpec::dirichlet());
  EXPECT_LT((e.complex.points.row(4) - Eigen::RowVector3d(1, 1, 0)).norm(), 1e-13);  // the symmetric harmonic map
  auto broken = boundary;
  broken.pop_back();
  EXPECT_THROW(layout_complex(L, 3, {square}, broken), LayoutMismatchError);
  broken = boundary;
  std::swap(broken[0].a, broken[0].b);
  EXPECT_THROW(layout_complex(L, 3, {square}, broken), LayoutMismatchError);
  broken = boundary;
  broken[1].piece.t0 = 0.6;
  EXPECT_THROW(layout_complex(L, 3, {square}, broken), LayoutMismatchError);
  broken = boundary;
  std::swap(broken[0].piece, broken[2].piece);  // side 0's first half on side 1's edge
  EXPECT_THROW(layout_complex(L, 3, {square}, broken), LayoutMismatchError);
}

INSTANTIATE_TEST_SUITE_P(Kinds, LoopKinds, ::testing::Values(PatchKind::triangular, PatchKind::tensor));
