// 004-cmc-sphere-convergence: CMC critical points (triangular CMC, eq. (11)) with conformal boundary
// data taken from the unit sphere (inverse stereographic projection; boundaries/reference_boundaries.h:
// sphere_triangle, sphere_square) converge to the sphere as the degree grows (docs/errata.md, triangular CMC §4).
//
// Usage: example_004_cmc_sphere_convergence [--write-jobs] [EXAMPLE_DIR [OUT_DIR]]
//   EXAMPLE_DIR defaults to examples/004-cmc-sphere-convergence, OUT_DIR to
//   out/004-cmc-sphere-convergence. --write-jobs regenerates the job files.
// Prints Markdown tables (README.md holds their output):
//   1. the job files through read_job_file / run_job / write_outcome (as `bpde solve`);
//   2. triangular nets, n = 4..16, H = +1: max ||x| − 1| and max |x − x_sphere(u,v)| on a 40-grid,
//      mean-curvature statistics (corners left out, margin 0.1), |H_mean − 1|, solve time;
//   3. the same for tensor nets (sphere_square);
//   4. the sign check: H = −1 with the same data does not give the sphere;
//   5. the fold of the D_H branch from H = 0 (triangular), both signs of H;
//   6. the memory of the D_H functional per degree (docs/cmc_measurements.md).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/energies/cmc.h"
#include "examples/common/generated.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/solvers/cmc/cmc.h"

namespace fs = std::filesystem;
using bpde::Json;

namespace {

constexpr int kGrid = 40;

struct Errors {
  double dist = 0;   // max ||x| - 1|
  double param = 0;  // max |x(u,v) - sphere(u,v)|
};

Errors errors(const bpde::TriangularNet& net) {
  Errors e;
  for (int a = 0; a <= kGrid; ++a)
    for (int b = 0; a + b <= kGrid; ++b) {
      const double u = double(a) / kGrid, v = double(b) / kGrid;
      const Eigen::Vector3d x = net.evaluate(u, v);
      e.dist = std::max(e.dist, std::abs(x.norm() - 1));
      e.param = std::max(e.param, (x - bpde::sphere_triangle(u, v)).norm());
    }
  return e;
}

Errors errors(const bpde::TensorNet& net) {
  Errors e;
  for (int a = 0; a <= kGrid; ++a)
    for (int b = 0; b <= kGrid; ++b) {
      const double u = double(a) / kGrid, v = double(b) / kGrid;
      const Eigen::Vector3d x = net.evaluate(u, v);
      e.dist = std::max(e.dist, std::abs(x.norm() - 1));
      e.param = std::max(e.param, (x - bpde::sphere_square(u, v)).norm());
    }
  return e;
}

template <class NetT>
void sweep_row(const NetT& data, int n, double H) {
  bpde::CmcOptions o;
  o.H = H;
  const auto r = bpde::solve_cmc(data, o);
  if (!r.summary.converged) {
    std::printf("| %d | %s | | | | | |\n", n, r.summary.message.c_str());
    return;
  }
  const Errors e = errors(r.net);
  const bpde::MeanCurvatureStats s = bpde::mean_curvature_stats(r.net, kGrid, 0.1);
  // Distances below 1e-9 are at the rounding of the solve (square n = 16: 2.1e-10 portable,
  // 1.0e-10 with -march=native): printed as the bound "< 1e-09".
  std::printf("| %d | %s | %s | %.7f | %.6f / %.6f | %.1e | %.1f |\n", n, bpde::examples::stable_small(e.dist, 1e-9).c_str(),
              bpde::examples::stable_small(e.param, 1e-9).c_str(), s.mean, s.min, s.max, std::abs(s.mean - H),
              1e3 * r.summary.seconds);
}

const char* kSweepHeader =
    "| n | max \\|\\|x\\| − 1\\| | max \\|x − x_sphere\\| | H mean | H min / max | \\|H_mean − 1\\| | ms |\n"
    "|---|---|---|---|---|---|---|\n";

Json job_json(const bpde::Net& net, double H) {
  return {{"net", bpde::net_to_json(net)},
          {"fixed", "boundary"},
          {"problem", {{"kind", "cmc"}, {"H", H}, {"solver", "newton"}}},
          {"samples", kGrid}};
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool write_jobs = std::erase(args, std::string("--write-jobs")) > 0;
  const fs::path dir = args.size() > 0 ? args[0] : "examples/004-cmc-sphere-convergence";
  const fs::path out = args.size() > 1 ? args[1] : "out/004-cmc-sphere-convergence";

  if (write_jobs) {
    bpde::write_json_file((dir / "triangle-n8.json").string(),
                          job_json(bpde::triangular_boundary(8, bpde::sphere_triangle), 1.0));
    bpde::write_json_file((dir / "square-n8.json").string(),
                          job_json(bpde::tensor_boundary(8, bpde::sphere_square), 1.0));
  }

  // The tables are generated sections of README.md (scripts/docs.sh); the degree sweeps and the
  // fold also stand in docs/cmc_measurements.md. The solve times (ms) are machine-dependent and not
  // compared.
  std::optional<bpde::examples::GeneratedSection> section;
  section.emplace("cmc-sphere-jobs");
  // 1. Job files.
  std::vector<fs::path> jobs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") jobs.push_back(e.path());
  std::sort(jobs.begin(), jobs.end());
  std::printf(
      "#### Job files\n\n| job | H | exit | D_H | V | max \\|\\|x\\| − 1\\| | H mean | self-intersections |\n"
      "|---|---|---|---|---|---|---|---|\n");
  for (const auto& p : jobs) {
    const bpde::Job job = bpde::read_job_file(p.string());
    const bpde::SolveOutcome o = bpde::run_job(job);
    const int status = bpde::write_outcome((out / p.stem()).string(), job, o);
    const bpde::TriangleMesh mesh = bpde::sample_net(o.net, job.samples);
    double dist = 0;
    if (const auto* t = std::get_if<bpde::TriangularNet>(&o.net)) dist = errors(*t).dist;
    if (const auto* q = std::get_if<bpde::TensorNet>(&o.net)) dist = errors(*q).dist;
    std::printf("| %s | %g | %d | %.6f | %.6f | %.1e | %.6f | %d |\n", p.stem().c_str(), job.problem.H, status,
                o.report["energy"].get<double>(), o.report["volume"].get<double>(), dist,
                bpde::mean_curvature_stats(o.net, mesh, job.samples)["mean"].get<double>(),
                bpde::check_report(mesh)["self_intersections"].get<int>());
  }

  // 2–3. Degree sweeps, H = +1 (the sphere's H in the FORMATS.md orientation).
  section.reset();
  std::printf("\n");
  section.emplace("cmc-sphere-convergence", "ms");
  std::printf("#### Triangular (sphere_triangle), H = +1\n\n%s", kSweepHeader);
  for (int n = 4; n <= 16; ++n) sweep_row(bpde::triangular_boundary(n, bpde::sphere_triangle), n, 1.0);
  std::printf("\n#### Tensor (sphere_square), H = +1\n\n%s", kSweepHeader);
  for (int n = 4; n <= 16; ++n) sweep_row(bpde::tensor_boundary(n, bpde::sphere_square), n, 1.0);

  // 4. Sign check.
  section.reset();
  std::printf("\n");
  section.emplace("cmc-sphere-sign");
  std::printf(
      "#### Sign check: the same data with H = −1 (n = 8)\n\n| net | converged | max \\|\\|x\\| − 1\\| | V "
      "|\n|---|---|---|---|\n");
  {
    bpde::CmcOptions o;
    o.H = -1.0;
    const auto t = bpde::solve_cmc(bpde::triangular_boundary(8, bpde::sphere_triangle), o);
    std::printf("| triangular | %s | %.3f | %.6f |\n", t.summary.converged ? "yes" : t.summary.message.c_str(),
                errors(t.net).dist, t.V);
    const auto q = bpde::solve_cmc(bpde::tensor_boundary(8, bpde::sphere_square), o);
    std::printf("| tensor | %s | %.3f | %.6f |\n", q.summary.converged ? "yes" : q.summary.message.c_str(),
                errors(q.net).dist, q.V);
  }

  // 5. The fold of the D_H branch from H = 0 on the triangular data, towards H = ±10 (the solve
  // stops at the fold): not symmetric in ±H, since the boundary is not planar.
  section.reset();
  std::printf("\n");
  section.emplace("cmc-sphere-fold");
  std::printf("| n | fold H > 0 | fold H < 0 |\n|---|---|---|\n");
  for (int n : {4, 6, 8, 10, 12}) {
    bpde::CmcOptions o;
    o.H = 10;
    const auto pos = bpde::solve_cmc(bpde::triangular_boundary(n, bpde::sphere_triangle), o);
    o.H = -10;
    const auto neg = bpde::solve_cmc(bpde::triangular_boundary(n, bpde::sphere_triangle), o);
    std::printf("| %d | %.4f | %.4f |\n", n, pos.H, neg.H);
  }

  // 6. Memory per degree of the D_H functional (docs/cmc_measurements.md): what CmcFunctional
  // keeps (Gram and volume tables) against the dense tensor C_IJK, the time to build it (uncached)
  // and one solve at H = +1 on the sphere data.
  section.reset();
  std::printf("\n");
  section.emplace("cmc-memory", "setup ms, solve ms");
  std::printf(
      "| n | points N | free k | nodes | memory MB | dense C_IJK would need, MB | setup ms | solve ms |\n"
      "|---|---|---|---|---|---|---|---|\n");
  for (int n : {4, 6, 8, 10, 12, 15, 20, 25}) {
    const auto t0 = std::chrono::steady_clock::now();
    const bpde::CmcFunctional f = bpde::CmcFunctional::triangular(n);
    const double setup = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    bpde::CmcOptions o;
    o.H = 1.0;
    const auto r = bpde::solve_cmc(bpde::triangular_boundary(n, bpde::sphere_triangle), o);
    const double N = f.size();
    std::printf("| %d | %d | %d | %d | %.3g | %.3g | %.1f | %.1f |\n", n, f.size(), (n - 1) * (n - 2) / 2,
                f.volume_form().nodes(), f.memory_bytes() / 1e6, N * N * N * 8 / 1e6, setup, 1e3 * r.summary.seconds);
  }
  section.reset();
  std::printf("\n");
  section.emplace("cmc-memory-tensor");
  std::printf("| n = m | points N | memory MB |\n|---|---|---|\n");
  for (int n : {4, 10, 15, 20}) {
    const bpde::CmcFunctional f = bpde::CmcFunctional::tensor(n, n);
    std::printf("| %d | %d | %.3g |\n", n, f.size(), f.memory_bytes() / 1e6);
  }
  return 0;
}
