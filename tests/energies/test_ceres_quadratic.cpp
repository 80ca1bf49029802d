// A quadratic energy as a Ceres residual block, and its tests: the cost equals the energy;
// Ceres alone reproduces the linear extremal; with a non-quadratic soft pin it agrees with an
// independent Newton iteration on the same objective.
//
// The adapter lives here, not in the library: its only user is this test. It was tried as the
// Dirichlet part of the CMC Ceres route (solvers/cmc/cmc_ceres.cpp): minimise D_H = D + 2HV with
// D as this block and 2HV as the one least-squares form a sign-indefinite cubic term has,
// r = sqrt(2 (2HV + K)). On the triangular degree-5 planar-triangle data, correcting from the
// solution at 0.95 H to H (H from 0.1 to 0.97 of the fold), that route stalls at a relative
// eq. (11) residual of 1e-10..1e-9 (the cost change vanishes in rounding before the gradient
// reaches 1e-11) after 5..200 iterations, depending on the shift K and more towards the fold
// (Gauss–Newton drops the 2H d²V part of the Hessian). The route of cmc_ceres.cpp (LM on the
// residuals F_I of eq. (11), exact Jacobian) reaches 1e-11 in 3..5 iterations. The energy form
// suits terms that are sums of squares (e.g. an area term per quadrature node).
//
// The adapter: E(P) = 1/2 Σ_c P_c^T Q P_c (energies/quadratic_energy.h) with Q symmetric positive
// semidefinite, factored once as Q = R^T R with R = diag(sqrt(λ_k)) V_k^T from its
// eigen-decomposition, keeping the eigenvalues above rank_tolerance * λ_max. The residual vector
// is r[3k + c] = (R P_c)_k, so Ceres's cost of the block, 1/2 |r|^2, EQUALS E(P). Parameter
// blocks: one block of 3 doubles per control point, in point order; prescribed points are held
// with problem.SetParameterBlockConstant.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/quadratic_energy.h"
#include "bezierpde/energies/tensor_gram.h"
#include "bezierpde/solvers/extremal.h"
#include "tests/random_points.h"

namespace bpde {
namespace {

/// R (r x N) with R^T R = Q up to the dropped eigenvalues below rank_tolerance * λ_max. Throws
/// SizeError (not square), NonFiniteError, ParameterError if Q has an eigenvalue below
/// -negative_tolerance * λ_max (Q indefinite: the energy is not a sum of squares).
Eigen::MatrixXd psd_factor(const Eigen::MatrixXd& Q, double rank_tolerance = 1e-14, double negative_tolerance = 1e-10);

class QuadraticEnergyCost : public ceres::CostFunction {
 public:
  /// From a factor R (r x N), see psd_factor.
  explicit QuadraticEnergyCost(Eigen::MatrixXd R);
  /// From the Gram matrix Q (N x N) through psd_factor.
  static QuadraticEnergyCost* from_gram(const Eigen::MatrixXd& Q);
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::MatrixXd R_;
};

/// Adds the energy of Q to `problem`; blocks[I] points to the 3 doubles of control point I
/// (blocks.size() == Q.rows(), SizeError otherwise). Ceres takes ownership of the cost function.
ceres::ResidualBlockId add_quadratic_energy(ceres::Problem& problem, const Eigen::MatrixXd& Q,
                                            const std::vector<double*>& blocks);

Eigen::MatrixXd psd_factor(const Eigen::MatrixXd& Q, double rank_tolerance, double negative_tolerance) {
  if (Q.rows() != Q.cols()) throw SizeError("psd_factor: Gram matrix is not square");
  if (!Q.allFinite()) throw NonFiniteError("psd_factor: Gram matrix has a non-finite entry");
  if (Q.rows() == 0) return Eigen::MatrixXd(0, 0);
  const Eigen::MatrixXd S = 0.5 * (Q + Q.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S);
  if (es.info() != Eigen::Success) throw ParameterError("psd_factor: eigen-decomposition failed");
  const Eigen::VectorXd& lam = es.eigenvalues();  // increasing
  const double lmax = std::max(lam.cwiseAbs().maxCoeff(), 0.0);
  if (lmax == 0.0) return Eigen::MatrixXd::Zero(0, Q.cols());
  if (lam(0) < -negative_tolerance * lmax) {
    std::ostringstream s;
    s << "psd_factor: the Gram matrix is indefinite (eigenvalue " << lam(0) << " against " << lmax
      << "): the energy is not a sum of squares and cannot be a Ceres residual";
    throw ParameterError(s.str());
  }
  std::vector<Eigen::Index> keep;
  for (Eigen::Index k = 0; k < lam.size(); ++k)
    if (lam(k) > rank_tolerance * lmax) keep.push_back(k);
  Eigen::MatrixXd R(static_cast<Eigen::Index>(keep.size()), Q.cols());
  for (size_t r = 0; r < keep.size(); ++r)
    R.row(static_cast<Eigen::Index>(r)) = std::sqrt(lam(keep[r])) * es.eigenvectors().col(keep[r]).transpose();
  return R;
}

QuadraticEnergyCost::QuadraticEnergyCost(Eigen::MatrixXd R) : R_(std::move(R)) {
  if (!R_.allFinite()) throw NonFiniteError("QuadraticEnergyCost: non-finite factor");
  set_num_residuals(static_cast<int>(3 * R_.rows()));
  std::vector<int32_t>& sizes = *mutable_parameter_block_sizes();
  sizes.assign(static_cast<size_t>(R_.cols()), 3);
}

QuadraticEnergyCost* QuadraticEnergyCost::from_gram(const Eigen::MatrixXd& Q) {
  return new QuadraticEnergyCost(psd_factor(Q));
}

bool QuadraticEnergyCost::Evaluate(double const* const* parameters, double* residuals, double** jacobians) const {
  const Eigen::Index r = R_.rows(), N = R_.cols();
  Eigen::MatrixX3d P(N, 3);
  for (Eigen::Index I = 0; I < N; ++I)
    for (int c = 0; c < 3; ++c) P(I, c) = parameters[I][c];
  // residual 3k + c = (R P)(k, c): a row-major r x 3 matrix.
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> res(residuals, r, 3);
  res.noalias() = R_ * P;
  if (jacobians != nullptr) {
    for (Eigen::Index I = 0; I < N; ++I) {
      double* J = jacobians[I];
      if (J == nullptr) continue;
      // (3r x 3) row-major: d r[3k + c] / d P_I[d] = R(k, I) δ_cd.
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>> Jm(J, 3 * r, 3);
      Jm.setZero();
      for (Eigen::Index k = 0; k < r; ++k)
        for (int c = 0; c < 3; ++c) Jm(3 * k + c, c) = R_(k, I);
    }
  }
  return true;
}

ceres::ResidualBlockId add_quadratic_energy(ceres::Problem& problem, const Eigen::MatrixXd& Q,
                                            const std::vector<double*>& blocks) {
  if (static_cast<Eigen::Index>(blocks.size()) != Q.rows())
    throw SizeError("add_quadratic_energy: " + std::to_string(blocks.size()) + " parameter blocks for " +
                    std::to_string(Q.rows()) + " control points");
  return problem.AddResidualBlock(QuadraticEnergyCost::from_gram(Q), nullptr, blocks);
}

using testing::random_points;

std::vector<double*> point_blocks(std::vector<Eigen::Vector3d>& pts) {
  std::vector<double*> b;
  for (auto& p : pts) b.push_back(p.data());
  return b;
}

ceres::Solver::Options tight_options() {
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.function_tolerance = 1e-16;
  o.gradient_tolerance = 1e-16;
  o.parameter_tolerance = 1e-16;
  o.max_num_iterations = 200;
  return o;
}

TEST(CeresQuadratic, FactorReproducesGram) {
  for (const auto& e : {EnergySpec::dirichlet(), EnergySpec::laplacian_squared(), EnergySpec::gnorm(2.0, 0.4)}) {
    const Eigen::MatrixXd Q = tensor_gram(e, 5, 4);
    const Eigen::MatrixXd R = psd_factor(Q);
    EXPECT_LE((R.transpose() * R - Q).cwiseAbs().maxCoeff(), 1e-12 * Q.cwiseAbs().maxCoeff()) << e.name();
    EXPECT_LT(R.rows(), Q.rows());  // the affine (or constant) functions have zero energy
  }
  // a|x_u|^2 + 3<x_u,x_v> + |x_v|^2 is indefinite (x = u - v has negative energy)
  EXPECT_THROW(psd_factor(tensor_gram(EnergySpec::second_order(1, 3, 1), 3, 3)), ParameterError);
}

TEST(CeresQuadratic, CostEqualsEnergy) {
  const int n = 4, m = 3;
  const Eigen::MatrixXd Q = tensor_gram(EnergySpec::biharmonic(), n, m);
  const Eigen::MatrixX3d P = random_points(Q.rows(), 11);
  std::vector<Eigen::Vector3d> pts;
  for (int I = 0; I < P.rows(); ++I) pts.push_back(P.row(I).transpose());
  ceres::Problem problem;
  add_quadratic_energy(problem, Q, point_blocks(pts));
  double cost = 0;
  std::vector<double> grad;
  problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, &grad, nullptr);
  const QuadraticEnergy E(Q);
  EXPECT_NEAR(cost, E.value(P), 1e-12 * E.value(P));
  const Eigen::MatrixX3d G = E.gradient(P);
  for (int I = 0; I < P.rows(); ++I)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(grad[static_cast<size_t>(3 * I + c)], G(I, c), 1e-10 * G.cwiseAbs().maxCoeff());
  EXPECT_THROW(add_quadratic_energy(problem, Q, {}), SizeError);
}

TEST(CeresQuadratic, CeresAloneReproducesTheLinearExtremal) {
  const int n = 5, m = 4;
  const EnergySpec e = EnergySpec::laplacian_squared();
  const TensorNet data(n, m, random_points((n + 1) * (m + 1), 21));
  const ExtremalResult ref = solve_extremal(data, e, FixedSet::Boundary);
  std::vector<Eigen::Vector3d> pts;
  for (int I = 0; I < data.size(); ++I) pts.push_back(data.points().row(I).transpose() * 0.3);  // bad start inside
  ceres::Problem problem;
  add_quadratic_energy(problem, tensor_gram(e, n, m), point_blocks(pts));
  for (int I : data.fixed_indices(FixedSet::Boundary)) {
    pts[static_cast<size_t>(I)] = data.points().row(I).transpose();
    problem.SetParameterBlockConstant(pts[static_cast<size_t>(I)].data());
  }
  ceres::Solver::Summary summary;
  ceres::Solve(tight_options(), &problem, &summary);
  double err = 0;
  for (int I = 0; I < data.size(); ++I)
    err = std::max(err, (pts[static_cast<size_t>(I)] - ref.net.points().row(I).transpose()).cwiseAbs().maxCoeff());
  EXPECT_LE(err, 1e-8) << summary.BriefReport();
  EXPECT_NEAR(summary.final_cost, ref.energy, 1e-10 * ref.energy);
}

// Soft pin: residuals κ sinh(p - target), cost 1/2 κ² Σ sinh²(p - target).
struct SinhPin {
  SinhPin(const Eigen::Vector3d& t, double k) : target(t), kappa(k) {}
  template <typename T>
  bool operator()(const T* p, T* r) const {
    for (int c = 0; c < 3; ++c) r[c] = T(kappa) * sinh(p[c] - T(target(c)));
    return true;
  }
  Eigen::Vector3d target;
  double kappa;
};

TEST(CeresQuadratic, WithANonQuadraticTermAgreesWithNewton) {
  const int n = 4, m = 4;
  const EnergySpec e = EnergySpec::biharmonic();
  const Eigen::MatrixXd Q = tensor_gram(e, n, m);
  const TensorNet data(n, m, random_points((n + 1) * (m + 1), 33));
  const std::vector<int> fixed = data.fixed_indices(FixedSet::Boundary), free = data.free_indices(FixedSet::Boundary);
  const std::vector<int> pinned = {data.index(2, 2), data.index(1, 3)};
  const std::vector<Eigen::Vector3d> targets = {{0.4, -0.2, 1.5}, {-0.7, 0.3, -1.0}};
  const double kappa = 3.0;

  // Ceres
  std::vector<Eigen::Vector3d> pts;
  for (int I = 0; I < data.size(); ++I) pts.push_back(data.points().row(I).transpose());
  for (int I : free) pts[static_cast<size_t>(I)].setZero();
  ceres::Problem problem;
  add_quadratic_energy(problem, Q, point_blocks(pts));
  for (int I : fixed) problem.SetParameterBlockConstant(pts[static_cast<size_t>(I)].data());
  for (size_t k = 0; k < pinned.size(); ++k)
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<SinhPin, 3, 3>(new SinhPin(targets[k], kappa)), nullptr,
                             pts[static_cast<size_t>(pinned[k])].data());
  ceres::Solver::Summary summary;
  ceres::Solve(tight_options(), &problem, &summary);

  // Independent Newton on F(P_f) = 1/2 Σ_c P_c^T Q P_c + 1/2 κ² Σ sinh²(p - t), coordinates separate.
  Eigen::MatrixX3d P = data.points();
  for (int I : free) P.row(I).setZero();
  const int nf = static_cast<int>(free.size());
  for (int it = 0; it < 50; ++it) {
    double step = 0;
    for (int c = 0; c < 3; ++c) {
      Eigen::VectorXd g(nf);
      Eigen::MatrixXd H(nf, nf);
      for (int a = 0; a < nf; ++a) {
        g(a) = Q.row(free[static_cast<size_t>(a)]).dot(P.col(c));
        for (int b = 0; b < nf; ++b) H(a, b) = Q(free[static_cast<size_t>(a)], free[static_cast<size_t>(b)]);
      }
      for (size_t k = 0; k < pinned.size(); ++k) {
        const int a = static_cast<int>(std::find(free.begin(), free.end(), pinned[k]) - free.begin());
        const double d = P(pinned[k], c) - targets[k](c);
        g(a) += kappa * kappa * std::sinh(d) * std::cosh(d);
        H(a, a) += kappa * kappa * std::cosh(2 * d);
      }
      const Eigen::VectorXd dx = H.ldlt().solve(-g);
      for (int a = 0; a < nf; ++a) P(free[static_cast<size_t>(a)], c) += dx(a);
      step = std::max(step, dx.cwiseAbs().maxCoeff());
    }
    if (step < 1e-15) break;
  }
  double err = 0;
  for (int I = 0; I < data.size(); ++I)
    err = std::max(err, (pts[static_cast<size_t>(I)] - P.row(I).transpose()).cwiseAbs().maxCoeff());
  EXPECT_LE(err, 1e-7) << summary.BriefReport();
  // the pin really pulls: the answer is not the plain extremal
  const ExtremalResult plain = solve_extremal(data, e, FixedSet::Boundary);
  EXPECT_GT((plain.net.points() - P).cwiseAbs().maxCoeff(), 1e-2);
}

}  // namespace
}  // namespace bpde
