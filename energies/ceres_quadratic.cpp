#include "energies/ceres_quadratic.h"

#include <Eigen/Eigenvalues>
#include <sstream>
#include <string>

#include "core/errors.h"

namespace bpde {

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

}  // namespace bpde
