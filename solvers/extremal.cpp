#include "bezierpde/solvers/extremal.h"

#include "bezierpde/core/interruption.h"
#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/bernstein_ops.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/core/keyed_cache.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/core/symmetric_factor.h"
#include "bezierpde/energies/tensor_gram.h"
#include "bezierpde/energies/triangular_gram.h"

namespace bpde {

struct ExtremalSolver::Factor {
  SymmetricFactor<double> sym;  // blocked Cholesky of the unit-diagonal reduced matrix
};

namespace {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using LVector = VecLD;

// ---------------------------------------------------------------------------------------------
// A well-conditioned basis of the 1-D free space {polynomials of degree <= n vanishing to order s
// at t = 0 and t = 1} = span{B_s^n, ..., B_{n-s}^n}:
//     φ_k(t) = (t(1-t))^s C_k^(λ)(2t-1),  λ = 2s + 1/2,  k = 0..n-2s,
// i.e. the Jacobi polynomials P_k^(2s,2s) times the weight root, orthogonal in L2 up to the factor
// (t(1-t))^s. Each φ_k is normalised to unit L2 norm.
struct Basis1D {
  int n = 0, s = 0, K = 0;
  // A[a][b] = ∫ φ^(a) φ^(b)ᵀ (K x K); C[a][b] = ∫ φ^(a) (B^n)^(b)ᵀ (K x (n+1)).
  std::vector<std::vector<Eigen::MatrixXd>> A, C;
  Eigen::MatrixXd T;  // (K x K): Bernstein coefficients (indices s..n-s) of φ_k in column k
};

// Gegenbauer C_0..C_{K-1} with parameter lam at x.
void gegenbauer_values(int K, double lam, double x, double* out) {
  if (K <= 0) return;
  out[0] = 1.0;
  if (K > 1) out[1] = 2.0 * lam * x;
  for (int k = 2; k < K; ++k) out[k] = (2.0 * x * (k + lam - 1) * out[k - 1] - (k + 2 * lam - 2) * out[k - 2]) / k;
}

// Bernstein coefficients (degree d+1) of x f(t), x = 2t - 1, f of degree d.
LVector times_x(const LVector& f) {
  const int d = static_cast<int>(f.size()) - 1;
  LVector g = LVector::Zero(d + 2);
  for (int i = 0; i <= d + 1; ++i) {
    const long double tf = (i >= 1) ? i * f(i - 1) : 0.0L;        // (d+1) t f
    const long double sf = (i <= d) ? (d + 1 - i) * f(i) : 0.0L;  // (d+1) (1-t) f
    g(i) = (tf - sf) / (d + 1);
  }
  return g;
}

// Power-basis coefficients of g(t) = (t - t^2)^s (degree 2s), for its derivatives.
std::vector<double> weight_power_coefficients(int s) {
  std::vector<double> g(static_cast<size_t>(2 * s + 1), 0.0);
  for (int r = 0; r <= s; ++r) g[static_cast<size_t>(s + r)] = binomial(s, r) * ((r % 2) ? -1.0 : 1.0);
  return g;
}

// g^(d)(t) from the power coefficients of g (degree 2s).
double weight_derivative(const std::vector<double>& g, int s, int d, double t) {
  double v = 0.0;
  for (int e = d; e <= 2 * s; ++e) {
    double c = g[static_cast<size_t>(e)];
    for (int z = 0; z < d; ++z) c *= (e - z);
    v += c * std::pow(t, e - d);
  }
  return v;
}

// Phi[d](g, k) = φ_k^(d)(x_g) (unnormalised) at the nodes of `rule`, d = 0..dmax, by Leibniz and
// d^e/dt^e C_k^λ(2t-1) = 2^e * 2^e λ(λ+1)..(λ+e-1) C_{k-e}^(λ+e)(2t-1).
std::vector<Eigen::MatrixXd> basis_derivatives_at_nodes(const QuadratureRule1D& rule, int s, int K, int dmax) {
  const double lam = 2.0 * s + 0.5;
  const int q = static_cast<int>(rule.x.size());
  const std::vector<double> g = weight_power_coefficients(s);
  std::vector<Eigen::MatrixXd> Phi(static_cast<size_t>(dmax + 1), Eigen::MatrixXd::Zero(q, K));
  std::vector<double> vals(static_cast<size_t>(K + 1));
  for (int gi = 0; gi < q; ++gi) {
    const double t = rule.x(gi), x = 2 * t - 1;
    // P[e][k] = e-th t-derivative of C_k^λ(2t-1)
    std::vector<std::vector<double>> P(static_cast<size_t>(dmax + 1), std::vector<double>(static_cast<size_t>(K), 0.0));
    for (int e = 0; e <= dmax; ++e) {
      gegenbauer_values(K, lam + e, x, vals.data());
      double f = 1.0;
      for (int z = 0; z < e; ++z) f *= 4.0 * (lam + z);
      for (int k = e; k < K; ++k)
        P[static_cast<size_t>(e)][static_cast<size_t>(k)] = f * vals[static_cast<size_t>(k - e)];
    }
    for (int d = 0; d <= dmax; ++d)
      for (int r = 0; r <= d; ++r) {
        const double gd = binomial(d, r) * weight_derivative(g, s, r, t);
        if (gd == 0.0) continue;
        for (int k = 0; k < K; ++k)
          Phi[static_cast<size_t>(d)](gi, k) += gd * P[static_cast<size_t>(d - r)][static_cast<size_t>(k)];
      }
  }
  return Phi;
}

// The 1-D integrals A[a][c] = ∫ φ^(a) φ^(c)ᵀ and C[a][c] = ∫ φ^(a) (B^n)^(c)ᵀ by the quadrature.
void basis_integrals(const std::vector<Eigen::MatrixXd>& Phi, const QuadratureRule1D& rule, int dmax, Basis1D& b) {
  std::vector<Eigen::MatrixXd> Bern;
  for (int d = 0; d <= dmax; ++d) Bern.push_back(bernstein_table(b.n, rule.x, d));
  b.A.assign(static_cast<size_t>(dmax + 1), std::vector<Eigen::MatrixXd>(static_cast<size_t>(dmax + 1)));
  b.C = b.A;
  for (int a = 0; a <= dmax; ++a)
    for (int c = 0; c <= dmax; ++c) {
      b.A[static_cast<size_t>(a)][static_cast<size_t>(c)] =
          Phi[static_cast<size_t>(a)].transpose() * rule.w.asDiagonal() * Phi[static_cast<size_t>(c)];
      b.C[static_cast<size_t>(a)][static_cast<size_t>(c)] =
          Phi[static_cast<size_t>(a)].transpose() * rule.w.asDiagonal() * Bern[static_cast<size_t>(c)];
    }
}

// Bernstein coefficients (indices s..n-s, degree n) of the normalised φ_k, k = 0..K-1, in the
// columns of a K x K matrix: C_k by the Gegenbauer recurrence in Bernstein form, times g, elevated.
Eigen::MatrixXd basis_bernstein_coefficients(int n, int s, int K, const Eigen::VectorXd& norm) {
  Eigen::MatrixXd T(K, K);
  std::vector<LVector> Ck;
  const long double llam = 2.0L * s + 0.5L;
  for (int k = 0; k < K; ++k) {
    LVector c;
    if (k == 0) {
      c = LVector::Ones(1);
    } else if (k == 1) {
      c = 2.0L * llam * times_x(Ck[0]);
    } else {
      c = (2.0L * (k + llam - 1) * times_x(Ck[static_cast<size_t>(k - 1)]) -
           (k + 2 * llam - 2) * elevate(Ck[static_cast<size_t>(k - 2)], 2)) /
          static_cast<long double>(k);
    }
    Ck.push_back(c);
    // times (t(1-t))^s: h_i = c_{i-s} C(k, i-s) / C(k+2s, i).
    LVector h = LVector::Zero(k + 2 * s + 1);
    for (int i = s; i <= k + s; ++i)
      h(i) = c(i - s) * binomial<long double>(k, i - s) / binomial<long double>(k + 2 * s, i);
    const LVector full = elevate(h, n - k - 2 * s);
    T.col(k) = (static_cast<long double>(norm(k)) * full.segment(s, K)).cast<double>();
  }
  return T;
}

Basis1D make_basis(int n, int s, int dmax) {
  Basis1D b;
  b.n = n;
  b.s = s;
  b.K = n + 1 - 2 * s;
  const int K = b.K;
  const QuadratureRule1D rule = gauss_legendre01(n + 2);  // exact for degree <= 2n + 3
  std::vector<Eigen::MatrixXd> Phi = basis_derivatives_at_nodes(rule, s, K, dmax);
  // Normalise to unit L2 norm.
  Eigen::VectorXd norm(K);
  for (int k = 0; k < K; ++k) norm(k) = 1.0 / std::sqrt((rule.w.array() * Phi[0].col(k).array().square()).sum());
  for (auto& P : Phi) P = P * norm.asDiagonal();
  basis_integrals(Phi, rule, dmax, b);
  b.T = basis_bernstein_coefficients(n, s, K, norm);
  return b;
}

// Kronecker accumulation: out += c * kron(A, B) (out is (A.rows*B.rows) x (A.cols*B.cols)).
void add_kron(Eigen::MatrixXd& out, double c, const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  const Eigen::Index br = B.rows(), bc = B.cols();
  for (Eigen::Index k = 0; k < A.cols(); ++k)
    for (Eigen::Index i = 0; i < A.rows(); ++i) {
      const double a = c * A(i, k);
      if (a != 0.0) out.block(i * br, k * bc, br, bc).noalias() += a * B;
    }
}

void check_min_degree(int n, int m, FixedSet fixed) {
  std::ostringstream s;
  switch (fixed) {
    case FixedSet::Boundary:
      if (n >= 2 && m >= 2) return;
      s << "extremal: tensor degree (" << n << ", " << m << ") is too low for boundary (C0) data: needs n, m >= 2";
      break;
    case FixedSet::BoundaryAdjacent:
      if (n >= 4 && m >= 4) return;
      s << "extremal: tensor degree (" << n << ", " << m
        << ") is too low for boundary+adjacent (C1) data: needs n, m >= 4";
      break;
    case FixedSet::UBoundaries:
      if (n >= 2 && m >= 1) return;
      s << "extremal: tensor degree (" << n << ", " << m << ") is too low for u-boundaries data: needs n >= 2";
      break;
  }
  throw DegreeError(s.str());
}

}  // namespace

void ExtremalOptions::validate() const {
  if (!(singular_tolerance >= 0.0 && singular_tolerance < 1.0))
    throw ParameterError("ExtremalOptions.singular_tolerance must be in [0, 1)");
}

ExtremalSolver::ExtremalSolver(const Eigen::MatrixXd& Q, std::vector<int> fixed, const ExtremalOptions& options)
    : N_(static_cast<int>(Q.rows())), Q_(Q), fixed_(std::move(fixed)) {
  options.validate();
  if (Q.rows() != Q.cols())
    throw SizeError("extremal: Gram matrix is " + std::to_string(Q.rows()) + " x " + std::to_string(Q.cols()) +
                    ", not square");
  if (!Q.allFinite()) throw NonFiniteError("extremal: Gram matrix has a non-finite entry");
  std::vector<char> is_fixed(static_cast<size_t>(N_), 0);
  for (int I : fixed_) {
    if (I < 0 || I >= N_)
      throw SizeError("extremal: fixed index " + std::to_string(I) + " outside 0.." + std::to_string(N_ - 1));
    if (is_fixed[static_cast<size_t>(I)]) throw SizeError("extremal: fixed index " + std::to_string(I) + " repeated");
    is_fixed[static_cast<size_t>(I)] = 1;
  }
  for (int I = 0; I < N_; ++I)
    if (!is_fixed[static_cast<size_t>(I)]) free_.push_back(I);
  if (free_.empty()) throw ParameterError("extremal: no free control point");
  factor(Q(free_, free_), Q(free_, fixed_), options, "extremal");
}

ExtremalSolver::ExtremalSolver(const EnergySpec& energy, int n, int m, FixedSet fixed, const ExtremalOptions& options) {
  options.validate();
  const TensorNet shape(n, m);  // DegreeError outside 1..kMaxDegree
  check_min_degree(n, m, fixed);
  const std::vector<QuadraticTerm> terms = energy.terms();
  check_interruption();  // core/interruption.h: around the Gram matrix's assembly
  Q_ = tensor_gram(n, m, terms);
  check_interruption();
  N_ = static_cast<int>(Q_.rows());
  fixed_ = shape.fixed_indices(fixed);
  free_ = shape.free_indices(fixed);
  const std::string what = "extremal (" + energy.name() + ", degree (" + std::to_string(n) + ", " + std::to_string(m) +
                           "), " + to_string(fixed) + ")";
  int dmax = 0;
  for (const auto& t : terms) dmax = std::max({dmax, t.au, t.av, t.bu, t.bv});
  if (!options.conditioned_basis || terms.empty()) {
    factor(Q_(free_, free_), Q_(free_, fixed_), options, what);
    return;
  }
  // Free set = {su..n-su} x {sv..m-sv}.
  const int su = (fixed == FixedSet::BoundaryAdjacent) ? 2 : 1;
  const int sv = (fixed == FixedSet::BoundaryAdjacent) ? 2 : (fixed == FixedSet::UBoundaries ? 0 : 1);
  const Basis1D bu = make_basis(n, su, dmax), bv = make_basis(m, sv, dmax);
  const Eigen::Index nf = static_cast<Eigen::Index>(bu.K) * bv.K;
  if (nf != static_cast<Eigen::Index>(free_.size()))
    throw Error("extremal: internal error (free set is not a tensor product)");
  Eigen::MatrixXd Aff = Eigen::MatrixXd::Zero(nf, nf);
  Eigen::MatrixXd Afb = Eigen::MatrixXd::Zero(nf, static_cast<Eigen::Index>(fixed_.size()));
  for (const auto& t : terms) {
    const double h = 0.5 * t.w;
    const auto au = static_cast<size_t>(t.au), av = static_cast<size_t>(t.av), cu = static_cast<size_t>(t.bu),
               cv = static_cast<size_t>(t.bv);
    add_kron(Aff, h, bu.A[au][cu], bv.A[av][cv]);
    add_kron(Aff, h, bu.A[cu][au], bv.A[cv][av]);
    // column J = (i, j) of the fixed set: h (Cu(a,b)[:, i] ⊗ Cv(a,b)[:, j] + Cu(b,a)[:, i] ⊗ Cv(b,a)[:, j])
    const Eigen::MatrixXd &C1u = bu.C[au][cu], &C1v = bv.C[av][cv], &C2u = bu.C[cu][au], &C2v = bv.C[cv][av];
    for (size_t c = 0; c < fixed_.size(); ++c) {
      const int i = fixed_[c] / (m + 1), j = fixed_[c] % (m + 1);
      Eigen::Map<RowMajorMatrix> col(Afb.col(static_cast<Eigen::Index>(c)).data(), bu.K, bv.K);
      col.noalias() += h * (C1u.col(i) * C1v.col(j).transpose() + C2u.col(i) * C2v.col(j).transpose());
    }
  }
  Tu_ = bu.T;
  Tv_ = bv.T;
  factor(Aff, Afb, options, what);
}

void ExtremalSolver::factor(const Eigen::MatrixXd& Aff, const Eigen::MatrixXd& Afb, const ExtremalOptions& options,
                            const std::string& what) {
  const Eigen::Index nf = Aff.rows();
  Eigen::VectorXd d = Aff.diagonal();
  for (Eigen::Index a = 0; a < nf; ++a)
    if (!(d(a) > 0.0)) {
      std::ostringstream s;
      s << what << ": the reduced system is " << (d(a) < 0 ? "indefinite" : "singular") << " (a free direction has "
        << (d(a) < 0 ? "negative" : "zero")
        << " energy); the energy does not determine the free control points for this fixed set";
      throw ParameterError(s.str());
    }
  scale_ = d.cwiseSqrt().cwiseInverse();
  A_ff_ = scale_.asDiagonal() * Aff * scale_.asDiagonal();
  A_fb_ = scale_.asDiagonal() * Afb;
  auto f = std::make_shared<Factor>();
  // Cholesky (blocked, fast). Failure means indefinite or singular (a pivoted LDLT says which);
  // success with a reciprocal condition estimate below the tolerance means numerically singular.
  // Interruption points (core/interruption.h) before and after the factorisation and the mould's
  // solve, the steps that cannot stop (docs/robustness.md).
  check_interruption();
  f->sym.compute(A_ff_);
  check_interruption();
  const double rcond = f->sym.rcond();
  const bool ok = f->sym.cholesky() && rcond > options.singular_tolerance;
  const double dmin = f->sym.cholesky() ? rcond : f->sym.min_pivot();
  if (!ok) {
    std::ostringstream s;
    s << what << ": the reduced system Q_ff is "
      << (dmin < -options.singular_tolerance ? "indefinite (the energy is not convex over the free points: is "
                                               "the operator elliptic?)"
                                             : "singular (the energy does not determine the free control points)")
      << (rcond > 0 ? "; reciprocal condition number " : "; smallest scaled pivot ") << dmin;
    if (Tu_.size() == 0) s << " (generic Bernstein path: high degrees are ill-conditioned)";
    throw ParameterError(s.str());
  }
  factor_ = f;
  mould_ = apply_basis(f->sym.solve(-A_fb_));
  check_interruption();
}

Eigen::MatrixXd ExtremalSolver::apply_basis(const Eigen::MatrixXd& Y) const {
  Eigen::MatrixXd Z = scale_.asDiagonal() * Y;
  if (Tu_.size() == 0) return Z;
  const Eigen::Index ku = Tu_.rows(), kv = Tv_.rows();
  Eigen::MatrixXd X(Z.rows(), Z.cols());
  RowMajorMatrix tmp(ku, kv), tmp2(ku, kv);
  for (Eigen::Index c = 0; c < Z.cols(); ++c) {
    Eigen::Map<const RowMajorMatrix> Ym(Z.col(c).data(), ku, kv);
    tmp2.noalias() = Ym * Tv_.transpose();
    tmp.noalias() = Tu_ * tmp2;
    X.col(c) = Eigen::Map<const Eigen::VectorXd>(tmp.data(), ku * kv);
  }
  return X;
}

void ExtremalSolver::check_rows(Eigen::Index rows) const {
  if (rows != N_)
    throw SizeError("extremal: " + std::to_string(rows) + " points given, the solver is for " + std::to_string(N_));
}

Eigen::MatrixX3d ExtremalSolver::solve(const Eigen::MatrixX3d& points) const {
  check_rows(points.rows());
  const Eigen::MatrixX3d Xb = points(fixed_, Eigen::all);
  const Eigen::MatrixX3d Xf = mould_ * Xb;
  Eigen::MatrixX3d out = points;
  out(free_, Eigen::all) = Xf;
  return out;
}

Eigen::MatrixX3d ExtremalSolver::solve_factored(const Eigen::MatrixX3d& points) const {
  check_rows(points.rows());
  const Eigen::MatrixX3d Xb = points(fixed_, Eigen::all);
  const Eigen::MatrixXd Xf = apply_basis(factor_->sym.solve(-(A_fb_ * Xb)));
  Eigen::MatrixX3d out = points;
  out(free_, Eigen::all) = Xf;
  return out;
}

TensorNet ExtremalSolver::solve(const TensorNet& net) const {
  check_rows(net.size());
  return TensorNet(net.n(), net.m(), solve(net.points()));
}

double ExtremalSolver::optimality_residual(const Eigen::MatrixX3d& points) const {
  check_rows(points.rows());
  double r = 0.0;
  const Eigen::MatrixXd absP = points.cwiseAbs();
  for (int I : free_) {
    const Eigen::RowVector3d g = Q_.row(I) * points;
    const Eigen::RowVector3d scale = Q_.row(I).cwiseAbs() * absP;
    for (int c = 0; c < 3; ++c)
      if (scale(c) > 0.0) r = std::max(r, std::abs(g(c)) / scale(c));
  }
  return r;
}

double ExtremalSolver::reduced_residual(const Eigen::MatrixX3d& points) const {
  check_rows(points.rows());
  const Eigen::MatrixX3d Xb = points(fixed_, Eigen::all);
  const Eigen::MatrixXd rhs = A_fb_ * Xb;
  const Eigen::MatrixXd Y = factor_->sym.solve(-rhs);
  const Eigen::MatrixXd r = A_ff_ * Y + rhs;
  const Eigen::MatrixXd size = A_ff_.cwiseAbs() * Y.cwiseAbs() + A_fb_.cwiseAbs() * Xb.cwiseAbs();
  double out = 0.0;
  for (Eigen::Index i = 0; i < r.rows(); ++i)
    for (Eigen::Index c = 0; c < r.cols(); ++c)
      if (size(i, c) > 0.0) out = std::max(out, std::abs(r(i, c)) / size(i, c));
  return out;
}

double ExtremalSolver::extremal_energy(const Eigen::MatrixX3d& points) const {
  check_rows(points.rows());
  const Eigen::MatrixX3d Xb = points(fixed_, Eigen::all);
  const Eigen::MatrixXd Qbb = Q_(fixed_, fixed_);
  const Eigen::MatrixXd rhs = A_fb_ * Xb;
  const Eigen::MatrixXd Y = factor_->sym.solve(-rhs);
  return 0.5 * (Y.cwiseProduct(A_ff_ * Y).sum() + 2.0 * Y.cwiseProduct(rhs).sum() + Xb.cwiseProduct(Qbb * Xb).sum());
}

double ExtremalSolver::energy(const Eigen::MatrixX3d& points) const {
  check_rows(points.rows());
  return 0.5 * points.cwiseProduct(Q_ * points).sum();
}

std::shared_ptr<const ExtremalSolver> ExtremalSolver::cached(const EnergySpec& energy, int n, int m, FixedSet fixed,
                                                             const ExtremalOptions& options) {
  std::ostringstream key;
  key << n << ' ' << m << ' ' << static_cast<int>(fixed) << ' ' << std::hexfloat << options.singular_tolerance << ' '
      << options.conditioned_basis;
  for (const auto& t : energy.terms()) key << " (" << t.au << t.av << t.bu << t.bv << ' ' << t.w << ')';
  static KeyedCache<std::string, ExtremalSolver> cache(32);
  return cache.get(key.str(), [&](const std::string&) {
    return std::make_shared<const ExtremalSolver>(energy, n, m, fixed, options);
  });
}

namespace {

ExtremalResult solve_extremal_untimed(const TensorNet& net, const EnergySpec& energy, FixedSet fixed,
                                      const ExtremalOptions& options) {
  std::shared_ptr<const ExtremalSolver> solver =
      options.use_cache ? ExtremalSolver::cached(energy, net.n(), net.m(), fixed, options)
                        : std::make_shared<const ExtremalSolver>(energy, net.n(), net.m(), fixed, options);
  check_interruption();  // core/interruption.h: between the solve and its figures
  ExtremalResult r{solver->solve(net), 0.0, {}};
  check_interruption();
  r.energy = solver->extremal_energy(r.net.points());
  r.summary.iterations = 0;
  r.summary.residual = solver->reduced_residual(r.net.points());
  check_interruption();
  const bool ok = r.summary.residual <= kConvergenceTolerance && std::isfinite(r.energy) && r.net.points().allFinite();
  std::ostringstream s;
  if (!ok)
    s << "extremal: optimality residual " << r.summary.residual << " above " << kConvergenceTolerance;
  else
    s << "direct solve";
  s << " (Bernstein-coordinate residual " << solver->optimality_residual(r.net.points()) << ")";
  if (ok)
    r.summary.set_converged();
  else
    r.summary.set_failed(Status::NumericalLimit, s.str());
  r.summary.message = s.str();
  return r;
}

}  // namespace

ExtremalResult solve_extremal(const TensorNet& net, const EnergySpec& energy, FixedSet fixed,
                              const ExtremalOptions& options) {
  options.validate();
  ExtremalResult r;
  {
    ScopedTimer timer(r.summary.seconds);
    r = solve_extremal_untimed(net, energy, fixed, options);
  }
  return r;
}

TriangularExtremalResult solve_extremal(const TriangularNet& net, const EnergySpec& energy, FixedSet fixed,
                                        const ExtremalOptions& options) {
  options.validate();
  return timed_solve([&] {
    const ExtremalSolver solver(triangular_gram(net.n(), energy), net.fixed_indices(fixed), options);
    TriangularExtremalResult r{TriangularNet(net.n(), solver.solve(net.points())), 0.0, {}};
    r.summary.residual = solver.reduced_residual(net.points());
    r.energy = solver.extremal_energy(net.points());
    r.summary.finish(r.summary.residual <= kConvergenceTolerance, Status::NumericalLimit,
                     [&] { return "optimality residual " + std::to_string(r.summary.residual) + " above 1e-11"; });
    return r;
  });
}

}  // namespace bpde
