#include "bezierpde/energies/mean_curvature_least_squares.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <ceres/jet.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/columns3.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/energies/patch_assembly.h"

namespace bpde {
namespace {

// r = √(w |N|) (H_x − H) from the jet (x_u, x_v, x_uu, x_uv, x_vv) = j[0..14]; N = x_u ∧ x_v and
// H_x = (⟨x_uu,N⟩G − 2⟨x_uv,N⟩F + ⟨x_vv,N⟩E) / (2|N|³) (core/differential_geometry.h, with the
// unit normal written as N/|N|).
template <class T>
T residual_from_jet(const T* j, double H, double w) {
  using std::sqrt;
  const T* xu = j;
  const T* xv = j + 3;
  const T N[3] = {xu[1] * xv[2] - xu[2] * xv[1], xu[2] * xv[0] - xu[0] * xv[2], xu[0] * xv[1] - xu[1] * xv[0]};
  auto dot = [](const T* a, const T* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
  const T n2 = dot(N, N), nn = sqrt(n2);
  const T E = dot(xu, xu), F = dot(xu, xv), G = dot(xv, xv);
  const T e = dot(j + 6, N), f = dot(j + 9, N), g = dot(j + 12, N);
  const T Hx = (e * G - 2.0 * f * F + g * E) / (2.0 * n2 * nn);
  return sqrt(w * nn) * (Hx - H);
}

// The rule's weights times the corner weight ρ = Π_c (1 − λ_c^8)^4 (mean_curvature_least_squares.h):
// λ_c the barycentric coordinates (u, v, 1 - u - v) on the triangle, the bilinear corner
// functions on the square.
Eigen::VectorXd weighted(const QuadratureRuleTriangle& rule, bool square) {
  Eigen::VectorXd w = rule.w;
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    const double u = rule.uv(i, 0), v = rule.uv(i, 1);
    const std::array<double, 4> lambda =
        square ? std::array<double, 4>{(1 - u) * (1 - v), u * (1 - v), u * v, (1 - u) * v}
               : std::array<double, 4>{u, v, 1.0 - u - v, 0.0};
    for (int c = 0; c < (square ? 4 : 3); ++c) {
      const double l2 = lambda[size_t(c)] * lambda[size_t(c)], l8 = (l2 * l2) * (l2 * l2);
      const double f = 1.0 - l8, f2 = f * f;
      w(i) *= f2 * f2;
    }
  }
  return w;
}

// A regular node: |x_u ∧ x_v| > 1e-14 |x_u||x_v| (a singular one contributes r = 0). Not finite
// derivatives are neither (their node gets r = NaN, so Φ is NaN, never a silent 0).
bool singular(const Eigen::Vector3d& xu, const Eigen::Vector3d& xv) {
  return xu.allFinite() && xv.allFinite() && !(xu.cross(xv).norm() > 1e-14 * xu.norm() * xv.norm());
}

// The rule with the corner weight, after the degree and q checks (the rule checks q <= 200).
QuadratureRuleTriangle checked_rule(bool square, int n, int m, int q, Eigen::VectorXd& w) {
  if (n < 2 || m < 2 || n > kMaxDegree || m > kMaxDegree)
    throw DegreeError(std::string("mean-curvature least squares: ") + (square ? "tensor degrees" : "triangular degree") +
                      " must be in 2.." + std::to_string(kMaxDegree));
  if (q < 2) throw ParameterError("mean-curvature least squares: q must be >= 2");
  const QuadratureRuleTriangle rule = square ? corner_collapsed_square_rule(q) : corner_collapsed_triangle_rule(q);
  w = weighted(rule, square);
  return rule;
}

}  // namespace

MeanCurvatureLeastSquares MeanCurvatureLeastSquares::triangular(int n, int q) {
  MeanCurvatureLeastSquares f;
  f.q_ = q;
  f.n_ = f.m_ = n;
  const QuadratureRuleTriangle rule = checked_rule(false, n, n, q, f.w_);
  const int du[5] = {1, 0, 2, 1, 0}, dv[5] = {0, 1, 0, 1, 2};
  for (size_t t = 0; t < 5; ++t) f.D_[t] = triangular_basis_table(n, rule.uv, du[t], dv[t]);
  return f;
}

MeanCurvatureLeastSquares MeanCurvatureLeastSquares::tensor(int n, int m, int q) {
  MeanCurvatureLeastSquares f;
  f.q_ = q;
  f.square_ = true;
  f.n_ = n;
  f.m_ = m;
  const QuadratureRuleTriangle rule = checked_rule(true, n, m, q, f.w_);
  const Eigen::VectorXd us = rule.uv.col(0), vs = rule.uv.col(1);
  std::array<Eigen::MatrixXd, 3> U, V;
  for (int d = 0; d <= 2; ++d) {
    U[size_t(d)] = bernstein_table(n, us, d);
    V[size_t(d)] = bernstein_table(m, vs, d);
  }
  const int du[5] = {1, 0, 2, 1, 0}, dv[5] = {0, 1, 0, 1, 2};
  for (size_t t = 0; t < 5; ++t) {
    f.D_[t].resize(rule.w.size(), (n + 1) * (m + 1));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= m; ++j)
        f.D_[t].col(i * (m + 1) + j) = U[size_t(du[t])].col(i).cwiseProduct(V[size_t(dv[t])].col(j));
  }
  return f;
}

MeanCurvatureLeastSquares MeanCurvatureLeastSquares::assembled(std::shared_ptr<const MeanCurvatureLeastSquares> patch,
                                                               std::shared_ptr<const PatchAssembly> assembly) {
  if (!patch || !assembly || patch->assembly_)
    throw ParameterError("MeanCurvatureLeastSquares::assembled: needs a single-patch form and an assembly");
  if (assembly->patch_size != patch->size())
    throw SizeError("MeanCurvatureLeastSquares::assembled: the assembly's patches have " +
                    std::to_string(assembly->patch_size) + " points, the patch form " + std::to_string(patch->size()));
  for (const auto& map : assembly->maps) {
    if (static_cast<int>(map.size()) != patch->size())
      throw SizeError("MeanCurvatureLeastSquares::assembled: a patch map has the wrong size");
    for (int r : map)
      if (r < 0 || r >= assembly->size) throw SizeError("MeanCurvatureLeastSquares::assembled: a patch map row is out of range");
  }
  // find_seams tells an edge's points by their basis values at t = 0.37 along it, at least 0.37^n
  // (4.6e-11 at n = 24) against rounding below n·1e-16 off the edge: degree 24 keeps the two
  // apart by more than 1e-13 on both sides.
  if (std::max(patch->n_, patch->m_) > 24)
    throw DegreeError("MeanCurvatureLeastSquares::assembled: patches of degree at most 24, got " +
                      std::to_string(std::max(patch->n_, patch->m_)));
  MeanCurvatureLeastSquares f;
  f.q_ = patch->q_;
  f.square_ = patch->square_;
  f.n_ = patch->n_;
  f.m_ = patch->m_;
  f.patch_ = std::move(patch);
  f.assembly_ = std::move(assembly);
  f.find_seams();
  return f;
}

namespace {

// The basis of a patch (triangular of degree n, or tensor (n, m)) differentiated du, dv times at the
// points uv (#points by patch points, the net's order).
Eigen::MatrixXd basis_at(bool square, int n, int m, const Eigen::MatrixX2d& uv, int du, int dv) {
  if (!square) return triangular_basis_table(n, uv, du, dv);
  const Eigen::MatrixXd U = bernstein_table(n, uv.col(0), du), V = bernstein_table(m, uv.col(1), dv);
  Eigen::MatrixXd B(uv.rows(), (n + 1) * (m + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) B.col(i * (m + 1) + j) = U.col(i).cwiseProduct(V.col(j));
  return B;
}

// An edge of the domain: (u, v)(t) = (u0 + t du, v0 + t dv), and +1 when t runs along the domain's
// counter-clockwise boundary, −1 against it.
struct DomainEdge {
  double u0, v0, du, dv;
  int ccw;
};
const std::vector<DomainEdge>& domain_edges(bool square) {
  static const std::vector<DomainEdge> tri = {{0, 0, 1, 0, 1}, {1, 0, -1, 1, 1}, {0, 0, 0, 1, -1}};
  static const std::vector<DomainEdge> sq = {{0, 0, 1, 0, 1}, {1, 0, 0, 1, 1}, {0, 1, 1, 0, -1}, {0, 0, 0, 1, -1}};
  return square ? sq : tri;
}
Eigen::MatrixX2d edge_points(const DomainEdge& e, const Eigen::VectorXd& t) {
  Eigen::MatrixX2d uv(t.size(), 2);
  for (Eigen::Index i = 0; i < t.size(); ++i) uv.row(i) << e.u0 + t(i) * e.du, e.v0 + t(i) * e.dv;
  return uv;
}

// n = x_u ∧ x_v / |x_u ∧ x_v| from the jet (x_u, x_v) = j[0..5].
template <class T>
void unit_normal(const T* j, T* n) {
  using std::sqrt;
  const T* xu = j;
  const T* xv = j + 3;
  const T N[3] = {xu[1] * xv[2] - xu[2] * xv[1], xu[2] * xv[0] - xu[0] * xv[2], xu[0] * xv[1] - xu[1] * xv[0]};
  const T nn = sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
  for (int c = 0; c < 3; ++c) n[c] = N[c] / nn;
}

}  // namespace

// The inner edges: an edge of a patch's domain carries the control points where the basis does
// not vanish on it (n + 1 of them); two patches whose edges carry the same n + 1 distinct global
// points share that edge. t of one patch is t or 1 − t of the other (by the global point at t = 0);
// the orientations agree when the two run along it in opposite directions on their
// counter-clockwise boundaries.
void MeanCurvatureLeastSquares::find_seams() {
  const PatchAssembly& a = *assembly_;
  const std::vector<DomainEdge>& edges = domain_edges(square_);
  struct Found {
    std::vector<int> key;  // the global points, sorted
    int patch, edge, start, end;
  };
  std::vector<Found> found;
  Eigen::VectorXd probe(3);
  probe << 0.0, 0.37, 1.0;
  for (int p = 0; p < a.patches(); ++p) {
    const std::vector<int>& map = a.maps[size_t(p)];
    for (int e = 0; e < int(edges.size()); ++e) {
      const Eigen::MatrixXd B = basis_at(square_, n_, m_, edge_points(edges[size_t(e)], probe), 0, 0);
      Found f{{}, p, e, -1, -1};
      for (Eigen::Index l = 0; l < B.cols(); ++l) {
        if (std::abs(B(1, l)) > 1e-13) f.key.push_back(map[size_t(l)]);
        if (B(0, l) > 0.5) f.start = map[size_t(l)];
        if (B(2, l) > 0.5) f.end = map[size_t(l)];
      }
      std::sort(f.key.begin(), f.key.end());
      const size_t count = f.key.size();
      f.key.erase(std::unique(f.key.begin(), f.key.end()), f.key.end());
      if (f.key.size() == count && count >= 2 && f.start != f.end) found.push_back(std::move(f));
    }
  }
  std::sort(found.begin(), found.end(), [](const Found& x, const Found& y) { return x.key < y.key; });
  const QuadratureRule1D g = gauss_legendre01(q_);
  const Eigen::VectorXd back = Eigen::VectorXd::Ones(g.x.size()) - g.x;
  for (size_t i = 0, run = 1; i + 1 < found.size(); i += run) {
    run = 1;  // the patches that have this edge: a seam only where exactly two do
    while (i + run < found.size() && found[i + run].key == found[i].key) ++run;
    if (run != 2) continue;
    const Found &x = found[i], &y = found[i + 1];
    if (x.patch == y.patch) continue;
    const DomainEdge &ex = edges[size_t(x.edge)], &ey = edges[size_t(y.edge)];
    const bool same_start = x.start == y.start;
    Seam s;
    s.p = x.patch;
    s.q = y.patch;
    s.w = g.w;
    const Eigen::MatrixX2d uv_p = edge_points(ex, g.x), uv_q = edge_points(ey, same_start ? g.x : back);
    s.Bu_p = basis_at(square_, n_, m_, uv_p, 1, 0);
    s.Bv_p = basis_at(square_, n_, m_, uv_p, 0, 1);
    s.Bu_q = basis_at(square_, n_, m_, uv_q, 1, 0);
    s.Bv_q = basis_at(square_, n_, m_, uv_q, 0, 1);
    // Counter-clockwise directions along the global edge: x from start to end when ex.ccw > 0.
    const int dir_x = ex.ccw, dir_y = same_start ? ey.ccw : -ey.ccw;
    s.sign = dir_x == -dir_y ? 1.0 : -1.0;
    seams_.push_back(std::move(s));
  }
}

int MeanCurvatureLeastSquares::size() const {
  return assembly_ ? assembly_->size : static_cast<int>(w_.size() ? D_[0].cols() : 0);
}
int MeanCurvatureLeastSquares::nodes() const {
  if (!assembly_) return static_cast<int>(w_.size());
  int seam_rows = 0;
  for (const Seam& s : seams_) seam_rows += 3 * static_cast<int>(s.w.size());
  return patch_->nodes() * assembly_->patches() + seam_rows;
}

void MeanCurvatureLeastSquares::check_single(const char* what) const {
  if (assembly_)
    throw UnsupportedProblem(std::string("mean-curvature least squares: ") + what +
                             " is the patch form's (patch_form()), not the assembled form's");
}

MeanCurvatureLeastSquares::NodeDerivatives MeanCurvatureLeastSquares::derivatives(const Eigen::MatrixX3d& P) const {
  check_single("derivatives");
  if (P.rows() != size()) throw SizeError("mean-curvature least squares: the net has the wrong number of points");
  NodeDerivatives X;
  // Three matrix-vector products per table (core/columns3.h), not a GEMM that packs the
  // #nodes x #points table on every call for three columns.
  for (size_t t = 0; t < 5; ++t) X[t] = times(D_[t], P);
  return X;
}

double MeanCurvatureLeastSquares::node_residual(const NodeDerivatives& X, Eigen::Index q, double H,
                                                Eigen::Matrix<double, 15, 1>* dr) const {
  check_single("node_residual");
  if (singular(X[0].row(q).transpose(), X[1].row(q).transpose())) {
    if (dr) dr->setZero();
    return 0.0;
  }
  if (dr) {
    using Jet = ceres::Jet<double, 15>;
    Jet jet[15];
    for (int t = 0; t < 5; ++t)
      for (int c = 0; c < 3; ++c) jet[3 * t + c] = Jet(X[size_t(t)](q, c), 3 * t + c);
    const Jet v = residual_from_jet(jet, H, w_(q));
    *dr = v.v;
    return v.a;
  }
  double jet[15];
  for (int t = 0; t < 5; ++t)
    for (int c = 0; c < 3; ++c) jet[3 * t + c] = X[size_t(t)](q, c);
  return residual_from_jet(jet, H, w_(q));
}

Eigen::VectorXd MeanCurvatureLeastSquares::h_derivative(const NodeDerivatives& X) const {
  check_single("h_derivative");
  Eigen::VectorXd d(nodes());
  for (Eigen::Index q = 0; q < nodes(); ++q) {
    const Eigen::Vector3d xu = X[0].row(q).transpose(), xv = X[1].row(q).transpose();
    d(q) = singular(xu, xv) ? 0.0 : -std::sqrt(w_(q) * xu.cross(xv).norm());
  }
  return d;
}

void MeanCurvatureLeastSquares::residuals(const Eigen::MatrixX3d& P, double H, Eigen::VectorXd* r,
                                          const std::vector<int>* idx, Eigen::MatrixXd* J, Eigen::VectorXd* dH) const {
  if (P.rows() != size()) throw SizeError("mean-curvature least squares: the net has the wrong number of points");
  if (J && !idx) throw ParameterError("mean-curvature least squares: the Jacobian needs the list of points idx");
  if (idx)
    for (int i : *idx)
      if (i < 0 || i >= size())
        throw ParameterError("mean-curvature least squares: point index " + std::to_string(i) + " out of range");
  if (assembly_) {
    assembled_residuals(P, H, r, idx, J, dH);
    return;
  }
  const Eigen::Index M = nodes();
  const NodeDerivatives X = derivatives(P);
  Eigen::MatrixXd dr;
  if (J) dr.resize(M, 15);
  if (r) r->resize(M);
  Eigen::Matrix<double, 15, 1> d;
  for (Eigen::Index q = 0; q < M; ++q) {
    const double v = node_residual(X, q, H, J ? &d : nullptr);
    if (r) (*r)(q) = v;
    if (J) dr.row(q) = d.transpose();
  }
  if (dH) *dH = h_derivative(X);
  if (!J) return;
  const std::vector<int>& ix = *idx;
  J->setZero(M, 3 * Eigen::Index(ix.size()));
  for (size_t a = 0; a < ix.size(); ++a)
    for (int t = 0; t < 5; ++t)
      for (int c = 0; c < 3; ++c)
        J->col(3 * Eigen::Index(a) + c) += dr.col(3 * t + c).cwiseProduct(D_[size_t(t)].col(ix[a]));
}

// Patch p's residuals fill rows p·Mp … (p + 1)·Mp − 1; its Jacobian over its local rows among idx
// goes to the columns of those rows' positions in idx (the rest of its rows' columns stay 0).
void MeanCurvatureLeastSquares::assembled_residuals(const Eigen::MatrixX3d& P, double H, Eigen::VectorXd* r,
                                                    const std::vector<int>* idx, Eigen::MatrixXd* J,
                                                    Eigen::VectorXd* dH) const {
  const PatchAssembly& a = *assembly_;
  const Eigen::Index Mp = patch_->nodes(), M = nodes();
  std::vector<int> where;
  if (idx) where = positions(a, *idx);  // SizeError for a row out of range
  if (r) r->resize(M);
  if (dH) dH->resize(M);
  if (J) J->setZero(M, 3 * Eigen::Index(idx->size()));
  std::vector<int> local, pos;
  Eigen::VectorXd rp, dHp;
  Eigen::MatrixXd Jp;
  for (int p = 0; p < a.patches(); ++p) {
    const Eigen::MatrixX3d Pp = patch_points(a, p, P);
    if (J) local_rows(a, p, where, local, pos);
    patch_->residuals(Pp, H, r ? &rp : nullptr, J ? &local : nullptr, J ? &Jp : nullptr, dH ? &dHp : nullptr);
    const Eigen::Index row0 = Mp * p;
    if (r) r->segment(row0, Mp) = rp;
    if (dH) dH->segment(row0, Mp) = dHp;
    if (J)
      for (size_t b = 0; b < local.size(); ++b)
        J->block(row0, 3 * Eigen::Index(pos[b]), Mp, 3) = Jp.middleCols(3 * Eigen::Index(b), 3);
  }
  // The seams: √w_g (n_p − sign n_q), three rows per node.
  Eigen::Index row = Mp * a.patches();
  using Jet = ceres::Jet<double, 6>;
  for (const Seam& s : seams_) {
    const Eigen::MatrixX3d Pp = patch_points(a, s.p, P), Pq = patch_points(a, s.q, P);
    const Eigen::MatrixX3d xup = times(s.Bu_p, Pp), xvp = times(s.Bv_p, Pp), xuq = times(s.Bu_q, Pq),
                           xvq = times(s.Bv_q, Pq);
    for (Eigen::Index k = 0; k < s.w.size(); ++k, row += 3) {
      const double sw = std::sqrt(s.w(k));
      if (dH) dH->segment<3>(row).setZero();
      if (singular(xup.row(k).transpose(), xvp.row(k).transpose()) ||
          singular(xuq.row(k).transpose(), xvq.row(k).transpose())) {
        if (r) r->segment<3>(row).setZero();
        continue;
      }
      // Each side's unit normal and its derivatives over (x_u, x_v): dn(c, d) = ∂n_c/∂(jet d).
      auto side = [&](const Eigen::MatrixX3d& xu, const Eigen::MatrixX3d& xv, Eigen::Vector3d& n,
                      Eigen::Matrix<double, 3, 6>& dn) {
        Jet j[6], nj[3];
        for (int c = 0; c < 3; ++c) {
          j[c] = Jet(xu(k, c), c);
          j[3 + c] = Jet(xv(k, c), 3 + c);
        }
        unit_normal(j, nj);
        for (int c = 0; c < 3; ++c) {
          n(c) = nj[c].a;
          dn.row(c) = nj[c].v.transpose();
        }
      };
      Eigen::Vector3d np, nq;
      Eigen::Matrix<double, 3, 6> dnp, dnq;
      side(xup, xvp, np, dnp);
      side(xuq, xvq, nq, dnq);
      if (r) r->segment<3>(row) = sw * (np - s.sign * nq);
      if (!J) continue;
      auto add = [&](int patch, const Eigen::MatrixXd& Bu, const Eigen::MatrixXd& Bv,
                     const Eigen::Matrix<double, 3, 6>& dn, double f) {
        const std::vector<int>& map = a.maps[size_t(patch)];
        for (size_t l = 0; l < map.size(); ++l) {
          const int at = where[size_t(map[l])];
          if (at < 0) continue;
          const double bu = Bu(k, Eigen::Index(l)), bv = Bv(k, Eigen::Index(l));
          if (bu == 0.0 && bv == 0.0) continue;
          J->block<3, 3>(row, 3 * Eigen::Index(at)) += f * (bu * dn.leftCols<3>() + bv * dn.rightCols<3>());
        }
      };
      add(s.p, s.Bu_p, s.Bv_p, dnp, sw);
      add(s.q, s.Bu_q, s.Bv_q, dnq, -s.sign * sw);
    }
  }
}

double MeanCurvatureLeastSquares::value(const Eigen::MatrixX3d& P, double H) const {
  Eigen::VectorXd r;
  residuals(P, H, &r);
  return r.squaredNorm();
}

}  // namespace bpde
