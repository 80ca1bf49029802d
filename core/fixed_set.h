#pragma once
// Which control points a problem prescribes (FORMATS.md, job field "fixed").
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

#include "bezierpde/core/errors.h"

namespace bpde {

enum class FixedSet {
  Boundary,          ///< "boundary": C0 data, the outer ring (tensor/bspline) or some index 0 (triangular)
  BoundaryAdjacent,  ///< "boundary+adjacent": C1 data, outer two rings / smallest index <= 1
  UBoundaries,       ///< "u-boundaries": rows i = 0 and i = n of a tensor net (harmonic PDE)
};

inline std::string to_string(FixedSet f) {
  switch (f) {
    case FixedSet::Boundary:
      return "boundary";
    case FixedSet::BoundaryAdjacent:
      return "boundary+adjacent";
    case FixedSet::UBoundaries:
      return "u-boundaries";
  }
  return "?";
}

/// Throws NonFiniteError "<who>: prescribed point r (i = .., j = ..) is not finite" for the first
/// row r of `rows` of P with a NaN or infinite coordinate. `columns` > 0 names the tensor indices
/// (i = r / columns, j = r % columns); 0 names the row alone. Solvers call it on their prescribed
/// points, which net constructors check but `points()` lets a caller overwrite. A row outside P
/// is a SizeError.
inline void require_finite_rows(const Eigen::MatrixX3d& P, const std::vector<int>& rows, const std::string& who,
                                int columns = 0) {
  for (int r : rows) {
    if (r < 0 || r >= P.rows())
      throw SizeError(who + ": prescribed point " + std::to_string(r) + " is not one of the " +
                      std::to_string(P.rows()) + " control points");
    for (int c = 0; c < 3; ++c)
      if (!std::isfinite(P(r, c))) {
        std::string where = "point " + std::to_string(r);
        if (columns > 0) where += " (i = " + std::to_string(r / columns) + ", j = " + std::to_string(r % columns) + ")";
        throw NonFiniteError(who + ": prescribed " + where + " is not finite");
      }
  }
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
