#pragma once
// Exact operations on B-spline curves and tensor-product B-spline nets (Sun–Zhu, B-spline Euler–Lagrange; the
// algorithms are the standard ones of Piegl–Tiller, "The NURBS Book", ch. 5):
//   - knot insertion (Boehm), one knot at a time, as a linear map on the control points;
//   - Bézier extraction: the Bernstein coefficients of every knot span, obtained by inserting
//     each knot of the domain up to multiplicity k;
//   - the B-spline control points of a polynomial (blossoming), used to represent a Bézier patch
//     exactly on any knot vector.
//
// Conventions: standard indexing (docs/errata.md, B-spline Euler–Lagrange). A curve of degree k over the knot vector K
// (length n + k + 1) has n control points, the rows of an n x d matrix; N_{i,k} has support
// [K_i, K_{i+k+1}]; the domain is [K_k, K_n]. Nets follow tensor/bspline_net.h (P_ij at row
// i*nv + j, i along u). Every operation is exact in exact arithmetic and uses convex
// combinations only (knot insertion) or de Casteljau steps (blossoming).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

#include "bezierpde/tensor/bspline_net.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

/// A curve after knot insertion: the new knot vector and the new control points.
struct KnotRefinement {
  std::vector<double> knots;
  Eigen::MatrixXd points;
};

/// Insert the knot t `times` times into the curve (degree k, knots K, control points P with
/// len(K) - k - 1 rows, any number of columns). Boehm's algorithm: the new points are
///   Q_i = a_i P_i + (1 - a_i) P_{i-1},  a_i = 1 if K_{i+k} <= t, 0 if K_i >= t,
///   else (t - K_i) / (K_{i+k} - K_i).
/// The curve is unchanged. Throws (core/errors.h): the knot checks of BSplineNet; SizeError if P
/// has the wrong row count; NonFiniteError for a non-finite t; ParameterError if t lies outside
/// the domain [K_k, K_n], times < 0, or the multiplicity of t would exceed k + 1.
KnotRefinement insert_knot(int k, const std::vector<double>& K, const Eigen::MatrixXd& P, double t, int times = 1);

/// The linear map of inserting all of `new_knots` (any order, repeats allowed): returns the
/// n' x n matrix T with Q = T * P, and writes the refined knot vector to *refined (if non-null).
Eigen::MatrixXd knot_insertion_matrix(int k, const std::vector<double>& K, const std::vector<double>& new_knots,
                                      std::vector<double>* refined = nullptr);

/// The net with the knots `u_knots` inserted along u and `v_knots` along v (same surface).
BSplineNet insert_knots(const BSplineNet& net, const std::vector<double>& u_knots, const std::vector<double>& v_knots);

/// Bézier extraction of one direction (degree k, knots K).
///   breaks: the distinct knot values of the domain, b_0 = K_k < b_1 < ... < b_S = K_n;
///   C[s]:   (k+1) x n matrix; C[s] * P are the Bernstein coefficients (degree k, local
///           parameter (t - b_s) / (b_{s+1} - b_s) in [0,1]) of the curve on [b_s, b_{s+1}].
///   first[s]: the first column of C[s] that can be non-zero; columns first[s] .. first[s]+k
///           (the basis functions living on the span) hold all of C[s]'s entries.
struct BezierExtraction {
  std::vector<double> breaks;
  std::vector<Eigen::MatrixXd> C;
  std::vector<int> first;
  int spans() const { return static_cast<int>(C.size()); }
  double width(int s) const { return breaks[static_cast<size_t>(s) + 1] - breaks[static_cast<size_t>(s)]; }
};
BezierExtraction bezier_extraction(int k, const std::vector<double>& K);

/// One knot span of a net as a Bézier patch: x(u,v) = net((u-u0)/(u1-u0), (v-v0)/(v1-v0)) on
/// [u0,u1] x [v0,v1].
struct BezierPatch {
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
  int su = 0, sv = 0;  ///< span indices along u and v
  TensorNet net;
};
/// Every non-empty span of the net as a degree-(p,q) Bézier patch, in the order su * Sv + sv.
std::vector<BezierPatch> bezier_patches(const BSplineNet& net);

/// The n x (d+1) matrix M whose row i holds the B-spline control point i (degree k, knots K) of
/// each Bernstein basis polynomial B_r^d((t - t0)/(t1 - t0)), d <= k: the polynomial with
/// Bernstein coefficients c on [t0, t1] has the B-spline control points M * c on the whole knot
/// vector. Computed by degree elevation and blossoming: P_i = blossom(K_{i+1}, ..., K_{i+k}).
/// Requires t0 < t1 (ParameterError) and 0 <= d <= k (DegreeError).
Eigen::MatrixXd polynomial_to_bspline_matrix(int d, double t0, double t1, int k, const std::vector<double>& K);

/// The B-spline net of degree (p, q) over the knots (U, V) that represents exactly the polynomial
/// patch x(u,v) = patch((u-u0)/(u1-u0), (v-v0)/(v1-v0)) (patch degree n <= p, m <= q).
BSplineNet bspline_from_bezier(const TensorNet& patch, double u0, double u1, double v0, double v1, int p, int q,
                               const std::vector<double>& U, const std::vector<double>& V);

}  // namespace bpde
