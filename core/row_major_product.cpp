#include "core/row_major_product.h"

#include <sstream>

#include "core/errors.h"

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

// Rows of C in pairs: each loaded vector of B feeds two fused multiply-adds (one per row), and the
// 12 accumulators plus two broadcasts and one load fit the 16 ymm registers.
__attribute__((target("avx2,fma"))) void product_fma(const double* A, int r, int k, int lda, const double* B, int w,
                                                     int ldb, double* C, int ldc) {
  int a = 0;
  for (; a + 2 <= r; a += 2) {
    double* c0 = C + static_cast<long>(a) * ldc;
    double* c1 = c0 + ldc;
    const double* a0 = A + static_cast<long>(a) * lda;
    const double* a1 = a0 + lda;
    int b = 0;
    for (; b + 24 <= w; b += 24) {
      __m256d x0 = _mm256_setzero_pd(), x1 = x0, x2 = x0, x3 = x0, x4 = x0, x5 = x0;
      __m256d y0 = x0, y1 = x0, y2 = x0, y3 = x0, y4 = x0, y5 = x0;
      for (int i = 0; i < k; ++i) {
        const __m256d s = _mm256_broadcast_sd(a0 + i), t = _mm256_broadcast_sd(a1 + i);
        const double* p = B + static_cast<long>(i) * ldb + b;
        __m256d v = _mm256_loadu_pd(p);
        x0 = _mm256_fmadd_pd(s, v, x0);
        y0 = _mm256_fmadd_pd(t, v, y0);
        v = _mm256_loadu_pd(p + 4);
        x1 = _mm256_fmadd_pd(s, v, x1);
        y1 = _mm256_fmadd_pd(t, v, y1);
        v = _mm256_loadu_pd(p + 8);
        x2 = _mm256_fmadd_pd(s, v, x2);
        y2 = _mm256_fmadd_pd(t, v, y2);
        v = _mm256_loadu_pd(p + 12);
        x3 = _mm256_fmadd_pd(s, v, x3);
        y3 = _mm256_fmadd_pd(t, v, y3);
        v = _mm256_loadu_pd(p + 16);
        x4 = _mm256_fmadd_pd(s, v, x4);
        y4 = _mm256_fmadd_pd(t, v, y4);
        v = _mm256_loadu_pd(p + 20);
        x5 = _mm256_fmadd_pd(s, v, x5);
        y5 = _mm256_fmadd_pd(t, v, y5);
      }
      _mm256_storeu_pd(c0 + b, x0);
      _mm256_storeu_pd(c0 + b + 4, x1);
      _mm256_storeu_pd(c0 + b + 8, x2);
      _mm256_storeu_pd(c0 + b + 12, x3);
      _mm256_storeu_pd(c0 + b + 16, x4);
      _mm256_storeu_pd(c0 + b + 20, x5);
      _mm256_storeu_pd(c1 + b, y0);
      _mm256_storeu_pd(c1 + b + 4, y1);
      _mm256_storeu_pd(c1 + b + 8, y2);
      _mm256_storeu_pd(c1 + b + 12, y3);
      _mm256_storeu_pd(c1 + b + 16, y4);
      _mm256_storeu_pd(c1 + b + 20, y5);
    }
    for (; b + 4 <= w; b += 4) {
      __m256d x0 = _mm256_setzero_pd(), y0 = x0;
      for (int i = 0; i < k; ++i) {
        const __m256d v = _mm256_loadu_pd(B + static_cast<long>(i) * ldb + b);
        x0 = _mm256_fmadd_pd(_mm256_broadcast_sd(a0 + i), v, x0);
        y0 = _mm256_fmadd_pd(_mm256_broadcast_sd(a1 + i), v, y0);
      }
      _mm256_storeu_pd(c0 + b, x0);
      _mm256_storeu_pd(c1 + b, y0);
    }
    if (b < w) {  // 1..3 columns left: masked loads and stores
      const __m256i mask = tail_mask(w - b);
      __m256d x0 = _mm256_setzero_pd(), y0 = x0;
      for (int i = 0; i < k; ++i) {
        const __m256d v = _mm256_maskload_pd(B + static_cast<long>(i) * ldb + b, mask);
        x0 = _mm256_fmadd_pd(_mm256_broadcast_sd(a0 + i), v, x0);
        y0 = _mm256_fmadd_pd(_mm256_broadcast_sd(a1 + i), v, y0);
      }
      _mm256_maskstore_pd(c0 + b, mask, x0);
      _mm256_maskstore_pd(c1 + b, mask, y0);
    }
  }
  for (; a < r; ++a) {  // the last row when r is odd
    double* c = C + static_cast<long>(a) * ldc;
    const double* arow = A + static_cast<long>(a) * lda;
    int b = 0;
    for (; b + 4 <= w; b += 4) {
      __m256d x0 = _mm256_setzero_pd();
      for (int i = 0; i < k; ++i)
        x0 = _mm256_fmadd_pd(_mm256_broadcast_sd(arow + i), _mm256_loadu_pd(B + static_cast<long>(i) * ldb + b), x0);
      _mm256_storeu_pd(c + b, x0);
    }
    if (b < w) {
      const __m256i mask = tail_mask(w - b);
      __m256d x0 = _mm256_setzero_pd();
      for (int i = 0; i < k; ++i)
        x0 = _mm256_fmadd_pd(_mm256_broadcast_sd(arow + i),
                             _mm256_maskload_pd(B + static_cast<long>(i) * ldb + b, mask), x0);
      _mm256_maskstore_pd(c + b, mask, x0);
    }
  }
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
