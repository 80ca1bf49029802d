#pragma once
// A planar domain for a triangular layout (complex/layout.h): a position in the plane for every
// layout vertex, so that the complex becomes a spline on a planar triangulation and its C¹
// conditions across seams are linear in the control points (solvers/complex/complex_c1.h).
//
// Conventions:
//   - A DomainTriangle holds, row by row, the domain points of a patch's x(0,0), x(1,0), x(0,1)
//     (the layout face's vertices in order: P_00n, P_n00, P_0n0 of complex/layout.h). The patch
//     is the map of its domain triangle y = y0 + u (y1 - y0) + v (y2 - y0) <-> (u, v).
//   - Every domain triangle is counter-clockwise (positive signed area): the orientation of the
//     layout's faces.
//
// The default positions (layout_domain_positions), a Tutte embedding:
//   one boundary loop (a disc): its vertices at equal angles on the unit circle, counter-clockwise
//     in the loop's direction, the loop's first vertex at angle 0;
//   two boundary loops (an annulus): the loop through the smallest vertex id is the outer one, on
//     the unit circle as above; the other on the circle of radius 1/2 at equal angles, clockwise
//     (its direction), turned to the start angle (of 8 per inner edge) that makes the smallest
//     signed triangle area largest;
//   inner vertices: each the mean of its neighbours (Tutte's barycentric embedding), one sparse
//     solve. For a disc with its boundary on a convex polygon this is one-to-one (Tutte; Floater);
//     otherwise the triangles are checked.
// The fan of the automatic disc layout thus becomes the regular N-gon fan around the origin, the
// annulus ring a ring of triangles between two concentric circles.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <vector>

#include "bezierpde/complex/layout.h"

namespace bpde {

/// Continuity across the seams of a complex: C⁰ (shared control points) or C¹ on the planar
/// domain (solvers/complex/complex_c1.h).
enum class Continuity { C0, C1 };

using DomainTriangle = Eigen::Matrix<double, 3, 2>;

/// The default planar positions of the layout's vertices (#vertices x 2, above). ParameterError
/// for a tensor layout (C¹ on a planar domain takes triangular patches), a layout whose boundary
/// is not one or two loops, or an embedding with a triangle of non-positive area.
Eigen::MatrixX2d layout_domain_positions(const Layout& layout);

/// The domain triangle of every face of a triangular layout from vertex positions (#vertices x 2).
/// ParameterError for a tensor layout, a wrong row count, a non-finite position or a triangle
/// whose signed area is not above 1e-12 times the squared diameter of the positions.
std::vector<DomainTriangle> layout_domain(const Layout& layout, const Eigen::MatrixX2d& positions);

/// The domain triangles of refine_h (complex/refine.h) of a complex with these triangles: patch
/// 4p + k is the k-th part of patch p, (A, AB, CA), (AB, B, BC), (CA, BC, C), (BC, CA, AB).
std::vector<DomainTriangle> refine_domain_h(const std::vector<DomainTriangle>& domain);

}  // namespace bpde
