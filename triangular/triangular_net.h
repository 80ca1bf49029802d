#pragma once
// Triangular Bézier patches.
//
// Conventions (FORMATS.md, docs/errata.md):
//   x(u,v) = sum_{|I|=n} P_I B_I^n(u,v,w),  B_I^n = n!/(i! j! k!) u^i v^j w^k,  w = 1 - u - v,
//   on T = {u, v >= 0, u + v <= 1}. The first index belongs to u, the second to v, the third to w.
//   Barycentric order of the points: i from n down to 0; for each i, j from n-i down to 0
//   (k = n-i-j). P_{n00} is row 0 and P_{00n} the last row:
//     index(i, j) = s(s+1)/2 + (s - j),  s = n - i.
//   Corners: P_{n00} = x(1,0), P_{0n0} = x(0,1), P_{00n} = x(0,0).
//   Orientation: P_{00n} -> P_{n00} -> P_{0n0} counter-clockwise seen from +z makes x_u ^ x_v
//   point to +z.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <array>
#include <vector>

#include "bezierpde/core/differential_geometry.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/mesh.h"

namespace bpde {

/// A barycentric multi-index (i, j, k) with i + j + k = n.
using MultiIndex = std::array<int, 3>;

class TriangularNet {
 public:
  /// Degree 1 net with zero points.
  TriangularNet() : TriangularNet(1) {}
  /// Degree n net with zero points. Throws DegreeError unless 1 <= n <= kMaxDegree.
  explicit TriangularNet(int n);
  /// Degree n with (n+1)(n+2)/2 by 3 points. Throws DegreeError, SizeError or NonFiniteError.
  TriangularNet(int n, Eigen::MatrixX3d points);

  /// Number of control points of degree n: (n+1)(n+2)/2.
  static int count(int n) { return (n + 1) * (n + 2) / 2; }
  /// Row of P_{ijk} (k = n-i-j) in a degree-n net.
  static int index(int n, int i, int j) {
    const int s = n - i;
    return s * (s + 1) / 2 + (s - j);
  }
  /// Multi-index of row r in a degree-n net.
  static MultiIndex multi_index(int n, int r);

  int n() const { return n_; }
  int size() const { return count(n_); }
  int index(int i, int j) const { return index(n_, i, j); }

  const Eigen::MatrixX3d& points() const { return points_; }
  Eigen::MatrixX3d& points() { return points_; }
  Eigen::Vector3d point(int i, int j) const { return points_.row(index(i, j)).transpose(); }
  void set_point(int i, int j, const Eigen::Vector3d& p) { points_.row(index(i, j)) = p.transpose(); }

  /// x(u,v) by de Casteljau with barycentric weights (u, v, 1-u-v).
  Eigen::Vector3d evaluate(double u, double v) const;
  /// Partial derivative d^(du+dv) x / du^du dv^dv (u and v as the two free parameters, w = 1-u-v):
  ///   x_u = n sum_{|J|=n-1} (P_{J+e1} - P_{J+e3}) B_J^{n-1},  x_v likewise with e2.
  Eigen::Vector3d derivative(double u, double v, int du, int dv) const;
  /// Directional derivative along the parameter direction d = (du, dv): d0 x_u + d1 x_v.
  Eigen::Vector3d directional_derivative(double u, double v, const Eigen::Vector2d& d) const;
  /// Control points (degree n-du-dv, same barycentric order) of the partial derivative net.
  Eigen::MatrixX3d derivative_points(int du, int dv) const;
  SurfaceJet jet(double u, double v) const;
  FundamentalForms geometry(double u, double v) const;

  /// The same surface at degree n + r.
  TriangularNet elevated(int r) const;

  /// #uv by (n+1)(n+2)/2 matrix of B_I^n at the parameter points (rows of uv: (u, v)).
  static Eigen::MatrixXd basis_matrix(int n, const Eigen::MatrixX2d& uv);
  /// Evaluate at many points: basis_matrix(uv) * points.
  Eigen::MatrixX3d evaluate_many(const Eigen::MatrixX2d& uv) const;

  /// Points whose smallest index equals r (r = 0: the boundary, some index 0).
  std::vector<int> ring_indices(int r) const;
  std::vector<int> boundary_indices() const { return ring_indices(0); }
  std::vector<int> adjacent_ring_indices() const { return ring_indices(1); }
  /// Prescribed points: Boundary -> smallest index 0; BoundaryAdjacent -> smallest index <= 1.
  /// UBoundaries is not defined for triangular nets (UnsupportedProblem).
  std::vector<int> fixed_indices(FixedSet fixed) const;
  std::vector<int> free_indices(FixedSet fixed) const;

 private:
  int n_ = 1;
  Eigen::MatrixX3d points_;
};

/// The parameter points u = a/N, v = b/N with a + b <= N, in the order a = 0..N and, within each
/// a, b = 0..N-a ((N+1)(N+2)/2 rows).
Eigen::MatrixX2d triangular_sample_parameters(int N);

/// Sample on triangular_sample_parameters(N), N^2 triangles, mean curvature at every vertex.
TriangleMesh sample_mesh(const TriangularNet& net, int N);

}  // namespace bpde
