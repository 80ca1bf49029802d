#pragma once
// Sampling a patch complex (complex/patch_complex.h) into one welded triangle mesh, and the angle
// between the patches' normals across their seams.
//
// Sampling: every patch is sampled as its net's sample_mesh(net, N) (triangular: the parameters of
// triangular_sample_parameters(N), N² triangles; tensor: the (N+1)² grid, 2N² triangles), in patch
// order. Welding is by identity, not by distance: a sample on a patch's edge is the sample s of
// that complex edge (s counted in the edge's canonical direction, complex_edges) and a corner
// sample is the complex's corner row, so the two patches along a seam use one vertex there. Such a
// vertex keeps the position and mean curvature of the first patch that sampled it (the other
// patch's value differs by rounding only: both evaluate the same edge control points).
// Vertices: the first patch's samples in its order, then each further patch's new ones in its order.
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/core/mesh.h"

namespace bpde {

/// Most vertices of a sampled complex before welding, #patches · (N+1)² (ParameterError beyond):
/// the memory of a single net's largest mesh (core/mesh.h kMaxSamples).
inline constexpr long long kMaxComplexSampleVertices = static_cast<long long>(kMaxSamples + 1) * (kMaxSamples + 1);

struct ComplexMesh {
  TriangleMesh mesh;
  Eigen::VectorXi patch;  ///< per triangle of mesh.F: the patch it samples
  Eigen::VectorXi vertex_patch;  ///< per vertex: the first patch that sampled it
  Eigen::MatrixX2d uv;           ///< per vertex: its parameters (u, v) in that patch
};

/// The welded mesh of the complex at N samples per patch edge (1..kMaxSamples, and at most
/// kMaxComplexSampleVertices samples over all patches: ParameterError otherwise). Validates the
/// complex (validate()).
ComplexMesh sample_complex(const PatchComplex& c, int N);

/// The largest angle in degrees between the two patches' unit normals across every interior edge,
/// at the `samples` edge parameters t = (k + 1/2)/samples, k = 0..samples-1, of each side (the
/// ends, where a corner may be singular, are left out); points where either patch is singular are
/// skipped. 0 for a complex without interior edges. ParameterError unless samples >= 1.
double seam_angle_max(const PatchComplex& c, int samples = 16);

}  // namespace bpde
