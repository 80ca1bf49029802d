#include "bezierpde/complex/planar_domain.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "bezierpde/core/errors.h"

namespace bpde {

namespace {

void require_triangular(const Layout& layout) {
  if (layout.kind != PatchKind::triangular)
    throw ParameterError(
        "C1 continuity takes triangular complexes: a tensor layout's quads are not parallelograms "
        "of a planar domain (the O-grid's ring), so its seams have no linear C1 condition");
}

double signed_area(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
}

/// Smallest signed face area of positions P.
double min_area(const Layout& layout, const Eigen::MatrixX2d& P) {
  double m = INFINITY;
  for (const std::vector<int>& f : layout.faces)
    m = std::min(m, signed_area(P.row(f[0]).transpose(), P.row(f[1]).transpose(), P.row(f[2]).transpose()));
  return m;
}

/// Tutte: the inner vertices (not on a boundary loop) at the mean of their neighbours.
void tutte_inner(const Layout& layout, const std::vector<bool>& on_boundary, Eigen::MatrixX2d& P) {
  const int nv = static_cast<int>(layout.vertices.rows());
  std::vector<int> index(nv, -1);
  int ni = 0;
  for (int v = 0; v < nv; ++v)
    if (!on_boundary[v]) index[v] = ni++;
  if (ni == 0) return;
  std::vector<Eigen::Triplet<double>> t;
  Eigen::MatrixX2d rhs = Eigen::MatrixX2d::Zero(ni, 2);
  for (const LayoutEdge& e : layout_edges(layout))
    for (const auto& [from, to] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}}) {
      if (index[from] < 0) continue;
      t.emplace_back(index[from], index[from], 1.0);
      if (index[to] >= 0)
        t.emplace_back(index[from], index[to], -1.0);
      else
        rhs.row(index[from]) += P.row(to);
    }
  Eigen::SparseMatrix<double> L(ni, ni);
  L.setFromTriplets(t.begin(), t.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(L);
  if (solver.info() != Eigen::Success) throw InternalError("Tutte embedding: the graph Laplacian did not factor");
  const Eigen::MatrixX2d X = solver.solve(rhs);
  for (int v = 0; v < nv; ++v)
    if (index[v] >= 0) P.row(v) = X.row(index[v]);
}

void place_on_circle(const std::vector<int>& loop, double radius, double start, double direction, Eigen::MatrixX2d& P) {
  const int m = static_cast<int>(loop.size());
  for (int k = 0; k < m; ++k) {
    const double a = start + direction * 2 * std::numbers::pi * k / m;
    P.row(loop[k]) << radius * std::cos(a), radius * std::sin(a);
  }
}

}  // namespace

Eigen::MatrixX2d layout_domain_positions(const Layout& layout) {
  require_triangular(layout);
  validate_layout(layout);
  const std::vector<std::vector<int>> loops = layout_boundary_loops(layout);
  if (loops.empty() || loops.size() > 2)
    throw ParameterError("C1 continuity needs a layout whose boundary is one loop (a disc) or two (an annulus), got " +
                         std::to_string(loops.size()));
  const int nv = static_cast<int>(layout.vertices.rows());
  std::vector<bool> on_boundary(nv, false);
  for (const auto& loop : loops)
    for (int v : loop) on_boundary[v] = true;
  Eigen::MatrixX2d P = Eigen::MatrixX2d::Zero(nv, 2);
  place_on_circle(loops[0], 1.0, 0.0, 1.0, P);
  if (loops.size() == 1) {
    tutte_inner(layout, on_boundary, P);
  } else {
    const int m = static_cast<int>(loops[1].size());
    const int tries = 8 * m;
    double best = -INFINITY, best_start = 0;
    for (int k = 0; k < tries; ++k) {
      const double start = 2 * std::numbers::pi * k / tries;
      place_on_circle(loops[1], 0.5, start, -1.0, P);
      tutte_inner(layout, on_boundary, P);
      const double a = min_area(layout, P);
      if (a > best) best = a, best_start = start;
    }
    place_on_circle(loops[1], 0.5, best_start, -1.0, P);
    tutte_inner(layout, on_boundary, P);
  }
  (void)layout_domain(layout, P);  // checks the triangles
  return P;
}

std::vector<DomainTriangle> layout_domain(const Layout& layout, const Eigen::MatrixX2d& positions) {
  require_triangular(layout);
  if (positions.rows() != layout.vertices.rows())
    throw ParameterError("domain positions: " + std::to_string(positions.rows()) + " rows for " +
                         std::to_string(layout.vertices.rows()) + " layout vertices");
  if (!positions.allFinite()) throw ParameterError("domain positions: a non-finite coordinate");
  const double diameter = (positions.colwise().maxCoeff() - positions.colwise().minCoeff()).norm();
  std::vector<DomainTriangle> out;
  out.reserve(layout.faces.size());
  for (int f = 0; f < static_cast<int>(layout.faces.size()); ++f) {
    DomainTriangle T;
    for (int k = 0; k < 3; ++k) T.row(k) = positions.row(layout.faces[f][k]);
    if (!(signed_area(T.row(0).transpose(), T.row(1).transpose(), T.row(2).transpose()) > 1e-12 * diameter * diameter))
      throw ParameterError("the planar domain of layout face " + std::to_string(f) +
                           " is degenerate or clockwise (the layout does not embed in the plane as a C1 domain)");
    out.push_back(T);
  }
  return out;
}

std::vector<DomainTriangle> refine_domain_h(const std::vector<DomainTriangle>& domain) {
  std::vector<DomainTriangle> out;
  out.reserve(4 * domain.size());
  for (const DomainTriangle& T : domain) {
    const Eigen::RowVector2d A = T.row(0), B = T.row(1), C = T.row(2);
    const Eigen::RowVector2d AB = (A + B) / 2, BC = (B + C) / 2, CA = (C + A) / 2;
    for (const auto& part :
         {std::array{A, AB, CA}, std::array{AB, B, BC}, std::array{CA, BC, C}, std::array{BC, CA, AB}}) {
      DomainTriangle S;
      for (int k = 0; k < 3; ++k) S.row(k) = part[k];
      out.push_back(S);
    }
  }
  return out;
}

}  // namespace bpde
