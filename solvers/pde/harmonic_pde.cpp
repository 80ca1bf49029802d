#include "bezierpde/solvers/pde/harmonic_pde.h"

#include <cmath>

#include "bezierpde/core/errors.h"

namespace bpde {

PdeSolution solve_harmonic_pde(const TensorNet& data, const EnergySpec& op, const PdeLuOptions& options) {
  PdeSolution out;
  {
    ScopedTimer timer(out.summary.seconds);
    if (op.order() != 2)
      throw UnsupportedProblem(
          "pde: fixed \"u-boundaries\" is for second-order operators (dirichlet, second-order); \"" + op.name() +
          "\" is fourth order and needs fixed \"boundary\"");
    if (!(std::abs(op.second_order_coeffs()[0]) > 0))
      throw ParameterError(
          "pde: the operator a x_uu + b x_uv + c x_vv needs a != 0 for data on the rows u = 0 and u = 1");
    const PdeMould mould(op, data.n(), data.m(), FixedSet::UBoundaries, options);
    out = mould.solve(data);
    if (!out.summary.converged) out.summary.message = "harmonic PDE from u-boundaries: " + out.summary.message;
  }
  return out;
}

}  // namespace bpde
