// core/row_major_product: the grid-evaluation kernel against a plain triple loop in long double.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/core/row_major_product.h"

using namespace bpde;

namespace {

// Shapes that hit every path: a single row (32-column blocks), row pairs (24-column blocks), the
// three-row block of odd row counts (16-column blocks), 4-column blocks
// and the 1-3 masked columns, strides larger than the width, and empty products.
TEST(RowMajorProduct, MatchesTheDefinitionOnEveryShape) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  for (int r : {0, 1, 2, 3, 4, 5, 7, 50})
    for (int k : {0, 1, 5, 21})
      for (int w : {0, 1, 2, 3, 4, 5, 15, 16, 17, 23, 24, 25, 27, 31, 32, 35, 50, 51}) {
        const int lda = k + 2, ldb = w + 3, ldc = w + 1;
        std::vector<double> A(static_cast<size_t>(r * lda + 1)), B(static_cast<size_t>(k * ldb + 1));
        for (double& x : A) x = U(rng);
        for (double& x : B) x = U(rng);
        std::vector<double> C(static_cast<size_t>(r * ldc + 1), 12345.0);  // sentinel beyond the rows
        row_major_product(A.data(), r, k, lda, B.data(), w, ldb, C.data(), ldc);
        for (int a = 0; a < r; ++a) {
          for (int b = 0; b < w; ++b) {
            long double s = 0;
            for (int i = 0; i < k; ++i)
              s += static_cast<long double>(A[static_cast<size_t>(a * lda + i)]) * B[static_cast<size_t>(i * ldb + b)];
            EXPECT_NEAR(C[static_cast<size_t>(a * ldc + b)], static_cast<double>(s), 1e-14 * (k + 1))
                << r << "x" << k << "x" << w << " at (" << a << ", " << b << ")";
          }
          // Padding between rows (ldc > w) is not written.
          EXPECT_EQ(C[static_cast<size_t>(a * ldc + w)], 12345.0) << r << "x" << k << "x" << w;
        }
      }
}

TEST(RowMajorProduct, ZeroInnerDimensionGivesZero) {
  std::vector<double> C(6, 1.0);
  row_major_product(nullptr, 2, 0, 0, nullptr, 3, 3, C.data(), 3);
  for (double c : C) EXPECT_EQ(c, 0.0);
}

TEST(RowMajorProduct, RejectsInconsistentSizes) {
  std::vector<double> A(6), B(6), C(6);
  EXPECT_THROW(row_major_product(A.data(), -1, 2, 2, B.data(), 3, 3, C.data(), 3), SizeError);
  EXPECT_THROW(row_major_product(A.data(), 2, 3, 2, B.data(), 2, 2, C.data(), 2), SizeError);  // lda < k
  EXPECT_THROW(row_major_product(A.data(), 2, 2, 2, B.data(), 3, 2, C.data(), 3), SizeError);  // ldb < w
  EXPECT_THROW(row_major_product(A.data(), 2, 2, 2, B.data(), 3, 3, C.data(), 2), SizeError);  // ldc < w
}

}  // namespace
