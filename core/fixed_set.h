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

#include <vector>

namespace bpde {

/// The indices 0..size-1 that are not in `sorted` (an increasing list): the free points of a net
/// given its fixed points.
inline std::vector<int> complement_indices(const std::vector<int>& sorted, int size) {
  std::vector<int> out;
  out.reserve(static_cast<size_t>(size) - sorted.size());
  size_t k = 0;
  for (int r = 0; r < size; ++r) {
    if (k < sorted.size() && sorted[k] == r) {
      ++k;
      continue;
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace bpde
