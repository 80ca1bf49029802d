#pragma once
// The cubic "volume" term of the CMC functional (Arnal, Lluch, Monterde, triangular CMC, Prop. 3,
// eqs. (5)–(7), corrected as in docs/errata.md, triangular CMC eq. (5)–(6) and eq. (7)):
//   V(x) = 1/3 ∫ <x_u ∧ x_v, x> du dv
// = the algebraic volume of the cone from the origin over the patch.
//
// Closed form (Prop. 3 with the sign correction: d_13 enters with a minus sign):
//   C_IJK = ∫_T ((B_I)_u (B_J)_v - (B_I)_v (B_J)_u) B_K
//         = [n!/I!][n!/J!][n!/K!] / [(3n)!/(I+J+K)!] * (d_12 + d_23 - d_13),
//   d_rs  = (I^r J^s - J^r I^s) / ((I^r+J^r+K^r)(I^s+J^s+K^s))   (0 when the numerator is 0),
//   V     = 1/6 sum_{I,J,K} C_IJK <P_I ∧ P_J, P_K>.
// (Writing V = sum S_IJK x^1_I x^2_J x^3_K needs the cyclic average S of C: docs/errata.md,
// triangular CMC Prop. 3.)
//
// Production route: Gauss rules that integrate the polynomial integrand, its gradient and its
// Hessian exactly; VolumeForm stores only the basis tables at the nodes, never the N^3 tensor
// C_IJK (rule sizes and memory per degree: docs/cmc_algorithm.md, "How V is computed").
//
// Gradient (exact, for every control point, boundary included):
//   dV/dP_L = 1/3 ∫ (B_L)_u (x_v ∧ x) + (B_L)_v (x ∧ x_u) + B_L (x_u ∧ x_v).
// For a point whose B_L vanishes on the boundary this equals ∫ B_L x_u ∧ x_v (eq. (7) without the
// spurious 1/3; eq. (10): 1/2 sum_JK C_LJK P_J ∧ P_K).
// Hessian block (3x3) of points I, L: d^2V/dP_I dP_L = [a_IL]_x (cross-product matrix, a_IL = -a_LI),
//   a_IL = 1/3 ∫ x ((B_I)_v (B_L)_u - (B_I)_u (B_L)_v) + x_v ((B_I)_u B_L - B_I (B_L)_u)
//              + x_u (B_I (B_L)_v - (B_I)_v B_L).
// The 3k x 3k Hessian over points idx[0..k-1] uses row 3a + c for (idx[a], coordinate c).
//
// Point matrices P are N x 3 in the net's order (TriangularNet / TensorNet, FORMATS.md).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace bpde {

class TriangularNet;
class TensorNet;
struct PatchAssembly;

class VolumeForm {
 public:
  /// Degree-n triangular nets (1 <= n <= kMaxDegree, DegreeError otherwise).
  static VolumeForm triangular(int n);
  /// Degree-(n,m) tensor nets.
  static VolumeForm tensor(int n, int m);
  /// V of a surface of several patches (energies/patch_assembly.h): the sum of `patch`'s V over
  /// the patches of `assembly`, on the #global x 3 points; every method below is the sum of the
  /// patch's through the local -> global maps (gradient rows and Hessian blocks of shared points
  /// add up). For a closed-up disc the sum is the volume of the cone from the origin over the
  /// whole surface, as for one patch. The node tables (weights(), basis(), ...) are the patch's.
  static VolumeForm assembled(std::shared_ptr<const VolumeForm> patch, std::shared_ptr<const PatchAssembly> assembly);
  /// The assembly of an assembled form (null for a single patch).
  const std::shared_ptr<const PatchAssembly>& assembly() const { return assembly_; }

  /// Number of control points N (assembled: the global points).
  int size() const;
  /// Number of quadrature nodes (assembled: over all patches).
  int nodes() const;
  /// Bytes held by the tables.
  std::size_t memory_bytes() const;

  /// V for the N x 3 points P (SizeError if P has the wrong number of rows).
  double value(const Eigen::MatrixX3d& P) const;
  /// N x 3 matrix of dV/dP_L.
  Eigen::MatrixX3d gradient(const Eigen::MatrixX3d& P) const;
  /// N x 3 matrix with the same integrals taken of absolute values (|B_L| |x_v ∧ x| ...): the size
  /// of the terms of the gradient, used to make optimality residuals relative.
  Eigen::MatrixX3d gradient_scale(const Eigen::MatrixX3d& P) const;
  /// 1/3 ∫ |<x_u ∧ x_v, x>|: the size of the terms of V (relative volume tolerances).
  double value_scale(const Eigen::MatrixX3d& P) const;
  /// 3k x 3k Hessian restricted to the points idx (row 3a + c <-> (idx[a], c)). Symmetric.
  /// When every point of idx is interior (its B_I vanishes on the boundary of the domain) the
  /// Hessian is assembled in O(k^2) from exact Bernstein products (see volume.cpp): for interior
  /// I, L, a_IL = ∫ B_I ((B_L)_v x_u - (B_L)_u x_v), and B_I (B_L)_v is a two-term Bernstein
  /// polynomial of degree 2n-1. Otherwise by quadrature in O(k^2 #nodes).
  Eigen::MatrixXd hessian(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const;
  /// The quadrature route of hessian() for any idx (kept for cross-checks).
  Eigen::MatrixXd hessian_quadrature(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const;
  /// k x 3 rows idx of gradient() (for interior points: ∫ B_I x_u ∧ x_v).
  Eigen::MatrixX3d gradient_rows(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const;
  /// k x 3 size of the terms of gradient_rows: ∫ |B_I| |x_u ∧ x_v| (componentwise) for interior
  /// points, the rows of gradient_scale() otherwise.
  Eigen::MatrixX3d gradient_scale_rows(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const;
  /// gradient_rows and gradient_scale_rows in one pass (either pointer may be null).
  void gradient_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                               Eigen::MatrixX3d* S) const;
  /// True when B_I vanishes on the boundary of the domain (triangular: every index >= 1;
  /// tensor: 1 <= i <= n-1 and 1 <= j <= m-1).
  /// Always false for an assembled form.
  bool interior(int I) const { return !assembly_ && interior_[static_cast<std::size_t>(I)] != 0; }

  /// Quadrature nodes' data, for callers that evaluate other integrands on the same rule.
  const Eigen::VectorXd& weights() const { return w_; }
  const Eigen::MatrixXd& basis() const { return B_; }
  const Eigen::MatrixXd& basis_u() const { return Bu_; }
  const Eigen::MatrixXd& basis_v() const { return Bv_; }

 private:
  void check(const Eigen::MatrixX3d& P) const;
  bool all_interior(const std::vector<int>& idx) const;
  Eigen::MatrixXd hessian_interior_triangular(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const;
  Eigen::MatrixXd hessian_interior_tensor(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const;
  bool triangular_ = true;
  int n_ = 1, m_ = 1;
  Eigen::VectorXd w_;
  Eigen::MatrixXd B_, Bu_, Bv_;  // #nodes x N: B_I, (B_I)_u, (B_I)_v at the nodes
  std::vector<char> interior_;
  // Fast interior Hessian data. Triangular: Du, Dv (count(n-1) x N) derivative nets and
  // Mt = ∫ B^{2n-1} B^{n-1} (count(2n-1) x count(n-1)); multinomials of degree n, n-1, 2n-1.
  // Tensor: Mu1 = ∫B^{2n}B^{n-1}, Mv1 = ∫B^{2m-1}B^m, Mu2 = ∫B^{2n-1}B^n, Mv2 = ∫B^{2m}B^{m-1}.
  Eigen::MatrixXd Du_, Dv_, Mt_;
  Eigen::VectorXd mult_n_, mult_n1_, mult_2n1_;
  Eigen::MatrixXd Mu1_, Mv1_, Mu2_, Mv2_;
  // Assembled forms (energies/assembled_forms.cpp): the patch's form and the maps; the tables above empty.
  std::shared_ptr<const VolumeForm> patch_;
  std::shared_ptr<const PatchAssembly> assembly_;
  double assembled_value(const Eigen::MatrixX3d& P, bool scale) const;
  Eigen::MatrixX3d assembled_gradient(const Eigen::MatrixX3d& P, bool scale) const;
  Eigen::MatrixXd assembled_hessian(const Eigen::MatrixX3d& P, const std::vector<int>& idx, bool quadrature) const;
  void assembled_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                                Eigen::MatrixX3d* S) const;
};

/// V = 1/3 ∫ <x_u ∧ x_v, x>, exact from the control net.
double volume(const TriangularNet& net);
double volume(const TensorNet& net);

/// C_IJK of the corrected eqs. (5)–(6) for a degree-n triangular net.
double volume_coefficient(int n, const std::array<int, 3>& I, const std::array<int, 3>& J, const std::array<int, 3>& K);

/// V = 1/6 sum C_IJK <P_I ∧ P_J, P_K> from the closed form, with C_IJK computed on the fly
/// (O(N^3) time, O(N) memory). For cross-checks; the quadrature route is faster.
double volume_closed_form(int n, const Eigen::MatrixX3d& P);

}  // namespace bpde
