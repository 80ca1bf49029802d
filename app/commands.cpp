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
#include "solvers/smoothing_spline.h"

namespace bpde::app {
namespace {

void make_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir)) throw FileError("cannot create output directory '" + dir + "'");
}

Json check_json(const TriangleMesh& mesh) {
  std::vector<double> V(static_cast<size_t>(mesh.V.rows()) * 3);
  for (Eigen::Index r = 0; r < mesh.V.rows(); ++r)
    for (int c = 0; c < 3; ++c) V[static_cast<size_t>(3 * r + c)] = mesh.V(r, c);
  std::vector<int> F(static_cast<size_t>(mesh.F.rows()) * 3);
  for (Eigen::Index r = 0; r < mesh.F.rows(); ++r)
    for (int c = 0; c < 3; ++c) F[static_cast<size_t>(3 * r + c)] = mesh.F(r, c);
  const MeshCheckReport rep = check_mesh(V, F);
  Json j = {{"self_intersections", rep.self_intersections}, {"closed", rep.closed}, {"cone_volume", rep.cone_volume}};
  j["volume"] = rep.volume ? Json(*rep.volume) : Json(nullptr);
  return j;
}

// {min, max, mean} of H over the sample grid, leaving out samples within parameter distance
// 0.1 (relative to the domain) of a corner, where a circle split into arcs is nearly singular.
Json mean_curvature_stats(const Net& net, const TriangleMesh& mesh, int N) {
  std::vector<double> vals;
  auto add = [&](double du, double dv, Eigen::Index k, const std::vector<std::pair<double, double>>& corners) {
    for (auto [cu, cv] : corners)
      if (std::hypot(du - cu, dv - cv) < 0.1) return;
    vals.push_back(mesh.H(k));
  };
  if (std::holds_alternative<TriangularNet>(net)) {
    const Eigen::MatrixX2d uv = triangular_sample_parameters(N);
    for (Eigen::Index k = 0; k < uv.rows(); ++k) add(uv(k, 0), uv(k, 1), k, {{0, 0}, {1, 0}, {0, 1}});
  } else {
    for (int a = 0; a <= N; ++a)
      for (int b = 0; b <= N; ++b)
        add(static_cast<double>(a) / N, static_cast<double>(b) / N, a * (N + 1) + b, {{0, 0}, {1, 0}, {0, 1}, {1, 1}});
  }
  if (vals.empty()) return nullptr;
  double mn = vals[0], mx = vals[0], sum = 0;
  for (double v : vals) {
    mn = std::min(mn, v);
    mx = std::max(mx, v);
    sum += v;
  }
  return {{"min", mn}, {"max", mx}, {"mean", sum / static_cast<double>(vals.size())}};
}

}  // namespace

SolveOutcome run_job(const Job& job) {
  throw UnsupportedProblem("problem \"" + to_string(job.problem.kind) + "\" on a " + net_kind(job.net) +
                           " net: this solver is not available in this build yet");
}

namespace {

// result.json + surface files for a net and its sampled mesh; the report gains the mean-curvature
// statistics and the CGAL figures unless the solver already set them.
int write_result(const std::string& dir, const Net& net, const TriangleMesh& mesh, int samples, Json report,
                 const Json& extra, bool converged) {
  if (!report.contains("mean_curvature")) report["mean_curvature"] = mean_curvature_stats(net, mesh, samples);
  if (!report.contains("check")) report["check"] = check_json(mesh);
  Json result = {{"net", net_to_json(net)}, {"report", report}};
  for (auto it = extra.begin(); it != extra.end(); ++it) result[it.key()] = it.value();
  make_dir(dir);
  write_json_file(dir + "/result.json", result);
  write_surface_files(dir, net, mesh);
  return converged ? 0 : 1;
}

}  // namespace

int write_outcome(const std::string& dir, const Job& job, const SolveOutcome& out) {
  const TriangleMesh mesh = sample_net(out.net, job.samples);
  return write_result(dir, out.net, mesh, job.samples, out.report, out.extra, out.converged);
}

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
  make_dir(out_dir);
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
  (void)spec;
  throw UnsupportedProblem("energy " + spec.name() + " on a " + net_kind(net) + " net is not available in this build yet");
}

int cmd_check(const std::string& net_path, int samples) {
  if (samples < 1 || samples > kMaxSamples)
    throw ParameterError("--samples must be in 1.." + std::to_string(kMaxSamples) + ", got " + std::to_string(samples));
  const Net net = read_net_file(net_path);
  std::cout << check_json(sample_net(net, samples)).dump() << "\n";
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
  make_dir(out_dir);
  write_surface_files(out_dir, net, mesh);
  write_json_file(out_dir + "/net.json", net_to_json(net));
  std::printf("bpde demo: sampled a built-in degree-%d triangular net into %s\n", n, out_dir.c_str());
  return 0;
}

}  // namespace bpde::app
