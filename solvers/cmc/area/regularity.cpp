// Regularity of a solved net (area_problem.h: Regularity, regularity, final_regularity) and the
// normal gap of two nets, the branch test of the continuations.
#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bezierpde/solvers/cmc/area/area_problem.h"
#include "bezierpde/solvers/cmc/area/area_solve.h"

namespace bpde::cmc_detail {
namespace {
template <class Net>
Eigen::Vector3d normal_at(const Net& net, double u, double v) {
  return net.derivative(u, v, 1, 0).cross(net.derivative(u, v, 0, 1));
}

// The corners, where |x_u ∧ x_v| may vanish (an edge's tangents meet at an angle the net cannot
// open): a barycentric coordinate (u, v, 1 − u − v) above 1 − 0.05 (triangular), or both u and v
// within 0.05 of 0 or 1 (tensor). The regularity test and normal_gap leave them out.
constexpr double kCornerMargin = 0.05;
bool near_corner(bool triangular, double u, double v) {
  if (triangular) return std::max({u, v, 1 - u - v}) > 1 - kCornerMargin + 1e-12;
  return std::min(u, 1 - u) < kCornerMargin - 1e-12 && std::min(v, 1 - v) < kCornerMargin - 1e-12;
}
}  // namespace

// Folds inside the corner margins, which the grid leaves out. On rays from each corner into the
// domain, (1 − a) d1 + a d2 (d1, d2 its edges, a = 0, 1/4, …, 1), at distances 0.05 · 4^-k
// (k = 0 … 7, down to 3e-6 of the edge), the normal must keep its direction: N · N' < 0 between
// a sample and the one at 0.05 on its ray, or between neighbouring rays at one distance, is a fold.
// A corner where the edges meet at 180° has N → 0 there but N ≈ r (a cos φ + b sin φ) along each
// ray, whose direction does not turn; a fold (the circle's arcs fitted at degree 4, which meet at
// 180.84°: docs/cmc_algorithm.md, "The area functional A_H") turns it over.
template <class Net>
void corner_folds(const Net& net, double mean, const std::vector<std::array<double, 6>>& corners, Regularity& r) {
  constexpr int kRays = 4, kDepth = 7;
  for (const auto& c : corners) {
    std::vector<Eigen::Vector3d> outer(kRays + 1);
    bool fold = false;
    double mn = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= kDepth; ++k) {
      const double d = kCornerMargin * std::ldexp(1.0, -2 * k);
      std::vector<Eigen::Vector3d> N(kRays + 1);
      for (int j = 0; j <= kRays; ++j) {
        const double a = double(j) / kRays;
        const double u = c[0] + d * ((1 - a) * c[2] + a * c[4]), v = c[1] + d * ((1 - a) * c[3] + a * c[5]);
        N[j] = normal_at(net, u, v);
        mn = std::min(mn, N[j].norm() / mean);
        if (k == 0) outer[j] = N[j];
        if (N[j].dot(outer[j]) < 0 || (j > 0 && N[j].dot(N[j - 1]) < 0)) fold = true;
      }
    }
    if (fold && r.fold_u < 0) {
      r.fold_u = c[0];
      r.fold_v = c[1];
      r.fold_min_ratio = mn;
      // The boundary's angle at the corner, on the side of the surface (its normal at 0.05 on the
      // middle ray): above 180° (reflex) the edges' tangents give a corner normal against it.
      const Eigen::Vector3d xu = net.derivative(c[0], c[1], 1, 0), xv = net.derivative(c[0], c[1], 0, 1);
      const Eigen::Vector3d t1 = c[2] * xu + c[3] * xv, t2 = c[4] * xu + c[5] * xv;
      const double det = c[2] * c[5] - c[3] * c[4];
      const double theta = std::atan2(t1.cross(t2).norm(), t1.dot(t2)) * 180 / std::numbers::pi;
      r.fold_corner_angle = t1.cross(t2).dot(outer[kRays / 2]) * det >= 0 ? theta : 360 - theta;
    }
  }
}

// |x_u ∧ x_v| on a 40 x 40 grid away from the corners (margin 0.05), relative to the mean A/|domain|.
Regularity regularity(const TriangularNet& net, double A) {
  const int Ns = 40;
  const double mean = A / 0.5;
  Regularity r;
  r.min_ratio = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> N(static_cast<size_t>((Ns + 1) * (Ns + 1)));
  std::vector<char> use(N.size(), 0);
  auto id = [&](int a, int b) { return static_cast<size_t>(a * (Ns + 1) + b); };
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns - a; ++b) {
      const double u = double(a) / Ns, v = double(b) / Ns;
      if (near_corner(true, u, v)) continue;
      N[id(a, b)] = normal_at(net, u, v);
      use[id(a, b)] = 1;
      r.min_ratio = std::min(r.min_ratio, N[id(a, b)].norm() / mean);
    }
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns - a; ++b) {
      if (!use[id(a, b)]) continue;
      if (a + 1 + b <= Ns && use[id(a + 1, b)] && N[id(a, b)].dot(N[id(a + 1, b)]) < 0) r.flipped = true;
      if (a + b + 1 <= Ns && use[id(a, b + 1)] && N[id(a, b)].dot(N[id(a, b + 1)]) < 0) r.flipped = true;
    }
  r.ok = std::isfinite(r.min_ratio) && r.min_ratio >= 1e-3 && !r.flipped;
  return r;
}

Regularity regularity(const TensorNet& net, double A) {
  const int Ns = 40;
  const double mean = A;
  Regularity r;
  r.min_ratio = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3d> N(static_cast<size_t>((Ns + 1) * (Ns + 1)));
  std::vector<char> use(N.size(), 0);
  auto id = [&](int a, int b) { return static_cast<size_t>(a * (Ns + 1) + b); };
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns; ++b) {
      const double u = double(a) / Ns, v = double(b) / Ns;
      if (near_corner(false, u, v)) continue;
      N[id(a, b)] = normal_at(net, u, v);
      use[id(a, b)] = 1;
      r.min_ratio = std::min(r.min_ratio, N[id(a, b)].norm() / mean);
    }
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= Ns; ++b) {
      if (!use[id(a, b)]) continue;
      if (a < Ns && use[id(a + 1, b)] && N[id(a, b)].dot(N[id(a + 1, b)]) < 0) r.flipped = true;
      if (b < Ns && use[id(a, b + 1)] && N[id(a, b)].dot(N[id(a, b + 1)]) < 0) r.flipped = true;
    }
  r.ok = std::isfinite(r.min_ratio) && r.min_ratio >= 1e-3 && !r.flipped;
  return r;
}

// The corners (u, v) with their edges' directions (barycentric order: P_n00 at (1, 0), P_0n0 at
// (0, 1), P_00n at (0, 0); tensor: P_00, P_n0, P_nn, P_0n).
Regularity final_regularity(const TriangularNet& net, double A) {
  Regularity r = regularity(net, A);
  if (r.ok) {
    corner_folds(net, A / 0.5, {{1, 0, -1, 1, -1, 0}, {0, 1, 0, -1, 1, -1}, {0, 0, 1, 0, 0, 1}}, r);
    r.ok = r.fold_u < 0;
  }
  return r;
}

Regularity final_regularity(const TensorNet& net, double A) {
  Regularity r = regularity(net, A);
  if (r.ok) {
    corner_folds(net, A, {{0, 0, 1, 0, 0, 1}, {1, 0, -1, 0, 0, 1}, {1, 1, -1, 0, 0, -1}, {0, 1, 1, 0, 0, -1}}, r);
    r.ok = r.fold_u < 0;
  }
  return r;
}

std::string Regularity::describe() const {
  if (!(std::isfinite(min_ratio) && min_ratio >= 1e-3) || flipped || fold_u < 0)
    return "|x_u ∧ x_v| falls to " + num(min_ratio) + " of its mean inside the patch" +
           (flipped ? " and the normal flips" : "");
  return "the normal flips near the corner (u, v) = (" + num(fold_u, 1) + ", " + num(fold_v, 1) +
         ") (a fold inside the corner margin 0.05; |x_u ∧ x_v| down to " + num(fold_min_ratio, 3) +
         " of its mean there; the boundary's edges meet at " + num(fold_corner_angle, 6) + "°" +
         (fold_corner_angle > 180 ? " (reflex: the normal at the corner, which the edges fix, points against the surface's)"
                                  : "") +
         ")";
}


namespace {
// The samples of normal_gap: the points (a/10, b/10) of the domain (66 on the triangle, 121 on
// the square) without the corners (near_corner).
std::vector<Eigen::Vector2d> gap_samples(bool triangular) {
  const int Ns = 10;
  std::vector<Eigen::Vector2d> uv;
  for (int a = 0; a <= Ns; ++a)
    for (int b = 0; b <= (triangular ? Ns - a : Ns); ++b) {
      const double u = double(a) / Ns, v = double(b) / Ns;
      if (!near_corner(triangular, u, v)) uv.emplace_back(u, v);
    }
  return uv;
}

// normal_gap (area_problem.h) for both nets.
template <class Net>
double normal_gap_on(const Net& a, const Net& b) {
  double gap = 0.0;
  for (const Eigen::Vector2d& uv : gap_samples(area_impl::is_triangular(a))) {
    const Eigen::Vector3d N = normal_at(a, uv[0], uv[1]);
    const double len = N.norm();
    if (!(len > 0)) return std::numeric_limits<double>::infinity();
    gap = std::max(gap, std::abs((b.evaluate(uv[0], uv[1]) - a.evaluate(uv[0], uv[1])).dot(N)) / len);
  }
  return gap;
}

}  // namespace

double normal_gap(const TriangularNet& a, const TriangularNet& b) { return normal_gap_on(a, b); }
double normal_gap(const TensorNet& a, const TensorNet& b) { return normal_gap_on(a, b); }

}  // namespace bpde::cmc_detail
