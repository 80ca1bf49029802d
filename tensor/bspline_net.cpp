#include "bezierpde/tensor/bspline_net.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/sample_progress.h"

namespace bpde {
namespace {

void check_knots(int k, const std::vector<double>& K, const char* dir) {
  const std::string d(dir);
  if (k < 1 || k > kMaxDegree)
    throw DegreeError("bspline: degree " + d + " = " + std::to_string(k) + " is outside 1.." +
                      std::to_string(kMaxDegree));
  for (size_t i = 0; i < K.size(); ++i)
    if (!std::isfinite(K[i])) throw NonFiniteError("bspline: knot " + d + "[" + std::to_string(i) + "] is not finite");
  const int count = static_cast<int>(K.size()) - k - 1;
  if (count < k + 1)
    throw SizeError("bspline: " + std::to_string(K.size()) + " knots in " + d + " give " + std::to_string(count) +
                    " control points; degree " + std::to_string(k) + " needs at least " + std::to_string(k + 1) +
                    " (len(knots) >= 2*degree + 2)");
  int mult = 1;
  for (size_t i = 1; i < K.size(); ++i) {
    if (K[i] < K[i - 1])
      throw ParameterError("bspline: knots " + d + " decrease at index " + std::to_string(i) + " (" +
                           std::to_string(K[i - 1]) + " > " + std::to_string(K[i]) + ")");
    mult = (K[i] == K[i - 1]) ? mult + 1 : 1;
    if (mult > k + 1)
      throw ParameterError("bspline: knot " + d + "[" + std::to_string(i) + "] has multiplicity > degree + 1");
  }
  if (!(K[static_cast<size_t>(k)] < K[static_cast<size_t>(count)]))
    throw ParameterError("bspline: empty domain in " + d + ": knot[" + std::to_string(k) + "] == knot[" +
                         std::to_string(count) + "]");
  // Scale (BSplineNet::kMaxKnotMagnitude, kMinDomainResolution, kMinSpanRatio): every width
  // computed from the knots (spans, the domain, the whole vector) is then finite and non-zero
  // where it is not an exact multiple knot, so no parameter derived from them is inf or NaN.
  double big = 0.0;
  for (size_t i = 0; i < K.size(); ++i) {
    if (std::abs(K[i]) > BSplineNet::kMaxKnotMagnitude)
      throw ParameterError("bspline: knot " + d + "[" + std::to_string(i) + "] is too large (|knot| must be <= 1e50)");
    big = std::max(big, std::abs(K[i]));
  }
  const double domain = K[static_cast<size_t>(count)] - K[static_cast<size_t>(k)];
  if (!(domain >= BSplineNet::kMinDomainResolution * big) || !(domain >= BSplineNet::kMinDomainWidth))
    throw ParameterError("bspline: the domain of " + d + " [knot[" + std::to_string(k) + "], knot[" +
                         std::to_string(count) +
                         "]] is badly scaled: its width must be >= 1e-50 and >= 1e-8 "
                         "times the largest |knot|");
  const double total = K.back() - K.front();
  for (size_t i = 1; i < K.size(); ++i) {
    const double h = K[i] - K[i - 1];
    if (h > 0 && !(h >= BSplineNet::kMinSpanRatio * total))
      throw ParameterError("bspline: knot span " + d + "[" + std::to_string(i - 1) + "].." + d + "[" +
                           std::to_string(i) +
                           "] is badly scaled: a non-zero span must be >= 1e-12 times "
                           "knot.back() - knot.front()");
  }
}

// The parameters are finite here (checked by the callers): clamp() and the comparisons below let
// a NaN through, and a NaN would give the span count, one past the last basis function.
void require_finite_parameter(double t, const char* what) {
  if (!std::isfinite(t)) throw NonFiniteError(std::string("bspline: ") + what + " parameter is not finite");
}

// Span index s with K[s] <= t < K[s+1], clamped to [k, count-1] (Piegl–Tiller A2.1).
int find_span(int k, const std::vector<double>& K, double t) {
  require_finite_parameter(t, "a");
  const int count = static_cast<int>(K.size()) - k - 1;
  if (t >= K[static_cast<size_t>(count)]) {
    int s = count - 1;
    while (s > k && K[static_cast<size_t>(s)] == K[static_cast<size_t>(count)]) --s;
    return s;
  }
  if (t <= K[static_cast<size_t>(k)]) {
    int s = k;
    while (s < count - 1 && K[static_cast<size_t>(s + 1)] == K[static_cast<size_t>(k)]) ++s;
    return s;
  }
  // K[k] < t < K[count]: the first knot > t is in K[k+1..count], so k <= span <= count - 1.
  const auto it = std::upper_bound(K.begin() + k, K.begin() + count + 1, t);
  return std::clamp(static_cast<int>(it - K.begin()) - 1, k, count - 1);
}

// Non-zero basis functions and derivatives up to order nd at t (Piegl–Tiller A2.3):
// ders(r, c) = r-th derivative of N_{span-k+c}.
Eigen::MatrixXd ders_basis(int span, double t, int k, int nd, const std::vector<double>& K) {
  Eigen::MatrixXd ndu(k + 1, k + 1), a(2, k + 1), ders = Eigen::MatrixXd::Zero(nd + 1, k + 1);
  std::vector<double> left(static_cast<size_t>(k + 1)), right(static_cast<size_t>(k + 1));
  ndu(0, 0) = 1.0;
  for (int j = 1; j <= k; ++j) {
    left[static_cast<size_t>(j)] = t - K[static_cast<size_t>(span + 1 - j)];
    right[static_cast<size_t>(j)] = K[static_cast<size_t>(span + j)] - t;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu(j, r) = right[static_cast<size_t>(r + 1)] + left[static_cast<size_t>(j - r)];
      const double temp = ndu(r, j - 1) / ndu(j, r);
      ndu(r, j) = saved + right[static_cast<size_t>(r + 1)] * temp;
      saved = left[static_cast<size_t>(j - r)] * temp;
    }
    ndu(j, j) = saved;
  }
  for (int j = 0; j <= k; ++j) ders(0, j) = ndu(j, k);
  const int top = std::min(nd, k);
  for (int r = 0; r <= k; ++r) {
    int s1 = 0, s2 = 1;
    a(0, 0) = 1.0;
    for (int d = 1; d <= top; ++d) {
      double dd = 0.0;
      const int rk = r - d, pk = k - d;
      if (r >= d) {
        a(s2, 0) = a(s1, 0) / ndu(pk + 1, rk);
        dd = a(s2, 0) * ndu(rk, pk);
      }
      const int j1 = (rk >= -1) ? 1 : -rk;
      const int j2 = (r - 1 <= pk) ? d - 1 : k - r;
      for (int j = j1; j <= j2; ++j) {
        a(s2, j) = (a(s1, j) - a(s1, j - 1)) / ndu(pk + 1, rk + j);
        dd += a(s2, j) * ndu(rk + j, pk);
      }
      if (r <= pk) {
        a(s2, d) = -a(s1, d - 1) / ndu(pk + 1, r);
        dd += a(s2, d) * ndu(r, pk);
      }
      ders(d, r) = dd;
      std::swap(s1, s2);
    }
  }
  double f = k;
  for (int d = 1; d <= top; ++d) {
    ders.row(d) *= f;
    f *= (k - d);
  }
  return ders;
}

}  // namespace

BSplineNet::BSplineNet(int p, int q, std::vector<double> U, std::vector<double> V, Eigen::MatrixX3d points)
    : p_(p), q_(q), U_(std::move(U)), V_(std::move(V)), points_(std::move(points)) {
  check_knots(p_, U_, "u");
  check_knots(q_, V_, "v");
  if (points_.rows() != size())
    throw SizeError("bspline net with " + std::to_string(nu()) + " x " + std::to_string(nv()) +
                    " control points needs " + std::to_string(size()) + " points, got " +
                    std::to_string(points_.rows()));
  for (Eigen::Index r = 0; r < points_.rows(); ++r)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(points_(r, c)))
        throw NonFiniteError("bspline net: point " + std::to_string(r) + " coordinate " + std::to_string(c) +
                             " is not finite");
}

void BSplineNet::validate_knots(int k, const std::vector<double>& K, const char* dir) { check_knots(k, K, dir); }

Eigen::MatrixXd BSplineNet::basis_table(int k, const std::vector<double>& K, const Eigen::VectorXd& t, int d) {
  const int count = static_cast<int>(K.size()) - k - 1;
  Eigen::MatrixXd T = Eigen::MatrixXd::Zero(t.size(), count);
  if (d > k) return T;
  for (Eigen::Index s = 0; s < t.size(); ++s) {
    require_finite_parameter(t(s), "a basis_table");
    const double x = std::clamp(t(s), K[static_cast<size_t>(k)], K[static_cast<size_t>(count)]);
    const int span = find_span(k, K, x);
    const Eigen::MatrixXd D = ders_basis(span, x, k, d, K);
    for (int c = 0; c <= k; ++c) T(s, span - k + c) = D(d, c);
  }
  return T;
}

Eigen::Vector3d BSplineNet::derivative(double u, double v, int du, int dv) const {
  Eigen::VectorXd tu(1), tv(1);
  tu << u;
  tv << v;
  const Eigen::RowVectorXd Nu = basis_table(p_, U_, tu, du), Nv = basis_table(q_, V_, tv, dv);
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (int i = 0; i < nu(); ++i) {
    if (Nu(i) == 0.0) continue;
    for (int j = 0; j < nv(); ++j)
      if (Nv(j) != 0.0) out += Nu(i) * Nv(j) * points_.row(index(i, j)).transpose();
  }
  return out;
}

namespace {

// de Boor's algorithm on the control points ctrl(0..count-1) of one direction (degree k, knots K).
Eigen::Vector3d de_boor(int k, const std::vector<double>& K, const std::vector<Eigen::Vector3d>& ctrl, double t) {
  const int count = static_cast<int>(K.size()) - k - 1;
  require_finite_parameter(t, "a de Boor");
  t = std::clamp(t, K[static_cast<size_t>(k)], K[static_cast<size_t>(count)]);
  const int s = find_span(k, K, t);
  std::vector<Eigen::Vector3d> d(static_cast<size_t>(k + 1));
  for (int j = 0; j <= k; ++j) d[static_cast<size_t>(j)] = ctrl[static_cast<size_t>(s - k + j)];
  for (int r = 1; r <= k; ++r)
    for (int j = k; j >= r; --j) {
      const int i = s - k + j;
      const double den = K[static_cast<size_t>(i + k - r + 1)] - K[static_cast<size_t>(i)];
      const double alpha = den > 0 ? (t - K[static_cast<size_t>(i)]) / den : 0.0;
      d[static_cast<size_t>(j)] = (1 - alpha) * d[static_cast<size_t>(j - 1)] + alpha * d[static_cast<size_t>(j)];
    }
  return d[static_cast<size_t>(k)];
}

}  // namespace

Eigen::Vector3d BSplineNet::evaluate_de_boor(double u, double v) const {
  std::vector<Eigen::Vector3d> row(static_cast<size_t>(nv())), col(static_cast<size_t>(nu()));
  for (int i = 0; i < nu(); ++i) {
    for (int j = 0; j < nv(); ++j) row[static_cast<size_t>(j)] = points_.row(index(i, j)).transpose();
    col[static_cast<size_t>(i)] = de_boor(q_, V_, row, v);
  }
  return de_boor(p_, U_, col, u);
}

SurfaceJet BSplineNet::jet(double u, double v) const { return surface_jet(*this, u, v); }

FundamentalForms BSplineNet::geometry(double u, double v) const { return fundamental_forms(jet(u, v)); }

std::vector<int> BSplineNet::ring_indices(int r) const {
  std::vector<int> out;
  for (int i = 0; i < nu(); ++i)
    for (int j = 0; j < nv(); ++j)
      if (std::min({i, nu() - 1 - i, j, nv() - 1 - j}) == r) out.push_back(index(i, j));
  return out;
}

std::vector<int> BSplineNet::fixed_indices(FixedSet fixed) const {
  std::vector<int> out;
  for (int i = 0; i < nu(); ++i)
    for (int j = 0; j < nv(); ++j) {
      const int d = std::min({i, nu() - 1 - i, j, nv() - 1 - j});
      const bool take = fixed == FixedSet::Boundary           ? d == 0
                        : fixed == FixedSet::BoundaryAdjacent ? d <= 1
                                                              : (i == 0 || i == nu() - 1);
      if (take) out.push_back(index(i, j));
    }
  return out;
}

std::vector<int> BSplineNet::free_indices(FixedSet fixed) const {
  return complement_indices(fixed_indices(fixed), size());
}

TriangleMesh sample_mesh(const BSplineNet& net, int N) { return sample_mesh(net, N, ProgressFn{}); }

TriangleMesh sample_mesh(const BSplineNet& net, int N, const ProgressFn& progress) {
  if (N < 1) throw ParameterError("sample_mesh: samples must be >= 1");
  Eigen::VectorXd tu(N + 1), tv(N + 1);
  for (int a = 0; a <= N; ++a) {
    tu(a) = net.u_min() + (net.u_max() - net.u_min()) * a / N;
    tv(a) = net.v_min() + (net.v_max() - net.v_min()) * a / N;
  }
  int evaluations = 0;
  report(progress, kSamplingStage, 0.0, 1.0);
  auto grid = [&](int du, int dv) {
    const Eigen::MatrixXd Bu = BSplineNet::basis_table(net.p(), net.knots_u(), tu, du);
    const Eigen::MatrixXd Bv = BSplineNet::basis_table(net.q(), net.knots_v(), tv, dv);
    Eigen::MatrixX3d out((N + 1) * (N + 1), 3);
    using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
    for (int c = 0; c < 3; ++c) {
      const Eigen::Map<const RowMat, 0, Eigen::OuterStride<>> Pc(net.points().col(c).data(), net.nu(), net.nv(),
                                                                 Eigen::OuterStride<>(net.nv()));
      Eigen::Map<RowMat>(out.col(c).data(), N + 1, N + 1) = Bu * (Pc * Bv.transpose());
    }
    report(progress, kSamplingStage, sampling_fraction(++evaluations), 1.0);
    return out;
  };
  TriangleMesh mesh;
  mesh.V = grid(0, 0);
  const Eigen::MatrixX3d Xu = grid(1, 0), Xv = grid(0, 1), Xuu = grid(2, 0), Xuv = grid(1, 1), Xvv = grid(0, 2);
  const double cu = 0.5 * (net.u_min() + net.u_max()), cv = 0.5 * (net.v_min() + net.v_max());
  mesh.H = sampled_mean_curvature(
      mesh.V, Xu, Xv, Xuu, Xuv, Xvv,
      [&](Eigen::Index k, double h) {
        const double u = tu(k / (N + 1)), v = tv(k % (N + 1));
        return net.geometry(u + h * (cu - u), v + h * (cv - v));
      },
      &mesh.regular);
  report(progress, kSamplingStage, 0.95, 1.0);
  mesh.F = grid_triangles(N);
  return mesh;
}

}  // namespace bpde
