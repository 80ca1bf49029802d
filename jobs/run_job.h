#pragma once
// Run a validated job (FORMATS.md "Jobs") and write its results: the library entry point behind
// `bpde solve`, usable from C++ directly.
//
//   bpde::Job job = bpde::read_job_file("job.json");    // throws InvalidInput on bad input
//   bpde::SolveOutcome out = bpde::run_job(job);         // no files written
//   int status = bpde::write_outcome("out/dir", job, out); // 0 solved, 1 no solution
#include <string>

#include "core/mesh.h"
#include "io/job.h"

namespace bpde {

/// What a solve produced: the net, the report object (FORMATS.md "Results"), extra top-level
/// result fields (e.g. {"load": NET} for biharmonic-load) and whether it converged.
struct SolveOutcome {
  Net net;
  Json report = Json::object();
  Json extra = Json::object();
  bool converged = true;
};

/// Run a validated job. Throws InvalidInput for problems the solvers reject; a valid problem
/// without a solution returns converged = false with report["message"].
SolveOutcome run_job(const Job& job);

/// Mean-curvature statistics {min, max, mean, count} of a sampled net, away from the corners
/// (energies/cmc.h mean_curvature_stats with corner margin 0.1; corners of a circle split into
/// arcs are nearly singular), null when no sample qualifies.
Json mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int samples);
/// The object `bpde check` prints for a mesh (CGAL figures).
Json check_report(const TriangleMesh& mesh);

/// Create DIR with its parents (FileError if that fails).
void make_output_dir(const std::string& dir);

/// Write DIR/result.json and surface.obj, surface.ply, net.obj (DIR created with its parents).
/// The report gains `mean_curvature` and `check` unless already present. Returns 0 if converged,
/// else 1.
int write_result(const std::string& dir, const Net& net, const TriangleMesh& mesh, int samples, Json report,
                 const Json& extra, bool converged);
/// write_result for a job's outcome, sampled at job.samples.
int write_outcome(const std::string& dir, const Job& job, const SolveOutcome& out);

}  // namespace bpde
