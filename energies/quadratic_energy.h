#pragma once
// Value, gradient and Hessian of a quadratic energy E(P) = 1/2 Σ_{c=x,y,z} P_c^T Q P_c of a net.
//
// P is the N x 3 point matrix of a net (FORMATS.md order; for tensor nets row i*(m+1)+j), P_c its
// column c, Q the N x N Gram matrix (energies/tensor_gram.h for tensor nets; any symmetric Q for
// other nets). The energy is the same in every coordinate, so
//   gradient  ∂E/∂P = Q P                         (N x 3, row I = ∂E/∂P_I),
//   Hessian   ∂²E/∂P_{I,c}∂P_{J,d} = Q[I,J] δ_cd  (per coordinate Q; on the point-major vector
//             (P_0x, P_0y, P_0z, P_1x, ...) it is kron(Q, I_3), see full_hessian()).
// The energies are those of FORMATS.md ("ENERGY"); Arnal–Monterde–Ugail eq. (1) (gnorm),
// Sun–Zhu (fourth order); docs/errata.md, explicit PDE solutions §2 (laplacian-squared vs biharmonic).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

class QuadraticEnergy {
 public:
  /// From a symmetric N x N Gram matrix (SizeError if not square, NonFiniteError if it has a
  /// non-finite entry). Symmetry is the caller's contract (tensor_gram returns exactly symmetric Q).
  explicit QuadraticEnergy(Eigen::MatrixXd Q);
  /// The energy of degree-(n,m) tensor nets (tensor_gram(energy, n, m)).
  static QuadraticEnergy tensor(const EnergySpec& energy, int n, int m);

  int size() const { return static_cast<int>(Q_.rows()); }
  /// 1/2 Σ_c P_c^T Q P_c. P: size() x 3 (SizeError otherwise).
  double value(const Eigen::MatrixX3d& P) const;
  /// Q P (size() x 3).
  Eigen::MatrixX3d gradient(const Eigen::MatrixX3d& P) const;
  /// Per-coordinate Hessian Q (size() x size()).
  const Eigen::MatrixXd& hessian() const { return Q_; }
  /// Hessian on the point-major 3N vector: kron(Q, I_3).
  Eigen::MatrixXd full_hessian() const;

 private:
  void check(const Eigen::MatrixX3d& P) const;
  Eigen::MatrixXd Q_;
};

/// Convenience for one tensor net (assembles the Gram matrix each call; keep a QuadraticEnergy
/// to evaluate many nets of the same degree).
double energy_value(const TensorNet& net, const EnergySpec& energy);
Eigen::MatrixX3d energy_gradient(const TensorNet& net, const EnergySpec& energy);

}  // namespace bpde
