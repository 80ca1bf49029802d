#include "bezierpde/boundaries/fit_boundary.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/boundaries/fit_samples.h"

namespace bpde {
namespace {

Eigen::Vector3d bezier_at(const Eigen::MatrixX3d& P, double t) {
  const int k = static_cast<int>(P.rows()) - 1;
  std::vector<double> B(static_cast<size_t>(k + 1));
  bernstein_values(k, t, B.data());
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int i = 0; i <= k; ++i) x += B[static_cast<size_t>(i)] * P.row(i).transpose();
  return x;
}

struct EdgeMap {
  std::vector<int> bnd;  // net rows of the edge's points, s = 0..edge degree
  std::vector<int> adj;  // net rows of the adjacent points, s = 0..tangent degree
  int cross = 1;         // the degree across the edge (D_s / cross)
};

template <class NetT>
BoundaryFit<NetT> fit_net(NetT net, const std::vector<EdgeMap>& maps, const BoundaryData& data,
                          const BoundaryFitOptions& o) {
  o.validate();
  const size_t E = maps.size();
  if (data.edges.size() != E)
    throw SizeError("boundary: expected " + std::to_string(E) + " edges, got " + std::to_string(data.edges.size()));
  if (!data.tangents.empty() && data.tangents.size() != E)
    throw SizeError("boundary: tangents are given for " + std::to_string(data.tangents.size()) + " of the " +
                    std::to_string(E) + " edges (give one per edge, or none)");
  // The corners meet.
  std::vector<Eigen::Vector3d> starts(E), ends(E);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (size_t e = 0; e < E; ++e) {
    starts[e] = data.edges[e].start();
    ends[e] = data.edges[e].end();
    if (!starts[e].allFinite() || !ends[e].allFinite())
      throw NonFiniteError("boundary: the end points of edge " + std::to_string(e) + " overflow");
    lo = lo.cwiseMin(starts[e]).cwiseMin(ends[e]);
    hi = hi.cwiseMax(starts[e]).cwiseMax(ends[e]);
  }
  const double scale = std::max(1.0, (hi - lo).norm());
  if (!std::isfinite(scale)) throw NonFiniteError("boundary: the curves' end points overflow");
  const double tol = o.corner_tolerance * scale;
  for (size_t e = 0; e < E; ++e) {
    const size_t f = (e + 1) % E;
    const double gap = (ends[e] - starts[f]).norm();
    if (!(gap <= tol)) {
      char buf[160];
      std::snprintf(buf, sizeof buf, "the end of edge %zu is %.3g from the start of edge %zu (tolerance %.3g)", e, gap,
                    f, tol);
      throw ParameterError("boundary: edges " + std::to_string(e) + " and " + std::to_string(f) +
                           " do not meet: " + buf);
    }
  }
  // Fit the edges; share the corners.
  std::vector<CurveFit> fits;
  for (size_t e = 0; e < E; ++e) {
    const int d = static_cast<int>(maps[e].bnd.size()) - 1;
    // With C¹ data the tangent field is given in the edge's parameter, so it is not corrected.
    fits.push_back(fit_edge(data.edges[e], d, o.method, data.tangents.empty()));
  }
  for (size_t e = 0; e < E; ++e) {
    const size_t f = (e + 1) % E;
    Eigen::MatrixX3d& a = fits[e].points;
    Eigen::MatrixX3d& b = fits[f].points;
    const Eigen::RowVector3d corner = 0.5 * (a.row(a.rows() - 1) + b.row(0));
    a.row(a.rows() - 1) = corner;
    b.row(0) = corner;
  }
  Eigen::MatrixX3d& P = net.points();
  P.setZero();
  std::vector<char> on_boundary(static_cast<size_t>(P.rows()), 0);
  for (size_t e = 0; e < E; ++e)
    for (size_t s = 0; s < maps[e].bnd.size(); ++s) {
      P.row(maps[e].bnd[s]) = fits[e].points.row(static_cast<Eigen::Index>(s));
      on_boundary[static_cast<size_t>(maps[e].bnd[s])] = 1;
    }
  BoundaryFit<NetT> out{net, {}};
  for (size_t e = 0; e < E; ++e) {
    EdgeFit r;
    r.edge = static_cast<int>(e);
    r.curve = data.edges[e].kind();
    r.method = fits[e].method;
    r.max_error = edge_error(data.edges[e], fits[e]);
    if (!fits[e].parameters.empty()) {
      r.parameters = fits[e].parameters;
      r.corrections = fits[e].corrections;
    }
    out.edges.push_back(r);
  }
  if (!data.tangents.empty()) {
    Eigen::MatrixX3d sum = Eigen::MatrixX3d::Zero(P.rows(), 3);
    std::vector<int> count(static_cast<size_t>(P.rows()), 0);
    for (size_t e = 0; e < E; ++e) {
      const int d = static_cast<int>(maps[e].adj.size()) - 1;
      // A tangent field is read at the edge's parameter: samples of it are never corrected.
      const CurveFit D = fit_edge(data.tangents[e], d, o.method, false);
      out.edges[e].tangent_curve = data.tangents[e].kind();
      out.edges[e].tangent_method = D.method;
      for (int s = 0; s <= d; ++s) {
        const int a = maps[e].adj[static_cast<size_t>(s)];
        if (on_boundary[static_cast<size_t>(a)]) continue;
        sum.row(a) += P.row(maps[e].bnd[static_cast<size_t>(s)]) + D.points.row(s) / maps[e].cross;
        ++count[static_cast<size_t>(a)];
      }
    }
    for (Eigen::Index r = 0; r < P.rows(); ++r)
      if (count[static_cast<size_t>(r)] > 0) P.row(r) = sum.row(r) / count[static_cast<size_t>(r)];
    for (size_t e = 0; e < E; ++e) {
      const int d = static_cast<int>(maps[e].adj.size()) - 1;
      Eigen::MatrixX3d Dr(d + 1, 3);
      for (int s = 0; s <= d; ++s)
        Dr.row(s) =
            maps[e].cross * (P.row(maps[e].adj[static_cast<size_t>(s)]) - P.row(maps[e].bnd[static_cast<size_t>(s)]));
      out.edges[e].tangent_max_error = edge_error(data.tangents[e], Dr);
    }
  }
  if (!P.allFinite()) throw NonFiniteError("boundary: the fitted control points overflow");
  out.net = net;
  for (auto& r : out.edges)
    if (!std::isfinite(r.max_error) || (r.tangent_max_error && !std::isfinite(*r.tangent_max_error)))
      throw NonFiniteError("boundary: the fit error of edge " + std::to_string(r.edge) + " overflows");
  return out;
}

void check_degree(int n, const char* what) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError(std::string("boundary: ") + what + " " + std::to_string(n) + " is outside 1.." +
                      std::to_string(kMaxDegree));
}

}  // namespace

std::string to_string(FitMethod m) { return m == FitMethod::Interpolation ? "interpolation" : "least-squares"; }

void BoundaryFitOptions::validate() const {
  if (!std::isfinite(corner_tolerance) || !(corner_tolerance > 0))
    throw ParameterError("corner_tolerance: must be a finite number > 0");
}

CurveFit fit_edge(const BoundaryCurve& curve, int n, FitMethod method, bool correct) {
  check_degree(n, "degree");
  if (const auto* b = curve.as_bezier()) {
    const int k = static_cast<int>(b->points.rows()) - 1;
    if (k == n) return {b->points, "elevation"};
    if (k < n) return {bernstein_elevation_operator(k, n - k) * b->points, "elevation"};
  }
  if (const auto* s = curve.as_samples()) {
    if (s->chord_length && s->correct && correct) {
      const SampleFit g = fit_samples_orthogonal(n, s->params, s->points);
      return {g.points, "least-squares", g.params, g.corrected ? "corrected" : "chord-length", g.iterations};
    }
    return {least_squares_at(n, s->params, s->points), "least-squares", s->params,
            s->chord_length ? "chord-length" : "given", 0};
  }
  if (method == FitMethod::LeastSquares) {
    const int M = 8 * n + 1;
    Eigen::VectorXd t(M);
    Eigen::MatrixX3d Q(M, 3);
    for (int k = 0; k < M; ++k) {
      t(k) = k == M - 1 ? 1.0 : static_cast<double>(k) / (M - 1);
      Q.row(k) = curve.evaluate(t(k)).transpose();
    }
    return {least_squares_at(n, t, Q), "least-squares", {}, "", 0};
  }
  // Chebyshev–Lobatto interpolation (the same computation as fit_curve of reference_boundaries.h).
  Eigen::MatrixXd A(n + 1, n + 1);
  Eigen::MatrixX3d rhs(n + 1, 3);
  std::vector<double> B(static_cast<size_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    const double t = 0.5 * (1 - std::cos(std::numbers::pi * k / n));
    bernstein_values(n, t, B.data());
    for (int i = 0; i <= n; ++i) A(k, i) = B[static_cast<size_t>(i)];
    rhs.row(k) = curve.evaluate(t).transpose();
  }
  Eigen::MatrixX3d P = A.partialPivLu().solve(rhs);
  P.row(0) = curve.evaluate(0.0).transpose();
  P.row(n) = curve.evaluate(1.0).transpose();
  return {P, "interpolation"};
}

double edge_error(const BoundaryCurve& curve, const Eigen::MatrixX3d& points) {
  if (const auto* s = curve.as_samples()) return edge_error(curve, CurveFit{points, "", s->params, "", 0});
  return edge_error(curve, CurveFit{points, "", {}, "", 0});
}

double edge_error(const BoundaryCurve& curve, const CurveFit& fit) {
  const Eigen::MatrixX3d& points = fit.points;
  double err = 0;
  if (const auto* s = curve.as_samples()) {
    const Eigen::VectorXd& t = fit.params.size() == s->params.size() ? fit.params : s->params;
    for (Eigen::Index i = 0; i < t.size(); ++i)
      err = std::max(err, (bezier_at(points, t(i)) - s->points.row(i).transpose()).norm());
    return err;
  }
  constexpr int kSamples = 256;
  for (int k = 0; k <= kSamples; ++k) {
    const double t = static_cast<double>(k) / kSamples;
    err = std::max(err, (bezier_at(points, t) - curve.evaluate(t)).norm());
  }
  return err;
}

BoundaryFit<TensorNet> fit_tensor_boundary(int n, int m, const BoundaryData& data, const BoundaryFitOptions& options) {
  check_degree(n, "degree");
  check_degree(m, "degree");
  if (!data.tangents.empty() && (n < 2 || m < 2))
    throw DegreeError("boundary: C1 data (tangents) need tensor degrees >= 2, got [" + std::to_string(n) + ", " +
                      std::to_string(m) + "]");
  const TensorNet net(n, m);
  auto id = [&](int i, int j) { return net.index(i, j); };
  std::vector<EdgeMap> maps(4);
  for (int s = 0; s <= n; ++s) {
    maps[0].bnd.push_back(id(s, 0));
    maps[0].adj.push_back(id(s, 1));
    maps[2].bnd.push_back(id(n - s, m));
    maps[2].adj.push_back(id(n - s, m - 1));
  }
  for (int s = 0; s <= m; ++s) {
    maps[1].bnd.push_back(id(n, s));
    maps[1].adj.push_back(id(n - 1, s));
    maps[3].bnd.push_back(id(0, m - s));
    maps[3].adj.push_back(id(1, m - s));
  }
  maps[0].cross = maps[2].cross = m;
  maps[1].cross = maps[3].cross = n;
  return fit_net(net, maps, data, options);
}

BoundaryFit<TriangularNet> fit_triangular_boundary(int n, const BoundaryData& data, const BoundaryFitOptions& options) {
  check_degree(n, "degree");
  if (!data.tangents.empty() && n < 2)
    throw DegreeError("boundary: C1 data (tangents) need triangular degree >= 2, got " + std::to_string(n));
  const TriangularNet net(n);
  auto id = [&](int i, int j) { return net.index(i, j); };
  std::vector<EdgeMap> maps(3);
  for (int s = 0; s <= n; ++s) {
    maps[0].bnd.push_back(id(s, 0));
    maps[1].bnd.push_back(id(n - s, s));
    maps[2].bnd.push_back(id(0, n - s));
  }
  for (int s = 0; s <= n - 1; ++s) {
    maps[0].adj.push_back(id(s, 1));
    maps[1].adj.push_back(id(n - 1 - s, s));
    maps[2].adj.push_back(id(1, n - 1 - s));
  }
  for (auto& mp : maps) mp.cross = n;
  return fit_net(net, maps, data, options);
}

}  // namespace bpde
