#include "bezierpde/energies/quadratic_energy.h"

#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/tensor_gram.h"

namespace bpde {

QuadraticEnergy::QuadraticEnergy(Eigen::MatrixXd Q) : Q_(std::move(Q)) {
  if (Q_.rows() != Q_.cols())
    throw SizeError("QuadraticEnergy: Gram matrix is " + std::to_string(Q_.rows()) + " x " + std::to_string(Q_.cols()) +
                    ", not square");
  if (!Q_.allFinite()) throw NonFiniteError("QuadraticEnergy: Gram matrix has a non-finite entry");
}

QuadraticEnergy QuadraticEnergy::tensor(const EnergySpec& energy, int n, int m) {
  return QuadraticEnergy(tensor_gram(energy, n, m));
}

void QuadraticEnergy::check(const Eigen::MatrixX3d& P) const {
  if (P.rows() != Q_.rows())
    throw SizeError("QuadraticEnergy: " + std::to_string(P.rows()) + " points for an energy of " +
                    std::to_string(Q_.rows()) + " control points");
}

double QuadraticEnergy::value(const Eigen::MatrixX3d& P) const {
  check(P);
  return 0.5 * P.cwiseProduct(Q_ * P).sum();
}

Eigen::MatrixX3d QuadraticEnergy::gradient(const Eigen::MatrixX3d& P) const {
  check(P);
  return Q_ * P;
}

Eigen::MatrixXd QuadraticEnergy::full_hessian() const {
  const Eigen::Index N = Q_.rows();
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(3 * N, 3 * N);
  for (Eigen::Index J = 0; J < N; ++J)
    for (Eigen::Index I = 0; I < N; ++I)
      for (int c = 0; c < 3; ++c) H(3 * I + c, 3 * J + c) = Q_(I, J);
  return H;
}

double energy_value(const TensorNet& net, const EnergySpec& energy) {
  return QuadraticEnergy::tensor(energy, net.n(), net.m()).value(net.points());
}

Eigen::MatrixX3d energy_gradient(const TensorNet& net, const EnergySpec& energy) {
  return QuadraticEnergy::tensor(energy, net.n(), net.m()).gradient(net.points());
}

}  // namespace bpde
