#pragma once
// The subcommands of `bpde`: each parses its input with io/, calls the library and writes.
// They return the process exit status (0 solved, 1 valid input without a solution) and let
// InvalidInput (exit 2) propagate to main.
#include <optional>
#include <string>

#include "io/job.h"

namespace bpde::app {

/// What a solve produced: the net, the report object, and extra top-level result fields.
struct SolveOutcome {
  Net net;
  Json report = Json::object();
  Json extra = Json::object();  ///< e.g. {"load": NET} for biharmonic-load
  bool converged = true;
};

/// Run a validated job (no files written). Throws InvalidInput for problems the library rejects.
SolveOutcome run_job(const Job& job);

/// Write DIR/result.json and the surface files; returns the exit status (0 or 1).
int write_outcome(const std::string& dir, const Job& job, const SolveOutcome& out);

int cmd_solve(const std::string& job_path, const std::string& out_dir);
int cmd_sample(const std::string& net_path, const std::string& out_dir, int samples);
int cmd_energy(const std::string& net_path, const std::string& energy, std::optional<double> H);
int cmd_check(const std::string& net_path, int samples);
int cmd_plate(double aspect, int degree, const std::string& method);
int cmd_blend(const std::string& config_path, const std::string& out_dir);
/// The built-in default job (README's main command).
int cmd_demo(const std::string& out_dir);

}  // namespace bpde::app
