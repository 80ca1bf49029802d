#include "solvers/bspline_pde.h"

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <string>

#include "core/bernstein.h"
#include "core/errors.h"
#include "solvers/bspline_common.h"
#include "solvers/bspline_extremal.h"
#include "tensor/bspline_ops.h"

namespace bpde {
namespace {

double term_size_ratio(const Eigen::MatrixXd& A, const Eigen::MatrixXd& X, const Eigen::MatrixXd& R) {
  // max |R| / max (|A| |X|), over rows and coordinates.
  const Eigen::MatrixXd S = A.cwiseAbs() * X.cwiseAbs();
  const double smax = S.size() ? S.maxCoeff() : 0.0;
  const double rmax = R.size() ? R.cwiseAbs().maxCoeff() : 0.0;
  return smax > 0 ? rmax / smax : rmax;
}

std::string fmt(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

}  // namespace

void BSplinePdeOptions::validate() const {
  if (!(rank_tolerance > 0 && rank_tolerance < 1))
    throw ParameterError("bspline pde: rank_tolerance must be in (0, 1), got " + std::to_string(rank_tolerance));
  if (!(consistency_tolerance > 0 && consistency_tolerance < 1))
    throw ParameterError("bspline pde: consistency_tolerance must be in (0, 1), got " +
                         std::to_string(consistency_tolerance));
}

std::vector<OperatorTerm> euler_lagrange_terms(const EnergySpec& op) {
  std::vector<OperatorTerm> t;
  if (op.order() == 2) {
    const auto& c = op.second_order_coeffs();
    t = {{2, 0, c[0]}, {1, 1, c[1]}, {0, 2, c[2]}};
  } else {
    const auto& c = op.operator_coeffs();
    t = {{4, 0, c[0]}, {3, 1, c[1]}, {2, 2, c[2]}, {1, 3, c[3]}, {0, 4, c[4]}};
  }
  std::vector<OperatorTerm> out;
  for (const auto& x : t)
    if (x.c != 0.0) out.push_back(x);
  return out;
}

Eigen::MatrixXd bspline_pde_equations(int p, int q, const std::vector<double>& U, const std::vector<double>& V,
                                      const EnergySpec& op) {
  BSplineNet::validate_knots(p, U, "u");
  BSplineNet::validate_knots(q, V, "v");
  const std::vector<OperatorTerm> terms = euler_lagrange_terms(op);
  if (terms.empty()) throw ParameterError("bspline pde: the operator " + op.name() + " has all coefficients zero");
  int du = 0, dv = 0;
  for (const auto& t : terms) {
    if (t.ku > p || t.kv > q)
      throw DegreeError("bspline pde: the operator term d^" + std::to_string(t.ku) + "/du^" + std::to_string(t.ku) +
                        " d^" + std::to_string(t.kv) + "/dv^" + std::to_string(t.kv) + " of " + op.name() +
                        " vanishes identically at degree [" + std::to_string(p) + ", " + std::to_string(q) +
                        "]; the degree must be at least the order of differentiation in each direction");
    du = std::max(du, p - t.ku);
    dv = std::max(dv, q - t.kv);
  }
  const BezierExtraction eu = bezier_extraction(p, U), ev = bezier_extraction(q, V);
  const int nu = static_cast<int>(U.size()) - p - 1, nv = static_cast<int>(V.size()) - q - 1;
  // 1-D operators per span and derivative order: (d+1) x n,  E D_k C[s] / h^k.
  auto ops = [&terms](int k, int d, const BezierExtraction& ex, int order, bool along_u) {
    std::vector<std::vector<Eigen::MatrixXd>> R(static_cast<size_t>(ex.spans()));
    std::vector<bool> used(static_cast<size_t>(order) + 1, false);
    for (const auto& t : terms) used[static_cast<size_t>(along_u ? t.ku : t.kv)] = true;
    for (int s = 0; s < ex.spans(); ++s)
      for (int o = 0; o <= order; ++o) {
        if (!used[static_cast<size_t>(o)]) {
          R[static_cast<size_t>(s)].emplace_back();
          continue;
        }
        const Eigen::MatrixXd M = bernstein_elevation_operator(k - o, d - (k - o)) *
                                  bernstein_derivative_operator(k, o) * ex.C[static_cast<size_t>(s)] /
                                  std::pow(ex.width(s), o);
        R[static_cast<size_t>(s)].push_back(M);
      }
    return R;
  };
  const int order = op.order();
  const auto Ru = ops(p, du, eu, order, true), Rv = ops(q, dv, ev, order, false);
  const int per = (du + 1) * (dv + 1), S = eu.spans() * ev.spans();
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(per) * S, nu * nv);
  for (int su = 0; su < eu.spans(); ++su)
    for (int sv = 0; sv < ev.spans(); ++sv) {
      const int r0 = (su * ev.spans() + sv) * per;
      auto block = A.middleRows(r0, per);
      // Only columns of the live basis functions can be non-zero.
      const int iu0 = eu.first[static_cast<size_t>(su)], iv0 = ev.first[static_cast<size_t>(sv)];
      for (const auto& t : terms) {
        const Eigen::MatrixXd& Mu = Ru[static_cast<size_t>(su)][static_cast<size_t>(t.ku)];
        const Eigen::MatrixXd& Mv = Rv[static_cast<size_t>(sv)][static_cast<size_t>(t.kv)];
        for (int a = 0; a <= du; ++a)
          for (int i = iu0; i <= iu0 + p; ++i) {
            const double x = t.c * Mu(a, i);
            if (x == 0.0) continue;
            for (int b = 0; b <= dv; ++b)
              for (int j = iv0; j <= iv0 + q; ++j) block(a * (dv + 1) + b, i * nv + j) += x * Mv(b, j);
          }
      }
      const double mx = block.cwiseAbs().maxCoeff();
      if (mx > 0) block /= mx;
    }
  return A;
}

double bspline_pde_equation_residual(const BSplineNet& net, const EnergySpec& op) {
  const Eigen::MatrixXd A = bspline_pde_equations(net.p(), net.q(), net.knots_u(), net.knots_v(), op);
  const Eigen::MatrixXd P = net.points();
  return term_size_ratio(A, P, A * P);
}

double bspline_pde_residual(const BSplineNet& net, const EnergySpec& op, int samples) {
  if (samples < 1) throw ParameterError("bspline_pde_residual: samples must be >= 1");
  const std::vector<OperatorTerm> terms = euler_lagrange_terms(op);
  const int N = samples;
  Eigen::VectorXd tu(N + 1), tv(N + 1);
  for (int a = 0; a <= N; ++a) {
    tu(a) = net.u_min() + (net.u_max() - net.u_min()) * a / N;
    tv(a) = net.v_min() + (net.v_max() - net.v_min()) * a / N;
  }
  using RowMat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  std::vector<RowMat> Pc(3, RowMat(net.nu(), net.nv()));
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < net.nu(); ++i)
      for (int j = 0; j < net.nv(); ++j) Pc[static_cast<size_t>(c)](i, j) = net.points()(net.index(i, j), c);
  const int G = (N + 1) * (N + 1);
  Eigen::MatrixXd L = Eigen::MatrixXd::Zero(G, 3);
  Eigen::VectorXd size = Eigen::VectorXd::Zero(G);
  for (const auto& t : terms) {
    const Eigen::MatrixXd Bu = BSplineNet::basis_table(net.p(), net.knots_u(), tu, t.ku);
    const Eigen::MatrixXd Bv = BSplineNet::basis_table(net.q(), net.knots_v(), tv, t.kv);
    Eigen::MatrixXd D(G, 3);
    for (int c = 0; c < 3; ++c) {
      const RowMat g = Bu * Pc[static_cast<size_t>(c)] * Bv.transpose();
      for (int a = 0; a <= N; ++a)
        for (int b = 0; b <= N; ++b) D(a * (N + 1) + b, c) = g(a, b);
    }
    L += t.c * D;
    size += std::abs(t.c) * D.rowwise().norm();
  }
  const double smax = size.maxCoeff();
  const double lmax = L.rowwise().norm().maxCoeff();
  return smax > 0 ? lmax / smax : 0.0;
}

BSplinePdeResult solve_bspline_pde(const BSplineNet& data, const EnergySpec& op, const std::vector<int>& fixed,
                                   const BSplinePdeOptions& options) {
  options.validate();
  const auto t0 = std::chrono::steady_clock::now();
  const int N = data.size();
  {
    // The equations are solved densely (QR + SVD). Refuse sizes that would take minutes or
    // gigabytes instead of hanging; the extremal (sparse) has no such limit.
    int spans = 1;
    for (const auto* K : {&data.knots_u(), &data.knots_v()}) {
      int s = 0;
      const int k = K == &data.knots_u() ? data.p() : data.q();
      const int n = static_cast<int>(K->size()) - k - 1;
      for (int i = k; i < n; ++i) s += (*K)[static_cast<size_t>(i)] < (*K)[static_cast<size_t>(i) + 1];
      spans *= s;
    }
    const double rows = static_cast<double>(spans) * (data.p() + 1) * (data.q() + 1);
    if (N > kMaxDensePdeUnknowns || rows * N > kMaxDensePdeEntries)
      throw UnsupportedProblem("bspline pde: a net with " + std::to_string(N) + " control points and " +
                               std::to_string(spans) + " spans exceeds the dense solver's limits (" +
                               std::to_string(kMaxDensePdeUnknowns) + " points, " +
                               std::to_string(static_cast<long long>(kMaxDensePdeEntries)) +
                               " matrix entries); use the extremal, or fewer spans (on several spans an elliptic "
                               "fourth-order solution is one polynomial anyway)");
  }
  const Eigen::MatrixXd A = bspline_pde_equations(data.p(), data.q(), data.knots_u(), data.knots_v(), op);
  const std::vector<int> free = detail::complement_indices(N, fixed, "bspline pde");
  if (free.empty()) throw SizeError("bspline pde: every control point is fixed; nothing to solve");
  const Eigen::MatrixXd Xc = detail::gather_rows(data.points(), fixed);
  BSplinePdeResult out{data, {}, static_cast<int>(A.rows()), 0, 0, 0, 0, false, 0.0};

  // Compress the tall system: A = Q R (Householder, backward stable) has the singular values of
  // R, and min |A_f X_f + A_c X_c| = min |R_f X_f + R_c X_c|, so the SVDs below act on N rows.
  Eigen::MatrixXd Rm;
  if (A.rows() > A.cols()) {
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(A);
    Rm = qr.matrixQR().topRows(N).triangularView<Eigen::Upper>();
  } else {
    Rm = A;
  }
  const Eigen::MatrixXd Rf = detail::gather_cols(Rm, free);
  const Eigen::MatrixXd B = -(detail::gather_cols(Rm, fixed) * Xc);
  auto count_rank = [&](const Eigen::VectorXd& sv) {
    int k = 0;
    const double top = sv.size() ? sv(0) : 0.0;
    for (Eigen::Index i = 0; i < sv.size(); ++i)
      if (sv(i) > options.rank_tolerance * top) ++k;
    return k;
  };
  // Rank over all control points (the paper's count).
  out.rank = count_rank(Eigen::BDCSVD<Eigen::MatrixXd>(Rm).singularValues());
  // Rank-revealing least squares over the free points (V must be square: nf x nf).
  const int nf = static_cast<int>(free.size());
  Eigen::VectorXd s;
  Eigen::MatrixXd Uthin, Vfull;
  if (Rf.rows() >= Rf.cols()) {
    const Eigen::BDCSVD<Eigen::MatrixXd> svd(Rf, Eigen::ComputeThinU | Eigen::ComputeThinV);
    s = svd.singularValues();
    Uthin = svd.matrixU();
    Vfull = svd.matrixV();
  } else {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Rf, Eigen::ComputeThinU | Eigen::ComputeFullV);
    s = svd.singularValues();
    Uthin = svd.matrixU();
    Vfull = svd.matrixV();
  }
  const int r = count_rank(s);
  out.rank_free = r;
  out.free_parameters = nf - r;
  out.compatibility_conditions = out.rank - r;
  Eigen::MatrixXd Xf = Vfull.leftCols(r) * (s.head(r).cwiseInverse().asDiagonal() * (Uthin.leftCols(r).transpose() * B));

  auto residual_of = [&](const Eigen::MatrixXd& X) {
    Eigen::MatrixXd full(N, 3);
    for (int k = 0; k < nf; ++k) full.row(free[static_cast<size_t>(k)]) = X.row(k);
    for (size_t k = 0; k < fixed.size(); ++k) full.row(fixed[k]) = Xc.row(static_cast<Eigen::Index>(k));
    return term_size_ratio(A, full, A * full);
  };
  double res = residual_of(Xf);
  out.summary.residual = res;

  if (!(res <= options.consistency_tolerance) || !Xf.allFinite()) {
    std::ostringstream m;
    m << "incompatible data: no B-spline solution of the " << op.name() << " PDE on this net meets the prescribed "
      << fixed.size() << " control points. The " << out.equations << " span equations have rank " << out.rank
      << " (" << r << " on the free points), so the prescribed points must meet " << out.compatibility_conditions
      << " linear compatibility condition(s); the least-squares residual is " << fmt(res)
      << " relative (tolerance " << fmt(options.consistency_tolerance) << ").";
    out.summary.message = m.str();
    out.summary.converged = false;
    out.energy = bspline_energy(out.net, op);
    out.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
  }

  std::string message;
  if (out.free_parameters > 0) {
    // Minimise the energy over X0 + Z Y.
    const Eigen::MatrixXd Z = Vfull.rightCols(out.free_parameters);
    const Eigen::SparseMatrix<double> Q = bspline_gram(data.p(), data.q(), data.knots_u(), data.knots_v(), op);
    const Eigen::MatrixXd Qff = Eigen::MatrixXd(detail::sparse_submatrix(Q, free, free));
    const Eigen::MatrixXd Qfc = Eigen::MatrixXd(detail::sparse_submatrix(Q, free, fixed));
    const Eigen::MatrixXd H = Z.transpose() * Qff * Z;
    const Eigen::MatrixXd g = Z.transpose() * (Qff * Xf + Qfc * Xc);
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
    const Eigen::VectorXd lam = es.eigenvalues();
    // Zero eigenvalues are judged against the energy's scale on all free points (|Q_ff|), not
    // against H alone: an energy that vanishes on the whole solution set gives H ~ rounding.
    const double qscale = Qff.cwiseAbs().maxCoeff();
    const double cut = 1e-11 * std::max(qscale, 1e-300);
    Eigen::VectorXd inv = Eigen::VectorXd::Zero(lam.size());
    int zero = 0, negative = 0;
    for (Eigen::Index k = 0; k < lam.size(); ++k) {
      if (std::abs(lam(k)) > cut)
        inv(k) = 1.0 / lam(k);
      else
        ++zero;
      if (lam(k) < -cut) ++negative;
    }
    const Eigen::MatrixXd Y = -es.eigenvectors() * inv.asDiagonal() * es.eigenvectors().transpose() * g;
    Xf += Z * Y;
    res = residual_of(Xf);
    out.summary.residual = res;
    out.minimum_energy_member = true;
    std::ostringstream m;
    m << "the PDE with the prescribed points leaves " << out.free_parameters
      << " free parameter(s) per coordinate (equations of rank " << out.rank << " over all points, " << r
      << " over the free ones); returned the member of minimal " << op.name() << " energy";
    if (negative > 0)
      m << " (the energy is indefinite on the solution set: this is its critical point, not a minimum)";
    else if (zero > 0)
      m << " (the energy is constant along " << zero << " direction(s) of the solution set: the minimum-norm minimiser)";
    message = m.str();
  }
  detail::scatter_rows(out.net.points(), free, Xf);
  out.energy = bspline_energy(out.net, op);
  out.summary.converged = res <= options.consistency_tolerance && Xf.allFinite();
  out.summary.message = out.summary.converged
                            ? message
                            : "the solution lost accuracy: relative residual " + fmt(res) + " after fixing the free parameters";
  out.summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

BSplinePdeResult solve_bspline_pde(const BSplineNet& data, const EnergySpec& op, const BSplinePdeOptions& options) {
  options.validate();
  if (op.order() == 4 && options.fixed == FixedSet::UBoundaries)
    throw UnsupportedProblem("bspline pde: \"u-boundaries\" is for second-order operators; the fourth-order " +
                             op.name() + " PDE takes \"boundary\" data");
  return solve_bspline_pde(data, op, data.fixed_indices(options.fixed), options);
}

}  // namespace bpde
