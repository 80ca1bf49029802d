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
  bool html = false;
  solve->add_flag("--html", html, "Also write DIR/view.html, the self-contained web viewer");

  std::string mesh_format = "ascii";
  auto* sample = app.add_subcommand("sample", "Write surface.obj, surface.ply, surface.vtp and net.obj for any net");
  sample->add_option("net", in, "NET.json")->required();
  sample->add_option("--out", out, "Output directory")->required();
  sample->add_option("--samples", samples, "Mesh resolution N (default 50)");
  sample->add_option("--mesh-format", mesh_format, "surface.ply/.vtp numbers: ascii (default) or binary (float32)");

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

  auto* view = app.add_subcommand("view", "Write DIR/view.html (web viewer) for the result.json in DIR");
  view->add_option("dir", in, "DIR holding result.json")->required();
  view->add_option("--samples", samples, "Mesh resolution N (default 50)");

  std::string step_path;
  auto* exp = app.add_subcommand("export", "Write the exact patch of a net for CAD (STEP, through OpenCASCADE)");
  exp->add_option("net", in, "NET.json")->required();
  exp->add_option("--step", step_path, "FILE.step")->required();

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
    if (*solve) return cmd_solve(in, out, html);
    if (*sample) return cmd_sample(in, out, samples, mesh_format);
    if (*en) return cmd_energy(in, energy, H);
    if (*check) return cmd_check(in, samples);
    if (*plate) return cmd_plate(aspect, degree, method);
    if (*blend) return cmd_blend(in, out);
    if (*view) return cmd_view(in, samples);
    if (*exp) return cmd_export(in, step_path);
    if (*demo) return cmd_demo(demo_out);
  } catch (...) {
    // InvalidInput: exit 2; out of memory, broken invariants, anything else: exit 3.
    const bpde::ErrorExit x = bpde::error_exit(std::current_exception());
    std::fputs(x.line.c_str(), stderr);
    return x.code;
  }
  return 2;
}
