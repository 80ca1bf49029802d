// complex/patch_complex.h, layout.h, complex_mesh.h: construction checks, patches as nets, the
// welded mesh and the seam angle.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/core/errors.h"
#include "tests/complex/complex_fixtures.h"

using namespace bpde;
using namespace bpde::test;

namespace {

Eigen::Vector3d paraboloid(double x, double y) { return {x, y, 0.3 * x * x - 0.2 * x * y + 0.1 * y * y}; }

class ComplexKinds : public ::testing::TestWithParam<PatchKind> {};

}  // namespace

TEST(PatchComplex, ValidateRejectsBadComplexesWithTypedErrors) {
  const Layout L = grid_layout(PatchKind::tensor, 2);
  const PatchComplex good = complex_topology(L, 3);
  EXPECT_NO_THROW(validate(good));
  EXPECT_THROW(validate(PatchComplex{}), SizeError);
  PatchComplex c = good;
  c.patches[1].points.pop_back();
  EXPECT_THROW(validate(c), SizeError);
  c = good;
  c.patches[2].points[5] = static_cast<int>(c.points.rows());
  EXPECT_THROW(validate(c), SizeError);
  c = good;
  c.patches[3].degree = 2;
  EXPECT_THROW(validate(c), DegreeError);
  c = good;
  c.patches[2].kind = PatchKind::triangular;
  EXPECT_THROW(validate(c), DegreeError);
  c = good;
  c.points(7, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(validate(c), NonFiniteError);
  c = good;
  c.fixed = {3, 1};
  EXPECT_THROW(validate(c), ParameterError);
  c = good;
  c.patches.push_back(c.patches[0]);  // the same edges a third time
  EXPECT_THROW(validate(c), ParameterError);
}

TEST(PatchComplex, LayoutsThatAreNoOrientedManifoldAreRefused) {
  Layout L = grid_layout(PatchKind::triangular, 1);
  EXPECT_NO_THROW(validate_layout(L));
  Layout flipped = L;
  std::swap(flipped.faces[1][0], flipped.faces[1][1]);
  EXPECT_THROW(validate_layout(flipped), ParameterError);
  Layout bowtie;  // two triangles that meet in one vertex only
  bowtie.kind = PatchKind::triangular;
  bowtie.vertices.resize(5, 3);
  bowtie.vertices << 0, 0, 0, 1, 0, 0, 0, 1, 0, -1, 0, 0, 0, -1, 0;
  bowtie.faces = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_THROW(validate_layout(bowtie), ParameterError);
  Layout quad_in_triangles = L;
  quad_in_triangles.faces[0].push_back(2);
  EXPECT_THROW(validate_layout(quad_in_triangles), ParameterError);
  Layout out_of_range = L;
  out_of_range.faces[0][2] = 9;
  EXPECT_THROW(validate_layout(out_of_range), ParameterError);
  EXPECT_THROW(complex_topology(L, 0), DegreeError);
}

TEST_P(ComplexKinds, PatchesAreTheNetsOfTheirRowsAndWriteBack) {
  const Layout L = grid_layout(GetParam(), 2);
  PatchComplex c = complex_topology(L, 3);
  set_from_function(c, L, paraboloid);
  ASSERT_NO_THROW(validate(c));
  EXPECT_EQ(c.fixed, boundary_rows(c));
  EXPECT_EQ(layout_boundary_loops(L).size(), 1u);
  EXPECT_EQ(layout_boundary_loops(L)[0].size(), 8u);
  for (int f = 0; f < static_cast<int>(c.patches.size()); ++f)
    for (double u : {0.0, 0.2, 0.5})
      for (double v : {0.0, 0.3, 0.5}) {
        const Eigen::Vector2d X = face_map(L, f, u, v);
        EXPECT_LT((patch_point(c, f, u, v) - paraboloid(X(0), X(1))).norm(), 1e-13);
      }
  // write back: moving patch 0's points moves the rows it shares with its neighbours
  Eigen::MatrixX3d P = GetParam() == PatchKind::tensor ? tensor_net(c, 0).points() : triangular_net(c, 0).points();
  P.col(2).array() += 1.0;
  set_patch_points(c, 0, P);
  const Eigen::MatrixX3d back = GetParam() == PatchKind::tensor ? tensor_net(c, 0).points() : triangular_net(c, 0).points();
  EXPECT_EQ(back, P);
  EXPECT_THROW(set_patch_points(c, 0, P.topRows(2)), SizeError);
  EXPECT_THROW(triangular_net(c, 99), SizeError);
  EXPECT_THROW(GetParam() == PatchKind::tensor ? (void)triangular_net(c, 0) : (void)tensor_net(c, 0), ParameterError);
}

TEST_P(ComplexKinds, SampledComplexIsOneWeldedMesh) {
  const int k = 2, N = 5;
  const Layout L = grid_layout(GetParam(), k);
  PatchComplex c = complex_topology(L, 3);
  set_from_function(c, L, paraboloid);
  const ComplexMesh m = sample_complex(c, N);
  // every patch's samples lie on the global lattice of spacing 1/N: welded, it has (kN+1)^2 vertices
  EXPECT_EQ(m.mesh.V.rows(), (k * N + 1) * (k * N + 1));
  const int per_patch = GetParam() == PatchKind::tensor ? 2 * N * N : N * N;
  EXPECT_EQ(m.mesh.F.rows(), static_cast<int>(c.patches.size()) * per_patch);
  ASSERT_EQ(m.patch.size(), m.mesh.F.rows());
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) EXPECT_EQ((m.patch.array() == p).count(), per_patch);
  // each mesh edge has one or two triangles, and exactly the 4kN boundary edges have one
  std::map<std::pair<int, int>, int> uses;
  for (int f = 0; f < m.mesh.F.rows(); ++f)
    for (int e = 0; e < 3; ++e) {
      const int a = m.mesh.F(f, e), b = m.mesh.F(f, (e + 1) % 3);
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  int boundary = 0;
  for (const auto& [edge, count] : uses) {
    EXPECT_LE(count, 2);
    boundary += count == 1;
  }
  EXPECT_EQ(boundary, 4 * k * N);
  for (int r = 0; r < m.mesh.V.rows(); ++r) {
    const Eigen::Vector3d x = m.mesh.V.row(r).transpose();
    EXPECT_LT((x - paraboloid(x(0), x(1))).norm(), 1e-13);
  }
  EXPECT_THROW(sample_complex(c, 0), ParameterError);
}

TEST_P(ComplexKinds, SeamAngleIsZeroOnOneSmoothSurfaceAndTheCreaseAngleOnARoof) {
  const Layout L = grid_layout(GetParam(), 2);
  PatchComplex c = complex_topology(L, 4);
  set_from_function(c, L, paraboloid);
  EXPECT_LT(seam_angle_max(c), 1e-6);
  // the roof z = |x - 1| over [0,2]^2: the planes' normals (-1,0,1)/√2 and (1,0,1)/√2 meet at 90°
  set_from_function(c, L, [](double x, double y) { return Eigen::Vector3d(x, y, std::abs(x - 1)); });
  EXPECT_NEAR(seam_angle_max(c), 90.0, 1e-9);
  // a crease of 30° between the normals: z = tan(30°)(x - 1) for x > 1
  const double t = std::tan(M_PI / 6);
  set_from_function(c, L, [t](double x, double y) { return Eigen::Vector3d(x, y, x > 1 ? t * (x - 1) : 0.0); });
  EXPECT_NEAR(seam_angle_max(c), 30.0, 1e-9);
  EXPECT_THROW(seam_angle_max(c, 0), ParameterError);
}

INSTANTIATE_TEST_SUITE_P(Kinds, ComplexKinds, ::testing::Values(PatchKind::triangular, PatchKind::tensor));
