#pragma once
// The progress callback (core/progress.h) of the jobs run on this thread: run_job passes it to
// the solvers' Options (CmcOptions::progress), write_result reports its stages (sampling,
// checking, writing). Null unless a caller installs one with a JobProgressScope, so that the job
// functions keep their signatures and cost nothing when progress is off.
#include <string_view>

#include "bezierpde/core/progress.h"
#include "bezierpde/core/sample_progress.h"

namespace bpde {

/// The stages of writing a result are kSamplingStage (core/sample_progress.h), kMeshCheckStage
/// (checks/mesh_checks.h) and writing the files, one step per file (write_output_files).
inline constexpr std::string_view kWritingFilesStage = "writing files";

/// The callback installed on this thread (an empty function when none is).
const ProgressFn& job_progress();

/// Installs `progress` for the jobs run on this thread while it lives (scopes nest).
class JobProgressScope {
 public:
  explicit JobProgressScope(ProgressFn progress);
  ~JobProgressScope();
  JobProgressScope(const JobProgressScope&) = delete;
  JobProgressScope& operator=(const JobProgressScope&) = delete;

 private:
  ProgressFn previous_;
};

}  // namespace bpde
