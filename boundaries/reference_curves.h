#pragma once
// The reference boundaries of boundaries/reference_boundaries.h as boundary curves
// (boundaries/boundary_curves.h), in the edge order and direction of boundaries/fit_boundary.h, so
// that fit_tensor_boundary / fit_triangular_boundary build them at any degree (the job form
// `"boundary": {"builder": NAME, ...}` of FORMATS.md "Boundary curves"). C⁰ data only.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <functional>

#include "bezierpde/boundaries/fit_boundary.h"

namespace bpde {

/// The circle of the given radius about `center` in the plane with unit normal N (arc convention of
/// boundaries/boundary_curves.h, default reference direction) split into three arcs by angle
/// (triangular CMC, Fig. 1): P_n00 at angle 0, P_0n0 at 2π/3, P_00n at 4π/3, counter-clockwise
/// about N. With radius 1, center 0 and N = +z these are the arcs of circle_three_arcs(n).
/// Throws ParameterError (radius <= 0, zero normal), NonFiniteError.
BoundaryData circle_three_arcs_curves(double radius = 1.0, const Eigen::Vector3d& center = Eigen::Vector3d::Zero(),
                                      const Eigen::Vector3d& normal = Eigen::Vector3d::UnitZ());

/// The three edges of the surface s(u,v) over the triangle (x(t,0), x(1-t,t), x(0,1-t)).
BoundaryData triangular_surface_curves(const std::function<Eigen::Vector3d(double, double)>& s);
/// The four edges of the surface s(u,v) over [0,1]² (s(t,0), s(1,t), s(1-t,1), s(0,1-t)).
BoundaryData tensor_surface_curves(const std::function<Eigen::Vector3d(double, double)>& s);

}  // namespace bpde
