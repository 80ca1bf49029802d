// core/binomial: Pascal's triangle in double, long double and binary128 against exact integers
// (a small big-integer Pascal triangle), the exactness and error bounds of the header, the
// lazily built table equal to an eager one, and concurrent first use.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

#include "bezierpde/core/binomial.h"
#include "bezierpde/core/errors.h"

using namespace bpde;

namespace {

// Non-negative integers as little-endian base-2^32 limbs.
using Big = std::vector<std::uint32_t>;

Big add(const Big& a, const Big& b) {
  Big r(std::max(a.size(), b.size()) + 1, 0);
  std::uint64_t carry = 0;
  for (size_t i = 0; i < r.size(); ++i) {
    const std::uint64_t s = carry + (i < a.size() ? a[i] : 0u) + (i < b.size() ? b[i] : 0u);
    r[i] = static_cast<std::uint32_t>(s);
    carry = s >> 32;
  }
  while (r.size() > 1 && r.back() == 0) r.pop_back();
  return r;
}

int bits(const Big& a) {
  int b = 32 * static_cast<int>(a.size() - 1);
  for (std::uint32_t top = a.back(); top; top >>= 1) ++b;
  return b;
}

// Horner from the top limb in binary128: exact while the value fits 113 bits, else within
// (#limbs) units of 2^-113 relative.
quad to_quad(const Big& a) {
  quad v = 0;
  for (size_t i = a.size(); i-- > 0;) v = v * quad(4294967296.0) + quad(a[i]);
  return v;
}

// Exact rows 0..N of Pascal's triangle.
const std::vector<std::vector<Big>>& exact_rows() {
  static const std::vector<std::vector<Big>> rows = [] {
    std::vector<std::vector<Big>> r(kMaxBinomialRow + 1);
    r[0] = {Big{1}};
    for (int n = 1; n <= kMaxBinomialRow; ++n) {
      r[n].resize(static_cast<size_t>(n) + 1);
      r[n][0] = r[n][static_cast<size_t>(n)] = Big{1};
      for (int k = 1; k < n; ++k)
        r[n][static_cast<size_t>(k)] = add(r[n - 1][static_cast<size_t>(k - 1)], r[n - 1][static_cast<size_t>(k)]);
    }
    return r;
  }();
  return rows;
}

template <class T>
void check_against_exact(int digits, int nmax) {
  const auto& ex = exact_rows();
  int exact_checked = 0;
  for (int n = 0; n <= nmax; ++n)
    for (int k = 0; k <= n; ++k) {
      const Big& e = ex[static_cast<size_t>(n)][static_cast<size_t>(k)];
      const quad truth = to_quad(e);
      const quad got = static_cast<quad>(binomial<T>(n, k));
      if (bits(e) <= digits) {
        ASSERT_TRUE(got == truth) << "C(" << n << ", " << k << ") must be exact in " << digits << " bits";
        ++exact_checked;
      } else {
        // n units in the last place of T, plus the rounding of the truth to binary128.
        const double rel = static_cast<double>((got > truth ? got - truth : truth - got) / truth);
        ASSERT_LE(rel, (n + 1) * std::ldexp(1.0, -digits) + 64 * std::ldexp(1.0, -112)) << n << ' ' << k;
      }
    }
  EXPECT_GT(exact_checked, 0);
}

TEST(Binomial, DoubleAgainstExactIntegers) { check_against_exact<double>(53, kMaxBinomialRow); }
TEST(Binomial, LongDoubleAgainstExactIntegers) { check_against_exact<long double>(64, kMaxBinomialRow); }
TEST(Binomial, Binary128AgainstExactIntegers) { check_against_exact<quad>(113, 300); }

TEST(Binomial, WholeRowsExactUpToTheStatedDegrees) {
  // The header's claim: every C(n, k) exact for n <= 56 (double), 67 (long double), 116 (quad).
  const auto& ex = exact_rows();
  for (int k = 0; k <= 56; ++k)
    EXPECT_TRUE(static_cast<quad>(binomial<double>(56, k)) == to_quad(ex[56][static_cast<size_t>(k)]));
  for (int k = 0; k <= 67; ++k)
    EXPECT_TRUE(static_cast<quad>(binomial<long double>(67, k)) == to_quad(ex[67][static_cast<size_t>(k)]));
  for (int k = 0; k <= 116; ++k) EXPECT_TRUE(binomial<quad>(116, k) == to_quad(ex[116][static_cast<size_t>(k)]));
  EXPECT_GT(bits(ex[57][28]), 53);
  EXPECT_GT(bits(ex[68][34]), 64);
  EXPECT_GT(bits(ex[117][58]), 113);
  EXPECT_EQ(binomial(56, 28), 7648690600760440.0);
  EXPECT_EQ(binomial<long double>(67, 33), 14226520737620288370.0L);
}

TEST(Binomial, SameBitsAsAnEagerDoubleTable) {
  // The former eager 1025 x 1025 table (positive additions in double): the lazy rows are the
  // same numbers to the bit, also where they are rounded.
  std::vector<double> prev{1.0}, row;
  for (int n = 1; n <= kMaxBinomialRow; ++n) {
    row.assign(static_cast<size_t>(n) + 1, 0.0);
    row[0] = 1.0;
    for (int k = 1; k <= n; ++k)
      row[static_cast<size_t>(k)] =
          prev[static_cast<size_t>(k - 1)] + (k <= n - 1 ? prev[static_cast<size_t>(k)] : 0.0);
    for (int k = 0; k <= n; ++k) ASSERT_EQ(binomial(n, k), row[static_cast<size_t>(k)]) << n << ' ' << k;
    prev.swap(row);
  }
}

TEST(Binomial, OutsideTheTriangleAndRange) {
  EXPECT_EQ(binomial(5, 6), 0.0);
  EXPECT_EQ(binomial(5, -1), 0.0);
  EXPECT_EQ(binomial(-1, 0), 0.0);
  EXPECT_EQ(binomial<long double>(3, 4), 0.0L);
  EXPECT_TRUE(binomial<quad>(3, -2) == 0);
  EXPECT_EQ(binomial(kMaxBinomialRow, 0), 1.0);
  EXPECT_THROW(binomial(kMaxBinomialRow + 1, 1), DegreeError);
  EXPECT_THROW(binomial<long double>(kMaxBinomialRow + 1, 1), DegreeError);
}

TEST(Binomial, MultinomialAndFactorial) {
  EXPECT_EQ(multinomial(4, 2, 1), 12.0);  // 4! / (2! 1! 1!)
  EXPECT_EQ(multinomial(6, 0, 0), 1.0);
  for (int n = 0; n <= 20; ++n) {
    double sum = 0;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n - i; ++j) sum += multinomial(n, i, j);
    EXPECT_EQ(sum, std::pow(3.0, n)) << n;  // (1 + 1 + 1)^n
  }
  EXPECT_EQ(multinomial<long double>(30, 10, 10), 5550996791340.0L);
  EXPECT_EQ(factorial(10), 3628800.0);
  EXPECT_EQ(factorial(-1), 1.0);
  EXPECT_EQ(factorial(171), std::numeric_limits<double>::infinity());
}

TEST(Binomial, ConcurrentFirstUse) {
  // Threads reach for far rows of a fresh scalar type's table at once (long double and quad are
  // first used here by at most this test and the ones above; the answers must not depend on it).
  const auto& ex = exact_rows();
  std::vector<std::thread> threads;
  std::vector<int> wrong(8, 0);
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&, t] {
      for (int n = 1000 - 37 * t; n >= 0; n -= 53) {
        const int k = n / 3;
        const quad truth = to_quad(ex[static_cast<size_t>(n)][static_cast<size_t>(k)]);
        const quad got = binomial<quad>(n, k);
        if (!((got > truth ? got - truth : truth - got) <= truth * quad((n + 1) * std::ldexp(1.0, -112))))
          ++wrong[static_cast<size_t>(t)];
      }
    });
  for (auto& th : threads) th.join();
  for (int w : wrong) EXPECT_EQ(w, 0);
}

}  // namespace
