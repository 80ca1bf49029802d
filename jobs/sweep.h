#pragma once
// Parameter sweeps (FORMATS.md "Sweeps", `bpde sweep SWEEP.json --out DIR [--jobs N]`): a base job
// and axes (io/sweep_spec.h: the file, its limits and the order of the jobs), expanded into the
// product of jobs, each run as `bpde solve` runs it, with one row of results per job. The
// expansion exists once, here: the command and the Python module (bezierpde.sweep, also on a Dask
// cluster) both call expand_sweep and run_sweep_job. A named boundary builder makes the data
// follow the degree axis: after the axes are applied, "net" is replaced by the builder's net for
// net.degree (sweep_boundary_names() lists them; register_sweep_boundary adds one).
#include <functional>
#include <string>
#include <vector>

#include "bezierpde/io/json_io.h"
#include "bezierpde/io/sweep_spec.h"

namespace bpde {

/// Largest number of worker threads (`--jobs`) a sweep may ask for (ParameterError beyond).
inline constexpr int kMaxSweepThreads = 1024;

/// One expanded job: its index, its id (folder name, "job-0003"), the axis values (an object
/// path -> value) and the job JSON. `error` is set when the job could not be built (the boundary
/// builder refused its degree): the job then runs to an invalid-input row.
struct SweepJob {
  int index = 0;
  std::string id;
  Json values = Json::object();
  Json job = Json::object();
  std::string error;
};

/// Parse a sweep spec (io/sweep_spec.h parse_sweep_spec): a string "base" is a job file read
/// relative to `base_dir`, "boundary" one of sweep_boundary_names(). Throws ParseError,
/// FileError, SizeError, ParameterError naming `source`.
SweepSpec sweep_from_json(const Json& j, const std::string& source = "sweep", const std::string& base_dir = ".");
SweepSpec read_sweep_file(const std::string& path);

/// The product of the axes (see the header comment). Never throws for one bad job (its `error`).
std::vector<SweepJob> expand_sweep(const SweepSpec& spec);

/// A boundary builder: the net JSON (FORMATS.md "Nets") of a reference boundary at a degree
/// (the value of net.degree: an integer, or [n, m] for tensor nets). Throws InvalidInput.
using SweepBoundaryBuilder = std::function<Json(const Json& degree)>;
/// Add or replace a builder (thread-safe). Built in: "circle-three-arcs" (triangular CMC Fig. 1),
/// "sphere-triangle" (triangular), "sphere-square" (tensor; boundaries/reference_boundaries.h).
void register_sweep_boundary(const std::string& name, SweepBoundaryBuilder builder);
std::vector<std::string> sweep_boundary_names();
/// ParameterError for an unknown name.
Json build_sweep_boundary(const std::string& name, const Json& degree);

/// Columns of results.csv: index, job, the axis paths, then kSweepResultColumns (io/sweep_spec.h).
std::vector<std::string> sweep_columns(const SweepSpec& spec);

/// Run one job into `dir` as `bpde solve` does (result.json and surface files), plus dir/job.json
/// (the expanded job) and dir/row.json (its row). Never throws for the job's own failures: an
/// invalid job (exit 2) or an internal error (exit 3) is a row with its `error`.
/// Row keys: index, job, the axis paths, then kSweepResultColumns:
///   status ("converged", a Status name, "invalid-input", "internal-error"), exit_code (as
///   `bpde solve`), converged, energy, residual (report residual, else pde_residual), H (report H:
///   the requested H, or the last H reached before a fold), H_min,
///   H_max, H_mean (report mean_curvature), check_self_intersections, check_closed, check_volume,
///   seconds (wall time of the job), error (one line, or the report's message when not converged),
///   boundary_error (a job in the boundary form: the largest max_error of its report's
///   boundary_fit; null otherwise).
Json run_sweep_job(const SweepJob& job, const std::string& dir);

/// The row of a job already run into `dir` (resume): row.json when job.json equals the job, its
/// exit code is 0, 1 or 2 (internal errors are retried) and it has every column of
/// kSweepResultColumns (a row of an older version is run again); null otherwise.
Json finished_sweep_row(const SweepJob& job, const std::string& dir);

struct SweepProgress {
  int done = 0;  ///< finished jobs, including the ones resumed
  int total = 0;
  int resumed = 0;            ///< jobs skipped because they were already done
  double seconds = 0.0;       ///< wall time since the sweep started
  const Json* row = nullptr;  ///< the row just finished (null for the initial call)
};

struct SweepRunOptions {
  int jobs = 0;  ///< worker threads; 0: the hardware concurrency. 0..kMaxSweepThreads.
  bool resume = true;
  /// Called (serialised, from the worker threads) once before the first job and after each job.
  std::function<void(const SweepProgress&)> on_progress;
};

/// Expand and run a sweep into `out_dir`: each job in out_dir/jobs/<id>/, then
/// out_dir/results.csv and out_dir/results.jsonl (one row per job, in index order). Returns the
/// rows. Throws only for an unusable out_dir (FileError) or options (ParameterError).
std::vector<Json> run_sweep(const SweepSpec& spec, const std::string& out_dir, const SweepRunOptions& options = {});

/// results.csv text of rows (header sweep_columns(spec)); numbers with 17 significant digits,
/// null as empty, arrays and objects as JSON, strings quoted when needed.
std::string sweep_csv(const SweepSpec& spec, const std::vector<Json>& rows);
/// Write out_dir/results.csv and out_dir/results.jsonl.
void write_sweep_tables(const std::string& out_dir, const SweepSpec& spec, const std::vector<Json>& rows);

}  // namespace bpde
