#include "bezierpde/core/quadrature.h"

#include <array>
#include <cstddef>
#include <cmath>
#include <string>
#include <vector>
#include <numbers>

#include "bezierpde/core/errors.h"

namespace bpde {

QuadratureRule1D gauss_legendre01(int q) {
  if (q < 1 || q > 200) throw ParameterError("gauss_legendre01: q must be in 1..200");
  QuadratureRule1D r;
  r.x.resize(q);
  r.w.resize(q);
  // Newton on P_q from the Chebyshev-like initial guess; weights 2/((1-x^2) P_q'(x)^2) on [-1,1].
  for (int i = 0; i < q; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (q + 0.5));
    double dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= q; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (q == 1) {
        p1 = x;
        p0 = 1;
      }
      dp = q * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= q; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (q == 1) {
        p1 = x;
        p0 = 1;
      }
      dp = q * (x * p1 - p0) / (x * x - 1);
    }
    const double w = 2.0 / ((1 - x * x) * dp * dp);
    // map [-1,1] -> [0,1], increasing order
    r.x(q - 1 - i) = 0.5 * (x + 1);
    r.w(q - 1 - i) = 0.5 * w;
  }
  return r;
}

QuadratureRuleTriangle gauss_triangle(int q) {
  const QuadratureRule1D g = gauss_legendre01(q);
  QuadratureRuleTriangle r;
  r.uv.resize(q * q, 2);
  r.w.resize(q * q);
  // (s, t) in [0,1]^2 -> u = s, v = (1 - s) t, Jacobian (1 - s).
  for (int a = 0; a < q; ++a)
    for (int b = 0; b < q; ++b) {
      const int k = a * q + b;
      r.uv(k, 0) = g.x(a);
      r.uv(k, 1) = (1 - g.x(a)) * g.x(b);
      r.w(k) = g.w(a) * g.w(b) * (1 - g.x(a));
    }
  return r;
}

namespace {

using Tri = std::array<Eigen::Vector2d, 3>;  // {collapsed corner C, P1, P2}

// Nodes and weights of the Duffy rules on the triangles (u, v) = C + s(P1 - C) + s t(P2 - P1),
// Jacobian s |det(P1 - C, P2 - C)|, with q Gauss–Legendre points in t and, radially, either q
// points in σ with s = σ^p (levels = 0; p = the grading, p = 1 the plain Duffy rule,
// ds = p σ^(p-1) dσ) or q points on each of the levels + 1 pieces [0, ρ^L], [ρ^(k+1), ρ^k] of s
// (levels = L > 0, grading 1, ρ = kGeometricRatio).
QuadratureRuleTriangle duffy_rule(const std::vector<Tri>& tris, int q, int grading, int levels) {
  if (q < 1 || q > 200) throw ParameterError("corner-collapsed rule: q must be in 1..200, got " + std::to_string(q));
  if (grading < 1 || grading > 4)
    throw ParameterError("corner-collapsed rule: grading must be in 1..4, got " + std::to_string(grading));
  if (levels < 0 || levels > kMaxGeometricLevels)
    throw ParameterError("corner-collapsed rule: levels must be in 0.." + std::to_string(kMaxGeometricLevels) +
                         ", got " + std::to_string(levels));
  if (levels > 0 && grading != 1)
    throw ParameterError("corner-collapsed rule: geometric levels take grading 1, got " + std::to_string(grading));
  const QuadratureRule1D g = gauss_legendre01(q);
  // The radial nodes s and their weights (with the ds/dσ of the grading).
  std::vector<double> rs, rw;
  if (levels == 0) {
    for (int a = 0; a < q; ++a) {
      const double sg = g.x(a);
      rs.push_back(std::pow(sg, grading));
      rw.push_back(g.w(a) * grading * std::pow(sg, grading - 1));
    }
  } else {
    for (int k = levels; k >= 0; --k) {
      const double hi = std::pow(kGeometricRatio, k), lo = k == levels ? 0.0 : hi * kGeometricRatio;
      for (int a = 0; a < q; ++a) {
        rs.push_back(lo + (hi - lo) * g.x(a));
        rw.push_back((hi - lo) * g.w(a));
      }
    }
  }
  const Eigen::Index per = static_cast<Eigen::Index>(rs.size()) * q;
  QuadratureRuleTriangle rule;
  rule.uv.resize(per * static_cast<Eigen::Index>(tris.size()), 2);
  rule.w.resize(rule.uv.rows());
  Eigen::Index r = 0;
  for (const Tri& T : tris) {
    const Eigen::Vector2d e1 = T[1] - T[0], e2 = T[2] - T[1];
    const double det = std::abs(e1(0) * (T[2] - T[0])(1) - e1(1) * (T[2] - T[0])(0));
    for (std::size_t a = 0; a < rs.size(); ++a)
      for (int b = 0; b < q; ++b, ++r) {
        const double s = rs[a], t = g.x(b);
        rule.uv.row(r) = (T[0] + s * e1 + s * t * e2).transpose();
        rule.w(r) = rw[a] * g.w(b) * s * det;
      }
  }
  return rule;
}

}  // namespace

QuadratureRuleTriangle corner_collapsed_triangle_rule(int q, int grading, int levels) {
  const Eigen::Vector2d A(1, 0), B(0, 1), C(0, 0), G(1.0 / 3, 1.0 / 3);
  const Eigen::Vector2d mAB = (A + B) / 2, mAC = (A + C) / 2, mBC = (B + C) / 2;
  return duffy_rule({{A, mAB, G}, {A, mAC, G}, {B, mAB, G}, {B, mBC, G}, {C, mAC, G}, {C, mBC, G}}, q, grading, levels);
}

QuadratureRuleTriangle corner_collapsed_square_rule(int q, int grading, int levels) {
  const Eigen::Vector2d M(0.5, 0.5);
  std::vector<Tri> tris;
  for (int cu = 0; cu <= 1; ++cu)
    for (int cv = 0; cv <= 1; ++cv) {
      const Eigen::Vector2d corner(cu, cv);
      tris.push_back({corner, Eigen::Vector2d(0.5, cv), M});
      tris.push_back({corner, Eigen::Vector2d(cu, 0.5), M});
    }
  return duffy_rule(tris, q, grading, levels);
}

}  // namespace bpde
