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
#include "jobs/run_job.h"
#include "energies/cmc.h"
#include "energies/quadratic_energy.h"
#include "energies/triangular_gram.h"
#include "solvers/bspline/bspline_extremal.h"
#include "solvers/c1/clamped_plate.h"
#include "boundaries/reference_boundaries.h"
#include "solvers/blend/smoothing_spline.h"

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

namespace {

// Energies of nets with huge coordinates overflow; say so instead of printing null.
double finite_energy(double x, const char* what) {
  if (!std::isfinite(x))
    throw NonFiniteError(std::string(what) + " overflows: the net's coordinates are too large");
  return x;
}

}  // namespace

int cmd_energy(const std::string& net_path, const std::string& energy, std::optional<double> H) {
  const Net net = read_net_file(net_path);
  if (H && !std::isfinite(*H)) throw NonFiniteError("--H is not finite");
  if (energy == "cmc") {
    if (!H) throw ParseError("--energy cmc needs --H");
    CmcEnergies e;
    if (const auto* t = std::get_if<TensorNet>(&net))
      e = cmc_energies(*t, *H);
    else if (const auto* tr = std::get_if<TriangularNet>(&net))
      e = cmc_energies(*tr, *H);
    else
      throw UnsupportedProblem("energy cmc needs a triangular or tensor net, not a " + net_kind(net) + " net");
    std::cout << Json{{"D", finite_energy(e.D, "D")}, {"V", finite_energy(e.V, "V")}, {"DH", finite_energy(e.DH, "D + 2HV")}}.dump() << "\n";
    return 0;
  }
  const EnergySpec spec = energy_from_argument(energy);
  if (const auto* t = std::get_if<TensorNet>(&net)) {
    std::cout << Json{{"energy", finite_energy(energy_value(*t, spec), "the energy")}}.dump() << "\n";
    return 0;
  }
  if (const auto* t = std::get_if<TriangularNet>(&net)) {
    const Eigen::MatrixXd Q = triangular_gram(t->n(), spec);
    const Eigen::MatrixX3d& P = t->points();
    std::cout << Json{{"energy", finite_energy(0.5 * (P.transpose() * Q * P).trace(), "the energy")}}.dump() << "\n";
    return 0;
  }
  if (const auto* b = std::get_if<BSplineNet>(&net)) {
    std::cout << Json{{"energy", finite_energy(bspline_energy(*b, spec), "the energy")}}.dump() << "\n";
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
  ClampedPlateOptions o;
  o.aspect = aspect;
  o.degree = degree;
  o.method = parse_plate_method(method);
  const ClampedPlateResult r = solve_clamped_plate(o);
  Json j = {{"center_deflection", r.center_deflection},
            {"energy", r.energy},
            {"aspect", aspect},
            {"degree", degree},
            {"method", method},
            {"converged", r.summary.converged},
            {"seconds", r.summary.seconds}};
  if (!r.summary.message.empty()) j["message"] = r.summary.message;
  std::cout << j.dump() << "\n";
  return r.summary.converged ? 0 : 1;
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
  // The main job: the Fig. 1 set-up of Arnal–Lluch–Monterde (triangular CMC). A unit circle split into three arcs bounds a
  // degree-4 triangular net (the paper's degree: its ansatz uses P_112, P_121, P_211); the CMC critical point of D + 2HV at H = -1 on the branch from
  // the Dirichlet extremal (Newton with the exact Hessian), checked with CGAL.
  Job job{circle_three_arcs(4), FixedSet::Boundary, {}, 50};
  job.problem.kind = ProblemKind::CmcH;
  job.problem.H = -1.0;
  job.problem.solver = CmcSolver::Newton;
  const SolveOutcome out = run_job(job);
  const int status = write_outcome(out_dir, job, out);
  const Json result = read_json_file(out_dir + "/result.json");
  const Json& r = result["report"];
  std::printf("bpde demo: CMC approximation (Arnal-Lluch-Monterde Fig. 1): circle in three arcs, triangular degree 4, H = -1\n");
  std::printf("  converged           %s (%d Newton iterations, %d continuation steps)\n",
              r["converged"].get<bool>() ? "yes" : "no", r.value("iterations", 0), r.value("continuation_steps", 0));
  if (r.contains("message")) std::printf("  message             %s\n", r["message"].get<std::string>().c_str());
  std::printf("  energy D + 2HV      %.12g\n", r["energy"].is_number() ? r["energy"].get<double>() : NAN);
  std::printf("  Dirichlet energy D  %.12g\n", r["D"].is_number() ? r["D"].get<double>() : NAN);
  std::printf("  volume V            %.12g\n", r["volume"].is_number() ? r["volume"].get<double>() : NAN);
  if (r["mean_curvature"].is_object())
    std::printf("  mean curvature      min %.6g, max %.6g, mean %.6g (away from the corners)\n",
                r["mean_curvature"]["min"].get<double>(), r["mean_curvature"]["max"].get<double>(),
                r["mean_curvature"]["mean"].get<double>());
  std::printf("  self-intersections  %d\n", r["check"]["self_intersections"].get<int>());
  std::printf("  files               %s/{result.json, surface.obj, surface.ply, net.obj}\n", out_dir.c_str());
  return status;
}

}  // namespace bpde::app
