#include "bezierpde/jobs/run_energy.h"

#include <cmath>

#include "bezierpde/core/errors.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/quadratic_energy.h"
#include "bezierpde/energies/triangular_gram.h"
#include "bezierpde/io/job.h"
#include "bezierpde/solvers/bspline/bspline_extremal.h"

namespace bpde {

namespace {

// Energies of nets with huge coordinates overflow; say so instead of printing null.
double finite_energy(double x, const char* what) {
  if (!std::isfinite(x)) throw NonFiniteError(std::string(what) + " overflows: the net's coordinates are too large");
  return x;
}

}  // namespace

Json energy_report(const Net& net, const std::string& energy, std::optional<double> H,
                   const EnergyArgumentNames& names) {
  if (H && !std::isfinite(*H)) throw NonFiniteError(names.H + " is not finite");
  if (energy == "cmc") {
    if (!H) throw ParseError(names.energy + " cmc needs " + names.H);
    CmcEnergies e;
    if (const auto* t = std::get_if<TensorNet>(&net))
      e = cmc_energies(*t, *H);
    else if (const auto* tr = std::get_if<TriangularNet>(&net))
      e = cmc_energies(*tr, *H);
    else
      throw UnsupportedProblem("energy cmc needs a triangular or tensor net, not a " + net_kind(net) + " net");
    return Json{{"D", finite_energy(e.D, "D")}, {"V", finite_energy(e.V, "V")}, {"DH", finite_energy(e.DH, "D + 2HV")}};
  }
  const EnergySpec spec = energy_from_argument(energy, names.energy);
  if (const auto* t = std::get_if<TensorNet>(&net))
    return Json{{"energy", finite_energy(energy_value(*t, spec), "the energy")}};
  if (const auto* t = std::get_if<TriangularNet>(&net)) {
    const Eigen::MatrixXd Q = triangular_gram(t->n(), spec);
    const Eigen::MatrixX3d& P = t->points();
    return Json{{"energy", finite_energy(0.5 * (P.transpose() * Q * P).trace(), "the energy")}};
  }
  if (const auto* b = std::get_if<BSplineNet>(&net))
    return Json{{"energy", finite_energy(bspline_energy(*b, spec), "the energy")}};
  throw UnsupportedProblem("energy " + spec.name() + " on a " + net_kind(net) +
                           " net is not available in this build yet");
}

}  // namespace bpde
