// The closed-form volume V = 1/3 int <x_u ^ x_v, x> (energies/volume, triangular CMC eq. (5)-(6) as
// corrected) against the CGAL unit's cone volume of the sampled mesh as the sampling refines:
// the mesh value converges to V at second order in the sample spacing.
#include <gtest/gtest.h>

#include <cmath>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/checks/mesh_checks.h"
#include "bezierpde/energies/volume.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"

using namespace bpde;

namespace {

double cone_volume(const Net& net, int N) {
  const TriangleMesh m = sample_net(net, N);
  std::vector<double> V(static_cast<size_t>(m.V.rows()) * 3);
  std::vector<int> F(static_cast<size_t>(m.F.rows()) * 3);
  for (Eigen::Index r = 0; r < m.V.rows(); ++r)
    for (int c = 0; c < 3; ++c) V[static_cast<size_t>(3 * r + c)] = m.V(r, c);
  for (Eigen::Index r = 0; r < m.F.rows(); ++r)
    for (int c = 0; c < 3; ++c) F[static_cast<size_t>(3 * r + c)] = m.F(r, c);
  return check_mesh(V, F).cone_volume;
}

template <class NetT>
void expect_second_order(const NetT& net) {
  const double exact = volume(net);
  ASSERT_GT(std::abs(exact), 1e-3);
  double previous = 0;
  for (int N : {8, 16, 32, 64}) {
    const double err = std::abs(cone_volume(Net(net), N) - exact);
    if (N > 8) {
      // halving the spacing divides the error by ~4 (second order); allow 3..5
      EXPECT_GT(previous / err, 3.0) << N;
      EXPECT_LT(previous / err, 5.0) << N;
    }
    previous = err;
  }
  EXPECT_LT(previous, 1e-2 * std::abs(exact));  // and the limit is V itself (same sign, same size)
}

}  // namespace

TEST(VolumeVsMesh, TriangularSpherePatch) {
  // a conformal sphere patch, with a non-trivial interior from a lifted centre
  TriangularNet net = triangular_boundary(6, sphere_triangle);
  for (int r : net.free_indices(FixedSet::Boundary)) net.points().row(r) << 0.1 * r, -0.05 * r, 0.3;
  expect_second_order(net);
}

TEST(VolumeVsMesh, TensorPatch) {
  TensorNet net(4, 5);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 5; ++j)
      net.set_point(i, j, {i / 4.0, j / 5.0 + 0.1 * i * (4 - i), 0.3 * std::sin(i + 2.0 * j)});
  expect_second_order(net);
}
