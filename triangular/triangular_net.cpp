#include "bezierpde/triangular/triangular_net.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/binomial.h"
#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

void check_degree(int n) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError("triangular net: degree " + std::to_string(n) + " is outside 1.." + std::to_string(kMaxDegree));
}

// de Casteljau on a raw degree-n net (n may be 0).
Eigen::Vector3d eval_raw(const Eigen::MatrixX3d& P, int n, double u, double v) {
  const double w = 1.0 - u - v;
  Eigen::MatrixX3d b = P;
  for (int d = n; d >= 1; --d) {
    Eigen::MatrixX3d next(TriangularNet::count(d - 1), 3);
    for (int i = 0; i <= d - 1; ++i)
      for (int j = 0; j <= d - 1 - i; ++j)
        next.row(TriangularNet::index(d - 1, i, j)) = u * b.row(TriangularNet::index(d, i + 1, j)) +
                                                      v * b.row(TriangularNet::index(d, i, j + 1)) +
                                                      w * b.row(TriangularNet::index(d, i, j));
    b.swap(next);
  }
  return b.row(0).transpose();
}

// One derivative along u (dir = 0) or v (dir = 1): Q_J = n (P_{J+e_dir} - P_{J+e3}).
Eigen::MatrixX3d differentiate_raw(const Eigen::MatrixX3d& P, int n, int dir) {
  Eigen::MatrixX3d Q(TriangularNet::count(n - 1), 3);
  for (int i = 0; i <= n - 1; ++i)
    for (int j = 0; j <= n - 1 - i; ++j) {
      const int plus = dir == 0 ? TriangularNet::index(n, i + 1, j) : TriangularNet::index(n, i, j + 1);
      Q.row(TriangularNet::index(n - 1, i, j)) = n * (P.row(plus) - P.row(TriangularNet::index(n, i, j)));
    }
  return Q;
}

}  // namespace

TriangularNet::TriangularNet(int n) : n_(n) {
  check_degree(n);
  points_ = Eigen::MatrixX3d::Zero(count(n), 3);
}

TriangularNet::TriangularNet(int n, Eigen::MatrixX3d points) : n_(n), points_(std::move(points)) {
  check_degree(n);
  if (points_.rows() != count(n))
    throw SizeError("triangular net of degree " + std::to_string(n) + " needs " + std::to_string(count(n)) +
                    " points, got " + std::to_string(points_.rows()));
  for (Eigen::Index r = 0; r < points_.rows(); ++r)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(points_(r, c)))
        throw NonFiniteError("triangular net: point " + std::to_string(r) + " coordinate " + std::to_string(c) +
                             " is not finite");
}

MultiIndex TriangularNet::multi_index(int n, int r) {
  // rows s(s+1)/2 .. s(s+1)/2 + s belong to i = n - s, with j = s - offset.
  int s = 0;
  while ((s + 1) * (s + 2) / 2 <= r) ++s;
  const int off = r - s * (s + 1) / 2;
  const int i = n - s, j = s - off;
  return {i, j, n - i - j};
}

Eigen::Vector3d TriangularNet::evaluate(double u, double v) const { return eval_raw(points_, n_, u, v); }

Eigen::MatrixX3d TriangularNet::derivative_points(int du, int dv) const {
  if (du < 0 || dv < 0 || du + dv > n_)
    throw DegreeError("triangular net: derivative order " + std::to_string(du + dv) + " exceeds the degree " +
                      std::to_string(n_));
  Eigen::MatrixX3d P = points_;
  int d = n_;
  for (int s = 0; s < du; ++s) P = differentiate_raw(P, d--, 0);
  for (int s = 0; s < dv; ++s) P = differentiate_raw(P, d--, 1);
  return P;
}

Eigen::Vector3d TriangularNet::derivative(double u, double v, int du, int dv) const {
  if (du < 0 || dv < 0) throw DegreeError("triangular net: negative derivative order");
  if (du + dv > n_) return Eigen::Vector3d::Zero();
  return eval_raw(derivative_points(du, dv), n_ - du - dv, u, v);
}

Eigen::Vector3d TriangularNet::directional_derivative(double u, double v, const Eigen::Vector2d& d) const {
  return d(0) * derivative(u, v, 1, 0) + d(1) * derivative(u, v, 0, 1);
}

SurfaceJet TriangularNet::jet(double u, double v) const { return surface_jet(*this, u, v); }

FundamentalForms TriangularNet::geometry(double u, double v) const { return fundamental_forms(jet(u, v)); }

TriangularNet TriangularNet::elevated(int r) const {
  if (r < 0) throw DegreeError("triangular net: elevation by a negative amount");
  if (n_ + r > kMaxDegree) throw DegreeError("triangular net: elevated degree exceeds " + std::to_string(kMaxDegree));
  Eigen::MatrixX3d P = points_;
  for (int d = n_; d < n_ + r; ++d) {
    // degree d -> d+1: Q_I = (i P_{I-e1} + j P_{I-e2} + k P_{I-e3}) / (d+1)
    Eigen::MatrixX3d Q = Eigen::MatrixX3d::Zero(count(d + 1), 3);
    for (int i = 0; i <= d + 1; ++i)
      for (int j = 0; j <= d + 1 - i; ++j) {
        const int k = d + 1 - i - j;
        Eigen::RowVector3d q = Eigen::RowVector3d::Zero();
        if (i > 0) q += i * P.row(index(d, i - 1, j));
        if (j > 0) q += j * P.row(index(d, i, j - 1));
        if (k > 0) q += k * P.row(index(d, i, j));
        Q.row(index(d + 1, i, j)) = q / (d + 1);
      }
    P.swap(Q);
  }
  return TriangularNet(n_ + r, P);
}

// Column by column: each column B_I is contiguous over the points, so the products vectorise over
// them (the row-by-row fill wrote with a stride of #uv: 3-5x slower at n = 6 ... 16 and 8x in the
// 1024-row blocks of the report's area, docs/performance_measurements.md, "Design decisions"). Same products in the
// same order, so the same numbers: coefficient * u^i * v^j * w^k.
Eigen::MatrixXd TriangularNet::basis_matrix(int n, const Eigen::MatrixX2d& uv) {
  const Eigen::Index S = uv.rows();
  Eigen::MatrixXd B(S, count(n));
  Eigen::ArrayXXd pu(S, n + 1), pv(S, n + 1), pw(S, n + 1);  // powers 0..n of u, v, w at each point
  const Eigen::ArrayXd w = 1.0 - uv.col(0).array() - uv.col(1).array();
  pu.col(0).setOnes();
  pv.col(0).setOnes();
  pw.col(0).setOnes();
  for (int e = 1; e <= n; ++e) {
    pu.col(e) = pu.col(e - 1) * uv.col(0).array();
    pv.col(e) = pv.col(e - 1) * uv.col(1).array();
    pw.col(e) = pw.col(e - 1) * w;
  }
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n - i; ++j)
      B.col(index(n, i, j)).array() = multinomial(n, i, j) * pu.col(i) * pv.col(j) * pw.col(n - i - j);
  return B;
}

Eigen::MatrixX3d TriangularNet::evaluate_many(const Eigen::MatrixX2d& uv) const {
  return basis_matrix(n_, uv) * points_;
}

std::vector<int> TriangularNet::ring_indices(int r) const {
  std::vector<int> out;
  for (int row = 0; row < size(); ++row) {
    const MultiIndex I = multi_index(n_, row);
    if (std::min({I[0], I[1], I[2]}) == r) out.push_back(row);
  }
  return out;
}

std::vector<int> TriangularNet::fixed_indices(FixedSet fixed) const {
  if (fixed == FixedSet::UBoundaries)
    throw UnsupportedProblem("fixed \"u-boundaries\" is defined for tensor nets only, not triangular nets");
  const int limit = fixed == FixedSet::Boundary ? 0 : 1;
  std::vector<int> out;
  for (int row = 0; row < size(); ++row) {
    const MultiIndex I = multi_index(n_, row);
    if (std::min({I[0], I[1], I[2]}) <= limit) out.push_back(row);
  }
  return out;
}

std::vector<int> TriangularNet::free_indices(FixedSet fixed) const {
  return complement_indices(fixed_indices(fixed), size());
}

Eigen::MatrixX2d triangular_sample_parameters(int N) {
  if (N < 1) throw ParameterError("triangular sampling: samples must be >= 1");
  Eigen::MatrixX2d uv((N + 1) * (N + 2) / 2, 2);
  int k = 0;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N - a; ++b) {
      uv(k, 0) = static_cast<double>(a) / N;
      uv(k, 1) = static_cast<double>(b) / N;
      ++k;
    }
  return uv;
}

TriangleMesh sample_mesh(const TriangularNet& net, int N) {
  const Eigen::MatrixX2d uv = triangular_sample_parameters(N);
  const int n = net.n();
  TriangleMesh mesh;
  mesh.V = net.evaluate_many(uv);
  auto deriv_values = [&](int du, int dv) -> Eigen::MatrixX3d {
    if (du + dv > n) return Eigen::MatrixX3d::Zero(uv.rows(), 3);
    return TriangularNet::basis_matrix(n - du - dv, uv) * net.derivative_points(du, dv);
  };
  const Eigen::MatrixX3d Xu = deriv_values(1, 0), Xv = deriv_values(0, 1), Xuu = deriv_values(2, 0),
                         Xuv = deriv_values(1, 1), Xvv = deriv_values(0, 2);
  mesh.H = sampled_mean_curvature(
      mesh.V, Xu, Xv, Xuu, Xuv, Xvv,
      [&](Eigen::Index k, double h) {
        const double u = uv(k, 0), v = uv(k, 1);
        return net.geometry(u + h * (1.0 / 3 - u), v + h * (1.0 / 3 - v));
      },
      &mesh.regular);
  auto vid = [N](int a, int b) { return a * (N + 1) - a * (a - 1) / 2 + b; };
  mesh.F.resize(N * N, 3);
  int f = 0;
  for (int a = 0; a < N; ++a)
    for (int b = 0; b < N - a; ++b) {
      mesh.F.row(f++) << vid(a, b), vid(a + 1, b), vid(a, b + 1);
      if (b < N - a - 1) mesh.F.row(f++) << vid(a + 1, b), vid(a + 1, b + 1), vid(a, b + 1);
    }
  return mesh;
}

}  // namespace bpde
