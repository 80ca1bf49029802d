#include "bezierpde/jobs/run_plate.h"

#include <cmath>

#include "bezierpde/core/errors.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/solvers/c1/clamped_plate.h"

namespace bpde {

PlateOutcome run_plate(double aspect, int degree, const std::string& method, const PlateArgumentNames& names) {
  if (!std::isfinite(aspect) || !(aspect > 0)) throw ParameterError(names.aspect + " must be a finite number > 0");
  if (method != "admissible-load" && method != "ritz")
    throw ParseError(names.method + " must be admissible-load or ritz, got \"" + method + "\"");
  ClampedPlateOptions o;
  o.aspect = aspect;
  o.degree = degree;
  o.method = parse_plate_method(method);
  const ClampedPlateResult r = solve_clamped_plate(o);
  PlateOutcome out;
  out.status = checked_status(r.summary);
  out.report = {{"center_deflection", r.center_deflection},
                {"energy", r.energy},
                {"aspect", aspect},
                {"degree", degree},
                {"method", method},
                {"converged", r.summary.converged},
                {"seconds", r.summary.seconds}};
  if (!r.summary.message.empty()) out.report["message"] = r.summary.message;
  return out;
}

}  // namespace bpde
