#pragma once
// The subcommands of `bpde`: each parses its input with io/, runs it through jobs/ and writes.
// Net inputs may be the result.json bpde writes (its "net"); a file given to the wrong subcommand
// is bad input naming the right one (app/inputs.h).
// They return the process exit status (0 solved, 1 valid input without a solution) and let
// exceptions propagate to main (InvalidInput: exit 2; internal errors: exit 3).
#include <optional>
#include <string>

#include "bezierpde/jobs/run_job.h"

namespace bpde::app {

/// The flags of `bpde solve`.
struct SolveFlags {
  bool quiet = false;          ///< no summary on stdout
  std::optional<int> samples;  ///< overrides the job's "samples" (1..kMaxSamples)
  bool html = false;           ///< also write DIR/view.html (as the job's "export": ["html"])
};

/// Solve a job, write DIR and print the summary (jobs/solve_summary.h) unless flags.quiet.
int cmd_solve(const std::string& job_path, const std::string& out_dir, const SolveFlags& flags = {});
/// sample, view and export print the files they wrote (files_line, jobs/solve_summary.h) unless quiet.
int cmd_sample(const std::string& net_path, const std::string& out_dir, int samples,
               const std::string& mesh_format = "ascii", bool quiet = false);
int cmd_energy(const std::string& net_path, const std::string& energy, std::optional<double> H);
int cmd_check(const std::string& net_path, int samples);
int cmd_plate(double aspect, int degree, const std::string& method);
int cmd_blend(const std::string& config_path, const std::string& out_dir);
/// DIR/view.html for DIR/result.json (its net sampled at `samples`, its report beside it).
int cmd_view(const std::string& dir, int samples, bool quiet = false);
/// The exact patch of NET.json as STEP (io/step_export.h).
int cmd_export(const std::string& net_path, const std::string& step_path, bool quiet = false);
/// The built-in default job (README's main command).
int cmd_demo(const std::string& out_dir);

}  // namespace bpde::app
