#pragma once
// CMC surfaces of several patches (complex/patch_complex.h): the solves of solvers/cmc/cmc.h on a
// PatchComplex, and what a result of several patches needs besides: the mean-curvature statistics
// over all patches and the continuity of the normal across the shared edges.
//
// The solve is the single-patch solve itself (solvers/cmc/complex_net.h explains how): D_H = D + 2HV
// ("functional": "dirichlet") or A_H = A + 2HV ("area") summed over the patches, over the free
// rows (PatchComplex::fixed held), H or V form. The patches meet C⁰ (shared control points); the
// critical point of the sum makes the normals agree across a shared edge only as the degree
// grows (max_seam_angle measures it).
#include "bezierpde/core/eigen.h"
#include <Eigen/Core>

#include "bezierpde/complex/patch_complex.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace bpde {

/// The solve (cmc.h) of `data`'s free rows with its fixed rows held. Throws as solve_cmc on a net,
/// and ParameterError / SizeError / DegreeError for a malformed complex
/// (energies/complex_functionals.h: patch_assembly), UnsupportedProblem for a fixed set other than
/// boundary or the mean-curvature functional. result.net is the complex with the solved points;
/// A and V are sums over the patches; result.routes as for one patch.
CmcResult<PatchComplex> solve_cmc(const PatchComplex& data, const CmcOptions& options);

/// mean_curvature_stats (energies/cmc.h) of every patch on its own N grid, merged: the smallest
/// min, the largest max, the mean weighted by the samples.
MeanCurvatureStats mean_curvature_stats(const PatchComplex& c, int N = 50, double corner_margin = 0.1);

/// The largest angle (radians) between the unit normals of two patches at the same point of an
/// edge they share (found by its end rows, its control rows the same in opposite order), over
/// `samples` points (k + 1/2)/samples of each shared edge (the corners left out, where a normal
/// may vanish). 0 when no edge is shared; π where a normal vanishes at a sample.
double max_seam_angle(const PatchComplex& c, int samples = 20);

}  // namespace bpde
