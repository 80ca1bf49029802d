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

/// X = A * P for a #cols(A) x 3 matrix P in one pass over A (any dense column-major block): each
/// column of A is read once and added to the three columns of X. For the tall blocks of basis
/// tables at quadrature nodes (rows: nodes, columns: control points), where a GEMM spends more
/// time packing A than multiplying by P's three columns. X has A's rows.
template <class Matrix, class Out>
inline void times_into(const Matrix& A, const Eigen::MatrixX3d& P, Out&& X) {
  X.setZero();
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    const auto a = A.col(j);
    X.col(0) += P(j, 0) * a;
    X.col(1) += P(j, 1) * a;
    X.col(2) += P(j, 2) * a;
  }
}

/// X = A * P and Y = A * Q in the same single pass over A (two point sets on one table: x_u and
/// x_v of a triangular net share their basis table).
template <class Matrix, class Out>
inline void times_into(const Matrix& A, const Eigen::MatrixX3d& P, const Eigen::MatrixX3d& Q, Out&& X, Out&& Y) {
  X.setZero();
  Y.setZero();
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    const auto a = A.col(j);
    for (int c = 0; c < 3; ++c) {
      X.col(c) += P(j, c) * a;
      Y.col(c) += Q(j, c) * a;
    }
  }
}

/// A^T * W for a #rows(A) x 3 matrix W.
inline Eigen::MatrixX3d times_t(const Eigen::MatrixXd& A, const Eigen::MatrixX3d& W) {
  Eigen::MatrixX3d out(A.cols(), 3);
  for (int c = 0; c < 3; ++c) out.col(c).noalias() = A.transpose() * W.col(c);
  return out;
}

}  // namespace bpde
