// 004-cmc-c1-triangle: Arnal–Lluch–Monterde (triangular CMC) §5, Figs. 3–4 — the C¹ problem: the boundary
// control points lie along a planar equilateral triangle and the next line of control points
// ("three more lines", Fig. 3) is prescribed too (fixed = "boundary+adjacent"); the remaining
// interior points solve eq. (11) for H = −2, −1.5, −1 (Fig. 4).
//
// Set-up (the paper prints no numbers): corners P_{n00} = (1,0,0), P_{0n0} at 120°, P_{00n} at 240°
// on the unit circle in z = 0 (counter-clockwise P_{00n} → P_{n00} → P_{0n0}, so H < 0 bulges
// towards +z, FORMATS.md); every control point sits above its barycentric position
// (I¹ P_{n00} + I² P_{0n0} + I³ P_{00n})/n; the boundary at z = 0, the adjacent ring (smallest index
// 1) lifted to z = kLift. The free points start at z = 0 (the solver ignores them anyway).
//
// Usage: example_004_cmc_c1_triangle [--write-jobs] [EXAMPLE_DIR [OUT_DIR]]
//   EXAMPLE_DIR defaults to examples/004-cmc-c1-triangle, OUT_DIR to out/004-cmc-c1-triangle.
// Prints Markdown tables (README.md holds their output): the job files through run_job (as
// `bpde solve`), then a degree sweep and the fold of the branch from H = 0 per degree.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "examples/common/generated.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace fs = std::filesystem;
using bpde::Json;

namespace {

constexpr int kSamples = 40;
constexpr int kDegree = 6;      // the lowest degree with a free point for C¹ data: P_222
constexpr double kLift = 0.25;  // height of the adjacent ring

bpde::TriangularNet c1_triangle(int n, double lift) {
  const double a = 2 * std::numbers::pi / 3;
  const Eigen::Vector3d c1(1, 0, 0), c2(std::cos(a), std::sin(a), 0), c3(std::cos(2 * a), std::sin(2 * a), 0);
  bpde::TriangularNet net(n);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; i + j <= n; ++j) {
      const int k = n - i - j;
      Eigen::Vector3d p = (i * c1 + j * c2 + k * c3) / n;
      p.z() = std::min({i, j, k}) == 1 ? lift : 0.0;
      net.set_point(i, j, p);
    }
  return net;
}

Json job_json(const bpde::TriangularNet& net, double H) {
  return {{"net", bpde::net_to_json(net)},
          {"fixed", "boundary+adjacent"},
          {"problem", {{"kind", "cmc"}, {"H", H}, {"solver", "newton"}}},
          {"samples", kSamples}};
}

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", x);
  return b;
}

void row(const std::string& name, const bpde::Job& job, const fs::path* out) {
  const bpde::SolveOutcome o = bpde::run_job(job);
  const auto& net = std::get<bpde::TriangularNet>(o.net);
  int status = o.converged ? 0 : 1;
  if (out) status = bpde::write_outcome((*out / name).string(), job, o);
  std::printf("| %s | %d | %g | %d |", name.c_str(), net.n(), job.problem.H, status);
  if (!o.converged) {
    std::printf(" %s | | | | | | |\n", o.report.value("message", std::string("?")).c_str());
    return;
  }
  const bpde::TriangleMesh mesh = bpde::sample_net(o.net, job.samples);
  const Json mc = bpde::mean_curvature_stats(o.net, mesh, job.samples);
  std::printf(" %.6f | %.6f | %.6f | %.4f | %.4f | %.3f / %.3f / %.3f | %d |\n", o.report["energy"].get<double>(),
              o.report["D"].get<double>(), o.report["volume"].get<double>(), net.evaluate(1.0 / 3, 1.0 / 3).z(),
              mesh.V.col(2).maxCoeff(), mc["min"].get<double>(), mc["mean"].get<double>(), mc["max"].get<double>(),
              bpde::check_report(mesh)["self_intersections"].get<int>());
}

const char* kHeader =
    "| job | n | H | exit | D_H | D | V | z(⅓,⅓) | max z | H min / mean / max | self-intersections |\n"
    "|---|---|---|---|---|---|---|---|---|---|---|\n";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool write_jobs = std::erase(args, std::string("--write-jobs")) > 0;
  const fs::path dir = args.size() > 0 ? args[0] : "examples/004-cmc-c1-triangle";
  const fs::path out = args.size() > 1 ? args[1] : "out/004-cmc-c1-triangle";

  if (write_jobs) {
    const std::vector<std::pair<std::string, double>> paper = {{"a", -2.0}, {"b", -1.5}, {"c", -1.0}};  // Fig. 4 order
    for (const auto& [tag, H] : paper) {
      char name[64];
      std::snprintf(name, sizeof name, "n%d-%s-H%g.json", kDegree, tag.c_str(), H);
      bpde::write_json_file((dir / name).string(), job_json(c1_triangle(kDegree, kLift), H));
    }
  }

  std::vector<fs::path> jobs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") jobs.push_back(e.path());
  std::sort(jobs.begin(), jobs.end());
  std::printf("### Job files (lift %g)\n\n", kLift);
  std::optional<bpde::examples::GeneratedSection> section;
  section.emplace("cmc-c1-triangle-jobs");
  std::printf("%s", kHeader);
  for (const auto& p : jobs) row(p.stem().string(), bpde::read_job_file(p.string()), &out);
  section.reset();

  std::printf("\n### Degree sweep (lift %g)\n\n", kLift);
  section.emplace("cmc-c1-triangle-sweep");
  std::printf("%s", kHeader);
  for (int n : {6, 7, 8, 10})
    for (double H : {0.0, -1.0, -1.5, -2.0}) {
      bpde::Job job;
      job.net = c1_triangle(n, kLift);
      job.fixed = bpde::FixedSet::BoundaryAdjacent;
      job.problem.kind = bpde::ProblemKind::CmcH;
      job.problem.H = H;
      job.samples = kSamples;
      row("sweep", job, nullptr);
    }

  section.reset();
  std::printf("\n### Fold of the branch from H = 0 (lift %g)\n\n", kLift);
  section.emplace("cmc-c1-triangle-fold");
  std::printf("| n | free points | fold H < 0 | fold H > 0 |\n|---|---|---|---|\n");
  for (int n : {6, 7, 8, 10}) {
    const bpde::TriangularNet d = c1_triangle(n, kLift);
    auto fold = [&](double H) {
      bpde::CmcOptions o;
      o.H = H;
      o.fixed = bpde::FixedSet::BoundaryAdjacent;
      const auto r = bpde::solve_cmc(d, o);
      return r.summary.converged ? fmt(H) + " reached" : fmt(r.H);
    };
    std::printf("| %d | %zu | %s | %s |\n", n, d.free_indices(bpde::FixedSet::BoundaryAdjacent).size(),
                fold(-100).c_str(), fold(100).c_str());
  }
  return 0;
}
