#include "app/commands.h"

#include <cstdio>
#include <iostream>

#include "app/inputs.h"
#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/blend_config.h"
#include "bezierpde/io/html_view.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/io/output_folder.h"
#include "bezierpde/io/step_export.h"
#include "bezierpde/jobs/job_progress.h"
#include "bezierpde/jobs/complex_exports.h"
#include "bezierpde/jobs/exports.h"
#include "bezierpde/jobs/run_blend.h"
#include "bezierpde/jobs/run_demo.h"
#include "bezierpde/jobs/run_energy.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/jobs/run_plate.h"
#include "bezierpde/jobs/solve_summary.h"

namespace bpde::app {

namespace {

void check_samples(int samples) {
  if (samples < 1 || samples > kMaxSamples)
    throw ParameterError(samples_limit_message("--samples", samples));
}

// sample_net with its progress stage.
TriangleMesh sampled(const Net& net, int samples) {
  const ProgressStage stage(job_progress(), kSamplingStage);
  return sample_net(net, samples, job_progress());
}

// sample_complex with its progress stage (the welded mesh of a complex, complex/complex_mesh.h).
ComplexMesh sampled(const PatchComplex& c, int samples) {
  const ProgressStage stage(job_progress(), kSamplingStage);
  return sample_complex(c, samples);
}

}  // namespace

int cmd_solve(const std::string& job_path, const std::string& out_dir, const SolveFlags& flags) {
  if (flags.samples) check_samples(*flags.samples);
  Job job = read_job_input(job_path);
  if (flags.samples) job.samples = *flags.samples;
  if (flags.html) job.export_html = true;
  Exports exports;
  exports.html = job.export_html;
  exports.step = job.export_step;
  const std::vector<std::string> files = output_file_names(true, exports);
  check_output_dir(out_dir, files);
  if (exports.step) step_plugin_path();  // a missing STEP plugin fails before the solve, not after it
  const SolveOutcome out = run_job(job);
  const WrittenResult written = write_job_result(out_dir, job, out);
  if (!flags.quiet) std::fputs(solve_summary(out, written, job_path, out_dir, files).c_str(), stdout);
  return written.exit_code;
}

int cmd_sample(const std::string& net_path, const std::string& out_dir, int samples, const std::string& mesh_format,
               bool quiet) {
  check_samples(samples);
  const MeshFormat format = mesh_format_from_string(mesh_format, "--mesh-format");
  const AnyNet input = read_any_net_input(net_path);
  check_output_dir(out_dir, surface_file_names());
  if (const auto* complex = std::get_if<ComplexNetFile>(&input)) {
    const ComplexMesh m = sampled(complex->complex, samples);
    {
      const ProgressStage stage(job_progress(), kWritingFilesStage);
      write_complex_surface_files(out_dir, complex->complex, m, format);
    }
    if (!quiet) std::fputs(files_line(out_dir, surface_file_names()).c_str(), stdout);
    return 0;
  }
  const Net& net = std::get<Net>(input);
  const TriangleMesh mesh = sampled(net, samples);
  {
    const ProgressStage stage(job_progress(), kWritingFilesStage);
    write_output_files(out_dir, nullptr, net, mesh, format);
  }
  if (!quiet) std::fputs(files_line(out_dir, surface_file_names()).c_str(), stdout);
  return 0;
}

int cmd_energy(const std::string& net_path, const std::string& energy, std::optional<double> H) {
  const Net net = read_net_input(net_path);
  std::cout << energy_report(net, energy, H).dump() << "\n";
  return 0;
}

int cmd_check(const std::string& net_path, int samples) {
  check_samples(samples);
  const AnyNet input = read_any_net_input(net_path);
  const TriangleMesh mesh = std::holds_alternative<ComplexNetFile>(input)
                                ? sampled(std::get<ComplexNetFile>(input).complex, samples).mesh
                                : sampled(std::get<Net>(input), samples);
  Json report;
  {
    const ProgressStage stage(job_progress(), kMeshCheckStage);
    report = check_report(mesh);
  }
  std::cout << report.dump() << "\n";
  return 0;
}

int cmd_plate(double aspect, int degree, const std::string& method) {
  const PlateOutcome out = run_plate(aspect, degree, method);
  std::cout << out.report.dump() << "\n";
  return exit_code(out.status);
}

int cmd_blend(const std::string& config_path, const std::string& out_dir) {
  const BlendConfig config = read_blend_input(config_path);
  check_output_dir(out_dir);
  const BlendOutcome out = run_blend(config);
  return write_blend_outcome(out_dir, config, out);
}

int cmd_view(const std::string& dir, int samples, bool quiet) {
  check_samples(samples);
  const std::string path = dir + "/result.json";
  const Json result = read_json_file(path);
  json_read::require_object(result, path);
  const AnyNet input = any_net_from_json(json_read::field(result, path, "net"), path + ".net");
  const Json report = result.contains("report") ? result["report"] : Json::object();
  OutputFolder out(dir, {"view.html"});
  if (const auto* complex = std::get_if<ComplexNetFile>(&input)) {
    const PatchComplex& c = complex->complex;
    const ComplexMesh m = sampled(c, samples);
    write_view_html(out.file("view.html"), c, m, complex_surface_fields(c, m), report, view_title(c, report), samples);
  } else {
    const Net& net = std::get<Net>(input);
    write_view_html(out.file("view.html"), net, sampled(net, samples), report, view_title(net, report));
  }
  out.commit();
  if (!quiet) std::fputs(files_line(dir, {"view.html"}).c_str(), stdout);
  return 0;
}

int cmd_export(const std::string& net_path, const std::string& step_path, bool quiet) {
  const AnyNet input = read_any_net_input(net_path);
  if (const auto* complex = std::get_if<ComplexNetFile>(&input))
    write_step(step_path, complex->complex);
  else
    write_step(step_path, std::get<Net>(input));
  if (!quiet) std::fputs(files_line("", {step_path}).c_str(), stdout);
  return 0;
}

int cmd_demo(const std::string& out_dir) {
  const Job job = demo_job(), area_job = demo_area_job(), mc_job = demo_mean_curvature_job();
  const std::string area_dir = out_dir + "/area", mc_dir = out_dir + "/mean-curvature";
  check_output_dir(out_dir);
  check_output_dir(area_dir);
  check_output_dir(mc_dir);
  const SolveOutcome out = run_job(job), area = run_job(area_job), mc = run_job(mc_job);
  const WrittenResult written = write_job_result(out_dir, job, out);
  const WrittenResult written_area = write_job_result(area_dir, area_job, area);
  const WrittenResult written_mc = write_job_result(mc_dir, mc_job, mc);
  const double H = job.problem.H;
  auto dist = [&](const SolveOutcome& o) { return unit_circle_cap_distance(std::get<TriangularNet>(o.net), H); };
  std::fputs(demo_summary({{"D + 2HV (the paper)", written.result["report"], dist(out), out_dir},
                           {"A + 2HV (area)", written_area.result["report"], dist(area), area_dir},
                           {"(H_x - H)^2 (least squares)", written_mc.result["report"], dist(mc), mc_dir}})
                 .c_str(),
             stdout);
  // The paper's job decides the exit status (as before); the other results' status is printed.
  return written.exit_code;
}

}  // namespace bpde::app
