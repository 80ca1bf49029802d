// core/gram: A += JᵀJ by row blocks against the sum of outer products of the rows, in long double.
#include <gtest/gtest.h>

#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cstdlib>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/gram.h"

using namespace bpde;

namespace {

// Row counts on both sides of the block size (a partial last block, exactly one and two blocks,
// none), on a row block of a larger matrix (a block expression) and on a plain matrix (what the
// Levenberg–Marquardt loop passes).
TEST(Gram, AddsTheLowerTriangleOfJtJOverEveryRowCount) {
  std::srand(3);
  for (Eigen::Index rows : {Eigen::Index(0), Eigen::Index(1), kGramRows - 1, kGramRows, kGramRows + 1, 2 * kGramRows,
                            5 * kGramRows + 17})
    for (Eigen::Index k : {1, 7, 40}) {
      const Eigen::MatrixXd big = Eigen::MatrixXd::Random(rows + 3, k);
      const auto J = big.middleRows(2, rows);
      Eigen::MatrixXd A = Eigen::MatrixXd::Constant(k, k, 0.25);  // the sum is added to what A holds
      add_gram_lower(A, J);
      Eigen::MatrixXd Aplain = Eigen::MatrixXd::Constant(k, k, 0.25);
      add_gram_lower(Aplain, Eigen::MatrixXd(J));
      EXPECT_EQ(A, Aplain) << "rows " << rows << ", k " << k;
      for (Eigen::Index i = 0; i < k; ++i)
        for (Eigen::Index j = 0; j < k; ++j) {
          if (j > i) {  // the strict upper triangle is not touched
            EXPECT_EQ(A(i, j), 0.25);
            continue;
          }
          long double s = 0.25L;
          for (Eigen::Index r = 0; r < rows; ++r) s += static_cast<long double>(J(r, i)) * J(r, j);
          EXPECT_NEAR(A(i, j), static_cast<double>(s), 1e-13 * (1.0 + double(rows)))
              << "rows " << rows << ", k " << k << ", entry (" << i << ", " << j << ")";
        }
    }
}

TEST(Gram, ASumOfTheWrongSizeIsASizeError) {
  const Eigen::MatrixXd J = Eigen::MatrixXd::Ones(5, 3);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(3, 4);
  EXPECT_THROW(add_gram_lower(A, J), SizeError);
  A = Eigen::MatrixXd::Zero(2, 2);
  EXPECT_THROW(add_gram_lower(A, J), SizeError);
  EXPECT_EQ(A, Eigen::MatrixXd::Zero(2, 2));  // left as it was
}

}  // namespace
