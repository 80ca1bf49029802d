#pragma once
// Boundary curves: the curves a user gives for the edges of a net (FORMATS.md "Boundary curves"),
// each a map c: [0,1] -> R^3, and their evaluation. boundaries/fit_boundary.h turns them into the
// boundary control points of a net at any degree.
//
// Every curve is parametrised by t in [0,1]:
//   bezier   c(t) = sum_i B_i^k(t) P_i, k = #points - 1 >= 1 (core/bernstein.h).
//   bspline  degree p, knots K (tensor/bspline_net.h checks), t mapped linearly onto the domain
//            [K_p, K_{len-p-1}].
//   samples  points q_0..q_M with parameters t_0 = 0 < t_1 < ... < t_M = 1: the given parameters
//            mapped affinely onto [0,1], or, when none are given, the normalised chord length.
//            Chord-length parameters are by default only the start of the fit: the fit corrects
//            them to the foot points on the fitted curve (SampleParameters::Corrected,
//            fit_boundary.h); SampleParameters::ChordLength keeps them.
//            evaluate() interpolates linearly between samples; the fit uses the samples only.
//   segment  c(t) = (1-t) a + t b (held as a degree-1 Bézier curve).
//   arc      c(t) = center + r (cos a e1 + sin a e2), a = a0 + t (a1 - a0) (angles in radians,
//            counter-clockwise about the unit normal N, right-handed: e2 = N x e1). e1 is the
//            reference direction projected onto the plane of the circle and normalised; the
//            default reference is (1,0,0), or (0,1,0) when |N_x| > 0.9.
//            The three-point form (p0, pm, p1) is the arc from p0 through pm to p1: its center is
//            the circumcenter, N = (pm - p0) x (p1 - pm) normalised, e1 = (p0 - center)/r, a0 = 0
//            and a1 in (0, 2π) the angle of p1; c(0) = p0 and c(1) = p1 exactly (the given points,
//            not the circle's rounding of them), so that a corner it shares with another edge's
//            given point is that point exactly.
//   helix    the arc about the axis N through `center`, rising by `pitch` per turn:
//            c(t) = center + r (cos a e1 + sin a e2) + (pitch a / 2π) N.
//   circle   the whole circle: the arc of angles 0 to 2π (reference as for arcs), c(1) = c(0)
//            exactly (a closed curve: the only curve of a loop, or one of several).
//   closed samples  samples whose last point is followed by the first again: the first point is
//            appended, so c(1) = c(0) exactly (chord-length or given parameters as above; given
//            parameters then need one more entry, the parameter of the closing point).
//   function any c(t) given as a C++ callable (the named reference boundaries; not a JSON form).
//
// The factories validate their input with the typed exceptions of core/errors.h (messages without
// a location; io/ prefixes the JSON path): DegreeError (a Bézier or B-spline curve of degree < 1),
// SizeError (too few points, wrong knot count), NonFiniteError (non-finite numbers),
// ParameterError (radius <= 0, a zero normal, a reference parallel to the normal, an empty angle
// range, collinear three points, samples whose parameters do not increase).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace bpde {

class BoundaryCurve {
 public:
  /// Most points of a B-spline curve or of samples (SizeError beyond): a fit costs O(points · n²)
  /// time and the least-squares table O(points · n) memory.
  static constexpr int kMaxPoints = 100000;

  struct Bezier {
    Eigen::MatrixX3d points;  ///< (k+1) x 3, k >= 1
  };
  struct BSpline {
    int degree = 1;
    std::vector<double> knots;
    Eigen::MatrixX3d points;  ///< (len(knots) - degree - 1) x 3
  };
  struct Samples {
    Eigen::MatrixX3d points;  ///< (M+1) x 3, M >= 1
    Eigen::VectorXd params;   ///< M+1 strictly increasing, first 0, last 1
    bool chord_length = false;  ///< params are the normalised chord length (none were given)
    /// The fit corrects the chord-length `params` to foot points (the default; fit_boundary.h).
    bool correct = false;
  };
  /// Arc and helix (pitch 0 for an arc).
  struct Arc {
    Eigen::Vector3d center, e1, e2, normal;
    double radius = 1, angle0 = 0, angle1 = 1, pitch = 0;
    bool helix = false;
    /// The three-point form's p0 and p1: c(0) and c(1) exactly.
    std::optional<Eigen::Vector3d> from, to;
  };
  struct Function {
    std::function<Eigen::Vector3d(double)> f;
  };

  static BoundaryCurve bezier(Eigen::MatrixX3d points);
  static BoundaryCurve bspline(int degree, std::vector<double> knots, Eigen::MatrixX3d points);
  /// How samples without parameters are parametrised: the normalised chord length, corrected
  /// by the fit to the foot points on the fitted curve (the default), or the chord length kept.
  enum class SampleParameters { Corrected, ChordLength };
  /// Samples with chord-length parameters (consecutive points must differ), corrected by the fit
  /// unless `parameters` is ChordLength.
  static BoundaryCurve samples(Eigen::MatrixX3d points, SampleParameters parameters = SampleParameters::Corrected);
  /// Samples with their parameters (strictly increasing, any range: mapped affinely onto [0,1]).
  static BoundaryCurve samples(Eigen::MatrixX3d points, const std::vector<double>& params);
  static BoundaryCurve segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
  static BoundaryCurve arc(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double radius, double angle0,
                           double angle1, const std::optional<Eigen::Vector3d>& reference = std::nullopt);
  static BoundaryCurve arc_through(const Eigen::Vector3d& p0, const Eigen::Vector3d& pm, const Eigen::Vector3d& p1);
  static BoundaryCurve helix(const Eigen::Vector3d& center, const Eigen::Vector3d& axis, double radius, double angle0,
                             double angle1, double pitch,
                             const std::optional<Eigen::Vector3d>& reference = std::nullopt);
  static BoundaryCurve function(std::function<Eigen::Vector3d(double)> f, std::string kind = "function");
  /// The whole circle (kind "circle"): ParameterError for radius <= 0 or a zero normal.
  static BoundaryCurve circle(const Eigen::Vector3d& center, const Eigen::Vector3d& normal, double radius,
                              const std::optional<Eigen::Vector3d>& reference = std::nullopt);
  /// Samples of a closed curve: the first point is appended as the last (above).
  static BoundaryCurve closed_samples(Eigen::MatrixX3d points,
                                      SampleParameters parameters = SampleParameters::Corrected);
  static BoundaryCurve closed_samples(Eigen::MatrixX3d points, const std::vector<double>& params);

  /// The piece t in [t0, t1] (0 <= t0 < t1 <= 1) as a curve of its own, parametrised by
  /// s = (t - t0)/(t1 - t0) in [0,1] and of the same form where the form allows: a Bézier curve by
  /// exact subdivision (de Casteljau), an arc, helix or circle by its angle range (kind "arc" or
  /// "helix"; c(0), c(1) exact where t0 = 0, t1 = 1), samples by the samples inside with the
  /// curve's points at t0 and t1 as the ends (their parameters mapped; chord-length samples stay
  /// chord-length and corrected alike), anything else as a function of the same kind.
  /// ParameterError unless 0 <= t0 < t1 <= 1.
  BoundaryCurve piece(double t0, double t1) const;

  /// "bezier", "bspline", "samples", "segment", "arc", "helix" or the function's kind.
  const std::string& kind() const { return kind_; }
  /// c(t) for t in [0,1] (clamped to it).
  Eigen::Vector3d evaluate(double t) const;
  Eigen::Vector3d start() const { return evaluate(0.0); }
  Eigen::Vector3d end() const { return evaluate(1.0); }
  /// The direction of the curve's tangent at t = 0 (at_end false) or t = 1, where the form gives it
  /// exactly: c'(t) of a Bézier curve (the first non-zero difference of its end points when c' = 0
  /// there), segment, B-spline, arc or helix; nullopt for samples and functions, whose tangent a fit
  /// only estimates. Not normalised; nullopt also when it vanishes (a curve that is one point, or
  /// a B-spline whose derivative is 0 at that end: then the fit estimates it like a sample's).
  std::optional<Eigen::Vector3d> exact_tangent(bool at_end) const;

  /// The form, for the fit (nullptr when it is another one; a segment is a Bézier curve).
  const Bezier* as_bezier() const { return std::get_if<Bezier>(&data_); }
  const Samples* as_samples() const { return std::get_if<Samples>(&data_); }

 private:
  using Data = std::variant<Bezier, BSpline, Samples, Arc, Function>;
  BoundaryCurve(Data d, std::string kind) : data_(std::move(d)), kind_(std::move(kind)) {}
  BoundaryCurve as_arc() const;  // a helix with its pitch dropped, named "arc"
  Data data_;
  std::string kind_;
};

}  // namespace bpde
