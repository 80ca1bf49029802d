// 004-cmc-circle: Arnal–Lluch–Monterde (triangular CMC) Fig. 1 — CMC critical points spanning the unit
// circle split into three arcs (boundaries/reference_boundaries.h: circle_three_arcs), H = −1.5, −1,
// −0.5, at the paper's degree n = 4 and at n = 5, 6, 8, 10; and the fold of the H-branch per degree.
//
// Usage: example_004_cmc_circle [--write-jobs] [EXAMPLE_DIR [OUT_DIR]]
//   EXAMPLE_DIR defaults to examples/004-cmc-circle, OUT_DIR to out/004-cmc-circle.
//   --write-jobs regenerates the job files of EXAMPLE_DIR from the library's boundary.
// Prints three Markdown tables (README.md holds their output):
//   1. every job file of EXAMPLE_DIR through read_job_file / run_job / write_outcome (the same path
//      as `bpde solve`): exit status, D_H, D, V, mean-curvature statistics, self-intersections;
//   2. the same quantities for the degree sweep (jobs built in memory);
//   3. the fold: the last H reached on the branch from H = 0 towards H = −10 (and +10).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "examples/common/generated.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace fs = std::filesystem;
using bpde::Json;

namespace {

constexpr int kSamples = 40;

Json job_json(const bpde::TriangularNet& net, double H) {
  return {{"net", bpde::net_to_json(net)},
          {"fixed", "boundary"},
          {"problem", {{"kind", "cmc"}, {"H", H}, {"solver", "newton"}}},
          {"samples", kSamples}};
}

std::string fmt(const char* f, double x) {
  char b[64];
  std::snprintf(b, sizeof b, f, x);
  return b;
}

// One table row: the job's name, degree, H, then the outcome (exit 0) or the fold message (exit 1).
void row(const std::string& name, const bpde::Job& job, const fs::path* out_dir) {
  const bpde::SolveOutcome o = bpde::run_job(job);
  const int n = std::get<bpde::TriangularNet>(job.net).n();
  int status = o.converged ? 0 : 1;
  if (out_dir) status = bpde::write_outcome((*out_dir / name).string(), job, o);
  std::printf("| %s | %d | %g | %d |", name.c_str(), n, job.problem.H, status);
  if (!o.converged) {
    std::printf(" %s | | | | | |\n", o.report.value("message", std::string("?")).c_str());
    return;
  }
  const bpde::TriangleMesh mesh = bpde::sample_net(o.net, job.samples);
  const Json mc = bpde::mean_curvature_stats(o.net, mesh, job.samples);
  const int si = bpde::check_report(mesh)["self_intersections"].get<int>();
  std::printf(" %.6f | %.6f | %.6f | %.3f | %.3f / %.3f | %d |\n", o.report["energy"].get<double>(),
              o.report["D"].get<double>(), o.report["volume"].get<double>(), mc["mean"].get<double>(),
              mc["min"].get<double>(), mc["max"].get<double>(), si);
}

const char* kHeader =
    "| job | n | H | exit | D_H | D | V | H mean | H min / max | self-intersections |\n"
    "|---|---|---|---|---|---|---|---|---|---|\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool write_jobs = std::erase(args, std::string("--write-jobs")) > 0;
  const fs::path dir = args.size() > 0 ? args[0] : "examples/004-cmc-circle";
  const fs::path out = args.size() > 1 ? args[1] : "out/004-cmc-circle";

  if (write_jobs) {
    // The paper's three surfaces (n = 4, in the paper's order a, b, c), and n = 6 at H = −1.5,
    // which lies past the fold of the branch (exit 1, the documented outcome).
    const std::vector<std::pair<std::string, double>> paper = {{"a", -1.5}, {"b", -1.0}, {"c", -0.5}};
    for (const auto& [tag, H] : paper)
      bpde::write_json_file((dir / ("n4-" + tag + "-H" + fmt("%g", H) + ".json")).string(),
                            job_json(bpde::circle_three_arcs(4), H));
    bpde::write_json_file((dir / "n6-H-1.5-past-fold.json").string(), job_json(bpde::circle_three_arcs(6), -1.5));
  }

  // 1. The job files (as `bpde solve` runs them).
  std::vector<fs::path> jobs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") jobs.push_back(e.path());
  std::sort(jobs.begin(), jobs.end());
  std::printf("### Job files\n\n");
  {
    const bpde::examples::GeneratedSection section("cmc-circle-jobs");
    std::printf("%s", kHeader);
    for (const auto& p : jobs) row(p.stem().string(), bpde::read_job_file(p.string()), &out);
  }

  // 2. Degree sweep.
  std::printf("\n### Degree sweep (newton)\n\n");
  std::optional<bpde::examples::GeneratedSection> section;
  section.emplace("cmc-circle-sweep");
  std::printf("%s", kHeader);
  for (int n : {4, 5, 6, 8, 10})
    for (double H : {-1.5, -1.0, -0.5}) {
      bpde::Job job;
      job.net = bpde::circle_three_arcs(n);
      job.problem.kind = bpde::ProblemKind::CmcH;
      job.problem.H = H;
      job.samples = kSamples;
      row("sweep", job, nullptr);
    }

  // 3. The fold per degree: continue towards H = ∓10; the solve stops at the fold.
  section.reset();
  std::printf("\n### Fold of the branch from H = 0\n\n");
  section.emplace("cmc-circle-fold");
  std::printf(
      "| n | fold H < 0 | fold H > 0 | V at the fold (H < 0) | steps "
      "|\n|---|---|---|---|---|\n");
  for (int n : {4, 5, 6, 7, 8, 10, 12}) {
    bpde::CmcOptions o;
    o.H = -10;
    const auto neg = bpde::solve_cmc(bpde::circle_three_arcs(n), o);
    o.H = 10;
    const auto pos = bpde::solve_cmc(bpde::circle_three_arcs(n), o);
    std::printf("| %d | %.4f | %.4f | %.4f | %d |\n", n, neg.H, pos.H, neg.V, neg.continuation_steps);
  }
  return 0;
}
