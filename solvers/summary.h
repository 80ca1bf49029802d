#pragma once
// What every solver returns beside its result (in the spirit of ceres::Solver::Summary).
#include <string>

namespace bpde {

struct Summary {
  /// The solution is usable: the optimality condition holds to 1e-11 relative to the size of its
  /// terms (FORMATS.md "converged"). A direct solve that succeeded sets it true.
  bool converged = false;
  /// Iterations (Newton steps, continuation steps, ...) or 0 for direct solves.
  int iterations = 0;
  /// Final relative optimality residual (solver-specific; documented by each solver).
  double residual = 0.0;
  /// Human-readable outcome. Required when converged is false, e.g.
  /// "no critical point on the branch from H = 0 beyond H ≈ -2.31".
  std::string message;
  /// Wall time of the solve in seconds.
  double seconds = 0.0;
};

}  // namespace bpde
