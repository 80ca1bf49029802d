#include <gtest/gtest.h>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/quadratic_energy.h"
#include "bezierpde/energies/tensor_gram.h"
#include "tests/random_points.h"

namespace bpde {
namespace {

using testing::random_points;

TEST(QuadraticEnergy, GradientMatchesCentralDifferences) {
  for (const auto& e :
       {EnergySpec::dirichlet(), EnergySpec::laplacian_squared(), EnergySpec::fourth_order({1, 0.4, 2, -0.3, 1.5})}) {
    const int n = 4, m = 3;
    const QuadraticEnergy E = QuadraticEnergy::tensor(e, n, m);
    const Eigen::MatrixX3d P = random_points(E.size(), 7);
    const Eigen::MatrixX3d G = E.gradient(P);
    const double h = 1e-3;
    double err = 0, scale = G.cwiseAbs().maxCoeff();
    for (int I = 0; I < E.size(); ++I)
      for (int c = 0; c < 3; ++c) {
        Eigen::MatrixX3d Pp = P, Pm = P;
        Pp(I, c) += h;
        Pm(I, c) -= h;
        err = std::max(err, std::abs((E.value(Pp) - E.value(Pm)) / (2 * h) - G(I, c)));
      }
    EXPECT_LE(err, 1e-9 * scale) << e.name();
  }
}

TEST(QuadraticEnergy, HessianIsTheGramPerCoordinate) {
  const QuadraticEnergy E = QuadraticEnergy::tensor(EnergySpec::biharmonic(), 3, 3);
  const Eigen::MatrixX3d P = random_points(E.size(), 3);
  const Eigen::MatrixXd H = E.full_hessian();
  Eigen::VectorXd x(3 * E.size());
  for (int I = 0; I < E.size(); ++I) x.segment<3>(3 * I) = P.row(I).transpose();
  EXPECT_NEAR(0.5 * x.dot(H * x), E.value(P), 1e-12 * E.value(P));
  // d/dt gradient(P + t D) = Q D
  const Eigen::MatrixX3d D = random_points(E.size(), 4);
  const Eigen::MatrixX3d dG = (E.gradient(P + 1e-3 * D) - E.gradient(P - 1e-3 * D)) / 2e-3;
  EXPECT_LE((dG - E.hessian() * D).cwiseAbs().maxCoeff(), 1e-9 * dG.cwiseAbs().maxCoeff());
}

TEST(QuadraticEnergy, TensorNetConvenienceAndErrors) {
  TensorNet net(3, 2, random_points(12, 5));
  EXPECT_NEAR(energy_value(net, EnergySpec::coons()),
              QuadraticEnergy(tensor_gram(EnergySpec::coons(), 3, 2)).value(net.points()), 1e-14);
  EXPECT_EQ(energy_gradient(net, EnergySpec::coons()).rows(), 12);
  const QuadraticEnergy E = QuadraticEnergy::tensor(EnergySpec::coons(), 3, 3);
  EXPECT_THROW(E.value(random_points(12, 1)), SizeError);
  EXPECT_THROW(QuadraticEnergy(Eigen::MatrixXd::Zero(3, 4)), SizeError);
  Eigen::MatrixXd bad = Eigen::MatrixXd::Zero(2, 2);
  bad(0, 1) = std::nan("");
  EXPECT_THROW(QuadraticEnergy{bad}, NonFiniteError);
}

}  // namespace
}  // namespace bpde
