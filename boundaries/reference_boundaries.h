#pragma once
// Boundary data of the papers' reference problems, built as Bézier nets: curve fitting, the
// circle split into three arcs of Fig. 1 of Arnal–Lluch–Monterde (triangular CMC), and conformal
// sphere patches (inverse stereographic projection), whose CMC approximations converge to the
// sphere (docs/errata.md, triangular CMC §4).
//
// Conventions: tensor and triangular nets as in tensor/tensor_net.h and
// triangular/triangular_net.h; only the boundary points (outer ring / some index 0) are set, the
// others are zero.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <numbers>

#include "bezierpde/boundaries/boundary_curves.h"
#include "bezierpde/boundaries/fit_boundary.h"
#include "bezierpde/core/bernstein.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

/// Degree-n Bézier control points of the curve c(t), t in [0,1], interpolating it at the
/// Chebyshev–Lobatto nodes (end points exact): fit_edge of fit_boundary.h on the curve as a
/// function, so that the reference nets and jobs' boundary curves share one interpolation (and
/// its DegreeError outside 1..kMaxDegree).
inline Eigen::MatrixX3d fit_curve(int n, const std::function<Eigen::Vector3d(double)>& c) {
  return fit_edge(BoundaryCurve::function(c), n, FitMethod::Interpolation).points;
}

/// Triangular net whose boundary fits the surface s(u,v) along the three edges (interior zero).
inline TriangularNet triangular_boundary(int n, const std::function<Eigen::Vector3d(double, double)>& s) {
  TriangularNet net(n);
  // v = 0: P_{i,0,n-i}, x(u,0) = sum B_i^n(u) P_{i0}
  const Eigen::MatrixX3d e1 = fit_curve(n, [&](double t) { return s(t, 0); });
  // u = 0: P_{0,j,n-j}, x(0,v) = sum B_j^n(v) P_{0j}
  const Eigen::MatrixX3d e2 = fit_curve(n, [&](double t) { return s(0, t); });
  // w = 0: P_{i,n-i,0}, x(u,1-u) = sum B_i^n(u) P_{i,n-i}
  const Eigen::MatrixX3d e3 = fit_curve(n, [&](double t) { return s(t, 1 - t); });
  for (int i = 0; i <= n; ++i) {
    net.set_point(i, 0, e1.row(i).transpose());
    net.set_point(0, i, e2.row(i).transpose());
    net.set_point(i, n - i, e3.row(i).transpose());
  }
  return net;
}

/// Tensor net whose outer ring fits s along the four edges.
inline TensorNet tensor_boundary(int n, const std::function<Eigen::Vector3d(double, double)>& s) {
  TensorNet net(n, n);
  const Eigen::MatrixX3d a = fit_curve(n, [&](double t) { return s(t, 0); });
  const Eigen::MatrixX3d b = fit_curve(n, [&](double t) { return s(t, 1); });
  const Eigen::MatrixX3d c = fit_curve(n, [&](double t) { return s(0, t); });
  const Eigen::MatrixX3d d = fit_curve(n, [&](double t) { return s(1, t); });
  for (int i = 0; i <= n; ++i) {
    net.set_point(i, 0, a.row(i).transpose());
    net.set_point(i, n, b.row(i).transpose());
    net.set_point(0, i, c.row(i).transpose());
    net.set_point(n, i, d.row(i).transpose());
  }
  return net;
}

/// Inverse stereographic projection (from the north pole) onto the unit sphere: conformal, and
/// x_s ∧ x_t points inwards, so the sphere has H = +1 in the FORMATS.md convention.
inline Eigen::Vector3d inverse_stereographic(double s, double t) {
  const double r2 = s * s + t * t;
  return Eigen::Vector3d(2 * s, 2 * t, r2 - 1) / (1 + r2);
}

/// The sphere patch over the triangle: (s, t) = (u - 1/3, v - 1/3) (a translation: conformal).
inline Eigen::Vector3d sphere_triangle(double u, double v) { return inverse_stereographic(u - 1.0 / 3, v - 1.0 / 3); }
inline Eigen::Vector3d sphere_square(double u, double v) { return inverse_stereographic(u - 0.5, v - 0.5); }

/// Planar boundary in z = 0: the reference triangle with a wiggle in the plane, corners
/// P_{00n} = (0,0) -> P_{n00} = (1,0) -> P_{0n0} = (0,1) counter-clockwise.
inline Eigen::Vector3d planar_triangle(double u, double v) {
  return Eigen::Vector3d(u + 0.1 * u * v * (1 - u - v) + 0.05 * std::sin(3 * v) * u * (1 - u), v - 0.07 * u * v, 0.0);
}

/// Unit circle split into three arcs (triangular CMC, Fig. 1): P_{n00} at angle 0, P_{0n0} at 2π/3,
/// P_{00n} at 4π/3. Each edge is the arc parametrised by angle, fitted at degree n.
inline TriangularNet circle_three_arcs(int n) {
  const double third = 2 * std::numbers::pi / 3;
  auto arc = [](double a0, double a1) {
    return [a0, a1](double t) {
      const double a = a0 + (a1 - a0) * t;
      return Eigen::Vector3d(std::cos(a), std::sin(a), 0.0);
    };
  };
  TriangularNet net(n);
  // v = 0 edge from x(0,0) = P_{00n} (4π/3) to x(1,0) = P_{n00} (2π).
  const Eigen::MatrixX3d e1 = fit_curve(n, arc(2 * third, 3 * third));
  // u = 0 edge from P_{00n} (4π/3) to P_{0n0} (2π/3): decreasing angle.
  const Eigen::MatrixX3d e2 = fit_curve(n, arc(2 * third, third));
  // w = 0 edge x(t, 1-t) from P_{0n0} (t = 0, 2π/3) to P_{n00} (t = 1, 0).
  const Eigen::MatrixX3d e3 = fit_curve(n, arc(third, 0.0));
  for (int i = 0; i <= n; ++i) {
    net.set_point(i, 0, e1.row(i).transpose());
    net.set_point(0, i, e2.row(i).transpose());
    net.set_point(i, n - i, e3.row(i).transpose());
  }
  return net;
}

}  // namespace bpde
