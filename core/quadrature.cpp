#include "bezierpde/core/quadrature.h"

#include <cmath>
#include <numbers>

#include "bezierpde/core/errors.h"

namespace bpde {

QuadratureRule1D gauss_legendre01(int q) {
  if (q < 1 || q > 200) throw ParameterError("gauss_legendre01: q must be in 1..200");
  QuadratureRule1D r;
  r.x.resize(q);
  r.w.resize(q);
  // Newton on P_q from the Chebyshev-like initial guess; weights 2/((1-x^2) P_q'(x)^2) on [-1,1].
  for (int i = 0; i < q; ++i) {
    double x = std::cos(std::numbers::pi * (i + 0.75) / (q + 0.5));
    double dp = 0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= q; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (q == 1) {
        p1 = x;
        p0 = 1;
      }
      dp = q * (x * p1 - p0) / (x * x - 1);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= q; ++k) {
        const double p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      if (q == 1) {
        p1 = x;
        p0 = 1;
      }
      dp = q * (x * p1 - p0) / (x * x - 1);
    }
    const double w = 2.0 / ((1 - x * x) * dp * dp);
    // map [-1,1] -> [0,1], increasing order
    r.x(q - 1 - i) = 0.5 * (x + 1);
    r.w(q - 1 - i) = 0.5 * w;
  }
  return r;
}

QuadratureRuleTriangle gauss_triangle(int q) {
  const QuadratureRule1D g = gauss_legendre01(q);
  QuadratureRuleTriangle r;
  r.uv.resize(q * q, 2);
  r.w.resize(q * q);
  // (s, t) in [0,1]^2 -> u = s, v = (1 - s) t, Jacobian (1 - s).
  for (int a = 0; a < q; ++a)
    for (int b = 0; b < q; ++b) {
      const int k = a * q + b;
      r.uv(k, 0) = g.x(a);
      r.uv(k, 1) = (1 - g.x(a)) * g.x(b);
      r.w(k) = g.w(a) * g.w(b) * (1 - g.x(a));
    }
  return r;
}

}  // namespace bpde
