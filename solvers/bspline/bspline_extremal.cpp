#include "bezierpde/solvers/bspline/bspline_extremal.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/quadrature.h"
#include "bezierpde/solvers/bspline/bspline_common.h"

namespace bpde {

Eigen::MatrixXd bspline_derivative_integrals(int k, const std::vector<double>& K, int a, int b) {
  BSplineNet::validate_knots(k, K, "of the direction");
  const int n = static_cast<int>(K.size()) - k - 1;
  if (a < 0 || b < 0) throw ParameterError("bspline_derivative_integrals: derivative orders must be >= 0");
  if (a > k || b > k) return Eigen::MatrixXd::Zero(n, n);
  const QuadratureRule1D g = gauss_legendre01(k + 1);
  std::vector<double> lo, hi;
  for (int i = k; i < n; ++i)
    if (K[static_cast<size_t>(i)] < K[static_cast<size_t>(i) + 1]) {
      lo.push_back(K[static_cast<size_t>(i)]);
      hi.push_back(K[static_cast<size_t>(i) + 1]);
    }
  const int S = static_cast<int>(lo.size()), G = static_cast<int>(g.x.size());
  Eigen::VectorXd t(S * G), w(S * G);
  for (int s = 0; s < S; ++s)
    for (int r = 0; r < G; ++r) {
      const double h = hi[static_cast<size_t>(s)] - lo[static_cast<size_t>(s)];
      t(s * G + r) = lo[static_cast<size_t>(s)] + h * g.x(r);
      w(s * G + r) = h * g.w(r);
    }
  const Eigen::MatrixXd Ta = BSplineNet::basis_table(k, K, t, a);
  const Eigen::MatrixXd Tb = (b == a) ? Ta : BSplineNet::basis_table(k, K, t, b);
  return Ta.transpose() * w.asDiagonal() * Tb;
}

Eigen::SparseMatrix<double> bspline_gram(int p, int q, const std::vector<double>& U, const std::vector<double>& V,
                                         const EnergySpec& energy) {
  BSplineNet::validate_knots(p, U, "u");
  BSplineNet::validate_knots(q, V, "v");
  const int nu = static_cast<int>(U.size()) - p - 1, nv = static_cast<int>(V.size()) - q - 1;
  const int N = nu * nv;
  std::vector<Eigen::Triplet<double>> trip;
  for (const QuadraticTerm& term : energy.terms()) {
    const Eigen::MatrixXd Ku = bspline_derivative_integrals(p, U, term.au, term.bu);
    const Eigen::MatrixXd Kv = bspline_derivative_integrals(q, V, term.av, term.bv);
    // sym(Ku ⊗ Kv) = ½ (Ku ⊗ Kv + Ku^T ⊗ Kv^T)
    for (int i = 0; i < nu; ++i)
      for (int i2 = std::max(0, i - p); i2 <= std::min(nu - 1, i + p); ++i2) {
        const double ku = Ku(i, i2), kut = Ku(i2, i);
        if (ku == 0.0 && kut == 0.0) continue;
        for (int j = 0; j < nv; ++j)
          for (int j2 = std::max(0, j - q); j2 <= std::min(nv - 1, j + q); ++j2) {
            const double val = 0.5 * term.w * (ku * Kv(j, j2) + kut * Kv(j2, j));
            if (val != 0.0) trip.emplace_back(i * nv + j, i2 * nv + j2, val);
          }
      }
  }
  Eigen::SparseMatrix<double> Q(N, N);
  Q.setFromTriplets(trip.begin(), trip.end());
  Q.makeCompressed();
  return Q;
}

double bspline_energy(const BSplineNet& net, const EnergySpec& energy) {
  const Eigen::SparseMatrix<double> Q = bspline_gram(net.p(), net.q(), net.knots_u(), net.knots_v(), energy);
  const Eigen::MatrixX3d& P = net.points();
  return 0.5 * (P.transpose() * (Q * P)).trace();
}

void BSplineExtremalOptions::validate() const {
  if (!(tolerance > 0 && tolerance < 1))
    throw ParameterError("bspline extremal: tolerance must be in (0, 1), got " + std::to_string(tolerance));
}

struct BSplineExtremalSolver::Impl {
  int p = 0, q = 0;
  std::vector<double> U, V;
  EnergySpec energy;
  double tol = kConvergenceTolerance;
  Eigen::SparseMatrix<double> Q, Qff, Qfc;
  std::vector<int> fixed, free;
  Eigen::SimplicialLLT<Eigen::SparseMatrix<double>> llt;
  bool llt_ok = false;
  // Dense fallback (built on demand when Q_ff is not positive definite).
  mutable std::unique_ptr<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>> cod;
  mutable double eig_ratio = 0.0;
  /// BSplineExtremalSolver::solve without the timing.
  BSplineExtremalResult solve(const BSplineNet& data) const;
};

BSplineExtremalSolver::BSplineExtremalSolver(int p, int q, const std::vector<double>& U, const std::vector<double>& V,
                                             const EnergySpec& energy, const std::vector<int>& fixed, double tolerance)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.p = p;
  m.q = q;
  m.U = U;
  m.V = V;
  m.energy = energy;
  m.tol = tolerance;
  m.Q = bspline_gram(p, q, U, V, energy);
  const int N = static_cast<int>(m.Q.rows());
  m.fixed = fixed;
  m.free = detail::complement_indices(N, fixed, "bspline extremal");
  if (m.free.empty()) throw SizeError("bspline extremal: every control point is fixed; nothing to solve");
  m.Qff = detail::sparse_submatrix(m.Q, m.free, m.free);
  m.Qfc = detail::sparse_submatrix(m.Q, m.free, m.fixed);
  m.llt.compute(m.Qff);
  m.llt_ok = m.llt.info() == Eigen::Success;
  if (m.llt_ok) {
    // A semi-definite Q_ff can factor in rounding with tiny pivots: treat pivot ratios below
    // 1e-13 as singular (the dense fallback then returns the minimum-norm minimiser).
    const Eigen::VectorXd d = Eigen::SparseMatrix<double>(m.llt.matrixL()).diagonal().cwiseAbs2();
    m.llt_ok = d.size() > 0 && d.minCoeff() > 1e-13 * d.maxCoeff();
  }
}

BSplineExtremalSolver::~BSplineExtremalSolver() = default;
BSplineExtremalSolver::BSplineExtremalSolver(BSplineExtremalSolver&&) noexcept = default;
BSplineExtremalSolver& BSplineExtremalSolver::operator=(BSplineExtremalSolver&&) noexcept = default;

const Eigen::SparseMatrix<double>& BSplineExtremalSolver::gram() const { return impl_->Q; }
const std::vector<int>& BSplineExtremalSolver::fixed() const { return impl_->fixed; }
const std::vector<int>& BSplineExtremalSolver::free() const { return impl_->free; }

BSplineExtremalResult BSplineExtremalSolver::solve(const BSplineNet& data) const {
  return timed_solve([&] { return impl_->solve(data); });
}

BSplineExtremalResult BSplineExtremalSolver::Impl::solve(const BSplineNet& data) const {
  const Impl& m = *this;
  if (data.p() != m.p || data.q() != m.q || data.knots_u() != m.U || data.knots_v() != m.V)
    throw ParameterError("bspline extremal: the net's degrees or knots differ from the ones the solver was built for");
  const Eigen::MatrixXd Xc = detail::gather_rows(data.points(), m.fixed);
  const Eigen::MatrixXd rhs = -(m.Qfc * Xc);
  Eigen::MatrixXd Xf;
  auto residual = [&](const Eigen::MatrixXd& X) {
    const Eigen::MatrixXd r = m.Qff * X + m.Qfc * Xc;
    const Eigen::SparseMatrix<double> Af = m.Qff.cwiseAbs(), Ac = m.Qfc.cwiseAbs();
    const Eigen::MatrixXd s = Af * X.cwiseAbs() + Ac * Xc.cwiseAbs();
    const double smax = s.size() ? s.maxCoeff() : 0.0;
    const double rmax = r.size() ? r.cwiseAbs().maxCoeff() : 0.0;
    return smax > 0 ? rmax / smax : rmax;
  };
  std::string message;
  double res = 1.0;
  if (m.llt_ok) {
    Xf = m.llt.solve(rhs);
    res = residual(Xf);
    if (res > m.tol) {  // one step of iterative refinement
      Xf += m.llt.solve(rhs - m.Qff * Xf);
      res = residual(Xf);
    }
  }
  if (!m.llt_ok || !Xf.allFinite() || res > m.tol) {
    if (!m.cod) {
      const Eigen::MatrixXd D(m.Qff);
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(D, Eigen::EigenvaluesOnly);
      const double lmax = es.eigenvalues().cwiseAbs().maxCoeff();
      m.eig_ratio = lmax > 0 ? es.eigenvalues()(0) / lmax : 0.0;
      m.cod = std::make_unique<Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>>(D);
      m.cod->setThreshold(1e-12);
    }
    Xf = m.cod->solve(rhs);
    res = residual(Xf);
    std::ostringstream s;
    s << "the energy is not positive definite on the free control points (smallest/largest eigenvalue " << m.eig_ratio
      << "); returned the minimum-norm solution of the reduced system";
    if (m.eig_ratio < -1e-12) s << " (a critical point, not a minimum)";
    message = s.str();
  }
  BSplineNet net = data;
  detail::scatter_rows(net.points(), m.free, Xf);
  BSplineExtremalResult out{std::move(net), 0.0, {}};
  const Eigen::MatrixX3d& P = out.net.points();
  out.energy = 0.5 * (P.transpose() * (m.Q * P)).trace();
  out.summary.residual = res;
  out.summary.message = message;
  // Q_ff singular: the reduced system has no unique solution; otherwise rounding stopped it.
  out.summary.finish(res <= m.tol && Xf.allFinite(), m.llt_ok ? Status::NumericalLimit : Status::NotUnique, [&] {
    std::ostringstream s;
    s << "the reduced extremal system has no solution to the tolerance: relative residual " << res << " > " << m.tol;
    if (!message.empty()) s << "; " << message;
    return s.str();
  });
  return out;
}

BSplineExtremalResult solve_bspline_extremal(const BSplineNet& data, const EnergySpec& energy,
                                             const std::vector<int>& fixed, const BSplineExtremalOptions& options) {
  options.validate();
  require_finite_rows(data.points(), fixed, "bspline extremal", data.nv());
  return timed_solve([&] {
    BSplineExtremalSolver solver(data.p(), data.q(), data.knots_u(), data.knots_v(), energy, fixed, options.tolerance);
    return solver.solve(data);
  });
}

BSplineExtremalResult solve_bspline_extremal(const BSplineNet& data, const EnergySpec& energy,
                                             const BSplineExtremalOptions& options) {
  options.validate();
  return solve_bspline_extremal(data, energy, data.fixed_indices(options.fixed), options);
}

}  // namespace bpde
