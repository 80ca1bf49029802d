#pragma once
// Iterative refinement of a solution operator ("mould") G with x_interior = G x_fixed, for a
// consistent linear system A_I G = -A_F that was factored in long double but whose residual
//   R = A_I G + A_F
// is evaluated more accurately (in binary128 from exact entries) by the caller. Each step
// G -= correct(R), where correct applies the long double factorisation. It stops when a
// correction falls below 1e-18 of G, when a correction after the first fails to halve (not
// contracting: the condition number is beyond ~1e19 and G is kept as it is), or after max_steps.
// Used by solvers/c1/biharmonic_load.cpp and solvers/c1/tetraharmonic.cpp.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "bezierpde/core/scalar_types.h"

namespace bpde {

/// The binary128 net of column c of the mould (X has one entry per control point): G(:, c) on the
/// interior rows, 1 at the fixed row fixed[c], 0 elsewhere. Its residual is column c of R.
inline void mould_column(const MatLD& G, int c, const std::vector<int>& interior, const std::vector<int>& fixed,
                         std::vector<quad>& X) {
  std::fill(X.begin(), X.end(), quad(0));
  for (size_t r = 0; r < interior.size(); ++r) X[static_cast<size_t>(interior[r])] = G(static_cast<Eigen::Index>(r), c);
  X[static_cast<size_t>(fixed[static_cast<size_t>(c)])] = 1;
}

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
