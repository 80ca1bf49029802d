#include "app/commands.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "checks/mesh_checks.h"
#include "core/errors.h"
#include "io/blend_config.h"
#include "io/mesh_io.h"
#include "io/run_job.h"
#include "energies/quadratic_energy.h"
#include "solvers/smoothing_spline.h"

namespace bpde::app {

int cmd_solve(const std::string& job_path, const std::string& out_dir) {
  const Job job = read_job_file(job_path);
  const SolveOutcome out = run_job(job);
  return write_outcome(out_dir, job, out);
}

int cmd_sample(const std::string& net_path, const std::string& out_dir, int samples) {
  if (samples < 1 || samples > kMaxSamples)
    throw ParameterError("--samples must be in 1.." + std::to_string(kMaxSamples) + ", got " + std::to_string(samples));
  const Net net = read_net_file(net_path);
  const TriangleMesh mesh = sample_net(net, samples);
  make_output_dir(out_dir);
  write_surface_files(out_dir, net, mesh);
  return 0;
}

int cmd_energy(const std::string& net_path, const std::string& energy, std::optional<double> H) {
  const Net net = read_net_file(net_path);
  if (H && !std::isfinite(*H)) throw NonFiniteError("--H is not finite");
  if (energy == "cmc") {
    if (!H) throw ParseError("--energy cmc needs --H");
    throw UnsupportedProblem("energy cmc is not available in this build yet");
  }
  const EnergySpec spec = energy_from_argument(energy);
  if (const auto* t = std::get_if<TensorNet>(&net)) {
    std::cout << Json{{"energy", energy_value(*t, spec)}}.dump() << "\n";
    return 0;
  }
  throw UnsupportedProblem("energy " + spec.name() + " on a " + net_kind(net) + " net is not available in this build yet");
}

int cmd_check(const std::string& net_path, int samples) {
  if (samples < 1 || samples > kMaxSamples)
    throw ParameterError("--samples must be in 1.." + std::to_string(kMaxSamples) + ", got " + std::to_string(samples));
  const Net net = read_net_file(net_path);
  std::cout << check_report(sample_net(net, samples)).dump() << "\n";
  return 0;
}

int cmd_plate(double aspect, int degree, const std::string& method) {
  if (!std::isfinite(aspect) || !(aspect > 0)) throw ParameterError("--aspect must be a finite number > 0");
  if (method != "admissible-load" && method != "ritz")
    throw ParseError("--method must be admissible-load or ritz, got \"" + method + "\"");
  (void)degree;
  throw UnsupportedProblem("bpde plate is not available in this build yet");
}

int cmd_blend(const std::string& config_path, const std::string& out_dir) {
  const BlendConfig cfg = read_blend_config(config_path);
  const SmoothingSplineResult r = solve_smoothing_spline(cfg.problem);
  const BSplineNet net = r.spline.to_bspline_net();
  const TriangleMesh mesh = r.spline.sample(cfg.samples);
  Json report = {{"problem", "blend"},
                 {"energy", r.functional},
                 {"data_misfit", r.data_misfit},
                 {"L_energy", r.energy},
                 {"max_data_error", r.max_data_error},
                 {"converged", r.summary.converged},
                 {"seconds", r.summary.seconds}};
  if (!r.summary.message.empty()) report["message"] = r.summary.message;
  return write_result(out_dir, Net(net), mesh, cfg.samples, report, Json::object(), r.summary.converged);
}

int cmd_demo(const std::string& out_dir) {
  // Until the CMC solver lands: sample a built-in triangular net over a circle boundary.
  const int n = 6;
  TriangularNet net(n);
  for (int r = 0; r < net.size(); ++r) {
    const MultiIndex I = TriangularNet::multi_index(n, r);
    const double u = static_cast<double>(I[0]) / n, v = static_cast<double>(I[1]) / n;
    net.points().row(r) << u - 0.5 * v, 0.8660254037844386 * v, 0.5 * u * v;
  }
  const TriangleMesh mesh = sample_mesh(net, 50);
  make_output_dir(out_dir);
  write_surface_files(out_dir, net, mesh);
  write_json_file(out_dir + "/net.json", net_to_json(net));
  std::printf("bpde demo: sampled a built-in degree-%d triangular net into %s\n", n, out_dir.c_str());
  return 0;
}

}  // namespace bpde::app
