#pragma once
// Gauss quadrature rules, used to cross-check exact Bernstein integrals and to assemble
// finite-element forms.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

namespace bpde {

/// Gauss–Legendre rule with q points on [0,1]: exact for polynomials of degree <= 2q-1.
/// Nodes increasing; weights sum to 1. q in 1..200 (ParameterError otherwise).
struct QuadratureRule1D {
  Eigen::VectorXd x, w;
};
QuadratureRule1D gauss_legendre01(int q);

/// Rule on the triangle T = {u, v >= 0, u + v <= 1} (area 1/2) by the collapsed (Duffy) product
/// of two Gauss rules with q points: exact for polynomials of total degree <= 2q - 2.
/// Rows of uv are (u, v); weights sum to 1/2.
struct QuadratureRuleTriangle {
  Eigen::MatrixX2d uv;
  Eigen::VectorXd w;
};
QuadratureRuleTriangle gauss_triangle(int q);

/// Corner-collapsed rules (the area functional's, energies/area_functional.h, "The rules"):
/// the triangle T cut by its centroid and edge midpoints into six triangles, each mapped from the
/// unit square by the Duffy map collapsed at its corner of T, (u, v) = C + s(P1 − C) + st(P2 − P1),
/// with q × q Gauss–Legendre points in (σ, t) and s = σ^grading: 6q² nodes, weights summing to 1/2.
/// An integrand that is s times a smooth function near a corner (|x_u ∧ x_v| where x_u ∥ x_v there)
/// is integrated with an error exponential in q. q in 1..200, grading in 1..4 (ParameterError).
///   levels = L > 0 (grading 1) cuts the radial coordinate geometrically instead: s in [0, ρ^L] and
/// [ρ^(k+1), ρ^k], k = 0 … L − 1 (ρ = kGeometricRatio), q Gauss points on each, q in t:
/// 6(L + 1)q² nodes. Near a corner where |x_u ∧ x_v| is small but not 0 (c), its branch point lies
/// at s ~ c off the real axis; each piece above it sees it at a fixed ratio of its length, so the
/// error falls exponentially in q whatever c ≥ ρ^L is (the hp-graded mesh of Babuška–Guo towards a
/// corner singularity). levels in 0..kMaxGeometricLevels.
QuadratureRuleTriangle corner_collapsed_triangle_rule(int q, int grading = 1, int levels = 0);
/// The same on the unit square: each quadrant split by its diagonal into two triangles collapsed
/// at the square's corner, 8q² nodes (8(L + 1)q² with levels), weights summing to 1 (rows of uv
/// are (u, v)).
QuadratureRuleTriangle corner_collapsed_square_rule(int q, int grading = 1, int levels = 0);
/// The ratio ρ of the geometric pieces of the corner-collapsed rules, and their largest number.
inline constexpr double kGeometricRatio = 0.3;
inline constexpr int kMaxGeometricLevels = 30;

}  // namespace bpde
