#pragma once
// A layout: the coarse mesh of a patch complex (its vertices and faces, one face per patch), and
// the complex's row structure built from it.
//
// Conventions:
//   - faces list vertex ids counter-clockwise seen from the side the normals point to (the
//     orientation of complex/patch_complex.h): 3 per face for triangular patches, 4 for tensor.
//   - Face (A, B, C) is the triangular patch with P_00n = A (x(0,0)), P_n00 = B (x(1,0)),
//     P_0n0 = C (x(0,1)): its edges 0, 1, 2 run A -> B, B -> C, C -> A.
//     Face (A, B, C, D) is the tensor patch with P_00 = A, P_n0 = B, P_nn = C, P_0n = D: its edges
//     0..3 run A -> B, B -> C, C -> D, D -> A.
//   - Rows of the complex built by complex_topology: rows 0..#vertices-1 are the vertices; then,
//     for each layout edge in the order of layout_edges(), its n-1 inner points from its smaller
//     to its larger vertex id; then each face's inner points, face by face, in the net's row order.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <array>
#include <vector>

#include "bezierpde/complex/patch_complex.h"

namespace bpde {

struct Layout {
  PatchKind kind = PatchKind::triangular;
  Eigen::MatrixX3d vertices;            ///< #vertices x 3 (positions of the patch corners)
  std::vector<std::vector<int>> faces;  ///< 3 or 4 vertex ids each, counter-clockwise
};

/// An edge of a layout: vertices a < b and the faces that use it (one on the boundary, two inside).
struct LayoutEdge {
  int a = 0, b = 0;
  std::vector<int> faces;
};

/// Every edge once, in the order of first appearance (face 0's edges first).
std::vector<LayoutEdge> layout_edges(const Layout& layout);

/// The boundary of a layout as closed loops of vertex ids, each in the direction the faces run
/// along it (counter-clockwise around the surface), starting at its smallest vertex id; loops in
/// the order of their first vertex.
std::vector<std::vector<int>> layout_boundary_loops(const Layout& layout);

/// Checks that the layout is an oriented 2-manifold with boundary, and throws ParameterError
/// otherwise (naming the face or vertex): a face of the wrong size or with a repeated vertex, a
/// vertex id out of range, an edge used by more than two faces or twice in one direction
/// (inconsistent orientation), a vertex used by no face, a vertex whose faces do not form one fan
/// (non-manifold vertex). SizeError for no faces or more than kMaxComplexPatches; NonFiniteError
/// for a non-finite vertex.
void validate_layout(const Layout& layout);

/// The complex of degree n on the layout (validated): the row structure of the header, points
/// zero except the vertex rows (the layout's vertices), `fixed` the rows on the layout boundary.
/// DegreeError unless 1 <= n <= kMaxDegree.
PatchComplex complex_topology(const Layout& layout, int n);

}  // namespace bpde
