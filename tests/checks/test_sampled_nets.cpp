// check_mesh on meshes sampled from the project's nets (the way `bpde check` uses it).
#include <gtest/gtest.h>

#include <vector>

#include "bezierpde/checks/mesh_checks.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {
namespace {

MeshCheckReport check(const TriangleMesh& m) {
  std::vector<double> V;
  std::vector<int> F;
  for (Eigen::Index r = 0; r < m.V.rows(); ++r)
    for (int c = 0; c < 3; ++c) V.push_back(m.V(r, c));
  for (Eigen::Index r = 0; r < m.F.rows(); ++r)
    for (int c = 0; c < 3; ++c) F.push_back(m.F(r, c));
  return check_mesh(V, F);
}

TEST(SampledNets, TensorPatchWithACollapsedEdge) {
  // Bilinear patch with P00 = P01: the edge u = 0 collapses to a point, the patch is the
  // triangle (0,0,1), (2,0,1), (2,3,1) at height 1 (area 3), oriented +z.
  Eigen::MatrixX3d P(4, 3);
  P << 0, 0, 1,  //
      0, 0, 1,   //
      2, 0, 1,   //
      2, 3, 1;
  const TensorNet net(1, 1, P);
  const int N = 8;
  const auto r = check(sample_mesh(net, N));
  EXPECT_EQ(r.degenerate_triangles, N);  // one per cell along the collapsed edge
  EXPECT_EQ(r.merged_vertices, (N + 1) * (N + 1) - N);
  EXPECT_EQ(r.self_intersections, 0);
  EXPECT_NEAR(r.cone_volume, 3.0 / 3.0, 1e-13);
  EXPECT_FALSE(r.closed);
  ASSERT_TRUE(r.volume.has_value());  // planar boundary: the cap cancels the patch
  EXPECT_NEAR(*r.volume, 0.0, 1e-13);
}

TEST(SampledNets, FlatTriangularPatch) {
  // Degree-3 triangular net of the flat triangle with corners P300 = (1,0,2), P030 = (0,1,2),
  // P003 = (0,0,2): area 1/2, normal -z or +z depending on the corner order (FORMATS.md: P003 ->
  // P300 -> P030 counter-clockwise seen from +z gives +z), so the cone volume is +(1/3)(1/2)(2).
  const int n = 3;
  TriangularNet net(n);
  for (int r = 0; r < net.size(); ++r) {
    const auto I = TriangularNet::multi_index(n, r);
    net.points().row(r) << static_cast<double>(I[0]) / n, static_cast<double>(I[1]) / n, 2.0;
  }
  const auto rep = check(sample_mesh(net, 10));
  EXPECT_EQ(rep.self_intersections, 0);
  EXPECT_EQ(rep.degenerate_triangles, 0);
  EXPECT_NEAR(rep.cone_volume, 1.0 / 3.0, 1e-13);
}

}  // namespace
}  // namespace bpde
