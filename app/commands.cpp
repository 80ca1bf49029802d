#include "app/commands.h"

#include <cstdio>
#include <iostream>

#include "core/errors.h"
#include "io/blend_config.h"
#include "io/mesh_io.h"
#include "jobs/run_blend.h"
#include "jobs/run_demo.h"
#include "jobs/run_energy.h"
#include "jobs/run_job.h"
#include "jobs/run_plate.h"

namespace bpde::app {

namespace {

void check_samples(int samples) {
  if (samples < 1 || samples > kMaxSamples)
    throw ParameterError("--samples must be in 1.." + std::to_string(kMaxSamples) + ", got " + std::to_string(samples));
}

}  // namespace

int cmd_solve(const std::string& job_path, const std::string& out_dir) {
  const Job job = read_job_file(job_path);
  const SolveOutcome out = run_job(job);
  return write_outcome(out_dir, job, out);
}

int cmd_sample(const std::string& net_path, const std::string& out_dir, int samples) {
  check_samples(samples);
  const Net net = read_net_file(net_path);
  const TriangleMesh mesh = sample_net(net, samples);
  make_output_dir(out_dir);
  write_surface_files(out_dir, net, mesh);
  return 0;
}

int cmd_energy(const std::string& net_path, const std::string& energy, std::optional<double> H) {
  const Net net = read_net_file(net_path);
  std::cout << energy_report(net, energy, H).dump() << "\n";
  return 0;
}

int cmd_check(const std::string& net_path, int samples) {
  check_samples(samples);
  const Net net = read_net_file(net_path);
  std::cout << check_report(sample_net(net, samples)).dump() << "\n";
  return 0;
}

int cmd_plate(double aspect, int degree, const std::string& method) {
  const PlateOutcome out = run_plate(aspect, degree, method);
  std::cout << out.report.dump() << "\n";
  return exit_code(out.status);
}

int cmd_blend(const std::string& config_path, const std::string& out_dir) {
  const BlendConfig config = read_blend_config(config_path);
  const BlendOutcome out = run_blend(config);
  return write_blend_outcome(out_dir, config, out);
}

int cmd_demo(const std::string& out_dir) {
  const Job job = demo_job(), area_job = demo_area_job();
  const SolveOutcome out = run_job(job), area = run_job(area_job);
  const std::string area_dir = out_dir + "/area";
  const WrittenResult written = write_job_result(out_dir, job, out);
  const WrittenResult written_area = write_job_result(area_dir, area_job, area);
  const double H = job.problem.H;
  std::fputs(demo_summary(written.result["report"], written_area.result["report"],
                          unit_circle_cap_distance(std::get<TriangularNet>(out.net), H),
                          unit_circle_cap_distance(std::get<TriangularNet>(area.net), H), out_dir, area_dir)
                 .c_str(),
             stdout);
  // The paper's job decides the exit status (as before); the area result's status is printed.
  return written.exit_code;
}

}  // namespace bpde::app
