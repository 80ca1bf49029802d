#pragma once
// A += Jᵀ J (the lower triangle, selfadjointView<Lower>) for a tall dense J, by blocks of
// kGramRows rows of J.
//
//   J: #rows by k, a matrix or a block of one (direct access: an expression such as a product
//      would be evaluated again for every block); A: k by k (SizeError otherwise).
//
// The normal matrix JᵀJ of the library's Levenberg–Marquardt loop (solvers/optim/levenberg_marquardt.cpp:
// the mean-curvature functional, whose Jacobian is #nodes by 3·#free, and the area soft-mode
// phase) is such a sum.
//
// Why by blocks: one Eigen rank update over all rows sizes its packing buffers by the depth (the
// rows of J) and the cache sizes Eigen reads at run time (on the build machine an L3 of 508 MiB,
// so nothing caps them), and takes buffers above Eigen's 128 KB stack limit from the heap on every
// call. Whether glibc then maps fresh pages for them depends on its dynamic thresholds, i.e. on
// the process's allocation history, and on this VM every page fault costs several µs
// (docs/performance_measurements.md, "Design decisions"). Blocks of 64 rows keep the buffers small. Measured (random J,
// CPU time per call, one run, glibc's defaults; then with the thresholds the CLI sets):
//
//   J          one product   by 64 rows   (CLI thresholds: one product, by 64 rows)
//   243 × 243  2.28 ms       0.27 ms      (0.28, 0.27)   square, as the soft-mode phase's reduced system
//   363 × 363  6.62 ms       0.87 ms      (0.95, 0.89)
//   500 × 500  13.8 ms       2.27 ms      (2.86, 2.17)
//   648 × 243  0.77 … 9.6 ms 0.69 ms      (0.73, 0.73)   the mean-curvature Jacobian, tensor n = 10
//   2400 × 363 6.7 … 23.7 ms 5.67 ms      (7.69, 5.89)
//
// (the spread of one product across runs is the allocation history). Blocks of 128 rows were as
// slow as one product at 243 × 243; blocks of 16384/k rows (the packing buffer under the stack
// limit) were up to 20 % slower than 64 at k = 500. The area Hessian's RᵀR (blocks of up to 16384
// rows by 3·#free) was measured by blocks too and kept as one product: by 64 rows (with its three
// cross products) a Hessian call was 1.8–1.9x faster at triangular n = 10, q = 20, 1.2x slower at
// tensor n = 12, q = 30 and level at two others; by 128 rows the area solves did not change
// (docs/performance_measurements.md, "Design decisions").
//
// The sum is over the same terms in another order, so A differs from the one-product value by
// rounding only.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <string>

#include "bezierpde/core/errors.h"

namespace bpde {

inline constexpr Eigen::Index kGramRows = 64;

template <class Derived>
void add_gram_lower(Eigen::MatrixXd& A, const Eigen::MatrixBase<Derived>& J) {
  if (A.rows() != J.cols() || A.cols() != J.cols())
    throw SizeError("add_gram_lower: A is " + std::to_string(A.rows()) + " by " + std::to_string(A.cols()) +
                    " for a J with " + std::to_string(J.cols()) + " columns");
  for (Eigen::Index s = 0; s < J.rows(); s += kGramRows) {
    const Eigen::Index b = std::min(kGramRows, J.rows() - s);
    A.selfadjointView<Eigen::Lower>().rankUpdate(J.middleRows(s, b).transpose());
  }
}

}  // namespace bpde
