#pragma once
// Small helpers shared by solvers/bspline/bspline_pde.cpp and bspline_extremal.cpp (internal):
// index sets, gathers and scatters, and timing.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/fixed_set.h"
#include "bezierpde/solvers/summary.h"

namespace bpde::detail {

/// Validates `fixed` (strictly increasing indices in 0..N-1: ParameterError / SizeError) and
/// returns its complement in 0..N-1, increasing.
inline std::vector<int> complement_indices(int N, const std::vector<int>& fixed, const std::string& who) {
  for (size_t k = 0; k < fixed.size(); ++k) {
    if (fixed[k] < 0 || fixed[k] >= N)
      throw SizeError(who + ": fixed index " + std::to_string(fixed[k]) + " is outside 0.." + std::to_string(N - 1));
    if (k > 0 && fixed[k] <= fixed[k - 1])
      throw ParameterError(who + ": fixed indices must be strictly increasing (index " + std::to_string(k) + ")");
  }
  return bpde::complement_indices(fixed, N);
}

/// A(rows, cols) of a sparse matrix.
inline Eigen::SparseMatrix<double> sparse_submatrix(const Eigen::SparseMatrix<double>& A, const std::vector<int>& rows,
                                                    const std::vector<int>& cols) {
  std::vector<int> rmap(static_cast<size_t>(A.rows()), -1), cmap(static_cast<size_t>(A.cols()), -1);
  for (size_t k = 0; k < rows.size(); ++k) rmap[static_cast<size_t>(rows[k])] = static_cast<int>(k);
  for (size_t k = 0; k < cols.size(); ++k) cmap[static_cast<size_t>(cols[k])] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double>> t;
  for (int c = 0; c < A.outerSize(); ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, c); it; ++it) {
      const int r = rmap[static_cast<size_t>(it.row())], cc = cmap[static_cast<size_t>(it.col())];
      if (r >= 0 && cc >= 0) t.emplace_back(r, cc, it.value());
    }
  Eigen::SparseMatrix<double> S(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(cols.size()));
  S.setFromTriplets(t.begin(), t.end());
  return S;
}

inline Eigen::MatrixXd gather_rows(const Eigen::MatrixX3d& P, const std::vector<int>& idx) {
  return P(idx, Eigen::all);
}

inline void scatter_rows(Eigen::MatrixX3d& P, const std::vector<int>& idx, const Eigen::MatrixXd& X) {
  P(idx, Eigen::all) = X;
}

/// Columns idx of a dense matrix.
inline Eigen::MatrixXd gather_cols(const Eigen::MatrixXd& A, const std::vector<int>& idx) { return A(Eigen::all, idx); }

}  // namespace bpde::detail
