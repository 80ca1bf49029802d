#pragma once
// Tensor-product B-spline surfaces (Sun–Zhu, B-spline Euler–Lagrange), in the layout of FORMATS.md.
//
//   x(u,v) = sum_{i<nu} sum_{j<nv} N_{i,p}(u) N_{j,q}(v) P_ij,  P_ij at row i*nv + j,
//   nu = len(U) - p - 1, nv = len(V) - q - 1; N_{i,p} has support [U_i, U_{i+p+1}] (standard
//   indexing, docs/errata.md). Domain [U_p, U_nu] x [V_q, V_nv].
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

#include "bezierpde/core/differential_geometry.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/core/mesh.h"

namespace bpde {

class BSplineNet {
 public:
  /// Scale rule of a knot vector K of degree k (count = len(K) - k - 1), checked with the other
  /// knot checks (ParameterError naming the knot or span):
  ///   |K_i| <= kMaxKnotMagnitude;
  ///   domain width K[count] - K[k] >= kMinDomainWidth and >= kMinDomainResolution * max |K_i|
  ///     (the domain holds at least ~1e8 distinct doubles);
  ///   every non-zero span K[i+1] - K[i] >= kMinSpanRatio * (K.back() - K.front()).
  /// Every width and parameter computed from such knots is finite (a span of ±1e308 overflowed to
  /// inf and gave NaN parameters), and the fundamental forms, which scale like width^-4, stay
  /// inside double's range.
  static constexpr double kMaxKnotMagnitude = 1e50;
  static constexpr double kMinDomainWidth = 1e-50;
  static constexpr double kMinDomainResolution = 1e-8;
  static constexpr double kMinSpanRatio = 1e-12;

  /// Validates (typed exceptions of core/errors.h): degrees 1..kMaxDegree (DegreeError); finite,
  /// non-decreasing knots with multiplicity <= degree + 1, at least degree + 1 control points per
  /// direction and a non-empty domain (ParameterError / SizeError), well scaled (the rule above,
  /// ParameterError); point count nu*nv (SizeError); finite coordinates (NonFiniteError).
  BSplineNet(int p, int q, std::vector<double> U, std::vector<double> V, Eigen::MatrixX3d points);

  int p() const { return p_; }
  int q() const { return q_; }
  int nu() const { return static_cast<int>(U_.size()) - p_ - 1; }
  int nv() const { return static_cast<int>(V_.size()) - q_ - 1; }
  int size() const { return nu() * nv(); }
  int index(int i, int j) const { return i * nv() + j; }
  const std::vector<double>& knots_u() const { return U_; }
  const std::vector<double>& knots_v() const { return V_; }
  const Eigen::MatrixX3d& points() const { return points_; }
  Eigen::MatrixX3d& points() { return points_; }
  double u_min() const { return U_[static_cast<size_t>(p_)]; }
  double u_max() const { return U_[static_cast<size_t>(nu())]; }
  double v_min() const { return V_[static_cast<size_t>(q_)]; }
  double v_max() const { return V_[static_cast<size_t>(nv())]; }

  /// Derivative of order (du, dv) at (u, v) in the knot domain (clamped to it; NonFiniteError for
  /// a non-finite u or v).
  Eigen::Vector3d derivative(double u, double v, int du, int dv) const;
  Eigen::Vector3d evaluate(double u, double v) const { return derivative(u, v, 0, 0); }
  /// x(u,v) by de Boor's algorithm (corner cutting in v on each of the p+1 active rows, then in
  /// u); the same surface as evaluate(), by an independent route.
  Eigen::Vector3d evaluate_de_boor(double u, double v) const;
  SurfaceJet jet(double u, double v) const;
  FundamentalForms geometry(double u, double v) const;

  /// The knot-vector checks of the constructor for one direction (degree k, knots K; dir names it
  /// in messages, e.g. "u"): DegreeError, NonFiniteError, SizeError, ParameterError.
  static void validate_knots(int k, const std::vector<double>& K, const char* dir);

  /// #t by n_basis table of the d-th derivatives of the basis functions (Piegl–Tiller A2.3) of
  /// one direction: knots K, degree k. Parameters are clamped to the domain; a non-finite
  /// parameter throws NonFiniteError (it has no span).
  static Eigen::MatrixXd basis_table(int k, const std::vector<double>& K, const Eigen::VectorXd& t, int d = 0);

  /// Indices (i, j) with min(i, nu-1-i, j, nv-1-j) == r.
  std::vector<int> ring_indices(int r) const;
  std::vector<int> fixed_indices(FixedSet fixed) const;
  std::vector<int> free_indices(FixedSet fixed) const;

 private:
  int p_, q_;
  std::vector<double> U_, V_;
  Eigen::MatrixX3d points_;
};

/// Sample on the (N+1)^2 grid mapped linearly onto the knot domain, in the tensor order
/// a(N+1)+b, with mean curvature per vertex.
TriangleMesh sample_mesh(const BSplineNet& net, int N);

}  // namespace bpde
