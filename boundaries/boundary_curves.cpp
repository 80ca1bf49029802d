#include "bezierpde/boundaries/boundary_curves.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/tensor/bspline_net.h"

namespace bpde {
namespace {

void require_finite(const Eigen::MatrixX3d& P, const char* what) {
  if (!P.allFinite()) throw NonFiniteError(std::string(what) + ": non-finite coordinates");
}
void require_finite(const Eigen::Vector3d& p, const char* what) {
  if (!p.allFinite()) throw NonFiniteError(std::string(what) + ": non-finite coordinates");
}
void require_finite(double x, const char* what) {
  if (!std::isfinite(x)) throw NonFiniteError(std::string(what) + ": not a finite number");
}

// The unit normal and the in-plane frame (e1, e2 = N x e1) of an arc or helix.
void frame(const Eigen::Vector3d& normal, const std::optional<Eigen::Vector3d>& reference, Eigen::Vector3d& N,
           Eigen::Vector3d& e1, Eigen::Vector3d& e2) {
  require_finite(normal, "normal");
  const double len = normal.norm();
  if (!(len > 0) || !std::isfinite(len)) throw ParameterError("normal: the zero vector has no direction");
  N = normal / len;
  Eigen::Vector3d r;
  if (reference) {
    require_finite(*reference, "reference");
    r = *reference;
  } else {
    r = std::abs(N.x()) > 0.9 ? Eigen::Vector3d(0, 1, 0) : Eigen::Vector3d(1, 0, 0);
  }
  const Eigen::Vector3d p = r - r.dot(N) * N;
  const double pl = p.norm();
  if (!(pl > 1e-12 * r.norm()) || !std::isfinite(pl))
    throw ParameterError("reference: parallel to the normal (or zero), it gives no direction in the plane");
  e1 = p / pl;
  e2 = N.cross(e1);
}

void require_at_most(Eigen::Index rows, const char* what) {
  if (rows > BoundaryCurve::kMaxPoints)
    throw SizeError(std::string(what) + ": at most " + std::to_string(BoundaryCurve::kMaxPoints) + " points, got " +
                    std::to_string(rows));
}

}  // namespace

BoundaryCurve BoundaryCurve::bezier(Eigen::MatrixX3d points) {
  if (points.rows() < 2)
    throw DegreeError("a Bézier curve needs at least 2 points (degree >= 1), got " + std::to_string(points.rows()));
  if (points.rows() - 1 > kMaxDegree)
    throw DegreeError("a Bézier curve has degree at most " + std::to_string(kMaxDegree) + ", got " +
                      std::to_string(points.rows() - 1));
  require_finite(points, "points");
  return BoundaryCurve(Bezier{std::move(points)}, "bezier");
}

BoundaryCurve BoundaryCurve::bspline(int degree, std::vector<double> knots, Eigen::MatrixX3d points) {
  require_at_most(points.rows(), "a B-spline curve");
  BSplineNet::validate_knots(degree, knots, "curve");
  const Eigen::Index count = static_cast<Eigen::Index>(knots.size()) - degree - 1;
  if (points.rows() != count)
    throw SizeError("a B-spline curve of degree " + std::to_string(degree) + " with " + std::to_string(knots.size()) +
                    " knots has " + std::to_string(count) + " points, got " + std::to_string(points.rows()));
  require_finite(points, "points");
  return BoundaryCurve(BSpline{degree, std::move(knots), std::move(points)}, "bspline");
}

BoundaryCurve BoundaryCurve::samples(Eigen::MatrixX3d points, SampleParameters parameters) {
  if (points.rows() < 2) throw SizeError("samples: at least 2 points, got " + std::to_string(points.rows()));
  require_at_most(points.rows(), "samples");
  require_finite(points, "points");
  std::vector<double> s(static_cast<size_t>(points.rows()), 0.0);
  for (Eigen::Index i = 1; i < points.rows(); ++i) {
    const double d = (points.row(i) - points.row(i - 1)).norm();
    if (!(d > 0))
      throw ParameterError("samples: points " + std::to_string(i - 1) + " and " + std::to_string(i) +
                           " coincide (chord-length parameters must increase; give \"parameters\")");
    s[static_cast<size_t>(i)] = s[static_cast<size_t>(i - 1)] + d;
  }
  BoundaryCurve c = samples(std::move(points), s);
  std::get<Samples>(c.data_).chord_length = true;
  std::get<Samples>(c.data_).correct = parameters == SampleParameters::Corrected;
  return c;
}

BoundaryCurve BoundaryCurve::samples(Eigen::MatrixX3d points, const std::vector<double>& params) {
  if (points.rows() < 2) throw SizeError("samples: at least 2 points, got " + std::to_string(points.rows()));
  require_at_most(points.rows(), "samples");
  if (static_cast<Eigen::Index>(params.size()) != points.rows())
    throw SizeError("samples: " + std::to_string(points.rows()) + " points but " + std::to_string(params.size()) +
                    " parameters");
  require_finite(points, "points");
  for (double p : params) require_finite(p, "parameters");
  const double a = params.front(), b = params.back();
  Eigen::VectorXd t(points.rows());
  for (size_t i = 0; i < params.size(); ++i) {
    if (i > 0 && !(params[i] > params[i - 1]))
      throw ParameterError("samples: parameters must increase strictly, but parameter " + std::to_string(i) +
                           " is not above parameter " + std::to_string(i - 1));
    t(static_cast<Eigen::Index>(i)) = (params[i] - a) / (b - a);
  }
  if (!t.allFinite()) throw NonFiniteError("samples: parameters overflow");
  t(0) = 0.0;
  t(t.size() - 1) = 1.0;
  return BoundaryCurve(Samples{std::move(points), std::move(t)}, "samples");
}

BoundaryCurve BoundaryCurve::segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  require_finite(a, "from");
  require_finite(b, "to");
  // A degree-1 Bézier curve: fitted by exact elevation.
  Eigen::MatrixX3d P(2, 3);
  P.row(0) = a.transpose();
  P.row(1) = b.transpose();
  return BoundaryCurve(Bezier{P}, "segment");
}

BoundaryCurve BoundaryCurve::arc(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double radius,
                                 double angle0, double angle1, const std::optional<Eigen::Vector3d>& reference) {
  return helix(center, normal, radius, angle0, angle1, 0.0, reference).as_arc();
}

BoundaryCurve BoundaryCurve::helix(const Eigen::Vector3d& center, const Eigen::Vector3d& axis, double radius,
                                   double angle0, double angle1, double pitch,
                                   const std::optional<Eigen::Vector3d>& reference) {
  require_finite(center, "center");
  require_finite(radius, "radius");
  require_finite(angle0, "angles");
  require_finite(angle1, "angles");
  require_finite(pitch, "pitch");
  if (!(radius > 0)) throw ParameterError("radius: must be > 0, got " + std::to_string(radius));
  if (!(angle1 != angle0)) throw ParameterError("angles: the two angles are equal (an empty arc)");
  Arc a;
  frame(axis, reference, a.normal, a.e1, a.e2);
  a.center = center;
  a.radius = radius;
  a.angle0 = angle0;
  a.angle1 = angle1;
  a.pitch = pitch;
  a.helix = true;
  return BoundaryCurve(a, "helix");
}

BoundaryCurve BoundaryCurve::as_arc() const {
  Arc a = std::get<Arc>(data_);
  a.helix = false;
  a.pitch = 0.0;
  return BoundaryCurve(a, "arc");
}

BoundaryCurve BoundaryCurve::arc_through(const Eigen::Vector3d& p0, const Eigen::Vector3d& pm,
                                         const Eigen::Vector3d& p1) {
  require_finite(p0, "through");
  require_finite(pm, "through");
  require_finite(p1, "through");
  // Circumcenter of (p0, pm, p1): with a = p0 - p1, b = pm - p1,
  //   center = p1 + ((|a|² b - |b|² a) x (a x b)) / (2 |a x b|²).
  const Eigen::Vector3d a = p0 - p1, b = pm - p1;
  const Eigen::Vector3d axb = a.cross(b);
  const Eigen::Vector3d d0 = pm - p0, d1 = p1 - pm;
  const Eigen::Vector3d n = d0.cross(d1);
  if (!(n.norm() > 1e-12 * d0.norm() * d1.norm()) || !std::isfinite(n.norm()))
    throw ParameterError("through: the three points are collinear (or coincide): no circle through them");
  const Eigen::Vector3d center = p1 + (a.squaredNorm() * b - b.squaredNorm() * a).cross(axb) / (2 * axb.squaredNorm());
  const double r = (p0 - center).norm();
  Arc arc;
  arc.normal = n.normalized();
  arc.center = center;
  arc.radius = r;
  arc.e1 = (p0 - center) / r;
  arc.e2 = arc.normal.cross(arc.e1);
  const Eigen::Vector3d q = p1 - center;
  double a1 = std::atan2(q.dot(arc.e2), q.dot(arc.e1));
  if (a1 <= 0) a1 += 2 * std::numbers::pi;
  arc.angle0 = 0.0;
  arc.angle1 = a1;
  arc.from = p0;
  arc.to = p1;
  if (!arc.center.allFinite() || !std::isfinite(r) || !(r > 0))
    throw NonFiniteError("through: the circle through the three points overflows");
  return BoundaryCurve(arc, "arc");
}

BoundaryCurve BoundaryCurve::function(std::function<Eigen::Vector3d(double)> f, std::string kind) {
  return BoundaryCurve(Function{std::move(f)}, std::move(kind));
}

BoundaryCurve BoundaryCurve::circle(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double radius,
                                    const std::optional<Eigen::Vector3d>& reference) {
  BoundaryCurve c = arc(center, normal, radius, 0.0, 2 * std::numbers::pi, reference);
  Arc& a = std::get<Arc>(c.data_);
  a.from = c.evaluate(0.0);
  a.to = a.from;
  c.kind_ = "circle";
  return c;
}

BoundaryCurve BoundaryCurve::closed_samples(Eigen::MatrixX3d points, SampleParameters parameters) {
  if (points.rows() < 2) throw SizeError("samples: at least 2 points, got " + std::to_string(points.rows()));
  Eigen::MatrixX3d closed(points.rows() + 1, 3);
  closed << points, points.row(0);
  return samples(std::move(closed), parameters);
}

BoundaryCurve BoundaryCurve::closed_samples(Eigen::MatrixX3d points, const std::vector<double>& params) {
  if (points.rows() < 2) throw SizeError("samples: at least 2 points, got " + std::to_string(points.rows()));
  Eigen::MatrixX3d closed(points.rows() + 1, 3);
  closed << points, points.row(0);
  return samples(std::move(closed), params);
}

BoundaryCurve BoundaryCurve::piece(double t0, double t1) const {
  if (!(t0 >= 0 && t0 < t1 && t1 <= 1)) throw ParameterError("a curve piece needs 0 <= t0 < t1 <= 1");
  if (const auto* b = std::get_if<Bezier>(&data_)) {
    // blossom rows (t0^(k-i), t1^i) by de Casteljau on the control points
    const int k = static_cast<int>(b->points.rows()) - 1;
    Eigen::MatrixX3d P(k + 1, 3);
    for (int i = 0; i <= k; ++i) {
      Eigen::MatrixX3d Q = b->points;
      for (int d = k; d >= 1; --d) {
        const double t = (k - d) < k - i ? t0 : t1;
        for (int j = 0; j < d; ++j) Q.row(j) = (1 - t) * Q.row(j) + t * Q.row(j + 1);
      }
      P.row(i) = Q.row(0);
    }
    if (t0 == 0) P.row(0) = b->points.row(0);
    if (t1 == 1) P.row(k) = b->points.row(k);
    return BoundaryCurve(Bezier{P}, kind_ == "segment" ? "segment" : "bezier");
  }
  if (const auto* a = std::get_if<Arc>(&data_)) {
    Arc p = *a;
    p.angle0 = a->angle0 + t0 * (a->angle1 - a->angle0);
    p.angle1 = t1 == 1 ? a->angle1 : a->angle0 + t1 * (a->angle1 - a->angle0);
    p.from = t0 == 0 ? a->from : std::nullopt;
    p.to = t1 == 1 ? a->to : std::nullopt;
    return BoundaryCurve(p, a->helix ? "helix" : "arc");
  }
  if (const auto* s = std::get_if<Samples>(&data_)) {
    std::vector<Eigen::Vector3d> pts{evaluate(t0)};
    std::vector<double> par{0.0};
    for (Eigen::Index i = 0; i < s->params.size(); ++i)
      if (s->params(i) > t0 && s->params(i) < t1) {
        pts.push_back(s->points.row(i).transpose());
        par.push_back((s->params(i) - t0) / (t1 - t0));
      }
    pts.push_back(evaluate(t1));
    par.push_back(1.0);
    Samples q;
    q.points.resize(static_cast<Eigen::Index>(pts.size()), 3);
    q.params.resize(static_cast<Eigen::Index>(par.size()));
    for (size_t i = 0; i < pts.size(); ++i) {
      q.points.row(static_cast<Eigen::Index>(i)) = pts[i].transpose();
      q.params(static_cast<Eigen::Index>(i)) = par[i];
    }
    q.chord_length = s->chord_length;
    q.correct = s->correct;
    return BoundaryCurve(q, "samples");
  }
  const BoundaryCurve whole = *this;
  return BoundaryCurve(Function{[whole, t0, t1](double t) { return whole.evaluate(t0 + t * (t1 - t0)); }}, kind_);
}

Eigen::Vector3d BoundaryCurve::evaluate(double t) const {
  t = std::clamp(t, 0.0, 1.0);
  if (const auto* b = std::get_if<Bezier>(&data_)) {
    const int k = static_cast<int>(b->points.rows()) - 1;
    std::vector<double> B(static_cast<size_t>(k + 1));
    bernstein_values(k, t, B.data());
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int i = 0; i <= k; ++i) x += B[static_cast<size_t>(i)] * b->points.row(i).transpose();
    return x;
  }
  if (const auto* s = std::get_if<BSpline>(&data_)) {
    const int p = s->degree;
    const size_t count = s->knots.size() - static_cast<size_t>(p) - 1;
    const double u0 = s->knots[static_cast<size_t>(p)], u1 = s->knots[count];
    Eigen::VectorXd u(1);
    u(0) = t == 1.0 ? u1 : u0 + t * (u1 - u0);
    const Eigen::MatrixXd N = BSplineNet::basis_table(p, s->knots, u, 0);
    return (N.row(0) * s->points).transpose();
  }
  if (const auto* s = std::get_if<Samples>(&data_)) {
    const Eigen::VectorXd& T = s->params;
    const auto it = std::upper_bound(T.data(), T.data() + T.size(), t);
    const Eigen::Index i = std::clamp<Eigen::Index>(it - T.data(), 1, T.size() - 1);
    const double w = (t - T(i - 1)) / (T(i) - T(i - 1));
    return ((1 - w) * s->points.row(i - 1) + w * s->points.row(i)).transpose();
  }
  if (const auto* a = std::get_if<Arc>(&data_)) {
    if (t == 0.0 && a->from) return *a->from;
    if (t == 1.0 && a->to) return *a->to;
    const double ang = t == 1.0 ? a->angle1 : a->angle0 + t * (a->angle1 - a->angle0);
    Eigen::Vector3d x = a->center + a->radius * (std::cos(ang) * a->e1 + std::sin(ang) * a->e2);
    if (a->helix) x += (a->pitch * ang / (2 * std::numbers::pi)) * a->normal;
    return x;
  }
  return std::get<Function>(data_).f(t);
}

std::optional<Eigen::Vector3d> BoundaryCurve::exact_tangent(bool at_end) const {
  std::optional<Eigen::Vector3d> d;
  if (const auto* b = std::get_if<Bezier>(&data_)) {
    // c'(0) = k (P_1 - P_0); where it vanishes the direction is that of the first non-zero
    // difference P_j - P_0 (c(t) - c(0) = C(k,j) t^j (P_j - P_0) + O(t^{j+1})).
    const Eigen::Index k = b->points.rows() - 1;
    const Eigen::Index end = at_end ? k : 0, step = at_end ? -1 : 1;
    for (Eigen::Index j = 1; j <= k && !d; ++j) {
      const Eigen::Vector3d diff = (b->points.row(end + step * j) - b->points.row(end)).transpose();
      if (diff.squaredNorm() > 0) d = at_end ? Eigen::Vector3d(-diff) : diff;
    }
  } else if (const auto* s = std::get_if<BSpline>(&data_)) {
    const size_t count = s->knots.size() - static_cast<size_t>(s->degree) - 1;
    Eigen::VectorXd u(1);
    u(0) = at_end ? s->knots[count] : s->knots[static_cast<size_t>(s->degree)];
    const Eigen::MatrixXd N = BSplineNet::basis_table(s->degree, s->knots, u, 1);
    d = (N.row(0) * s->points).transpose();
  } else if (const auto* a = std::get_if<Arc>(&data_)) {
    const double ang = at_end ? a->angle1 : a->angle0, da = a->angle1 - a->angle0;
    Eigen::Vector3d x = a->radius * da * (-std::sin(ang) * a->e1 + std::cos(ang) * a->e2);
    if (a->helix) x += (a->pitch * da / (2 * std::numbers::pi)) * a->normal;
    d = x;
  }
  if (d && !(d->allFinite() && d->squaredNorm() > 0)) d.reset();
  return d;
}

}  // namespace bpde
