// 004-cmc-area-tables: the area functional A_H = A + 2HV against the paper's D_H = D + 2HV
// (Arnal–Lluch–Monterde, triangular CMC) on boundaries whose parametrisation is not conformal, where
// the answer is known in closed form (docs/cmc.md, "The area functional"):
//   - the unit circle in three arcs by angle (boundaries/reference_boundaries.h: circle_three_arcs),
//     H = -0.5 and -0.9: the small cap of the sphere of radius 1/|H| through the circle;
//   - H = 0, tensor: the helicoid piece (s cos t, s sin t, t), s in [0.3, 1], t in [0, 1.2], from its
//     own parametrisation; checked by |x sin z - y cos z|;
//   - H = 0, triangular: the catenoid piece ρ = cosh z from its radial parametrisation
//     (θ, ρ) = (1.2u + 0.4v, 1.1 + 0.8v); checked by |√(x² + y²) - cosh z|.
//
// Usage: example_004_cmc_area_tables [--full | --tolerance-probe]
//   Without --full (what scripts/docs.py --check runs in CI, a few seconds): the circle at H = -0.5
//   for n = 4, 5. With --full (scripts/docs.sh --full; minutes): the degree tables n = 4 … 16 of
//   docs/cmc.md, in the sections whose names end in "-full". --tolerance-probe: the circle at n = 10
//   (H = -0.5, -0.9) solved to the tolerances 1e-11, 1e-12, 1e-13 (a plain table, about a minute).
// Columns: "dist" is the max over a 40-sample grid (every sample, corners included) of the distance
// measure above; the H range is taken on the 40-grid with corner margin 0.1; "residual" is the
// relative first variation of the functional solved (eq. (11) for D_H, A_H for area); "iterations"
// and "seconds" are the solver summary's (all stages included).
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "examples/common/generated.h"

using bpde::examples::GeneratedSection;
using bpde::examples::stable_small;

namespace {

template <class Net>
bpde::CmcResult<Net> solve(const Net& data, double H, bool area) {
  bpde::CmcOptions o;
  o.H = H;
  if (area) o.functional = bpde::CmcFunctionalKind::Area;
  return bpde::solve_cmc(data, o);
}

// A residual for the table: "≤ 1e-11" when it meets the tolerance (its digits there vary with the
// machine), two digits otherwise.
std::string residual_cell(double r) { return r <= 1e-11 ? "≤ 1e-11" : stable_small(r); }

std::string status_cell(const bpde::Summary& s) { return bpde::to_string(s.status); }

// Max over the 40-grid of |f(x)| on a triangular net (every sample, corners included).
double worst(const bpde::TriangularNet& net, const std::function<double(const Eigen::Vector3d&)>& f) {
  double e = 0;
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; a + b <= 40; ++b) e = std::max(e, std::abs(f(net.evaluate(a / 40.0, b / 40.0))));
  return e;
}
double worst(const bpde::TensorNet& net, const std::function<double(const Eigen::Vector3d&)>& f) {
  double e = 0;
  for (int a = 0; a <= 40; ++a)
    for (int b = 0; b <= 40; ++b) e = std::max(e, std::abs(f(net.evaluate(a / 40.0, b / 40.0))));
  return e;
}

template <class Net>
void row(int n, const char* functional, const bpde::CmcResult<Net>& r, double dist, bool with_h) {
  std::printf("| %d | %s | %s |", n, functional, stable_small(dist, 1e-10).c_str());
  if (with_h) {
    const bpde::MeanCurvatureStats s = bpde::mean_curvature_stats(r.net, 40, 0.1);
    std::printf(" %.5f … %.5f |", s.min, s.max);
  }
  std::printf(" %s | %s | %d | %.1f |\n", residual_cell(r.summary.residual).c_str(), status_cell(r.summary).c_str(),
              r.summary.iterations, r.summary.seconds);
}

void circle_table(const char* name, double H, const std::vector<int>& degrees) {
  const double R = 1 / std::abs(H);
  const Eigen::Vector3d c(0, 0, -std::sqrt(R * R - 1));  // the small cap bulges to +z for H < 0
  const GeneratedSection section(name, "iterations, seconds");
  std::printf("| n | functional | dist to the sphere | H min … max | residual | status | iterations | seconds |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (int n : degrees) {
    const bpde::TriangularNet data = bpde::circle_three_arcs(n);
    for (bool area : {false, true}) {
      const auto r = solve(data, H, area);
      row(n, area ? "area" : "dirichlet", r, worst(r.net, [&](const Eigen::Vector3d& x) { return (x - c).norm() - R; }),
          true);
    }
  }
}

Eigen::Vector3d helicoid(double u, double v) {
  const double s = 0.3 + 0.7 * u, t = 1.2 * v;
  return {s * std::cos(t), s * std::sin(t), t};
}
Eigen::Vector3d catenoid(double u, double v) {
  const double th = 1.2 * u + 0.4 * v, rho = 1.1 + 0.8 * v;
  return {rho * std::cos(th), rho * std::sin(th), std::acosh(rho)};
}

void minimal_tables(const std::vector<int>& tensor_degrees, const std::vector<int>& triangular_degrees) {
  {
    const GeneratedSection section("cmc-area-helicoid-full", "iterations, seconds");
    std::printf("| n | functional | \\|x sin z − y cos z\\| | residual | status | iterations | seconds |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
    for (int n : tensor_degrees) {
      const bpde::TensorNet data = bpde::tensor_boundary(n, helicoid);
      for (bool area : {false, true}) {
        const auto r = solve(data, 0.0, area);
        row(n, area ? "area" : "dirichlet", r,
            worst(r.net, [](const Eigen::Vector3d& x) { return x(0) * std::sin(x(2)) - x(1) * std::cos(x(2)); }),
            false);
      }
    }
  }
  std::printf("\n");
  {
    const GeneratedSection section("cmc-area-catenoid-full", "iterations, seconds");
    std::printf("| n | functional | \\|√(x² + y²) − cosh z\\| | residual | status | iterations | seconds |\n");
    std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
    for (int n : triangular_degrees) {
      const bpde::TriangularNet data = bpde::triangular_boundary(n, catenoid);
      for (bool area : {false, true}) {
        const auto r = solve(data, 0.0, area);
        row(n, area ? "area" : "dirichlet", r,
            worst(r.net, [](const Eigen::Vector3d& x) { return std::hypot(x(0), x(1)) - std::cosh(x(2)); }), false);
      }
    }
  }
}

// The circle at n = 10 solved to tighter first-variation tolerances than the default 1e-11
// (docs/cmc.md, "Degree tables"): whether the distance and the H range at a degree are set by the
// polynomial space or by where the solve stops.
void tolerance_probe() {
  std::printf("| H | n | tolerance | residual | status | iterations | dist to the sphere | max \\|H_sampled − H\\| |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (double H : {-0.5, -0.9}) {
    const double R = 1 / std::abs(H);
    const Eigen::Vector3d c(0, 0, -std::sqrt(R * R - 1));
    for (double tol : {1e-11, 1e-12, 1e-13}) {
      bpde::CmcOptions o;
      o.H = H;
      o.functional = bpde::CmcFunctionalKind::Area;
      o.tolerance = tol;
      const auto r = bpde::solve_cmc(bpde::circle_three_arcs(10), o);
      const bpde::MeanCurvatureStats s = bpde::mean_curvature_stats(r.net, 40, 0.1);
      std::printf("| %g | 10 | %.0e | %.1e | %s | %d | %.1e | %.1e |\n", H, tol, r.summary.residual,
                  status_cell(r.summary).c_str(), r.summary.iterations,
                  worst(r.net, [&](const Eigen::Vector3d& x) { return (x - c).norm() - R; }),
                  std::max(std::abs(s.min - H), std::abs(s.max - H)));
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--tolerance-probe") {
    tolerance_probe();
    return 0;
  }
  const bool full = argc > 1 && std::string(argv[1]) == "--full";
  std::printf("### Circle in three arcs, H = -0.5, n = 4, 5\n\n");
  circle_table("cmc-area-circle", -0.5, {4, 5});
  if (!full) return 0;
  std::printf("\n### Circle in three arcs, H = -0.5\n\n");
  circle_table("cmc-area-circle-0.5-full", -0.5, {4, 6, 8, 10, 12, 14, 16});
  std::printf("\n### Circle in three arcs, H = -0.9\n\n");
  circle_table("cmc-area-circle-0.9-full", -0.9, {4, 6, 8, 10, 12, 14, 16});
  std::printf("\n### H = 0\n\n");
  minimal_tables({4, 6, 8, 10, 12}, {4, 6, 8, 10, 12, 14, 16});
  return 0;
}
