#include "bezierpde/solvers/c1/clamped_plate.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/bernstein_ops.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/kron.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/solvers/c1/biharmonic_load.h"

namespace bpde {
namespace {

using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The deflection net (u_i, a v_j, W_ij) from the (n+1) x (n+1) scalar net W.
TensorNet deflection_net(const Eigen::MatrixXd& W, double a) {
  const int n = static_cast<int>(W.rows()) - 1;
  TensorNet net(n, n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) net.set_point(i, j, Eigen::Vector3d(static_cast<double>(i) / n, a * j / n, W(i, j)));
  return net;
}

// J(w) = a [ ½ ∫∫ (w_uu + w_vv/a²)² - ∫∫ w ] du dv, exactly from the Bernstein net W.
double plate_energy(const Eigen::MatrixXd& W, double a) {
  const int n = static_cast<int>(W.rows()) - 1;
  const Eigen::MatrixXd G00 = bernstein_derivative_integrals(n, 0, 0), G22 = bernstein_derivative_integrals(n, 2, 2),
                        G20 = bernstein_derivative_integrals(n, 2, 0);
  const double a2 = a * a;
  const double quad = (W.cwiseProduct(G22 * W * G00)).sum() +
                      2.0 / a2 * (W.cwiseProduct(G20 * W * G20.transpose())).sum() +
                      (W.cwiseProduct(G00 * W * G22)).sum() / (a2 * a2);
  const double lin = W.sum() / ((n + 1.0) * (n + 1.0));
  return a * (0.5 * quad - lin);
}

Eigen::MatrixXd load_of(const Eigen::MatrixXd& W, double a) {
  const int n = static_cast<int>(W.rows()) - 1;
  const Eigen::MatrixXd T4 = derivative_at_degree(n, 4), T2 = derivative_at_degree(n, 2);
  const double a2 = a * a;
  return T4 * W + (2.0 / a2) * (T2 * W * T2.transpose()) + (1.0 / (a2 * a2)) * (W * T4.transpose());
}

TensorNet load_net(const Eigen::MatrixXd& R, double a) { return deflection_net(R, a); }

// Legendre P_0..P_kmax at x in [-1,1], with first and second derivatives.
struct LegendreValues {
  std::vector<double> P, dP, d2P;
};
LegendreValues legendre(int kmax, double x) {
  LegendreValues L;
  L.P.assign(static_cast<size_t>(kmax + 1), 0.0);
  L.dP = L.P;
  L.d2P = L.P;
  L.P[0] = 1.0;
  if (kmax >= 1) {
    L.P[1] = x;
    L.dP[1] = 1.0;
  }
  for (int k = 1; k < kmax; ++k) {
    const size_t K = static_cast<size_t>(k);
    L.P[K + 1] = ((2.0 * k + 1.0) * x * L.P[K] - k * L.P[K - 1]) / (k + 1.0);
    L.dP[K + 1] = L.dP[K - 1] + (2.0 * k + 1.0) * L.P[K];
    L.d2P[K + 1] = L.d2P[K - 1] + (2.0 * k + 1.0) * L.dP[K];
  }
  return L;
}

// Normalised doubly integrated Legendre functions φ_k = sqrt(2k+1) ∬_0^u P_k(2s-1), k >= 2:
// derivatives of order 0..4 at the point where L was evaluated (needs L up to k+2).
struct PhiJet {
  double d0, d1, d2, d4;
};
PhiJet phi(int k, const LegendreValues& L) {
  const double s = std::sqrt(2.0 * k + 1.0);
  const auto p = [&](int j) { return L.P[static_cast<size_t>(j)]; };
  PhiJet f;
  f.d4 = 4.0 * s * L.d2P[static_cast<size_t>(k)];
  f.d2 = s * p(k);
  f.d1 = s * (p(k + 1) - p(k - 1)) / (2.0 * (2 * k + 1));
  f.d0 = s * ((p(k + 2) - p(k)) / (2 * k + 3) - (p(k) - p(k - 2)) / (2 * k - 1)) / (4.0 * (2 * k + 1));
  return f;
}

// The symmetric modes φ_k (k = 2, 4, .., <= n-2) at the Gauss nodes: columns of F0, F1, F2, F4.
struct ModeTables {
  std::vector<int> ks;
  QuadratureRule1D rule;
  Eigen::MatrixXd F0, F1, F2, F4;
  Eigen::VectorXd mid;  // φ_k(1/2)
};
ModeTables mode_tables(int n) {
  ModeTables t;
  for (int k = 2; k <= n - 2; k += 2) t.ks.push_back(k);
  const int L = static_cast<int>(t.ks.size());
  t.rule = gauss_legendre01(n + 2);
  const Eigen::Index nq = t.rule.x.size();
  t.F0.resize(nq, L);
  t.F1.resize(nq, L);
  t.F2.resize(nq, L);
  t.F4.resize(nq, L);
  for (Eigen::Index q = 0; q < nq; ++q) {
    const LegendreValues Lv = legendre(n, 2.0 * t.rule.x(q) - 1.0);
    for (int c = 0; c < L; ++c) {
      const PhiJet f = phi(t.ks[static_cast<size_t>(c)], Lv);
      t.F0(q, c) = f.d0;
      t.F1(q, c) = f.d1;
      t.F2(q, c) = f.d2;
      t.F4(q, c) = f.d4;
    }
  }
  const LegendreValues Lm = legendre(n, 0.0);
  t.mid.resize(L);
  for (int c = 0; c < L; ++c) t.mid(c) = phi(t.ks[static_cast<size_t>(c)], Lm).d0;
  return t;
}

// Bernstein coefficients at degree n of φ_k (exact integer prefix sums, one division).
Eigen::VectorXd phi_bernstein(int k, int n) {
  // P_k(2u-1) = sum_i (-1)^(k-i) C(k,i) B_i^k(u); integrate twice from 0.
  std::vector<std::int64_t> b(static_cast<size_t>(k + 1)), s1(static_cast<size_t>(k + 2), 0),
      s2(static_cast<size_t>(k + 3), 0);
  for (int i = 0; i <= k; ++i)
    b[static_cast<size_t>(i)] = static_cast<std::int64_t>(((k - i) % 2 ? -1 : 1) * binomial(k, i));
  for (int i = 1; i <= k + 1; ++i)
    s1[static_cast<size_t>(i)] = s1[static_cast<size_t>(i - 1)] + b[static_cast<size_t>(i - 1)];
  for (int i = 1; i <= k + 2; ++i)
    s2[static_cast<size_t>(i)] = s2[static_cast<size_t>(i - 1)] + s1[static_cast<size_t>(i - 1)];
  Eigen::VectorXd e(k + 3);
  const double scale = std::sqrt(2.0 * k + 1.0) / ((k + 1.0) * (k + 2.0));
  for (int i = 0; i <= k + 2; ++i) e(i) = scale * static_cast<double>(s2[static_cast<size_t>(i)]);
  return bernstein_elevation_operator(k + 2, n - k - 2) * e;
}

// The (n+1) x (n+1) Bernstein net of sum_kl C_kl φ_k(u) φ_l(v) over the modes of t.
Eigen::MatrixXd modes_to_bernstein(const ModeTables& t, const Eigen::MatrixXd& C, int n) {
  const int L = static_cast<int>(t.ks.size());
  Eigen::MatrixXd E(n + 1, L);
  for (int k = 0; k < L; ++k) E.col(k) = phi_bernstein(t.ks[static_cast<size_t>(k)], n);
  return E * C * E.transpose();
}

ClampedPlateResult ritz(int n, double a) {
  ClampedPlateResult out;
  const ModeTables t = mode_tables(n);
  const int L = static_cast<int>(t.ks.size());
  const auto& w = t.rule.w;
  const Eigen::MatrixXd M = t.F0.transpose() * w.asDiagonal() * t.F0, S = t.F1.transpose() * w.asDiagonal() * t.F1,
                        Q = t.F2.transpose() * w.asDiagonal() * t.F2;
  const Eigen::VectorXd m = t.F0.transpose() * w;
  const double a2 = a * a;
  const Eigen::MatrixXd K = kron(Q, M) + (2.0 / a2) * kron(S, S) + (1.0 / (a2 * a2)) * kron(M, Q);
  Eigen::VectorXd f(L * L);
  for (int k = 0; k < L; ++k)
    for (int l = 0; l < L; ++l) f(k * L + l) = m(k) * m(l);
  const Eigen::VectorXd c = K.llt().solve(f);
  const Eigen::Map<const RowMat> C(c.data(), L, L);
  out.center_deflection = t.mid.dot(C * t.mid);
  out.energy = -0.5 * a * f.dot(c);
  const Eigen::MatrixXd W = modes_to_bernstein(t, C, n);
  out.net = deflection_net(W, a);
  out.load = load_net(load_of(W, a), a);
  out.summary.residual = (K * c - f).norm() / f.norm();
  if (out.summary.residual <= kConvergenceTolerance) {
    out.summary.set_converged();
    out.summary.message = "solved (Ritz, integrated-Legendre basis, Cholesky)";
  } else {
    std::ostringstream m;
    m << "the Galerkin residual is " << out.summary.residual;
    out.summary.set_failed(Status::NumericalLimit, m.str());
  }
  return out;
}

// ---------------------------------------------------------------- admissible load
// The paper's discrete problem: the interior of the degree-(n,n) Bernstein net of Δ²w is 1.
// It is intrinsically ill-conditioned: the solution's sensitivity to rounding of the system grows
// from ~1e3 at n = 7 to ~1e14 at n = 30 in any basis we tried (Bernstein, or a Petrov–Galerkin
// form with orthogonal bases), so double precision cannot give 1e-9 beyond n ~ 17. We therefore
// assemble the Bernstein system from exact integer formulas and solve it in binary128
// (__float128, 113-bit mantissa): about 1e-20 relative at n = 30. Restricted to the nets that are
// symmetric under i -> n-i and j -> n-j (the problem is, and its solution is unique), which
// leaves (floor(n/2) - 1)^2 unknowns.

quad qabs(quad x) { return x < 0 ? -x : x; }

// Solve A x = b (N x N, row-major) by Gaussian elimination with partial pivoting, in quad.
// Returns false if a pivot is exactly zero.
bool qsolve(std::vector<quad>& A, std::vector<quad>& b, int N) {
  for (int c = 0; c < N; ++c) {
    int p = c;
    for (int r = c + 1; r < N; ++r)
      if (qabs(A[static_cast<size_t>(r * N + c)]) > qabs(A[static_cast<size_t>(p * N + c)])) p = r;
    if (A[static_cast<size_t>(p * N + c)] == 0) return false;
    if (p != c) {
      for (int k = 0; k < N; ++k) std::swap(A[static_cast<size_t>(p * N + k)], A[static_cast<size_t>(c * N + k)]);
      std::swap(b[static_cast<size_t>(p)], b[static_cast<size_t>(c)]);
    }
    const quad piv = A[static_cast<size_t>(c * N + c)];
    for (int r = c + 1; r < N; ++r) {
      const quad f = A[static_cast<size_t>(r * N + c)] / piv;
      if (f == 0) continue;
      for (int k = c + 1; k < N; ++k) A[static_cast<size_t>(r * N + k)] -= f * A[static_cast<size_t>(c * N + k)];
      b[static_cast<size_t>(r)] -= f * b[static_cast<size_t>(c)];
    }
  }
  for (int r = N - 1; r >= 0; --r) {
    quad s = b[static_cast<size_t>(r)];
    for (int k = r + 1; k < N; ++k) s -= A[static_cast<size_t>(r * N + k)] * b[static_cast<size_t>(k)];
    b[static_cast<size_t>(r)] = s / A[static_cast<size_t>(r * N + r)];
  }
  return true;
}

// The Bernstein system of the admissible load on the symmetric nets: unknown (i, j) of the
// fundamental domain 2 <= i, j <= h = floor(n/2) at row/column (i-2) L + (j-2), L = h - 1.
struct SymmetricPlateSystem {
  int n, h, L, N;
  std::vector<quad> A;  // N x N, row-major; right-hand side 1
  // Unknown of the net point (i, j), 2 <= i, j <= n-2, through the symmetries i -> n-i, j -> n-j.
  int pos(int i, int j) const { return (rep(i) - 2) * L + (rep(j) - 2); }
  int rep(int i) const { return i <= h ? i : n - i; }
};

SymmetricPlateSystem plate_system(int n, double a) {
  SymmetricPlateSystem sys;
  sys.n = n;
  sys.h = n / 2;
  sys.L = sys.h - 1;
  sys.N = sys.L * sys.L;  // fundamental domain 2..h in each direction
  const int h = sys.h, L = sys.L, N = sys.N;
  const std::vector<quad> T4 = derivative_at_degree_rm<quad>(n, 4), T2 = derivative_at_degree_rm<quad>(n, 2);
  auto t4 = [&](int i, int k) { return T4[static_cast<size_t>(i * (n + 1) + k)]; };
  auto t2 = [&](int i, int k) { return T2[static_cast<size_t>(i * (n + 1) + k)]; };
  const quad qa = a, c2 = 2 / (qa * qa), c4 = 1 / (qa * qa * qa * qa);
  auto pos = [&](int i, int j) { return sys.pos(i, j); };
  std::vector<quad>& A = sys.A;
  A.assign(static_cast<size_t>(N * N), 0);
  for (int i = 2; i <= h; ++i)
    for (int j = 2; j <= h; ++j) {
      const size_t row = static_cast<size_t>(((i - 2) * L + (j - 2)) * N);
      for (int k = 2; k <= n - 2; ++k) {
        A[row + static_cast<size_t>(pos(k, j))] += t4(i, k);
        A[row + static_cast<size_t>(pos(i, k))] += c4 * t4(j, k);
        if (t2(i, k) != 0)
          for (int l = 2; l <= n - 2; ++l) A[row + static_cast<size_t>(pos(k, l))] += c2 * t2(i, k) * t2(j, l);
      }
    }
  return sys;
}

// Solve A x = 1 (N x N, row-major, in quad). Mixed precision: LU in long double (x87, 64-bit
// mantissa), residuals and updates in quad (iterative refinement). Each step contracts the error
// by ~ cond * 1e-19 (~1e-3 at n = 30); fall back to a quad LU if the refinement stalls (which
// overwrites A). x must hold N ones on entry. False if the system is singular.
bool solve_refined(std::vector<quad>& A, int N, std::vector<quad>& x, int& iterations) {
  bool ok = true;
  using MatL = MatLD;
  using VecL = VecLD;
  MatL Ad(N, N);
  for (int r = 0; r < N; ++r)
    for (int c = 0; c < N; ++c) Ad(r, c) = static_cast<long double>(A[static_cast<size_t>(r * N + c)]);
  const Eigen::PartialPivLU<MatL> lu(Ad);
  std::vector<quad> sol(static_cast<size_t>(N), 0);
  VecL rd(N);
  bool refined = false;
  for (int it = 0; it < 20 && !refined; ++it) {
    for (int r = 0; r < N; ++r) {
      quad acc = 1;  // b = 1
      for (int c = 0; c < N; ++c) acc -= A[static_cast<size_t>(r * N + c)] * sol[static_cast<size_t>(c)];
      rd(r) = static_cast<long double>(acc);
    }
    const VecL d = lu.solve(rd);
    double dmax = 0.0, xmax = 0.0;
    for (int r = 0; r < N; ++r) {
      sol[static_cast<size_t>(r)] += static_cast<quad>(d(r));
      dmax = std::max(dmax, std::abs(static_cast<double>(d(r))));
      xmax = std::max(xmax, std::abs(static_cast<double>(sol[static_cast<size_t>(r)])));
    }
    refined = std::isfinite(dmax) && dmax <= 1e-17 * xmax;
    iterations = it + 1;
  }
  if (refined)
    x = sol;
  else
    ok = qsolve(A, x, N);
  return ok;
}

ClampedPlateResult admissible_load(int n, double a) {
  ClampedPlateResult out;
  SymmetricPlateSystem sys = plate_system(n, a);
  std::vector<quad> x(static_cast<size_t>(sys.N), 1);
  int iterations = 0;
  const bool ok = solve_refined(sys.A, sys.N, x, iterations);
  quad w = 0, half_n = 1;
  for (int k = 0; k < n; ++k) half_n /= 2;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int i = 2; i <= n - 2; ++i)
    for (int j = 2; j <= n - 2; ++j) {
      const quad xij = x[static_cast<size_t>(sys.pos(i, j))];
      W(i, j) = static_cast<double>(xij);
      w += binomial<quad>(n, i) * binomial<quad>(n, j) * half_n * half_n * xij;
    }
  out.center_deflection = static_cast<double>(w);
  out.energy = plate_energy(W, a);
  out.net = deflection_net(W, a);
  const Eigen::MatrixXd R = load_of(W, a);
  out.load = load_net(R, a);
  // Residual of the double net (the quad solution rounded to double) against the load 1.
  double res = 0.0;
  for (int i = 2; i <= n - 2; ++i)
    for (int j = 2; j <= n - 2; ++j) res = std::max(res, std::abs(R(i, j) - 1.0));
  out.summary.residual = res;
  out.summary.iterations = iterations;
  if (!ok) {
    out.summary.set_failed(Status::NotUnique, "the admissible-load system is singular");
  } else if (!std::isfinite(out.center_deflection)) {
    out.summary.set_failed(Status::NumericalLimit, "the admissible-load solution is not finite in double precision");
  } else {
    out.summary.set_converged();
    out.summary.message = "solved (admissible load, Bernstein basis, long-double LU refined in binary128)";
  }
  return out;
}

}  // namespace

void ClampedPlateOptions::validate() const {
  if (!std::isfinite(aspect)) throw NonFiniteError("plate: aspect is not a finite number");
  if (!(aspect >= 0.01 && aspect <= 100.0))
    throw ParameterError("plate: aspect must be in [0.01, 100], got " + std::to_string(aspect));
  if (degree < 4 || degree > 30) throw DegreeError("plate: degree must be in 4..30, got " + std::to_string(degree));
  if (method != Method::AdmissibleLoad && method != Method::Ritz)
    throw ParameterError("plate: unknown method (use admissible-load or ritz)");
}

ClampedPlateOptions::Method parse_plate_method(const std::string& name) {
  if (name == "admissible-load") return ClampedPlateOptions::Method::AdmissibleLoad;
  if (name == "ritz") return ClampedPlateOptions::Method::Ritz;
  throw ParameterError("plate: unknown method \"" + name + "\" (use admissible-load or ritz)");
}

ClampedPlateResult solve_clamped_plate(const ClampedPlateOptions& options) {
  options.validate();
  ClampedPlateResult out;
  {
    ScopedTimer timer(out.summary.seconds);
    out = options.method == ClampedPlateOptions::Method::Ritz ? ritz(options.degree, options.aspect)
                                                              : admissible_load(options.degree, options.aspect);
  }
  return out;
}

}  // namespace bpde
