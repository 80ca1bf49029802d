#pragma once
// The summary `bpde solve` prints on stdout after writing a result (unless --quiet): one screen,
// the same figures as `bpde demo` prints, for any problem.
#include <string>
#include <vector>

#include "bezierpde/jobs/run_job.h"

namespace bpde {

/// The lines `bpde solve` prints, from the solve's outcome (its net and figures), what writing it
/// added (the mean-curvature statistics and the CGAL check), the job's file name and the output
/// directory: problem and net, converged or not (and why: the summary's message), energy,
/// residual, mean-curvature range, self-intersections, the files written (`files`, names in
/// out_dir: files_line). Figures a problem does not report are left out; values that are not
/// finite (a failed solve) print as "none".
std::string solve_summary(const SolveOutcome& out, const WrittenResult& written, const std::string& job_path,
                          const std::string& out_dir, const std::vector<std::string>& files);

/// The one line naming the files a command wrote, as `bpde solve`, `sample`, `view` and `export`
/// print it: "  files               DIR/{a, b, c}\n" (one file: "DIR/a"; an empty DIR: the names
/// alone, as given).
std::string files_line(const std::string& dir, const std::vector<std::string>& names);

}  // namespace bpde
