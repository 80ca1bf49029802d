#pragma once
// The boundary control points of a net at a given degree from boundary curves
// (boundaries/boundary_curves.h; FORMATS.md "Boundary curves"): C⁰ data from one curve per edge,
// C¹ data (boundary + adjacent ring) from a cross-boundary derivative field per edge as well.
//
// Edge order and direction: the edges run once around the boundary, each curve from the end of
// the previous one to the start of the next (c_e(1) = c_{e+1}(0), the last back to the first), in
// the corner order of FORMATS.md "Orientation" (counter-clockwise seen from +z makes x_u ^ x_v
// point to +z):
//   tensor (degree n, m), P_ij at index i(m+1)+j, i along u:
//     edge 0: v = 0, u from 0 to 1   (P_00 -> P_n0; points P_{s,0},   s = 0..n)
//     edge 1: u = 1, v from 0 to 1   (P_n0 -> P_nm; points P_{n,s},   s = 0..m)
//     edge 2: v = 1, u from 1 to 0   (P_nm -> P_0m; points P_{n-s,m}, s = 0..n)
//     edge 3: u = 0, v from 1 to 0   (P_0m -> P_00; points P_{0,m-s}, s = 0..m)
//   triangular (degree n, P_ijk of triangular/triangular_net.h, x(u,v) with w = 1-u-v;
//   corners P_00n = x(0,0), P_n00 = x(1,0), P_0n0 = x(0,1)):
//     edge 0: v = 0, x(t, 0)       (P_00n -> P_n00; points P_{s,0,n-s})
//     edge 1: w = 0, x(1-t, t)     (P_n00 -> P_0n0; points P_{n-s,s,0})
//     edge 2: u = 0, x(0, 1-t)     (P_0n0 -> P_00n; points P_{0,n-s,s})
//
// Fit of one curve at degree n (fit_edge):
//   - a Bézier curve of degree k <= n, or a segment: exact degree elevation (method "elevation");
//   - samples: least squares over the samples at their parameters with the end points fixed to
//     the first and last sample ("least-squares"; needs at least n+1 samples that determine the
//     polynomial: SizeError / ParameterError otherwise). Samples given without parameters start
//     from the normalised chord length, which is then corrected (unless asked not to, or with C¹
//     data): the orthogonal least-squares fit of fit_samples.h, each parameter at the foot point
//     of its sample on the fitted curve. The chord length follows the arc length, a poor
//     polynomial parameter where the speed varies (docs/boundaries.md, "Samples without
//     parameters": 1.6e-3 against 1.5e-10 at n = 12 on a wavy curve);
//   - any other curve: interpolation at the n+1 Chebyshev–Lobatto nodes t_k = (1 - cos(πk/n))/2
//     ("interpolation", the default; spectral convergence for analytic curves, docs/boundaries.md),
//     or least squares over 8n+1 uniform parameters with the end points fixed ("least-squares"),
//     or the orthogonal least squares of fit_samples.h over its points at the 4n+1
//     Chebyshev–Lobatto nodes ("geometric": each node's parameter on the fit moves to the foot
//     point of its curve point, from the nodes themselves: the degree ladder of fit_samples.h,
//     then 500 iterations at degree n with first damping 1e-12). The geometric fit follows the curve,
//     not its parametrisation: on a 120° arc 1.4e-8 from the circle at n = 5 where the
//     interpolant is 1.1e-4 away, on a catenoid's edge 2.0e-8 against 3.6e-4 at n = 6
//     (docs/boundaries.md, "Geometric fits"; cost: 1.4 ms at n = 8, 0.11 s at n = 32 per edge,
//     against 0.04 ms for the interpolant). For the functionals that do not depend on the
//     boundary's parametrisation (area, mean curvature); the Dirichlet functional's result does.
//     Not with C¹ data (the tangent field is given in the edge's parameter: interpolation then),
//     and where the correction does not lower the sum of squares at the nodes, the interpolant.
// Corners: the edges must meet, |c_e(1) - c_{e+1}(0)| <= corner_tolerance * max(1, d) with d the
// diagonal of the bounding box of the curves' end points (ParameterError naming the two edges and
// the gap otherwise). The corner control point is the mean of the two fitted end points, shared
// exactly by both edges. Every fit keeps the curve's end points c(0), c(1) as its end control
// points, so where both edges end at the same given point (a segment's, a Bézier curve's or the
// samples' end point, a three-point arc's p0 or p1) the corner is that point bit for bit.
//
// C¹ data: tangent field T_e(t) along edge e (same parameter t as the edge) = the derivative of
// the surface across the edge, into the domain:
//   tensor: edge 0: x_v, edge 1: -x_u, edge 2: -x_v, edge 3: x_u (at the edge point of parameter t);
//   triangular: the derivative towards the opposite corner C from the edge's first corner A,
//     d/dε x(q + ε(C - A)) in (u,v): edge 0: x_v, edge 1: -x_u, edge 2: x_u - x_v.
// It is fitted (as above) at the degree of the cross derivative along the edge (tensor: the edge's
// degree; triangular: n - 1), giving coefficients D_s, and the adjacent ring is
//   tensor edge 0: P_{s,1} = P_{s,0} + D_s / m (likewise for the others with 1/n or 1/m),
//   triangular edge 0: P_{s,1,n-1-s} = P_{s,0,n-s} + D_s / n (likewise, cyclically).
// An adjacent point that is itself a boundary point is left to the boundary curves; one that two
// edges define (the corner "twist" points) is the mean of both. The reported tangent error is
// measured on the result, so that inconsistent corner data show up there.
//
// Corners where the curve is smooth (C⁰ data only): cutting a smooth closed curve into edges puts
// corners where the curve has none, and two separate fits then meet at 180° only up to their
// errors. Where that angle is slightly reflex on the side the surface spans, every patch with these
// edges turns over next to the corner (docs/boundaries.md, "Corners where the curve is smooth").
// So a corner is joined G¹ when it is smooth:
//   - where both curves give their end tangents exactly (BoundaryCurve::exact_tangent: Bézier,
//     segment, B-spline, arc, helix): when those agree in direction to kExactSmoothRadians;
//   - otherwise: when the data's tangents turn by at most smooth_corner_angle degrees.
//   smooth_corner_angle 0 keeps every corner as fitted (both tiers).
//     The data's tangent is the exact one where the form gives it; for samples the derivative of
//     the cubic through the four samples nearest the corner (at their parameters), for a function
//     that of the cubic through c at t = 0, 1e-3, 2e-3, 3e-3 (or from t = 1). Both are independent
//     of the net's degree: on the wavy curve of FitBoundary.CornersWhereTheCurveIsSmoothAreJoinedG1
//     (61 samples an edge) the samples' cubics turn by 0.01°–0.03° at the corners, its fits at
//     n = 5 by 1.5°–3.8°.
// The common direction d: the exact tangent where one curve gives it (the mean of the two unit
// tangents where both do); where both are estimated, the direction in the plane of the two fitted
// end legs that minimises the two edges' summed least squares (golden section on its angle over
// [-turn, 2 turn] from the incoming leg, two sweeps over the corners). Each edge at a joined corner
// is then fitted again with its end leg along d, P_1 = P_0 + a d (or P_{k-1} = P_k - b d), a, b
// free: the same least squares as its fit (samples at the fit's parameters, "least-squares" at its
// 8k+1 parameters), "interpolation" and "geometric" as least squares at the 4k+1
// Chebyshev–Lobatto nodes (a geometric edge restarts there, not from its own fit), all
// solved by QR (the Bernstein matrix reduced to its triangle, then the constrained problem on it);
// corrected samples then have their parameters corrected again under the constraint
// (fit_samples_orthogonal_constrained), and so do the rows of every other curve (its points at
// those 4k+1 or 8k+1 parameters, taken as samples: the orthogonal least squares, each row's
// parameter on the fit moved to the foot point of its curve point; 500 iterations, first damping
// 1e-12, each end leg held within ×2 of the least squares' length, fit_boundary.cpp). With its end
// legs held, the least squares at the curve's own parameters errs to one side of the curve (the
// circle's arcs: a mean radial error of 1.2e-5 at n = 5, where the interpolant's oscillates about
// 0 with mean 9e-8); the corrected fit spends the freedom of the parametrisation on the distance
// instead (reported with `parameters` "corrected" and the iterations as `corrections`). An
// exactly elevated Bézier curve has its leg projected onto d instead (it moves by at most
// |leg| kExactSmoothRadians; a leg of length 0 cannot be projected: the corner is kept). A curve
// refitted so is reported as "geometric" whatever its own method, and every corrected edge adds
// the iterations of the constrained correction to `corrections`. A corner is kept as fitted when
// an edge at it has degree < 3, the constrained problem is numerically rank deficient (QR
// threshold 1e-12; seen at degree 64, where the plain fit's corners are already smooth to
// rounding) or the constrained fit turns that corner's leg
// around (a or b <= 0); the edges are then fitted again without it (the searched directions are
// not searched again).
// Cost: the search is O(k³) per trial; corrected samples pay one more constrained correction
// (measured on four edges of 2001 samples: 3.2 s against 1.8 s kept at n = 8, 7.2 s against
// 4.5 s at n = 32); a curve's correction runs on 4k+1 rows (the circle's three arcs: 2 ms at
// n = 8, 31 ms at n = 32). The report gives
// each edge's end corner as "g1" or "kept" and its turning angle before the join.
// What the join costs or gains: on that wavy curve given as samples the largest edge error
// changes by ×0.8 … ×1.45 (n = 5 … 12); given as functions, it falls ×3 … ×4.5 against the plain
// interpolants (n = 6, 9, 12), though one edge alone may lose (×15 at n = 12 on an edge whose
// plain error was far below the others'). The circle's arcs come ×63 … ×9e4 nearer the circle
// than the interpolants (n = 4 … 8), and the area of its CMC cap with them (docs/boundaries.md,
// "Corners where the curve is smooth", and FitBoundary.JoinedCurvesAreFittedGeometrically).
//
// The other control points are zero: every solver determines them (FORMATS.md "Jobs").
// Errors (per edge): the maximum over 257 uniform parameters (samples: over the samples) of
// |x_e(t) - c_e(t)|, with x_e the net's boundary curve: the parametric distance, an upper bound
// of the geometric one. A curve corrected at a joined corner (`parameters` "corrected"): the
// geometric distance instead, the maximum over the 257 points c_e(t) of their distance to the foot
// point on x_e (from the fit's parameter interpolated between its rows', Newton on
// (x_e(τ) − c)·x_e'(τ) while the distance falls). It is one-sided, from the curve to the fit: a
// loop of the fit between foot points would not show (the correction starts at the curve's own
// parameters and only lowers the distances at its rows, 4k+1 of them for degree k). Tangent
// errors likewise with the net's cross derivative, always parametric.
#include <optional>
#include <string>
#include <vector>

#include "bezierpde/boundaries/boundary_curves.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

enum class FitMethod { Interpolation, LeastSquares, Geometric };

/// Where both curves give their tangents exactly, a corner is smooth when they agree in direction
/// to this many radians (input typed to 7 digits stays within it).
inline constexpr double kExactSmoothRadians = 1e-6;

/// "interpolation", "least-squares" or "geometric".
std::string to_string(FitMethod m);

/// The boundary of a net as curves, in the edge order above; `tangents` is empty (C⁰ data) or
/// holds one field per edge (C¹ data).
struct BoundaryData {
  std::vector<BoundaryCurve> edges;
  std::vector<BoundaryCurve> tangents;
};

struct BoundaryFitOptions {
  FitMethod method = FitMethod::Interpolation;  ///< for curves that are neither low-degree Bézier nor samples
  double corner_tolerance = 1e-8;               ///< relative gap allowed at the corners, > 0
  /// Corners whose estimated tangents turn by at most this many degrees are joined G¹ (above);
  /// 0 keeps every corner as fitted. In [0, 90].
  double smooth_corner_angle = 2.0;
  /// ParameterError unless corner_tolerance is finite and > 0 and smooth_corner_angle in [0, 90].
  void validate() const;
};

/// How one edge was fitted.
struct EdgeFit {
  int edge = 0;
  std::string curve;   ///< the curve's kind
  std::string method;  ///< "elevation", "interpolation", "least-squares" or "geometric"
  double max_error = 0;
  /// C¹ data: the tangent field's kind, method and error on the result.
  std::optional<std::string> tangent_curve, tangent_method;
  std::optional<double> tangent_max_error;
  /// Samples: how their parameters were set ("given", "chord-length", "corrected"); a geometric
  /// curve fit: "corrected". With the iterations of the correction.
  std::optional<std::string> parameters;
  std::optional<int> corrections;
  /// The corner at the edge's end (where the next edge starts): "g1" when joined, "kept" when not
  /// (always with C¹ data), and the angle in degrees by which the fitted edges' tangents turned
  /// there before the join (0 is a smooth continuation).
  std::optional<std::string> end_corner;
  std::optional<double> end_corner_turn;
};

/// One curve at degree n >= 1: its Bernstein coefficients ((n+1) x 3) and the method used.
struct CurveFit {
  Eigen::MatrixX3d points;
  std::string method;
  /// Samples: the parameters of the fit (as given, chord length, or corrected); a geometric curve
  /// fit: the parameters on the fit of its rows (`curve_params`); empty otherwise.
  Eigen::VectorXd params;
  /// Samples: "given", "chord-length" or "corrected"; a geometric curve fit ("geometric", or
  /// refitted at a joined corner): "corrected"; empty otherwise.
  std::string parameters;
  int corrections = 0;  ///< "corrected": the iterations of the correction taken
  /// A geometric curve fit: the curve's parameters of its rows (4n+1 Chebyshev–Lobatto nodes, or
  /// the rows of the join's refit), strictly increasing from 0 to 1, whose foot points on the fit
  /// are at `params` (same size); empty otherwise.
  Eigen::VectorXd curve_params;
};
/// `correct` false keeps chord-length parameters of samples uncorrected and a "geometric" fit
/// interpolating (C¹ data: the tangent field is given in the edge's parameter).
CurveFit fit_edge(const BoundaryCurve& curve, int n, FitMethod method = FitMethod::Interpolation, bool correct = true);

/// The maximum distance between the Bézier curve `points` and the curve (see above; samples at
/// their own parameters).
double edge_error(const BoundaryCurve& curve, const Eigen::MatrixX3d& points);
/// The same for a fit, samples at the fit's parameters (the corrected ones where corrected); a
/// geometric curve fit (`curve_params` set): the geometric distance of Errors above. Throws
/// ParameterError when curve_params and params do not correspond (sizes, order, range). A NaN
/// anywhere gives NaN, never a smaller number.
double edge_error(const BoundaryCurve& curve, const CurveFit& fit);

template <class NetT>
struct BoundaryFit {
  NetT net;
  std::vector<EdgeFit> edges;
};

/// The tensor net of degree (n, m) with the fitted boundary (and adjacent ring with tangents).
/// Throws SizeError (not 4 edges, or tangents for some edges only), DegreeError (degrees outside
/// 1..kMaxDegree; tangents with n or m < 2), ParameterError (corners that do not meet, options),
/// NonFiniteError (a fit that overflows), and the fit's errors.
BoundaryFit<TensorNet> fit_tensor_boundary(int n, int m, const BoundaryData& data,
                                           const BoundaryFitOptions& options = {});

/// The triangular net of degree n likewise (3 edges; tangents need n >= 2).
BoundaryFit<TriangularNet> fit_triangular_boundary(int n, const BoundaryData& data,
                                                   const BoundaryFitOptions& options = {});

}  // namespace bpde
