#pragma once
// The blending surface of `bpde blend` (FORMATS.md; solvers/blend/smoothing_spline.h): the solve
// of a blend config, its report, and the files it writes.
#include <string>

#include "bezierpde/core/mesh.h"
#include "bezierpde/io/blend_config.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/solvers/summary.h"
#include "bezierpde/tensor/bspline_net.h"

namespace bpde {

struct BlendOutcome {
  BSplineNet net;     ///< the discrete PDE spline as a bicubic B-spline net (result.json "net")
  TriangleMesh mesh;  ///< the spline sampled at the config's `samples`
  /// {"problem": "blend", "energy", "data_misfit", "L_energy", "max_data_error", "converged",
  /// "seconds"} and "message" when the solver gave one.
  Json report = Json::object();
  Status status = Status::Converged;
};

/// Solve a validated blend config (io/blend_config.h); no files written.
BlendOutcome run_blend(const BlendConfig& config);

/// Write DIR/result.json and the surface files (jobs/run_job.h write_result) of a blend; returns
/// the exit code (0 converged, else 1).
int write_blend_outcome(const std::string& dir, const BlendConfig& config, const BlendOutcome& out);

}  // namespace bpde
