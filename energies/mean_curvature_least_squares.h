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
//
// Assembled mode (assembled(): a surface of several patches sharing control points, energies/
// patch_assembly.h):
//
//     Φ = Σ_p Φ_patch(P(map_p)) + Σ_seams ∫₀¹ |n_p(t) − n_q(t)|² dt,
//
// each patch in its own parameter domain with its own corner weight, plus the seam term: over every
// inner edge shared by two patches p and q (the same n + 1 global control points), the squared
// difference of their unit normals n = x_u ∧ x_v / |x_u ∧ x_v| at the same point of the edge, by
// the edge's parameter t (dimensionless, as Φ). Why: the shared points make the surface only C⁰,
// and the patches' Φ alone is 0 for pieces of CMC surfaces meeting at kinks (measured on the cap's
// fan of 6 triangles at degree 4: √Φ = 7.9e-6 with seams kinked by 23° and the surface 0.25 off the
// sphere); pieces of constant mean curvature H whose normals agree along the seams form one CMC
// surface. A seam whose patches run along it in the same direction (orientations that disagree)
// compares n_p with −n_q. Residuals: patch 0's nodes, then patch 1's, … (patches × the patch
// form's nodes), then per seam its Gauss–Legendre nodes (q of the patch form's rule, weights w_g
// on [0, 1]) with three residuals √w_g (n_p − n_q) each (a node where either parametrisation is
// singular contributes 0). The Jacobian over the global rows idx has column 3a + c for idx[a];
// patch p's block of rows is the patch form's Jacobian over its local rows among idx, its columns
// moved to their positions in idx (a point shared by several patches has entries in the rows of
// each); a seam's rows have the unit normals' derivatives (ceres::Jet on x_u, x_v) times the basis
// derivatives of both patches at the node; ∂r/∂H is 0 on the seam rows. J is dense (#nodes by 3·#idx), so the assembled mode serves
// complexes of moderate size (the cmc solve takes it up to area_impl::kSparseFromCoordinates free
// coordinates: solvers/cmc/complex_net.h). The node-by-node calls (derivatives, node_residual,
// h_derivative, basis_derivative) are the patch form's (patch_form()); on the assembled form they
// throw UnsupportedProblem.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <array>
#include <memory>
#include <vector>

#include "bezierpde/energies/patch_assembly.h"

namespace bpde {

class MeanCurvatureLeastSquares {
 public:
  /// Triangular net of degree n (2..kMaxDegree, DegreeError), corner-collapsed rule with q points per
  /// direction (2..200, ParameterError).
  static MeanCurvatureLeastSquares triangular(int n, int q);
  /// Tensor net of degree (n, m) (each 2..kMaxDegree), corner-collapsed rule with q points per
  /// direction (2..200).
  static MeanCurvatureLeastSquares tensor(int n, int m, int q);
  /// The sum of `patch` (a single-patch form) over the patches of `assembly` (assembled mode, above).
  /// ParameterError for a missing or assembled patch form; SizeError when the assembly's patch
  /// size is not the form's or a map row is out of range.
  static MeanCurvatureLeastSquares assembled(std::shared_ptr<const MeanCurvatureLeastSquares> patch,
                                             std::shared_ptr<const PatchAssembly> assembly);

  int size() const;   ///< points of the net (assembled: the global points)
  int nodes() const;  ///< residuals (assembled: of all patches)
  int points_per_direction() const { return q_; }
  bool is_assembled() const { return assembly_ != nullptr; }
  /// The single-patch form (itself when not assembled).
  const MeanCurvatureLeastSquares& patch_form() const { return patch_ ? *patch_ : *this; }

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
  const Eigen::MatrixXd& basis_derivative(int t) const {
    check_single("basis_derivative");
    return D_[size_t(t)];
  }

 private:
  MeanCurvatureLeastSquares() = default;
  /// An inner edge of an assembled form: patches p and q, the basis derivatives ∂_u, ∂_v of each at
  /// the edge's nodes (#nodes by patch points), the weights, and the sign of n_q.
  struct Seam {
    int p = 0, q = 0;
    Eigen::MatrixXd Bu_p, Bv_p, Bu_q, Bv_q;
    Eigen::VectorXd w;
    double sign = 1.0;
  };
  void find_seams();
  void assembled_residuals(const Eigen::MatrixX3d& P, double H, Eigen::VectorXd* r, const std::vector<int>* idx,
                           Eigen::MatrixXd* J, Eigen::VectorXd* dH) const;
  void check_single(const char* what) const;
  int q_ = 0;
  bool square_ = false;  ///< tensor (square domain) or triangular
  int n_ = 0, m_ = 0;    ///< degrees (triangular: m_ = n_)
  std::vector<Seam> seams_;  ///< assembled mode: the inner edges
  std::shared_ptr<const MeanCurvatureLeastSquares> patch_;  ///< assembled mode: the patch form
  std::shared_ptr<const PatchAssembly> assembly_;          ///< assembled mode: the patches' maps
  /// Derivatives of the basis at the nodes (#nodes by #points): ∂_u, ∂_v, ∂_uu, ∂_uv, ∂_vv.
  std::array<Eigen::MatrixXd, 5> D_;
  Eigen::VectorXd w_;
};

}  // namespace bpde
