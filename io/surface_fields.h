#pragma once
// Per-vertex fields of a sampled net for the surface files (surface.ply, surface.vtp, view.html):
// parameters, unit normals, mean and Gaussian curvature, and whether the parametrisation is
// regular at the vertex.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cstdint>

#include "bezierpde/core/mesh.h"
#include "bezierpde/io/json_io.h"

namespace bpde {

/// A vertex is regular when the sine of the angle between x_u and x_v is at least this:
/// |x_u ^ x_v| >= kRegularSine |x_u| |x_v| (about 2.9 degrees). Where boundary curves meet
/// tangentially, as the demo's circle in three arcs does, x_u and x_v are parallel in the exact
/// problem and nearly so in the fitted net (0.84 degrees at the demo's corners, with sampled
/// H = -21487 and -8888 there, against about -1 elsewhere): the curvature there measures the
/// near-degenerate parametrisation, not the shape, and would swamp any automatic colour range.
/// A patch parametrised anywhere else at such an angle is degenerate too.
inline constexpr double kRegularSine = 0.05;

/// Fields at the #V vertices of `mesh`, in mesh order (FORMATS.md "bpde sample").
///  - uv: #V by 2 parameters (u, v) of each vertex; for a bspline net in its knot domain.
///  - normal: #V by 3 unit normals N = x_u ^ x_v / |x_u ^ x_v|.
///  - H: #V mean curvatures, mesh.H at regular vertices. K: #V Gaussian curvatures.
///  - regular: #V flags (1 regular, 0 not).
/// At an irregular vertex, H, K and the normal are the mean over its regular neighbours (the
/// vertices sharing a triangle with it; the normal renormalised). An irregular vertex with no
/// regular neighbour (inside a degenerate corner wider than one sample) takes the mean over its
/// neighbours filled in the ring before, ring by ring outwards from the regular vertices; only a
/// mesh without any regular vertex keeps H = K = 0 and the normal (0, 0, 1). Nothing is NaN.
struct SurfaceFields {
  Eigen::MatrixX2d uv;
  Eigen::MatrixX3d normal;
  Eigen::VectorXd H, K;
  Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 1> regular;
};

/// The mesh resolution N of a mesh sampled from `net` by sample_net (FORMATS.md "bpde sample"):
/// (N+1)^2 vertices for tensor and bspline nets, (N+1)(N+2)/2 for triangular ones. InternalError
/// if the vertex count is not of that form.
int sampled_resolution(const Net& net, const TriangleMesh& mesh);

/// The parameters of the vertices of sample_net(net, N), in mesh order.
Eigen::MatrixX2d sample_parameters(const Net& net, int N);

/// The fields of `mesh`, a sampling of `net` (sample_net, or a blend's spline sampled the same
/// way): normals, K and the regular flags from the net's derivatives at the vertex parameters,
/// H from mesh.H.
SurfaceFields surface_fields(const Net& net, const TriangleMesh& mesh);

}  // namespace bpde
