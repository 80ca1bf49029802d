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
    throw ParameterError(samples_limit_message("--samples", samples));
}

}  // namespace

int cmd_solve(const std::string& job_path, const std::string& out_dir) {
  const Job job = read_job_file(job_path);
  check_output_dir(out_dir);
  const SolveOutcome out = run_job(job);
  return write_outcome(out_dir, job, out);
}

int cmd_sample(const std::string& net_path, const std::string& out_dir, int samples) {
  check_samples(samples);
  const Net net = read_net_file(net_path);
  check_output_dir(out_dir, surface_file_names());
  const TriangleMesh mesh = sample_net(net, samples);
  write_output_files(out_dir, nullptr, net, mesh);
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
  check_output_dir(out_dir);
  const BlendOutcome out = run_blend(config);
  return write_blend_outcome(out_dir, config, out);
}

int cmd_demo(const std::string& out_dir) {
  const Job job = demo_job();
  check_output_dir(out_dir);
  const SolveOutcome out = run_job(job);
  const WrittenResult written = write_job_result(out_dir, job, out);
  std::fputs(demo_summary(written.result["report"], out_dir).c_str(), stdout);
  return written.exit_code;
}

}  // namespace bpde::app
