#include "core/quad_bernstein.h"

#include <algorithm>

namespace bpde {

quad qbinom(int n, int k) {
  if (k < 0 || k > n) return 0;
  quad r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

std::vector<quad> qderivative_at_degree(int n, int d) {
  std::vector<quad> T(static_cast<size_t>((n + 1) * (n + 1)), 0);
  if (d > n) return T;
  std::vector<quad> D(static_cast<size_t>((n - d + 1) * (n + 1)), 0);
  quad s = 1;
  for (int k = 0; k < d; ++k) s *= (n - k);
  for (int j = 0; j <= n - d; ++j)
    for (int k = 0; k <= d; ++k) D[static_cast<size_t>(j * (n + 1) + j + k)] = s * ((d - k) % 2 ? -1 : 1) * qbinom(d, k);
  for (int r = 0; r <= n; ++r)
    for (int i = std::max(0, r - d); i <= std::min(r, n - d); ++i) {
      const quad e = qbinom(n - d, i) * qbinom(d, r - i) / qbinom(n, r);
      for (int c = 0; c <= n; ++c) T[static_cast<size_t>(r * (n + 1) + c)] += e * D[static_cast<size_t>(i * (n + 1) + c)];
    }
  return T;
}

}  // namespace bpde
