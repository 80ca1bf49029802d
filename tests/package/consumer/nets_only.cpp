// Links bezierpde::core alone (nets; Eigen only): a consumer of one component.
#include <cstdio>

#include "bezierpde/tensor/tensor_net.h"
#include "bezierpde/triangular/triangular_net.h"

int main() {
  bpde::TensorNet net(2, 2);
  for (int i = 0; i <= 2; ++i)
    for (int j = 0; j <= 2; ++j) net.points().row(i * 3 + j) << i / 2.0, j / 2.0, 0.0;
  const Eigen::Vector3d x = net.evaluate(0.25, 0.75);  // the plane z = 0: x(u, v) = (u, v, 0)
  if (std::abs(x.x() - 0.25) > 1e-15 || std::abs(x.y() - 0.75) > 1e-15 || x.z() != 0.0) return 1;
  std::puts("nets_only: ok");
  return 0;
}
