#pragma once
// Jobs whose boundary is a patch complex (FORMATS.md "Patch complexes"): the solve, the
// refinement rounds of a job's `tolerance`, and what the shared output path (jobs/run_job.h:
// ResultSurface, SampledSurface, write_result) needs to know about a complex.
//
// The solve is the extremal of the job's energy (solvers/complex/complex_extremal.h) or its cmc
// problem (solvers/cmc/complex_cmc.h) on the complex. The report adds `patches`, `degree`,
// `refine`, `seam_angle_max` (degrees, complex/complex_mesh.h at 16 points per seam), `area` and
// `volume` (sums over the patches) and `boundary_error` (complex_boundary_error). The files are
// those of a single net, written by the same code (jobs/run_job.h write_result) from one welded
// mesh (complex/complex_mesh.h): surface.vtp carries the patch id of every triangle as the
// CellData "patch", and net.obj every complex row once with each patch's control net lines.
// Per-vertex fields: the normal and K from the patch that sampled the vertex first (at its
// parameters; where that patch is singular, at the point nudged towards its domain's centre),
// H and `regular` from the mesh; uv are those parameters in that patch.
//
// Tolerance rounds (Job::tolerance): solve, measure (the certificate's mean-curvature deviation
// over the statistics' samples of the result, seam_angle_max, the boundary error), and while a
// tolerance fails, refine and solve again:
//   - in p first: the degree +2 while the worst failing figure is more than 10 times its
//     tolerance, else +1, up to Tolerance::max_degree; the boundary is fitted again at the new
//     degree (complex_job_at), so the boundary error falls with it;
//   - then in h: refine += 1 (every patch split into four, uniformly: splitting only the patches
//     where the error sits would leave T-junctions, which a complex of shared control rows cannot
//     express), up to Tolerance::max_refine, kMaxComplexPatches patches, kMaxComplexGramEntries
//     and kMaxComplexSampleVertices at the job's samples. h refinement splits the fitted edges
//     exactly, so it keeps the boundary error: a failing boundary tolerance at the degree limit ends
//     the rounds;
//   - at most Tolerance::max_rounds rounds.
// Each round is one entry of report.rounds. The solves start as a job's solve does (the cmc
// routes build their own start from the boundary rows): a round costs a full solve.
#include <string>

#include "bezierpde/io/surface_fields.h"
#include "bezierpde/jobs/run_job.h"

namespace bpde {

/// The problem of job on *job.complex (and its tolerance rounds when job.tolerance is set).
/// Throws the solvers' InvalidInput errors.
SolveOutcome run_complex_job(const Job& job);

/// The boundary error of a complex job's data (run_job.h BoundaryError): over every layout
/// boundary edge k (data.coarse.boundary, the order of boundary_fit), the curve piece it follows
/// sampled at 64n + 1 uniform parameters (n the degree), each point's distance to the edge's
/// Bézier curve (the foot point by Newton from the nearest of 64n + 1 samples of the edge): the
/// largest, with the edge, loop, curve, the curve's own parameter t and the point. The edges are
/// the boundary rows of the data, which every solve holds (the fixed rows), so this is the solved
/// surface's boundary; h refinement splits them exactly.
BoundaryError complex_boundary_error(const ComplexJobData& data);

/// The per-vertex fields of a complex's sampled surface (the header).
SurfaceFields complex_surface_fields(const PatchComplex& c, const SampledSurface& s);

/// net.obj of a complex: every row once, each patch's control-net segments once.
void write_complex_net_obj(const std::string& path, const PatchComplex& c);

}  // namespace bpde
