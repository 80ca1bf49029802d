#include "solvers/pde_lu.h"

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "core/bernstein.h"
#include "core/errors.h"

namespace bpde {
namespace {

using Clock = std::chrono::steady_clock;

std::vector<double> operator_coefficients(const EnergySpec& op) {
  if (op.order() == 2) {
    const auto& c = op.second_order_coeffs();
    return {c[0], c[1], c[2]};
  }
  const auto& c = op.operator_coeffs();
  return {c[0], c[1], c[2], c[3], c[4]};
}

void check_degrees(int n, int m, const char* who) {
  if (n < 1 || m < 1 || n > kMaxDegree || m > kMaxDegree) {
    std::ostringstream s;
    s << who << ": degree [" << n << ", " << m << "] out of range 1.." << kMaxDegree;
    throw DegreeError(s.str());
  }
}

// Rank of M from its singular values relative to `scale`.
int numerical_rank(const Eigen::JacobiSVD<Eigen::MatrixXd>& svd, double scale, double tol) {
  int r = 0;
  for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i)
    if (svd.singularValues()(i) > tol * scale) ++r;
  return r;
}

}  // namespace

void PdeLuOptions::validate() const {
  auto ok = [](double x) { return std::isfinite(x) && x > 0 && x < 1; };
  if (!ok(compatibility_tolerance))
    throw ParameterError("PdeLuOptions: compatibility_tolerance must be in (0, 1)");
  if (!ok(rank_tolerance)) throw ParameterError("PdeLuOptions: rank_tolerance must be in (0, 1)");
}

PdeStructure analyse_pde_structure(const std::vector<double>& c, int n, int m, FixedSet fixed,
                                   double rank_tolerance) {
  const int p = static_cast<int>(c.size()) - 1;
  PdeStructure out;
  double cmax = 0;
  for (double x : c) cmax = std::max(cmax, std::abs(x));
  if (!(cmax > 0)) {
    out.unique = false;
    out.diagnosis = "the operator is zero";
    return out;
  }
  std::ostringstream diag;
  for (int s = 0; s <= n + m; ++s) {
    const int lo = std::max(0, s - n), hi = std::min(s, m);  // l range of a_{s-l,l} inside the box
    std::vector<int> unknown, data;
    for (int l = lo; l <= hi; ++l) {
      const int k = s - l;
      bool determined;
      if (fixed == FixedSet::Boundary)
        determined = (l == 0 || k == 0 || k == 1 || l == 1);
      else  // UBoundaries: x(0,v) gives a_{0,l}; x(1,v) gives a_{1,l} from the higher anti-diagonals
        determined = (k == 0 || k == 1);
      (determined ? data : unknown).push_back(l);
    }
    // Equations sum_j c_j y_{l0+j} = 0, l0 = 0..s-p, that touch the box.
    std::vector<int> rows;
    for (int l0 = 0; l0 + p <= s; ++l0)
      if (l0 + p >= lo && l0 <= hi) rows.push_back(l0);
    if (rows.empty() || (unknown.empty() && data.empty())) continue;
    auto block = [&](const std::vector<int>& cols) {
      Eigen::MatrixXd M = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()),
                                                static_cast<Eigen::Index>(cols.size()));
      for (size_t r = 0; r < rows.size(); ++r)
        for (size_t q = 0; q < cols.size(); ++q) {
          const int j = cols[q] - rows[r];
          if (j >= 0 && j <= p) M(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(q)) = c[static_cast<size_t>(j)];
        }
      return M;
    };
    const Eigen::MatrixXd U = block(unknown), Dm = block(data);
    int rank = 0;
    Eigen::MatrixXd leftnull;
    if (!unknown.empty()) {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(U, Eigen::ComputeFullU);
      rank = numerical_rank(svd, cmax, rank_tolerance);
      if (rank < U.cols()) {
        if (out.unique)
          diag << "the polynomial solution is not unique: on the anti-diagonal k + l = " << s
               << " the operator has a nonzero polynomial solution with zero boundary data";
        out.unique = false;
      }
      leftnull = svd.matrixU().rightCols(U.rows() - rank);
    } else {
      leftnull = Eigen::MatrixXd::Identity(U.rows(), U.rows());
    }
    if (leftnull.cols() > 0 && Dm.cols() > 0) {
      const Eigen::MatrixXd T = leftnull.transpose() * Dm;
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(T);
      const int k = numerical_rank(svd, cmax, rank_tolerance);
      if (k > 0) {
        if (out.conditions == 0 && out.unique)
          diag << "the data must satisfy linear compatibility conditions (first on the anti-diagonal k + l = " << s
               << ")";
        out.conditions += k;
      }
    }
  }
  out.diagnosis = diag.str();
  return out;
}

namespace {

// The solve runs in long double: the Bernstein matrix has condition ~1e16 at n = 20, so double
// (and even a long double solve of a matrix rounded to double) loses every digit, while a long
// double matrix built from exact-in-long-double binomials keeps the error near the data-rounding
// floor (docs/pde_accuracy.md).
using LD = long double;
using MatL = Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic>;
using VecL = Eigen::Matrix<LD, Eigen::Dynamic, 1>;

LD binomial_ld(int n, int k) {
  if (k < 0 || k > n) return 0;
  LD r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

// (n-d+1) x (n+1): Bernstein coefficients of the d-th derivative, elevated back to degree n:
// (n+1) x (n+1) in total.
MatL derivative_elevated_ld(int n, int d) {
  MatL D = MatL::Identity(n + 1, n + 1);
  for (int q = 0; q < d; ++q) {
    const int k = n - q;
    MatL S = MatL::Zero(k, k + 1);
    for (int i = 0; i < k; ++i) {
      S(i, i) = -k;
      S(i, i + 1) = k;
    }
    D = (S * D).eval();
  }
  const int nd = n - d;
  MatL E = MatL::Zero(n + 1, nd + 1);
  for (int i = 0; i <= nd; ++i)
    for (int j = i; j <= i + d; ++j) E(j, i) = binomial_ld(nd, i) * binomial_ld(d, j - i) / binomial_ld(n, j);
  return E * D;
}

MatL bernstein_matrix_ld(const std::vector<PdeTerm>& terms, int n, int m) {
  const int N = (n + 1) * (m + 1);
  MatL K = MatL::Zero(N, N);
  for (const PdeTerm& t : terms) {
    if (t.du > n || t.dv > m || t.c == 0.0) continue;
    const MatL Au = derivative_elevated_ld(n, t.du), Av = derivative_elevated_ld(m, t.dv);
    for (int i = 0; i <= n; ++i)
      for (int k = 0; k <= n; ++k) {
        const LD a = static_cast<LD>(t.c) * Au(i, k);
        if (a == 0) continue;
        for (int j = 0; j <= m; ++j)
          for (int l = 0; l <= m; ++l) K(i * (m + 1) + j, k * (m + 1) + l) += a * Av(j, l);
      }
  }
  return K;
}

struct Split {
  std::vector<int> fixed, free;
};

Split split_indices(int n, int m, FixedSet fixed) {
  TensorNet shape(n, m);
  return {shape.fixed_indices(fixed), shape.free_indices(fixed)};
}

MatL columns(const MatL& K, const std::vector<int>& idx) {
  MatL out(K.rows(), static_cast<Eigen::Index>(idx.size()));
  for (size_t q = 0; q < idx.size(); ++q) out.col(static_cast<Eigen::Index>(q)) = K.col(idx[q]);
  return out;
}

Eigen::MatrixXd rows_of(const Eigen::MatrixX3d& P, const std::vector<int>& idx) {
  Eigen::MatrixXd out(static_cast<Eigen::Index>(idx.size()), 3);
  for (size_t q = 0; q < idx.size(); ++q) out.row(static_cast<Eigen::Index>(q)) = P.row(idx[q]);
  return out;
}

void check_problem(const EnergySpec& op, FixedSet fixed) {
  if (op.order() == 4 && fixed != FixedSet::Boundary)
    throw UnsupportedProblem("pde: a fourth-order operator (" + op.name() + ") needs fixed = \"boundary\", got \"" +
                             to_string(fixed) + "\"");
  if (op.order() == 2 && fixed != FixedSet::UBoundaries)
    throw UnsupportedProblem("pde: a second-order operator (" + op.name() + ") needs fixed = \"u-boundaries\", got \"" +
                             to_string(fixed) + "\"");
}

// Column-equilibrated QR of K_FF. Returns the factorisation and the column scales.
struct ScaledQR {
  Eigen::ColPivHouseholderQR<MatL> qr;
  VecL scale;
};

void factor(const MatL& KFF, ScaledQR& f) {
  f.scale = KFF.colwise().norm().transpose();
  for (Eigen::Index q = 0; q < f.scale.size(); ++q)
    if (!(f.scale(q) > 0)) f.scale(q) = 1.0;
  f.qr.compute(KFF * f.scale.cwiseInverse().asDiagonal());
}

// Compatibility functionals: the k strongest directions of Q2^T K_FB, Q2 the left null space of K_FF.
Eigen::MatrixXd compatibility_rows(const ScaledQR& f, const MatL& KFB, int k) {
  const Eigen::Index R = KFB.rows(), r = f.qr.cols();
  const MatL Q = f.qr.householderQ() * MatL::Identity(R, R);
  const Eigen::MatrixXd T = (Q.rightCols(R - r).transpose() * KFB).cast<double>();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(T, Eigen::ComputeThinV);
  Eigen::MatrixXd W = svd.matrixV().leftCols(k).transpose();  // unit rows
  return W;
}

Eigen::MatrixXd conditions_without_unknowns(const MatL& KFB, int k) {
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(KFB.cast<double>(), Eigen::ComputeThinV);
  return svd.matrixV().leftCols(k).transpose();
}

double violation(const Eigen::MatrixXd& W, const Eigen::MatrixXd& XB) {
  double worst = 0;
  for (Eigen::Index r = 0; r < W.rows(); ++r)
    for (int c = 0; c < 3; ++c) {
      const double v = std::abs(W.row(r).dot(XB.col(c)));
      const double s = W.row(r).cwiseAbs().dot(XB.col(c).cwiseAbs());
      if (v > 0) worst = std::max(worst, s > 0 ? v / s : 1.0);
    }
  return worst;
}

PdeSolution finish(const TensorNet& data, int n, int m, const Split& sp, const Eigen::MatrixXd& XF, double viol,
                   double tol, const PdeStructure& st, Clock::time_point t0) {
  PdeSolution out{TensorNet(n, m, data.points()), Summary{}};
  for (size_t q = 0; q < sp.free.size(); ++q) out.net.points().row(sp.free[q]) = XF.row(static_cast<Eigen::Index>(q));
  out.summary.residual = viol;
  if (!XF.allFinite()) {
    out.net = data;
    out.summary.converged = false;
    out.summary.message = "the linear solve produced non-finite values (data too large for double precision)";
  } else if (viol > tol) {
    std::ostringstream s;
    s << "no polynomial solution: the data violate a compatibility condition (relative violation " << viol
      << " > tolerance " << tol << "); " << st.diagnosis << "; the returned net is the least-squares net";
    out.summary.converged = false;
    out.summary.message = s.str();
  } else {
    out.summary.converged = true;
  }
  out.summary.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

PdeSolution not_unique(const TensorNet& data, const PdeStructure& st, Clock::time_point t0) {
  PdeSolution out{data, Summary{}};
  out.summary.converged = false;
  out.summary.message = st.diagnosis + "; the data are returned unchanged";
  out.summary.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return out;
}

}  // namespace

PdeMould::PdeMould(const EnergySpec& op, int n, int m, FixedSet fixed, const PdeLuOptions& options)
    : n_(n), m_(m), fixed_(fixed), options_(options) {
  options_.validate();
  check_degrees(n, m, "pde mould");
  check_problem(op, fixed);
  structure_ = analyse_pde_structure(operator_coefficients(op), n, m, fixed, options_.rank_tolerance);
  const Split sp = split_indices(n, m, fixed);
  fixed_idx_ = sp.fixed;
  free_idx_ = sp.free;
  if (!structure_.unique) return;
  const MatL K = bernstein_matrix_ld(pde_operator_terms(op), n, m);
  const MatL KFF = columns(K, free_idx_), KFB = columns(K, fixed_idx_);
  if (free_idx_.empty()) {
    S_.resize(0, static_cast<Eigen::Index>(fixed_idx_.size()));
    // No unknowns: the conditions are L x = 0 itself, K_FB x_B = 0.
    if (structure_.conditions > 0) W_ = conditions_without_unknowns(KFB, structure_.conditions);
  } else {
    ScaledQR f;
    factor(KFF, f);
    S_ = (f.scale.cwiseInverse().asDiagonal() * f.qr.solve(MatL(-KFB))).cast<double>();
    if (structure_.conditions > 0) W_ = compatibility_rows(f, KFB, structure_.conditions);
  }
}

void PdeMould::apply(const TensorNet& data, TensorNet& out) const {
  if (!structure_.unique) throw UnsupportedProblem("pde mould: " + structure_.diagnosis);
  if (data.n() != n_ || data.m() != m_ || out.n() != n_ || out.m() != m_)
    throw DegreeError("pde mould: apply needs nets of the mould's degree");
  const Eigen::MatrixXd XB = rows_of(data.points(), fixed_idx_);
  const Eigen::MatrixXd XF = S_ * XB;
  for (size_t q = 0; q < fixed_idx_.size(); ++q) out.points().row(fixed_idx_[q]) = XB.row(static_cast<Eigen::Index>(q));
  for (size_t q = 0; q < free_idx_.size(); ++q) out.points().row(free_idx_[q]) = XF.row(static_cast<Eigen::Index>(q));
}

double PdeMould::compatibility_violation(const TensorNet& data) const {
  if (W_.rows() == 0) return 0.0;
  return violation(W_, rows_of(data.points(), fixed_idx_));
}

PdeSolution PdeMould::solve(const TensorNet& data) const {
  const auto t0 = Clock::now();
  if (data.n() != n_ || data.m() != m_) {
    std::ostringstream s;
    s << "pde mould of degree [" << n_ << ", " << m_ << "] cannot solve a net of degree [" << data.n() << ", "
      << data.m() << "]";
    throw DegreeError(s.str());
  }
  if (!structure_.unique) return not_unique(data, structure_, t0);
  const Eigen::MatrixXd XB = rows_of(data.points(), fixed_idx_);
  const Eigen::MatrixXd XF = S_ * XB;
  const double viol = W_.rows() ? violation(W_, XB) : 0.0;
  return finish(data, n_, m_, {fixed_idx_, free_idx_}, XF, viol, options_.compatibility_tolerance, structure_, t0);
}

PdeSolution solve_pde_lu(const TensorNet& data, const EnergySpec& op, const PdeLuOptions& options) {
  const auto t0 = Clock::now();
  options.validate();
  check_problem(op, FixedSet::Boundary);
  const int n = data.n(), m = data.m();
  const PdeStructure st = analyse_pde_structure(operator_coefficients(op), n, m, FixedSet::Boundary,
                                                options.rank_tolerance);
  if (!st.unique) return not_unique(data, st, t0);
  const Split sp = split_indices(n, m, FixedSet::Boundary);
  const MatL K = bernstein_matrix_ld(pde_operator_terms(op), n, m);
  const MatL KFB = columns(K, sp.fixed);
  const Eigen::MatrixXd XB = rows_of(data.points(), sp.fixed);
  Eigen::MatrixXd XF(static_cast<Eigen::Index>(sp.free.size()), 3);
  double viol = 0;
  if (!sp.free.empty()) {
    ScaledQR f;
    factor(columns(K, sp.free), f);
    XF = (f.scale.cwiseInverse().asDiagonal() * f.qr.solve(MatL(-(KFB * XB.cast<LD>())))).cast<double>();
    if (st.conditions > 0) viol = violation(compatibility_rows(f, KFB, st.conditions), XB);
  } else if (st.conditions > 0) {
    viol = violation(conditions_without_unknowns(KFB, st.conditions), XB);
  }
  return finish(data, n, m, sp, XF, viol, options.compatibility_tolerance, st, t0);
}

Eigen::MatrixXd pde_bernstein_matrix(const std::vector<PdeTerm>& terms, int n, int m) {
  check_degrees(n, m, "pde_bernstein_matrix");
  return bernstein_matrix_ld(terms, n, m).cast<double>();
}

}  // namespace bpde
