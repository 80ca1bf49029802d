#pragma once
// Surfaces of several Bézier patches that share their control points along common edges.
//
// A PatchComplex is a C⁰ surface: every patch is a triangular or tensor Bézier patch of one degree
// n (tensor patches have degree (n, n)), and the control points of an edge shared by two patches
// are the same rows of the complex's point matrix, so the patches meet exactly along it.
//
// Conventions:
//   - Each patch lists, for each of its control points in the local order of its net
//     (triangular/triangular_net.h: barycentric order, P_{n00} is row 0; tensor/tensor_net.h:
//     P_ij at row i(n+1)+j, i along u), the row of `points` it uses (`ComplexPatch::points`).
//   - All patches are oriented alike: x_u ∧ x_v points to the same side of the surface in every
//     patch (for the outer loop of a disc seen counter-clockwise from the side of the normal).
//   - `fixed` lists (sorted, unique) the rows held by the boundary data; the other rows are the
//     unknowns of every solve (the "free coordinates": y(3a + c) = points(free[a], c)).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

namespace bpde {

class TriangularNet;
class TensorNet;

enum class PatchKind { triangular, tensor };

/// One patch of a complex.
struct ComplexPatch {
  PatchKind kind = PatchKind::triangular;
  int degree = 1;
  /// local control point r (the net's row order) -> row of PatchComplex::points;
  /// (n+1)(n+2)/2 entries for a triangular patch, (n+1)² for a tensor patch.
  std::vector<int> points;
};

/// Several patches of one kind and degree sharing #points x 3 control points.
struct PatchComplex {
  std::vector<ComplexPatch> patches;
  Eigen::MatrixX3d points;
  std::vector<int> fixed;  ///< rows held by the boundary data, sorted
};

}  // namespace bpde
