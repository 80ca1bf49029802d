#include "bezierpde/tensor/tensor_net.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/row_major_product.h"
#include "bezierpde/core/sample_progress.h"

namespace bpde {
namespace {

void check_degree(int d, const char* what) {
  if (d < 1 || d > kMaxDegree)
    throw DegreeError(std::string("tensor net: degree ") + what + " = " + std::to_string(d) + " is outside 1.." +
                      std::to_string(kMaxDegree));
}

// de Casteljau on the rows of a (deg+1) x 3 block (in place on a copy).
Eigen::Vector3d casteljau(std::vector<Eigen::Vector3d>& b, double t) {
  const int deg = static_cast<int>(b.size()) - 1;
  const double s = 1.0 - t;
  for (int r = 1; r <= deg; ++r)
    for (int i = 0; i <= deg - r; ++i)
      b[static_cast<size_t>(i)] = s * b[static_cast<size_t>(i)] + t * b[static_cast<size_t>(i) + 1];
  return b[0];
}

// Evaluate a raw (n+1)(m+1) x 3 net (degrees may be 0) at (u,v): de Casteljau along v in each
// row i, then along u on the column of row values.
Eigen::Vector3d eval_raw(const Eigen::MatrixX3d& P, int n, int m, double u, double v) {
  std::vector<Eigen::Vector3d> row(static_cast<size_t>(m + 1)), col(static_cast<size_t>(n + 1));
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= m; ++j) row[static_cast<size_t>(j)] = P.row(i * (m + 1) + j).transpose();
    col[static_cast<size_t>(i)] = casteljau(row, v);
  }
  return casteljau(col, u);
}

// Forward differences: derivative net of order (du, dv), degree (n-du, m-dv).
Eigen::MatrixX3d derivative_raw(const Eigen::MatrixX3d& P, int n, int m, int du, int dv) {
  Eigen::MatrixX3d cur = P;
  int cn = n, cm = m;
  for (int s = 0; s < du; ++s) {
    Eigen::MatrixX3d next(cn * (cm + 1), 3);
    for (int i = 0; i < cn; ++i)
      for (int j = 0; j <= cm; ++j)
        next.row(i * (cm + 1) + j) = cn * (cur.row((i + 1) * (cm + 1) + j) - cur.row(i * (cm + 1) + j));
    cur.swap(next);
    --cn;
  }
  for (int s = 0; s < dv; ++s) {
    Eigen::MatrixX3d next((cn + 1) * cm, 3);
    for (int i = 0; i <= cn; ++i)
      for (int j = 0; j < cm; ++j)
        next.row(i * cm + j) = cm * (cur.row(i * (cm + 1) + j + 1) - cur.row(i * (cm + 1) + j));
    cur.swap(next);
    --cm;
  }
  return cur;
}

}  // namespace

TensorNet::TensorNet(int n, int m) : n_(n), m_(m) {
  check_degree(n, "n");
  check_degree(m, "m");
  points_ = Eigen::MatrixX3d::Zero((n + 1) * (m + 1), 3);
}

TensorNet::TensorNet(int n, int m, Eigen::MatrixX3d points) : n_(n), m_(m), points_(std::move(points)) {
  check_degree(n, "n");
  check_degree(m, "m");
  const Eigen::Index want = static_cast<Eigen::Index>(n + 1) * (m + 1);
  if (points_.rows() != want)
    throw SizeError("tensor net of degree [" + std::to_string(n) + ", " + std::to_string(m) + "] needs " +
                    std::to_string(want) + " points, got " + std::to_string(points_.rows()));
  for (Eigen::Index r = 0; r < points_.rows(); ++r)
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(points_(r, c)))
        throw NonFiniteError("tensor net: point " + std::to_string(r) + " coordinate " + std::to_string(c) +
                             " is not finite");
}

Eigen::Vector3d TensorNet::evaluate(double u, double v) const { return eval_raw(points_, n_, m_, u, v); }

Eigen::MatrixX3d TensorNet::derivative_points(int du, int dv) const {
  if (du < 0 || dv < 0 || du > n_ || dv > m_)
    throw DegreeError("tensor net: derivative order (" + std::to_string(du) + ", " + std::to_string(dv) +
                      ") exceeds the degree (" + std::to_string(n_) + ", " + std::to_string(m_) + ")");
  return derivative_raw(points_, n_, m_, du, dv);
}

Eigen::Vector3d TensorNet::derivative(double u, double v, int du, int dv) const {
  if (du < 0 || dv < 0) throw DegreeError("tensor net: negative derivative order");
  if (du > n_ || dv > m_) return Eigen::Vector3d::Zero();
  return eval_raw(derivative_raw(points_, n_, m_, du, dv), n_ - du, m_ - dv, u, v);
}

SurfaceJet TensorNet::jet(double u, double v) const { return surface_jet(*this, u, v); }

FundamentalForms TensorNet::geometry(double u, double v) const { return fundamental_forms(jet(u, v)); }

TensorNet TensorNet::elevated(int dn, int dm) const {
  if (dn < 0 || dm < 0) throw DegreeError("tensor net: elevation by a negative amount");
  const Eigen::MatrixXd Eu = bernstein_elevation_operator(n_, dn);
  const Eigen::MatrixXd Ev = bernstein_elevation_operator(m_, dm);
  TensorNet out(n_ + dn, m_ + dm);
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd Pc(n_ + 1, m_ + 1);
    for (int i = 0; i <= n_; ++i)
      for (int j = 0; j <= m_; ++j) Pc(i, j) = points_(index(i, j), c);
    const Eigen::MatrixXd Q = Eu * Pc * Ev.transpose();
    for (int i = 0; i <= out.n(); ++i)
      for (int j = 0; j <= out.m(); ++j) out.points_(out.index(i, j), c) = Q(i, j);
  }
  return out;
}

Eigen::MatrixX3d TensorNet::evaluate_grid(const Eigen::VectorXd& us, const Eigen::VectorXd& vs, int du, int dv) const {
  Eigen::MatrixX3d out(us.size() * vs.size(), 3);
  if (du > n_ || dv > m_) {
    out.setZero();
    return out;
  }
  // Two row-major products per coordinate (core/row_major_product.h):
  //   T = P_c * Bv^T    ((n+1) x #vs),   X = Bu * T    (#us x #vs, row a = u_a),
  // and X is exactly out.col(c) read row-major (row index a * #vs + b).
  using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  const int nu = static_cast<int>(us.size()), nv = static_cast<int>(vs.size());
  const Eigen::MatrixXd BvT = bernstein_table(m_, vs, dv);  // #vs x (m+1) column-major = (m+1) x #vs row-major
  // #us x (n+1), row-major; the usual square grid (us = vs, same degree and order) reuses BvT.
  const RowMat Bu =
      (n_ == m_ && du == dv && us.size() == vs.size() && us == vs) ? RowMat(BvT) : RowMat(bernstein_table(n_, us, du));
  RowMat T(n_ + 1, nv);
  for (int c = 0; c < 3; ++c) {
    // Points are stored row-major by (i, j): column c is P_c, (n+1) x (m+1) row-major.
    row_major_product(points_.col(c).data(), n_ + 1, m_ + 1, m_ + 1, BvT.data(), nv, nv, T.data(), nv);
    row_major_product(Bu.data(), nu, n_ + 1, n_ + 1, T.data(), nv, nv, out.col(c).data(), nv);
  }
  return out;
}

std::vector<int> TensorNet::ring_indices(int r) const {
  std::vector<int> out;
  for (int i = 0; i <= n_; ++i)
    for (int j = 0; j <= m_; ++j)
      if (std::min({i, n_ - i, j, m_ - j}) == r) out.push_back(index(i, j));
  return out;
}

std::vector<int> TensorNet::fixed_indices(FixedSet fixed) const {
  std::vector<int> out;
  for (int i = 0; i <= n_; ++i)
    for (int j = 0; j <= m_; ++j) {
      const int d = std::min({i, n_ - i, j, m_ - j});
      bool take = false;
      switch (fixed) {
        case FixedSet::Boundary:
          take = d == 0;
          break;
        case FixedSet::BoundaryAdjacent:
          take = d <= 1;
          break;
        case FixedSet::UBoundaries:
          take = (i == 0 || i == n_);
          break;
      }
      if (take) out.push_back(index(i, j));
    }
  return out;
}

std::vector<int> TensorNet::free_indices(FixedSet fixed) const {
  return complement_indices(fixed_indices(fixed), size());
}

TriangleMesh sample_mesh(const TensorNet& net, int N) { return sample_mesh(net, N, ProgressFn{}); }

TriangleMesh sample_mesh(const TensorNet& net, int N, const ProgressFn& progress) {
  if (N < 1) throw ParameterError("sample_mesh: samples must be >= 1");
  Eigen::VectorXd t(N + 1);
  for (int a = 0; a <= N; ++a) t(a) = static_cast<double>(a) / N;
  int evaluations = 0;
  auto grid = [&](int du, int dv) {
    if (evaluations == 0) report(progress, kSamplingStage, 0.0, 1.0);
    Eigen::MatrixX3d X = net.evaluate_grid(t, t, du, dv);
    report(progress, kSamplingStage, sampling_fraction(++evaluations), 1.0);
    return X;
  };
  TriangleMesh mesh;
  mesh.V = grid(0, 0);
  const Eigen::MatrixX3d Xu = grid(1, 0), Xv = grid(0, 1), Xuu = grid(2, 0), Xuv = grid(1, 1), Xvv = grid(0, 2);
  mesh.H = sampled_mean_curvature(
      mesh.V, Xu, Xv, Xuu, Xuv, Xvv,
      [&](Eigen::Index k, double h) {
        const double u = t(k / (N + 1)), v = t(k % (N + 1));
        return net.geometry(u + h * (0.5 - u), v + h * (0.5 - v));
      },
      &mesh.regular);
  report(progress, kSamplingStage, 0.95, 1.0);
  mesh.F = grid_triangles(N);
  return mesh;
}

}  // namespace bpde
