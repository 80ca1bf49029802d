#include "bezierpde/complex/patch_complex.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

namespace {

std::string patch_name(int p) { return "patch " + std::to_string(p); }

void check_patch_index(const PatchComplex& c, int p) {
  if (p < 0 || p >= static_cast<int>(c.patches.size()))
    throw SizeError("patch index " + std::to_string(p) + " outside 0.." + std::to_string(c.patches.size()) + "-1");
}

Eigen::MatrixX3d gather(const PatchComplex& c, int p) {
  const ComplexPatch& patch = c.patches[p];
  Eigen::MatrixX3d P(patch.points.size(), 3);
  for (int r = 0; r < static_cast<int>(patch.points.size()); ++r) P.row(r) = c.points.row(patch.points[r]);
  return P;
}

void validate_patch(const PatchComplex& c, int p) {
  const ComplexPatch& patch = c.patches[p];
  const ComplexPatch& first = c.patches.front();
  if (patch.degree < 1 || patch.degree > kMaxDegree)
    throw DegreeError(patch_name(p) + ": degree " + std::to_string(patch.degree) + " outside 1.." +
                      std::to_string(kMaxDegree));
  if (patch.kind != first.kind) throw DegreeError(patch_name(p) + ": patches of different kinds");
  if (patch.degree != first.degree)
    throw DegreeError(patch_name(p) + ": degree " + std::to_string(patch.degree) + " differs from patch 0's " +
                      std::to_string(first.degree) + " (shared edges of different degrees)");
  const int count = patch_point_count(patch.kind, patch.degree);
  if (static_cast<int>(patch.points.size()) != count)
    throw SizeError(patch_name(p) + ": " + std::to_string(patch.points.size()) + " point rows, expected " +
                    std::to_string(count));
  std::vector<int> rows = patch.points;
  for (int r : rows)
    if (r < 0 || r >= c.points.rows())
      throw SizeError(patch_name(p) + ": row " + std::to_string(r) + " outside 0.." +
                      std::to_string(c.points.rows()) + "-1");
  std::sort(rows.begin(), rows.end());
  if (std::adjacent_find(rows.begin(), rows.end()) != rows.end())
    throw ParameterError(patch_name(p) + ": uses a row twice");
}

}  // namespace

int patch_point_count(PatchKind kind, int n) {
  return kind == PatchKind::triangular ? (n + 1) * (n + 2) / 2 : (n + 1) * (n + 1);
}

std::vector<int> patch_edge_local_rows(PatchKind kind, int n, int e) {
  std::vector<int> rows(n + 1);
  for (int s = 0; s <= n; ++s) {
    if (kind == PatchKind::triangular) {
      rows[s] = e == 0 ? TriangularNet::index(n, s, 0) : e == 1 ? TriangularNet::index(n, n - s, s)
                                                                : TriangularNet::index(n, 0, n - s);
    } else {
      const int i = e == 0 ? s : e == 1 ? n : e == 2 ? n - s : 0;
      const int j = e == 0 ? 0 : e == 1 ? s : e == 2 ? n : n - s;
      rows[s] = i * (n + 1) + j;
    }
  }
  return rows;
}

Eigen::Vector2d patch_edge_parameter(PatchKind kind, int e, double t) {
  if (kind == PatchKind::triangular)
    return e == 0 ? Eigen::Vector2d(t, 0) : e == 1 ? Eigen::Vector2d(1 - t, t) : Eigen::Vector2d(0, 1 - t);
  return e == 0 ? Eigen::Vector2d(t, 0)
       : e == 1 ? Eigen::Vector2d(1, t)
       : e == 2 ? Eigen::Vector2d(1 - t, 1)
                : Eigen::Vector2d(0, 1 - t);
}

std::pair<int, int> patch_lattice_edge(PatchKind kind, int D, int a, int b) {
  if (kind == PatchKind::triangular) {
    if (b == 0) return {0, a};
    if (a + b == D) return {1, b};
    if (a == 0) return {2, D - b};
    return {-1, 0};
  }
  if (b == 0) return {0, a};
  if (a == D) return {1, b};
  if (b == D) return {2, D - a};
  if (a == 0) return {3, D - b};
  return {-1, 0};
}

void validate(const PatchComplex& c) {
  if (c.patches.empty()) throw SizeError("a complex needs at least one patch");
  if (c.patches.size() > static_cast<std::size_t>(kMaxComplexPatches))
    throw SizeError("a complex has at most " + std::to_string(kMaxComplexPatches) + " patches, got " +
                    std::to_string(c.patches.size()));
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) validate_patch(c, p);
  for (int r = 0; r < c.points.rows(); ++r)
    if (!c.points.row(r).allFinite()) throw NonFiniteError("points[" + std::to_string(r) + "] is not finite");
  for (std::size_t k = 0; k < c.fixed.size(); ++k) {
    if (c.fixed[k] < 0 || c.fixed[k] >= c.points.rows())
      throw ParameterError("fixed row " + std::to_string(c.fixed[k]) + " outside the points");
    if (k > 0 && c.fixed[k] <= c.fixed[k - 1]) throw ParameterError("fixed rows must be sorted and unique");
  }
  complex_edges(c);  // throws on non-manifold or inconsistently oriented seams
}

TriangularNet triangular_net(const PatchComplex& c, int p) {
  check_patch_index(c, p);
  if (c.patches[p].kind != PatchKind::triangular) throw ParameterError(patch_name(p) + " is not triangular");
  return TriangularNet(c.patches[p].degree, gather(c, p));
}

TensorNet tensor_net(const PatchComplex& c, int p) {
  check_patch_index(c, p);
  if (c.patches[p].kind != PatchKind::tensor) throw ParameterError(patch_name(p) + " is not a tensor patch");
  return TensorNet(c.patches[p].degree, c.patches[p].degree, gather(c, p));
}

void set_patch_points(PatchComplex& c, int p, const Eigen::MatrixX3d& local) {
  check_patch_index(c, p);
  const ComplexPatch& patch = c.patches[p];
  if (local.rows() != static_cast<int>(patch.points.size()))
    throw SizeError(patch_name(p) + ": " + std::to_string(local.rows()) + " rows, expected " +
                    std::to_string(patch.points.size()));
  for (int r = 0; r < local.rows(); ++r) c.points.row(patch.points[r]) = local.row(r);
}

std::vector<ComplexEdge> complex_edges(const PatchComplex& c) {
  std::vector<ComplexEdge> edges;
  std::map<std::vector<int>, int> index;
  for (int p = 0; p < static_cast<int>(c.patches.size()); ++p) {
    const ComplexPatch& patch = c.patches[p];
    for (int e = 0; e < patch_edge_count(patch.kind); ++e) {
      std::vector<int> rows;
      for (int r : patch_edge_local_rows(patch.kind, patch.degree, e)) rows.push_back(patch.points[r]);
      std::vector<int> rev(rows.rbegin(), rows.rend());
      const bool reversed = rev < rows;
      const std::vector<int>& key = reversed ? rev : rows;
      auto [it, added] = index.emplace(key, static_cast<int>(edges.size()));
      if (added) edges.push_back({key, {}});
      ComplexEdge& edge = edges[it->second];
      if (edge.sides.size() == 2)
        throw ParameterError(patch_name(p) + " edge " + std::to_string(e) +
                             ": an edge shared by more than two patches (not a manifold)");
      if (edge.sides.size() == 1 && edge.sides[0].reversed == reversed)
        throw ParameterError(patch_name(p) + " edge " + std::to_string(e) + " runs along " +
                             patch_name(edge.sides[0].patch) + "'s edge in the same direction (patches oriented apart)");
      edge.sides.push_back({p, e, reversed});
    }
  }
  return edges;
}

std::vector<int> boundary_rows(const PatchComplex& c) {
  std::vector<int> rows;
  for (const ComplexEdge& e : complex_edges(c))
    if (e.boundary()) rows.insert(rows.end(), e.rows.begin(), e.rows.end());
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

}  // namespace bpde
