#pragma once
// The summary `bpde solve` prints on stdout after writing a result (unless --quiet): one screen,
// the same figures as `bpde demo` prints, for any problem.
#include <string>

#include "bezierpde/io/json_io.h"

namespace bpde {

/// The lines `bpde solve` prints, from the whole result.json object it wrote ({"net", "report",
/// ...}; the report with `mean_curvature` and `check`), the job's file name and the output
/// directory: problem and net, converged or not (and why: the report's message), energy,
/// residual, mean-curvature range, self-intersections, the files written. Fields a problem does
/// not report are left out; null values (a failed solve) print as "none".
std::string solve_summary(const Json& result, const std::string& job_path, const std::string& out_dir);

}  // namespace bpde
