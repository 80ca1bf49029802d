#pragma once
// The Bogner–Fox–Schmit (BFS) C¹ bicubic rectangle on a uniform k×l partition of Ω = [0,1]²
// (Pasadas, Rodríguez, smoothing PDE splines §5–6: "the BFS's rectangle of class C¹").
//
// Nodes (x_i, y_j) = (i/k, j/l), 0 <= i <= k, 0 <= j <= l. Each node carries 4 degrees of freedom
// d = 0..3: u, u_x, u_y, u_xy. Global index of dof d at node (i, j):
//     dof(i, j, d) = 4 (i (l+1) + j) + d.
// On the element [x_i, x_{i+1}] × [y_j, y_{j+1}] (sizes hx = 1/k, hy = 1/l) the basis function of
// dof d = p + 2q at the corner (i+di, j+dj) is
//     hx^p H_{2di+p}((x - x_i)/hx) · hy^q H_{2dj+q}((y - y_j)/hy),
// with the cubic Hermite functions of hermite_cubic(). The space is the tensor product of the 1D
// C¹ cubic Hermite spline spaces, i.e. C¹ bicubic splines with double interior knots.
//
// A field (3 coordinates) is a num_dofs() by 3 coefficient matrix.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <array>
#include <functional>

namespace bpde {

/// The four cubic Hermite functions on [0,1] and their derivatives of order r = 0..3 (w.r.t. t):
///   H0 = 1 - 3t² + 2t³ (value at 0), H1 = t - 2t² + t³ (slope at 0),
///   H2 = 3t² - 2t³      (value at 1), H3 = -t² + t³     (slope at 1).
/// r > 3 gives zeros. Throws ParameterError for r < 0.
std::array<double, 4> hermite_cubic(double t, int r);

/// Coefficients of the symmetric bilinear form (u, v)_L = ∫ c_xx u_xx v_xx + c_xy u_xy v_xy +
/// c_yy u_yy v_yy over Ω. Smoothing PDE splines §6 (docs/errata.md): operator ∂⁴_x + 2a ∂²_x∂²_y + a² ∂⁴_y gives
/// c = (1, 2a, a²).
struct SecondOrderForm {
  double c_xx = 1.0, c_xy = 2.0, c_yy = 1.0;
  static SecondOrderForm from_a(double a) { return {1.0, 2.0 * a, a * a}; }
};

class BfsSpace {
 public:
  /// Largest k and l accepted (a k×l partition has 4(k+1)(l+1) dofs): what `bpde blend` solves
  /// within a minute and 2 GB with the sparse Cholesky of the reduced system (measured:
  /// docs/performance_measurements.md "Blend"; it was 128 with the KKT LU).
  static constexpr int kMaxPartition = 256;

  /// Throws ParameterError unless 1 <= k, l <= kMaxPartition.
  BfsSpace(int k, int l);

  int k() const { return k_; }
  int l() const { return l_; }
  double hx() const { return 1.0 / k_; }
  double hy() const { return 1.0 / l_; }
  int num_nodes() const { return (k_ + 1) * (l_ + 1); }
  int num_dofs() const { return 4 * num_nodes(); }
  int dof(int i, int j, int d) const { return 4 * (i * (l_ + 1) + j) + d; }

  /// The 16 basis functions that may be nonzero at (x, y) ∈ Ω, differentiated dx times in x
  /// and dy times in y: their global dof indices and values. Points on element sides belong to
  /// the element on their lower-left (clamped to the last element at x = 1 or y = 1); for
  /// dx, dy <= 1 the result does not depend on that choice (C¹). Throws ParameterError when
  /// (x, y) is outside Ω by more than 1e-12 or is not finite.
  void basis_at(double x, double y, int dx, int dy, std::array<int, 16>& index, std::array<double, 16>& value) const;

  /// 16 by 16 element matrix of (·,·)_L on one element (the same for every element of a uniform
  /// partition), local dof order 4 (2 di + dj) + d, by a 4×4 Gauss rule (exact: the integrands
  /// have degree <= 6 in each variable).
  Eigen::Matrix<double, 16, 16> element_form(const SecondOrderForm& form) const;

  /// A square root of element_form: the 48 by 16 matrix B with element_form(form) = BᵀB up to
  /// rounding, rows 3q + {0, 1, 2} = √(w_q c_xx) ∂_xx, √(w_q c_xy) ∂_xy, √(w_q c_yy) ∂_yy of the 16
  /// local basis functions at the q-th point of the same 4×4 Gauss rule. The energy of a field on
  /// the element is then |B c_e|², a sum of squares (no cancellation of the form's terms). All
  /// coefficients of the form must be >= 0 (ParameterError otherwise).
  Eigen::Matrix<double, 48, 16> element_form_factor(const SecondOrderForm& form) const;

  /// Global dofs of the element (i, j) in its local order.
  std::array<int, 16> element_dofs(int i, int j) const;

  /// R = ((ω_r, ω_s)_L), num_dofs by num_dofs, symmetric positive semidefinite.
  Eigen::SparseMatrix<double> assemble_form(const SecondOrderForm& form) const;

  /// Gram matrix ((ω_r, ω_s)_0) (the L² inner product), num_dofs by num_dofs.
  Eigen::SparseMatrix<double> assemble_mass() const;

  /// ((ω_r, f)_0) for a vector field f: num_dofs by 3, by a q×q Gauss rule per element
  /// (exact when f is a polynomial of degree <= 2q - 4 in each variable). Throws NonFiniteError
  /// if f returns a non-finite value.
  Eigen::MatrixX3d assemble_load(const std::function<Eigen::Vector3d(double, double)>& f, int q = 6) const;

  /// ∂^(dx+dy) u / ∂x^dx ∂y^dy at (x, y) for the field with the given coefficients.
  Eigen::Vector3d evaluate(const Eigen::MatrixX3d& coefficients, double x, double y, int dx = 0, int dy = 0) const;

  /// Coefficients of the field that interpolates u, u_x, u_y, u_xy of a given function at the
  /// nodes (exact for bicubic polynomials). jet(x, y) returns the rows u, u_x, u_y, u_xy.
  Eigen::MatrixX3d interpolate(const std::function<Eigen::Matrix<double, 4, 3>(double, double)>& jet) const;

  /// The same field as a clamped bicubic B-spline (FORMATS.md "bspline" net): degree (3, 3),
  /// knots {0,0,0,0, 1/k,1/k, ..., (k-1)/k,(k-1)/k, 1,1,1,1} in x (likewise in y), and
  /// (2k+2)(2l+2) control points at index I (2l+2) + J, I along x. Per direction, node i with
  /// value u and slope u' gives the control points P_2i = u - (h/3) u' and P_2i+1 = u + (h/3) u',
  /// except P_0 = u_0 and P_2k+1 = u_k (the Bézier points of the Hermite segments, with the
  /// shared end points dropped).
  struct BSplineForm {
    std::vector<double> knots_x, knots_y;
    Eigen::MatrixX3d points;
  };
  BSplineForm to_bspline(const Eigen::MatrixX3d& coefficients) const;

 private:
  void locate(double x, double y, int& i, int& j, double& t, double& s) const;
  int k_, l_;
};

}  // namespace bpde
