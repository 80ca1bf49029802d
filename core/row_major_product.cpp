#include "bezierpde/core/row_major_product.h"

#include <sstream>

#include "bezierpde/core/errors.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define BPDE_X86_DISPATCH 1
#include <immintrin.h>
#endif

namespace bpde {
namespace {

void product_portable(const double* A, int r, int k, int lda, const double* B, int w, int ldb, double* C, int ldc) {
  for (int a = 0; a < r; ++a) {
    double* c = C + static_cast<long>(a) * ldc;
    const double* arow = A + static_cast<long>(a) * lda;
    for (int b = 0; b < w; ++b) c[b] = 0.0;
    for (int i = 0; i < k; ++i) {
      const double s = arow[i];
      const double* brow = B + static_cast<long>(i) * ldb;
      for (int b = 0; b < w; ++b) c[b] += s * brow[b];
    }
  }
}

#ifdef BPDE_X86_DISPATCH
// The first `left` (1..3) lanes set: masked loads read nothing past the end of a row.
__attribute__((target("avx2,fma"))) inline __m256i tail_mask(int left) {
  return _mm256_set_epi64x(left > 3 ? -1 : 0, left > 2 ? -1 : 0, left > 1 ? -1 : 0, -1);
}

// One register block: R rows of C by V vectors of 4 columns, starting at column b, accumulated
// over i = 0..k-1 (each entry in that order, one fused multiply-add per term). R*V accumulators,
// R broadcasts and one load must fit the 16 ymm registers: R*V + R + 1 <= 16.
template <int R, int V>
__attribute__((target("avx2,fma"), always_inline)) inline void block_fma(const double* const* arow, const double* B,
                                                                         int k, int ldb, int b, double* const* crow) {
  __m256d acc[R][V];
#pragma GCC unroll 8
  for (int r = 0; r < R; ++r)
#pragma GCC unroll 8
    for (int v = 0; v < V; ++v) acc[r][v] = _mm256_setzero_pd();
  for (int i = 0; i < k; ++i) {
    const double* p = B + static_cast<long>(i) * ldb + b;
    __m256d s[R];
#pragma GCC unroll 8
    for (int r = 0; r < R; ++r) s[r] = _mm256_broadcast_sd(arow[r] + i);
#pragma GCC unroll 8
    for (int v = 0; v < V; ++v) {
      const __m256d x = _mm256_loadu_pd(p + 4 * v);
#pragma GCC unroll 8
      for (int r = 0; r < R; ++r) acc[r][v] = _mm256_fmadd_pd(s[r], x, acc[r][v]);
    }
  }
#pragma GCC unroll 8
  for (int r = 0; r < R; ++r)
#pragma GCC unroll 8
    for (int v = 0; v < V; ++v) _mm256_storeu_pd(crow[r] + b + 4 * v, acc[r][v]);
}

// The last 1..3 columns of R rows: masked loads read nothing past the end of a row.
template <int R>
__attribute__((target("avx2,fma"), always_inline)) inline void tail_fma(const double* const* arow, const double* B,
                                                                        int k, int ldb, int b, int w,
                                                                        double* const* crow) {
  const __m256i mask = tail_mask(w - b);
  __m256d acc[R];
#pragma GCC unroll 8
  for (int r = 0; r < R; ++r) acc[r] = _mm256_setzero_pd();
  for (int i = 0; i < k; ++i) {
    const __m256d x = _mm256_maskload_pd(B + static_cast<long>(i) * ldb + b, mask);
#pragma GCC unroll 8
    for (int r = 0; r < R; ++r) acc[r] = _mm256_fmadd_pd(_mm256_broadcast_sd(arow[r] + i), x, acc[r]);
  }
#pragma GCC unroll 8
  for (int r = 0; r < R; ++r) _mm256_maskstore_pd(crow[r] + b, mask, acc[r]);
}

// R rows of C: blocks of V vectors (4V columns), then single vectors, then the masked tail.
template <int R, int V>
__attribute__((target("avx2,fma"))) void rows_fma(const double* A, int a, int k, int lda, const double* B, int w,
                                                  int ldb, double* C, int ldc) {
  const double* arow[R];
  double* crow[R];
  for (int r = 0; r < R; ++r) {
    arow[r] = A + static_cast<long>(a + r) * lda;
    crow[r] = C + static_cast<long>(a + r) * ldc;
  }
  int b = 0;
  for (; b + 4 * V <= w; b += 4 * V) block_fma<R, V>(arow, B, k, ldb, b, crow);
  for (; b + 4 <= w; b += 4) block_fma<R, 1>(arow, B, k, ldb, b, crow);
  if (b < w) tail_fma<R>(arow, B, k, ldb, b, w, crow);
}

// Rows of C in pairs (each loaded vector of B feeds two fused multiply-adds; 12 accumulators);
// an odd row count starts with one block of three rows (12 accumulators, each load feeding three:
// the x, y, z rows of the mould product of solvers/pde/pde_lu.cpp); a single row alone runs 8
// independent accumulators, enough to hide the FMA latency.
__attribute__((target("avx2,fma"))) void product_fma(const double* A, int r, int k, int lda, const double* B, int w,
                                                     int ldb, double* C, int ldc) {
  int a = 0;
  if (r == 1) {
    rows_fma<1, 8>(A, 0, k, lda, B, w, ldb, C, ldc);
    return;
  }
  if (r % 2 == 1) {
    rows_fma<3, 4>(A, 0, k, lda, B, w, ldb, C, ldc);
    a = 3;
  }
  for (; a + 2 <= r; a += 2) rows_fma<2, 6>(A, a, k, lda, B, w, ldb, C, ldc);
}

bool cpu_has_fma() {
  static const bool yes = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return yes;
}
#endif

}  // namespace

bool row_major_product_uses_fma() {
#ifdef BPDE_X86_DISPATCH
  return cpu_has_fma();
#else
  return false;
#endif
}

void row_major_product(const double* A, int r, int k, int lda, const double* B, int w, int ldb, double* C, int ldc) {
  if (r < 0 || k < 0 || w < 0 || lda < k || ldb < w || ldc < w) {
    std::ostringstream m;
    m << "row_major_product: sizes r = " << r << ", k = " << k << ", w = " << w << " need 0 <= k <= lda = " << lda
      << " and 0 <= w <= ldb = " << ldb << ", ldc = " << ldc;
    throw SizeError(m.str());
  }
#ifdef BPDE_X86_DISPATCH
  if (cpu_has_fma()) {
    product_fma(A, r, k, lda, B, w, ldb, C, ldc);
    return;
  }
#endif
  product_portable(A, r, k, lda, B, w, ldb, C, ldc);
}

}  // namespace bpde
