// bpde: the command-line program over the bezierpde library (FORMATS.md).
//
// Exit status: 0 solved; 1 valid input without a solution (result.json still written, with
// "converged": false and a message); 2 bad input (one line `error: ...` on stderr, nothing
// written); 3 internal failure: out of memory or a broken invariant (one line
// `internal error: ...` on stderr; jobs/exit_status.h).
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <iostream>
#include <new>
#include <optional>

#include "app/commands.h"
#include "app/progress_line.h"
#include "app/version.h"
#include "app/sweep_command.h"
#include "bezierpde/jobs/exit_status.h"
#include "bezierpde/jobs/job_progress.h"
#include "bezierpde/solvers/cmc/ceres_log.h"

namespace {

// The solvers make a fresh Hessian (and its factor or eigen-decomposition) each iteration. Above
// glibc's mmap and trim thresholds each is a new mapping whose every page faults when first
// written; a whole-process tool keeps freed memory instead (docs/performance_measurements.md, "Design decisions":
// the area route on the tensor catenoid at n = 10, 5.31 -> 4.42 s wall). A malloc threshold the
// user sets in the environment is left alone.
void keep_freed_memory() {
#if defined(__GLIBC__)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if ((tunables && (std::strstr(tunables, "glibc.malloc.mmap_threshold") ||
                    std::strstr(tunables, "glibc.malloc.trim_threshold"))) ||
      std::getenv("MALLOC_TRIM_THRESHOLD_") || std::getenv("MALLOC_MMAP_THRESHOLD_"))
    return;
  mallopt(M_MMAP_THRESHOLD, 32 << 20);   // blocks up to 32 MB come from the heap
  mallopt(M_TRIM_THRESHOLD, 256 << 20);  // and up to 256 MB of freed heap stay mapped
#endif
}

// Exit 3 with one line where C++ would abort: an exception that reaches a noexcept boundary
// (nlohmann::json's destructor allocates, so memory running out while a job's JSON is freed
// ends here) or a thread that could not be joined. Fixed strings only: memory may be gone.
[[noreturn]] void terminate_as_internal_error() noexcept {
  const char* line = "internal error: terminated\n";
  if (const std::exception_ptr e = std::current_exception()) {
    try {
      std::rethrow_exception(e);
    } catch (const std::bad_alloc&) {
      line = "internal error: out of memory\n";
    } catch (...) {
      line = "internal error: uncaught exception\n";
    }
  }
  std::fflush(stdout);
  std::fputs(line, stderr);
  std::_Exit(3);
}

}  // namespace

int main(int argc, char** argv) {
  std::set_terminate(terminate_as_internal_error);
  keep_freed_memory();
  bpde::quiet_ceres_log();  // stderr carries bpde's own lines only (ceres_log.h)
  CLI::App app{"bpde: Bézier surfaces from boundary data by energies and PDEs (bezierpde)", "bpde"};
  app.require_subcommand(0, 1);  // bare `bpde` prints the usage (below)
  app.set_version_flag("-V,--version", "bpde " BPDE_VERSION, "Print the version and exit");
  app.set_help_all_flag("--help-all", "Show help for every subcommand");

  std::string in, out;
  int samples = 50;
  bool progress = false;
  const char* progress_help = "Show progress on stderr even when it is not a terminal";

  auto* solve =
      app.add_subcommand("solve", "Solve a job (FORMATS.md \"Jobs\") and write DIR/result.json + surface files");
  solve->add_option("job", in, "JOB.json")->required();
  solve->add_option("--out", out, "Output directory (created if missing)")->required();
  bpde::app::SolveFlags solve_flags;
  solve->add_flag("-q,--quiet", solve_flags.quiet, "Print no summary (errors still go to stderr)");
  solve->add_option("--samples", solve_flags.samples, "Mesh resolution N, overriding the job's \"samples\"");
  solve->add_flag("--progress", progress, progress_help);
  solve->add_flag("--html", solve_flags.html, "Also write DIR/view.html, the self-contained web viewer");

  std::string mesh_format = "ascii";
  auto* sample = app.add_subcommand("sample", "Write surface.obj, surface.ply, surface.vtp and net.obj for any net");
  sample->add_option("net", in, "NET.json (or a result.json of bpde: its net)")->required();
  sample->add_option("--out", out, "Output directory")->required();
  sample->add_option("--samples", samples, "Mesh resolution N (default 50)");
  sample->add_option("--mesh-format", mesh_format, "surface.ply/.vtp numbers: ascii (default) or binary (float32)");
  sample->add_flag("--progress", progress, progress_help);
  bool quiet = false;
  const char* quiet_help = "Print nothing on success (errors still go to stderr)";
  sample->add_flag("-q,--quiet", quiet, quiet_help);

  std::string energy;
  std::optional<double> H;
  auto* en = app.add_subcommand("energy", "Print the value of an energy of a net as JSON");
  en->add_option("net", in, "NET.json (or a result.json of bpde: its net)")->required();
  en->add_option("--energy", energy, "Bare name (dirichlet, biharmonic, laplacian-squared, coons, cmc) or ENERGY JSON")
      ->required();
  en->add_option("--H", H, "Mean curvature H (required for cmc)");

  auto* check = app.add_subcommand("check", "CGAL checks of the sampled surface, as JSON");
  check->add_option("net", in, "NET.json (or a result.json of bpde: its net)")->required();
  check->add_option("--samples", samples, "Mesh resolution N (default 50)");
  check->add_flag("--progress", progress, progress_help);

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
  blend->add_flag("--progress", progress, progress_help);

  auto* view = app.add_subcommand("view", "Write DIR/view.html (web viewer) for the result.json in DIR");
  view->add_option("dir", in, "DIR holding result.json")->required();
  view->add_option("--samples", samples, "Mesh resolution N (default 50)");
  view->add_flag("-q,--quiet", quiet, quiet_help);

  std::string step_path;
  auto* exp = app.add_subcommand("export", "Write the exact patch of a net for CAD (STEP, through OpenCASCADE)");
  exp->add_option("net", in, "NET.json (or a result.json of bpde: its net)")->required();
  exp->add_option("--step", step_path, "FILE.step")->required();
  exp->add_flag("-q,--quiet", quiet, quiet_help);

  int sweep_jobs = 0;
  auto* sweep = app.add_subcommand("sweep", "Run a parameter sweep (FORMATS.md \"Sweeps\"): DIR/jobs/*, results.csv");
  sweep->add_option("sweep", in, "SWEEP.json")->required();
  sweep->add_option("--out", out, "Output directory (rerunning skips the jobs already done)")->required();
  sweep->add_option("--jobs", sweep_jobs, "Jobs run at once (default 0: every core)");
  sweep->add_flag("--progress", progress, "One progress line per job on stderr, also on a terminal (no bar)");

  std::string demo_out = "out/demo";
  auto* demo = app.add_subcommand("demo", "Run the built-in default job (the README's main command)");
  demo->add_option("--out", demo_out, "Output directory (default out/demo)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version: exit 0
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "error: %s (see bpde --help)\n", bpde::one_line(e.what()).c_str());
    return 2;
  }

  if (app.get_subcommands().empty()) {  // bare `bpde`: the usage, as --help prints it
    std::cout << app.help();
    return 0;
  }

  // Progress on stderr (core/progress.h): on a terminal, or forced by --progress. Off, no callback
  // is installed and the library does not format a single progress line.
  std::optional<bpde::app::ProgressLine> line;
  std::optional<bpde::JobProgressScope> scope;
  // A sweep reports per job (app/sweep_command.h): its jobs' stages would interleave.
  if (!*sweep && bpde::app::progress_wanted(progress)) {
    line.emplace(stderr, ::isatty(STDERR_FILENO) == 1);
    scope.emplace(line->callback());
  }

  try {
    using namespace bpde::app;
    if (*solve) return cmd_solve(in, out, solve_flags);
    if (*sample) return cmd_sample(in, out, samples, mesh_format, quiet);
    if (*en) return cmd_energy(in, energy, H);
    if (*check) return cmd_check(in, samples);
    if (*plate) return cmd_plate(aspect, degree, method);
    if (*blend) return cmd_blend(in, out);
    if (*view) return cmd_view(in, samples, quiet);
    if (*exp) return cmd_export(in, step_path, quiet);
    if (*demo) return cmd_demo(demo_out);
    if (*sweep) return cmd_sweep(in, out, sweep_jobs, progress);
  } catch (...) {
    // InvalidInput: exit 2; out of memory, broken invariants, anything else: exit 3.
    const bpde::ErrorExit x = bpde::error_exit(std::current_exception());
    scope.reset();
    line.reset();  // clears the progress line before the one error line
    std::fputs(x.line.c_str(), stderr);
    return x.code;
  }
  return 2;
}
