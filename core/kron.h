#pragma once
// Kronecker product of dense matrices, in the row-major layout of tensor nets:
// (A kron B) vec_r(X) = vec_r(A X B^T), with vec_r stacking the rows of X (row i*(m+1)+j of a
// tensor net's points is X(i, j)).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

namespace bpde {

inline Eigen::MatrixXd kron(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  Eigen::MatrixXd K(A.rows() * B.rows(), A.cols() * B.cols());
  for (Eigen::Index i = 0; i < A.rows(); ++i)
    for (Eigen::Index j = 0; j < A.cols(); ++j) K.block(i * B.rows(), j * B.cols(), B.rows(), B.cols()) = A(i, j) * B;
  return K;
}

}  // namespace bpde
