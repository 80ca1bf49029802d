#include "bezierpde/solvers/c1/tetraharmonic.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/bernstein_ops.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/interruption.h"
#include "bezierpde/core/keyed_cache.h"
#include "bezierpde/core/kron.h"
#include "bezierpde/solvers/c1/biharmonic_load.h"
#include "bezierpde/solvers/c1/refine_mould.h"
#include "bezierpde/tensor/power_basis.h"

namespace bpde {
namespace {

using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
constexpr double kBinom4[5] = {1.0, 4.0, 6.0, 4.0, 1.0};

void check_data(const TensorNet& data) {
  if (data.n() != data.m())
    throw DegreeError("tetraharmonic: needs a net of degree [n, n], got [" + std::to_string(data.n()) + ", " +
                      std::to_string(data.m()) + "]");
  if (data.n() < 4)
    throw DegreeError("tetraharmonic: needs degree n >= 4 (Theorem 1), got " + std::to_string(data.n()));
  require_finite_rows(data.points(), data.fixed_indices(FixedSet::BoundaryAdjacent), "tetraharmonic data",
                      data.m() + 1);
}

// ---- high-precision pieces of the solution operator (computed once per degree).
// The Bernstein least-squares matrix is ill-conditioned (cond(A_I) ~ 3e6 at n = 12, 3e10 at
// n = 16, 5e13 at n = 20), so a double QR loses up to 1e-3 relative in G. We factor in long double
// (64-bit mantissa) and refine G with residuals computed in binary128 from exact matrix entries.
using MatL = MatLD;

// Eigen's HouseholderQR computed as Eigen computes it (householder_qr_inplace_blocked: panels of
// 48 columns, each factored and then applied to the trailing columns) with an interruption point
// (core/interruption.h) between the panels: the QR of the degree-40 operator takes tens of seconds.
// The same numbers as HouseholderQR(A); solve() and the other members are HouseholderQR's.
class InterruptibleQR : public Eigen::HouseholderQR<MatL> {
 public:
  explicit InterruptibleQR(const MatL& A) {
    constexpr Eigen::Index kPanel = 48;  // Eigen's block size in HouseholderQR::computeInPlace
    m_qr = A;
    const Eigen::Index rows = A.rows(), cols = A.cols(), size = std::min(rows, cols);
    m_hCoeffs.resize(size);
    m_temp.resize(cols);
    for (Eigen::Index k = 0; k < size; k += kPanel) {
      check_interruption();
      const Eigen::Index bs = std::min(size - k, kPanel), tcols = cols - k - bs, brows = rows - k;
      Eigen::Block<MatL> A11_21 = m_qr.block(k, k, brows, bs);
      auto h = m_hCoeffs.segment(k, bs);
      Eigen::internal::householder_qr_inplace_unblocked(A11_21, h, m_temp.data());
      if (tcols) {
        Eigen::Block<MatL> A21_22 = m_qr.block(k, k + bs, brows, tcols);
        Eigen::internal::apply_block_householder_on_the_left(A21_22, A11_21, h, false);
      }
    }
    m_isInitialized = true;
  }
};

struct LuSolver {
  std::vector<int> interior, fixed;
  Eigen::MatrixXd G;                               // interior = G * fixed
  std::vector<std::vector<quad>> T;                // T_0, T_2, .., T_8 in quad (index d)
  std::unique_ptr<InterruptibleQR> qr;             // of the interior columns, for refinement
  std::vector<Eigen::MatrixXd> TD;  // T_0, T_2, .., T_8 rounded to double (index d/2)
  Eigen::MatrixXd pinv;  // the least-squares operator qr->solve(.) as an (interior x (n+1)^2) matrix
};

// sum_t C(4,t) T_{8-2t} X T_{2t}^T in quad for one coordinate (X row-major (n+1)^2).
void apply_operator(const std::vector<std::vector<quad>>& T, int n, const std::vector<quad>& X, std::vector<quad>& Y) {
  const int n1 = n + 1, N = n1 * n1;
  std::fill(Y.begin(), Y.end(), quad(0));
  std::vector<quad> XB(static_cast<size_t>(N));
  for (int t = 0; t <= 4; ++t) {
    if (8 - 2 * t > n || 2 * t > n) continue;
    const auto& A = T[static_cast<size_t>(8 - 2 * t)];
    const auto& B = T[static_cast<size_t>(2 * t)];
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        quad acc = 0;
        for (int l = 0; l <= n; ++l) {
          const quad b = B[static_cast<size_t>(j * n1 + l)];
          if (b != 0) acc += X[static_cast<size_t>(i * n1 + l)] * b;
        }
        XB[static_cast<size_t>(i * n1 + j)] = acc;
      }
    for (int i = 0; i <= n; ++i)
      for (int k = 0; k <= n; ++k) {
        const quad a = A[static_cast<size_t>(i * n1 + k)];
        if (a == 0) continue;
        const quad ca = kBinom4[t] * a;
        for (int j = 0; j <= n; ++j) Y[static_cast<size_t>(i * n1 + j)] += ca * XB[static_cast<size_t>(k * n1 + j)];
      }
  }
}

std::shared_ptr<const LuSolver> build_lu_solver(int n) {
  auto s = std::make_shared<LuSolver>();
  const TensorNet shape(n, n);
  s->fixed = shape.fixed_indices(FixedSet::BoundaryAdjacent);
  s->interior = shape.free_indices(FixedSet::BoundaryAdjacent);
  const int n1 = n + 1, N = n1 * n1, ni = static_cast<int>(s->interior.size()), nf = static_cast<int>(s->fixed.size());
  std::vector<std::vector<quad>> T(9);
  for (int d = 0; d <= 8; d += 2) {
    check_interruption();  // core/interruption.h (each matrix takes seconds in binary128 at n = 40)
    T[static_cast<size_t>(d)] = derivative_at_degree_rm<quad>(n, d);
  }
  // Operator columns in long double: column (k,l) of sum_t C_t T_{8-2t} (x) T_{2t} is
  // sum_t C_t T_{8-2t}(:,k) T_{2t}(:,l)^T.
  auto column = [&](int k, int l, Eigen::Ref<VecLD> out) {
    out.setZero();
    for (int t = 0; t <= 4; ++t) {
      const auto& A = T[static_cast<size_t>(8 - 2 * t)];
      const auto& B = T[static_cast<size_t>(2 * t)];
      for (int i = 0; i <= n; ++i) {
        const quad a = A[static_cast<size_t>(i * n1 + k)];
        if (a == 0) continue;
        for (int j = 0; j <= n; ++j)
          out(i * n1 + j) += static_cast<long double>(kBinom4[t] * a * B[static_cast<size_t>(j * n1 + l)]);
      }
    }
  };
  // Interruption points (core/interruption.h): every 64 columns assembled or solved, 16 refined, and
  // between the panels of the QR factorisation (InterruptibleQR).
  constexpr int kColumnBlock = 64;
  MatL AI(N, ni), AF(N, nf);
  for (int c = 0; c < ni; ++c) {
    if (c % kColumnBlock == 0) check_interruption();
    column(s->interior[static_cast<size_t>(c)] / n1, s->interior[static_cast<size_t>(c)] % n1, AI.col(c));
  }
  for (int c = 0; c < nf; ++c) {
    if (c % kColumnBlock == 0) check_interruption();
    column(s->fixed[static_cast<size_t>(c)] / n1, s->fixed[static_cast<size_t>(c)] % n1, AF.col(c));
  }
  check_interruption();
  s->qr = std::make_unique<InterruptibleQR>(AI);
  check_interruption();
  const Eigen::HouseholderQR<MatL>& qr = *s->qr;
  // qr.solve by blocks of columns (each column of the right-hand side is solved on its own).
  auto solve_by_blocks = [&](const auto& rhs) {
    MatL X(ni, rhs.cols());
    for (Eigen::Index c = 0; c < rhs.cols(); c += kColumnBlock) {
      const Eigen::Index w = std::min<Eigen::Index>(kColumnBlock, rhs.cols() - c);
      X.middleCols(c, w) = qr.solve(MatL(rhs.middleCols(c, w)));
      check_interruption();
    }
    return X;
  };
  MatL G = -solve_by_blocks(AF);
  // Refinement: R = A_I G + A_F in quad (Kronecker form, X_c = G(:,c) on the interior + e_f),
  // then G -= QR \ R. The system is consistent (Theorem 1), so R -> 0.
  // Two steps (solvers/c1/refine_mould.h) suffice up to n ~ 20; none below n = 9.
  std::vector<quad> X(static_cast<size_t>(N)), Y(static_cast<size_t>(N));
  refine_mould(
      G, n <= 8 ? 0 : 2,
      [&](const MatL& cur) {
        MatL R(N, nf);
        for (int c = 0; c < nf; ++c) {
          // every 16 columns: each applies the operator in binary128 (a tenth of a second at n = 40)
          if (c % 16 == 0) check_interruption();
          mould_column(cur, c, s->interior, s->fixed, X);
          apply_operator(T, n, X, Y);
          for (int r = 0; r < N; ++r) R(r, c) = static_cast<long double>(Y[static_cast<size_t>(r)]);
        }
        return R;
      },
      [&](const MatL& R) -> MatL { return solve_by_blocks(R); });
  s->G = G.cast<double>();
  for (int d = 0; d <= 8; d += 2) {
    Eigen::MatrixXd M(n1, n1);
    for (int i = 0; i < n1; ++i)
      for (int j = 0; j < n1; ++j)
        M(i, j) = static_cast<double>(T[static_cast<size_t>(d)][static_cast<size_t>(i * n1 + j)]);
    s->TD.push_back(std::move(M));
  }
  s->pinv = solve_by_blocks(MatL::Identity(N, N)).cast<double>();
  s->T = std::move(T);
  return s;
}

std::shared_ptr<const LuSolver> lu_solver(int n) {
  static DegreeCache<LuSolver> cache;
  return cache.get(n, build_lu_solver, "lu solver");
}

// Relative residual of Δ⁴x: max |Bernstein coefficient of Δ⁴x| divided by the max of the same
// sums taken in absolute values, sum_t C(4,t) |T_{8-2t}| |X| |T_{2t}|^T (the size of the terms
// that cancel).
double relative_residual(const TensorNet& net) {
  const int n = net.n();
  std::vector<Eigen::MatrixXd> T(9);
  for (int d = 0; d <= 8; d += 2) T[static_cast<size_t>(d)] = derivative_at_degree(n, d);
  double res = 0.0, scale = 0.0;
  for (int c = 0; c < 3; ++c) {
    const Eigen::Map<const RowMat> X(net.points().col(c).data(), n + 1, n + 1);
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(n + 1, n + 1), mag = sum;
    for (int t = 0; t <= 4; ++t) {
      const Eigen::MatrixXd& A = T[static_cast<size_t>(8 - 2 * t)];
      const Eigen::MatrixXd& B = T[static_cast<size_t>(2 * t)];
      sum += kBinom4[t] * (A * X * B.transpose());
      mag += kBinom4[t] * (A.cwiseAbs() * X.cwiseAbs() * B.cwiseAbs().transpose());
    }
    res = std::max(res, sum.cwiseAbs().maxCoeff());
    scale = std::max(scale, mag.maxCoeff());
  }
  return scale > 0.0 ? res / scale : 0.0;
}

// ---- the explicit recursion of Annex A, in named steps.

// Row i of the net (P_i0..P_in) and column j (P_0j..P_nj) as (n+1) x 3 Bernstein coefficients.
Eigen::MatrixX3d net_row(const TensorNet& data, int i) {
  const int n = data.n();
  Eigen::MatrixX3d r(n + 1, 3);
  for (int j = 0; j <= n; ++j) r.row(j) = data.points().row(data.index(i, j));
  return r;
}
Eigen::MatrixX3d net_col(const TensorNet& data, int j) {
  const int n = data.n();
  Eigen::MatrixX3d r(n + 1, 3);
  for (int i = 0; i <= n; ++i) r.row(i) = data.points().row(data.index(i, j));
  return r;
}

// Factorial power coefficients (k! times power coefficient k) of a Bernstein curve; Mp is the
// Bernstein-to-power matrix of degree n.
Eigen::MatrixX3d factorial_power(const Eigen::MatrixXd& Mp, int n, const Eigen::MatrixX3d& bern) {
  Eigen::MatrixX3d c = Mp * bern;
  for (int k = 0; k <= n; ++k) c.row(k) *= factorial(k);
  return c;
}

// The coefficients a_ij being filled in, and the curves at u = 1 and v = 1 they must match.
struct AnnexA {
  int n;
  Eigen::MatrixX3d a;                 // a_ij, row i*(n+1)+j; zero until set
  Eigen::MatrixX3d X1, DX1, Y1, DY1;  // x(1,v), x_u(1,v), x(u,1), x_v(u,1) (factorial power basis)

  // Boundary curves and cross derivatives in the factorial power basis: eqs. (17)-(24). Sets
  // a_0j, a_1j, a_i0, a_i1.
  explicit AnnexA(const TensorNet& data) : n(data.n()), a(Eigen::MatrixX3d::Zero((n + 1) * (n + 1), 3)) {
    const Eigen::MatrixXd Mp = bernstein_to_power_matrix(n);
    auto fpow = [&](const Eigen::MatrixX3d& bern) { return factorial_power(Mp, n, bern); };
    const Eigen::MatrixX3d a0j = fpow(net_row(data, 0)), a1j = fpow(n * (net_row(data, 1) - net_row(data, 0)));
    const Eigen::MatrixX3d ai0 = fpow(net_col(data, 0)), ai1 = fpow(n * (net_col(data, 1) - net_col(data, 0)));
    X1 = fpow(net_row(data, n));
    DX1 = fpow(n * (net_row(data, n) - net_row(data, n - 1)));
    Y1 = fpow(net_col(data, n));
    DY1 = fpow(n * (net_col(data, n) - net_col(data, n - 1)));
    for (int k = 0; k <= n; ++k) {
      set(0, k, a0j.row(k));
      set(1, k, a1j.row(k));
      set(k, 0, ai0.row(k));
      set(k, 1, ai1.row(k));
    }
  }

  Eigen::RowVector3d A(int i, int j) const {
    if (i < 0 || j < 0 || i > n || j > n) return Eigen::RowVector3d::Zero();
    return a.row(i * (n + 1) + j);
  }
  void set(int i, int j, const Eigen::RowVector3d& x) { a.row(i * (n + 1) + j) = x; }

  // S^k: unknowns a_2k, a_3k (column k); S_k: unknowns a_k2, a_k3 (row k).
  //   a2/2 + a3/6 = r1,  a2 + a3/2 = r2   =>   a2 = 6 r1 - 2 r2,  a3 = 6 r2 - 12 r1.
  void solve_column(int k, Eigen::RowVector3d& a2, Eigen::RowVector3d& a3) const {
    Eigen::RowVector3d r1 = X1.row(k) - A(0, k) - A(1, k), r2 = DX1.row(k) - A(1, k);
    for (int i = 4; i <= n; ++i) {
      r1 -= A(i, k) / factorial(i);
      r2 -= A(i, k) / factorial(i - 1);
    }
    a2 = 6.0 * r1 - 2.0 * r2;
    a3 = 6.0 * r2 - 12.0 * r1;
  }
  void solve_row(int k, Eigen::RowVector3d& a2, Eigen::RowVector3d& a3) const {
    Eigen::RowVector3d r1 = Y1.row(k) - A(k, 0) - A(k, 1), r2 = DY1.row(k) - A(k, 1);
    for (int j = 4; j <= n; ++j) {
      r1 -= A(k, j) / factorial(j);
      r2 -= A(k, j) / factorial(j - 1);
    }
    a2 = 6.0 * r1 - 2.0 * r2;
    a3 = 6.0 * r2 - 12.0 * r1;
  }

  // Lemma 2 on the diagonal i + j = r (r >= 8): unknowns a_{r-j,j}, 4 <= j <= r-4, split by the
  // parity of j; the equations are eq. (7) at (r-8-j', j'), j' = j - 4.
  void lemma2(int r) {
    for (int p = 0; p <= 1; ++p) {
      std::vector<int> J;
      for (int j = 4; j <= r - 4; ++j)
        if (j % 2 == p) J.push_back(j);
      const int K = static_cast<int>(J.size());
      if (K == 0) continue;
      Eigen::MatrixXd M = Eigen::MatrixXd::Zero(K, K);
      Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(K, 3);
      for (int e = 0; e < K; ++e) {
        const int jp = J[static_cast<size_t>(e)] - 4;
        for (int t = 0; t <= 4; ++t) {
          const int jj = jp + 2 * t;
          if (jj >= 4 && jj <= r - 4)
            M(e, (jj - J[0]) / 2) += kBinom4[t];
          else
            rhs.row(e) -= kBinom4[t] * A(r - jj, jj);
        }
      }
      const Eigen::MatrixXd sol = M.llt().solve(rhs);
      for (int e = 0; e < K; ++e) set(r - J[static_cast<size_t>(e)], J[static_cast<size_t>(e)], sol.row(e));
    }
  }
};

}  // namespace

void TetraharmonicOptions::validate() const {
  if (method != Method::Explicit && method != Method::LU)
    throw ParameterError("tetraharmonic: unknown method (use \"explicit\" or \"lu\")");
}

TetraharmonicOptions::Method parse_tetraharmonic_method(const std::string& name) {
  if (name == "explicit") return TetraharmonicOptions::Method::Explicit;
  if (name == "lu") return TetraharmonicOptions::Method::LU;
  throw ParameterError("tetraharmonic: unknown method \"" + name + "\" (use \"explicit\" or \"lu\")");
}

Eigen::MatrixXd tetraharmonic_operator(int n) {
  if (n < 1) throw DegreeError("tetraharmonic_operator: needs n >= 1");
  const int N = (n + 1) * (n + 1);
  Eigen::MatrixXd Op = Eigen::MatrixXd::Zero(N, N);
  for (int t = 0; t <= 4; ++t) {
    if (8 - 2 * t > n || 2 * t > n) continue;
    Op += kBinom4[t] * kron(derivative_at_degree(n, 8 - 2 * t), derivative_at_degree(n, 2 * t));
  }
  return Op;
}

namespace tetraharmonic_detail {

Eigen::MatrixXd lemma2_matrix(int k) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(k, k);
  for (int i = 0; i < k; ++i)
    for (int d = -2; d <= 2; ++d)
      if (i + d >= 0 && i + d < k) M(i, i + d) = kBinom4[d + 2];
  return M;
}

double lemma2_determinant(int k) {
  const double K = k;
  return (12.0 + 28.0 * K + 23.0 * K * K + 8.0 * K * K * K + K * K * K * K) / 12.0;
}

Eigen::MatrixX3d explicit_coefficients(const TensorNet& data) {
  check_data(data);
  const int n = data.n();
  AnnexA s(data);
  Eigen::RowVector3d c2, c3, r2, r3;
  for (int k = n; k >= 4; --k) {
    s.solve_column(k, c2, c3);
    s.solve_row(k, r2, r3);
    s.set(2, k, c2);
    s.set(3, k, c3);
    s.set(k, 2, r2);
    s.set(k, 3, r3);
    if (k + 3 >= 8) s.lemma2(k + 3);
  }
  // k = 3: a_23, a_33 from S^3; a_32 (and a_33 again) from S_3 — compatible (eqs. (32)-(33)).
  s.solve_column(3, c2, c3);
  s.solve_row(3, r2, r3);
  s.set(2, 3, c2);
  s.set(3, 2, r2);
  s.set(3, 3, 0.5 * (c3 + r3));
  // k = 2: a_22 from S^2 and S_2 (a_32, a_23 already known).
  s.solve_column(2, c2, c3);
  s.solve_row(2, r2, r3);
  s.set(2, 2, 0.5 * (c2 + r2));
  return s.a;
}

}  // namespace tetraharmonic_detail

namespace {

// Per-solve refinement where G * data cancels (a small solution from a large G), only for the
// coordinates whose relative residual exceeds kRefineAbove, and only until it is below kRefineTo
// (at most 3 steps), all in double: the residual sum_t C(4,t) T_{8-2t} X T_{2t}^T of the double net
// (its rounding floor, ~1e-16 of the terms, is far below the 1e-12 that G * data leaves), the
// correction by the cached least-squares operator as one matrix-vector product (its own relative
// error, up to cond x 1e-16, applies to a correction that is itself ~1e-12 of the net). It used to
// compute the residual in binary128 and correct all three coordinates 3 times by long-double
// Householder solves whenever any residual exceeded 1e-12: 74-119x the explicit route from n = 16.
// What it buys is measured in docs/performance_measurements.md ("Tetraharmonic and the plate").
constexpr double kRefineAbove = 1e-12;
constexpr double kRefineTo = 1e-16;

void refine_lu_solution(const LuSolver& s, int n, TensorNet& net) {
  const int n1 = n + 1, N = n1 * n1;
  for (int c = 0; c < 3; ++c) {
    Eigen::MatrixXd X(n1, n1);
    for (int r = 0; r < N; ++r) X(r / n1, r % n1) = net.points()(r, c);
    // The size of the terms that cancel, sum_t C(4,t) |T_{8-2t}| |X| |T_{2t}|^T (as relative_residual).
    const Eigen::MatrixXd Xa = X.cwiseAbs();
    Eigen::MatrixXd mag = Eigen::MatrixXd::Zero(n1, n1);
    for (int t = 0; t <= 4; ++t) {
      if (8 - 2 * t > n || 2 * t > n) continue;
      mag += kBinom4[t] * (s.TD[static_cast<size_t>(4 - t)].cwiseAbs() * Xa *
                           s.TD[static_cast<size_t>(t)].cwiseAbs().transpose());
    }
    const double scale = mag.maxCoeff();
    if (!(scale > 0)) continue;
    for (int step = 0; step <= 3; ++step) {
      Eigen::MatrixXd Y = Eigen::MatrixXd::Zero(n1, n1);
      for (int t = 0; t <= 4; ++t) {
        if (8 - 2 * t > n || 2 * t > n) continue;
        Y.noalias() += kBinom4[t] * (s.TD[static_cast<size_t>(4 - t)] * X * s.TD[static_cast<size_t>(t)].transpose());
      }
      const double rel = Y.cwiseAbs().maxCoeff() / scale;
      if (rel <= (step == 0 ? kRefineAbove : kRefineTo) || step == 3) break;
      Eigen::VectorXd res(N);
      for (int r = 0; r < N; ++r) res(r) = Y(r / n1, r % n1);
      const Eigen::VectorXd d = s.pinv * res;
      for (size_t r = 0; r < s.interior.size(); ++r) {
        const int id = s.interior[r];
        X(id / n1, id % n1) -= d(static_cast<Eigen::Index>(r));
      }
    }
    for (int r : s.interior) net.points()(r, c) = X(r / n1, r % n1);
  }
}

// The LU method: interior = G * outer rings (the cached solution operator), refined if needed.
// `residual` receives relative_residual of the returned net (computed once when no refinement runs).
TensorNet lu_solution(const TensorNet& data, const std::vector<int>& fixed, bool refine, double& residual) {
  const int n = data.n();
  TensorNet net(n, n);
  const auto s = lu_solver(n);
  Eigen::MatrixXd xf(s->fixed.size(), 3);
  for (size_t r = 0; r < s->fixed.size(); ++r) xf.row(static_cast<Eigen::Index>(r)) = data.points().row(s->fixed[r]);
  const Eigen::MatrixXd xi = s->G * xf;
  for (size_t r = 0; r < s->interior.size(); ++r)
    net.points().row(s->interior[r]) = xi.row(static_cast<Eigen::Index>(r));
  for (int r : fixed) net.points().row(r) = data.points().row(r);
  residual = relative_residual(net);
  if (refine && residual > kRefineAbove) {
    refine_lu_solution(*s, n, net);
    residual = relative_residual(net);
  }
  return net;
}

TetraharmonicResult solve_tetraharmonic_untimed(const TensorNet& data, const TetraharmonicOptions& options) {
  check_data(data);
  const int n = data.n();
  const bool explicit_method = options.method == TetraharmonicOptions::Method::Explicit;
  const std::vector<int> fixed = data.fixed_indices(FixedSet::BoundaryAdjacent);
  double lu_residual = 0.0;
  TensorNet net = explicit_method ? from_factorial_power(n, n, tetraharmonic_detail::explicit_coefficients(data))
                                  : lu_solution(data, fixed, options.refine, lu_residual);
  for (int r : fixed) net.points().row(r) = data.points().row(r);

  TetraharmonicResult result{net, {}};
  Summary& summary = result.summary;
  summary.residual = explicit_method ? relative_residual(net) : lu_residual;
  if (std::isfinite(summary.residual) && summary.residual <= kConvergenceTolerance) {
    summary.set_converged();
    summary.message =
        explicit_method ? "solved (explicit recursion of Annex A)" : "solved (Bernstein-basis least squares, QR)";
  } else {
    std::ostringstream m;
    m << "Δ⁴x vanishes only to a relative residual of " << summary.residual
      << (explicit_method ? " (the power-basis recursion lost accuracy at this degree; use \"lu\")" : "");
    summary.set_failed(Status::NumericalLimit, m.str());
  }
  return result;
}

}  // namespace

TetraharmonicResult solve_tetraharmonic(const TensorNet& data, const TetraharmonicOptions& options) {
  options.validate();
  return timed_solve([&] { return solve_tetraharmonic_untimed(data, options); });
}

}  // namespace bpde
