#include "bezierpde/tensor/bspline_ops.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

int count_of(int k, const std::vector<double>& K) { return static_cast<int>(K.size()) - k - 1; }

int multiplicity(const std::vector<double>& K, double t) { return static_cast<int>(std::count(K.begin(), K.end(), t)); }

// One insertion of t (already validated) into knots K and rows P; returns the new points and
// updates K in place.
Eigen::MatrixXd insert_once(int k, std::vector<double>& K, const Eigen::MatrixXd& P, double t) {
  const int n = static_cast<int>(P.rows());
  Eigen::MatrixXd Q(n + 1, P.cols());
  for (int i = 0; i <= n; ++i) {
    const double Ki = K[static_cast<size_t>(i)], Kik = K[static_cast<size_t>(i + k)];
    double a;
    if (Kik <= t)
      a = 1.0;
    else if (Ki >= t)
      a = 0.0;
    else
      a = (t - Ki) / (Kik - Ki);
    if (a == 1.0)
      Q.row(i) = P.row(i);  // i < n is guaranteed: K_{n+k} > t would fail for i = n (t <= K_n)
    else if (a == 0.0)
      Q.row(i) = P.row(i - 1);  // i > 0 is guaranteed: K_k <= t gives a = 1 at i = 0
    else
      Q.row(i) = a * P.row(i) + (1.0 - a) * P.row(i - 1);
  }
  K.insert(std::upper_bound(K.begin(), K.end(), t), t);
  return Q;
}

void check_insertion(int k, const std::vector<double>& K, double t, int times) {
  if (!std::isfinite(t)) throw NonFiniteError("knot insertion: the knot to insert is not finite");
  if (times < 0) throw ParameterError("knot insertion: times must be >= 0");
  const int n = count_of(k, K);
  const double lo = K[static_cast<size_t>(k)], hi = K[static_cast<size_t>(n)];
  if (t < lo || t > hi)
    throw ParameterError("knot insertion: t = " + std::to_string(t) + " lies outside the domain [" +
                         std::to_string(lo) + ", " + std::to_string(hi) + "]");
  if (multiplicity(K, t) + times > k + 1)
    throw ParameterError("knot insertion: inserting " + std::to_string(t) + " " + std::to_string(times) +
                         " times would give multiplicity > degree + 1 = " + std::to_string(k + 1));
}

}  // namespace

KnotRefinement insert_knot(int k, const std::vector<double>& K, const Eigen::MatrixXd& P, double t, int times) {
  BSplineNet::validate_knots(k, K, "of the curve");
  if (P.rows() != count_of(k, K))
    throw SizeError("knot insertion: " + std::to_string(K.size()) + " knots of degree " + std::to_string(k) + " need " +
                    std::to_string(count_of(k, K)) + " control points, got " + std::to_string(P.rows()));
  if (!P.allFinite()) throw NonFiniteError("knot insertion: a control point is not finite");
  check_insertion(k, K, t, times);
  KnotRefinement out{K, P};
  for (int r = 0; r < times; ++r) out.points = insert_once(k, out.knots, out.points, t);
  return out;
}

Eigen::MatrixXd knot_insertion_matrix(int k, const std::vector<double>& K, const std::vector<double>& new_knots,
                                      std::vector<double>* refined) {
  BSplineNet::validate_knots(k, K, "of the curve");
  std::vector<double> knots = K;
  Eigen::MatrixXd T = Eigen::MatrixXd::Identity(count_of(k, K), count_of(k, K));
  for (double t : new_knots) {
    check_insertion(k, knots, t, 1);
    T = insert_once(k, knots, T, t);
  }
  if (refined) *refined = std::move(knots);
  return T;
}

BSplineNet insert_knots(const BSplineNet& net, const std::vector<double>& u_knots, const std::vector<double>& v_knots) {
  std::vector<double> U, V;
  const Eigen::MatrixXd Tu = knot_insertion_matrix(net.p(), net.knots_u(), u_knots, &U);
  const Eigen::MatrixXd Tv = knot_insertion_matrix(net.q(), net.knots_v(), v_knots, &V);
  const int nu = static_cast<int>(Tu.rows()), nv = static_cast<int>(Tv.rows());
  Eigen::MatrixX3d out(nu * nv, 3);
  using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  for (int c = 0; c < 3; ++c) {
    RowMat Pc(net.nu(), net.nv());
    for (int i = 0; i < net.nu(); ++i)
      for (int j = 0; j < net.nv(); ++j) Pc(i, j) = net.points()(net.index(i, j), c);
    const RowMat R = Tu * Pc * Tv.transpose();
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) out(i * nv + j, c) = R(i, j);
  }
  return BSplineNet(net.p(), net.q(), std::move(U), std::move(V), std::move(out));
}

BezierExtraction bezier_extraction(int k, const std::vector<double>& K) {
  BSplineNet::validate_knots(k, K, "of the curve");
  const int n = count_of(k, K);
  BezierExtraction ex;
  for (int i = k; i <= n; ++i)
    if (ex.breaks.empty() || K[static_cast<size_t>(i)] > ex.breaks.back())
      ex.breaks.push_back(K[static_cast<size_t>(i)]);
  // Insert every break up to multiplicity k (the ends too: an unclamped knot vector then has
  // Bernstein pieces on its first and last spans as well).
  std::vector<double> extra;
  for (double b : ex.breaks)
    for (int r = multiplicity(K, b); r < k; ++r) extra.push_back(b);
  std::vector<double> R;
  const Eigen::MatrixXd T = knot_insertion_matrix(k, K, extra, &R);
  const int S = static_cast<int>(ex.breaks.size()) - 1;
  for (int s = 0; s < S; ++s) {
    // Refined span index r with R_r = b_s < R_{r+1}: the last copy of b_s.
    const auto it = std::upper_bound(R.begin(), R.end(), ex.breaks[static_cast<size_t>(s)]);
    const int r = static_cast<int>(it - R.begin()) - 1;
    ex.C.push_back(T.middleRows(r - k, k + 1));
    // Original span index: last copy of b_s in K; its live basis functions are span-k..span.
    const auto it0 = std::upper_bound(K.begin(), K.end(), ex.breaks[static_cast<size_t>(s)]);
    ex.first.push_back(static_cast<int>(it0 - K.begin()) - 1 - k);
  }
  return ex;
}

std::vector<BezierPatch> bezier_patches(const BSplineNet& net) {
  const BezierExtraction eu = bezier_extraction(net.p(), net.knots_u());
  const BezierExtraction ev = bezier_extraction(net.q(), net.knots_v());
  std::vector<BezierPatch> out;
  using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::vector<RowMat> Pc(3, RowMat(net.nu(), net.nv()));
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < net.nu(); ++i)
      for (int j = 0; j < net.nv(); ++j) Pc[static_cast<size_t>(c)](i, j) = net.points()(net.index(i, j), c);
  for (int su = 0; su < eu.spans(); ++su)
    for (int sv = 0; sv < ev.spans(); ++sv) {
      BezierPatch b;
      b.u0 = eu.breaks[static_cast<size_t>(su)];
      b.u1 = eu.breaks[static_cast<size_t>(su) + 1];
      b.v0 = ev.breaks[static_cast<size_t>(sv)];
      b.v1 = ev.breaks[static_cast<size_t>(sv) + 1];
      b.su = su;
      b.sv = sv;
      b.net = TensorNet(net.p(), net.q());
      for (int c = 0; c < 3; ++c) {
        const RowMat B =
            eu.C[static_cast<size_t>(su)] * Pc[static_cast<size_t>(c)] * ev.C[static_cast<size_t>(sv)].transpose();
        for (int i = 0; i <= net.p(); ++i)
          for (int j = 0; j <= net.q(); ++j) b.net.points()(b.net.index(i, j), c) = B(i, j);
      }
      out.push_back(std::move(b));
    }
  return out;
}

Eigen::MatrixXd polynomial_to_bspline_matrix(int d, double t0, double t1, int k, const std::vector<double>& K) {
  BSplineNet::validate_knots(k, K, "of the curve");
  if (!std::isfinite(t0) || !std::isfinite(t1)) throw NonFiniteError("polynomial_to_bspline: interval not finite");
  if (!(t0 < t1)) throw ParameterError("polynomial_to_bspline: the interval [t0, t1] must have t0 < t1");
  if (d < 0 || d > k)
    throw DegreeError("polynomial_to_bspline: polynomial degree " + std::to_string(d) + " exceeds the spline degree " +
                      std::to_string(k));
  const int n = count_of(k, K);
  const Eigen::MatrixXd E = bernstein_elevation_operator(d, k - d);  // (k+1) x (d+1)
  Eigen::MatrixXd W(n, k + 1);                                       // blossom weights at degree k
  for (int i = 0; i < n; ++i) {
    Eigen::MatrixXd c = Eigen::MatrixXd::Identity(k + 1, k + 1);  // column r: coefficients of B_r^k
    for (int r = 1; r <= k; ++r) {
      const double s = (K[static_cast<size_t>(i + r)] - t0) / (t1 - t0);
      for (int j = 0; j <= k - r; ++j) c.row(j) = (1.0 - s) * c.row(j) + s * c.row(j + 1);
    }
    W.row(i) = c.row(0);
  }
  return W * E;
}

BSplineNet bspline_from_bezier(const TensorNet& patch, double u0, double u1, double v0, double v1, int p, int q,
                               const std::vector<double>& U, const std::vector<double>& V) {
  const Eigen::MatrixXd Mu = polynomial_to_bspline_matrix(patch.n(), u0, u1, p, U);
  const Eigen::MatrixXd Mv = polynomial_to_bspline_matrix(patch.m(), v0, v1, q, V);
  const int nu = static_cast<int>(Mu.rows()), nv = static_cast<int>(Mv.rows());
  Eigen::MatrixX3d out(nu * nv, 3);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd Pc(patch.n() + 1, patch.m() + 1);
    for (int i = 0; i <= patch.n(); ++i)
      for (int j = 0; j <= patch.m(); ++j) Pc(i, j) = patch.points()(patch.index(i, j), c);
    const Eigen::MatrixXd R = Mu * Pc * Mv.transpose();
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j) out(i * nv + j, c) = R(i, j);
  }
  return BSplineNet(p, q, U, V, std::move(out));
}

}  // namespace bpde
