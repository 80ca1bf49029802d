#pragma once
// The "boundary" form of a job (FORMATS.md "Boundary curves"): a net given by its type, degree
// and boundary curves (or a named reference boundary) instead of its control points. The net is
// built here (boundaries/fit_boundary.h), so that a sweep can vary the degree and the data follow.
#include <string>
#include <vector>

#include "bezierpde/boundaries/fit_boundary.h"
#include "bezierpde/io/json_io.h"

namespace bpde {

/// A net built from a "boundary" object: the net (boundary, and with tangents the adjacent ring,
/// fitted; the other points zero), the per-edge fit report, and whether C¹ data were given.
struct BoundaryNet {
  Net net;
  std::vector<EdgeFit> fits;
  bool c1 = false;
};

/// One CURVE object (bezier, bspline, samples (also closed), segment, arc, helix, circle). Throws the typed exceptions
/// of core/errors.h with messages starting with `path`: ParseError (unknown type or field, wrong
/// JSON type), SizeError, DegreeError, NonFiniteError, ParameterError.
BoundaryCurve curve_from_json(const Json& j, const std::string& path);

/// The whole "boundary" object (path e.g. "job.boundary"); the same exceptions, and the fit's
/// (corners that do not meet: ParameterError naming the edges and the gap). `default_fit` is the
/// method when the object has no "fit": a job passes Geometric for the area and mean-curvature
/// functionals and Interpolation otherwise (io/job.cpp, FORMATS.md "Boundary curves").
BoundaryNet boundary_from_json(const Json& j, const std::string& path,
                               FitMethod default_fit = FitMethod::Interpolation);

/// The report's `boundary_fit`: [{edge, curve, method, max_error[, tangent_curve, tangent_method,
/// tangent_max_error]}, ...].
Json boundary_fit_to_json(const std::vector<EdgeFit>& fits);

/// The names of the reference boundaries ("circle-three-arcs", ...), for messages and docs.
std::string reference_boundary_names();

}  // namespace bpde
