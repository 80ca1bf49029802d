#include "bezierpde/jobs/run_blend.h"

#include <utility>

#include "bezierpde/core/sample_progress.h"
#include "bezierpde/jobs/job_progress.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/solvers/blend/smoothing_spline.h"

namespace bpde {

BlendOutcome run_blend(const BlendConfig& config) {
  const SmoothingSplineResult r = solve_smoothing_spline(config.problem);
  BSplineNet net = r.spline.to_bspline_net();
  TriangleMesh mesh;
  {
    // the spline's own sample() (the same mesh: the spline is exactly this net), with progress
    const ProgressStage stage(job_progress(), kSamplingStage);
    mesh = sample_mesh(net, config.samples, job_progress());
  }
  BlendOutcome out{std::move(net), std::move(mesh), Json::object(), checked_status(r.summary)};
  out.report = {{"problem", "blend"},
                {"energy", r.functional},
                {"data_misfit", r.data_misfit},
                {"L_energy", r.energy},
                {"max_data_error", r.max_data_error},
                {"converged", r.summary.converged},
                {"seconds", r.summary.seconds}};
  if (!r.summary.message.empty()) out.report["message"] = r.summary.message;
  return out;
}

int write_blend_outcome(const std::string& dir, const BlendConfig& config, const BlendOutcome& out) {
  return write_result(dir, Net(out.net), out.mesh, config.samples, out.report, Json::object(), out.status).exit_code;
}

}  // namespace bpde
