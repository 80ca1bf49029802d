#include "bezierpde/solvers/pde/pde_lu.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/bernstein_ops.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/keyed_cache.h"
#include "bezierpde/core/row_major_product.h"
#include "bezierpde/tensor/power_basis.h"

namespace bpde {
namespace {

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
  if (!ok(compatibility_tolerance)) throw ParameterError("PdeLuOptions: compatibility_tolerance must be in (0, 1)");
  if (!ok(rank_tolerance)) throw ParameterError("PdeLuOptions: rank_tolerance must be in (0, 1)");
  if (formulation != Formulation::AntiDiagonal && formulation != Formulation::Bernstein)
    throw ParameterError("PdeLuOptions: unknown formulation");
}

PdeStructure analyse_pde_structure(const std::vector<double>& c, int n, int m, FixedSet fixed, double rank_tolerance) {
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
      Eigen::MatrixXd M =
          Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
      for (size_t r = 0; r < rows.size(); ++r)
        for (size_t q = 0; q < cols.size(); ++q) {
          const int j = cols[q] - rows[r];
          if (j >= 0 && j <= p)
            M(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(q)) = c[static_cast<size_t>(j)];
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
using MatL = MatLD;
using VecL = VecLD;

MatL bernstein_matrix_ld(const std::vector<PdeTerm>& terms, int n, int m) {
  const int N = (n + 1) * (m + 1);
  MatL K = MatL::Zero(N, N);
  for (const PdeTerm& t : terms) {
    if (t.du > n || t.dv > m || t.c == 0.0) continue;
    const MatL Au = derivative_at_degree_matrix<LD>(n, t.du), Av = derivative_at_degree_matrix<LD>(m, t.dv);
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
                   double tol, const PdeStructure& st) {
  PdeSolution out{TensorNet(n, m, data.points()), Summary{}};
  out.net.points()(sp.free, Eigen::all) = XF;
  out.summary.residual = viol;
  if (!XF.allFinite()) {
    out.net = data;
    out.summary.set_failed(Status::NumericalLimit,
                           "the linear solve produced non-finite values (data too large for double precision)");
  } else if (viol > tol) {
    std::ostringstream s;
    s << "no polynomial solution: the data violate a compatibility condition (relative violation " << viol
      << " > tolerance " << tol << "); " << st.diagnosis << "; the returned net is the least-squares net";
    out.summary.set_failed(Status::Incompatible, s.str());
  } else {
    out.summary.set_converged();
  }
  return out;
}

PdeSolution not_unique(const TensorNet& data, const PdeStructure& st) {
  PdeSolution out{data, Summary{}};
  out.summary.set_failed(Status::NotUnique, st.diagnosis + "; the data are returned unchanged");
  return out;
}

// ---- The square case n = m: block-triangular LU on the anti-diagonals -----------------------
//
// Unknowns: the factorial-scaled monomial coefficients a_kl of x = sum a_kl u^k v^l / (k! l!)
// (explicit PDE solutions eq. (4)). d^p_u d^q_v shifts (k, l) by (p, q), so the coefficient of u^k' v^l' in L x is
//   sum_j c_j a_{k'+4-j, l'+j} = 0                                    (eq. (8)-(9), docs/errata.md)
// and touches the anti-diagonal k + l = k' + l' + 4 only. The prescribed ring gives
//   a_{k,0}, a_{0,l}  from the edges v = 0, u = 0                     (eq. (5)-(6))
//   sum_k a_{k,l} / k! = e_l,  sum_l a_{k,l} / l! = f_k  from the edges u = 1, v = 1   (eq. (7))
// and the edge equation of index l (resp. k) involves a_{1,l} (resp. a_{k,1}) on the anti-diagonal
// l + 1 plus coefficients on higher anti-diagonals. So, taking the anti-diagonals s = 2n .. 2 in
// turn, each block  [PDE rows of degree s - 4; edge rows l = s-1 and k = s-1]  is a small linear
// system in that anti-diagonal's unknowns, with the higher anti-diagonals already known: the
// whole system is block triangular. The edge rows give a_{1,s-1} and a_{s-1,1} directly
// (coefficient 1); the PDE rows of a block s <= n+1 are then a banded Toeplitz system (bandwidth
// 2 + 2, at most n - 2 unknowns) solved by banded Gaussian elimination with partial pivoting. The
// blocks s = n+2, n+3 (outside the box but for their corner, homogeneous) are truncated
// convolutions, solved by dense Gaussian elimination with complete pivoting; s >= n+4 are full
// convolutions, injective, so zero. A pivot below the rank tolerance is a rank-deficient block:
// a nonzero polynomial solution with zero data (the solution is not unique). At s = 2 the two
// edge rows both give a_11; the row of the edge u = 1 is used, as in the explicit route.
//
// Cost: O(n) per banded block and per edge row, O(n^3) for the two truncated blocks and for the
// interior part of the way back to Bernstein form (O(n^2) for the edges): O(n^3) in all, against
// O(n^6) for a dense solve; the Table 1 benchmark at n = 20 runs in tens of microseconds.
// Accuracy: the same basis changes as the explicit route (both stay at the data-rounding floor of
// docs/pde_accuracy.md; the blocks themselves are well conditioned).
// Factorial-scaled power basis <-> Bernstein at degree n in the scalar T, both lower triangular,
// row-major (n+1) x (n+1):
//   to(k, i) = k! (-1)^(k-i) C(n,k) C(k,i)  (a = to p),   from(i, k) = C(i,k) / (C(n,k) k!)  (p = from a).
template <class T>
void factorial_power_conversions(int n, std::vector<T>& to, std::vector<T>& from) {
  const int N = n + 1;
  auto c = [](int i, int k) { return binomial<T>(i, k); };  // exact in T
  to.assign(static_cast<size_t>(N * N), T(0));
  from.assign(static_cast<size_t>(N * N), T(0));
  T fact = 1;
  for (int k = 0; k <= n; ++k) {
    if (k > 0) fact *= k;
    for (int i = 0; i <= k; ++i)
      to[static_cast<size_t>(k * N + i)] = (((k - i) % 2) ? -fact : fact) * c(n, k) * c(k, i);
    for (int i = k; i <= n; ++i) from[static_cast<size_t>(i * N + k)] = c(i, k) / (c(n, k) * fact);
  }
}

// Solve the r x u block M y = b (r >= u, 3 right-hand sides; M row-major, b r x 3, both
// overwritten) by Gaussian elimination with complete pivoting, which reveals the rank: false if a
// pivot falls below tol x the largest entry. y (u x 3) is the solution of the first u pivot rows;
// for r > u the remaining rows are consistent by construction (the blocks of s > n+1 are
// homogeneous).
template <class T>
bool eliminate(int r, int u, T* M, T* b, T tol, T* y) {
  std::vector<int> colperm(static_cast<size_t>(u));
  for (int j = 0; j < u; ++j) colperm[static_cast<size_t>(j)] = j;
  T first = 0;
  for (int p = 0; p < u; ++p) {
    int pr = p, pc = p;
    T best = 0;
    for (int i = p; i < r; ++i)
      for (int j = p; j < u; ++j)
        if (std::abs(M[i * u + j]) > best) {
          best = std::abs(M[i * u + j]);
          pr = i;
          pc = j;
        }
    if (p == 0) first = best;
    if (!(best > tol * first) || !(first > 0)) return false;
    if (pr != p) {
      for (int j = 0; j < u; ++j) std::swap(M[p * u + j], M[pr * u + j]);
      for (int d = 0; d < 3; ++d) std::swap(b[p * 3 + d], b[pr * 3 + d]);
    }
    if (pc != p) {
      for (int i = 0; i < r; ++i) std::swap(M[i * u + p], M[i * u + pc]);
      std::swap(colperm[static_cast<size_t>(p)], colperm[static_cast<size_t>(pc)]);
    }
    const T piv = M[p * u + p];
    for (int i = p + 1; i < r; ++i) {
      const T f = M[i * u + p] / piv;
      if (f == T(0)) continue;
      for (int j = p + 1; j < u; ++j) M[i * u + j] -= f * M[p * u + j];
      for (int d = 0; d < 3; ++d) b[i * 3 + d] -= f * b[p * 3 + d];
    }
  }
  for (int p = u - 1; p >= 0; --p)
    for (int d = 0; d < 3; ++d) {
      T v = b[p * 3 + d];
      for (int j = p + 1; j < u; ++j) v -= M[p * u + j] * b[j * 3 + d];
      b[p * 3 + d] = v / M[p * u + p];
    }
  for (int p = 0; p < u; ++p)
    for (int d = 0; d < 3; ++d) y[colperm[static_cast<size_t>(p)] * 3 + d] = b[p * 3 + d];
  return true;
}

inline size_t sz(int i) { return static_cast<size_t>(i); }

// The basis-change tables are constants of the degree: built once per degree (thread-safe).
template <class T>
struct ConversionTables {
  std::vector<T> to, from;
};

template <class T>
const ConversionTables<T>& conversion_tables(int n) {
  // A DegreeCache never evicts: the reference stays valid for the life of the program.
  static DegreeCache<ConversionTables<T>> cache;
  return *cache.get(n, [](int d) {
    ConversionTables<T> t;
    factorial_power_conversions<T>(d, t.to, t.from);
    return t;
  });
}

// The unknowns a_kl of the square case and the edge data they must match.
template <class T>
struct AntiDiagonalUnknowns {
  int n, N;
  std::vector<T> a;         // a_kl, entry ((k*N + l)*3 + d)
  std::vector<T> e1v, e1u;  // factorial-scaled monomials of x(1,v) and x(u,1), entry (k*3 + d)
  std::vector<T> ifact;     // 1 / k!

  // Edges to factorial-scaled monomials: x(0,v) -> a_{0l}, x(u,0) -> a_{k0} (eq. (5)-(6));
  // x(1,v) -> e1v, x(u,1) -> e1u (eq. (7)).
  AntiDiagonalUnknowns(const TensorNet& data, const std::vector<T>& to)
      : n(data.n()), N(n + 1), a(sz(N * N * 3), T(0)), e1v(sz(N * 3), T(0)), e1u(sz(N * 3), T(0)), ifact(sz(N)) {
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= k; ++i) {
        const T w = to[sz(k * N + i)];
        for (int d = 0; d < 3; ++d) {
          A(0, k, d) += w * static_cast<T>(data.points()(data.index(0, i), d));
          A(k, 0, d) += k == 0 ? T(0) : w * static_cast<T>(data.points()(data.index(i, 0), d));
          e1v[sz(k * 3 + d)] += w * static_cast<T>(data.points()(data.index(n, i), d));
          e1u[sz(k * 3 + d)] += w * static_cast<T>(data.points()(data.index(i, n), d));
        }
      }
    T f = 1;
    for (int k = 0; k <= n; ++k) {
      if (k > 0) f *= k;
      ifact[sz(k)] = T(1) / f;
    }
  }

  T& A(int k, int l, int d) { return a[sz((k * N + l) * 3 + d)]; }

  // eq. (7): a_{1,s-1} from x(1, v) (index l = s-1), a_{s-1,1} from x(u, 1) (index k = s-1; not
  // at s = 2, where both give a_11).
  void edge_rows(int s) {
    {
      const int l = s - 1;
      for (int d = 0; d < 3; ++d) {
        T v = e1v[sz(l * 3 + d)] - A(0, l, d);
        for (int k = 2; k <= n; ++k) v -= ifact[sz(k)] * A(k, l, d);
        A(1, l, d) = v;
      }
    }
    if (s != 2) {
      const int k = s - 1;
      for (int d = 0; d < 3; ++d) {
        T v = e1u[sz(k * 3 + d)] - A(k, 0, d);
        for (int l = 2; l <= n; ++l) v -= ifact[sz(l)] * A(k, l, d);
        A(k, 1, d) = v;
      }
    }
  }
};

// Anti-diagonals s >= n+2 lie outside the box but for their corner: no data reach them (a_{s,0},
// a_{0,s} and the edge rows are absent), so their blocks are homogeneous and a = 0 there unless
// a block is rank deficient. For s >= n+4 the rows are the full convolution of the anti-diagonal
// with (c_0..c_4), injective for c != 0: nothing to do. s = n+2, n+3 are truncated convolutions:
// check their rank (e.g. the G-norm with rho = 1, t = 0 fails here, docs/pde_accuracy.md). Returns the first
// rank-deficient s, or 0 if both have full rank.
template <class T>
int rank_deficient_outer_block(const std::array<T, 5>& c, int n, T tol) {
  std::vector<T> M, b, y;
  for (int s = std::min(2 * n, n + 3); s >= n + 2; --s) {
    const int k0 = s - n, u = 2 * n - s + 1;  // unknowns a_{k, s-k}, k = s-n..n
    if (u <= 0) continue;
    M.assign(sz((s - 3) * u), T(0));
    int row = 0;
    for (int lp = 0; lp <= s - 4; ++lp) {
      bool touches = false;
      for (int j = 0; j <= 4; ++j) {
        const int k = s - lp - j, l = lp + j;
        if (k < k0 || k > n || l > n || c[sz(j)] == T(0)) continue;
        touches = true;
        M[sz(row * u + k - k0)] += c[sz(j)];
      }
      if (touches) ++row;
    }
    b.assign(sz(std::max(row, 1) * 3), T(0));
    y.assign(sz(u * 3), T(0));
    if (row < u || !eliminate<T>(row, u, M.data(), b.data(), tol, y.data())) return s;
  }
  return 0;
}

// Anti-diagonal s <= n+1, after its edge rows: the PDE rows l' = 0..s-4 are a banded Toeplitz
// system (bandwidth 2 + 2) in the interior y_l = a_{s-l,l}, l = 2..s-2, with y_0 = a_{s,0}, y_1,
// y_{s-1}, y_s = a_{0,s} known (system (9)). It is solved by banded Gaussian elimination with
// partial pivoting; a pivot below the rank tolerance (relative to max |c_j| = 1) means the block
// is singular: false (not unique). `band` and `rhs` are work space.
template <class T>
bool solve_interior_block(AntiDiagonalUnknowns<T>& x, int s, const std::array<T, 5>& c, T tol, std::vector<T>& band,
                          std::vector<T>& rhs) {
  const int n = x.n;
  const int W5 = 5;     // stored band width after pivoting fill: columns l0-2 .. l0+2 -> l0-2 .. l0+4
  const int m = s - 3;  // interior unknowns y_2..y_{s-2}
  if (m <= 0) return true;
  // Row l0 (0..m-1): sum_j c_j y_{l0+j} = 0. Unknown y_l -> column l - 2 = l0 + j - 2.
  // band(l0, q) holds column l0 - 2 + q, q = 0..6 (q = 5, 6: fill from row swaps).
  const int Q = W5 + 2;
  band.assign(sz(m * Q), T(0));
  rhs.assign(sz(m * 3), T(0));
  for (int l0 = 0; l0 < m; ++l0)
    for (int j = 0; j <= 4; ++j) {
      const int l = l0 + j, k = s - l;
      if (k > n || l > n) continue;  // outside the box: a = 0
      if (l >= 2 && l <= s - 2)
        band[sz(l0 * Q + j)] += c[sz(j)];
      else
        for (int d = 0; d < 3; ++d) rhs[sz(l0 * 3 + d)] -= c[sz(j)] * x.A(k, l, d);
    }
  // Banded elimination with partial pivoting (rows l0 .. l0+2 can hold column l0).
  auto at_col = [&](int r, int col) -> T& { return band[sz(r * Q + (col - r + 2))]; };
  for (int p = 0; p < m; ++p) {
    int pr = p;
    T best = std::abs(at_col(p, p));
    for (int r = p + 1; r <= std::min(m - 1, p + 2); ++r)
      if (std::abs(at_col(r, p)) > best) {
        best = std::abs(at_col(r, p));
        pr = r;
      }
    if (!(best > tol)) return false;
    const int cmaxcol = std::min(m - 1, p + 4);
    if (pr != p) {
      for (int col = p; col <= cmaxcol; ++col) {
        // Columns beyond a row's stored range are zero; the swap stays inside both rows' ranges
        // because rows p..p+2 all cover columns p..p+4.
        std::swap(at_col(p, col), at_col(pr, col));
      }
      for (int d = 0; d < 3; ++d) std::swap(rhs[sz(p * 3 + d)], rhs[sz(pr * 3 + d)]);
    }
    const T piv = at_col(p, p);
    for (int r = p + 1; r <= std::min(m - 1, p + 2); ++r) {
      const T f = at_col(r, p) / piv;
      if (f == T(0)) continue;
      at_col(r, p) = 0;
      for (int col = p + 1; col <= cmaxcol; ++col) at_col(r, col) -= f * at_col(p, col);
      for (int d = 0; d < 3; ++d) rhs[sz(r * 3 + d)] -= f * rhs[sz(p * 3 + d)];
    }
  }
  for (int p = m - 1; p >= 0; --p)
    for (int d = 0; d < 3; ++d) {
      T v = rhs[sz(p * 3 + d)];
      for (int col = p + 1; col <= std::min(m - 1, p + 4); ++col) v -= at_col(p, col) * rhs[sz(col * 3 + d)];
      rhs[sz(p * 3 + d)] = v / at_col(p, p);
    }
  for (int l = 2; l <= s - 2; ++l)
    for (int d = 0; d < 3; ++d) x.A(s - l, l, d) = rhs[sz((l - 2) * 3 + d)];
  return true;
}

// Back to Bernstein form, P_d = from * A_d * from^T (from lower triangular). Split A into its
// edge lines (k <= 1 or l <= 1: they carry the boundary curves, and summing them to Bernstein form
// cancels ~3^n-fold, so they stay in T: O(n^2)) and the interior block k, l >= 2 (the cached
// double conversion of tensor/power_basis.h: O(n^3), vectorised).
//   from A_edge from^T (i, j) = from(i,0) r_0(j) + from(i,1) r_1(j) + c_0(i) from(j,0) + c_1(i) from(j,1)
//   r_k(j) = sum_l from(j,l) A(k,l)  (k = 0, 1),   c_l(i) = sum_{k>=2} from(i,k) A(k,l)  (l = 0, 1).
template <class T>
Eigen::MatrixX3d to_bernstein(AntiDiagonalUnknowns<T>& x, const std::vector<T>& from) {
  const int n = x.n, N = x.N;
  std::vector<T> r(sz(2 * N * 3), T(0)), cc(sz(2 * N * 3), T(0));
  for (int e = 0; e < 2; ++e)
    for (int j = 0; j <= n; ++j)
      for (int d = 0; d < 3; ++d) {
        T rv = 0, cv = 0;
        for (int l = 0; l <= j; ++l) rv += from[sz(j * N + l)] * x.A(e, l, d);
        for (int k = 2; k <= j; ++k) cv += from[sz(j * N + k)] * x.A(k, e, d);
        r[sz((e * N + j) * 3 + d)] = rv;
        cc[sz((e * N + j) * 3 + d)] = cv;
      }
  Eigen::MatrixX3d interior = Eigen::MatrixX3d::Zero(N * N, 3);
  for (int k = 2; k <= n; ++k)
    for (int l = 2; l <= n + 1 - k; ++l)
      for (int d = 0; d < 3; ++d) interior(k * N + l, d) = static_cast<double>(x.A(k, l, d));
  TensorNet interior_net = from_factorial_power(n, n, interior);
  Eigen::MatrixX3d P = std::move(interior_net.points());
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      for (int d = 0; d < 3; ++d) {
        const T v = from[sz(i * N)] * r[sz(j * 3 + d)] + from[sz(i * N + 1)] * r[sz((N + j) * 3 + d)] +
                    cc[sz(i * 3 + d)] * from[sz(j * N)] + cc[sz((N + i) * 3 + d)] * from[sz(j * N + 1)];
        P(i * N + j, d) = static_cast<double>(v + static_cast<T>(P(i * N + j, d)));
      }
  return P;
}

// The square case n = m: the anti-diagonals s = 2n .. 2 in turn (see the comment above). False
// with the status and reason when the solution is not unique or overflows.
template <class T>
bool antidiagonal_solve(const TensorNet& data, std::vector<double> coeffs, double rank_tolerance, TensorNet& out,
                        Status& status, std::string& why) {
  const int n = data.n();
  double cmax = 0;
  for (double x : coeffs) cmax = std::max(cmax, std::abs(x));
  if (!(cmax > 0)) {
    status = Status::NotUnique;
    why = "the polynomial solution is not unique: the operator is zero";
    return false;
  }
  // PDE rows with entries O(1), like the edge rows: a fair rank test.
  std::array<T, 5> c{};
  for (size_t j = 0; j < 5; ++j) c[j] = static_cast<T>(coeffs[j] / cmax);
  const ConversionTables<T>& tables = conversion_tables<T>(n);
  AntiDiagonalUnknowns<T> x(data, tables.to);
  auto not_unique = [&](int s) {
    std::ostringstream m;
    m << "the polynomial solution is not unique: on the anti-diagonal k + l = " << s
      << " the operator has a nonzero polynomial solution with zero boundary data";
    status = Status::NotUnique;
    why = m.str();
    return false;
  };
  const T tol = static_cast<T>(rank_tolerance);
  if (const int s = rank_deficient_outer_block<T>(c, n, tol)) return not_unique(s);
  std::vector<T> band, rhs;
  for (int s = std::min(n + 1, 2 * n); s >= 2; --s) {
    x.edge_rows(s);
    if (!solve_interior_block<T>(x, s, c, tol, band, rhs)) return not_unique(s);
  }
  Eigen::MatrixX3d P = to_bernstein<T>(x, tables.from);
  if (!P.allFinite()) {
    status = Status::NumericalLimit;
    why = "the linear solve overflowed double precision";
    return false;
  }
  out = TensorNet(n, n, std::move(P));
  // The prescribed ring is data: copy it exactly (the basis round trip rounds it).
  for (int k = 0; k <= n; ++k)
    for (int idx : {data.index(0, k), data.index(n, k), data.index(k, 0), data.index(k, n)})
      out.points().row(idx) = data.points().row(idx);
  return true;
}

}  // namespace

namespace {
// x_free = S x_fixed for the 3 coordinates, as XF^T = XB^T S^T: the column-major storage of S,
// XB and XF is exactly the row-major storage of S^T, XB^T and XF^T, so one row_major_product
// (3 rows, #free columns, vectorised along the free points) does it.
Eigen::MatrixXd mould_product(const Eigen::MatrixXd& S, const Eigen::MatrixXd& XB) {
  const int nf = static_cast<int>(S.rows()), nb = static_cast<int>(S.cols());
  Eigen::MatrixXd XF(nf, 3);
  row_major_product(XB.data(), 3, nb, nb, S.data(), nf, nf, XF.data(), nf);
  return XF;
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
  const MatL KFF = K(Eigen::all, free_idx_), KFB = K(Eigen::all, fixed_idx_);
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
  const Eigen::MatrixXd XB = data.points()(fixed_idx_, Eigen::all);
  const Eigen::MatrixXd XF = mould_product(S_, XB);
  out.points()(fixed_idx_, Eigen::all) = XB;
  out.points()(free_idx_, Eigen::all) = XF;
}

double PdeMould::compatibility_violation(const TensorNet& data) const {
  if (W_.rows() == 0) return 0.0;
  return violation(W_, data.points()(fixed_idx_, Eigen::all));
}

PdeSolution PdeMould::solve(const TensorNet& data) const {
  PdeSolution out;
  {
    ScopedTimer timer(out.summary.seconds);
    if (data.n() != n_ || data.m() != m_) {
      std::ostringstream s;
      s << "pde mould of degree [" << n_ << ", " << m_ << "] cannot solve a net of degree [" << data.n() << ", "
        << data.m() << "]";
      throw DegreeError(s.str());
    }
    if (!structure_.unique) {
      out = not_unique(data, structure_);
    } else {
      const Eigen::MatrixXd XB = data.points()(fixed_idx_, Eigen::all);
      const Eigen::MatrixXd XF = mould_product(S_, XB);
      const double viol = W_.rows() ? violation(W_, XB) : 0.0;
      out = finish(data, n_, m_, {fixed_idx_, free_idx_}, XF, viol, options_.compatibility_tolerance, structure_);
    }
  }
  return out;
}

namespace {

// n = m: the block LU on the anti-diagonals.
PdeSolution solve_antidiagonal(const TensorNet& data, const EnergySpec& op, const PdeLuOptions& options) {
  const int n = data.n();
  PdeSolution out{data, Summary{}};
  Status status = Status::NoConvergence;
  std::string why;
  TensorNet sol(n, n);
  if (antidiagonal_solve<LD>(data, operator_coefficients(op), options.rank_tolerance, sol, status, why)) {
    out.net = std::move(sol);
    out.summary.set_converged();
    check_pde_degree_limit(n, n, "lu", out.summary);
  } else {
    out.summary.set_failed(status, why + "; the data are returned unchanged");
  }
  return out;
}

// Any degrees: the Bernstein least-squares system, factored for this call.
PdeSolution solve_bernstein(const TensorNet& data, const EnergySpec& op, const PdeLuOptions& options) {
  const int n = data.n(), m = data.m();
  const PdeStructure st =
      analyse_pde_structure(operator_coefficients(op), n, m, FixedSet::Boundary, options.rank_tolerance);
  if (!st.unique) return not_unique(data, st);
  const Split sp = split_indices(n, m, FixedSet::Boundary);
  const MatL K = bernstein_matrix_ld(pde_operator_terms(op), n, m);
  const MatL KFB = K(Eigen::all, sp.fixed);
  const Eigen::MatrixXd XB = data.points()(sp.fixed, Eigen::all);
  Eigen::MatrixXd XF(static_cast<Eigen::Index>(sp.free.size()), 3);
  double viol = 0;
  if (!sp.free.empty()) {
    ScaledQR f;
    factor(K(Eigen::all, sp.free), f);
    XF = (f.scale.cwiseInverse().asDiagonal() * f.qr.solve(MatL(-(KFB * XB.cast<LD>())))).cast<double>();
    if (st.conditions > 0) viol = violation(compatibility_rows(f, KFB, st.conditions), XB);
  } else if (st.conditions > 0) {
    viol = violation(conditions_without_unknowns(KFB, st.conditions), XB);
  }
  PdeSolution out = finish(data, n, m, sp, XF, viol, options.compatibility_tolerance, st);
  check_pde_degree_limit(n, m, "lu", out.summary);
  return out;
}

}  // namespace

PdeSolution solve_pde_lu(const TensorNet& data, const EnergySpec& op, const PdeLuOptions& options) {
  PdeSolution out;
  {
    ScopedTimer timer(out.summary.seconds);
    options.validate();
    check_problem(op, FixedSet::Boundary);
    if (data.n() == data.m() && options.formulation == PdeLuOptions::Formulation::AntiDiagonal)
      out = solve_antidiagonal(data, op, options);
    else
      out = solve_bernstein(data, op, options);
  }
  return out;
}

}  // namespace bpde
