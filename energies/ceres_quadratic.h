#pragma once
// A quadratic energy E(P) = 1/2 Σ_c P_c^T Q P_c (energies/quadratic_energy.h) as a Ceres residual
// block, so that Ceres can minimise it together with non-quadratic terms.
//
// Q is symmetric positive semidefinite (every energy of FORMATS.md except non-elliptic
// fourth-order/second-order coefficient choices). It is factored once as Q = R^T R with
// R = diag(sqrt(λ_k)) V_k^T from its eigen-decomposition, keeping the eigenvalues λ_k above
// rank_tolerance * λ_max (r rows, r = numerical rank). The residual vector is
//     r[3k + c] = (R P_c)_k,    k = 0..r-1, c = x, y, z,
// so Ceres's cost of the block, 1/2 |r|^2 = 1/2 Σ_c |R P_c|^2, EQUALS the energy E(P) (no factor
// 2 to add when mixing with other terms). Parameter blocks: one block of 3 doubles (x, y, z) per
// control point, N blocks in point order; hold prescribed points with
// problem.SetParameterBlockConstant.
#include <ceres/ceres.h>

#include <Eigen/Core>
#include <vector>

namespace bpde {

/// R (r x N) with R^T R = Q up to the dropped eigenvalues below rank_tolerance * λ_max. Throws
/// SizeError (not square), NonFiniteError, ParameterError if Q has an eigenvalue below
/// -negative_tolerance * λ_max (Q indefinite: the energy is not a sum of squares).
Eigen::MatrixXd psd_factor(const Eigen::MatrixXd& Q, double rank_tolerance = 1e-14,
                           double negative_tolerance = 1e-10);

class QuadraticEnergyCost : public ceres::CostFunction {
 public:
  /// From a factor R (r x N), see psd_factor.
  explicit QuadraticEnergyCost(Eigen::MatrixXd R);
  /// From the Gram matrix Q (N x N) through psd_factor.
  static QuadraticEnergyCost* from_gram(const Eigen::MatrixXd& Q);

  int points() const { return static_cast<int>(R_.cols()); }
  const Eigen::MatrixXd& factor() const { return R_; }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override;

 private:
  Eigen::MatrixXd R_;
};

/// Adds the energy of Q to `problem`; blocks[I] points to the 3 doubles of control point I
/// (blocks.size() == Q.rows(), SizeError otherwise). Ceres takes ownership of the cost function.
ceres::ResidualBlockId add_quadratic_energy(ceres::Problem& problem, const Eigen::MatrixXd& Q,
                                            const std::vector<double*>& blocks);

}  // namespace bpde
