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
//   - Edges of a patch: the order and direction of boundaries/fit_boundary.h (counter-clockwise
//     around the patch's domain), with the edge parameter t in [0,1]:
//       triangular  edge 0: (u,v) = (t, 0)     P_{s,0,n-s}   (P_00n -> P_n00)
//                   edge 1: (u,v) = (1-t, t)   P_{n-s,s,0}   (P_n00 -> P_0n0)
//                   edge 2: (u,v) = (0, 1-t)   P_{0,n-s,s}   (P_0n0 -> P_00n)
//       tensor      edge 0: (t, 0)   P_{s,0};   edge 1: (1, t)   P_{n,s};
//                   edge 2: (1-t, 1) P_{n-s,n}; edge 3: (0, 1-t) P_{0,n-s}      (s = 0..n).
//     Two patches that share an edge list its rows in opposite directions (consistent orientation).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <utility>
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

/// Most patches of a complex (SizeError beyond): the sampled mesh, the seam checks and the sparse
/// solves grow linearly with the count; 4096 patches of degree 8 are about 3·10⁵ control points.
inline constexpr int kMaxComplexPatches = 4096;

/// Control points of one patch: (n+1)(n+2)/2 (triangular) or (n+1)² (tensor).
int patch_point_count(PatchKind kind, int n);
/// Edges of one patch: 3 (triangular) or 4 (tensor).
inline int patch_edge_count(PatchKind kind) { return kind == PatchKind::triangular ? 3 : 4; }
/// Local rows of edge e of a degree-n patch, s = 0..n along the edge (order of the header).
std::vector<int> patch_edge_local_rows(PatchKind kind, int n, int e);
/// The (u,v) of edge parameter t on edge e (header).
Eigen::Vector2d patch_edge_parameter(PatchKind kind, int e, double t);

/// The edge of a patch that the lattice point (a, b) of resolution D lies on: (u, v) = (a/D, b/D)
/// (triangular: a + b <= D), and its position s in 0..D along that edge in the edge's direction;
/// {-1, 0} for a point inside. A corner belongs to the edge it starts (s = 0) except the corners
/// (1,0) of edge 0 and (0,1) of edge 1 (triangular) / (1,0), (1,1), (0,1) likewise (tensor), which
/// are reported as the end (s = D) of the edge before.
std::pair<int, int> patch_lattice_edge(PatchKind kind, int D, int a, int b);

/// Checks the invariants and throws the typed errors of core/errors.h: SizeError (no patches,
/// more than kMaxComplexPatches, a point list of the wrong length, a row outside 0..#points-1),
/// DegreeError (a degree outside 1..kMaxDegree, patches of different kinds or degrees),
/// NonFiniteError (a non-finite coordinate, naming its row), ParameterError (a row used twice by
/// one patch, `fixed` not sorted and unique or out of range, an edge shared by more than two
/// patches, two patches sharing an edge in the same direction).
void validate(const PatchComplex& c);

/// Patch p as a net (its rows gathered in local order). SizeError for p out of range,
/// ParameterError when the patch is not of that kind.
TriangularNet triangular_net(const PatchComplex& c, int p);
TensorNet tensor_net(const PatchComplex& c, int p);

/// Writes a patch's local points (patch_point_count x 3) back to its rows. Rows shared with other
/// patches take these values (the caller keeps shared edges consistent). SizeError on a wrong
/// shape or p out of range.
void set_patch_points(PatchComplex& c, int p, const Eigen::MatrixX3d& local);

/// An edge of the complex: its rows s = 0..n in a canonical direction (first row < last row, or,
/// when they are equal, the lexicographically smaller of the two directions) and the patches that
/// have it.
struct ComplexEdge {
  std::vector<int> rows;
  struct Side {
    int patch = 0, edge = 0;
    bool reversed = false;  ///< the patch runs along it from rows.back() to rows.front()
  };
  std::vector<Side> sides;  ///< one (boundary) or two (interior seam)
  bool boundary() const { return sides.size() == 1; }
};

/// Every edge of the complex once, in the order of first appearance (patch 0 edge 0, ...).
/// ParameterError when an edge has more than two sides or two sides run in the same direction.
std::vector<ComplexEdge> complex_edges(const PatchComplex& c);

/// Rows of the edges with one side (the complex's boundary), sorted and unique.
std::vector<int> boundary_rows(const PatchComplex& c);

}  // namespace bpde
