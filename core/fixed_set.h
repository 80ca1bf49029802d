#pragma once
// Which control points a problem prescribes (FORMATS.md, job field "fixed").
#include <string>

namespace bpde {

enum class FixedSet {
  Boundary,          ///< "boundary": C0 data, the outer ring (tensor/bspline) or some index 0 (triangular)
  BoundaryAdjacent,  ///< "boundary+adjacent": C1 data, outer two rings / smallest index <= 1
  UBoundaries,       ///< "u-boundaries": rows i = 0 and i = n of a tensor net (harmonic PDE)
};

inline std::string to_string(FixedSet f) {
  switch (f) {
    case FixedSet::Boundary: return "boundary";
    case FixedSet::BoundaryAdjacent: return "boundary+adjacent";
    case FixedSet::UBoundaries: return "u-boundaries";
  }
  return "?";
}

}  // namespace bpde
