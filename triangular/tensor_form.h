#pragma once
// A triangular Bézier patch as an exact degenerate tensor Bézier patch (for CAD export:
// io/step_export.h), by the Duffy-type map of the unit square onto the triangle.
//
// The map: (s, t) in [0,1]^2  ->  (u, v) = (s, (1 - s) t), so that w = 1 - u - v = (1 - s)(1 - t).
// It takes the square onto T = {u, v >= 0, u + v <= 1}, collapsing the edge s = 1 onto the corner
// (u, v) = (1, 0) (P_{n00}). For i + j + k = n,
//   B^n_{ijk}(u, v, w) = n!/(i! j! k!) s^i (1-s)^(j+k) t^j (1-t)^k = B^n_i(s) B^(n-i)_j(t),
// so x(s, (1-s)t) = sum_i B^n_i(s) c_i(t) with the curve c_i(t) = sum_j B^(n-i)_j(t) P_{i,j,n-i-j}
// of degree n - i. Elevating every c_i to degree n,
//   Q_{i b} = sum_j P_{i,j,n-i-j} C(n-i, j) C(i, b-j) / C(n, b)     (0 <= b <= n),
// gives the tensor net Q of degree (n, n) with y(s, t) = x(s, (1-s)t) exactly. Its row i = n is n+1
// copies of P_{n00} (the collapsed edge s = 1); its edges s = 0, t = 0 and t = 1 are the
// triangle's edges u = 0 (from P_{00n} to P_{0n0}), v = 0 (P_{00n} to P_{n00}) and w = 0
// (P_{0n0} to P_{n00}).
#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

namespace bpde {

/// The tensor net of degree (n, n) above: tensor_form(T).evaluate(s, t) == T.evaluate(s, (1-s)t).
TensorNet tensor_form(const TriangularNet& net);

}  // namespace bpde
