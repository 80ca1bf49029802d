// The sampled result surfaces of jobs/run_job.h: a single net's statistics are those of
// energies/cmc.h, and a complex's samples are counted away from its boundary corners only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/jobs/run_complex.h"
#include "bezierpde/jobs/run_job.h"

namespace {

using bpde::Json;

// A single net: the statistics over the SampledSurface equal mean_curvature_stats of the mesh
// (energies/cmc.h, corner margin 0.1), location included, for both layouts.
TEST(ResultSurface, SingleNetStatisticsAreThoseOfTheMesh) {
  const int N = 24;
  const bpde::TriangularNet tri = bpde::circle_three_arcs(6);
  bpde::TensorNet ten(3, 4);
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 4; ++j) ten.set_point(i, j, Eigen::Vector3d(i / 3.0, j / 4.0, std::sin(i + 2.0 * j) / 5));
  for (const bpde::Net& net : {bpde::Net(tri), bpde::Net(ten)}) {
    const bool is_tri = std::holds_alternative<bpde::TriangularNet>(net);
    const bpde::TriangleMesh mesh = bpde::sample_net(net, N);
    const bpde::MeanCurvatureStats want = bpde::mean_curvature_stats(
        mesh, is_tri ? bpde::SampleLayout::TriangularGrid : bpde::SampleLayout::TensorGrid, N, 0.1);
    const bpde::SampledSurface s = bpde::sampled_net(net, mesh, N);
    const bpde::SurfaceStats got = bpde::surface_stats(s);
    ASSERT_GT(want.count, 0);
    EXPECT_EQ(got.count, want.count);
    EXPECT_EQ(got.min, want.min);
    EXPECT_EQ(got.max, want.max);
    EXPECT_NEAR(got.mean, want.mean, 1e-14 * std::abs(want.mean) + 1e-300);
    EXPECT_EQ(got.at_min, want.at_min);
    EXPECT_EQ(got.at_max, want.at_max);
    // the located vertex is the mesh's sample at that (u, v)
    EXPECT_EQ(mesh.H(got.vertex_min), want.min);
    const Eigen::Vector3d x = is_tri ? tri.evaluate(got.at_max[0], got.at_max[1]) : ten.evaluate(got.at_max[0], got.at_max[1]);
    EXPECT_LT((x - mesh.V.row(got.vertex_max).transpose()).norm(), 1e-12);
    const Json j = bpde::surface_stats_json(got, s);
    EXPECT_FALSE(j.contains("patch_at_min"));
  }
}

// A complex (the unit circle's fan of 6 triangles around a centre vertex): the samples within the
// margin of a patch corner on the circle are left out, those at the centre, where the patches
// meet inside, are counted; every vertex's (u, v) in its patch gives its position.
TEST(ResultSurface, ComplexCountsItsInnerCornersAndTheVerticesOnASmoothLoop) {
  const Json boundary = Json::parse(R"({"type": "complex", "patch": "triangular", "degree": 4, "loops": [[
      {"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]})");
  const bpde::ComplexJobData data = bpde::complex_from_json(boundary, "boundary", bpde::FitMethod::Interpolation);
  ASSERT_EQ(data.complex.patches.size(), 6u);
  bpde::PatchComplex c = data.complex;
  // lift the free rows so that the surface is curved (any C⁰ data serves)
  const std::vector<int> brows = bpde::boundary_rows(c);
  for (int r = 0; r < c.points.rows(); ++r)
    if (!std::binary_search(brows.begin(), brows.end(), r)) c.points(r, 2) = 0.5 * (1 - c.points.row(r).head<2>().squaredNorm());
  const int N = 20;
  const bpde::SampledSurface s = bpde::sampled_complex(c, N);
  ASSERT_TRUE(s.complex);
  EXPECT_EQ(s.triangle_patch.size(), s.mesh.F.rows());
  int near_rim_corner = 0, near_centre = 0;
  for (Eigen::Index k = 0; k < s.mesh.V.rows(); ++k) {
    const int p = s.vertex_patch(k);
    const double u = s.uv(k, 0), v = s.uv(k, 1);
    const auto net = bpde::triangular_net(c, p);
    EXPECT_LT((net.evaluate(u, v) - s.mesh.V.row(k).transpose()).norm(), 1e-12);
    const Eigen::Vector3d x = s.mesh.V.row(k).transpose();
    const double r = x.head<2>().norm();
    // corners on the circle are the fan's boundary vertices (6, at 60° steps); the centre is inner
    bool at_rim_corner = false;
    for (int j = 0; j < 6; ++j) {
      const Eigen::Vector3d corner = c.points.row(j);  // rows 0.. are the layout's vertices
      if (corner.head<2>().norm() > 0.99 && (x - corner).norm() < 0.08) at_rim_corner = true;
    }
    if (at_rim_corner) {  // the circle does not turn there: counted
      ++near_rim_corner;
      EXPECT_EQ(s.counted(k), 1) << "vertex " << k << " at " << x.transpose();
    }
    if (r < 0.05) {
      ++near_centre;
      EXPECT_EQ(s.counted(k), 1) << "vertex " << k << " at " << x.transpose();
    }
  }
  EXPECT_GT(near_rim_corner, 6);
  EXPECT_GT(near_centre, 0);
  const bpde::SurfaceStats st = bpde::surface_stats(s);
  const Json j = bpde::surface_stats_json(st, s);
  EXPECT_EQ(j["patch_at_min"], s.vertex_patch(st.vertex_min));
  // the certificate's location: its patch and point are those of the worst sample
  const bpde::CmcCertificate cert = bpde::cmc_certificate(st, -1.0, s);
  ASSERT_TRUE(cert.point.has_value());
  const Eigen::Index worst = -1.0 - st.min >= st.max + 1.0 ? st.vertex_min : st.vertex_max;
  EXPECT_EQ(cert.patch, s.vertex_patch(worst));
  EXPECT_EQ((*cert.point)[2], s.mesh.V(worst, 2));
}

}  // namespace

TEST(ResultSurface, ComplexLeavesOutTheCornersWhereItsBoundaryTurns) {
  // a square of four segments: the loop turns by 90° at its four corners, which are layout
  // vertices; the fan's other boundary vertices (if any) and its centre are counted
  const Json boundary = Json::parse(R"({"type": "complex", "patch": "triangular", "degree": 3, "loops": [[
      {"type": "segment", "from": [1, 0, 0], "to": [0, 1, 0]},
      {"type": "segment", "from": [0, 1, 0], "to": [-1, 0, 0]},
      {"type": "segment", "from": [-1, 0, 0], "to": [0, -1, 0]},
      {"type": "segment", "from": [0, -1, 0], "to": [1, 0, 0]}]]})");
  const bpde::ComplexJobData data = bpde::complex_from_json(boundary, "boundary", bpde::FitMethod::Interpolation);
  const bpde::SampledSurface s = bpde::sampled_complex(data.complex, 20);
  const Eigen::Vector3d corners[4] = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  int near_corner = 0, near_mid_edge = 0;
  for (Eigen::Index k = 0; k < s.mesh.V.rows(); ++k) {
    const Eigen::Vector3d x = s.mesh.V.row(k).transpose();
    for (const Eigen::Vector3d& q : corners)
      if ((x - q).norm() < 1e-9) {
        ++near_corner;
        EXPECT_EQ(s.counted(k), 0) << "corner vertex " << k << " at " << x.transpose();
      }
    // the middle of each side (a layout vertex of the fan when it has more than 4 patches, else a
    // point inside a patch edge): the segment is straight there, so it counts
    for (int j = 0; j < 4; ++j)
      if ((x - 0.5 * (corners[j] + corners[(j + 1) % 4])).norm() < 1e-9) {
        ++near_mid_edge;
        EXPECT_EQ(s.counted(k), 1) << "mid-side vertex " << k << " at " << x.transpose();
      }
  }
  EXPECT_GE(near_corner, 4);
  EXPECT_EQ(near_mid_edge, 4);
}
