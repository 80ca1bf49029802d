#pragma once
// SymmetricFactor<Scalar>: factorisation of a dense symmetric matrix with a positive-definite
// verdict that is robust against rounding. Used by the extremal solver (solvers/extremal.cpp) and
// the CMC solvers (solvers/cmc/).
//
//   1. Cholesky (Eigen::LLT, blocked). It counts as succeeded when Eigen reports success and the
//      factor is finite (a NaN entry passes Eigen's pivot test);
//   2. otherwise a pivoted LDL^T (Eigen::LDLT) of the same matrix.
// Verdict (positive_definite()): the Cholesky succeeded, or the LDL^T succeeded, its largest
// |pivot| is > 0 and every pivot is >= -pivot_tolerance * max |pivot| (so a semidefinite matrix
// whose smallest eigenvalues are rounding noise counts as positive definite; the Bernstein Grams
// reach that regime from degree ~18 on tensor nets, ~26 on triangular nets).
// rcond() is Eigen's 1-norm reciprocal condition estimate of the Cholesky factor (0 when the
// Cholesky failed): callers that need a numerically regular matrix compare it with a tolerance.
// solve() uses whichever factorisation was kept. Scalar: double or long double.
// No exceptions (a failed factorisation is a verdict, not an error); an empty matrix is positive
// definite.
#include "bezierpde/core/eigen.h"
#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace bpde {

template <class Scalar = double>
class SymmetricFactor {
 public:
  using Matrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  SymmetricFactor() = default;
  /// Factors the symmetric A (only its lower triangle is read).
  explicit SymmetricFactor(const Matrix& A, Scalar pivot_tolerance = Scalar(1e-10)) { compute(A, pivot_tolerance); }

  void compute(const Matrix& A, Scalar pivot_tolerance = Scalar(1e-10)) {
    llt_.compute(A);
    cholesky_ = llt_.info() == Eigen::Success && llt_.matrixLLT().diagonal().allFinite();
    if (cholesky_) {  // ldlt_ is not used
      positive_definite_ = true;
      return;
    }
    ldlt_.compute(A);
    const auto d = ldlt_.vectorD();
    const Scalar mx = d.size() ? d.cwiseAbs().maxCoeff() : Scalar(0);
    positive_definite_ = ldlt_.info() == Eigen::Success && mx > 0 && d.minCoeff() >= -pivot_tolerance * mx;
  }

  /// The Cholesky factorisation succeeded (finite factor).
  bool cholesky() const { return cholesky_; }
  /// The verdict described above.
  bool positive_definite() const { return positive_definite_; }
  /// Reciprocal condition estimate (1-norm) from the Cholesky factor; 0 when it failed.
  Scalar rcond() const { return cholesky_ ? Scalar(llt_.rcond()) : Scalar(0); }
  /// Smallest pivot: of the LDL^T when the Cholesky failed, else the smallest squared diagonal
  /// entry of the Cholesky factor. 0 for an empty matrix.
  Scalar min_pivot() const {
    if (cholesky_) return llt_.matrixLLT().rows() ? llt_.matrixLLT().diagonal().cwiseAbs2().minCoeff() : Scalar(0);
    return ldlt_.vectorD().size() ? ldlt_.vectorD().minCoeff() : Scalar(0);
  }
  /// A^{-1} b through the kept factorisation.
  template <class Rhs>
  Matrix solve(const Rhs& b) const {
    return cholesky_ ? Matrix(llt_.solve(b)) : Matrix(ldlt_.solve(b));
  }
  /// The lower Cholesky factor L (A = L L^T); meaningful only when cholesky().
  Matrix matrixL() const { return llt_.matrixL(); }
  /// The Cholesky factorisation itself (for products with L or L^T); meaningful when cholesky().
  const Eigen::LLT<Matrix>& llt() const { return llt_; }

 private:
  Eigen::LLT<Matrix> llt_;
  Eigen::LDLT<Matrix> ldlt_;
  bool cholesky_ = false, positive_definite_ = false;
};

}  // namespace bpde
