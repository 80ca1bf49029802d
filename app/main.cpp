// bpde: the command-line program over the bezierpde library (FORMATS.md).
//
// Exit status: 0 solved; 1 valid input without a solution (result.json still written, with
// "converged": false and a message); 2 bad input (one line `error: ...` on stderr, nothing
// written); 3 internal failure: out of memory or a broken invariant (one line
// `internal error: ...` on stderr; jobs/exit_status.h).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "app/sweep_command.h"
#include "jobs/exit_status.h"

int main(int argc, char** argv) {
  CLI::App app{"bpde: Bézier surfaces from boundary data by energies and PDEs (bezierpde)"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Show help for every subcommand");

  std::string in, out;
  int samples = 50;

  auto* solve =
      app.add_subcommand("solve", "Solve a job (FORMATS.md \"Jobs\") and write DIR/result.json + surface files");
  solve->add_option("job", in, "JOB.json")->required();
  solve->add_option("--out", out, "Output directory (created if missing)")->required();

  auto* sample = app.add_subcommand("sample", "Write surface.obj, surface.ply and net.obj for any net");
  sample->add_option("net", in, "NET.json")->required();
  sample->add_option("--out", out, "Output directory")->required();
  sample->add_option("--samples", samples, "Mesh resolution N (default 50)");

  std::string energy;
  std::optional<double> H;
  auto* en = app.add_subcommand("energy", "Print the value of an energy of a net as JSON");
  en->add_option("net", in, "NET.json")->required();
  en->add_option("--energy", energy, "Bare name (dirichlet, biharmonic, laplacian-squared, coons, cmc) or ENERGY JSON")
      ->required();
  en->add_option("--H", H, "Mean curvature H (required for cmc)");

  auto* check = app.add_subcommand("check", "CGAL checks of the sampled surface, as JSON");
  check->add_option("net", in, "NET.json")->required();
  check->add_option("--samples", samples, "Mesh resolution N (default 50)");

  double aspect = 1.0;
  int degree = 0;
  std::string method;
  auto* plate = app.add_subcommand("plate", "Clamped plate [0,1]x[0,a] under uniform load (Centella et al. §6)");
  plate->add_option("--aspect", aspect, "Aspect ratio a")->required();
  plate->add_option("--degree", degree, "Bidegree n")->required();
  plate->add_option("--method", method, "admissible-load or ritz")->required();

  auto* blend = app.add_subcommand("blend", "Blending surface by smoothing PDE splines (Pasadas-Rodriguez)");
  blend->add_option("config", in, "CONFIG.json")->required();
  blend->add_option("--out", out, "Output directory")->required();

  int sweep_jobs = 0;
  auto* sweep = app.add_subcommand("sweep", "Run a parameter sweep (FORMATS.md \"Sweeps\"): DIR/jobs/*, results.csv");
  sweep->add_option("sweep", in, "SWEEP.json")->required();
  sweep->add_option("--out", out, "Output directory (rerunning skips the jobs already done)")->required();
  sweep->add_option("--jobs", sweep_jobs, "Jobs run at once (default 0: every core)");

  std::string demo_out = "out/demo";
  auto* demo = app.add_subcommand("demo", "Run the built-in default job (the README's main command)");
  demo->add_option("--out", demo_out, "Output directory (default out/demo)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "error: %s (see bpde --help)\n", bpde::one_line(e.what()).c_str());
    return 2;
  }

  try {
    using namespace bpde::app;
    if (*solve) return cmd_solve(in, out);
    if (*sample) return cmd_sample(in, out, samples);
    if (*en) return cmd_energy(in, energy, H);
    if (*check) return cmd_check(in, samples);
    if (*plate) return cmd_plate(aspect, degree, method);
    if (*blend) return cmd_blend(in, out);
    if (*demo) return cmd_demo(demo_out);
    if (*sweep) return cmd_sweep(in, out, sweep_jobs);
  } catch (...) {
    // InvalidInput: exit 2; out of memory, broken invariants, anything else: exit 3.
    const bpde::ErrorExit x = bpde::error_exit(std::current_exception());
    std::fputs(x.line.c_str(), stderr);
    return x.code;
  }
  return 2;
}
