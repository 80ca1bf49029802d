#pragma once
// The energies of `bpde energy` (FORMATS.md): the value of a named energy of any net, or the CMC
// quantities D, V and D + 2HV.
#include <optional>
#include <string>

#include "bezierpde/io/json_io.h"

namespace bpde {

/// {"energy": E} for an energy given as `bpde energy --energy` takes it (a bare name or an ENERGY
/// JSON object, io/job.h energy_from_argument), or {"D", "V", "DH"} for "cmc" (which needs H).
/// Throws ParseError (unknown energy, cmc without H), NonFiniteError (H not finite, a value that
/// overflows), UnsupportedProblem (cmc on a bspline net).
/// Errors name the arguments as `names` says: the command's flags, or the Python arguments.
struct EnergyArgumentNames {
  std::string energy = "--energy", H = "--H";
};
Json energy_report(const Net& net, const std::string& energy, std::optional<double> H,
                   const EnergyArgumentNames& names = {});

}  // namespace bpde
