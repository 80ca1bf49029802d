#pragma once
// The area A(x) = ∫ |x_u ∧ x_v| du dv of a triangular or tensor Bézier patch, with its exact
// gradient and Hessian with respect to the control points, by a fixed quadrature rule. This is the
// geometric half of A_H = A + 2HV (docs/cmc_algorithm.md, "The area functional A_H"); V is energies/volume.h.
//
// Conventions: triangular nets as triangular/triangular_net.h (barycentric order: i from n down to
// 0, then j from n-i down to 0, k = n-i-j; P_{n00} is row 0, P_{00n} the last row; the third index
// belongs to w = 1-u-v; derivatives in u and v); tensor nets as tensor/tensor_net.h (P_ij at row
// i(m+1)+j, i along u). Point matrices P are N x 3. Restricted gradients and Hessians over point
// indices idx use the entry 3a + c for (idx[a], coordinate c).
//
// With N = x_u ∧ x_v and n̂ = N/|N| (at each quadrature node):
//   dA/dP_L = ∫ (B_L)_u (x_v ∧ n̂) + (B_L)_v (n̂ ∧ x_u),
//   d²A/dP_I,c dP_L,d = ∫ <J_I e_c, (Id - n̂n̂ᵀ) J_L e_d>/|N| + ((B_I)_u (B_L)_v - (B_I)_v (B_L)_u) <n̂, e_c ∧ e_d>,
// where J_L = (B_L)_v [x_u]_x - (B_L)_u [x_v]_x is the Jacobian of N with respect to P_L. The first
// term is assembled as RᵀR with two rows per node (the two tangent directions t ⊥ n̂:
// R = √w <t, J_L e_c>/√|N|), one dense symmetric rank-k product; the second as three products
// Buᵀ diag(w n̂_k) Bv. Both are the exact derivatives of the quadrature value (tested against finite
// differences), so Newton on them converges quadratically to the critical point of the discrete A.
//
// The rules. A is not polynomial (|N| is a square root), so no rule is exact; the caller chooses q
// by the measured error (energies/area_rule.h). The rules are built so that the error falls
// exponentially in q also where |N| vanishes at a corner of the domain (the three arcs of the
// paper's Fig. 1 meet at 180°, so x_u ∥ x_v there):
//   - triangle: the six triangles cut by the centroid and the edge midpoints, each mapped from the
//     unit square by the Duffy map collapsed at its corner of T (u, v) = C + s(P1 - C) + s t(P2 - P1)
//     with q x q Gauss–Legendre points: 6q² nodes. Near a corner |N| ≈ |a u + b v| is homogeneous of
//     degree 1, which the collapse turns into s·(smooth).
//   - square: each quadrant (corner, edge midpoints, centre) split by its diagonal into two
//     triangles collapsed at the corner of the square: 8q² nodes.
//   - graded (grading p > 1, used by area_rule.h when the plain rule stalls): the radial Duffy
//     coordinate is s = σ^p, Gauss in σ. A corner that is only NEARLY degenerate (|N(corner)| = c
//     small but not 0: e.g. the circle's arcs fitted at degree 5 meet at 179.925°, c ≈ 1e-3 of the
//     mean |N|) puts a branch point of |N| ≈ √(c² + |a u + b v|²) at s ~ c from the corner; the
//     plain rule then converges only like ~exp(-2q√(2c)) (measured error at n = 5: 1.6e-10 at
//     q = 15, 1.1e-11 at q = 64). With s = σ³ the branch point sits at σ ~ c^(1/3) (0.1 at
//     n = 5), and the error is 3.6e-12 at q = 15, 9.5e-14 at q = 20 (docs/cmc_algorithm.md, "The area functional A_H"). An integrand analytic in s stays analytic in σ, so the graded rule also converges
//     exponentially where the plain one does, with about twice the points.
//   - geometric (levels L > 0, used by area_rule.h where the graded rule misses too): the radial
//     coordinate cut at s = ρ^k (ρ = 0.3, k = 1 … L), q Gauss points on each piece. A branch point
//     at distance c from the corner is at a fixed ratio of the length of every piece above it, so
//     the error falls exponentially in q for any c ≥ ρ^L; the graded rule needs q ~ c^(-1/3) there.
//     Measured on the triangular nets of smooth closed curves that the graded q = 64 rule misses
//     (docs/cmc_algorithm.md, "The area functional A_H").
// The node tables (Bernstein derivatives at the nodes, #nodes x N) are built once per
// (degree, q, grading).
//
// A node where |N| = 0 (a degenerate parametrisation) makes the gradient and Hessian non-finite:
// callers check min_normal() first (solvers/cmc/area/ reports it as not converged).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cstddef>
#include <memory>
#include <vector>

namespace bpde {

struct PatchAssembly;

class AreaForm {
 public:
  /// Degree-n triangular nets, q Gauss points per direction on each of the six sub-triangles,
  /// radial coordinate s = σ^grading, or (levels L > 0, grading 1) q points on each of the L + 1
  /// geometric pieces of s ("The rules" above; core/quadrature.h). DegreeError unless
  /// 1 <= n <= kMaxDegree; ParameterError unless 1 <= q <= 200, 1 <= grading <= 4,
  /// 0 <= levels <= kMaxGeometricLevels, and grading 1 where levels > 0.
  static AreaForm triangular(int n, int q, int grading = 1, int levels = 0);
  /// Degree-(n,m) tensor nets, q points per direction on each of the eight sub-triangles.
  static AreaForm tensor(int n, int m, int q, int grading = 1, int levels = 0);
  /// Shared, cached instances (thread-safe; the most recently used 32 (kind, degree, q, grading,
  /// levels) are kept).
  static std::shared_ptr<const AreaForm> cached_triangular(int n, int q, int grading = 1, int levels = 0);
  static std::shared_ptr<const AreaForm> cached_tensor(int n, int m, int q, int grading = 1, int levels = 0);

  /// A of a surface of several patches (energies/patch_assembly.h): the sum of `patch`'s A over
  /// the patches of `assembly`, on the #global x 3 points, with patch's rule (q, grading,
  /// levels). value, gradient and Hessian are the sums of the patch's through the local -> global
  /// maps; the scale of the gradient rows is the sum of the patches' scales; min_normal is the
  /// smallest of the patches' (each relative to its own patch's mean |N|).
  static AreaForm assembled(std::shared_ptr<const AreaForm> patch, std::shared_ptr<const PatchAssembly> assembly);
  /// The assembly of an assembled form (null for a single patch).
  const std::shared_ptr<const PatchAssembly>& assembly() const { return assembly_; }

  /// Number of control points N (assembled: the global points).
  int size() const;
  /// Number of quadrature nodes (assembled: over all patches).
  int nodes() const;
  /// Gauss points per direction of each sub-triangle.
  int points_per_direction() const { return q_; }
  /// The grading p of the radial coordinate (1: the plain collapsed rule).
  int grading() const { return grading_; }
  /// The geometric pieces of the radial coordinate beyond the first (0: the plain or graded rule).
  int levels() const { return levels_; }
  /// Whether two forms use the same rule (q, grading, levels).
  bool same_rule(const AreaForm& o) const { return q_ == o.q_ && grading_ == o.grading_ && levels_ == o.levels_; }
  std::size_t memory_bytes() const;

  /// A for the N x 3 points P (SizeError when P has the wrong number of rows).
  double value(const Eigen::MatrixX3d& P) const;
  /// min over the nodes of |x_u ∧ x_v| divided by the mean of |x_u ∧ x_v| = A / (domain area); 0
  /// when A = 0. A regular parametrisation keeps it away from 0 (except near degenerate corners,
  /// where the collapsed rules put nodes at distance ~1e-3 of the corner).
  double min_normal(const Eigen::MatrixX3d& P) const;
  /// N x 3 matrix of dA/dP_L.
  Eigen::MatrixX3d gradient(const Eigen::MatrixX3d& P) const;
  /// k x 3 rows idx of the gradient (G) and the size of their terms (S):
  /// S_L = ∫ |(B_L)_u| |x_v ∧ n̂| + |(B_L)_v| |n̂ ∧ x_u| (componentwise). Either pointer may be null.
  void gradient_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                               Eigen::MatrixX3d* S) const;
  /// 3k x 3k Hessian over the points idx (symmetric). Accumulated over blocks of at most 8192
  /// nodes in a per-thread scratch (2 × min(8192, #nodes) × 3k doubles and smaller tables: 2.9 MB
  /// at triangular n = 10 with q = 15, 17 MB with the graded q = 64 rule) that stays allocated
  /// between calls until release_scratch().
  Eigen::MatrixXd hessian(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const;
  /// Frees this thread's scratch: the Hessian's blocks and the per-node arrays (x_u, x_v, N, |N|
  /// and the gradient's products: 7 arrays of #nodes × 3 doubles and one of #nodes) that value, min_normal,
  /// gradient and hessian keep between calls (the area solve calls it when it ends).
  static void release_scratch();

 private:
  void check(const Eigen::MatrixX3d& P) const;
  int q_ = 1;
  int grading_ = 1;
  int levels_ = 0;
  Eigen::VectorXd w_;
  Eigen::MatrixXd Bu_, Bv_;  // #nodes x N: (B_I)_u, (B_I)_v at the nodes
  // Assembled forms (energies/assembled_forms.cpp): the patch's form and the maps; the tables above empty.
  std::shared_ptr<const AreaForm> patch_;
  std::shared_ptr<const PatchAssembly> assembly_;
  void assembled_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                                Eigen::MatrixX3d* S) const;
};

class TriangularNet;
class TensorNet;
/// A of a net to double precision on regular patches, by a ladder of the rules above (plain, on the
/// derivative nets): q = 10, 14, 19, 26, … (q + ⌈q/3⌉), the first rule whose value changes by at
/// most 1e-14 (relative) from the one before taken; the ladder ends at the rule q = 3n + 8 (n the
/// larger degree for tensor nets), whose value is returned where no earlier rule settles, and at
/// once where |x_u ∧ x_v| at a corner of the domain is below 0.1 x its mean (a degenerate or
/// nearly degenerate corner). tests/energies/test_area_functional.cpp.
double area(const TriangularNet& net);
double area(const TensorNet& net);

}  // namespace bpde
