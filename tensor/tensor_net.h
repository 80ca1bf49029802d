#pragma once
// Tensor-product Bézier patches.
//
// Conventions (FORMATS.md):
//   x(u,v) = sum_{i=0..n} sum_{j=0..m} B_i^n(u) B_j^m(v) P_ij   on [0,1]^2,
//   P_ij is row i*(m+1) + j of the (n+1)(m+1) by 3 point matrix; i runs along u, j along v.
//   Orientation: P_00 -> P_n0 -> P_nn -> P_0n counter-clockwise seen from +z gives
//   x_u ^ x_v pointing to +z.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

#include "bezierpde/core/differential_geometry.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/mesh.h"

namespace bpde {

class TensorNet {
 public:
  /// Degree (1,1) net with zero points.
  TensorNet() : TensorNet(1, 1) {}
  /// Degree (n,m) net with zero points. Throws DegreeError unless 1 <= n, m <= kMaxDegree.
  TensorNet(int n, int m);
  /// Degree (n,m) net with the given (n+1)(m+1) by 3 points. Throws DegreeError, SizeError
  /// (wrong row count) or NonFiniteError (a NaN or infinite coordinate, naming its index).
  TensorNet(int n, int m, Eigen::MatrixX3d points);

  int n() const { return n_; }
  int m() const { return m_; }
  int size() const { return (n_ + 1) * (m_ + 1); }
  int index(int i, int j) const { return i * (m_ + 1) + j; }

  const Eigen::MatrixX3d& points() const { return points_; }
  /// Mutable access; the caller keeps the values finite.
  Eigen::MatrixX3d& points() { return points_; }
  Eigen::Vector3d point(int i, int j) const { return points_.row(index(i, j)).transpose(); }
  void set_point(int i, int j, const Eigen::Vector3d& p) { points_.row(index(i, j)) = p.transpose(); }

  /// x(u,v) by de Casteljau (rows first, then the column of results).
  Eigen::Vector3d evaluate(double u, double v) const;
  /// d^(du+dv) x / du^du dv^dv at (u,v): de Casteljau on the derivative net. Zero if du > n or dv > m.
  Eigen::Vector3d derivative(double u, double v, int du, int dv) const;
  /// Control points of the derivative net, degree (n-du, m-dv), in the same layout
  /// ((n-du+1)(m-dv+1) by 3). Requires du <= n and dv <= m (DegreeError otherwise).
  Eigen::MatrixX3d derivative_points(int du, int dv) const;
  /// Position and derivatives up to order two.
  SurfaceJet jet(double u, double v) const;
  /// Normal, fundamental forms, K and H at (u,v).
  FundamentalForms geometry(double u, double v) const;

  /// The same surface at degree (n+dn, m+dm).
  TensorNet elevated(int dn, int dm) const;

  /// Values (or derivatives of order (du,dv)) on the grid us x vs, using one Bernstein table per
  /// direction and two small matrix products per coordinate. Row a*#vs + b is (us(a), vs(b)).
  Eigen::MatrixX3d evaluate_grid(const Eigen::VectorXd& us, const Eigen::VectorXd& vs, int du = 0, int dv = 0) const;

  /// Indices of the ring at distance r from the border: points with min(i, n-i, j, m-j) == r.
  std::vector<int> ring_indices(int r) const;
  /// The outer ring (r = 0), in increasing index order.
  std::vector<int> boundary_indices() const { return ring_indices(0); }
  /// The ring next to the boundary (r = 1).
  std::vector<int> adjacent_ring_indices() const { return ring_indices(1); }
  /// Indices prescribed by a `fixed` set (FORMATS.md), increasing. UBoundaries: rows i=0, i=n.
  std::vector<int> fixed_indices(FixedSet fixed) const;
  /// The complement of fixed_indices, increasing.
  std::vector<int> free_indices(FixedSet fixed) const;

 private:
  int n_ = 1, m_ = 1;
  Eigen::MatrixX3d points_;
};

/// Sample the patch on the (N+1)^2 grid u = a/N, v = b/N (index a(N+1)+b), with 2N^2 triangles
/// and the mean curvature at every vertex. Requires N >= 1.
TriangleMesh sample_mesh(const TensorNet& net, int N);

}  // namespace bpde
