// The surface files: surface.ply (ASCII and binary, with the `regular` flag) and surface.vtp,
// read back by independent readers (mesh_readers.h) and checked against the net's own evaluation.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "bezierpde/core/differential_geometry.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/io/surface_fields.h"
#include "bezierpde/io/vtp_io.h"
#include "bezierpde/jobs/run_demo.h"
#include "bezierpde/jobs/run_job.h"
#include "mesh_readers.h"

using namespace bpde;
using namespace bpde::testing;
namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("bpde_surface_files_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d / name;
}

// The demo's solved net: a CMC patch over a circle in three arcs, whose corners have x_u || x_v.
const Net& demo_net() {
  static const Net net = run_job(demo_job()).net;
  return net;
}

TensorNet wavy_tensor() {
  TensorNet t(3, 2);
  for (int i = 0; i <= 3; ++i)
    for (int j = 0; j <= 2; ++j)
      t.set_point(i, j, Eigen::Vector3d(i / 3.0, j / 2.0 + 0.1 * i * j, std::sin(i + 2.0 * j)));
  return t;
}

BSplineNet wavy_bspline() {
  const std::vector<double> U = {0, 0, 0, 0.4, 1, 1, 1}, V = {-1, -1, -1, 2, 2, 2};
  Eigen::MatrixX3d P(4 * 3, 3);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j) P.row(i * 3 + j) << i, j, std::cos(1.0 * i * j) + 0.2 * i;
  return BSplineNet(2, 2, U, V, P);
}

double max_abs(const Eigen::VectorXd& v) { return v.cwiseAbs().maxCoeff(); }

}  // namespace

TEST(SurfaceFields, DemoCornersAreMarkedAndCarryTheirNeighboursMean) {
  const Net& net = demo_net();
  const int N = 50;
  const TriangleMesh mesh = sample_net(net, N);
  const SurfaceFields f = surface_fields(net, mesh);
  ASSERT_EQ(f.regular.size(), mesh.V.rows());
  // the three corners (a, b) = (0, 0), (0, N), (N, 0) are irregular, and nothing else but a few
  // samples next to them (the corners at (N, 0) and (0, N) are the sharper ones)
  const auto vid = [N](int a, int b) { return a * (N + 1) - a * (a - 1) / 2 + b; };
  for (int k : {vid(0, 0), vid(0, N), vid(N, 0)}) EXPECT_EQ(f.regular(k), 0) << k;
  const Eigen::MatrixX2d uv = sample_parameters(net, N);
  int irregular = 0;
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
    if (f.regular(k)) continue;
    ++irregular;
    const double u = uv(k, 0), v = uv(k, 1), w = 1 - u - v;
    EXPECT_LE(std::min({u + v, u + w, v + w}), 2.0 / N + 1e-12) << "irregular away from a corner: " << u << " " << v;
  }
  EXPECT_GE(irregular, 3);
  EXPECT_LE(irregular, 9);
  // the raw sampled H blows up there (the value the PLY used to carry)...
  EXPECT_GT(max_abs(mesh.H), 1000.0);
  // ...the written H is the mean of the regular neighbours, within the regular values
  double lo = 1e300, hi = -1e300;
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
    if (f.regular(k)) lo = std::min(lo, f.H(k)), hi = std::max(hi, f.H(k));
  }
  EXPECT_LT(hi - lo, 100.0);
  EXPECT_TRUE(f.H.allFinite() && f.K.allFinite() && f.normal.allFinite());
  // corner (0, 0) of the grid: neighbours (1, 0) and (0, 1), each in one triangle
  const int c = vid(0, 0), n1 = vid(1, 0), n2 = vid(0, 1);
  EXPECT_NEAR(f.H(c), 0.5 * (f.H(n1) + f.H(n2)), 1e-12 * std::abs(f.H(c)));
  EXPECT_NEAR(f.normal.row(c).norm(), 1.0, 1e-12);
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
    if (f.regular(k)) {
      EXPECT_EQ(f.H(k), mesh.H(k)) << k;
    }
  }
}

TEST(SurfaceFields, WideDegenerateCornersAreFilledRingByRing) {
  // On a 400-grid the demo's degenerate corners span several rings of irregular samples, so some
  // irregular vertices have no regular neighbour (they were written as H = 0 before). Each must
  // now carry a value inside the range of the regular ones, and the first ring still the mean of
  // its regular neighbours.
  const Net& net = demo_net();
  const int N = 400;
  const TriangleMesh mesh = sample_net(net, N);
  const SurfaceFields f = surface_fields(net, mesh);
  std::vector<int> ring(mesh.V.rows(), -1);  // 0 regular, 1 next to a regular vertex, 2 beyond
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k)
    if (f.regular(k)) ring[k] = 0;
  for (Eigen::Index t = 0; t < mesh.F.rows(); ++t)
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        if (!f.regular(mesh.F(t, a)) && f.regular(mesh.F(t, b))) ring[mesh.F(t, a)] = 1;
  double lo = 1e300, hi = -1e300;
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k)
    if (f.regular(k)) lo = std::min(lo, f.H(k)), hi = std::max(hi, f.H(k));
  int beyond = 0;
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
    if (f.regular(k)) continue;
    if (ring[k] == -1) ++beyond;
    EXPECT_GE(f.H(k), lo) << k;
    EXPECT_LE(f.H(k), hi) << k;
    EXPECT_NE(f.H(k), 0.0) << k;
    EXPECT_NEAR(f.normal.row(k).norm(), 1.0, 1e-12) << k;
    // the cap's normals point up and lean outwards at the boundary: not the (0, 0, 1) filler
    EXPECT_GT(f.normal(k, 2), 0.0) << k;
    EXPECT_LT(f.normal(k, 2), 1.0 - 1e-9) << k;
  }
  EXPECT_GE(beyond, 3) << "the test needs irregular vertices without a regular neighbour";
  // the first ring: exactly the mean over the regular neighbours (each counted once per triangle)
  const auto vid = [N](int a, int b) { return a * (N + 1) - a * (a - 1) / 2 + b; };
  int checked = 0;
  for (int a = 0; a <= N && checked < 50; ++a)
    for (int b = 0; a + b <= N && checked < 50; ++b) {
      const int k = vid(a, b);
      if (ring[k] != 1) continue;
      double sum = 0;
      int cnt = 0;
      for (Eigen::Index t = 0; t < mesh.F.rows(); ++t)
        for (int x = 0; x < 3; ++x)
          if (mesh.F(t, x) == k)
            for (int y = 0; y < 3; ++y)
              if (f.regular(mesh.F(t, y))) sum += f.H(mesh.F(t, y)), ++cnt;
      ASSERT_GT(cnt, 0);
      EXPECT_NEAR(f.H(k), sum / cnt, 1e-12 * std::abs(sum / cnt)) << k;
      ++checked;
    }
  EXPECT_GT(checked, 0);
}

TEST(SurfaceFields, ParametersAndGeometryMatchTheNet) {
  for (const Net& net : {Net(wavy_tensor()), Net(wavy_bspline()), demo_net()}) {
    const TriangleMesh mesh = sample_net(net, 7);
    EXPECT_EQ(sampled_resolution(net, mesh), 7);
    const SurfaceFields f = surface_fields(net, mesh);
    std::visit(
        [&](const auto& s) {
          for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
            const double u = f.uv(k, 0), v = f.uv(k, 1);
            EXPECT_LT((s.evaluate(u, v) - mesh.V.row(k).transpose()).norm(), 1e-12) << net_kind(net) << " " << k;
            if (!f.regular(k)) continue;
            const FundamentalForms g = fundamental_forms(surface_jet(s, u, v));
            EXPECT_LT((g.normal - f.normal.row(k).transpose()).norm(), 1e-12);
            EXPECT_NEAR(f.K(k), g.K, 1e-9 * (1 + std::abs(g.K)));
            EXPECT_NEAR(f.H(k), g.H, 1e-9 * (1 + std::abs(g.H)));
          }
        },
        net);
  }
  TriangleMesh bad = sample_net(Net(wavy_tensor()), 3);
  bad.V.conservativeResize(bad.V.rows() - 1, 3);
  EXPECT_THROW(sampled_resolution(Net(wavy_tensor()), bad), InternalError);
}

TEST(SurfaceFiles, PlyAsciiAndBinaryReadBackToTheWrittenValues) {
  const Net& net = demo_net();
  const TriangleMesh mesh = sample_net(net, 12);
  const SurfaceFields f = surface_fields(net, mesh);
  for (MeshFormat format : {MeshFormat::Ascii, MeshFormat::Binary}) {
    const bool binary = format == MeshFormat::Binary;
    const fs::path p = scratch(binary ? "b.ply" : "a.ply");
    write_ply(p.string(), mesh, f, format);
    const PlyData d = read_ply(p.string());
    EXPECT_EQ(d.format, binary ? "binary_little_endian" : "ascii");
    ASSERT_EQ(d.names, (std::vector<std::string>{"x", "y", "z", "mean_curvature", "regular"}));
    EXPECT_EQ(d.types[0], binary ? "float" : "double");
    ASSERT_EQ(d.vertex.at("x").size(), static_cast<size_t>(mesh.V.rows()));
    ASSERT_EQ(d.faces.size(), static_cast<size_t>(mesh.F.rows()));
    for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
      const size_t i = static_cast<size_t>(k);
      const double tol = binary ? 1e-7 : 0.0;  // float32 keeps 24 bits; 17 digits round-trip exactly
      EXPECT_NEAR(d.vertex.at("x")[i], mesh.V(k, 0), tol * (1 + std::abs(mesh.V(k, 0))));
      EXPECT_NEAR(d.vertex.at("y")[i], mesh.V(k, 1), tol * (1 + std::abs(mesh.V(k, 1))));
      EXPECT_NEAR(d.vertex.at("z")[i], mesh.V(k, 2), tol * (1 + std::abs(mesh.V(k, 2))));
      EXPECT_NEAR(d.vertex.at("mean_curvature")[i], f.H(k), tol * (1 + std::abs(f.H(k))));
      EXPECT_EQ(d.vertex.at("regular")[i], f.regular(k));
    }
    for (Eigen::Index t = 0; t < mesh.F.rows(); ++t)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(d.faces[static_cast<size_t>(t)][c], mesh.F(t, c));
    // no blown-up corner value is written
    double written_max = 0;
    for (double h : d.vertex.at("mean_curvature")) written_max = std::max(written_max, std::abs(h));
    EXPECT_LT(written_max, 100.0);
  }
  // binary is the compact one: 17 bytes a vertex and 13 a triangle after the header
  const TriangleMesh big = sample_net(net, 60);
  const SurfaceFields fb = surface_fields(net, big);
  write_ply(scratch("big_a.ply").string(), big, fb, MeshFormat::Ascii);
  write_ply(scratch("big_b.ply").string(), big, fb, MeshFormat::Binary);
  const auto header = read_all(scratch("big_b.ply").string()).find("end_header\n") + 11;
  EXPECT_EQ(fs::file_size(scratch("big_b.ply")), header + 17 * big.V.rows() + 13 * big.F.rows());
  EXPECT_LT(fs::file_size(scratch("big_b.ply")), fs::file_size(scratch("big_a.ply")) / 2);
}

TEST(SurfaceFiles, VtpReadsBackWithTheNetsFields) {
  for (const Net& net : {demo_net(), Net(wavy_bspline())}) {
    const TriangleMesh mesh = sample_net(net, 9);
    const SurfaceFields f = surface_fields(net, mesh);
    for (MeshFormat format : {MeshFormat::Ascii, MeshFormat::Binary}) {
      const bool binary = format == MeshFormat::Binary;
      const fs::path p = scratch(binary ? "b.vtp" : "a.vtp");
      write_vtp(p.string(), mesh, f, format);
      const VtpData d = read_vtp(p.string());
      EXPECT_EQ(d.piece.at("NumberOfPoints"), std::to_string(mesh.V.rows()));
      EXPECT_EQ(d.piece.at("NumberOfPolys"), std::to_string(mesh.F.rows()));
      EXPECT_EQ(d.point_data.at("Scalars"), "mean_curvature");
      EXPECT_EQ(d.point_data.at("Normals"), "Normals");
      EXPECT_EQ(d.point_data.at("TCoords"), "uv");
      const size_t nv = static_cast<size_t>(mesh.V.rows());
      const auto& P = d.arrays.at("Points").values;
      const auto& Nr = d.arrays.at("Normals").values;
      const auto& H = d.arrays.at("mean_curvature").values;
      const auto& K = d.arrays.at("gaussian_curvature").values;
      const auto& UV = d.arrays.at("uv").values;
      const auto& R = d.arrays.at("regular").values;
      ASSERT_EQ(P.size(), 3 * nv);
      ASSERT_EQ(Nr.size(), 3 * nv);
      ASSERT_EQ(H.size(), nv);
      ASSERT_EQ(K.size(), nv);
      ASSERT_EQ(UV.size(), 2 * nv);
      ASSERT_EQ(R.size(), nv);
      ASSERT_EQ(d.arrays.at("connectivity").values.size(), 3 * static_cast<size_t>(mesh.F.rows()));
      ASSERT_EQ(d.arrays.at("offsets").values.back(), 3.0 * static_cast<double>(mesh.F.rows()));
      const double tol = binary ? 2e-7 : 1e-12;
      std::visit(
          [&](const auto& s) {
            for (size_t k = 0; k < nv; ++k) {
              // the file's own (u, v) evaluated by the net gives the file's point
              const Eigen::Vector3d x = s.evaluate(UV[2 * k], UV[2 * k + 1]);
              for (int c = 0; c < 3; ++c) EXPECT_NEAR(P[3 * k + c], x(c), tol * (1 + x.norm())) << k;
              EXPECT_EQ(R[k], f.regular(static_cast<Eigen::Index>(k)));
              if (!R[k]) continue;
              const FundamentalForms g = fundamental_forms(surface_jet(s, UV[2 * k], UV[2 * k + 1]));
              for (int c = 0; c < 3; ++c) EXPECT_NEAR(Nr[3 * k + c], g.normal(c), tol * 10);
              EXPECT_NEAR(H[k], g.H, (tol + 1e-9) * (1 + std::abs(g.H)));
              EXPECT_NEAR(K[k], g.K, (tol + 1e-9) * (1 + std::abs(g.K)));
            }
          },
          net);
      for (size_t t = 0; t < static_cast<size_t>(mesh.F.rows()); ++t)
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(d.arrays.at("connectivity").values[3 * t + c], mesh.F(static_cast<Eigen::Index>(t), c));
    }
  }
}

TEST(SurfaceFiles, WrittenBesideObjAndPlyInEitherFormat) {
  const Net net(wavy_tensor());
  for (MeshFormat format : {MeshFormat::Ascii, MeshFormat::Binary}) {
    const fs::path dir = scratch(format == MeshFormat::Binary ? "dir_b" : "dir_a");
    fs::create_directories(dir);
    write_surface_files(dir.string(), net, sample_net(net, 5), format);
    for (const char* name : {"surface.obj", "surface.ply", "surface.vtp", "net.obj"})
      EXPECT_TRUE(fs::exists(dir / name)) << name;
    EXPECT_EQ(read_vtp((dir / "surface.vtp").string()).arrays.at("Points").type,
              format == MeshFormat::Binary ? "Float32" : "Float64");
  }
  EXPECT_EQ(mesh_format_from_string("binary", "x"), MeshFormat::Binary);
  EXPECT_THROW(mesh_format_from_string("BINARY", "x"), ParseError);
}

TEST(SurfaceFiles, SharedNumberTextWritesTheSameBytes) {
  // the vertex coordinates and H formatted once (SharedNumberText) give the files each writer
  // formats on its own, byte for byte, in both formats; and a text of another mesh is refused
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  for (const Net& net : {demo_net(), Net(wavy_tensor()), Net(wavy_bspline())}) {
    const TriangleMesh mesh = sample_net(net, 9);
    const SurfaceFields f = surface_fields(net, mesh);
    const SharedNumberText text(mesh, f);
    write_obj(scratch("own.obj").string(), mesh);
    write_obj(scratch("shared.obj").string(), mesh, &text);
    EXPECT_EQ(slurp(scratch("own.obj")), slurp(scratch("shared.obj")));
    EXPECT_NE(slurp(scratch("own.obj")).find("v "), std::string::npos);
    for (MeshFormat format : {MeshFormat::Ascii, MeshFormat::Binary}) {
      write_ply(scratch("own.ply").string(), mesh, f, format);
      write_ply(scratch("shared.ply").string(), mesh, f, format, &text);
      EXPECT_EQ(slurp(scratch("own.ply")), slurp(scratch("shared.ply")));
      write_vtp(scratch("own.vtp").string(), mesh, f, format);
      write_vtp(scratch("shared.vtp").string(), mesh, f, format, &text);
      EXPECT_EQ(slurp(scratch("own.vtp")), slurp(scratch("shared.vtp")));
    }
  }
  const TriangleMesh a = sample_net(Net(wavy_tensor()), 9), b = sample_net(Net(wavy_tensor()), 5);
  const SharedNumberText text_b(b, surface_fields(Net(wavy_tensor()), b));
  EXPECT_THROW(write_obj(scratch("bad.obj").string(), a, &text_b), InternalError);
}
