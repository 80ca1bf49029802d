#pragma once
// Iterative refinement of a solution operator ("mould") G with x_interior = G x_fixed, for a
// consistent linear system A_I G = -A_F that was factored in long double but whose residual
//   R = A_I G + A_F
// is evaluated more accurately (in binary128 from exact entries) by the caller. Each step
// G -= correct(R), where correct applies the long double factorisation. It stops when a
// correction falls below 1e-18 of G, when a correction after the first fails to halve (not
// contracting: the condition number is beyond ~1e19 and G is kept as it is), or after max_steps.
// Used by solvers/c1/biharmonic_load.cpp and solvers/c1/tetraharmonic.cpp.
#include <Eigen/Core>

namespace bpde {

using MatLD = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

/// residual(G) -> MatLD, correct(R) -> MatLD (same shape as G).
template <class Residual, class Correct>
void refine_mould(MatLD& G, int max_steps, const Residual& residual, const Correct& correct) {
  long double last = 0;
  for (int step = 0; step < max_steps; ++step) {
    const MatLD dG = correct(residual(G));
    const long double d = dG.cwiseAbs().maxCoeff();
    if (step > 0 && d > 0.5L * last) break;  // not contracting: keep G
    G -= dG;
    last = d;
    if (d <= 1e-18L * G.cwiseAbs().maxCoeff()) break;
  }
}

}  // namespace bpde
