#pragma once
// STEP (ISO 10303-21, AP214) export of the exact patch of a net through OpenCASCADE, and the
// reader the tests use to check it. io/step_export.cpp is the one translation unit that includes
// OpenCASCADE (target bpde_step), like checks/ for CGAL; this header speaks Eigen only.
//
// One face, bounded by the surface's natural parameter range:
//  - tensor nets: a Geom_BezierSurface with poles P_ij (i along u, j along v) on [0,1]^2;
//  - bspline nets: a Geom_BSplineSurface with the net's degrees, distinct knots and
//    multiplicities, on the knot domain [u_p, u_nu] x [v_q, v_nv];
//  - triangular nets: the exact degenerate tensor patch of degree (n, n) of
//    triangular/tensor_form.h, y(s, t) = x(s, (1-s)t), as a Geom_BezierSurface on [0,1]^2 whose
//    edge s = 1 is collapsed onto P_{n00}.
// Lengths are written as they are, in the file's millimetres.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <type_traits>
#include <variant>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/json_io.h"

namespace bpde {

/// OpenCASCADE's largest Bézier/B-spline degree (Geom_BezierSurface::MaxDegree()).
inline constexpr int kMaxStepDegree = 25;

/// Throws DegreeError (message starting `where: `) if `net` has a degree above kMaxStepDegree:
/// what write_step would refuse, checked before a job runs.
inline void check_step_degree(const Net& net, const std::string& where) {
  const int d = std::visit(
      [](const auto& n) {
        using T = std::decay_t<decltype(n)>;
        if constexpr (std::is_same_v<T, TriangularNet>)
          return n.n();
        else if constexpr (std::is_same_v<T, TensorNet>)
          return std::max(n.n(), n.m());
        else
          return std::max(n.p(), n.q());
      },
      net);
  if (d > kMaxStepDegree)
    throw DegreeError(where + ": STEP export: degree " + std::to_string(d) + " is above OpenCASCADE's largest degree " +
                      std::to_string(kMaxStepDegree));
}

/// Write `net` to `path`. Throws DegreeError above kMaxStepDegree, FileError if the file cannot
/// be written, InternalError if OpenCASCADE refuses the surface.
void write_step(const std::string& path, const Net& net);

/// What a STEP file holds, as OpenCASCADE reads it back: its faces, and for the first face the
/// kind and degrees of its surface, the parameter bounds and the surface's points at `uv`.
struct StepReadBack {
  int faces = 0;
  std::string surface;  ///< "bezier", "bspline" or "other"
  int u_degree = 0, v_degree = 0;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  Eigen::MatrixX3d points;  ///< one row per row of uv
};
/// Read `path` with STEPControl_Reader. Throws FileError if it cannot be read.
StepReadBack read_step(const std::string& path, const Eigen::MatrixX2d& uv);

}  // namespace bpde
