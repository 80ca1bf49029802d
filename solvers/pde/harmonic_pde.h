#pragma once
// Harmonic (and general second-order) tensor Bézier patches from the two u-boundaries
// (FORMATS.md `"fixed": "u-boundaries"`; Arnal–Monterde–Ugail §1 via Monterde–Ugail 2004; docs/errata.md):
//
//   a x_uu + b x_uv + c x_vv = 0   ([a, b, c] = EnergySpec::second_order_coeffs(); dirichlet: Δx = 0)
//
// on a net of degree (n, m) whose rows i = 0 and i = n (the curves x(0, v) and x(1, v)) are given.
//
// Existence and uniqueness (monomial anti-diagonal analysis, solvers/pde/pde_lu.h): for Δ and n = m
// the harmonic polynomials of bidegree (n, n) have dimension 2n+2 (odd n) or 2n+1 (even n) against
// 2n+2 data values, so the solution is unique for odd n, and for even n the two rows must satisfy
// one linear condition (for Δ: equal n-th differences, i.e. x(1,v) - x(0,v) has degree < n in v).
// For n > m the solution is unique; for n < m several conditions apply. Data that violate a
// condition (relative tolerance PdeLuOptions::compatibility_tolerance) give Summary converged =
// false with a message (the command exits 1); the net is then the least-squares net.
//
// The solve is the Bernstein least-squares system of solvers/pde/pde_lu.h (PdeMould with
// FixedSet::UBoundaries); use a PdeMould directly to solve many data sets of one degree.
#include "bezierpde/energies/energy_spec.h"
#include "bezierpde/solvers/pde/pde_lu.h"
#include "bezierpde/solvers/requirements.h"
#include "bezierpde/tensor/tensor_net.h"

namespace bpde {

/// The FORMATS.md "pde" problem for a second-order operator on tensor nets (method "lu" only):
/// "u-boundaries" data, degrees n, m >= 2.
inline SolverRequirements harmonic_pde_requirements(const EnergySpec& op) {
  SolverRequirements r;
  r.problem = "problem \"pde\"";
  r.nets = {NetKind::Tensor};
  if (op.order() == 2) {
    r.fixed = {FixedSet::UBoundaries};
    r.fixed_reason = "a second-order pde (" + op.name() + ") takes \"fixed\": \"u-boundaries\"";
  } else {
    r.fixed_reason = "a fourth-order pde (" + op.name() + ") takes \"fixed\": \"boundary\"";
  }
  r.min_degrees = {{NetKind::Tensor, FixedSet::UBoundaries, 2}};
  r.methods = {"lu"};
  r.method_reason = "the second-order pde has no explicit method (Arnal-Monterde-Ugail); use \"method\": \"lu\"";
  return r;
}

/// Solve a x_uu + b x_uv + c x_vv = 0 from rows i = 0 and i = n of `data` (its other points are
/// ignored). `op` must be second order (dirichlet or second-order; else UnsupportedProblem) with
/// a != 0 (ParameterError: the rows u = 0, 1 cannot determine a solution without an x_uu term).
PdeSolution solve_harmonic_pde(const TensorNet& data, const EnergySpec& op = EnergySpec::dirichlet(),
                               const PdeLuOptions& options = {});

}  // namespace bpde
