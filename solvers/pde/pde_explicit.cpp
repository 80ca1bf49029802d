#include "bezierpde/solvers/pde/pde_explicit.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/row_major_product.h"
#include "bezierpde/solvers/pde/pde_residual.h"
#include "bezierpde/tensor/power_basis.h"

namespace bpde {
namespace {

// sin(n pi/2) and cos(n pi/2), exactly.
double sin_half_pi(int n) {
  static const double t[4] = {0, 1, 0, -1};
  return t[((n % 4) + 4) % 4];
}
double cos_half_pi(int n) {
  static const double t[4] = {1, 0, -1, 0};
  return t[((n % 4) + 4) % 4];
}

[[noreturn]] void unsupported(const EnergySpec& op) {
  std::ostringstream s;
  s << "pde: method \"explicit\" has no closed form for the operator of \"" << op.name() << "\" [";
  const auto& c = op.operator_coeffs();
  for (int k = 0; k < 5; ++k) s << (k ? ", " : "") << c[static_cast<size_t>(k)];
  s << "] (the explicit solutions cover Coons, biharmonic, laplacian-squared, modified biharmonic and G-norm "
       "operators); "
       "use method \"lu\"";
  throw UnsupportedProblem(s.str());
}

// 1 - q^K for 0 < q <= 1, accurate when q is close to 1.
double one_minus_pow(double q, int K) { return -std::expm1(K * std::log(q)); }

// Weights (w_col, w_row) of Prop. 4 for the orthogonal family (E = 1): roots x0 >= x1 > 0 of
// x^2 - C x + A.
struct OrthWeights {
  double x0, q;      // q = x1 / x0 in (0, 1]
  bool double_root;  // q == 1 to rounding: §5.2.2 / §5.2.3
};

OrthWeights orth_roots(double A, double C) {
  const double disc = std::max(0.0, C * C - 4 * A);
  const double sq = std::sqrt(disc);
  const double x0 = 0.5 * (C + sq);
  const double x1 = A / x0;  // product of the roots is A (E = 1); no cancellation
  OrthWeights w{x0, x1 / x0, false};
  if (w.q >= 1.0 - 1e-15) w.double_root = true;
  return w;
}

// Prop. 4 weights of every interior (k, l) with k + l <= N, K = floor(k/2), L = floor(l/2):
//   G_{n} = x0^n (1 - q^{n+1}) / (1 - q);  w_col = G_{K-1} (-A)^L / G_{K+L-1},
//   w_row = G_{L-1} (-E)^K / G_{K+L-1}  (E = 1), with G_{-1} = 0, G_0 = 1 (docs/errata.md),
// from tables of the powers (one std::pow per exponent, not per pair).
void orth_weight_tables(const OrthWeights& w, double A, int N, Eigen::MatrixXd& wcol, Eigen::MatrixXd& wrow) {
  const int H = N / 2 + 1;
  Eigen::VectorXd pa(H), pe(H), om(N + 1);
  for (int e = 0; e < H; ++e) {
    pa(e) = std::pow(-A / w.x0, e);
    pe(e) = std::pow(-1.0 / w.x0, e);
  }
  for (int e = 0; e <= N; ++e) om(e) = w.double_root ? double(e) : one_minus_pow(w.q, e);
  wcol.setZero(N + 1, N + 1);
  wrow.setZero(N + 1, N + 1);
  for (int k = 2; k <= N; ++k)
    for (int l = 2; k + l <= N; ++l) {
      const int K = k / 2, L = l / 2;
      // double root: 1 - q^K -> K (the limit q -> 1 of (1 - q^K)/(1 - q^(K+L)) is K/(K+L))
      wcol(k, l) = pa(L) * om(K) / om(K + L);
      wrow(k, l) = pe(K) * om(L) / om(K + L);
    }
}

ExplicitOperator transposed(const ExplicitOperator& op) {
  ExplicitOperator t = op;
  t.rho = 1.0 / op.rho;
  t.A = t.rho * t.rho;
  t.B = t.D = 2 * t.rho * std::cos(op.t);
  t.C = 1 + t.A;
  t.E = 1;
  return t;
}

TensorNet transpose(const TensorNet& net) {
  TensorNet out(net.m(), net.n());
  for (int i = 0; i <= net.n(); ++i)
    for (int j = 0; j <= net.m(); ++j) out.set_point(j, i, net.point(i, j));
  return out;
}

}  // namespace

void PdeExplicitOptions::validate() const {
  auto ok = [](double x) { return std::isfinite(x) && x > 0 && x < 1; };
  if (!ok(singular_tolerance)) throw ParameterError("PdeExplicitOptions: singular_tolerance must be in (0, 1)");
  if (!ok(rank_tolerance)) throw ParameterError("PdeExplicitOptions: rank_tolerance must be in (0, 1)");
}

ExplicitOperator classify_explicit_operator(const EnergySpec& op) {
  if (op.order() != 4)
    throw UnsupportedProblem("pde: method \"explicit\" is for the fourth-order operators of Arnal-Monterde-Ugail; \"" +
                             op.name() +
                             "\" is second order (use fixed \"u-boundaries\" for the harmonic PDE, or method \"lu\")");
  if (op.kind() == EnergyKind::ModifiedBiharmonic && op.alpha() == 0.0)
    throw ParameterError(
        "pde: modified-biharmonic with alpha = 0 is x_uuuu = 0, which is not elliptic: the boundary does not "
        "determine the patch");
  const auto& c = op.operator_coeffs();
  double scale = 0;
  for (double x : c) scale += std::abs(x);
  if (!(scale > 0)) unsupported(op);
  const double tol = 1e-12 * scale;
  ExplicitOperator e;
  // Coons: only C.
  if (std::abs(c[0]) <= tol && std::abs(c[1]) <= tol && std::abs(c[3]) <= tol && std::abs(c[4]) <= tol) {
    e.family = ExplicitOperator::Family::Coons;
    e.A = e.B = e.D = e.E = 0;
    e.C = 1;
    return e;
  }
  if (!(std::abs(c[4]) > tol)) unsupported(op);
  const double A = c[0] / c[4], B = c[1] / c[4], C = c[2] / c[4], D = c[3] / c[4];
  const double rtol = 1e-12 * (std::abs(A) + std::abs(B) + std::abs(C) + std::abs(D) + 1);
  const bool orthogonal = std::abs(B) <= rtol && std::abs(D) <= rtol;
  const bool modified = orthogonal && A > 0 && C > 0 && std::abs(C * C - 4 * A) <= 1e-12 * (C * C + 4 * A);
  if (!(op.has_explicit_solution() || modified)) unsupported(op);
  if (!(A > 0)) unsupported(op);
  e.A = A;
  e.B = orthogonal ? 0 : B;
  e.C = C;
  e.D = orthogonal ? 0 : D;
  e.E = 1;
  e.rho = std::sqrt(A);
  e.t = std::acos(std::clamp(0.5 * (B + D) / (2 * e.rho) * 1.0, -1.0, 1.0));
  if (orthogonal) {
    e.family = ExplicitOperator::Family::Orthogonal;
    e.t = std::acos(0.0);
  } else {
    e.family = ExplicitOperator::Family::GNorm;
    e.C = 1 + A;  // G-norm: C = A + E exactly
  }
  return e;
}

Eigen::MatrixXd lemma1_sequences(double rho, double t, int N, bool closed_form) {
  if (!(rho > 0) || !std::isfinite(rho) || !std::isfinite(t))
    throw ParameterError("lemma1_sequences: need rho > 0 and finite t");
  if (N < 3) N = 3;
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(4, N + 1);
  const double ct = std::cos(t), st = std::sin(t);
  if (!closed_form) {
    const double a = rho * rho, b = 2 * rho * ct, c = 1 + rho * rho;
    for (int r = 0; r < 4; ++r) {
      F(r, r) = 1.0;
      for (int l = 0; l + 4 <= N; ++l)
        F(r, l + 4) = -(a * F(r, l) + b * F(r, l + 1) + c * F(r, l + 2) + b * F(r, l + 3));
    }
    return F;
  }
  // 1 + rho^4 + 2 rho^2 cos 2t = (1 - rho^2)^2 + 4 rho^2 cos^2 t  (no cancellation)
  const double den = (1 - rho * rho) * (1 - rho * rho) + 4 * rho * rho * ct * ct;
  if (!(std::abs(st) > 0) || !(den > 0))
    throw ParameterError("lemma1_sequences: eq. (12) needs sin t != 0 and (rho, t) != (1, pi/2)");
  auto Dn = [&](int n) {
    return ((rho * rho - 1) * sin_half_pi(n) - 2 * rho * ct * cos_half_pi(n) +
            std::pow(-rho, n - 1) * (rho * rho * std::sin((n - 2) * t) + std::sin(n * t)) / st) /
           den;
  };
  double Dprev = Dn(-1);
  for (int n = 0; n <= N; ++n) {
    const double Dcur = Dn(n);
    F(0, n) = -rho * rho * Dprev;
    F(1, n) = sin_half_pi(n) + Dcur;
    F(2, n) = -cos_half_pi(n) - rho * rho * Dprev;
    F(3, n) = Dcur;
    Dprev = Dcur;
  }
  return F;
}

namespace {

// The steps of explicit_pde_coefficients. `a` is the (n+2) x (n+2) table of one coordinate's
// a_kl (zero outside the box); anti-diagonal s holds the a_kl with k + l = s.

// Lemma 1 sequences of the G-norm operator, by eq. (12) where it is accurate, else by recurrence.
Eigen::MatrixXd gnorm_sequences(const ExplicitOperator& op, int n) {
  const double st = std::abs(std::sin(op.t));
  const double den =
      (1 - op.rho * op.rho) * (1 - op.rho * op.rho) + 4 * op.rho * op.rho * std::cos(op.t) * std::cos(op.t);
  const bool closed = st > 1e-3 && den > 1e-3 * (1 + std::pow(op.rho, 4));
  return lemma1_sequences(op.rho, op.t, n + 1, closed);
}

// Factorial-scaled monomial coefficients of the four edges of the three coordinates, one
// product Mf * [edges] (columns 4c + e, e: x(0,v), x(1,v) (= P_{n l}), x(u,0), x(u,1) (= P_{l n})),
// computed as its transpose [edges]^T Mf^T: column-major storage read row-major.
Eigen::MatrixXd edge_monomials(const TensorNet& data, const Eigen::MatrixXd& Mf) {
  const int n = data.n();
  const int N = n + 1;
  Eigen::MatrixXd edges(N, 12), mono(N, 12);
  for (int c = 0; c < 3; ++c)
    for (int j = 0; j <= n; ++j) {
      edges(j, 4 * c + 0) = data.points()(data.index(0, j), c);
      edges(j, 4 * c + 1) = data.points()(data.index(n, j), c);
      edges(j, 4 * c + 2) = data.points()(data.index(j, 0), c);
      edges(j, 4 * c + 3) = data.points()(data.index(j, n), c);
    }
  row_major_product(edges.data(), 12, N, N, Mf.data(), N, N, mono.data(), N);
  return mono;
}

// eq. (7): a_{1,s-1} from x(1, v), a_{s-1,1} from x(u, 1).
template <class Edge>
void edge_unknowns(Eigen::MatrixXd& a, int n, int s, const Edge& e1v, const Edge& e1u, const Eigen::VectorXd& ifact) {
  {
    const int j = s - 1;
    double sum = 0;
    for (int i = 2; i <= n; ++i) sum += a(i, j) * ifact(i);
    a(1, j) = e1v(j) - a(0, j) - sum;
  }
  if (s - 1 != 1) {
    const int i = s - 1;
    double sum = 0;
    for (int j = 2; j <= n; ++j) sum += a(i, j) * ifact(j);
    a(i, 1) = e1u(i) - a(i, 0) - sum;
  }
}

// Orthogonal family: Prop. 4, eq. (21), with the weight tables of orth_weight_tables.
void orthogonal_antidiagonal(Eigen::MatrixXd& a, int s, const Eigen::MatrixXd& wcol, const Eigen::MatrixXd& wrow) {
  for (int l = 2; l <= s - 2; ++l) {
    const int k = s - l, K = k / 2, L = l / 2;
    a(k, l) = wcol(k, l) * a(k + 2 * L, l % 2) + wrow(k, l) * a(k % 2, 2 * K + l);  // eq. (21)
  }
}

// G-norm family, M_s != 0: Prop. 2, eq. (13), from the known y_0, y_1, y_{s-1}, y_s.
void gnorm_closed_form(Eigen::MatrixXd& a, int s, const Eigen::MatrixXd& F, double M) {
  const double Cs = F(2, s), Ds = F(3, s), Cp = F(2, s - 1), Dp = F(3, s - 1);
  const double y0 = a(s, 0), y1 = a(s - 1, 1), ysm = a(1, s - 1), ys = a(0, s);
  const double As = F(0, s), Bs = F(1, s), Ap = F(0, s - 1), Bp = F(1, s - 1);
  const double MAD = As * Dp - Ds * Ap, MAC = As * Cp - Cs * Ap;
  const double MBD = Bs * Dp - Ds * Bp, MBC = Bs * Cp - Cs * Bp;
  for (int l = 2; l <= s - 2; ++l) {  // Prop. 2, eq. (13)
    const double Al = F(0, l), Bl = F(1, l), Cl = F(2, l), Dl = F(3, l);
    const double bA = (Al * M - Cl * MAD + Dl * MAC) / M;
    const double bB = (Bl * M - Cl * MBD + Dl * MBC) / M;
    const double bC = (-Cl * Ds + Dl * Cs) / M;
    const double bD = (Cl * Dp - Dl * Cp) / M;
    a(s - l, l) = bA * y0 + bB * y1 + bC * ysm + bD * ys;
  }
}

// G-norm family, M_s ~ 0: system (9) on this anti-diagonal, unknowns y_2..y_{s-2}, equations
// l0 = 0..s-4, solved numerically. False (with the summary failed) if it is singular.
bool gnorm_system9(Eigen::MatrixXd& a, int s, const ExplicitOperator& op, const PdeExplicitOptions& options,
                   Summary& summary) {
  const double y0 = a(s, 0), y1 = a(s - 1, 1), ysm = a(1, s - 1), ys = a(0, s);
  const int u = s - 3;
  const double co[5] = {op.A, op.B, op.C, op.D, op.E};
  Eigen::MatrixXd Mx = Eigen::MatrixXd::Zero(u, u);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(u);
  const double yknown[4] = {y0, y1, ysm, ys};
  for (int l0 = 0; l0 < u; ++l0)
    for (int j = 0; j <= 4; ++j) {
      const int l = l0 + j;
      if (l >= 2 && l <= s - 2)
        Mx(l0, l - 2) += co[j];
      else
        rhs(l0) -= co[j] * (l == 0 ? yknown[0] : l == 1 ? yknown[1] : l == s - 1 ? yknown[2] : yknown[3]);
    }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Mx, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  if (!(sv(u - 1) > options.rank_tolerance * std::max(1.0, sv(0)))) {
    std::ostringstream m;
    m << "the polynomial solution is not unique: on the anti-diagonal k + l = " << s
      << " the operator has a nonzero polynomial solution with zero boundary data (system (9) is singular)";
    summary.set_failed(Status::NotUnique, m.str());
    return false;
  }
  const Eigen::VectorXd y = svd.solve(rhs);
  for (int l = 2; l <= s - 2; ++l) a(s - l, l) = y(l - 2);
  return true;
}

// G-norm family: the closed form where M_s is large enough relative to its terms, else system (9).
bool gnorm_antidiagonal(Eigen::MatrixXd& a, int s, const Eigen::MatrixXd& F, const ExplicitOperator& op,
                        const PdeExplicitOptions& options, Summary& summary) {
  const double Cs = F(2, s), Ds = F(3, s), Cp = F(2, s - 1), Dp = F(3, s - 1);
  const double M = Cs * Dp - Ds * Cp;  // M_s(C, D)
  // Scale of M_s: the squared size of the sequences so far (they do not grow exponentially
  // for rho <= 1, which the transposition ensures); C_s, D_s themselves can all vanish.
  const double fmax = F.leftCols(s + 1).cwiseAbs().maxCoeff();
  const double Mscale = fmax * fmax;
  if (std::abs(M) > options.singular_tolerance * Mscale) {
    gnorm_closed_form(a, s, F, M);
    return true;
  }
  return gnorm_system9(a, s, op, options, summary);
}

}  // namespace

Eigen::MatrixX3d explicit_pde_coefficients(const TensorNet& data, const ExplicitOperator& op,
                                           const PdeExplicitOptions& options, Summary& summary) {
  const int n = data.n();
  if (data.m() != n) {
    std::ostringstream s;
    s << "pde: method \"explicit\" needs a net of degree [n, n] (Arnal-Monterde-Ugail), got [" << data.n() << ", "
      << data.m() << "]; use method \"lu\"";
    throw DegreeError(s.str());
  }
  summary.set_converged();
  const int W = n + 2;                                                 // padded: indices 0..n+1, zero outside the box
  const Eigen::MatrixXd& Mf = bernstein_to_factorial_power_matrix(n);  // edge -> a (eq. (5)-(6))
  Eigen::VectorXd ifact(n + 2);
  for (int k = 0; k <= n + 1; ++k) ifact(k) = 1.0 / factorial(k);

  // Fundamental sequences for the G-norm family.
  Eigen::MatrixXd F;
  if (op.family == ExplicitOperator::Family::GNorm) F = gnorm_sequences(op, n);
  // Prop. 4 weights of every interior (k, l), shared by the three coordinates.
  Eigen::MatrixXd wcol, wrow;
  if (op.family == ExplicitOperator::Family::Orthogonal) {
    orth_weight_tables(orth_roots(op.A, op.C), op.A, n + 1, wcol, wrow);
  }

  const Eigen::MatrixXd mono = edge_monomials(data, Mf);
  const int N = n + 1;
  Eigen::MatrixX3d out = Eigen::MatrixX3d::Zero(N * N, 3);
  Eigen::MatrixXd a(W, W);
  for (int c = 0; c < 3; ++c) {
    a.setZero();
    const auto e0v = mono.col(4 * c + 0), e1v = mono.col(4 * c + 1), e0u = mono.col(4 * c + 2),
               e1u = mono.col(4 * c + 3);
    for (int j = 0; j <= n; ++j) {
      a(0, j) = e0v(j);  // eq. (5)
      a(j, 0) = e0u(j);  // eq. (6)
    }
    for (int s = n + 1; s >= 2; --s) {
      edge_unknowns(a, n, s, e1v, e1u, ifact);
      if (s < 4) continue;
      // Interior of the anti-diagonal: k, l >= 2, k + l = s.
      switch (op.family) {
        case ExplicitOperator::Family::Coons:
          break;  // a_kl = 0 (§5.2.1)
        case ExplicitOperator::Family::Orthogonal:
          orthogonal_antidiagonal(a, s, wcol, wrow);
          break;
        case ExplicitOperator::Family::GNorm:
          if (!gnorm_antidiagonal(a, s, F, op, options, summary)) return out;
          break;
      }
    }
    for (int k = 0; k <= n; ++k)
      for (int l = 0; l <= n; ++l) out(k * (n + 1) + l, c) = a(k, l);
  }
  return out;
}

namespace {

PdeSolution solve_explicit_untimed(const TensorNet& data, const EnergySpec& op, const PdeExplicitOptions& options) {
  options.validate();
  ExplicitOperator e = classify_explicit_operator(op);
  if (data.m() != data.n()) {
    std::ostringstream s;
    s << "pde: method \"explicit\" needs a net of degree [n, n] (Arnal-Monterde-Ugail), got [" << data.n() << ", "
      << data.m() << "]; use method \"lu\"";
    throw DegreeError(s.str());
  }
  const int n = data.n();
  const bool flip = e.family == ExplicitOperator::Family::GNorm && e.rho > 1;
  const TensorNet flipped = flip ? transpose(data) : TensorNet(1, 1);
  const TensorNet& work = flip ? flipped : data;
  if (flip) e = transposed(e);
  PdeSolution out{data, Summary{}};
  if (e.family == ExplicitOperator::Family::GNorm && std::abs(e.rho - 1) < 1e-6) {
    // rho = 1 and t != pi/2: all characteristic roots lie on the unit circle and M_s can vanish,
    // also on the anti-diagonals s > n+1 that the closed form sets to 0. Check them all (the
    // small monomial blocks; ~1 ms at n = 20, only in this degenerate case).
    const PdeStructure st =
        analyse_pde_structure({e.A, e.B, e.C, e.D, e.E}, n, n, FixedSet::Boundary, options.rank_tolerance);
    if (!st.unique) {
      out.summary.set_failed(Status::NotUnique, st.diagnosis + "; the data are returned unchanged");
      return out;
    }
  }
  const Eigen::MatrixX3d a = explicit_pde_coefficients(work, e, options, out.summary);
  if (out.summary.converged && !a.allFinite()) {
    out.summary.set_failed(Status::NumericalLimit,
                           "the explicit coefficients overflowed double precision; the data are returned unchanged");
  } else if (out.summary.converged) {
    TensorNet sol = from_factorial_power(n, n, a);
    if (flip) sol = transpose(sol);
    // The prescribed ring is data: copy it exactly (the power-basis round trip rounds it).
    for (int k = 0; k <= n; ++k)
      for (int idx : {data.index(0, k), data.index(n, k), data.index(k, 0), data.index(k, n)})
        sol.points().row(idx) = data.points().row(idx);
    if (!sol.points().allFinite()) {
      out.summary.set_failed(Status::NumericalLimit, "the explicit solution overflowed double precision");
    } else {
      out.net = std::move(sol);
      check_pde_degree_limit(n, n, "explicit", out.summary);
    }
  } else {
    out.summary.message += "; the data are returned unchanged";
  }
  return out;
}

}  // namespace

PdeSolution solve_pde_explicit(const TensorNet& data, const EnergySpec& op, const PdeExplicitOptions& options) {
  require_finite_rows(data.points(), data.fixed_indices(FixedSet::Boundary), "pde explicit", data.m() + 1);
  PdeSolution out;
  {
    ScopedTimer timer(out.summary.seconds);
    out = solve_explicit_untimed(data, op, options);
  }
  return out;
}

}  // namespace bpde
