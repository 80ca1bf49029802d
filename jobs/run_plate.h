#pragma once
// The clamped plate of `bpde plate` (FORMATS.md; solvers/c1/clamped_plate.h): the options from the
// command's arguments, the solve, and the JSON object the command prints.
#include <string>

#include "bezierpde/io/json_io.h"
#include "bezierpde/solvers/summary.h"

namespace bpde {

struct PlateOutcome {
  /// {"center_deflection", "energy", "aspect", "degree", "method", "converged", "seconds"} and
  /// "message" when the solver gave one.
  Json report = Json::object();
  Status status = Status::Converged;
};

/// Solve the plate [0,1] x [0,aspect] of bidegree `degree` by `method` ("admissible-load" or
/// "ritz"). Throws ParameterError (aspect not a finite number > 0), ParseError (another method)
/// and the errors of ClampedPlateOptions::validate.
/// Errors name the arguments as `names` says: the command's flags, or the Python arguments (the
/// ranges of ClampedPlateOptions::validate name the options, aspect and degree, for both).
struct PlateArgumentNames {
  std::string aspect = "--aspect", method = "--method";
};
PlateOutcome run_plate(double aspect, int degree, const std::string& method, const PlateArgumentNames& names = {});

}  // namespace bpde
