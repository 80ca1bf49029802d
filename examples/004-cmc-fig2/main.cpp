// 004-cmc-fig2: Arnal–Lluch–Monterde (triangular CMC) Fig. 2, rebuilt from its description in §4:
//  - top: "boundary curves built in such a way that any associated patch would be isothermal at
//    the corner points", H = −1, 0, 1. Our boundary: the edges of Enneper's surface
//    E(s,t) = (s − s³/3 + st², t − t³/3 + ts², s² − t²) over (s,t) = c·(u − 1/3, v − 1/3), c = kScale.
//    E is conformal, so every patch with this boundary is isothermal at the corners; the edges are
//    cubics, so they are exact at any degree n ≥ 3, and at H = 0 the Dirichlet extremal is E itself.
//  - bottom: "the boundaries are approximations to three circular arcs, and therefore our results
//    look like pieces of a sphere", H = −2, −1.5, −1. Our boundary: the conformal (inverse
//    stereographic) triangle of the sphere of radius R = 2/3, with u and v swapped so that the sphere
//    itself is the H = −1/R = −1.5 surface (FORMATS.md orientation), the edges fitted at degree n.
//
// Usage: example_004_cmc_fig2 [--write-jobs] [EXAMPLE_DIR [OUT_DIR]]
//   EXAMPLE_DIR defaults to examples/004-cmc-fig2, OUT_DIR to out/004-cmc-fig2.
// Prints Markdown tables (README.md holds their output): the job files through run_job, then a
// degree sweep with the distance to the reference surface (Enneper at H = 0, the sphere at H = −1.5)
// and the folds of the two branches.
#include <algorithm>
#include <cmath>
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
constexpr double kScale = 1.5;       // Enneper domain scale c
constexpr double kRadius = 2.0 / 3;  // sphere radius of the bottom row

Eigen::Vector3d enneper(double u, double v) {
  const double s = kScale * (u - 1.0 / 3), t = kScale * (v - 1.0 / 3);
  return {s - s * s * s / 3 + s * t * t, t - t * t * t / 3 + t * s * s, s * s - t * t};
}
Eigen::Vector3d small_sphere(double u, double v) { return kRadius * bpde::sphere_triangle(v, u); }

Json job_json(const bpde::TriangularNet& net, double H) {
  return {{"net", bpde::net_to_json(net)},
          {"fixed", "boundary"},
          {"problem", {{"kind", "cmc"}, {"H", H}, {"solver", "newton"}}},
          {"samples", kSamples}};
}

std::string fmt(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%g", x);
  return b;
}

// Largest |x(u,v) − ref(u,v)| over the sample grid.
template <class F>
double param_error(const bpde::TriangularNet& net, F ref) {
  double e = 0;
  for (int a = 0; a <= kSamples; ++a)
    for (int b = 0; a + b <= kSamples; ++b) {
      const double u = double(a) / kSamples, v = double(b) / kSamples;
      e = std::max(e, (net.evaluate(u, v) - ref(u, v)).norm());
    }
  return e;
}

double max_z(const bpde::TriangleMesh& m) { return m.V.col(2).maxCoeff(); }
double min_z(const bpde::TriangleMesh& m) { return m.V.col(2).minCoeff(); }

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  const bool write_jobs = std::erase(args, std::string("--write-jobs")) > 0;
  const fs::path dir = args.size() > 0 ? args[0] : "examples/004-cmc-fig2";
  const fs::path out = args.size() > 1 ? args[1] : "out/004-cmc-fig2";
  constexpr int kDegree = 6;

  if (write_jobs) {
    // Fig. 2 order: tags a, b, c from left to right.
    const char* tags[] = {"a", "b", "c"};
    const double top[] = {-1.0, 0.0, 1.0}, bottom[] = {-2.0, -1.5, -1.0};
    for (int k = 0; k < 3; ++k) {
      bpde::write_json_file((dir / ("top-" + std::string(tags[k]) + "-enneper-H" + fmt(top[k]) + ".json")).string(),
                            job_json(bpde::triangular_boundary(kDegree, enneper), top[k]));
      bpde::write_json_file((dir / ("bottom-" + std::string(tags[k]) + "-arcs-H" + fmt(bottom[k]) + ".json")).string(),
                            job_json(bpde::triangular_boundary(kDegree, small_sphere), bottom[k]));
    }
  }

  std::vector<fs::path> jobs;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".json") jobs.push_back(e.path());
  std::sort(jobs.begin(), jobs.end());
  std::stable_partition(jobs.begin(), jobs.end(),
                        [](const fs::path& p) { return p.stem().string().starts_with("top"); });
  std::printf("### Job files (n = %d)\n\n", kDegree);
  std::optional<bpde::examples::GeneratedSection> section;
  section.emplace("cmc-fig2-jobs");
  std::printf(
      "| job | H | exit | D_H | D | V | z min / max | H mean | H min / max | "
      "self-intersections |\n"
      "|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& p : jobs) {
    const bpde::Job job = bpde::read_job_file(p.string());
    const bpde::SolveOutcome o = bpde::run_job(job);
    const int status = bpde::write_outcome((out / p.stem()).string(), job, o);
    if (!o.converged) {
      std::printf("| %s | %g | %d | %s | | | | | | |\n", p.stem().c_str(), job.problem.H, status,
                  o.report.value("message", std::string("?")).c_str());
      continue;
    }
    const bpde::TriangleMesh mesh = bpde::sample_net(o.net, job.samples);
    const Json mc = bpde::mean_curvature_stats(o.net, mesh, job.samples);
    std::printf("| %s | %g | %d | %.6f | %.6f | %.6f | %.4f / %.4f | %.4f | %.3f / %.3f | %d |\n", p.stem().c_str(),
                job.problem.H, status, o.report["energy"].get<double>(), o.report["D"].get<double>(),
                o.report["volume"].get<double>(), min_z(mesh), max_z(mesh), mc["mean"].get<double>(),
                mc["min"].get<double>(), mc["max"].get<double>(),
                bpde::check_report(mesh)["self_intersections"].get<int>());
  }

  // Degree sweep: distance to the reference surface and folds.
  section.reset();
  std::printf("\n### Degree sweep\n\n");
  section.emplace("cmc-fig2-sweep");
  std::printf(
      "| n | top: max \\|x − Enneper\\| at H = 0 | top: fold H < 0 | top: fold H > 0 "
      "| bottom: max \\|x − sphere\\| at H = −1.5 | bottom: fold H < 0 | bottom: fold H > 0 |\n"
      "|---|---|---|---|---|---|---|\n");
  for (int n : {4, 6, 8, 10}) {
    const bpde::TriangularNet top = bpde::triangular_boundary(n, enneper);
    const bpde::TriangularNet bot = bpde::triangular_boundary(n, small_sphere);
    bpde::CmcOptions o;
    const auto t0 = bpde::solve_cmc(top, o);
    o.H = -1.5;
    const auto b0 = bpde::solve_cmc(bot, o);
    auto fold = [&](const bpde::TriangularNet& d, double H) {
      bpde::CmcOptions f;
      f.H = H;
      const auto r = bpde::solve_cmc(d, f);
      return r.summary.converged ? fmt(H) + " reached" : fmt(r.H);
    };
    // The top at H = 0 is Enneper's surface to rounding (6.0e-16 .. 1.6e-15, other digits with
    // -march=native): printed as the bound "< 1e-14".
    std::printf("| %d | %s | %s | %s | %.1e | %s | %s |\n", n,
                bpde::examples::stable_small(param_error(t0.net, enneper), 1e-14).c_str(), fold(top, -20).c_str(),
                fold(top, 20).c_str(), param_error(b0.net, small_sphere), fold(bot, -20).c_str(),
                fold(bot, 20).c_str());
  }
  return 0;
}
