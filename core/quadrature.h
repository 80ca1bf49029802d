#pragma once
// Gauss quadrature rules, used to cross-check exact Bernstein integrals and to assemble
// finite-element forms.
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

}  // namespace bpde
