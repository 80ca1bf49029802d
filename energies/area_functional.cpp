#include "bezierpde/energies/area_functional.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Geometry>
#include <array>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/columns3.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/keyed_cache.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/energies/patch_assembly.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {
namespace {

void check_q(int q, int grading, int levels) {
  if (q < 1 || q > 200)
    throw ParameterError("AreaForm: points per direction must be in 1..200, got " + std::to_string(q));
  if (grading < 1 || grading > 4)
    throw ParameterError("AreaForm: grading must be in 1..4, got " + std::to_string(grading));
  if (levels < 0 || levels > kMaxGeometricLevels)
    throw ParameterError("AreaForm: levels must be in 0.." + std::to_string(kMaxGeometricLevels) + ", got " +
                         std::to_string(levels));
  if (levels > 0 && grading != 1)
    throw ParameterError("AreaForm: geometric levels take grading 1, got " + std::to_string(grading));
}

// x_u, x_v, N = x_u ∧ x_v and |N| at the nodes.
struct NodeFrame {
  Eigen::MatrixX3d Xu, Xv, N;
  Eigen::VectorXd len;
};

// The frame at P into f's storage.
void frame_into(const Eigen::MatrixXd& Bu, const Eigen::MatrixXd& Bv, const Eigen::MatrixX3d& P, NodeFrame& f) {
  f.Xu.resize(Bu.rows(), 3);
  f.Xv.resize(Bv.rows(), 3);
  for (int c = 0; c < 3; ++c) {
    f.Xu.col(c).noalias() = Bu * P.col(c);
    f.Xv.col(c).noalias() = Bv * P.col(c);
  }
  cross_rows_into(f.Xu, f.Xv, f.N);
  f.len.resize(f.N.rows());
  f.len = f.N.rowwise().norm();
}

// The per-node arrays of value, min_normal, the gradient and the Hessian, kept per thread until
// AreaForm::release_scratch(), as the Hessian's blocks are (below): fresh arrays per call cost
// their page faults on every call where the allocator has returned them to the system in
// between. Measured on a folded tensor patch at n = 3 whose rule is refined to q = 64 (32 768
// nodes, 0.8 MB per array), in a plain program linking the library:
// 9.2 s with 812 000 minor page faults and 4.3 s of system time, 2.1 s with the scratch
// (docs/performance_measurements.md, "Design decisions"; the bpde command sets the allocator's thresholds itself).
struct FrameScratch {
  NodeFrame f;
  Eigen::MatrixX3d wa, wb, aa, bb;
};
FrameScratch& frame_scratch() {
  thread_local FrameScratch scratch;
  return scratch;
}

constexpr std::size_t kAreaCacheSize = 32;

}  // namespace

AreaForm AreaForm::triangular(int n, int q, int grading, int levels) {
  if (n < 1 || n > kMaxDegree)
    throw DegreeError("AreaForm: triangular degree " + std::to_string(n) + " is outside 1.." +
                      std::to_string(kMaxDegree));
  check_q(q, grading, levels);
  Eigen::MatrixX2d uv;
  AreaForm f;
  {
    const QuadratureRuleTriangle rule = corner_collapsed_triangle_rule(q, grading, levels);
    uv = rule.uv;
    f.w_ = rule.w;
  }
  f.q_ = q;
  f.grading_ = grading;
  f.levels_ = levels;
  f.Bu_ = triangular_basis_table(n, uv, 1, 0);
  f.Bv_ = triangular_basis_table(n, uv, 0, 1);
  return f;
}

AreaForm AreaForm::tensor(int n, int m, int q, int grading, int levels) {
  if (n < 1 || n > kMaxDegree || m < 1 || m > kMaxDegree)
    throw DegreeError("AreaForm: tensor degree (" + std::to_string(n) + ", " + std::to_string(m) + ") is outside 1.." +
                      std::to_string(kMaxDegree));
  check_q(q, grading, levels);
  Eigen::MatrixX2d uv;
  AreaForm f;
  {
    const QuadratureRuleTriangle rule = corner_collapsed_square_rule(q, grading, levels);
    uv = rule.uv;
    f.w_ = rule.w;
  }
  f.q_ = q;
  f.grading_ = grading;
  f.levels_ = levels;
  const Eigen::VectorXd us = uv.col(0), vs = uv.col(1);
  const Eigen::MatrixXd Tu0 = bernstein_table(n, us, 0), Tu1 = bernstein_table(n, us, 1);
  const Eigen::MatrixXd Tv0 = bernstein_table(m, vs, 0), Tv1 = bernstein_table(m, vs, 1);
  const Eigen::Index Q = uv.rows(), Np = (n + 1) * (m + 1);
  f.Bu_.resize(Q, Np);
  f.Bv_.resize(Q, Np);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j) {
      const Eigen::Index c = i * (m + 1) + j;
      f.Bu_.col(c) = Tu1.col(i).cwiseProduct(Tv0.col(j));
      f.Bv_.col(c) = Tu0.col(i).cwiseProduct(Tv1.col(j));
    }
  return f;
}

std::shared_ptr<const AreaForm> AreaForm::cached_triangular(int n, int q, int grading, int levels) {
  static KeyedCache<std::array<int, 4>, AreaForm> cache(kAreaCacheSize);
  return cache.get({n, q, grading, levels},
                   [](const std::array<int, 4>& k) { return triangular(k[0], k[1], k[2], k[3]); });
}

std::shared_ptr<const AreaForm> AreaForm::cached_tensor(int n, int m, int q, int grading, int levels) {
  static KeyedCache<std::array<int, 5>, AreaForm> cache(kAreaCacheSize);
  return cache.get({n, m, q, grading, levels},
                   [](const std::array<int, 5>& k) { return tensor(k[0], k[1], k[2], k[3], k[4]); });
}

std::size_t AreaForm::memory_bytes() const {
  return sizeof(double) * static_cast<std::size_t>(w_.size() + Bu_.size() + Bv_.size());
}

void AreaForm::check(const Eigen::MatrixX3d& P) const {
  if (P.rows() != Bu_.cols())
    throw SizeError("AreaForm: " + std::to_string(P.rows()) + " points given, the net has " +
                    std::to_string(Bu_.cols()));
}

double AreaForm::value(const Eigen::MatrixX3d& P) const {
  if (assembly_) {
    double A = 0.0;
    for (int p = 0; p < assembly_->patches(); ++p) A += patch_->value(patch_points(*assembly_, p, P));
    return A;
  }
  check(P);
  NodeFrame& f = frame_scratch().f;
  frame_into(Bu_, Bv_, P, f);
  return w_.dot(f.len);
}

double AreaForm::min_normal(const Eigen::MatrixX3d& P) const {
  if (assembly_) {
    double r = std::numeric_limits<double>::infinity();
    for (int p = 0; p < assembly_->patches(); ++p) r = std::min(r, patch_->min_normal(patch_points(*assembly_, p, P)));
    return r;
  }
  check(P);
  NodeFrame& f = frame_scratch().f;
  frame_into(Bu_, Bv_, P, f);
  const double A = w_.dot(f.len), dom = w_.sum();
  if (!(A > 0.0) || !std::isfinite(A)) return 0.0;
  return f.len.minCoeff() / (A / dom);
}

Eigen::MatrixX3d AreaForm::gradient(const Eigen::MatrixX3d& P) const {
  // All rows by the same pass as gradient_rows_and_scale, so the two agree to the bit.
  std::vector<int> all(static_cast<std::size_t>(size()));
  for (int I = 0; I < size(); ++I) all[static_cast<std::size_t>(I)] = I;
  Eigen::MatrixX3d G;
  gradient_rows_and_scale(P, all, &G, nullptr);
  return G;
}

void AreaForm::gradient_rows_and_scale(const Eigen::MatrixX3d& P, const std::vector<int>& idx, Eigen::MatrixX3d* G,
                                       Eigen::MatrixX3d* S) const {
  if (assembly_) {
    assembled_rows_and_scale(P, idx, G, S);
    return;
  }
  check(P);
  for (int I : idx)
    if (I < 0 || I >= size()) throw SizeError("AreaForm: point index out of range");
  FrameScratch& sc = frame_scratch();
  NodeFrame& f = sc.f;
  frame_into(Bu_, Bv_, P, f);
  // n̂ over N's storage, and the cross products a = x_v ∧ n̂, b = n̂ ∧ x_u straight into their
  // weighted forms w a, w b (|a|, |b| weighted first where the scale is asked for): the same
  // operations in the same order as separate arrays would take, in four arrays instead of seven.
  Eigen::MatrixX3d &nh = f.N, &wa = sc.wa, &wb = sc.wb, &aa = sc.aa, &bb = sc.bb;
  nh = f.len.cwiseInverse().asDiagonal() * nh;  // coefficient-wise: in place is safe
  cross_rows_into(f.Xv, nh, wa);
  cross_rows_into(nh, f.Xu, wb);
  if (S) {
    aa.resize(wa.rows(), 3);
    bb.resize(wb.rows(), 3);
    aa = w_.asDiagonal() * wa.cwiseAbs();
    bb = w_.asDiagonal() * wb.cwiseAbs();
  }
  wa = w_.asDiagonal() * wa;
  wb = w_.asDiagonal() * wb;
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size());
  if (G) G->resize(k, 3);
  if (S) S->resize(k, 3);
  // One pass over the basis columns of the rows asked for (no copy of the #nodes x k sub-tables).
  for (Eigen::Index r = 0; r < k; ++r) {
    const auto bu = Bu_.col(idx[r]), bv = Bv_.col(idx[r]);
    if (G) G->row(r).noalias() = bu.transpose() * wa + bv.transpose() * wb;
    if (S) S->row(r).noalias() = bu.cwiseAbs().transpose() * aa + bv.cwiseAbs().transpose() * bb;
  }
}

namespace {
struct HessianScratch {
  Eigen::MatrixXd R, DB, Bub, Bvb;
  Eigen::MatrixX3d U0, W0, U1, W1, nh;
};
HessianScratch& hessian_scratch() {
  thread_local HessianScratch scratch;
  return scratch;
}
}  // namespace

void AreaForm::release_scratch() {
  hessian_scratch() = HessianScratch{};
  frame_scratch() = FrameScratch{};
}

Eigen::MatrixXd AreaForm::hessian(const Eigen::MatrixX3d& P, const std::vector<int>& idx) const {
  if (assembly_)
    return assembled_hessian_dense(*assembly_, P, idx, [this](const Eigen::MatrixX3d& Pp, const std::vector<int>& l) {
      return patch_->hessian(Pp, l);
    });
  check(P);
  for (int I : idx)
    if (I < 0 || I >= size()) throw SizeError("AreaForm: point index out of range");
  const Eigen::Index k = static_cast<Eigen::Index>(idx.size()), Q = w_.size();
  NodeFrame& f = frame_scratch().f;
  frame_into(Bu_, Bv_, P, f);
  // H = RᵀR + the antisymmetric part below, with
  // R(2q + r, 3a + c) = sqrt(w/|N|) [ (B_a)_u (x_v ∧ t_r) + (B_a)_v (t_r ∧ x_u) ]_c, t_0, t_1 ⊥ n̂.
  // Both are accumulated over blocks of kHessianBlock nodes: R is never #nodes × 3k (64 MB at
  // triangular n = 10 with the graded q = 64 rule), and each block's R is filled column by column
  // (contiguous), not row by row. Usual rules (up to 8192 nodes) are one block.
  constexpr Eigen::Index kHessianBlock = 8192;
  Eigen::MatrixXd Hs = Eigen::MatrixXd::Zero(3 * k, 3 * k);
  std::array<Eigen::MatrixXd, 3> M;
  for (auto& m : M) m = Eigen::MatrixXd::Zero(k, k);
  // The blocks' scratch (hessian_scratch() below), kept per thread until release_scratch(): the
  // solves call the Hessian hundreds of times, and a fresh R per call costs its page faults on
  // every call where the allocator has returned it to the system in between (3–13× slower Hessians
  // on the build machine: docs/performance_measurements.md, "Design decisions").
  HessianScratch& sc = hessian_scratch();
  Eigen::MatrixXd &R = sc.R, &DB = sc.DB, &Bub = sc.Bub, &Bvb = sc.Bvb;
  Eigen::MatrixX3d &U0 = sc.U0, &W0 = sc.W0, &U1 = sc.U1, &W1 = sc.W1, &nh = sc.nh;
  R.resize(2 * std::min(kHessianBlock, Q), 3 * k);
  for (Eigen::Index q0 = 0; q0 < Q; q0 += kHessianBlock) {
    const Eigen::Index len = std::min(kHessianBlock, Q - q0);
    U0.resize(len, 3);
    W0.resize(len, 3);
    U1.resize(len, 3);
    W1.resize(len, 3);
    nh.resize(len, 3);
    for (Eigen::Index r = 0; r < len; ++r) {
      const Eigen::Index q = q0 + r;
      const Eigen::Vector3d n = f.N.row(q).transpose() / f.len(q);
      nh.row(r) = n.transpose();
      // An orthonormal tangent pair: t0 along x_u (x_u ⊥ n̂ already), t1 = n̂ ∧ t0.
      Eigen::Vector3d t0 = f.Xu.row(q).transpose();
      const double l0 = t0.norm();
      if (l0 > 0) {
        t0 /= l0;
      } else {
        t0 = n.unitOrthogonal();
      }
      const Eigen::Vector3d t1 = n.cross(t0);
      const double sw = std::sqrt(w_(q) / f.len(q));
      const Eigen::Vector3d xu = f.Xu.row(q).transpose(), xv = f.Xv.row(q).transpose();
      U0.row(r) = sw * xv.cross(t0).transpose();
      W0.row(r) = sw * t0.cross(xu).transpose();
      U1.row(r) = sw * xv.cross(t1).transpose();
      W1.row(r) = sw * t1.cross(xu).transpose();
    }
    Bub = Bu_.middleRows(q0, len)(Eigen::all, idx);
    Bvb = Bv_.middleRows(q0, len)(Eigen::all, idx);
    using Strided = Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<2>>;
    for (Eigen::Index a = 0; a < k; ++a)
      for (int c = 0; c < 3; ++c) {
        double* col = R.col(3 * a + c).data();
        Strided(col, len) = Bub.col(a).cwiseProduct(U0.col(c)) + Bvb.col(a).cwiseProduct(W0.col(c));
        Strided(col + 1, len) = Bub.col(a).cwiseProduct(U1.col(c)) + Bvb.col(a).cwiseProduct(W1.col(c));
      }
    Hs.selfadjointView<Eigen::Lower>().rankUpdate(R.topRows(2 * len).transpose());
    // ((B_I)_u (B_L)_v - (B_I)_v (B_L)_u) <n̂, e_c ∧ e_d> = sum_k eps(c,d,k) n̂_k (...).
    for (int kk = 0; kk < 3; ++kk) {
      DB.noalias() = (w_.segment(q0, len).cwiseProduct(nh.col(kk))).asDiagonal() * Bvb;
      M[kk].noalias() += Bub.transpose() * DB;
    }
  }
  Hs.triangularView<Eigen::StrictlyUpper>() = Hs.transpose();
  for (int kk = 0; kk < 3; ++kk) {
    const Eigen::MatrixXd A = M[kk] - M[kk].transpose();
    const int c = (kk + 1) % 3, d = (kk + 2) % 3;  // eps(c, d, kk) = +1
    for (Eigen::Index I = 0; I < k; ++I)
      for (Eigen::Index L = 0; L < k; ++L) {
        Hs(3 * I + c, 3 * L + d) += A(I, L);
        Hs(3 * I + d, 3 * L + c) -= A(I, L);
      }
  }
  return Hs;
}

namespace {

// The report's area of one net (area() below) needs no node tables of the control points: it
// evaluates x_u and x_v from the derivative nets, a block of nodes at a time, so that its memory
// stays O(block × N) whatever q (the tables of AreaForm are #nodes × N twice: 232 MB at
// triangular n = 25, q = 83). Only the rule is kept between calls, and for small nets the
// derivative tables (report_rule, ReportTables below).
// Nodes per block, measured (docs/performance_measurements.md, "Design decisions"): triangular 256, so that the
// block's basis matrix (256 x 78 doubles at n = 11) stays in the L2 cache between its two products
// (1024: 9-20 % slower at n = 11 ... 16); tensor 1024, whose univariate tables are small (256:
// 12-16 % slower at n = m = 7 ... 9).
constexpr Eigen::Index kTriangleAreaBlock = 256, kSquareAreaBlock = 1024;

double streamed_area(const Eigen::MatrixX2d& uv, const Eigen::VectorXd& w, Eigen::Index block,
                     const std::function<void(const Eigen::MatrixX2d&, Eigen::MatrixX3d&, Eigen::MatrixX3d&)>& eval) {
  double A = 0.0;
  Eigen::MatrixX3d Xu, Xv;
  for (Eigen::Index r0 = 0; r0 < uv.rows(); r0 += block) {
    const Eigen::Index len = std::min(block, uv.rows() - r0);
    eval(uv.middleRows(r0, len), Xu, Xv);
    A += w.segment(r0, len).dot(cross_rows(Xu, Xv).rowwise().norm());
  }
  return A;
}

int report_q(int n) { return std::min(200, 3 * n + 8); }

// The report rules, cached per (kind, q) (0 triangle, 1 square): building one (Gauss–Legendre
// nodes, the Duffy maps) cost more than the D_H solve at n = 4 (docs/performance_measurements.md, "Design decisions").
std::shared_ptr<const QuadratureRuleTriangle> report_rule(int kind, int q) {
  static KeyedCache<std::array<int, 2>, QuadratureRuleTriangle> cache(16);
  return cache.get({kind, q}, [](const std::array<int, 2>& k) {
    return k[0] == 0 ? corner_collapsed_triangle_rule(k[1]) : corner_collapsed_square_rule(k[1]);
  });
}

// Small nets keep the derivative tables of the ladder's rules: x_u = Bu Du and x_v = Bv Dv at all
// nodes (Bu = Bv = B_{n-1} on the triangle). Cached per (degree, q), the most recent
// kReportTableCache, while a table holds at most this many doubles (4 MB: the report rule up to
// triangular n = 10, tensor n = m = 6); larger ones stream.
constexpr Eigen::Index kReportTableDoubles = Eigen::Index(1) << 19;
constexpr std::size_t kReportTableCache = 16;
// The ladder of area(): its first rule and the change (relative) at which a rule is taken. The
// rules converge exponentially in q on regular patches, so the rule whose change from the previous
// one is within 1e-14 is accurate far below it (measured: tests/energies/test_area_functional.cpp,
// ReportedAreaLadderAgreesWithAFineRule).
constexpr int kAreaLadderStart = 10;
constexpr double kAreaLadderChange = 1e-14;
struct ReportTables {
  Eigen::VectorXd w;
  Eigen::MatrixXd Bu, Bv;  // #nodes x #points of the derivative nets (Bv empty on the triangle)
};
// In blocks of 256 nodes: whole-rule temporaries (#nodes x 3, four of them) made the heap grow and
// shrink on every call, and the page faults and TLB flushes of that cost more than the products
// (measured on the D_H solve at n = 4, docs/performance_measurements.md, "Design decisions").
double tabled_area(const ReportTables& t, const Eigen::MatrixX3d& Du, const Eigen::MatrixX3d& Dv) {
  constexpr Eigen::Index kBlock = 256;
  const Eigen::MatrixXd& Bv = t.Bv.size() ? t.Bv : t.Bu;
  Eigen::MatrixX3d Xu(kBlock, 3), Xv(kBlock, 3);
  double A = 0.0;
  for (Eigen::Index r0 = 0; r0 < t.w.size(); r0 += kBlock) {
    const Eigen::Index len = std::min(kBlock, t.w.size() - r0);
    if (t.Bv.size()) {
      times_into(t.Bu.middleRows(r0, len), Du, Xu.topRows(len));
      times_into(Bv.middleRows(r0, len), Dv, Xv.topRows(len));
    } else {  // triangle: one table for both derivatives, read once
      times_into(t.Bu.middleRows(r0, len), Du, Dv, Xu.topRows(len), Xv.topRows(len));
    }
    for (Eigen::Index r = 0; r < len; ++r)
      A += t.w(r0 + r) * Xu.row(r).cross(Xv.row(r)).norm();
  }
  return A;
}

// The area of a net with the report rule of q points per direction (q^2 nodes on each
// sub-triangle): the derivative tables of small nets cached per (degree, q), else streamed.
double area_with_rule(const TriangularNet& net, const Eigen::MatrixX3d& Du, const Eigen::MatrixX3d& Dv, int q) {
  const int n = net.n();
  if (Eigen::Index(6) * q * q * TriangularNet::count(n - 1) <= kReportTableDoubles) {
    static KeyedCache<std::array<int, 2>, ReportTables> cache(kReportTableCache);
    const auto t = cache.get({n, q}, [](const std::array<int, 2>& k) {
      const auto rule = report_rule(0, k[1]);
      return ReportTables{rule->w, TriangularNet::basis_matrix(k[0] - 1, rule->uv), Eigen::MatrixXd()};
    });
    return tabled_area(*t, Du, Dv);
  }
  const auto rule = report_rule(0, q);
  const Eigen::MatrixX2d& uv = rule->uv;
  const Eigen::VectorXd& w = rule->w;
  return streamed_area(uv, w, kTriangleAreaBlock, [&](const Eigen::MatrixX2d& b, Eigen::MatrixX3d& Xu, Eigen::MatrixX3d& Xv) {
    const Eigen::MatrixXd B = TriangularNet::basis_matrix(n - 1, b);
    Xu.noalias() = B * Du;
    Xv.noalias() = B * Dv;
  });
}

double area_with_rule(const TensorNet& net, const Eigen::MatrixX3d& Du, const Eigen::MatrixX3d& Dv, int q) {
  const int n = net.n(), m = net.m();
  if (Eigen::Index(8) * q * q * (n * (m + 1) + (n + 1) * m) <= kReportTableDoubles) {
    static KeyedCache<std::array<int, 3>, ReportTables> cache(kReportTableCache);
    const auto t = cache.get({n, m, q}, [](const std::array<int, 3>& k) {
      const int a = k[0], b = k[1];
      const auto rule = report_rule(1, k[2]);
      const Eigen::VectorXd us = rule->uv.col(0), vs = rule->uv.col(1);
      const Eigen::MatrixXd Tu0 = bernstein_table(a, us), Tu1 = bernstein_table(a - 1, us);
      const Eigen::MatrixXd Tv0 = bernstein_table(b, vs), Tv1 = bernstein_table(b - 1, vs);
      ReportTables r{rule->w, Eigen::MatrixXd(us.size(), a * (b + 1)), Eigen::MatrixXd(us.size(), (a + 1) * b)};
      for (int i = 0; i < a; ++i)
        for (int j = 0; j <= b; ++j) r.Bu.col(i * (b + 1) + j) = Tu1.col(i).cwiseProduct(Tv0.col(j));
      for (int i = 0; i <= a; ++i)
        for (int j = 0; j < b; ++j) r.Bv.col(i * b + j) = Tu0.col(i).cwiseProduct(Tv1.col(j));
      return r;
    });
    return tabled_area(*t, Du, Dv);
  }
  const auto rule = report_rule(1, q);
  const Eigen::MatrixX2d& uv = rule->uv;
  const Eigen::VectorXd& w = rule->w;
  return streamed_area(uv, w, kSquareAreaBlock, [&](const Eigen::MatrixX2d& b, Eigen::MatrixX3d& Xu, Eigen::MatrixX3d& Xv) {
    const Eigen::VectorXd us = b.col(0), vs = b.col(1);
    const Eigen::MatrixXd Tu0 = bernstein_table(n, us), Tu1 = bernstein_table(n - 1, us);
    const Eigen::MatrixXd Tv0 = bernstein_table(m, vs), Tv1 = bernstein_table(m - 1, vs);
    Xu.resize(b.rows(), 3);
    Xv.resize(b.rows(), 3);
    for (int c = 0; c < 3; ++c) {
      // x_u,c(r) = sum_i Tu1(r, i) sum_j Du_c(i, j) Tv0(r, j), and likewise x_v.
      const Eigen::MatrixXd Gu = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>(
          Du.col(c).data(), n, m + 1, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(1, m + 1));
      const Eigen::MatrixXd Gv = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>>(
          Dv.col(c).data(), n + 1, m, Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>(1, m));
      Xu.col(c) = (Tu1 * Gu).cwiseProduct(Tv0).rowwise().sum();
      Xv.col(c) = (Tu0 * Gv).cwiseProduct(Tv1).rowwise().sum();
    }
  });
}

// The ladder of area() (area_functional.h): q_0 = kAreaLadderStart, q_{j+1} = q_j + ⌈q_j/3⌉,
// the first q_{j+1} whose change from q_j is within kAreaLadderChange (relative) taken; the
// report rule q = report_q(n) ends the ladder (its value returned whatever the change).
// A corner whose |x_u ∧ x_v| is below kLadderCorner x the mean |x_u ∧ x_v| (A / domain area)
// skips the ladder: near such a corner the plain rules converge slowly, and where the patch folds
// there the coarse rules miss the fold alike and agree (the circle's arcs fitted at degree 4).
constexpr double kLadderCorner = 0.1;

// |x_u ∧ x_v| at the corners of the domain, the smallest.
double smallest_corner_normal(const TriangularNet& net, const Eigen::MatrixX3d& Du, const Eigen::MatrixX3d& Dv) {
  Eigen::MatrixX2d uv(3, 2);
  uv << 1, 0, 0, 1, 0, 0;
  const Eigen::MatrixXd B = TriangularNet::basis_matrix(net.n() - 1, uv);
  return cross_rows(B * Du, B * Dv).rowwise().norm().minCoeff();
}
double smallest_corner_normal(const TensorNet& net, const Eigen::MatrixX3d& Du, const Eigen::MatrixX3d& Dv) {
  const int n = net.n(), m = net.m();
  const Eigen::Vector2d ends(0, 1);
  const Eigen::MatrixXd Tu0 = bernstein_table(n, ends), Tu1 = bernstein_table(n - 1, ends);
  const Eigen::MatrixXd Tv0 = bernstein_table(m, ends), Tv1 = bernstein_table(m - 1, ends);
  double smallest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 2; ++a)
    for (int b = 0; b < 2; ++b) {
      Eigen::RowVector3d xu = Eigen::RowVector3d::Zero(), xv = Eigen::RowVector3d::Zero();
      for (int i = 0; i < n; ++i)
        for (int j = 0; j <= m; ++j) xu += Tu1(a, i) * Tv0(b, j) * Du.row(i * (m + 1) + j);
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j < m; ++j) xv += Tu0(a, i) * Tv1(b, j) * Dv.row(i * m + j);
      smallest = std::min(smallest, xu.cross(xv).norm());
    }
  return smallest;
}
double domain_area(const TriangularNet&) { return 0.5; }
double domain_area(const TensorNet&) { return 1.0; }

template <class Net>
double area_by_ladder(const Net& net, int degree) {
  const Eigen::MatrixX3d Du = net.derivative_points(1, 0), Dv = net.derivative_points(0, 1);
  const int last = report_q(degree);
  int q = std::min(kAreaLadderStart, last);
  double A = area_with_rule(net, Du, Dv, q);
  if (!(smallest_corner_normal(net, Du, Dv) >= kLadderCorner * std::abs(A) / domain_area(net)))
    q = last, A = area_with_rule(net, Du, Dv, q);
  while (q < last) {
    q = std::min(last, q + (q + 2) / 3);
    const double next = area_with_rule(net, Du, Dv, q);
    const bool settled = std::abs(next - A) <= kAreaLadderChange * std::abs(next);
    A = next;
    if (settled) break;
  }
  return A;
}

}  // namespace

double area(const TriangularNet& net) { return area_by_ladder(net, net.n()); }
double area(const TensorNet& net) { return area_by_ladder(net, std::max(net.n(), net.m())); }

}  // namespace bpde
