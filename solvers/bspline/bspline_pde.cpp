#include "bezierpde/solvers/bspline/bspline_pde.h"

#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "bezierpde/core/bernstein.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/bspline/bspline_common.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"
#include "bezierpde/tensor/bspline_ops.h"

namespace bpde {
namespace {

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

namespace {

// The span equations, one span at a time: block(su, sv) is the (per x (p+1)(q+1)) matrix of the
// scaled Bernstein coefficients of Lx on that span in terms of its live control points
// (local column a*(q+1) + b  <->  point (first_u + a, first_v + b)).
class SpanSystem {
 public:
  SpanSystem(int p, int q, const std::vector<double>& U, const std::vector<double>& V, const EnergySpec& op)
      : p_(p), q_(q) {
    BSplineNet::validate_knots(p, U, "u");
    BSplineNet::validate_knots(q, V, "v");
    terms_ = pde_operator_terms(op);
    if (terms_.empty()) throw ParameterError("bspline pde: the operator " + op.name() + " has all coefficients zero");
    for (const auto& t : terms_) {
      if (t.du > p || t.dv > q)
        throw DegreeError("bspline pde: the operator term d^" + std::to_string(t.du) + "/du^" + std::to_string(t.du) +
                          " d^" + std::to_string(t.dv) + "/dv^" + std::to_string(t.dv) + " of " + op.name() +
                          " vanishes identically at degree [" + std::to_string(p) + ", " + std::to_string(q) +
                          "]; the degree must be at least the order of differentiation in each direction");
      du_ = std::max(du_, p - t.du);
      dv_ = std::max(dv_, q - t.dv);
    }
    eu_ = bezier_extraction(p, U);
    ev_ = bezier_extraction(q, V);
    nv_ = static_cast<int>(V.size()) - q - 1;
    N_ = (static_cast<int>(U.size()) - p - 1) * nv_;
    Ru_ = ops(p, du_, eu_, op.order(), true);
    Rv_ = ops(q, dv_, ev_, op.order(), false);
  }
  int per() const { return (du_ + 1) * (dv_ + 1); }
  int spans_u() const { return eu_.spans(); }
  int spans_v() const { return ev_.spans(); }
  int first_u(int su) const { return eu_.first[static_cast<size_t>(su)]; }
  int first_v(int sv) const { return ev_.first[static_cast<size_t>(sv)]; }
  int nv() const { return nv_; }
  int N() const { return N_; }
  int equations() const { return per() * spans_u() * spans_v(); }
  int global(int su, int sv, int a, int b) const { return (first_u(su) + a) * nv_ + first_v(sv) + b; }

  Eigen::MatrixXd block(int su, int sv) const {
    Eigen::MatrixXd B = Eigen::MatrixXd::Zero(per(), (p_ + 1) * (q_ + 1));
    const int iu0 = first_u(su), iv0 = first_v(sv);
    for (const auto& t : terms_) {
      const Eigen::MatrixXd& Mu = Ru_[static_cast<size_t>(su)][static_cast<size_t>(t.du)];
      const Eigen::MatrixXd& Mv = Rv_[static_cast<size_t>(sv)][static_cast<size_t>(t.dv)];
      for (int a = 0; a <= du_; ++a)
        for (int i = 0; i <= p_; ++i) {
          const double x = t.c * Mu(a, iu0 + i);
          if (x == 0.0) continue;
          for (int b = 0; b <= dv_; ++b)
            for (int j = 0; j <= q_; ++j) B(a * (dv_ + 1) + b, i * (q_ + 1) + j) += x * Mv(b, iv0 + j);
        }
    }
    const double mx = B.cwiseAbs().maxCoeff();
    if (mx > 0) B /= mx;
    return B;
  }

  /// max |A Y| / max (|A| |Y|) over all span equations (Y: N x 3, all control points).
  double residual(const Eigen::MatrixXd& Y) const {
    double rmax = 0, smax = 0;
    Eigen::MatrixXd y((p_ + 1) * (q_ + 1), Y.cols());
    for (int su = 0; su < spans_u(); ++su)
      for (int sv = 0; sv < spans_v(); ++sv) {
        const Eigen::MatrixXd B = block(su, sv);
        for (int a = 0; a <= p_; ++a)
          for (int b = 0; b <= q_; ++b) y.row(a * (q_ + 1) + b) = Y.row(global(su, sv, a, b));
        rmax = std::max(rmax, (B * y).cwiseAbs().maxCoeff());
        smax = std::max(smax, (B.cwiseAbs() * y.cwiseAbs()).maxCoeff());
      }
    return smax > 0 ? rmax / smax : rmax;
  }

  /// An N x N upper-triangular R with R^T R = A^T A, by Householder QR strip by strip (the rows of
  /// one u-span touch the columns of p+1 consecutive i only), so A is never formed.
  Eigen::MatrixXd compressed() const {
    const int W = (p_ + 1) * nv_;
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(N_, N_);
    Eigen::MatrixXd carry(0, W);
    int i0 = first_u(0);
    auto emit = [&](int count) {  // move the first `count` carry rows into R
      const int k = std::min<int>(count, static_cast<int>(carry.rows()));
      for (int r = 0; r < k; ++r) R.row(i0 * nv_ + r).segment(i0 * nv_, W) = carry.row(r);
      return k;
    };
    for (int su = 0; su < spans_u(); ++su) {
      const int fu = first_u(su);
      if (fu > i0) {
        const int sc = (fu - i0) * nv_;
        const int k = emit(sc);
        Eigen::MatrixXd rest = Eigen::MatrixXd::Zero(carry.rows() - k, W);
        if (rest.rows() > 0) rest.leftCols(W - sc) = carry.bottomRows(rest.rows()).rightCols(W - sc);
        carry = std::move(rest);
        i0 = fu;
      }
      Eigen::MatrixXd stacked = Eigen::MatrixXd::Zero(carry.rows() + static_cast<Eigen::Index>(per()) * spans_v(), W);
      stacked.topRows(carry.rows()) = carry;
      for (int sv = 0; sv < spans_v(); ++sv) {
        const Eigen::MatrixXd B = block(su, sv);
        const int r0 = static_cast<int>(carry.rows()) + sv * per();
        for (int a = 0; a <= p_; ++a)
          for (int b = 0; b <= q_; ++b)
            stacked.block(r0, a * nv_ + first_v(sv) + b, per(), 1) = B.col(a * (q_ + 1) + b);
      }
      const Eigen::HouseholderQR<Eigen::MatrixXd> qr(stacked);
      const int rows = static_cast<int>(std::min<Eigen::Index>(stacked.rows(), W));
      carry = qr.matrixQR().topRows(rows).triangularView<Eigen::Upper>();
    }
    emit(static_cast<int>(carry.rows()));
    return R;
  }

 private:
  std::vector<std::vector<Eigen::MatrixXd>> ops(int k, int d, const BezierExtraction& ex, int order,
                                                bool along_u) const {
    // 1-D operators per span and derivative order: (d+1) x n,  E D_k C[s] / h^k.
    std::vector<std::vector<Eigen::MatrixXd>> R(static_cast<size_t>(ex.spans()));
    std::vector<bool> used(static_cast<size_t>(order) + 1, false);
    for (const auto& t : terms_) used[static_cast<size_t>(along_u ? t.du : t.dv)] = true;
    for (int s = 0; s < ex.spans(); ++s)
      for (int o = 0; o <= order; ++o) {
        if (!used[static_cast<size_t>(o)]) {
          R[static_cast<size_t>(s)].emplace_back();
          continue;
        }
        R[static_cast<size_t>(s)].push_back(bernstein_elevation_operator(k - o, d - (k - o)) *
                                            bernstein_derivative_operator(k, o) * ex.C[static_cast<size_t>(s)] /
                                            std::pow(ex.width(s), o));
      }
    return R;
  }

  int p_, q_, du_ = 0, dv_ = 0, nv_ = 0, N_ = 0;
  std::vector<PdeTerm> terms_;
  BezierExtraction eu_, ev_;
  std::vector<std::vector<Eigen::MatrixXd>> Ru_, Rv_;
};

}  // namespace

Eigen::MatrixXd bspline_pde_equations(int p, int q, const std::vector<double>& U, const std::vector<double>& V,
                                      const EnergySpec& op) {
  const SpanSystem sys(p, q, U, V, op);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(sys.equations(), sys.N());
  for (int su = 0; su < sys.spans_u(); ++su)
    for (int sv = 0; sv < sys.spans_v(); ++sv) {
      const Eigen::MatrixXd B = sys.block(su, sv);
      const int r0 = (su * sys.spans_v() + sv) * sys.per();
      for (int a = 0; a <= p; ++a)
        for (int b = 0; b <= q; ++b) A.block(r0, sys.global(su, sv, a, b), sys.per(), 1) = B.col(a * (q + 1) + b);
    }
  return A;
}

double bspline_pde_equation_residual(const BSplineNet& net, const EnergySpec& op) {
  const SpanSystem sys(net.p(), net.q(), net.knots_u(), net.knots_v(), op);
  return sys.residual(net.points());
}

double bspline_pde_residual(const BSplineNet& net, const EnergySpec& op, int samples) {
  if (samples < 1) throw ParameterError("bspline_pde_residual: samples must be >= 1");
  const std::vector<PdeTerm> terms = pde_operator_terms(op);
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
    const Eigen::MatrixXd Bu = BSplineNet::basis_table(net.p(), net.knots_u(), tu, t.du);
    const Eigen::MatrixXd Bv = BSplineNet::basis_table(net.q(), net.knots_v(), tv, t.dv);
    Eigen::MatrixXd D(G, 3);
    for (int c = 0; c < 3; ++c) {
      const RowMat g = Bu * Pc[static_cast<size_t>(c)] * Bv.transpose();
      for (int a = 0; a <= N; ++a)
        for (int b = 0; b <= N; ++b) D(a * (N + 1) + b, c) = g(a, b);
    }
    L += t.c * D;
    size += std::abs(t.c) * D.rowwise().norm();
  }
  // Floor (see the header): the size a derivative of this net can have, times 1e-8.
  auto min_width = [](int k, const std::vector<double>& K) {
    double h = K.back() - K.front();
    const int n = static_cast<int>(K.size()) - k - 1;
    for (int i = k; i < n; ++i)
      if (K[static_cast<size_t>(i) + 1] > K[static_cast<size_t>(i)])
        h = std::min(h, K[static_cast<size_t>(i) + 1] - K[static_cast<size_t>(i)]);
    return h;
  };
  const double hu = min_width(net.p(), net.knots_u()), hv = min_width(net.q(), net.knots_v());
  double floor = 0;
  for (const auto& t : terms)
    if (t.du <= net.p() && t.dv <= net.q())
      floor += std::abs(t.c) * factorial(net.p()) / factorial(net.p() - t.du) * factorial(net.q()) /
               factorial(net.q() - t.dv) / (std::pow(hu, t.du) * std::pow(hv, t.dv));
  floor *= 1e-8 * net.points().cwiseAbs().maxCoeff();
  const double smax = std::max(size.maxCoeff(), floor);
  const double lmax = L.rowwise().norm().maxCoeff();
  return smax > 0 ? lmax / smax : 0.0;
}

namespace {

void check_size(int N) {
  if (N > kMaxDensePdeUnknowns)
    throw UnsupportedProblem("bspline pde: a net with " + std::to_string(N) +
                             " control points exceeds the dense "
                             "solver's limit of " +
                             std::to_string(kMaxDensePdeUnknowns) +
                             " points; use the extremal, or fewer spans (on several spans an elliptic fourth-order "
                             "solution is one polynomial anyway)");
}

// Singular values above rank_tolerance * the largest.
int count_rank(const Eigen::VectorXd& sv, double rank_tolerance) {
  int k = 0;
  const double top = sv.size() ? sv(0) : 0.0;
  for (Eigen::Index i = 0; i < sv.size(); ++i)
    if (sv(i) > rank_tolerance * top) ++k;
  return k;
}

// Rank-revealing least squares over the free points: Rf = U diag(s) V^T with V square (nf x nf),
// so that its last nf - rank columns span the null space of Rf.
struct FreeSvd {
  Eigen::VectorXd s;
  Eigen::MatrixXd U, V;
  explicit FreeSvd(const Eigen::MatrixXd& Rf) {
    if (Rf.rows() >= Rf.cols()) {
      const Eigen::BDCSVD<Eigen::MatrixXd> svd(Rf, Eigen::ComputeThinU | Eigen::ComputeThinV);
      s = svd.singularValues();
      U = svd.matrixU();
      V = svd.matrixV();
    } else {
      const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Rf, Eigen::ComputeThinU | Eigen::ComputeFullV);
      s = svd.singularValues();
      U = svd.matrixU();
      V = svd.matrixV();
    }
  }
  /// The minimum-norm least-squares solution of Rf X = B at rank r.
  Eigen::MatrixXd least_squares(const Eigen::MatrixXd& B, int r) const {
    return V.leftCols(r) * (s.head(r).cwiseInverse().asDiagonal() * (U.leftCols(r).transpose() * B));
  }
};

std::string incompatible_message(const EnergySpec& op, std::size_t prescribed, const BSplinePdeResult& out, double res,
                                 double tolerance) {
  std::ostringstream m;
  m << "incompatible data: no B-spline solution of the " << op.name() << " PDE on this net meets the prescribed "
    << prescribed << " control points. The " << out.equations << " span equations have rank " << out.rank << " ("
    << out.rank_free << " on the free points), so the prescribed points must meet " << out.compatibility_conditions
    << " linear compatibility condition(s); the least-squares residual is " << fmt(res) << " relative (tolerance "
    << fmt(tolerance) << ").";
  return m.str();
}

// Consistent data with free parameters: moves Xf to the member of Xf + Z Y (Z spans the free
// parameters) that minimises the energy of op, and says so in the returned message.
std::string minimise_energy_over_free_parameters(const BSplineNet& data, const EnergySpec& op,
                                                 const std::vector<int>& free, const std::vector<int>& fixed,
                                                 const Eigen::MatrixXd& Xc, const Eigen::MatrixXd& Z,
                                                 const BSplinePdeResult& out, Eigen::MatrixXd& Xf) {
  const Eigen::SparseMatrix<double> Q = bspline_gram(data.p(), data.q(), data.knots_u(), data.knots_v(), op);
  const Eigen::MatrixXd Qff = Eigen::MatrixXd(detail::sparse_submatrix(Q, free, free));
  const Eigen::MatrixXd Qfc = Eigen::MatrixXd(detail::sparse_submatrix(Q, free, fixed));
  const Eigen::MatrixXd H = Z.transpose() * Qff * Z;
  const Eigen::MatrixXd g = Z.transpose() * (Qff * Xf + Qfc * Xc);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(H);
  const Eigen::VectorXd lam = es.eigenvalues();
  // Zero eigenvalues are judged against the energy's scale on all free points (|Q_ff|), not
  // against H alone: an energy that vanishes on the whole solution set gives H ~ rounding. The
  // cut is relative to that scale (a rank decision, not the convergence tolerance).
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
  std::ostringstream m;
  m << "the PDE with the prescribed points leaves " << out.free_parameters
    << " free parameter(s) per coordinate (equations of rank " << out.rank << " over all points, " << out.rank_free
    << " over the free ones); returned the member of minimal " << op.name() << " energy";
  if (negative > 0)
    m << " (the energy is indefinite on the solution set: this is its critical point, not a minimum)";
  else if (zero > 0)
    m << " (the energy is constant along " << zero << " direction(s) of the solution set: the minimum-norm minimiser)";
  return m.str();
}

// The solve of solve_bspline_pde into out (out.net holds the data).
void solve_into(const BSplineNet& data, const EnergySpec& op, const std::vector<int>& fixed,
                const BSplinePdeOptions& options, BSplinePdeResult& out) {
  const int N = data.size();
  check_size(N);
  const SpanSystem sys(data.p(), data.q(), data.knots_u(), data.knots_v(), op);
  const std::vector<int> free = detail::complement_indices(N, fixed, "bspline pde");
  if (free.empty()) throw SizeError("bspline pde: every control point is fixed; nothing to solve");
  const Eigen::MatrixXd Xc = detail::gather_rows(data.points(), fixed);
  out.equations = sys.equations();

  // Compress the tall system strip by strip: R^T R = A^T A, so R has the singular values of A and
  // |A_f X_f + A_c X_c| = |R_f X_f + R_c X_c|; the SVDs below act on N rows and A is never formed.
  const Eigen::MatrixXd Rm = sys.compressed();
  const Eigen::MatrixXd Rf = detail::gather_cols(Rm, free);
  const Eigen::MatrixXd B = -(detail::gather_cols(Rm, fixed) * Xc);
  // Rank over all control points (the paper's count), then over the free points.
  out.rank = count_rank(Eigen::BDCSVD<Eigen::MatrixXd>(Rm).singularValues(), options.rank_tolerance);
  const int nf = static_cast<int>(free.size());
  const FreeSvd svd(Rf);
  const int r = count_rank(svd.s, options.rank_tolerance);
  out.rank_free = r;
  out.free_parameters = nf - r;
  out.compatibility_conditions = out.rank - r;
  Eigen::MatrixXd Xf = svd.least_squares(B, r);

  auto residual_of = [&](const Eigen::MatrixXd& X) {
    Eigen::MatrixXd full(N, 3);
    full(free, Eigen::all) = X;
    full(fixed, Eigen::all) = Xc;
    return sys.residual(full);
  };
  double res = residual_of(Xf);
  out.summary.residual = res;

  if (!(res <= options.consistency_tolerance) || !Xf.allFinite()) {
    // The input net is returned unchanged (no least-squares net).
    out.summary.set_failed(Xf.allFinite() ? Status::Incompatible : Status::NumericalLimit,
                           incompatible_message(op, fixed.size(), out, res, options.consistency_tolerance));
    out.energy = bspline_energy(out.net, op);
    return;
  }

  std::string message;
  if (out.free_parameters > 0) {
    message =
        minimise_energy_over_free_parameters(data, op, free, fixed, Xc, svd.V.rightCols(out.free_parameters), out, Xf);
    res = residual_of(Xf);
    out.summary.residual = res;
    out.minimum_energy_member = true;
  }
  detail::scatter_rows(out.net.points(), free, Xf);
  out.energy = bspline_energy(out.net, op);
  out.summary.message = message;
  out.summary.finish(res <= options.consistency_tolerance && Xf.allFinite(), Status::NumericalLimit, [&] {
    return "the solution lost accuracy: relative residual " + fmt(res) + " after fixing the free parameters";
  });
}

}  // namespace

BSplinePdeResult solve_bspline_pde(const BSplineNet& data, const EnergySpec& op, const std::vector<int>& fixed,
                                   const BSplinePdeOptions& options) {
  options.validate();
  require_finite_rows(data.points(), fixed, "bspline pde", data.nv());
  BSplinePdeResult out{data, {}, 0, 0, 0, 0, 0, false, 0.0};
  {
    ScopedTimer timer(out.summary.seconds);
    solve_into(data, op, fixed, options, out);
  }
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
