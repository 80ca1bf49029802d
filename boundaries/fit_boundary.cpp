#include "bezierpde/boundaries/fit_boundary.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

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

// The first non-zero leg of a Bézier polygon at one end, pointing along the curve (P_1 - P_0 at
// the start, P_k - P_{k-1} at the end); zero for a polygon that is one point.
Eigen::Vector3d end_leg(const Eigen::MatrixX3d& P, bool at_end) {
  const Eigen::Index k = P.rows() - 1;
  for (Eigen::Index j = 1; j <= k; ++j) {
    const Eigen::Vector3d d = at_end ? Eigen::Vector3d((P.row(k) - P.row(k - j)).transpose())
                                     : Eigen::Vector3d((P.row(j) - P.row(0)).transpose());
    if (d.squaredNorm() > 0) return d;
  }
  return Eigen::Vector3d::Zero();
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

// The derivative at x[0] of the polynomial through (x[j], y[j]), j = 0..k-1 (Lagrange).
Eigen::Vector3d lagrange_derivative(const std::vector<double>& x, const std::vector<Eigen::Vector3d>& y) {
  const size_t k = x.size();
  Eigen::Vector3d d = Eigen::Vector3d::Zero();
  for (size_t j = 0; j < k; ++j) {
    double w = 1;
    if (j == 0) {
      w = 0;
      for (size_t i = 1; i < k; ++i) w += 1 / (x[0] - x[i]);
    } else {
      for (size_t i = 1; i < k; ++i)
        if (i != j) w *= x[0] - x[i];
      for (size_t i = 0; i < k; ++i)
        if (i != j) w /= x[j] - x[i];
    }
    d += w * y[j];
  }
  return d;
}

// The curve's tangent at one end as the data give it (fit_boundary.h): exact where the form gives
// it, else the derivative of the cubic through the four samples nearest the end (at their
// parameters), or through c at t = 0, h, 2h, 3h (h = 1e-3; from the other end likewise) for a
// function. It is dc/dt: it points along the curve at both ends.
Eigen::Vector3d data_tangent(const BoundaryCurve& c, bool at_end) {
  if (const auto x = c.exact_tangent(at_end)) return *x;
  std::vector<double> t;
  std::vector<Eigen::Vector3d> y;
  if (const auto* s = c.as_samples()) {
    const Eigen::Index M = s->params.size() - 1, k = std::min<Eigen::Index>(4, M + 1);
    for (Eigen::Index j = 0; j < k; ++j) {
      const Eigen::Index i = at_end ? M - j : j;
      t.push_back(s->params(i));
      y.push_back(s->points.row(i).transpose());
    }
  } else {
    constexpr double h = 1e-3;
    for (int j = 0; j < 4; ++j) {
      t.push_back(at_end ? 1 - j * h : j * h);
      y.push_back(c.evaluate(t.back()));
    }
  }
  return lagrange_derivative(t, y);
}

// The curve at M >= 2 parameters: uniform, t_r = r/(M-1), or the Chebyshev–Lobatto nodes
// t_r = (1 - cos(π r/(M-1)))/2; the last is 1 exactly.
void curve_rows(const BoundaryCurve& c, int M, bool chebyshev, Eigen::VectorXd& t, Eigen::MatrixX3d& Q) {
  t.resize(M);
  Q.resize(M, 3);
  for (int r = 0; r < M; ++r) {
    t(r) = r == M - 1
               ? 1.0
               : (chebyshev ? 0.5 * (1 - std::cos(std::numbers::pi * r / (M - 1))) : static_cast<double>(r) / (M - 1));
    Q.row(r) = c.evaluate(t(r)).transpose();
  }
}

// The rows of an edge's least squares (fit_boundary.h, "Corners where the curve is smooth"): the
// samples at the fit's parameters, 8k+1 uniform parameters ("least-squares") or the 4k+1
// Chebyshev–Lobatto nodes ("interpolation").
void fit_rows(const BoundaryCurve& c, const CurveFit& fit, int k, Eigen::VectorXd& t, Eigen::MatrixX3d& Q) {
  if (const auto* s = c.as_samples()) {
    t = fit.params.size() == s->params.size() ? fit.params : s->params;
    Q = s->points;
    return;
  }
  const bool uniform = fit.method == "least-squares";
  curve_rows(c, uniform ? 8 * k + 1 : 4 * k + 1, !uniform, t, Q);
}

// The least squares of one edge (its rows from fit_rows) reduced to its triangle: with
// B = Q_B [T; 0] (Householder QR), |B P - Q|² = |T P - Y|² + const, so that the constrained fits
// below cost O(k³) each, whatever the number of samples.
struct EdgeLeastSquares {
  int k = 0;
  Eigen::VectorXd t;
  Eigen::MatrixX3d Q;
  Eigen::MatrixXd T;
  Eigen::MatrixX3d Y;

  EdgeLeastSquares(const BoundaryCurve& c, const CurveFit& fit, int degree) : k(degree) {
    fit_rows(c, fit, k, t, Q);
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(bernstein_table(k, t));
    T = qr.matrixQR().topRows(k + 1).triangularView<Eigen::Upper>();
    Y = (qr.householderQ().adjoint() * Q).topRows(k + 1);
  }

  // The fit with P's end points and, where given, P_1 = P_0 + a d0 and P_{k-1} = P_k - b d1 (a, b
  // free), the other inner points free; and |T R - Y|². G (if not null) receives the directions
  // in which the inner points may move (3(k-1) x #unknowns, for fit_samples_orthogonal_constrained).
  // nullopt when the problem is rank deficient.
  std::optional<std::pair<Eigen::MatrixX3d, double>> solve(const Eigen::MatrixX3d& P, const Eigen::Vector3d* d0,
                                                           const Eigen::Vector3d* d1,
                                                           Eigen::MatrixXd* G = nullptr) const {
    Eigen::MatrixX3d base = Eigen::MatrixX3d::Zero(k + 1, 3);
    base.row(0) = P.row(0);
    base.row(k) = P.row(k);
    std::vector<std::pair<int, Eigen::Vector3d>> cols;  // (point, its motion per unit of the unknown)
    if (d0) {
      base.row(1) = P.row(0);
      cols.emplace_back(1, *d0);
    }
    if (d1) {
      base.row(k - 1) = P.row(k);
      cols.emplace_back(k - 1, -*d1);
    }
    for (int i = 1; i < k; ++i)
      if (!((d0 && i == 1) || (d1 && i == k - 1)))
        for (int q = 0; q < 3; ++q) cols.emplace_back(i, Eigen::Vector3d::Unit(q));
    const Eigen::Index N = static_cast<Eigen::Index>(cols.size());
    Eigen::MatrixXd A(3 * (k + 1), N);
    Eigen::VectorXd r(3 * (k + 1));
    const Eigen::MatrixX3d rhs = Y - T * base;
    for (int row = 0; row <= k; ++row)
      for (int q = 0; q < 3; ++q) {
        r(3 * row + q) = rhs(row, q);
        for (Eigen::Index j = 0; j < N; ++j)
          A(3 * row + q, j) = T(row, cols[static_cast<size_t>(j)].first) * cols[static_cast<size_t>(j)].second(q);
      }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
    qr.setThreshold(1e-12);  // as least_squares_at (fit_samples.cpp)
    if (qr.rank() < N) return std::nullopt;
    const Eigen::VectorXd z = qr.solve(r);
    Eigen::MatrixX3d R = base;
    for (Eigen::Index j = 0; j < N; ++j)
      R.row(cols[static_cast<size_t>(j)].first) += z(j) * cols[static_cast<size_t>(j)].second.transpose();
    if (G) {
      G->setZero(3 * (k - 1), N);
      for (Eigen::Index j = 0; j < N; ++j)
        G->block<3, 1>(3 * (cols[static_cast<size_t>(j)].first - 1), j) = cols[static_cast<size_t>(j)].second;
    }
    return std::make_pair(R, (T * R - Y).squaredNorm());
  }
};

// An exactly elevated Bézier curve at a joined corner: its legs projected onto the directions.
// nullopt when a leg points against its direction.
std::optional<Eigen::MatrixX3d> project_legs(const Eigen::MatrixX3d& P, const Eigen::Vector3d* d0,
                                             const Eigen::Vector3d* d1) {
  const Eigen::Index k = P.rows() - 1;
  Eigen::MatrixX3d R = P;
  if (d0) {
    const double a = (P.row(1) - P.row(0)).dot(d0->transpose());
    if (!(a > 0)) return std::nullopt;
    R.row(1) = P.row(0) + a * d0->transpose();
  }
  if (d1) {
    const double b = (P.row(k) - P.row(k - 1)).dot(d1->transpose());
    if (!(b > 0)) return std::nullopt;
    R.row(k - 1) = P.row(k) - b * d1->transpose();
  }
  return R;
}

// A curve's rows at a joined corner start from the constrained least squares at the curve's own
// parameters, near the geometric optimum except along the nearly free reparametrisations, where
// the damping of samples (1e-3) and their 100 iterations stop early: measured on the circle in
// three arcs (radius 2.5), n = 6: 5.2e-9 from the circle after 100 iterations, 1.8e-10 after 175;
// n = 9, 10: 1.1e-12 with the damping 1e-3, 1e-14 with 1e-12. The end legs' lengths are such a
// reparametrisation too (the geometry barely depends on them), so they are held within a factor
// kLegRange of the least squares' (else a leg may shrink to 0 or turn around: a corner where the
// surface's parametrisation degenerates).
constexpr int kCurveIterations = 500;
constexpr double kCurveDamping = 1e-12;
constexpr double kLegRange = 2;

// Whether the legs of R point along their directions (a, b > 0).
bool legs_forward(const Eigen::MatrixX3d& R, const Eigen::Vector3d* d0, const Eigen::Vector3d* d1) {
  const Eigen::Index k = R.rows() - 1;
  return R.allFinite() && (!d0 || (R.row(1) - R.row(0)).dot(d0->transpose()) > 0) &&
         (!d1 || (R.row(k) - R.row(k - 1)).dot(d1->transpose()) > 0);
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
  // Corners where the curve is smooth: joined G¹ (fit_boundary.h).
  std::vector<char> joined(E, 0), search(E, 0);
  std::vector<Eigen::Vector3d> dir(E, Eigen::Vector3d::Zero()), leg_u(E), leg_w(E);
  std::vector<double> turn(E, 0.0);
  for (size_t e = 0; e < E; ++e) {
    const size_t f = (e + 1) % E;
    const Eigen::Vector3d lin = end_leg(fits[e].points, true), lout = end_leg(fits[f].points, false);
    turn[e] = angle_between(lin, lout) * 180 / std::numbers::pi;
    if (!data.tangents.empty() || !(o.smooth_corner_angle > 0)) continue;
    if (fits[e].points.rows() < 4 || fits[f].points.rows() < 4 || lin.squaredNorm() == 0 || lout.squaredNorm() == 0)
      continue;
    const bool xin = data.edges[e].exact_tangent(true).has_value(),
               xout = data.edges[f].exact_tangent(false).has_value();
    const Eigen::Vector3d tin = data_tangent(data.edges[e], true), tout = data_tangent(data.edges[f], false);
    if (!(tin.allFinite() && tout.allFinite() && tin.squaredNorm() > 0 && tout.squaredNorm() > 0)) continue;
    const Eigen::Vector3d rin = tin.normalized(), rout = tout.normalized();
    const double angle = angle_between(rin, rout);
    joined[e] = xin && xout ? angle <= kExactSmoothRadians : angle <= o.smooth_corner_angle * std::numbers::pi / 180;
    if (xin != xout) {
      dir[e] = xin ? rin : rout;
    } else if (xin) {
      dir[e] = (rin + rout).normalized();
    } else {
      // Estimated on both sides: the direction in the plane of the fitted legs that fits both
      // edges best (searched below), from the mean of the legs.
      leg_u[e] = lin.normalized();
      const Eigen::Vector3d w = lout.normalized() - leg_u[e].dot(lout.normalized()) * leg_u[e];
      leg_w[e] = w.squaredNorm() > 0 ? Eigen::Vector3d(w.normalized()) : Eigen::Vector3d::Zero();
      dir[e] = (lin.normalized() + lout.normalized()).normalized();
      search[e] = joined[e] && w.squaredNorm() > 0;
    }
  }
  // Each edge at a joined corner (not elevated) gets its least squares.
  std::vector<std::optional<EdgeLeastSquares>> ls(E);
  auto prepare = [&](size_t g) {
    if (!ls[g] && fits[g].method != "elevation")
      ls[g].emplace(data.edges[g], fits[g], static_cast<int>(fits[g].points.rows()) - 1);
  };
  for (size_t e = 0; e < E; ++e)
    if (joined[e]) {
      prepare(e);
      prepare((e + 1) % E);
    }
  auto dirs_of = [&](size_t g) {
    const size_t start = (g + E - 1) % E;
    return std::make_pair(joined[start] ? &dir[start] : nullptr, joined[g] ? &dir[g] : nullptr);
  };
  auto edge_cost = [&](size_t g) {
    if (!ls[g]) return 0.0;  // an elevated edge (exact tangents: never at a searched corner)
    const auto [d0, d1] = dirs_of(g);
    const auto r = ls[g]->solve(fits[g].points, d0, d1);
    return r && legs_forward(r->first, d0, d1) ? r->second : INFINITY;
  };
  // The search: per corner, golden section on the angle phi of d = cos(phi) u + sin(phi) w (u the
  // incoming leg, w towards the outgoing one, which is at phi = turn) over [-turn, 2 turn]; two
  // sweeps over the corners (an edge between two joined corners couples them).
  for (int sweep = 0; sweep < 2; ++sweep)
    for (size_t e = 0; e < E; ++e) {
      if (!search[e] || !joined[e]) continue;
      const size_t f = (e + 1) % E;
      const double th = turn[e] * std::numbers::pi / 180;
      auto cost = [&](double phi) {
        dir[e] = std::cos(phi) * leg_u[e] + std::sin(phi) * leg_w[e];
        return edge_cost(e) + edge_cost(f);
      };
      const double gr = 0.5 * (std::sqrt(5.0) - 1);
      double a = -th, b = 2 * th, x1 = b - gr * (b - a), x2 = a + gr * (b - a);
      double f1 = cost(x1), f2 = cost(x2);
      for (int it = 0; it < 60 && b - a > 1e-13 * std::max(1.0, th); ++it) {
        if (f1 <= f2) {
          b = x2;
          x2 = x1;
          f2 = f1;
          x1 = b - gr * (b - a);
          f1 = cost(x1);
        } else {
          a = x1;
          x1 = x2;
          f1 = f2;
          x2 = a + gr * (b - a);
          f2 = cost(x2);
        }
      }
      const double best = f1 <= f2 ? x1 : x2;
      if (std::isfinite(std::min(f1, f2))) {
        dir[e] = std::cos(best) * leg_u[e] + std::sin(best) * leg_w[e];
      } else {
        dir[e] = (leg_u[e] + std::cos(th) * leg_u[e] + std::sin(th) * leg_w[e]).normalized();
      }
    }
  // Fit the edges at joined corners again (corrected samples: their parameters too); a corner
  // whose edge cannot take it is kept, and the edges are fitted again without it (each pass keeps
  // at least one more corner).
  std::vector<Eigen::MatrixX3d> refit(E);
  std::vector<Eigen::VectorXd> params(E), curve_params(E);
  std::vector<std::string> parameters(E);
  std::vector<int> corrections(E, 0);
  auto reset = [&](size_t g) {
    refit[g] = fits[g].points;
    params[g] = fits[g].params;
    curve_params[g] = fits[g].curve_params;
    parameters[g] = fits[g].parameters;
    corrections[g] = fits[g].corrections;
  };
  for (size_t pass = 0; pass <= E; ++pass) {
    bool changed = false;
    for (size_t g = 0; g < E; ++g) {
      const size_t start = (g + E - 1) % E;
      const auto [d0, d1] = dirs_of(g);
      reset(g);
      if (!d0 && !d1) continue;
      std::optional<Eigen::MatrixX3d> r;
      if (!ls[g]) {
        r = project_legs(fits[g].points, d0, d1);
      } else {
        Eigen::MatrixXd G;
        if (auto s = ls[g]->solve(fits[g].points, d0, d1, &G)) {
          r = s->first;
          // Corrected samples, and every curve: the rows' parameters corrected under the
          // constraint (a curve's rows are its points at ls.t; fit_boundary.h).
          const bool samples = data.edges[g].as_samples() != nullptr;
          if (!samples || fits[g].parameters == "corrected") {
            ConstrainedFitOptions options;
            if (!samples) {
              const Eigen::Index k = r->rows() - 1;
              const double a0 = (r->row(1) - r->row(0)).norm(), b0 = (r->row(k) - r->row(k - 1)).norm();
              // The directions by value, not the structured bindings (clang < 16 cannot capture those).
              options = {kCurveIterations, kCurveDamping, [d0 = d0, d1 = d1, k, a0, b0](const Eigen::MatrixX3d& P) {
                           auto within = [](double x, double x0) { return x >= x0 / kLegRange && x <= x0 * kLegRange; };
                           return (!d0 || within((P.row(1) - P.row(0)).dot(d0->transpose()), a0)) &&
                                  (!d1 || within((P.row(k) - P.row(k - 1)).dot(d1->transpose()), b0));
                         }};
            }
            const SampleFit c = fit_samples_orthogonal_constrained(*r, ls[g]->t, ls[g]->Q, G, options);
            r = c.points;
            params[g] = c.params;
            if (!samples) {
              curve_params[g] = ls[g]->t;
              parameters[g] = "corrected";
            }
            corrections[g] += c.iterations;
          }
        }
      }
      // Keep only the corner whose leg turned around (both where the problem had no solution).
      const bool start_ok = r && legs_forward(*r, d0, nullptr), end_ok = r && legs_forward(*r, nullptr, d1);
      if (start_ok && end_ok) {
        refit[g] = *r;
      } else {
        reset(g);
        if (!start_ok) joined[start] = 0;
        if (!end_ok) joined[g] = 0;
        changed = true;
      }
    }
    if (!changed) break;
  }
  for (size_t g = 0; g < E; ++g) {
    const size_t start = (g + E - 1) % E;
    fits[g].points = refit[g];
    fits[g].params = params[g];
    fits[g].curve_params = curve_params[g];
    fits[g].parameters = parameters[g];
    fits[g].corrections = corrections[g];
    // A curve refitted at a joined corner is a geometric fit (its rows corrected), whatever its
    // own method was (fit_boundary.h).
    if ((joined[start] || joined[g]) && !data.edges[g].as_samples() && fits[g].parameters == "corrected")
      fits[g].method = "geometric";
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
    r.end_corner = joined[e] ? "g1" : "kept";
    r.end_corner_turn = turn[e];
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
      const CurveFit D =
          fit_edge(data.tangents[e], d, o.method == FitMethod::Geometric ? FitMethod::Interpolation : o.method, false);
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

CurveFit curve_fit(Eigen::MatrixX3d points, std::string method, Eigen::VectorXd params = {},
                   std::string parameters = {}, int corrections = 0) {
  CurveFit f;
  f.points = std::move(points);
  f.method = std::move(method);
  f.params = std::move(params);
  f.parameters = std::move(parameters);
  f.corrections = corrections;
  return f;
}

void check_degree(int n, const char* what) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError(std::string("boundary: ") + what + " " + std::to_string(n) + " is outside 1.." +
                      std::to_string(kMaxDegree));
}

}  // namespace

std::string to_string(FitMethod m) {
  return m == FitMethod::Interpolation ? "interpolation" : m == FitMethod::LeastSquares ? "least-squares" : "geometric";
}

void BoundaryFitOptions::validate() const {
  if (!std::isfinite(corner_tolerance) || !(corner_tolerance > 0))
    throw ParameterError("corner_tolerance: must be a finite number > 0");
  if (!(smooth_corner_angle >= 0 && smooth_corner_angle <= 90))
    throw ParameterError("smooth_corner_angle: must be a number of degrees in [0, 90]");
}

CurveFit fit_edge(const BoundaryCurve& curve, int n, FitMethod method, bool correct) {
  check_degree(n, "degree");
  if (const auto* b = curve.as_bezier()) {
    const int k = static_cast<int>(b->points.rows()) - 1;
    if (k == n) return curve_fit(b->points, "elevation");
    if (k < n) return curve_fit(bernstein_elevation_operator(k, n - k) * b->points, "elevation");
  }
  if (const auto* s = curve.as_samples()) {
    if (s->chord_length && s->correct && correct) {
      const SampleFit g = fit_samples_orthogonal(n, s->params, s->points);
      return curve_fit(g.points, "least-squares", g.params, g.corrected ? "corrected" : "chord-length", g.iterations);
    }
    return curve_fit(least_squares_at(n, s->params, s->points), "least-squares", s->params,
                     s->chord_length ? "chord-length" : "given");
  }
  Eigen::VectorXd t;
  Eigen::MatrixX3d Q;
  if (method == FitMethod::Geometric && correct && n >= 2) {
    curve_rows(curve, 4 * n + 1, true, t, Q);
    try {
      const SampleFit g = fit_samples_orthogonal(n, t, Q);
      if (g.corrected) {
        // The ladder ends where its 100 iterations at degree n crawl along the nearly free
        // reparametrisations; a last run with every inner point free and the curves' settings
        // (kCurveIterations, kCurveDamping) goes on from there (fit_boundary.h).
        const SampleFit h = fit_samples_orthogonal_constrained(
            g.points, g.params, Q, Eigen::MatrixXd::Identity(3 * (n - 1), 3 * (n - 1)),
            ConstrainedFitOptions{kCurveIterations, kCurveDamping, {}});
        CurveFit f = curve_fit(h.points, "geometric", h.params, "corrected", g.iterations + h.iterations);
        f.curve_params = t;
        return f;
      }
    } catch (const ParameterError&) {
      // The nodes' parameters no longer determine a least-squares fit (fewer than n − 1 distinct
      // inside (0,1)): the interpolant below.
    }
  }
  if (method == FitMethod::LeastSquares) {
    curve_rows(curve, 8 * n + 1, false, t, Q);
    return curve_fit(least_squares_at(n, t, Q), "least-squares");
  }
  // Chebyshev–Lobatto interpolation (fit_curve of reference_boundaries.h calls this).
  curve_rows(curve, n + 1, true, t, Q);
  Eigen::MatrixXd A(n + 1, n + 1);
  std::vector<double> B(static_cast<size_t>(n + 1));
  for (int k = 0; k <= n; ++k) {
    bernstein_values(n, t(k), B.data());
    for (int i = 0; i <= n; ++i) A(k, i) = B[static_cast<size_t>(i)];
  }
  Eigen::MatrixX3d P = A.partialPivLu().solve(Q);
  P.row(0) = curve.evaluate(0.0).transpose();
  P.row(n) = curve.evaluate(1.0).transpose();
  return curve_fit(P, "interpolation");
}

double edge_error(const BoundaryCurve& curve, const Eigen::MatrixX3d& points) {
  if (const auto* s = curve.as_samples()) return edge_error(curve, curve_fit(points, "", s->params));
  return edge_error(curve, curve_fit(points, ""));
}

double edge_error(const BoundaryCurve& curve, const CurveFit& fit) {
  const Eigen::MatrixX3d& points = fit.points;
  double err = 0;
  // The largest distance; a NaN stays (fit_net refuses a non-finite error).
  auto take = [&err](double x) {
    if (!(x <= err) && !std::isnan(err)) err = x;
  };
  if (const auto* s = curve.as_samples()) {
    const Eigen::VectorXd& t = fit.params.size() == s->params.size() ? fit.params : s->params;
    for (Eigen::Index i = 0; i < t.size(); ++i) take((bezier_at(points, t(i)) - s->points.row(i).transpose()).norm());
    return err;
  }
  constexpr int kSamples = 256;
  const Eigen::VectorXd &s = fit.curve_params, &tf = fit.params;
  const bool corrected = s.size() > 0;
  if (corrected) {
    bool ok = s.size() >= 2 && s.size() == tf.size() && s(0) == 0 && s(s.size() - 1) == 1 && tf.allFinite() &&
              tf.minCoeff() >= 0 && tf.maxCoeff() <= 1;
    for (Eigen::Index i = 1; ok && i < s.size(); ++i) ok = s(i) > s(i - 1);
    if (!ok)
      throw ParameterError("edge_error: curve_params (" + std::to_string(s.size()) +
                           ") must increase strictly from 0 to 1, with as many params (" + std::to_string(tf.size()) +
                           ") in [0, 1]");
  }
  const int k = static_cast<int>(points.rows()) - 1;
  const Eigen::MatrixX3d D =
      k >= 1 ? Eigen::MatrixX3d(k * (points.bottomRows(k) - points.topRows(k))) : Eigen::MatrixX3d::Zero(1, 3);
  Eigen::Index row = 0;
  for (int j = 0; j <= kSamples; ++j) {
    const double t = static_cast<double>(j) / kSamples;
    const Eigen::Vector3d c = curve.evaluate(t);
    if (!corrected || k < 1) {
      take((bezier_at(points, t) - c).norm());
      continue;
    }
    // A corrected curve: the distance from c(t) to its foot point on the fit, from the fit's
    // parameter interpolated between the rows' (Newton on (x(τ) − c)·x'(τ) with the Gauss–Newton
    // Hessian |x'|², within [0, 1]); never above the distance at that start.
    while (row + 2 < s.size() && s(row + 1) <= t) ++row;
    const double w = (t - s(row)) / (s(row + 1) - s(row));
    double tau = std::clamp(tf(row) + w * (tf(row + 1) - tf(row)), 0.0, 1.0);
    double best = (bezier_at(points, tau) - c).norm();
    for (int it = 0; it < 20; ++it) {
      const Eigen::Vector3d dx = bezier_at(D, tau);
      const double h = dx.squaredNorm();
      if (!(h > 0)) break;
      const double next = std::clamp(tau - (bezier_at(points, tau) - c).dot(dx) / h, 0.0, 1.0);
      const double dist = (bezier_at(points, next) - c).norm();
      if (!(dist < best)) break;
      best = dist;
      tau = next;
    }
    take(best);
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
