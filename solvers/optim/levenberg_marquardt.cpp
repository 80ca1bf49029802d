// Levenberg–Marquardt with geodesic acceleration (levenberg_marquardt.h).
#include "bezierpde/solvers/optim/levenberg_marquardt.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <limits>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/gram.h"
#include "bezierpde/solvers/optim/damping.h"

namespace bpde::optim {

void LevenbergMarquardtOptions::validate() const {
  auto bad = [](const std::string& what) { throw ParameterError("Levenberg–Marquardt options: " + what); };
  if (!(target >= 0) || !std::isfinite(target)) bad("target must be finite and >= 0");
  if (max_iterations < 0) bad("max_iterations must be >= 0");
  if (!(initial_lambda >= 0) || !std::isfinite(initial_lambda)) bad("initial_lambda must be finite and >= 0");
  if (!(geodesic_h > 0 && geodesic_h <= 1)) bad("geodesic_h must be in (0, 1]");
  if (!(geodesic_alpha > 0) || !std::isfinite(geodesic_alpha)) bad("geodesic_alpha must be finite and > 0");
}

Eigen::VectorXd second_directional_derivative(const Eigen::VectorXd& r, const Eigen::VectorXd& r_h,
                                              const Eigen::MatrixXd& J, const Eigen::VectorXd& delta, double h) {
  return (2.0 / h) * ((r_h - r) / h - J * delta);
}

namespace {

// What one iteration shares between its trials: JᵀJ, the gradient Jᵀr, D, and the constraint's
// value and gradient at x.
struct Linearisation {
  Eigen::MatrixXd A;
  Eigen::VectorXd g, diag, cgrad;
  double c = 0.0;
};

// The sizes of a problem at x: r and J from its residuals (J #r by k, k = x.size() >= 1), and the
// constraint's gradient (k) when there is one; SizeError naming the mismatch otherwise.
void check_sizes(const Eigen::VectorXd& x, const Eigen::VectorXd& r, const Eigen::MatrixXd& J) {
  if (x.size() == 0) throw SizeError("Levenberg–Marquardt: no unknowns");
  if (r.size() == 0 || J.rows() != r.size() || J.cols() != x.size())
    throw SizeError("Levenberg–Marquardt: the residuals' Jacobian is " + std::to_string(J.rows()) + " by " +
                    std::to_string(J.cols()) + " for " + std::to_string(r.size()) + " residuals and " +
                    std::to_string(x.size()) + " unknowns");
}

void check_problem(const LeastSquaresProblem& p) {
  if (!p.residuals) throw ParameterError("Levenberg–Marquardt: the problem has no residuals");
  if (p.constraint && !p.restore)
    throw ParameterError("Levenberg–Marquardt: a constraint needs its restore callback");
}

Linearisation linearise(const LeastSquaresProblem& p, const Eigen::VectorXd& x, const Eigen::VectorXd& r,
                        const Eigen::MatrixXd& J, const LevenbergMarquardtOptions& o) {
  Linearisation L;
  const Eigen::Index k = J.cols();
  L.A = Eigen::MatrixXd::Zero(k, k);
  add_gram_lower(L.A, J);  // by row blocks: core/gram.h
  L.A = L.A.selfadjointView<Eigen::Lower>();
  L.g = J.transpose() * r;
  const double top = L.A.diagonal().maxCoeff();
  L.diag = o.marquardt_scaling ? Eigen::VectorXd(L.A.diagonal().cwiseMax(1e-12 * top))
                               : Eigen::VectorXd::Constant(k, top);
  if (p.constraint) {
    L.c = p.constraint(x, &L.cgrad);
    if (L.cgrad.size() != k)
      throw SizeError("Levenberg–Marquardt: the constraint's gradient has " + std::to_string(L.cgrad.size()) +
                      " entries for " + std::to_string(k) + " unknowns");
  }
  return L;
}

LmTrial trial(const LeastSquaresProblem& p, const Linearisation& L, const Eigen::VectorXd& x,
              const Eigen::VectorXd& r, const Eigen::MatrixXd& J, double lambda, const LevenbergMarquardtOptions& o) {
  LmTrial t;
  Eigen::MatrixXd M = L.A;
  M.diagonal() += lambda * L.diag;
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  if (llt.info() != Eigen::Success) return t;
  Eigen::VectorXd d = -llt.solve(L.g), e;
  if (p.constraint) {  // δ = δ₀ − μ e with e = M⁻¹∇c and ∇cᵀδ = −c
    e = llt.solve(L.cgrad);
    const double ce = L.cgrad.dot(e);
    if (!(ce > 0)) return t;
    d -= ((L.cgrad.dot(d) + L.c) / ce) * e;
  }
  if (!d.allFinite()) return t;
  t.velocity = d;
  t.ok = true;
  const double dd = d.dot(L.diag.asDiagonal() * d);
  if (!o.geodesic_acceleration || !(dd > 0)) return t;
  Eigen::VectorXd rh;
  p.residuals(x + o.geodesic_h * d, rh, nullptr);
  if (rh.size() != r.size())
    throw SizeError("Levenberg–Marquardt: the residuals changed size from " + std::to_string(r.size()) + " to " +
                    std::to_string(rh.size()));
  Eigen::VectorXd a = -llt.solve(J.transpose() * second_directional_derivative(r, rh, J, d, o.geodesic_h));
  if (p.constraint) a -= (L.cgrad.dot(a) / L.cgrad.dot(e)) * e;  // ∇cᵀa = 0 (first order only)
  t.acceleration = a;
  const double ratio2 = a.dot(L.diag.asDiagonal() * a) / dd;  // (‖a‖_D/‖δ‖_D)²
  t.bend = 2.0 * std::sqrt(ratio2);
  t.bent = !(4.0 * ratio2 <= o.geodesic_alpha * o.geodesic_alpha);
  if (!a.allFinite() || !std::isfinite(t.bend)) t.ok = false;
  return t;
}

void evaluate(const LeastSquaresProblem& p, const Eigen::VectorXd& x, Eigen::VectorXd& r, Eigen::MatrixXd& J) {
  p.residuals(x, r, &J);
  check_sizes(x, r, J);
}

}  // namespace

LmTrial levenberg_marquardt_trial(const LeastSquaresProblem& problem, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd& r, const Eigen::MatrixXd& J, double lambda,
                                  const LevenbergMarquardtOptions& options) {
  options.validate();
  check_problem(problem);
  check_sizes(x, r, J);
  if (!(lambda >= 0) || !std::isfinite(lambda)) throw ParameterError("Levenberg–Marquardt: λ must be finite and >= 0");
  return trial(problem, linearise(problem, x, r, J, options), x, r, J, lambda, options);
}

namespace {

// λ: /5 after a good step, ×3 after a poor one, ×10 (from at least 1e-15) after a rejected or
// unsolvable trial, 30 trials per iteration.
constexpr Damping kLmDamping{30, 1e-15, 5.0, 3.0, 10.0, 0.0, 0.75, 0.25, true};

// One iteration's step: trials with rising λ until one lowers Φ. x, and λ, move; false when no
// trial does.
bool lm_step(const LeastSquaresProblem& p, const Linearisation& L, Eigen::VectorXd& x, const Eigen::VectorXd& r,
             const Eigen::MatrixXd& J, double phi, double& lambda, const LevenbergMarquardtOptions& o) {
  for (int tries = 0; tries < kLmDamping.max_tries; ++tries) {
    const LmTrial t = trial(p, L, x, r, J, lambda, o);
    if (!t.ok || t.bent) {  // not solvable, or bending too much for its second-order model
      kLmDamping.rejected(lambda);
      continue;
    }
    const Eigen::VectorXd& d = t.velocity;
    Eigen::VectorXd xn = t.acceleration.size() ? Eigen::VectorXd(d + 0.5 * t.acceleration) : d;
    xn += x;
    Eigen::VectorXd rn;
    double phin = std::numeric_limits<double>::infinity();
    if (!p.constraint || p.restore(xn)) {
      p.residuals(xn, rn, nullptr);
      if (rn.size() != r.size())
        throw SizeError("Levenberg–Marquardt: the residuals changed size from " + std::to_string(r.size()) + " to " +
                        std::to_string(rn.size()));
      phin = rn.squaredNorm();
    }
    const double pred = -(2.0 * L.g.dot(d) + d.dot(L.A * d));  // the fall of Φ the velocity predicts
    if (std::isfinite(phin) && phin < phi) {
      kLmDamping.accepted(lambda, pred > 0 ? (phi - phin) / pred : 0.0);
      x = std::move(xn);
      return true;
    }
    kLmDamping.rejected(lambda);
  }
  return false;
}

// The start restored onto the constraint; false (out.stop set) when it cannot be.
bool start_point(const LeastSquaresProblem& p, Eigen::VectorXd& x, LsOutcome& out) {
  if (!p.constraint) return true;
  Eigen::VectorXd xr = x;  // on a copy: a start that cannot be restored is reported as it was given
  if (!p.restore(xr)) {
    out.stop = LsStop::ConstraintUnmet;
    return false;
  }
  x = std::move(xr);
  return true;
}

}  // namespace

LsOutcome levenberg_marquardt(const LeastSquaresProblem& p, Eigen::VectorXd& x, const LevenbergMarquardtOptions& o,
                              const ProgressFn& progress) {
  o.validate();
  check_problem(p);
  if (x.size() == 0) throw SizeError("Levenberg–Marquardt: no unknowns");
  if (!x.allFinite()) throw NonFiniteError("Levenberg–Marquardt: the start is not finite");
  LsOutcome out;
  report(progress, o.stage, 0, 1);
  if (!start_point(p, x, out)) {
    report(progress, o.stage, 1, 1);
    return out;
  }
  Eigen::VectorXd r;
  Eigen::MatrixXd J;
  evaluate(p, x, r, J);
  double phi = r.squaredNorm(), lambda = o.initial_lambda;
  if (p.monitor && std::isfinite(phi) && !p.monitor(x, 0, phi)) {
    out.stop = LsStop::Interrupted;
    report(progress, o.stage, 1, 1);
    return out;
  }
  std::vector<double> history{phi};
  const double start = std::sqrt(phi);
  while (true) {
    if (!std::isfinite(phi) || !J.allFinite()) {
      out.stop = LsStop::NonFinite;
      break;
    }
    if (std::sqrt(phi) <= o.target) {
      out.stop = LsStop::Reached;
      break;
    }
    if (out.iterations >= o.max_iterations) {
      out.stop = LsStop::MaxIterations;
      break;
    }
    if (!lm_step(p, linearise(p, x, r, J, o), x, r, J, phi, lambda, o)) {
      out.stop = LsStop::NoStep;
      break;
    }
    ++out.iterations;
    evaluate(p, x, r, J);
    phi = r.squaredNorm();
    report(progress, o.stage, ls_fraction(start, o.target, std::sqrt(phi)), 1);
    if (p.monitor && std::isfinite(phi) && !p.monitor(x, out.iterations, phi)) {
      out.stop = LsStop::Interrupted;
      break;
    }
    history.push_back(phi);
    if (history.size() > 11) history.erase(history.begin());
    if (stalled(history) && std::sqrt(phi) > o.target) {
      out.stop = LsStop::Stalled;
      break;
    }
  }
  report(progress, o.stage, 1, 1);
  return out;
}

}  // namespace bpde::optim
