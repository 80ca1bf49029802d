#pragma once
// Bernstein operators in IEEE binary128 (GCC's __float128), for the C¹-methods systems (Centella et al.) whose
// exact coefficients must be formed beyond double precision (docs/c1.md: the admissible-load
// and tetraharmonic systems lose all digits in double from degree ~17).
#include <vector>

namespace bpde {

using quad = __float128;

/// C(n, k) in binary128 (0 outside 0 <= k <= n).
quad qbinom(int n, int k);

/// T_d = elevation(n-d -> n) * derivative(n -> n-d): the d-th derivative of a degree-n Bernstein
/// polynomial, written back at degree n. (n+1) x (n+1), row-major; zero if d > n.
std::vector<quad> qderivative_at_degree(int n, int d);

}  // namespace bpde
