// The names of the cmc solvers, functionals and area starts (solvers/cmc/cmc.h), apart from the solvers themselves: the job
// reader (io/job.cpp) needs them, and the fuzz targets (fuzz/) link the readers without Ceres.
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace bpde {

CmcSolver parse_cmc_solver(const std::string& name) {
  if (name == "newton") return CmcSolver::Newton;
  if (name == "ceres") return CmcSolver::Ceres;
  if (name == "nlopt") return CmcSolver::NLopt;
  throw ParameterError("unknown cmc solver \"" + name + "\" (expected newton, ceres or nlopt)");
}

std::string to_string(CmcSolver s) {
  switch (s) {
    case CmcSolver::Newton:
      return "newton";
    case CmcSolver::Ceres:
      return "ceres";
    case CmcSolver::NLopt:
      return "nlopt";
  }
  return "?";
}

CmcFunctionalKind parse_cmc_functional(const std::string& name) {
  if (name == "dirichlet") return CmcFunctionalKind::Dirichlet;
  if (name == "area") return CmcFunctionalKind::Area;
  if (name == "mean-curvature") return CmcFunctionalKind::MeanCurvature;
  throw ParameterError("unknown cmc functional \"" + name + "\" (expected dirichlet, area or mean-curvature)");
}

AreaStart parse_area_start(const std::string& name) {
  if (name == "mean-curvature") return AreaStart::MeanCurvature;
  if (name == "dirichlet") return AreaStart::Dirichlet;
  if (name == "minimal-surface") return AreaStart::MinimalSurface;
  throw ParameterError("unknown start \"" + name + "\" (expected mean-curvature, dirichlet or minimal-surface)");
}

std::string to_string(AreaStart s) {
  switch (s) {
    case AreaStart::Dirichlet:
      return "dirichlet";
    case AreaStart::MinimalSurface:
      return "minimal-surface";
    case AreaStart::MeanCurvature:
      break;
  }
  return "mean-curvature";
}

std::string to_string(CmcFunctionalKind f) {
  switch (f) {
    case CmcFunctionalKind::Area:
      return "area";
    case CmcFunctionalKind::MeanCurvature:
      return "mean-curvature";
    case CmcFunctionalKind::Dirichlet:
      break;
  }
  return "dirichlet";
}

}  // namespace bpde
