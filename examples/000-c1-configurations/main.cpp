// 000-c1-configurations: Centella–Monterde–Moreno–Oset (C¹ methods) §5, the cylindrical, spherical
// and arched C¹ boundary configurations of Figures IV–IX, solved by both C¹ methods at n = 7.
//
// Usage: example_000_c1_configurations [--write-jobs] [EXAMPLE_DIR [OUT_DIR]]
//   EXAMPLE_DIR defaults to examples/000-c1-configurations, OUT_DIR to out/000-c1-configurations.
//   --write-jobs regenerates EXAMPLE_DIR/<config>-{tetraharmonic,biharmonic-load}.json from
//   configurations.h first. Then every job is run through bpde::run_job (as `bpde solve` does),
//   its result written to OUT_DIR/<job>/ (result.json, with "load" for biharmonic-load, and the
//   surface files), and one Markdown table row printed (README.md holds the output).
//
// Columns: residual — tetraharmonic: the FORMATS.md pde_residual of Δ⁴x; biharmonic-load: max
// |load| over 2 <= i,j <= n−2 divided by max |load| (Theorem 3 makes it 0). self-int — CGAL
// self-intersecting triangle pairs of the sampled surface (check_report). load — the Bernstein
// net of Δ²x (for the tetraharmonic surface too, as the paper plots it in Figs. III, V–VII):
// max |p_ij| over the outer two rings and over the interior. z(½,½), max z — height of the centre
// and of the sampled surface. explicit vs lu — max control-point
// difference of the two tetraharmonic methods relative to max |P_ij|. sphere — max ||x| − 1| on
// a 201² grid (Fig. VI only).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>

#include "configurations.h"
#include "examples/common/generated.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_job.h"
#include "bezierpde/solvers/c1/biharmonic_load.h"
#include "bezierpde/solvers/c1/tetraharmonic.h"

namespace {

struct LoadStats {
  double rings = 0, interior = 0;
};

LoadStats load_stats(const bpde::TensorNet& load) {
  const int n = load.n();
  LoadStats s;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double a = load.point(i, j).norm();
      if (c1ex::in_outer_rings(i, j, n))
        s.rings = std::max(s.rings, a);
      else
        s.interior = std::max(s.interior, a);
    }
  return s;
}

double sphere_distance(const bpde::TensorNet& net) {
  double d = 0;
  for (int a = 0; a <= 200; ++a)
    for (int b = 0; b <= 200; ++b) d = std::max(d, std::abs(net.evaluate(a / 200.0, b / 200.0).norm() - 1));
  return d;
}

int self_intersections(const bpde::TensorNet& net) {
  return bpde::check_report(bpde::sample_net(net, 50))["self_intersections"].get<int>();
}

// How the paper's qualitative claims depend on the choices it leaves open (README "Sensitivity").
void sensitivity() {
  const int n = c1ex::kDegree;
  constexpr double pi = std::numbers::pi;
  std::printf("\n### Fig. VI: which piece of the sphere (paper: 0.00822637 / 0.0141973)\n\n");
  std::printf(
      "| piece (degree-7 Chebyshev–Lobatto interpolant, outer two rings) | data | biharmonic-load | tetraharmonic "
      "|\n|---|---|---|---|\n");
  auto sphere_row = [&](const char* name, auto f) {
    const bpde::TensorNet full = c1ex::interpolate_tensor(n, f);
    std::printf("| %s | %.1e | %.5f | %.5f |\n", name, sphere_distance(full),
                sphere_distance(bpde::solve_biharmonic_load(full).net),
                sphere_distance(bpde::solve_tetraharmonic(full).net));
  };
  for (double a : {0.45, 0.5, 0.52}) {
    char name[96];
    std::snprintf(name, sizeof name, "graph (x, y, √(1−x²−y²)) over [−%.2f, %.2f]²%s", a, a, a == 0.5 ? " (used)" : "");
    sphere_row(name, [a](double u, double v) {
      const double x = a * (2 * u - 1), y = a * (2 * v - 1);
      return Eigen::Vector3d(x, y, std::sqrt(1 - x * x - y * y));
    });
  }
  sphere_row("longitude–latitude over [−π/4, π/4]²", [pi](double u, double v) {
    const double l = pi / 2 * (u - 0.5), p = pi / 2 * (v - 0.5);
    return Eigen::Vector3d(std::cos(p) * std::cos(l), std::cos(p) * std::sin(l), std::sin(p));
  });
  sphere_row("inverse stereographic over [−½, ½]²", [](double u, double v) -> Eigen::Vector3d {
    const double s = u - 0.5, t = v - 0.5, r2 = s * s + t * t;
    return Eigen::Vector3d(2 * s, 2 * t, r2 - 1) / (1 + r2);
  });

  std::printf("\n### Fig. IX row 3: the outward shift δ of the adjacent ring\n\n");
  std::printf(
      "| adjacent ring | self-int biharmonic-load | self-int tetraharmonic | z(½,½) biharmonic-load | z(½,½) "
      "tetraharmonic |\n|---|---|---|---|---|\n");
  for (double d : {-0.1, -0.25, -0.5}) {
    const bpde::TensorNet data = c1ex::arch2_with_shift(n, d);
    const auto bl = bpde::solve_biharmonic_load(data).net;
    const auto th = bpde::solve_tetraharmonic(data).net;
    std::printf("| towards the origin, δ = %.2f%s | %d | %d | %.3f | %.3f |\n", d, d == -0.25 ? " (used)" : "",
                self_intersections(bl), self_intersections(th), bl.evaluate(0.5, 0.5).z(), th.evaluate(0.5, 0.5).z());
  }
  {  // the other reading: a purely horizontal shift perpendicular to each side
    const bpde::TensorNet ref = c1ex::arch2_with_shift(n, 0.0);
    const double d = -0.25;
    const bpde::TensorNet data = c1ex::rings_from(n, [&](int i, int j) -> Eigen::Vector3d {
      if (c1ex::on_boundary(i, j, n)) return ref.point(i, j);
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      int count = 0;
      if (j == 1) {
        sum += ref.point(i, 0) + Eigen::Vector3d(0, d, 0);
        ++count;
      }
      if (j == n - 1) {
        sum += ref.point(i, n) - Eigen::Vector3d(0, d, 0);
        ++count;
      }
      if (i == 1) {
        sum += ref.point(0, j) + Eigen::Vector3d(d, 0, 0);
        ++count;
      }
      if (i == n - 1) {
        sum += ref.point(n, j) - Eigen::Vector3d(d, 0, 0);
        ++count;
      }
      return sum / count;
    });
    const auto bl = bpde::solve_biharmonic_load(data).net;
    const auto th = bpde::solve_tetraharmonic(data).net;
    std::printf("| horizontally, perpendicular to each side, δ = %.2f | %d | %d | %.3f | %.3f |\n", d,
                self_intersections(bl), self_intersections(th), bl.evaluate(0.5, 0.5).z(), th.evaluate(0.5, 0.5).z());
  }

  std::printf("\n### Fig. V: which adjacent points are lowered (by 0.5)\n\n");
  std::printf("| lowered | z(½,½) biharmonic-load | z(½,½) tetraharmonic |\n|---|---|---|\n");
  auto cyl_row = [&](const char* name, auto lowered) {
    const bpde::TensorNet data = c1ex::rings_from(n, [&](int i, int j) -> Eigen::Vector3d {
      Eigen::Vector3d p(-c1ex::ck(i, n), 2.0 * j / n - 1, c1ex::sk(i, n));
      if (!c1ex::on_boundary(i, j, n) && lowered(i, j)) p.z() -= 0.5;
      return p;
    });
    std::printf("| %s | %.3f | %.3f |\n", name, bpde::solve_biharmonic_load(data).net.evaluate(0.5, 0.5).z(),
                bpde::solve_tetraharmonic(data).net.evaluate(0.5, 0.5).z());
  };
  cyl_row("none (Fig. IV)", [](int, int) { return false; });
  cyl_row("next to the circular arcs, j = 1, n−1, 2 ≤ i ≤ n−2 (used)",
          [n](int i, int j) { return (j == 1 || j == n - 1) && i >= 2 && i <= n - 2; });
  cyl_row("next to the straight sides, i = 1, n−1", [n](int i, int) { return i == 1 || i == n - 1; });
  cyl_row("the whole adjacent ring", [](int, int) { return true; });
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  int arg = 1;
  bool write_jobs = false;
  if (argc > 1 && std::strcmp(argv[1], "--write-jobs") == 0) {
    write_jobs = true;
    ++arg;
  }
  const fs::path dir = argc > arg ? argv[arg] : "examples/000-c1-configurations";
  const fs::path out = argc > arg + 1 ? argv[arg + 1] : "out/000-c1-configurations";
  const auto configs = c1ex::configurations();
  if (write_jobs) {
    for (const auto& c : configs) {
      for (const char* kind : {"tetraharmonic", "biharmonic-load"}) {
        bpde::Json problem = {{"kind", kind}};
        if (std::strcmp(kind, "tetraharmonic") == 0) problem["method"] = "lu";
        const bpde::Json job = {
            {"net", bpde::net_to_json(c.net)}, {"fixed", "boundary+adjacent"}, {"problem", problem}, {"samples", 50}};
        bpde::write_json_file((dir / (c.name + "-" + kind + ".json")).string(), job);
      }
    }
  }
  std::optional<bpde::examples::GeneratedSection> results;
  results.emplace("c1-results");
  std::printf(
      "| config | figure | method | n | residual | self-int | max \\|load\\| outer rings | max \\|load\\| interior | "
      "z(½,½) | max z | H range | explicit vs lu | sphere dist |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const auto& c : configs) {
    for (const char* kind : {"biharmonic-load", "tetraharmonic"}) {
      const std::string stem = c.name + "-" + kind;
      const bpde::Job job = bpde::read_job_file((dir / (stem + ".json")).string());
      const bpde::SolveOutcome res = bpde::run_job(job);
      bpde::write_outcome((out / stem).string(), job, res);
      const auto& net = std::get<bpde::TensorNet>(res.net);
      const bpde::TensorNet load = bpde::bilaplacian_load_net(net);
      const LoadStats ls = load_stats(load);
      const bpde::TriangleMesh mesh = bpde::sample_net(res.net, job.samples);
      const int si = bpde::check_report(mesh)["self_intersections"].get<int>();
      const bpde::Json H = bpde::mean_curvature_stats(res.net, mesh, job.samples);
      const bool tetra = std::strcmp(kind, "tetraharmonic") == 0;
      const double residual =
          tetra ? res.report["pde_residual"].get<double>() : ls.interior / std::max(ls.rings, 1e-300);
      char exp_vs_lu[32] = "";
      if (tetra) {
        bpde::TetraharmonicOptions o;
        o.method = bpde::TetraharmonicOptions::Method::Explicit;
        const auto ex = bpde::solve_tetraharmonic(std::get<bpde::TensorNet>(job.net), o);
        std::snprintf(exp_vs_lu, sizeof exp_vs_lu, "%s",
                      bpde::examples::stable_small((ex.net.points() - net.points()).cwiseAbs().maxCoeff() /
                                                   net.points().cwiseAbs().maxCoeff())
                          .c_str());
      }
      char sph[32] = "";
      if (c.name.rfind("sphere", 0) == 0) std::snprintf(sph, sizeof sph, "%.5f", sphere_distance(net));
      char interior[32];  // the biharmonic-load's interior load is rounding: Theorem 3 makes it 0
      if (ls.interior < 1e-9)
        std::snprintf(interior, sizeof interior, "< 1e-9");
      else
        std::snprintf(interior, sizeof interior, "%.2g", ls.interior);
      std::printf("| %s | %s | %s | %d | %s | %d | %.4g | %s | %.3f | %.3f | [%.3g, %.3g] | %s | %s |\n",
                  c.name.c_str(), c.figure.c_str(), tetra ? "tetraharmonic (lu)" : "biharmonic-load", net.n(),
                  bpde::examples::order_bound(residual).c_str(), si, ls.rings, interior, net.evaluate(0.5, 0.5).z(),
                  mesh.V.col(2).maxCoeff(), H["min"].get<double>(), H["max"].get<double>(), exp_vs_lu, sph);
    }
  }
  results.reset();
  // The data itself for Fig. VI: the full degree-7 interpolant of the sphere piece.
  std::printf("\nFig. VI data: the full degree-7 interpolant is within %.2e of the unit sphere.\n",
              sphere_distance(c1ex::interpolate_tensor(c1ex::kDegree, c1ex::sphere_piece)));
  {
    const bpde::examples::GeneratedSection section("c1-sensitivity");
    sensitivity();
  }
  return 0;
}
