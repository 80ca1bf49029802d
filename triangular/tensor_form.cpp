#include "bezierpde/triangular/tensor_form.h"

#include "bezierpde/core/binomial.h"

namespace bpde {

TensorNet tensor_form(const TriangularNet& net) {
  const int n = net.n();
  TensorNet out(n, n);
  for (int i = 0; i <= n; ++i) {
    const int d = n - i;  // degree of the curve c_i
    for (int b = 0; b <= n; ++b) {
      Eigen::Vector3d q = Eigen::Vector3d::Zero();
      for (int j = std::max(0, b - i); j <= std::min(d, b); ++j)
        q += (binomial(d, j) * binomial(i, b - j) / binomial(n, b)) * net.point(i, j);  // weight 1 exactly when alone
      out.set_point(i, b, q);
    }
  }
  return out;
}

}  // namespace bpde
