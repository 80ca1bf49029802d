#pragma once
// The summary `bpde solve` prints on stdout after writing a result (unless --quiet): one screen,
// the same figures as `bpde demo` prints, for any problem.
#include <string>

#include "bezierpde/jobs/run_job.h"

namespace bpde {

/// The lines `bpde solve` prints, from the solve's outcome (its net and figures), what writing it
/// added (the mean-curvature statistics and the CGAL check), the job's file name and the output
/// directory: problem and net, converged or not (and why: the summary's message), energy,
/// residual, mean-curvature range, self-intersections, the files written. Figures a problem does
/// not report are left out; values that are not finite (a failed solve) print as "none".
std::string solve_summary(const SolveOutcome& out, const WrittenResult& written, const std::string& job_path,
                          const std::string& out_dir);

}  // namespace bpde
