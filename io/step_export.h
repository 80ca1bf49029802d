#pragma once
// STEP (ISO 10303-21, AP214) export of the exact patch of a net through OpenCASCADE, and the
// reader the tests use to check it. This header speaks Eigen only; OpenCASCADE lives in the plugin
// bpde_step_plugin.so (io/step_plugin.cpp, the one translation unit that includes it), which the
// first call of write_step, read_step or step_plugin_path opens with dlopen: a process that writes
// no STEP file never loads OpenCASCADE. Where the plugin is looked for, in this order (the first
// file that exists is loaded, the others are not tried):
//  1. the environment variable BPDE_STEP_PLUGIN, if set and not empty: that file only;
//  2. the folder of the binary that holds this library's code (libbpde_step.so of a shared build,
//     else the program or shared object that linked the static library);
//  3. that folder's ../<libdir> (an installed bpde in <prefix>/bin beside <prefix>/<libdir>);
//  4. the install prefix's library folder, <prefix>/<libdir>, as configured at build time;
//  5. the build tree's folder of the plugin, as built.
// A plugin that is missing, cannot be loaded or belongs to another build is a StepPluginError
// (below; an InternalError, the command's exit status 3), raised by the call that needs it.
//
// One face, bounded by the surface's natural parameter range:
//  - tensor nets: a Geom_BezierSurface with poles P_ij (i along u, j along v) on [0,1]^2;
//  - bspline nets: a Geom_BSplineSurface with the net's degrees, distinct knots and
//    multiplicities, on the knot domain [u_p, u_nu] x [v_q, v_nv];
//  - triangular nets: the exact degenerate tensor patch of degree (n, n) of
//    triangular/tensor_form.h, y(s, t) = x(s, (1-s)t), as a Geom_BezierSurface on [0,1]^2 whose
//    edge s = 1 is collapsed onto P_{n00}.
// Lengths are written as they are, in the file's millimetres.
//
// A patch complex (complex/patch_complex.h) is one shape: one face per patch, as above (a
// triangular patch as its degenerate tensor form, a tensor patch as its Bézier surface), sewn with
// BRepBuilderAPI_Sewing at kStepSewingTolerance into one shell (a connected complex; the faces of
// a disconnected one into one shell per component, in a compound). Shared edges are the same
// control points in both patches, so the sewing joins every interior seam; the free edges of the
// shell are the complex's boundary edges (and no degenerate edge counts as one).
#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <algorithm>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/json_io.h"

namespace bpde {

/// The STEP plugin cannot be found, loaded or is not of this build: a part of the installation is
/// missing, not the input's fault. An InternalError (exit status 3), typed so that a caller can
/// tell it from a broken invariant.
class StepPluginError : public InternalError {
 public:
  using InternalError::InternalError;
};

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
/// be written, StepPluginError without the plugin, InternalError if OpenCASCADE refuses the surface.
void write_step(const std::string& path, const Net& net);

/// Sewing tolerance of a complex, relative to the diagonal of the bounding box of its control
/// points (absolute below a diagonal of 1 mm).
inline constexpr double kStepSewingTolerance = 1e-6;

/// Write the complex `c` to `path` as one sewn shell (above). Validates c (complex/patch_complex.h);
/// throws DegreeError above kMaxStepDegree, FileError if the file cannot be written,
/// StepPluginError without the plugin, InternalError if OpenCASCADE refuses a surface.
void write_step(const std::string& path, const PatchComplex& c);

/// The paths where the STEP plugin is looked for, in the order above.
std::vector<std::string> step_plugin_candidates();

/// Loads the STEP plugin (once per process) and returns the path it was loaded from. Throws
/// StepPluginError if it is missing: a job that exports STEP calls it before it solves.
std::string step_plugin_path();

/// What a STEP file holds, as OpenCASCADE reads it back: its faces, and for the first face the
/// kind and degrees of its surface, the parameter bounds and the surface's points at `uv`.
struct StepReadBack {
  int faces = 0;
  std::string surface;  ///< "bezier", "bspline" or "other"
  int u_degree = 0, v_degree = 0;
  double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
  Eigen::MatrixX3d points;  ///< one row per row of uv
};
/// The topology of a STEP file's shape as OpenCASCADE reads it back: BRepCheck_Analyzer's verdict
/// and the shapes, each counted once. `free_edges`: the edges of exactly one face that are not
/// degenerate; `degenerate_edges`: the edges collapsed to a point.
struct StepTopology {
  bool valid = false;
  int solids = 0, shells = 0, faces = 0, edges = 0, free_edges = 0, degenerate_edges = 0;
};
/// Read `path` with STEPControl_Reader and analyse its shape. Throws FileError if it cannot be
/// read, StepPluginError without the plugin.
StepTopology read_step_topology(const std::string& path);

/// Read `path` with STEPControl_Reader. Throws FileError if it cannot be read, StepPluginError
/// without the plugin.
StepReadBack read_step(const std::string& path, const Eigen::MatrixX2d& uv);

}  // namespace bpde
