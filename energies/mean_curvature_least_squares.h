#pragma once
// The least-squares mean-curvature functional
//
//     Φ(x) = ∫ ρ(u, v) (H_x − H)² |x_u ∧ x_v| du dv
//
// over a triangular or tensor Bézier patch x, with H_x its mean curvature (FORMATS.md convention,
// core/differential_geometry.h: N = x_u ∧ x_v, H_x = (eG − 2fF + gE) / (2(EG − F²)), so
// z = u² + v² has H = +2). Φ is dimensionless; Φ = 0 exactly when x has constant mean curvature H
// (on the whole patch: ρ > 0 away from the corners). It is the `"functional": "mean-curvature"` of
// a cmc job (solvers/cmc/cmc.h; docs/cmc_algorithm.md, "The least squares of the mean curvature").
//
// The corner weight ρ = Π_c (1 − λ_c⁸)⁴ over the corners c of the domain, with λ_c the barycentric
// coordinate of corner c (triangle) or its bilinear corner function ((1 − u)(1 − v) at (0, 0), …;
// square): each corner's factor is 0.98 at λ_c = 0.5, 0.48 at 0.8, 0.11 at 0.9 (ρ = 0.97 at an
// edge midpoint of the triangle, 1 − 2e-3 at its centre), and ρ
// vanishes like the 4th power of the distance at a corner. Why: where a smooth boundary is given in
// three (four) arcs, the parametrisation degenerates at the corners (x_u ∥ x_v), a polynomial
// patch cannot keep its mean curvature bounded there, and the unweighted integral diverges
// (measured on the area route's circle at degree 6: √Φ grows from 7.7e-3 to 0.29 as the rule goes
// from q = 7 to 24; with ρ it is 9.42e-5 … 9.46e-5 from q = 9 to 32). ρ makes Φ depend on
// the parametrisation near the corners only.
//
// Why it is there: the critical points of A_H = A + 2HV satisfy
// ∂A_H/∂P_I = 2∫ B_I (H − H_x)(x_u ∧ x_v) = 0 (tests/cmc/test_area_functional.cpp), which weighs
// the deviation by B_I; those vanish on the boundary edges, where the deviation of a
// polynomial patch from a CMC surface sits. Φ weighs it everywhere (measured on the circle of
// Arnal–Lluch–Monterde's Fig. 1, H = −0.9, degree 10: the A_H end point deviates 5.3e-3 from H,
// the Φ minimiser 1.1e-5; docs/cmc_measurements.md).
//
// Discretisation: Φ = Σ_q r_q², r_q = √(w_q |N(u_q, v_q)|) (H_x(u_q, v_q) − H), over the nodes of the
// corner-collapsed rules of the area functional (core/quadrature.h: corner_collapsed_triangle_rule,
// 6q² nodes; corner_collapsed_square_rule, 8q²), which keep the nodes off the corners, where a
// parametrisation of a smooth boundary in three or four arcs degenerates. A node whose
// parametrisation is singular there (|N| ≤ 1e-14 |x_u||x_v|) contributes r_q = 0. The Jacobian of
// r over the free points is exact: ∂r_q/∂(x_u, x_v, x_uu, x_uv, x_vv) by forward-mode automatic
// differentiation (ceres::Jet, 15 components), times the derivatives of the Bernstein basis at the
// node.
//
// Shapes: P is #points by 3 in the net's order (FORMATS.md); idx lists the free points; J is
// #nodes by 3·#idx, column 3a + c for point idx[a], coordinate c.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <array>
#include <vector>

namespace bpde {

class MeanCurvatureLeastSquares {
 public:
  /// Triangular net of degree n (2..kMaxDegree, DegreeError), corner-collapsed rule with q points per
  /// direction (2..200, ParameterError).
  static MeanCurvatureLeastSquares triangular(int n, int q);
  /// Tensor net of degree (n, m) (each 2..kMaxDegree), corner-collapsed rule with q points per
  /// direction (2..200).
  static MeanCurvatureLeastSquares tensor(int n, int m, int q);

  int size() const { return static_cast<int>(w_.size() ? D_[0].cols() : 0); }  ///< points of the net
  int nodes() const { return static_cast<int>(w_.size()); }
  int points_per_direction() const { return q_; }

  /// The residuals r (#nodes) at P for the target H, and, when J is given, their Jacobian over the
  /// points idx (#nodes by 3·#idx), and, when dH is given, ∂r/∂H (#nodes, as h_derivative(), from the
  /// same node derivatives).
  void residuals(const Eigen::MatrixX3d& P, double H, Eigen::VectorXd* r, const std::vector<int>* idx = nullptr,
                 Eigen::MatrixXd* J = nullptr, Eigen::VectorXd* dH = nullptr) const;
  /// Φ = Σ r_q².
  double value(const Eigen::MatrixX3d& P, double H) const;

  // Node by node (the Ceres route: one residual block per node, solvers/cmc/mean_curvature_ceres.cpp).
  /// The surface derivatives at the nodes: X[t] = D_t P (#nodes by 3), t = 0..4 for x_u, x_v, x_uu,
  /// x_uv, x_vv.
  using NodeDerivatives = std::array<Eigen::MatrixX3d, 5>;
  NodeDerivatives derivatives(const Eigen::MatrixX3d& P) const;
  /// r_q from X = derivatives(P) and, when dr is given, ∂r_q/∂(x_u, x_v, x_uu, x_uv, x_vv) (15
  /// components, 3t + c for derivative t and coordinate c; zero at a singular node, where r_q = 0).
  double node_residual(const NodeDerivatives& X, Eigen::Index q, double H, Eigen::Matrix<double, 15, 1>* dr) const;
  /// ∂r_q/∂H = −√(w_q |N_q|) at X = derivatives(P) (#nodes; 0 at a singular node), for the V form,
  /// where H is an unknown.
  Eigen::VectorXd h_derivative(const NodeDerivatives& X) const;
  /// ∂_t of the basis at the nodes (#nodes by #points), t as in derivatives(): ∂r_q/∂P_{I,c} =
  /// Σ_t dr(3t + c) basis_derivative(t)(q, I).
  const Eigen::MatrixXd& basis_derivative(int t) const { return D_[size_t(t)]; }

 private:
  MeanCurvatureLeastSquares() = default;
  int q_ = 0;
  /// Derivatives of the basis at the nodes (#nodes by #points): ∂_u, ∂_v, ∂_uu, ∂_uv, ∂_vv.
  std::array<Eigen::MatrixXd, 5> D_;
  Eigen::VectorXd w_;
};

}  // namespace bpde
