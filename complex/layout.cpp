#include "bezierpde/complex/layout.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

namespace {

std::string face_name(int f) { return "layout face " + std::to_string(f); }

int corners(PatchKind kind) { return kind == PatchKind::triangular ? 3 : 4; }

void validate_faces(const Layout& layout) {
  const int nv = static_cast<int>(layout.vertices.rows());
  for (int f = 0; f < static_cast<int>(layout.faces.size()); ++f) {
    const std::vector<int>& face = layout.faces[f];
    if (static_cast<int>(face.size()) != corners(layout.kind))
      throw ParameterError(face_name(f) + " has " + std::to_string(face.size()) + " vertices, expected " +
                           std::to_string(corners(layout.kind)));
    for (int v : face)
      if (v < 0 || v >= nv)
        throw ParameterError(face_name(f) + ": vertex " + std::to_string(v) + " outside 0.." + std::to_string(nv) + "-1");
    std::vector<int> sorted = face;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw ParameterError(face_name(f) + " repeats a vertex");
  }
}

/// Directed edges (a -> b) of the faces, with their face; ParameterError when one occurs twice.
std::map<std::pair<int, int>, int> directed_edges(const Layout& layout) {
  std::map<std::pair<int, int>, int> d;
  for (int f = 0; f < static_cast<int>(layout.faces.size()); ++f) {
    const std::vector<int>& face = layout.faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const std::pair<int, int> e{face[k], face[(k + 1) % face.size()]};
      if (!d.emplace(e, f).second)
        throw ParameterError(face_name(f) + ": edge " + std::to_string(e.first) + "-" + std::to_string(e.second) +
                             " runs in the same direction in two faces (not an oriented manifold)");
    }
  }
  return d;
}

/// Each vertex's faces are one fan: connected through the edges at the vertex.
void validate_vertex_fans(const Layout& layout, const std::map<std::pair<int, int>, int>& directed) {
  const int nv = static_cast<int>(layout.vertices.rows());
  std::vector<std::vector<int>> faces_at(nv);
  for (int f = 0; f < static_cast<int>(layout.faces.size()); ++f)
    for (int v : layout.faces[f]) faces_at[v].push_back(f);
  for (int v = 0; v < nv; ++v) {
    if (faces_at[v].empty()) throw ParameterError("layout vertex " + std::to_string(v) + " is in no face");
    std::set<int> reached{faces_at[v].front()};
    std::vector<int> stack{faces_at[v].front()};
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      const std::vector<int>& face = layout.faces[f];
      for (std::size_t k = 0; k < face.size(); ++k) {
        const int a = face[k], b = face[(k + 1) % face.size()];
        if (a != v && b != v) continue;
        auto other = directed.find({b, a});
        if (other != directed.end() && reached.insert(other->second).second) stack.push_back(other->second);
      }
    }
    if (reached.size() != faces_at[v].size())
      throw ParameterError("layout vertex " + std::to_string(v) + " joins faces that share no edge there (not a manifold)");
  }
}

}  // namespace

std::vector<LayoutEdge> layout_edges(const Layout& layout) {
  std::vector<LayoutEdge> edges;
  std::map<std::pair<int, int>, int> index;
  for (int f = 0; f < static_cast<int>(layout.faces.size()); ++f) {
    const std::vector<int>& face = layout.faces[f];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int a = std::min(face[k], face[(k + 1) % face.size()]), b = std::max(face[k], face[(k + 1) % face.size()]);
      auto [it, added] = index.emplace(std::pair{a, b}, static_cast<int>(edges.size()));
      if (added) edges.push_back({a, b, {}});
      edges[it->second].faces.push_back(f);
    }
  }
  return edges;
}

void validate_layout(const Layout& layout) {
  if (layout.faces.empty()) throw SizeError("a layout needs at least one face");
  if (layout.faces.size() > static_cast<std::size_t>(kMaxComplexPatches))
    throw SizeError("a layout has at most " + std::to_string(kMaxComplexPatches) + " faces, got " +
                    std::to_string(layout.faces.size()));
  for (int v = 0; v < layout.vertices.rows(); ++v)
    if (!layout.vertices.row(v).allFinite())
      throw NonFiniteError("layout vertex " + std::to_string(v) + " is not finite");
  validate_faces(layout);
  const auto directed = directed_edges(layout);
  validate_vertex_fans(layout, directed);
}

std::vector<std::vector<int>> layout_boundary_loops(const Layout& layout) {
  const auto directed = directed_edges(layout);
  std::map<int, int> next;
  for (const auto& [e, f] : directed)
    if (!directed.count({e.second, e.first})) next[e.first] = e.second;
  std::vector<std::vector<int>> loops;
  std::set<int> seen;
  for (const auto& [start, unused] : next) {
    if (seen.count(start)) continue;
    std::vector<int> loop;
    for (int v = start; !seen.count(v); v = next.at(v)) {
      seen.insert(v);
      loop.push_back(v);
    }
    loops.push_back(loop);
  }
  return loops;
}

PatchComplex complex_topology(const Layout& layout, int n) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError("degree " + std::to_string(n) + " outside 1.." + std::to_string(kMaxDegree));
  validate_layout(layout);
  const std::vector<LayoutEdge> edges = layout_edges(layout);
  std::map<std::pair<int, int>, int> edge_start;  // (a, b), a < b -> first inner row
  int row = static_cast<int>(layout.vertices.rows());
  for (const LayoutEdge& e : edges) {
    edge_start[{e.a, e.b}] = row;
    row += n - 1;
  }
  PatchComplex c;
  for (const std::vector<int>& face : layout.faces) {
    ComplexPatch patch{layout.kind, n, std::vector<int>(patch_point_count(layout.kind, n), -1)};
    const int ne = static_cast<int>(face.size());
    for (int e = 0; e < ne; ++e) {
      const int from = face[e], to = face[(e + 1) % ne];
      const std::vector<int> local = patch_edge_local_rows(layout.kind, n, e);
      const int start = edge_start.at({std::min(from, to), std::max(from, to)});
      patch.points[local[0]] = from;
      patch.points[local[n]] = to;
      for (int s = 1; s < n; ++s) patch.points[local[s]] = from < to ? start + s - 1 : start + n - 1 - s;
    }
    for (int& r : patch.points)
      if (r < 0) r = row++;
    c.patches.push_back(std::move(patch));
  }
  c.points = Eigen::MatrixX3d::Zero(row, 3);
  c.points.topRows(layout.vertices.rows()) = layout.vertices;
  c.fixed = boundary_rows(c);
  return c;
}

}  // namespace bpde
