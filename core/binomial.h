#pragma once
// Binomial and multinomial coefficients and factorials: the one implementation, in each scalar
// the library computes with (double, long double, binary128 `quad` of core/scalar_types.h).
//
// binomial<T>(n, k) is Pascal's triangle in T, built lazily (rows 0..n on first use of row n,
// thread-safe, kept for the life of the process). Every entry is a sum of two positive numbers,
// so:
//   - it is exact whenever C(n, k) < 2^p (p = mantissa bits: 53 double, 64 long double, 113
//     binary128), e.g. for every k when n <= 56 (double), n <= 67 (long double), n <= 116
//     (binary128);
//   - beyond, its relative error is below n units in the last place (no cancellation).
// Values for the same (n, k) and T are always the same bits.
//
// Errors: DegreeError for n > kMaxBinomialRow. Out of the triangle (n < 0, k < 0 or k > n) the
// value is 0.
#include "bezierpde/core/scalar_types.h"

namespace bpde {

/// Largest row of Pascal's triangle served (C(1024, 512) ~ 4.5e306 still fits a double).
inline constexpr int kMaxBinomialRow = 1024;

/// C(n, k) in T (double, long double or quad); 0 outside 0 <= k <= n.
template <class T = double>
T binomial(int n, int k);

/// binomial<double>(n, k) (also declared by core/bernstein.h, which every net includes).
double binomial(int n, int k);

/// The trinomial n! / (i! j! k!), k = n - i - j, as C(n, i) C(n - i, j) (two roundings at most;
/// exact while both factors and their product fit the mantissa). The weight of the triangular
/// Bernstein polynomial B_{ijk}^n.
template <class T = double>
T multinomial(int n, int i, int j) {
  return binomial<T>(n, i) * binomial<T>(n - i, j);
}

/// n! as a double: the left-to-right product 1 * 2 * ... * n (exact for n <= 22); 1 for n < 0,
/// +inf for n > 170.
double factorial(int n);

extern template double binomial<double>(int, int);
extern template long double binomial<long double>(int, int);
extern template quad binomial<quad>(int, int);

}  // namespace bpde
