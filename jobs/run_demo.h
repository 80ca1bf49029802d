#pragma once
// The built-in default job of `bpde demo` (the README's main command): the job, and the summary
// the command prints from its result.
#include <string>

#include "io/job.h"

namespace bpde {

/// The CMC approximation of the triangular CMC paper's Fig. 1 set-up: a unit circle split into
/// three arcs bounds a degree-4 triangular net (the paper's degree: its ansatz uses P_112, P_121,
/// P_211); the critical point of D + 2HV at H = -1 on the branch from the Dirichlet extremal
/// (Newton with the exact Hessian), 50 samples.
Job demo_job();

/// The lines `bpde demo` prints, from the report of the result it wrote (result.json's "report",
/// with `mean_curvature` and `check`) and the output directory.
std::string demo_summary(const Json& report, const std::string& out_dir);

}  // namespace bpde
