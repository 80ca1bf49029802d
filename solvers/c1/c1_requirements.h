#pragma once
// The requirements shared by the two C¹ methods of Centella, Monterde, Moreno, Oset (Two
// C¹-methods to generate Bézier surfaces from the boundary): tensor nets, C¹ data (the boundary and
// adjacent rows, "fixed": "boundary+adjacent"), n = m >= 4 (Theorem 1).
#include <string>

#include "bezierpde/solvers/requirements.h"

namespace bpde {

/// Largest degree of a C1 job (tetraharmonic, biharmonic-load): both solve a dense Bernstein
/// system of ~n^2 unknowns, O(n^6) work. Measured on the loaded 2-core CI machine: tetraharmonic
/// 25 s at n = 30 and 86 s at n = 40 (converged), so about 25 min at n = 64; biharmonic-load at
/// n = 40 already stops with converged = false after 40 s (its load does not vanish to 1e-11).
inline constexpr int kMaxC1Degree = 40;

/// `problem` names the problem in messages, e.g. `problem "tetraharmonic"`.
inline SolverRequirements c1_data_requirements(const std::string& problem) {
  SolverRequirements r;
  r.problem = problem;
  r.nets = {NetKind::Tensor};
  r.fixed = {FixedSet::BoundaryAdjacent};
  r.fixed_reason = r.problem + " takes C1 data: \"fixed\": \"boundary+adjacent\"";
  r.square = true;
  r.min_degrees = {{NetKind::Tensor, FixedSet::BoundaryAdjacent, 4}};
  r.max_degrees = {{NetKind::Tensor, kMaxC1Degree, "a dense solve of O(n^6) work: 86 s at n = 40"}};
  return r;
}

}  // namespace bpde
