#pragma once
// The sweep file (FORMATS.md "Sweeps"): parsed and validated into a typed SweepSpec, and the
// jobs' JSON built from it, with no solving. jobs/sweep.h runs what this describes (the command
// `bpde sweep`, Python's bezierpde.sweep); fuzz/fuzz_sweep.cpp fuzzes this reader alone.
//
//   {"base": JOB or "job.json",               // a job object, or a job file relative to the sweep file
//    "boundary": "circle-three-arcs",         // optional: the net is built by name from its degree
//    "axes": {"problem.H": [-0.5, -1, -1.5], "net.degree": [4, 6, 8]}}
//
// Axes are dotted paths into the job ("problem.H", "net.degree", "net.degree.0" for an array
// element; missing objects are created) with a non-empty array of values each. Jobs are the
// product of the axes, in the order of their paths (sorted, as JSON objects are), the last path
// varying fastest: index k's value of axis a is digit a of k in the mixed radix of the axes'
// sizes. Limits (FORMATS.md "Input limits"): at most kMaxSweepJobs jobs, at most kMaxJsonDepth
// keys per path; an axis may not be named like a column of the results table.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "bezierpde/io/json_io.h"

namespace bpde {

struct SweepAxis {
  std::string path;          ///< dotted path into the job, e.g. "problem.H"
  std::vector<Json> values;  ///< non-empty
};

struct SweepSpec {
  Json base = Json::object();   ///< the base job (before the axes are applied)
  std::vector<SweepAxis> axes;  ///< sorted by path
  std::string boundary;         ///< builder name, or empty
};

/// Largest number of jobs a sweep may expand to (SizeError beyond).
inline constexpr long kMaxSweepJobs = 100000;

/// The result columns of every row, after `index`, `job` and the axis values (jobs/sweep.h
/// run_sweep_job says what each holds). No axis may take one of these names, `index` or `job`.
extern const std::vector<std::string> kSweepResultColumns;

/// Reads the job file a string "base" names (the name as written in the sweep file).
using SweepBaseLoader = std::function<Json(const std::string& name)>;

/// Parse a sweep spec (strict keys: base, axes, boundary). A string "base" is given to
/// `load_base`; "boundary" must be one of `boundary_names`. Throws ParseError (structure, the
/// axis rules above), SizeError (more than kMaxSweepJobs jobs), ParameterError (an unknown
/// boundary) naming `source`, and whatever `load_base` throws.
SweepSpec parse_sweep_spec(const Json& j, const std::string& source, const SweepBaseLoader& load_base,
                           const std::vector<std::string>& boundary_names);

/// The number of jobs: the product of the axes' sizes (1 without axes).
std::size_t sweep_job_count(const SweepSpec& spec);

/// The job of index k (0 <= k < sweep_job_count(spec)) before a boundary builder, into `job`:
/// the base with each axis's value set at its path, in the axes' order, and `values` (an object
/// path -> value). Throws ParameterError naming `where` when a path indexes neither an object nor
/// an array that holds the index (the job then cannot be built, and `job` and `values` hold the
/// axes applied before it; the other jobs can).
void sweep_job_json(const SweepSpec& spec, std::size_t k, Json& job, Json& values, const std::string& where);

/// The value at a dotted path of `j` (as the axes address it), or null when there is none.
const Json* sweep_path_value(const Json& j, const std::string& path);

}  // namespace bpde
