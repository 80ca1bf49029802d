// The orthogonal least-squares fit of samples (fit_samples.h).
#include "bezierpde/boundaries/fit_samples.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"

namespace bpde {
namespace {

// Levenberg–Marquardt iterations per degree of the ladder, and its stopping tests: a step that
// lowers the sum of squares by less than kRelativeDecrease of it, or a gradient below
// kGradientTolerance relative to the sum's scale, ends a degree.
constexpr int kIterationsPerDegree = 100;
constexpr double kRelativeDecrease = 1e-14;
constexpr double kGradientTolerance = 1e-16;
// The first damping, relative to the largest diagonal entry of the normal equations.
constexpr double kInitialDamping = 1e-3;
// The ladder's first degree (fit_samples.h, "Method").
constexpr int kLadderStart = 3;
// More samples than this: the ladder runs on this many of them (evenly spread by index, the ends
// included), the other parameters are interpolated linearly in the index between theirs, and
// kFinalIterations iterations at degree n over all samples finish (fit_samples.h, "Cost").
constexpr Eigen::Index kLadderSamples = 2049;
constexpr int kFinalIterations = 20;

struct Model {
  int n;
  const Eigen::MatrixX3d& q;
  // x(t) and x'(t) of the curve P at t; the Bernstein values B_0..B_n into b, B^{n-1} into d.
  void eval(const Eigen::MatrixX3d& P, double t, Eigen::Vector3d& x, Eigen::Vector3d& dx, double* b, double* d) const {
    bernstein_values(n, t, b);
    bernstein_values(n - 1, t, d);
    x.setZero();
    dx.setZero();
    for (int i = 0; i <= n; ++i) x += b[i] * P.row(i).transpose();
    for (int i = 0; i < n; ++i) dx += d[i] * (P.row(i + 1) - P.row(i)).transpose();
    dx *= n;
  }
  double cost(const Eigen::MatrixX3d& P, const Eigen::VectorXd& t) const {
    const Eigen::MatrixXd B = bernstein_table(n, t);
    return (B * P - q).squaredNorm();
  }
};

// One degree: Levenberg–Marquardt on Σ_k |x(t_k) − q_k|² over the inner points (3(n−1) numbers,
// point-major) and the inner parameters, from (P, t); the parameters eliminated by the Schur
// complement (each residual block has its own t_k), Levenberg's damping mu·Id, Nielsen's update
// of the damping. A step is taken only when the parameters still increase strictly inside [0, 1]
// and the sum falls. Returns the iterations taken. With G (3(n−1) x N), the inner points move only
// in its range, P_inner += G dz: the problem is solved over dz (the normal equations projected,
// G^T A G, G^T C, G^T g; the damping on dz), as fit_samples_orthogonal_constrained needs.
int orthogonal_lm(const Model& m, Eigen::MatrixX3d& P, Eigen::VectorXd& t, int max_iterations = kIterationsPerDegree,
                  const Eigen::MatrixXd* G = nullptr, double initial_damping = kInitialDamping,
                  const std::function<bool(const Eigen::MatrixX3d&)>* admissible = nullptr) {
  const int n = m.n, k = 3 * (n - 1);
  const Eigen::Index M = t.size() - 1;
  std::vector<double> b(static_cast<size_t>(n + 1)), d(static_cast<size_t>(n));
  double cost = m.cost(P, t);
  double mu = -1, nu = 2;
  int it = 0;
  Eigen::MatrixXd A(k, k), S(k, k);
  Eigen::VectorXd g(k), rhs(k);
  Eigen::VectorXd gt(M + 1), ht(M + 1);
  while (it < max_iterations && cost > 0) {
    // Normal equations: [A  C; Cᵀ diag(ht)] over (P, t), gradient (g, gt).
    A.setZero(k, k);
    g.setZero(k);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(k, M + 1), W = Eigen::MatrixXd::Zero(k, M + 1);
    for (Eigen::Index s = 1; s < M; ++s) {
      Eigen::Vector3d x, dx;
      m.eval(P, t(s), x, dx, b.data(), d.data());
      const Eigen::Vector3d r = x - m.q.row(s).transpose();
      const Eigen::Map<const Eigen::VectorXd> bs(b.data() + 1, n - 1);  // B_1 .. B_{n-1} at t_s
      gt(s) = dx.dot(r);
      ht(s) = dx.squaredNorm();
      for (int i = 0; i < n - 1; ++i) {
        for (int c = 0; c < 3; ++c) {
          g(3 * i + c) += bs(i) * r(c);
          C(3 * i + c, s) = bs(i) * dx(c);
        }
        for (int j = 0; j <= i; ++j) A(3 * i, 3 * j) += bs(i) * bs(j);
      }
    }
    for (int i = 0; i < n - 1; ++i)
      for (int j = 0; j <= i; ++j) {
        const double v = A(3 * i, 3 * j);
        for (int c = 0; c < 3; ++c) A(3 * i + c, 3 * j + c) = A(3 * j + c, 3 * i + c) = v;
        if (i != j) A(3 * i, 3 * j) = A(3 * j, 3 * i) = v;
      }
    if (G) {  // the problem over dz
      A = G->transpose() * A * *G;
      C = G->transpose() * C;
      g = G->transpose() * g;
      W.setZero(G->cols(), M + 1);  // columns 0 and M stay zero (the fixed end parameters)
    }
    const double gnorm = std::max(g.cwiseAbs().maxCoeff(), gt.segment(1, M - 1).cwiseAbs().maxCoeff());
    if (!(gnorm > kGradientTolerance * std::max(1.0, std::sqrt(cost)))) break;
    if (mu < 0) mu = initial_damping * std::max(A.diagonal().maxCoeff(), ht.segment(1, M - 1).maxCoeff());
    bool accepted = false;
    while (!accepted && it < max_iterations) {
      ++it;
      // Damped blocks (Levenberg: + mu·Id on both), then the Schur complement of the parameters.
      S = A;
      S.diagonal().array() += mu;
      rhs = -g;
      for (Eigen::Index s = 1; s < M; ++s) {
        const double h = ht(s) + mu;
        W.col(s) = C.col(s) / std::sqrt(h);
        rhs += C.col(s) * (gt(s) / h);
      }
      S.selfadjointView<Eigen::Lower>().rankUpdate(W, -1.0);  // S −= W Wᵀ: one SYRK
      const Eigen::LLT<Eigen::MatrixXd> llt(S);
      if (llt.info() != Eigen::Success) {
        mu *= nu;
        nu *= 2;
        continue;
      }
      const Eigen::VectorXd dz = llt.solve(rhs), dp = G ? Eigen::VectorXd(*G * dz) : dz;
      Eigen::VectorXd tn = t;
      bool ok = dp.allFinite();
      for (Eigen::Index s = 1; ok && s < M; ++s) {
        tn(s) = t(s) - (gt(s) + C.col(s).dot(dz)) / (ht(s) + mu);
        ok = std::isfinite(tn(s));
      }
      for (Eigen::Index s = 1; ok && s <= M; ++s) ok = tn(s) > tn(s - 1) && tn(s) >= 0 && tn(s) <= 1;
      Eigen::MatrixX3d Pn = P;
      for (int i = 1; ok && i < n; ++i)
        for (int c = 0; c < 3; ++c) Pn(i, c) += dp(3 * (i - 1) + c);
      if (ok && admissible && *admissible) ok = (*admissible)(Pn);
      const double cn = ok ? m.cost(Pn, tn) : INFINITY;
      if (cn < cost) {
        // Gain ratio against the model's predicted decrease: (dp, dt)ᵀ(mu (dp, dt) − (g, gt)).
        Eigen::VectorXd dt = tn - t;
        const double pred =
            dz.dot(mu * dz - g) + dt.segment(1, M - 1).dot(mu * dt.segment(1, M - 1) - gt.segment(1, M - 1));
        const double rho = pred > 0 ? (cost - cn) / pred : 0;
        const bool small = cost - cn < kRelativeDecrease * cost;
        P = Pn;
        t = tn;
        cost = cn;
        mu *= std::max(1.0 / 3, 1 - std::pow(2 * rho - 1, 3));
        nu = 2;
        accepted = true;
        if (small) return it;
      } else {
        mu *= nu;
        nu *= 2;
        if (!(mu < 1e300)) return it;
      }
    }
    if (!accepted) break;
  }
  return it;
}

}  // namespace

Eigen::MatrixX3d least_squares_at(int n, const Eigen::VectorXd& t, const Eigen::MatrixX3d& q) {
  const Eigen::Index M = t.size();
  if (M < n + 1)
    throw SizeError("a least-squares fit at degree " + std::to_string(n) + " needs at least " + std::to_string(n + 1) +
                    " samples, got " + std::to_string(M));
  Eigen::MatrixX3d P(n + 1, 3);
  P.row(0) = q.row(0);
  P.row(n) = q.row(M - 1);
  if (n == 1) return P;
  // The inner columns B_1..B_{n-1} are t(1 − t) times a basis of the polynomials of degree n − 2:
  // they have full rank exactly when n − 1 distinct parameters lie inside (0,1).
  std::vector<double> inner;
  for (Eigen::Index k = 0; k < M; ++k)
    if (t(k) > 0 && t(k) < 1) inner.push_back(t(k));
  std::sort(inner.begin(), inner.end());
  if (std::unique(inner.begin(), inner.end()) - inner.begin() < n - 1)
    throw ParameterError("the samples' parameters do not determine a degree-" + std::to_string(n) +
                         " fit (too few distinct parameters inside (0,1))");
  const Eigen::MatrixXd A = bernstein_table(n, t);
  const Eigen::MatrixX3d rhs = q - A.col(0) * P.row(0) - A.col(n) * P.row(n);
  // The Bernstein matrix's condition grows about 2^n: at n = 50 its smallest singular values are
  // near 1e-13 of the largest. The complete orthogonal decomposition truncates at the rank
  // relative to rounding (Eigen's threshold: machine epsilon times the matrix's size, relative to
  // the largest pivot) and returns the least-norm solution: directions it drops change the fitted
  // values by rounding only (fit_samples.h, "Conditioning").
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> qr(A.middleCols(1, n - 1));
  P.middleRows(1, n - 1) = qr.solve(rhs);
  return P;
}

SampleFit fit_samples_orthogonal(int n, const Eigen::VectorXd& t0, const Eigen::MatrixX3d& q) {
  SampleFit out{least_squares_at(n, t0, q), t0, false, 0};
  const Eigen::Index M = t0.size() - 1;
  // Degree 1 (the segment between the end samples) and interpolation (n + 1 samples) do not
  // depend on the parameters.
  if (n < 2 || M <= n) return out;
  const double start_cost = Model{n, q}.cost(out.points, t0);
  if (!(start_cost > 0)) return out;
  // The ladder's samples: all, or kLadderSamples of them.
  const bool subset = M + 1 > kLadderSamples;
  std::vector<Eigen::Index> idx;
  for (Eigen::Index j = 0; j < (subset ? kLadderSamples : M + 1); ++j)
    idx.push_back(subset ? (j * M + (kLadderSamples - 1) / 2) / (kLadderSamples - 1) : j);
  idx.back() = M;
  const Eigen::Index L = static_cast<Eigen::Index>(idx.size());
  Eigen::MatrixX3d qs(L, 3);
  Eigen::VectorXd t(L);
  for (Eigen::Index j = 0; j < L; ++j) {
    qs.row(j) = q.row(idx[static_cast<size_t>(j)]);
    t(j) = t0(idx[static_cast<size_t>(j)]);
  }
  Eigen::MatrixX3d P;
  for (int d = std::min(n, kLadderStart); d <= n; ++d) {
    try {
      P = least_squares_at(d, t, qs);
    } catch (const ParameterError&) {
      return out;  // the parameters reached no longer determine the fit: the start fit is kept
    }
    out.iterations += orthogonal_lm(Model{d, qs}, P, t);
  }
  Eigen::VectorXd tall = t;
  if (subset) {
    tall.resize(M + 1);
    for (Eigen::Index j = 0; j + 1 < L; ++j) {
      const Eigen::Index a = idx[static_cast<size_t>(j)], b = idx[static_cast<size_t>(j + 1)];
      for (Eigen::Index s = a; s < b; ++s)
        tall(s) = t(j) + (t(j + 1) - t(j)) * static_cast<double>(s - a) / static_cast<double>(b - a);
    }
    tall(M) = 1.0;
    try {
      P = least_squares_at(n, tall, q);
    } catch (const ParameterError&) {
      return out;
    }
    out.iterations += orthogonal_lm(Model{n, q}, P, tall, kFinalIterations);
  }
  if (P.allFinite() && Model{n, q}.cost(P, tall) < start_cost) {
    out.points = P;
    out.params = tall;
    out.corrected = true;
  }
  return out;
}

SampleFit fit_samples_orthogonal_constrained(const Eigen::MatrixX3d& P, const Eigen::VectorXd& t,
                                             const Eigen::MatrixX3d& q, const Eigen::MatrixXd& G,
                                             const ConstrainedFitOptions& options) {
  const int n = static_cast<int>(P.rows()) - 1;
  if (n < 2 || G.rows() != 3 * (n - 1) || t.size() != q.rows() || t.size() < 2)
    throw SizeError("fit_samples_orthogonal_constrained: expected P of degree >= 2, G with 3(n-1) = " +
                    std::to_string(3 * std::max(n - 1, 0)) + " rows and one parameter per sample; got degree " +
                    std::to_string(n) + ", " + std::to_string(G.rows()) + " rows, " + std::to_string(t.size()) +
                    " parameters for " + std::to_string(q.rows()) + " samples");
  if (!P.allFinite() || !t.allFinite() || !q.allFinite() || !G.allFinite())
    throw NonFiniteError("fit_samples_orthogonal_constrained: non-finite P, t, q or G");
  for (Eigen::Index s = 1; s < t.size(); ++s)
    if (!(t(s) > t(s - 1)) || t(0) != 0 || t(t.size() - 1) != 1)
      throw ParameterError("fit_samples_orthogonal_constrained: the parameters must increase strictly from 0 to 1");
  SampleFit out{P, t, true, 0};
  if (!(options.max_iterations >= 1) || !(options.initial_damping > 0) || !std::isfinite(options.initial_damping))
    throw ParameterError(
        "fit_samples_orthogonal_constrained: max_iterations must be >= 1 and initial_damping a "
        "finite number > 0");
  if (G.cols() == 0) return out;
  const Eigen::Index M = t.size() - 1;
  out.iterations = orthogonal_lm(
      Model{n, q}, out.points, out.params,
      M + 1 > kLadderSamples ? std::min(kFinalIterations, options.max_iterations) : options.max_iterations, &G,
      options.initial_damping, &options.admissible);
  return out;
}

}  // namespace bpde
