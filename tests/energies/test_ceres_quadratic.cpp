// The Ceres adapter: its cost equals the energy; Ceres alone reproduces the linear extremal; with
// a non-quadratic soft pin it agrees with an independent Newton iteration on the same objective.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "core/errors.h"
#include "energies/ceres_quadratic.h"
#include "energies/quadratic_energy.h"
#include "energies/tensor_gram.h"
#include "solvers/extremal.h"
#include "tests/random_points.h"

namespace bpde {
namespace {

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
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(grad[static_cast<size_t>(3 * I + c)], G(I, c), 1e-10 * G.cwiseAbs().maxCoeff());
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
  for (int I = 0; I < data.size(); ++I) err = std::max(err, (pts[static_cast<size_t>(I)] - P.row(I).transpose()).cwiseAbs().maxCoeff());
  EXPECT_LE(err, 1e-7) << summary.BriefReport();
  // the pin really pulls: the answer is not the plain extremal
  const ExtremalResult plain = solve_extremal(data, e, FixedSet::Boundary);
  EXPECT_GT((plain.net.points() - P).cwiseAbs().maxCoeff(), 1e-2);
}

}  // namespace
}  // namespace bpde
