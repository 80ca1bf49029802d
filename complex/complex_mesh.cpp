#include "bezierpde/complex/complex_mesh.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <tuple>

#include "bezierpde/core/errors.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

namespace {

/// (patch, local edge) -> (complex edge, reversed).
std::map<std::pair<int, int>, std::pair<int, bool>> side_index(const std::vector<ComplexEdge>& edges) {
  std::map<std::pair<int, int>, std::pair<int, bool>> m;
  for (int k = 0; k < static_cast<int>(edges.size()); ++k)
    for (const ComplexEdge::Side& s : edges[k].sides) m[{s.patch, s.edge}] = {k, s.reversed};
  return m;
}

TriangleMesh patch_mesh(const PatchComplex& c, int p, int N) {
  return c.patches[p].kind == PatchKind::triangular ? sample_mesh(triangular_net(c, p), N)
                                                    : sample_mesh(tensor_net(c, p), N);
}

/// The (a, b) sample coordinates of each local vertex of a patch mesh (sample_mesh order).
std::vector<std::pair<int, int>> sample_coordinates(PatchKind kind, int N) {
  std::vector<std::pair<int, int>> ab;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= (kind == PatchKind::triangular ? N - a : N); ++b) ab.emplace_back(a, b);
  return ab;
}

/// The nets of every patch, built once.
struct PatchNets {
  std::vector<TriangularNet> triangular;
  std::vector<TensorNet> tensor;
  explicit PatchNets(const PatchComplex& c) {
    for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
      if (c.patches[p].kind == PatchKind::triangular) triangular.push_back(triangular_net(c, p));
      else tensor.push_back(tensor_net(c, p));
    }
  }
  FundamentalForms geometry(int p, const Eigen::Vector2d& uv) const {
    return triangular.empty() ? tensor[p].geometry(uv(0), uv(1)) : triangular[p].geometry(uv(0), uv(1));
  }
};

}  // namespace

ComplexMesh sample_complex(const PatchComplex& c, int N) {
  if (N < 1 || N > kMaxSamples) throw ParameterError(samples_limit_message("samples", N));
  const long long vertices = static_cast<long long>(c.patches.size()) * (N + 1) * (N + 1);
  if (vertices > kMaxComplexSampleVertices)
    throw ParameterError("samples: " + std::to_string(c.patches.size()) + " patches at " + std::to_string(N) +
                         " samples are " + std::to_string(vertices) + " vertices, more than " +
                         std::to_string(kMaxComplexSampleVertices) + " (fewer samples, or less refinement)");
  validate(c);
  const std::vector<ComplexEdge> edges = complex_edges(c);
  const auto sides = side_index(edges);
  const int n = c.patches.front().degree;
  std::map<std::tuple<int, int, int>, int> welded;  // (0, corner row, 0) or (1, edge, s) -> vertex
  std::vector<Eigen::Vector3d> V;
  std::vector<double> H;
  std::vector<std::pair<int, Eigen::Vector2d>> source;
  std::vector<unsigned char> regular;
  std::vector<Eigen::Vector3i> F;
  std::vector<int> patch_of;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    const PatchKind kind = c.patches[p].kind;
    const TriangleMesh m = patch_mesh(c, p, N);
    const auto ab = sample_coordinates(kind, N);
    std::vector<int> global(m.V.rows());
    for (int r = 0; r < m.V.rows(); ++r) {
      const auto [a, b] = ab[r];
      const auto [edge_of, s_of] = patch_lattice_edge(kind, N, a, b);
      const struct { int e, s; } es{edge_of, s_of};
      int key_vertex = -1;
      if (es.e >= 0) {
        const std::vector<int> local = patch_edge_local_rows(kind, n, es.e);
        std::tuple<int, int, int> key;
        if (es.s == 0 || es.s == N) {
          key = {0, c.patches[p].points[local[es.s == 0 ? 0 : n]], 0};
        } else {
          const auto [edge, reversed] = sides.at({p, es.e});
          key = {1, edge, reversed ? N - es.s : es.s};
        }
        auto [it, added] = welded.emplace(key, static_cast<int>(V.size()));
        if (!added) key_vertex = it->second;
      }
      if (key_vertex >= 0) {
        global[r] = key_vertex;
      } else {
        global[r] = static_cast<int>(V.size());
        V.push_back(m.V.row(r).transpose());
        H.push_back(m.H(r));
        source.emplace_back(p, Eigen::Vector2d(double(a) / N, double(b) / N));
        regular.push_back(m.regular.size() ? m.regular(r) : 1);
      }
    }
    for (int f = 0; f < m.F.rows(); ++f) {
      F.emplace_back(global[m.F(f, 0)], global[m.F(f, 1)], global[m.F(f, 2)]);
      patch_of.push_back(p);
    }
  }
  ComplexMesh out;
  out.mesh.V.resize(V.size(), 3);
  out.mesh.H.resize(V.size());
  out.mesh.regular.resize(V.size());
  out.vertex_patch.resize(V.size());
  out.uv.resize(V.size(), 2);
  for (std::size_t k = 0; k < V.size(); ++k) {
    out.vertex_patch(k) = source[k].first;
    out.uv.row(k) = source[k].second.transpose();
    out.mesh.V.row(k) = V[k].transpose();
    out.mesh.H(k) = H[k];
    out.mesh.regular(k) = regular[k];
  }
  out.mesh.F.resize(F.size(), 3);
  out.patch.resize(F.size());
  for (std::size_t f = 0; f < F.size(); ++f) {
    out.mesh.F.row(f) = F[f].transpose();
    out.patch(f) = patch_of[f];
  }
  return out;
}

double seam_angle_max(const PatchComplex& c, int samples) {
  if (samples < 1) throw ParameterError("seam samples must be >= 1");
  validate(c);
  const PatchNets nets(c);
  double worst = 0;
  for (const ComplexEdge& edge : complex_edges(c)) {
    if (edge.sides.size() != 2) continue;
    for (int k = 0; k < samples; ++k) {
      const double t = (k + 0.5) / samples;  // canonical direction
      Eigen::Vector3d normal[2];
      bool ok = true;
      for (int s = 0; s < 2; ++s) {
        const ComplexEdge::Side& side = edge.sides[s];
        const Eigen::Vector2d uv =
            patch_edge_parameter(c.patches[side.patch].kind, side.edge, side.reversed ? 1 - t : t);
        const FundamentalForms g = nets.geometry(side.patch, uv);
        ok = ok && g.regular;
        normal[s] = g.normal;
      }
      if (!ok) continue;
      const double d = std::clamp(normal[0].dot(normal[1]), -1.0, 1.0);
      const double cross = normal[0].cross(normal[1]).norm();
      worst = std::max(worst, std::atan2(cross, d) * 180.0 / std::numbers::pi);
    }
  }
  return worst;
}

}  // namespace bpde
