#pragma once
// Products of #rows x 3 matrices (points, derivatives or weights at quadrature nodes, one x, y, z
// column each) that the exact Bernstein integrals (energies/volume.cpp), the area quadrature
// (energies/area_functional.cpp) and the mean-curvature residuals
// (energies/mean_curvature_least_squares.cpp) share.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

namespace bpde {

/// Row-wise cross products of two #nodes x 3 matrices: row r is a.row(r) x b.row(r).
inline void cross_rows_into(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b, Eigen::MatrixX3d& c) {
  c.resize(a.rows(), 3);  // no allocation when c already has a's size (c must not be a or b)
  c.col(0) = a.col(1).cwiseProduct(b.col(2)) - a.col(2).cwiseProduct(b.col(1));
  c.col(1) = a.col(2).cwiseProduct(b.col(0)) - a.col(0).cwiseProduct(b.col(2));
  c.col(2) = a.col(0).cwiseProduct(b.col(1)) - a.col(1).cwiseProduct(b.col(0));
}
inline Eigen::MatrixX3d cross_rows(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  Eigen::MatrixX3d c;
  cross_rows_into(a, b, c);
  return c;
}

/// A * P for a #cols(A) x 3 matrix P, as three matrix-vector products (no GEMM packing of the
/// large A).
inline Eigen::MatrixX3d times(const Eigen::MatrixXd& A, const Eigen::MatrixX3d& P) {
  Eigen::MatrixX3d out(A.rows(), 3);
  for (int c = 0; c < 3; ++c) out.col(c).noalias() = A * P.col(c);
  return out;
}

/// A^T * W for a #rows(A) x 3 matrix W.
inline Eigen::MatrixX3d times_t(const Eigen::MatrixXd& A, const Eigen::MatrixX3d& W) {
  Eigen::MatrixX3d out(A.cols(), 3);
  for (int c = 0; c < 3; ++c) out.col(c).noalias() = A.transpose() * W.col(c);
  return out;
}

}  // namespace bpde
