#pragma once
// The requirements shared by the two C¹ methods of Centella, Monterde, Moreno, Oset (Two
// C¹-methods to generate Bézier surfaces from the boundary): tensor nets, C¹ data (the boundary and
// adjacent rows, "fixed": "boundary+adjacent"), n = m >= 4 (Theorem 1).
#include <string>

#include "solvers/requirements.h"

namespace bpde {

/// `problem` names the problem in messages, e.g. `problem "tetraharmonic"`.
inline SolverRequirements c1_data_requirements(const std::string& problem) {
  SolverRequirements r;
  r.problem = problem;
  r.nets = {NetKind::Tensor};
  r.fixed = {FixedSet::BoundaryAdjacent};
  r.fixed_reason = r.problem + " takes C1 data: \"fixed\": \"boundary+adjacent\"";
  r.square = true;
  r.min_degrees = {{NetKind::Tensor, FixedSet::BoundaryAdjacent, 4}};
  return r;
}

}  // namespace bpde
