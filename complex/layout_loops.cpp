#include "bezierpde/complex/layout_loops.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

namespace {

std::string curve_name(int l, int k) { return "loop " + std::to_string(l) + " curve " + std::to_string(k); }

std::string number(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

/// The allowed gap between curve ends: tolerance times max(1, the diagonal of the ends' box).
double gap_allowed(const std::vector<Loop>& loops, double tolerance) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (const Loop& loop : loops)
    for (const BoundaryCurve& c : loop)
      for (const Eigen::Vector3d& p : {c.start(), c.end()}) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return tolerance * std::max(1.0, (hi - lo).norm());
}

/// An estimate of the curve's length (polyline of 64 chords).
double curve_length(const BoundaryCurve& c) {
  double L = 0;
  for (int k = 0; k < 64; ++k) L += (c.evaluate((k + 1) / 64.0) - c.evaluate(k / 64.0)).norm();
  return L;
}

/// Loop l cut into at least m pieces (every curve at least one; more pieces to the curve whose
/// pieces are longest), in loop order.
std::vector<CurvePiece> cut_loop(const Loop& loop, int l, int m) {
  const int N = static_cast<int>(loop.size());
  std::vector<int> count(N, 1);
  std::vector<double> length(N);
  for (int k = 0; k < N; ++k) length[k] = curve_length(loop[k]);
  for (int total = N; total < m; ++total) {
    int best = 0;
    for (int k = 1; k < N; ++k)
      if (length[k] / count[k] > length[best] / count[best] * (1 + 1e-9)) best = k;
    ++count[best];
  }
  std::vector<CurvePiece> pieces;
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < count[k]; ++j)
      pieces.push_back({l, k, double(j) / count[k], j + 1 == count[k] ? 1.0 : double(j + 1) / count[k]});
  return pieces;
}

/// Rows of the complex edge from layout vertex a to b (as the face runs along it), s = 0..n.
std::vector<int> directed_edge_rows(const PatchComplex& c, const Layout& L, int a, int b) {
  for (int f = 0; f < static_cast<int>(L.faces.size()); ++f) {
    const std::vector<int>& face = L.faces[f];
    for (std::size_t e = 0; e < face.size(); ++e)
      if (face[e] == a && face[(e + 1) % face.size()] == b) {
        std::vector<int> rows;
        for (int r : patch_edge_local_rows(L.kind, c.patches[f].degree, static_cast<int>(e)))
          rows.push_back(c.patches[f].points[r]);
        return rows;
      }
  }
  throw LayoutMismatchError("layout edge " + std::to_string(a) + "-" + std::to_string(b) +
                            " is no boundary edge run in this direction by a face");
}

/// The complex on layout L with the boundary pieces fitted and the rest Coons-filled.
LoopComplex fit_layout(const Layout& L, int n, const std::vector<Loop>& loops,
                       const std::vector<LayoutBoundaryEdge>& boundary, const LoopOptions& options) {
  LoopComplex out{L, complex_topology(L, n), boundary, {}};
  std::vector<Eigen::Vector3d> sum(L.vertices.rows(), Eigen::Vector3d::Zero());
  std::vector<int> hits(L.vertices.rows(), 0);
  for (int k = 0; k < static_cast<int>(boundary.size()); ++k) {
    const LayoutBoundaryEdge& edge = boundary[k];
    const BoundaryCurve piece = loops[edge.piece.loop][edge.piece.curve].piece(edge.piece.t0, edge.piece.t1);
    const CurveFit fit = fit_edge(piece, n, options.method);
    const std::vector<int> rows = directed_edge_rows(out.complex, L, edge.a, edge.b);
    for (int s = 1; s < n; ++s) out.complex.points.row(rows[s]) = fit.points.row(s);
    sum[edge.a] += fit.points.row(0).transpose(), ++hits[edge.a];
    sum[edge.b] += fit.points.row(n).transpose(), ++hits[edge.b];
    EdgeFit report;
    report.edge = k;
    report.curve = piece.kind();
    report.method = fit.method;
    report.max_error = edge_error(piece, fit);
    if (!fit.parameters.empty()) report.parameters = fit.parameters, report.corrections = fit.corrections;
    out.fits.push_back(report);
  }
  for (int v = 0; v < L.vertices.rows(); ++v)
    if (hits[v] > 0) {
      out.complex.points.row(v) = (sum[v] / hits[v]).transpose();
      out.layout.vertices.row(v) = out.complex.points.row(v);
    }
  coons_fill(out.complex);
  return out;
}

/// The vertex ids of a cut loop's pieces (piece i from vertex first + i to first + i + 1, cyclic).
std::vector<LayoutBoundaryEdge> ring_edges(const std::vector<CurvePiece>& pieces, int first) {
  const int M = static_cast<int>(pieces.size());
  std::vector<LayoutBoundaryEdge> edges;
  for (int i = 0; i < M; ++i) edges.push_back({first + i, first + (i + 1) % M, pieces[i]});
  return edges;
}

Eigen::Vector3d piece_start(const std::vector<Loop>& loops, const CurvePiece& p) {
  return loops[p.loop][p.curve].evaluate(p.t0);
}

LoopComplex disc(PatchKind kind, int n, const std::vector<Loop>& loops, const LoopOptions& options) {
  const int N = static_cast<int>(loops[0].size());
  int M = kind == PatchKind::triangular ? (N >= 3 ? N : 6) : std::max(N, 4);
  if (kind == PatchKind::tensor && M % 2) ++M;
  const std::vector<CurvePiece> pieces = cut_loop(loops[0], 0, M);
  Layout L;
  L.kind = kind;
  const bool one_inner_quad = kind == PatchKind::tensor && M == 4;
  const int inner = kind == PatchKind::triangular ? 1 : one_inner_quad ? M : M + 1;
  L.vertices.resize(M + inner, 3);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (int i = 0; i < M; ++i) {
    L.vertices.row(i) = piece_start(loops, pieces[i]).transpose();
    for (int k = 0; k <= 16; ++k) {
      const CurvePiece& p = pieces[i];
      centre += loops[0][p.curve].evaluate(p.t0 + (p.t1 - p.t0) * k / 16.0) / (17.0 * M);
    }
  }
  if (kind == PatchKind::triangular) {
    L.vertices.row(M) = centre.transpose();
    for (int i = 0; i < M; ++i) L.faces.push_back({i, (i + 1) % M, M});
  } else {
    for (int i = 0; i < M; ++i) {
      L.vertices.row(M + i) = (0.5 * (centre + L.vertices.row(i).transpose())).transpose();
      L.faces.push_back({i, (i + 1) % M, M + (i + 1) % M, M + i});
    }
    if (one_inner_quad) {
      L.faces.push_back({M, M + 1, M + 2, M + 3});
    } else {
      L.vertices.row(2 * M) = centre.transpose();
      for (int j = 0; j < M / 2; ++j) L.faces.push_back({2 * M, M + 2 * j, M + 2 * j + 1, M + (2 * j + 2) % M});
    }
  }
  // the inner vertices of a disc over a curved loop are only a start: the fit sets the boundary
  return fit_layout(L, n, loops, ring_edges(pieces, 0), options);
}

LoopComplex annulus(PatchKind kind, int n, const std::vector<Loop>& loops, const LoopOptions& options) {
  const int M = std::max({static_cast<int>(loops[0].size()), static_cast<int>(loops[1].size()), 4});
  const std::vector<CurvePiece> outer = cut_loop(loops[0], 0, M), inner = cut_loop(loops[1], 1, M);
  Layout L;
  L.kind = kind;
  L.vertices.resize(2 * M, 3);
  for (int i = 0; i < M; ++i) {
    L.vertices.row(i) = piece_start(loops, outer[i]).transpose();
    L.vertices.row(M + i) = piece_start(loops, inner[i]).transpose();
  }
  // the inner loop runs the other way round; refused when it runs the same way (header)
  {
    const int q = 4, K = q * M;
    auto points = [&](const std::vector<CurvePiece>& pieces, int l) {
      std::vector<Eigen::Vector3d> x;
      for (const CurvePiece& p : pieces)
        for (int k = 0; k < q; ++k) x.push_back(loops[l][p.curve].evaluate(p.t0 + (p.t1 - p.t0) * k / q));
      return x;
    };
    const std::vector<Eigen::Vector3d> o = points(outer, 0), w = points(inner, 1);
    double opposite = INFINITY, same = INFINITY;
    for (int s = 0; s < K; ++s) {
      double a = 0, b = 0;
      for (int i = 0; i < K; ++i) {
        a += (o[i] - w[((s - i) % K + K) % K]).squaredNorm();
        b += (o[i] - w[(s + i) % K]).squaredNorm();
      }
      opposite = std::min(opposite, a), same = std::min(same, b);
    }
    if (same < opposite * (1 - 1e-9))
      throw LoopOrientationError(
          "loop 1 runs the same way round as loop 0: an annulus's inner loop runs the other way (the surface on the "
          "left of both; reverse its curves' order and direction, or give a circle the opposite normal)");
  }
  // outer vertex i faces inner vertex (shift - i) mod M
  int shift = 0;
  double best = INFINITY;
  for (int s = 0; s < M; ++s) {
    double d = 0;
    for (int i = 0; i < M; ++i) d += (L.vertices.row(i) - L.vertices.row(M + ((s - i) % M + M) % M)).squaredNorm();
    if (d < best) best = d, shift = s;
  }
  auto in = [&](int i) { return M + ((shift - i) % M + M) % M; };
  for (int i = 0; i < M; ++i) {
    const int o0 = i, o1 = (i + 1) % M, i0 = in(i), i1 = in(i + 1);
    if (kind == PatchKind::tensor) {
      L.faces.push_back({o0, o1, i1, i0});
    } else {
      L.faces.push_back({o0, o1, i0});
      L.faces.push_back({i1, i0, o1});
    }
  }
  std::vector<LayoutBoundaryEdge> edges = ring_edges(outer, 0);
  const std::vector<LayoutBoundaryEdge> inner_edges = ring_edges(inner, M);
  edges.insert(edges.end(), inner_edges.begin(), inner_edges.end());
  return fit_layout(L, n, loops, edges, options);
}

}  // namespace

void check_loops(const std::vector<Loop>& loops, double corner_tolerance) {
  if (loops.empty()) throw SizeError("no boundary loops");
  const double allowed = gap_allowed(loops, corner_tolerance);
  for (int l = 0; l < static_cast<int>(loops.size()); ++l) {
    const Loop& loop = loops[l];
    const int N = static_cast<int>(loop.size());
    if (N == 0) throw SizeError("loop " + std::to_string(l) + " has no curves");
    for (int k = 0; k < N; ++k) {
      const Eigen::Vector3d end = loop[k].end();
      const int next = (k + 1) % N;
      const double gap = (end - loop[next].start()).norm();
      if (gap <= allowed) continue;
      for (int j = 0; j < N; ++j) {
        if (j != next && (end - loop[j].start()).norm() <= allowed)
          throw CurvesOutOfOrderError(curve_name(l, k) + " ends where curve " + std::to_string(j) +
                                      " starts, not where the next curve " + std::to_string(next) + " starts");
        if ((end - loop[j].end()).norm() <= allowed && j != k)
          throw CurvesOutOfOrderError(curve_name(l, k) + " ends where curve " + std::to_string(j) +
                                      " ends: curve " + std::to_string(j) + " runs the wrong way round");
      }
      throw LoopNotClosedError(curve_name(l, k) + " ends " + number(gap) + " away from the start of " +
                               (N == 1 ? std::string("itself (a loop of one curve must be closed)")
                                       : "curve " + std::to_string(next)) +
                               " (allowed " + number(allowed) + ")");
    }
  }
}

LoopComplex loop_complex(PatchKind kind, int n, const std::vector<Loop>& loops, const LoopOptions& options) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError("degree " + std::to_string(n) + " outside 1.." + std::to_string(kMaxDegree));
  if (!(options.corner_tolerance > 0) || !std::isfinite(options.corner_tolerance))
    throw ParameterError("corner_tolerance must be finite and > 0");
  if (loops.size() != 1 && loops.size() != 2)
    throw SizeError("an automatic layout takes one loop (a disc) or two (an annulus), got " +
                    std::to_string(loops.size()) + " (give a layout)");
  check_loops(loops, options.corner_tolerance);
  return loops.size() == 1 ? disc(kind, n, loops, options) : annulus(kind, n, loops, options);
}

LoopComplex layout_complex(const Layout& layout, int n, const std::vector<Loop>& loops,
                           const std::vector<LayoutBoundaryEdge>& boundary, const LoopOptions& options) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError("degree " + std::to_string(n) + " outside 1.." + std::to_string(kMaxDegree));
  check_loops(loops, options.corner_tolerance);
  validate_layout(layout);
  const double allowed = gap_allowed(loops, options.corner_tolerance);
  // every layout boundary edge (directed as the faces run) has exactly one piece
  std::map<std::pair<int, int>, int> given;
  for (int k = 0; k < static_cast<int>(boundary.size()); ++k) {
    const LayoutBoundaryEdge& e = boundary[k];
    const std::string name = "layout boundary edge " + std::to_string(e.a) + "-" + std::to_string(e.b);
    if (e.piece.loop < 0 || e.piece.loop >= static_cast<int>(loops.size()) || e.piece.curve < 0 ||
        e.piece.curve >= static_cast<int>(loops[e.piece.loop].size()))
      throw LayoutMismatchError(name + ": no such loop or curve");
    if (!(e.piece.t0 >= 0 && e.piece.t0 < e.piece.t1 && e.piece.t1 <= 1))
      throw LayoutMismatchError(name + ": its range must satisfy 0 <= t0 < t1 <= 1");
    if (!given.emplace(std::pair{e.a, e.b}, k).second) throw LayoutMismatchError(name + " is given twice");
  }
  for (const std::vector<int>& loop : layout_boundary_loops(layout))
    for (std::size_t i = 0; i < loop.size(); ++i)
      if (!given.count({loop[i], loop[(i + 1) % loop.size()]}))
        throw LayoutMismatchError("layout boundary edge " + std::to_string(loop[i]) + "-" +
                                  std::to_string(loop[(i + 1) % loop.size()]) +
                                  " follows no curve (or is named against the faces' direction)");
  std::size_t boundary_edges = 0;
  for (const std::vector<int>& loop : layout_boundary_loops(layout)) boundary_edges += loop.size();
  if (boundary.size() != boundary_edges)
    throw LayoutMismatchError("the layout has " + std::to_string(boundary_edges) + " boundary edges, " +
                              std::to_string(boundary.size()) + " are given (an inner edge cannot follow a curve)");
  // each curve's pieces cover [0,1] once, and consecutive pieces meet at a layout vertex
  for (int l = 0; l < static_cast<int>(loops.size()); ++l)
    for (int c = 0; c < static_cast<int>(loops[l].size()); ++c) {
      std::vector<const LayoutBoundaryEdge*> pieces;
      for (const LayoutBoundaryEdge& e : boundary)
        if (e.piece.loop == l && e.piece.curve == c) pieces.push_back(&e);
      std::sort(pieces.begin(), pieces.end(), [](auto* x, auto* y) { return x->piece.t0 < y->piece.t0; });
      double t = 0;
      for (std::size_t i = 0; i < pieces.size(); ++i) {
        if (std::abs(pieces[i]->piece.t0 - t) > 1e-12)
          throw LayoutMismatchError(curve_name(l, c) + ": its pieces leave a gap or overlap at t = " + number(t));
        if (i > 0 && pieces[i]->a != pieces[i - 1]->b)
          throw LayoutMismatchError(curve_name(l, c) + ": consecutive pieces are on edges that do not meet");
        t = pieces[i]->piece.t1;
      }
      if (pieces.empty() || std::abs(t - 1) > 1e-12)
        throw LayoutMismatchError(curve_name(l, c) + " is not followed to its end by the layout's boundary");
    }
  // a boundary vertex's curve ends must meet
  std::map<int, Eigen::Vector3d> at;
  for (const LayoutBoundaryEdge& e : boundary) {
    const BoundaryCurve& curve = loops[e.piece.loop][e.piece.curve];
    for (const auto& [v, p] : {std::pair{e.a, curve.evaluate(e.piece.t0)}, std::pair{e.b, curve.evaluate(e.piece.t1)}}) {
      auto [it, added] = at.emplace(v, p);
      if (!added && (it->second - p).norm() > allowed)
        throw LayoutMismatchError("layout vertex " + std::to_string(v) + ": the curves ending there are " +
                                  number((it->second - p).norm()) + " apart");
    }
  }
  return fit_layout(layout, n, loops, boundary, options);
}

std::vector<EdgeFit> refit_boundary(PatchComplex& refined, const LoopComplex& coarse, int refine,
                                    const std::vector<Loop>& loops, const LoopOptions& options) {
  if (refine <= 0) return coarse.fits;
  const Layout& L = coarse.layout;
  // each refinement splits every patch into 4 (complex/refine.h)
  if (refine > 15 || refined.patches.size() != (L.faces.size() << (2 * refine)))
    throw SizeError("refit_boundary: the complex has " + std::to_string(refined.patches.size()) +
                    " patches, not the coarse layout's " + std::to_string(L.faces.size()) + " refined " +
                    std::to_string(refine) + " times");
  const int n = refined.patches.front().degree;
  // (patch, local edge, piece) of every boundary edge, split along with the patches: a part k of
  // patch p is patch 4p + k; coarse edge e of a patch is edges e of parts first[e], second[e]
  const bool tri = L.kind == PatchKind::triangular;
  const std::array<int, 4> first = tri ? std::array<int, 4>{0, 1, 2, 0} : std::array<int, 4>{0, 1, 2, 3};
  const std::array<int, 4> second = tri ? std::array<int, 4>{1, 2, 0, 0} : std::array<int, 4>{1, 2, 3, 0};
  struct Piece {
    int patch, edge, coarse;
    CurvePiece piece;
  };
  std::vector<Piece> pieces;
  for (int k = 0; k < static_cast<int>(coarse.boundary.size()); ++k) {
    const LayoutBoundaryEdge& b = coarse.boundary[k];
    bool found = false;
    for (int f = 0; f < static_cast<int>(L.faces.size()) && !found; ++f)
      for (std::size_t e = 0; e < L.faces[f].size() && !found; ++e)
        if (L.faces[f][e] == b.a && L.faces[f][(e + 1) % L.faces[f].size()] == b.b) {
          pieces.push_back({f, static_cast<int>(e), k, b.piece});
          found = true;
        }
    if (!found) throw LayoutMismatchError("layout boundary edge " + std::to_string(b.a) + "-" + std::to_string(b.b) +
                                          " is run by no face");
  }
  for (int r = 0; r < refine; ++r) {
    std::vector<Piece> next;
    for (const Piece& p : pieces) {
      const double tm = 0.5 * (p.piece.t0 + p.piece.t1);
      next.push_back({4 * p.patch + first[p.edge], p.edge, p.coarse, {p.piece.loop, p.piece.curve, p.piece.t0, tm}});
      next.push_back({4 * p.patch + second[p.edge], p.edge, p.coarse, {p.piece.loop, p.piece.curve, tm, p.piece.t1}});
    }
    pieces = std::move(next);
  }
  std::vector<EdgeFit> out = coarse.fits;
  for (EdgeFit& f : out) f.max_error = 0;
  std::map<int, std::pair<Eigen::Vector3d, int>> corners;
  for (const Piece& p : pieces) {
    const BoundaryCurve curve = loops[p.piece.loop][p.piece.curve].piece(p.piece.t0, p.piece.t1);
    const CurveFit fit = fit_edge(curve, n, options.method);
    const std::vector<int> local = patch_edge_local_rows(L.kind, n, p.edge);
    const std::vector<int>& rows = refined.patches[p.patch].points;
    for (int s = 1; s < n; ++s) refined.points.row(rows[local[s]]) = fit.points.row(s);
    for (int s : {0, n}) {
      auto& [sum, hits] = corners.try_emplace(rows[local[s]], Eigen::Vector3d::Zero(), 0).first->second;
      sum += fit.points.row(s).transpose(), ++hits;
    }
    EdgeFit& report = out[p.coarse];
    report.method = fit.method;
    const double error = edge_error(curve, fit);
    if (!(error <= report.max_error)) report.max_error = error;  // NaN stays NaN
  }
  for (const auto& [row, acc] : corners) refined.points.row(row) = (acc.first / acc.second).transpose();
  return out;
}

void coons_fill(PatchComplex& c) {
  validate(c);
  auto is_fixed = [&](int r) { return std::binary_search(c.fixed.begin(), c.fixed.end(), r); };
  const int n = c.patches.front().degree;
  for (const ComplexEdge& e : complex_edges(c))
    for (int s = 1; s < n; ++s)
      if (!is_fixed(e.rows[s]))
        c.points.row(e.rows[s]) = (1.0 - double(s) / n) * c.points.row(e.rows[0]) + (double(s) / n) * c.points.row(e.rows[n]);
  for (ComplexPatch& patch : c.patches) {
    auto P = [&](int local) { return Eigen::Vector3d(c.points.row(patch.points[local]).transpose()); };
    if (patch.kind == PatchKind::tensor) {
      auto at = [&](int i, int j) { return P(i * (n + 1) + j); };
      for (int i = 1; i < n; ++i)
        for (int j = 1; j < n; ++j) {
          const double a = double(i) / n, b = double(j) / n;
          const Eigen::Vector3d x = (1 - a) * at(0, j) + a * at(n, j) + (1 - b) * at(i, 0) + b * at(i, n) -
                                    ((1 - a) * (1 - b) * at(0, 0) + a * (1 - b) * at(n, 0) + a * b * at(n, n) +
                                     (1 - a) * b * at(0, n));
          if (!is_fixed(patch.points[i * (n + 1) + j])) c.points.row(patch.points[i * (n + 1) + j]) = x.transpose();
        }
    } else {
      auto at = [&](int i, int j) { return P(TriangularNet::index(n, i, j)); };
      for (int i = 1; i < n; ++i)
        for (int j = 1; i + j < n; ++j) {
          const int k = n - i - j;
          const Eigen::Vector3d x =
              ((1 - double(j) / (n - i)) * at(i, 0) + (double(j) / (n - i)) * at(i, n - i) +
               (1 - double(i) / (n - j)) * at(0, j) + (double(i) / (n - j)) * at(n - j, j) +
               (1 - double(i) / (n - k)) * at(0, n - k) + (double(i) / (n - k)) * at(n - k, 0)) / 3.0;
          const int row = patch.points[TriangularNet::index(n, i, j)];
          if (!is_fixed(row)) c.points.row(row) = x.transpose();
        }
    }
  }
}

}  // namespace bpde
