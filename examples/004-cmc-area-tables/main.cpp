// 004-cmc-area-tables: the area functional A_H = A + 2HV and the least squares of the mean curvature
// Φ = ∫ρ(H_x − H)² dA against the paper's D_H = D + 2HV (Arnal–Lluch–Monterde, triangular CMC) on
// boundaries whose parametrisation is not conformal, where the answer is known in closed form
// (docs/cmc.md, "The area functional" and "Least squares of the mean curvature"):
//   - the unit circle in three arcs by angle (boundaries/reference_boundaries.h: circle_three_arcs),
//     H = -0.5 and -0.9: the small cap of the sphere of radius 1/|H| through the circle;
//   - H = 0, tensor: the helicoid piece (s cos t, s sin t, t), s in [0.3, 1], t in [0, 1.2], from its
//     own parametrisation; checked by |x sin z - y cos z|;
//   - H = 0, triangular: the catenoid piece ρ = cosh z from its radial parametrisation
//     (θ, ρ) = (1.2u + 0.4v, 1.1 + 0.8v); checked by |√(x² + y²) - cosh z|;
//   - H = 0, tensor: the catenoid piece (θ, ρ) = (1.2u, 1.1 + 0.8v) on the square (radial, so not
//     conformal: the conformal one is ρ = cosh z with z linear); checked the same way.
//
// Usage: example_004_cmc_area_tables [--full [NAME ...] | --tolerance-probe | --margin-probe | --rule-probe |
//                                     --gauge-probe | --larger-caps [N H] |
//                                     --larger-caps-mean-curvature [N H] | --solve-circle N TOLERANCE]
//   Without --full (what scripts/docs.py --check runs in CI, a few seconds): the circle at H = -0.5
//   for n = 4, 5, and the rule probe below (section cmc-area-rule-probe). With --full
//   (scripts/docs.sh --full; minutes): the degree tables n = 4 … 16 of docs/cmc_measurements.md, its
//   trust-region final phase on and off, its starts of the area functional side by side, its
//   conformal-data gate of mean-curvature-start and its
//   mean-curvature tables on the circle (degree 10; the V form), in the sections whose names end in
//   "-full"; "--full NAME ..." prints only the named ones (docs.py --full-sections). --tolerance-probe: the circle at n = 10
//   (H = -0.5, -0.9) solved to the tolerances 1e-11, 1e-12, 1e-13 (a plain table, about a minute).
//   --margin-probe: where the area route's H deviates on the circle at n = 10, 12, 14 (corner
//   margins 0.1 … 0.3, boundary samples left out; under a minute).
//   --solve-circle N TOLERANCE: one library solve of the circle (H = -0.5) at degree N to that
//   first-variation tolerance, printed as JSON (scripts/evolver_compare.py --tolerances).
//   --rule-probe: the circle's corner angles by degree and the error of the plain and graded area
//   rules on the solved nets (docs/cmc_algorithm.md, "The area functional A_H"; seconds).
//   --gauge-probe: Newton steps restricted to normal motion of the free points on the solved
//   circle (docs/cmc_algorithm.md, "The final phases"; seconds).
//   --larger-caps [N H]: the V form on the circle with v0 the larger cap's volume (docs/cmc_algorithm.md,
//   `smaller-volume-start`; about 10 minutes, or the one case N, H).
//   --larger-caps-mean-curvature [N H]: the same with the mean-curvature functional (docs/cmc_algorithm.md,
//   "The least squares of the mean curvature", the V form; about 20 s, or the one case N, H).
// Columns: "dist" is the max over a 40-sample grid (every sample, corners included) of the distance
// measure above; the H range is taken on the 40-grid with corner margin 0.1; "residual" is the
// relative first variation of the functional solved (eq. (11) for D_H, A_H for area) or, for
// mean-curvature, √Φ (its tolerance 1e-6); "iterations" and "seconds" are the solver summary's
// (all stages included).
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

#include "bezierpde/boundaries/boundary_curves.h"
#include "bezierpde/boundaries/fit_boundary.h"
#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/energies/cmc.h"
#include "bezierpde/energies/area_functional.h"
#include "bezierpde/solvers/cmc/cmc.h"
#include "bezierpde/triangular/triangular_net.h"
#include "examples/common/generated.h"

using bpde::examples::GeneratedSection;
using bpde::examples::stable_small;

namespace {

template <class Net>
bpde::CmcResult<Net> solve(const Net& data, double H, bpde::CmcFunctionalKind functional) {
  bpde::CmcOptions o;
  o.H = H;
  o.functional = functional;
  return bpde::solve_cmc(data, o);
}
template <class Net>
bpde::CmcResult<Net> solve(const Net& data, double H, bool area) {
  return solve(data, H, area ? bpde::CmcFunctionalKind::Area : bpde::CmcFunctionalKind::Dirichlet);
}

// The three functionals of the tables, in their order.
constexpr bpde::CmcFunctionalKind kFunctionals[] = {bpde::CmcFunctionalKind::Dirichlet, bpde::CmcFunctionalKind::Area,
                                                    bpde::CmcFunctionalKind::MeanCurvature};

// A residual for the table: "≤ 1e-11" when it meets the tolerance (its digits there vary with the
// machine), two digits otherwise; for the mean-curvature functional √Φ, "≤ 1e-6" when it meets its
// tolerance.
std::string residual_cell(double r) { return r <= 1e-11 ? "≤ 1e-11" : stable_small(r); }
template <class Net>
std::string residual_cell(const bpde::CmcResult<Net>& r) {
  if (r.functional == bpde::CmcFunctionalKind::MeanCurvature)
    return r.summary.residual <= 1e-6 ? "√Φ ≤ 1e-6" : "√Φ = " + stable_small(r.summary.residual);
  return residual_cell(r.summary.residual);
}

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
void row(int n, const bpde::CmcResult<Net>& r, double dist, bool with_h) {
  std::printf("| %d | %s | %s |", n, bpde::to_string(r.functional).c_str(), stable_small(dist, 1e-10).c_str());
  if (with_h) {
    const bpde::MeanCurvatureStats s = bpde::mean_curvature_stats(r.net, 40, 0.1);
    std::printf(" %.5f … %.5f |", s.min, s.max);
  }
  std::printf(" %s | %s | %d | %.1f |\n", residual_cell(r).c_str(), status_cell(r.summary).c_str(),
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
    for (const bpde::CmcFunctionalKind f : kFunctionals) {
      const auto r = solve(data, H, f);
      row(n, r, worst(r.net, [&](const Eigen::Vector3d& x) { return (x - c).norm() - R; }), true);
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
Eigen::Vector3d catenoid_square(double u, double v) {
  const double th = 1.2 * u, rho = 1.1 + 0.8 * v;
  return {rho * std::cos(th), rho * std::sin(th), std::acosh(rho)};
}
double catenoid_off(const Eigen::Vector3d& x) { return std::hypot(x(0), x(1)) - std::cosh(x(2)); }

double helicoid_off(const Eigen::Vector3d& x) { return x(0) * std::sin(x(2)) - x(1) * std::cos(x(2)); }

// One H = 0 table: the three functionals on the nets make(n), the distance to the surface by `off`.
template <class MakeNet>
void minimal_table(const char* name, const char* column, const std::vector<int>& degrees, MakeNet make,
                   double (*off)(const Eigen::Vector3d&)) {
  const GeneratedSection section(name, "iterations, seconds");
  std::printf("| n | functional | %s | residual | status | iterations | seconds |\n", column);
  std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
  for (int n : degrees) {
    const auto data = make(n);
    for (const bpde::CmcFunctionalKind f : kFunctionals) {
      const auto r = solve(data, 0.0, f);
      row(n, r, worst(r.net, off), false);
    }
  }
}

// The H = 0 tables whose names `wants`.
template <class Wants>
void minimal_tables(const std::vector<int>& tensor_degrees, const std::vector<int>& triangular_degrees, Wants wants) {
  if (wants("cmc-area-helicoid-full")) {
    minimal_table("cmc-area-helicoid-full", "\\|x sin z − y cos z\\|", tensor_degrees,
                  [](int n) { return bpde::tensor_boundary(n, helicoid); }, helicoid_off);
    std::printf("\n");
  }
  if (wants("cmc-area-catenoid-full")) {
    minimal_table("cmc-area-catenoid-full", "\\|√(x² + y²) − cosh z\\|", triangular_degrees,
                  [](int n) { return bpde::triangular_boundary(n, catenoid); }, catenoid_off);
    std::printf("\n");
  }
  if (wants("cmc-area-catenoid-tensor-full"))
    minimal_table("cmc-area-catenoid-tensor-full", "\\|√(x² + y²) − cosh z\\|", tensor_degrees,
                  [](int n) { return bpde::tensor_boundary(n, catenoid_square); }, catenoid_off);
}

// The area functional from `"start": "minimal-surface"` and from the default start, side by side
// (docs/cmc_measurements.md, "The starts of the area functional side by side"): the H form on the
// circle (H = -0.5, -0.9, -1.2) and on the tensor helicoid and catenoid pieces (H = -0.8, +0.8), the
// V form on the circle with v0 the small cap's volume (H = -0.5, -0.9) and the larger cap's
// (H = -0.7, -0.9, -0.5). Each start's cell: status and first variation (a fold: the H where the
// branch turns; the V form: the distance of the H found to the cap's), then its continuation steps
// and the summary's seconds.
template <class Net>
bpde::CmcResult<Net> solve_from(const Net& data, double H, std::optional<double> V, bpde::AreaStart start) {
  bpde::CmcOptions o;
  o.functional = bpde::CmcFunctionalKind::Area;
  o.area_start = start;
  if (V)
    o.V = *V;
  else
    o.H = H;
  return bpde::solve_cmc(data, o);
}

template <class Net>
std::string start_cell(const bpde::CmcResult<Net>& r, double H, bool volume_form) {
  char buf[96];
  if (r.summary.status == bpde::Status::Fold)
    std::snprintf(buf, sizeof buf, "fold at H = %.6f", r.H);
  else if (volume_form)
    std::snprintf(buf, sizeof buf, "%s %s, \\|H − H_cap\\| = %.1e", status_cell(r.summary).c_str(),
                  residual_cell(r.summary.residual).c_str(), std::abs(r.H - H));
  else
    std::snprintf(buf, sizeof buf, "%s %s", status_cell(r.summary).c_str(), residual_cell(r.summary.residual).c_str());
  return buf;
}

template <class Net>
void starts_row(const char* form, const char* name, int n, const Net& data, double H, std::optional<double> V) {
  const auto a = solve_from(data, H, V, bpde::AreaStart::MinimalSurface);
  const auto b = solve_from(data, H, V, bpde::AreaStart::MeanCurvature);
  std::printf("| %s | %s | %d | %s | %d | %.2f | %s | %d | %.2f |\n", form, name, n, start_cell(a, H, V.has_value()).c_str(),
              a.continuation_steps, a.summary.seconds, start_cell(b, H, V.has_value()).c_str(), b.continuation_steps,
              b.summary.seconds);
  std::fflush(stdout);
}

// The volume of the small (larger = false) or the larger cap of H over the unit circle.
double cap_volume(double H, bool larger) {
  const double R = 1 / std::abs(H), h = larger ? R + std::sqrt(R * R - 1) : R - std::sqrt(R * R - 1);
  return std::numbers::pi * h * h * (3 * R - h) / 3;
}

void area_starts() {
  const GeneratedSection section("cmc-area-starts-full", "steps (minimal-surface), s (minimal-surface), steps (default), s (default)");
  std::printf("| form | case | n | start `minimal-surface` | steps (minimal-surface) | s (minimal-surface) | "
              "default start (`mean-curvature`) | steps (default) | s (default) |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  char name[64];
  for (double H : {-0.5, -0.9, -1.2})
    for (int n : {6, 8, 10}) {
      std::snprintf(name, sizeof name, "circle, H = %g", H);
      starts_row("H", name, n, bpde::circle_three_arcs(n), H, std::nullopt);
    }
  for (double H : {-0.8, 0.8})
    for (int n : {6, 8}) {
      std::snprintf(name, sizeof name, "helicoid piece (tensor), H = %g", H);
      starts_row("H", name, n, bpde::tensor_boundary(n, helicoid), H, std::nullopt);
    }
  for (double H : {-0.8, 0.8})
    for (int n : {6, 8}) {
      std::snprintf(name, sizeof name, "catenoid piece (tensor), H = %g", H);
      starts_row("H", name, n, bpde::tensor_boundary(n, catenoid_square), H, std::nullopt);
    }
  for (double H : {-0.5, -0.9})
    for (int n : {6, 8, 10}) {
      std::snprintf(name, sizeof name, "circle, cap of H = %g (v0 = %.4g)", H, cap_volume(H, false));
      starts_row("V", name, n, bpde::circle_three_arcs(n), H, cap_volume(H, false));
    }
  for (double H : {-0.7, -0.9, -0.5})
    for (int n : {8, 10}) {
      std::snprintf(name, sizeof name, "circle, larger cap of H = %g (v0 = %.4g)", H, cap_volume(H, true));
      starts_row("V", name, n, bpde::circle_three_arcs(n), H, cap_volume(H, true));
    }
}

// Curve A of docs/boundaries.md ("Samples without parameters"): the wavy closed space curve
// r = 1 + 0.25 cos 2θ + 0.2 sin 3θ, z = 0.3 cos 2θ + 0.2 sin 2θ − 0.25 cos 3θ, corners at
// θ = 0, 1.45, 3.3, 4.75, given as 61 samples per edge without parameters, fitted by a tensor net
// of degree n (as tests/cmc/test_cmc_area.cpp, CmcArea.RuleIsChosenAgainWhereTheStartNearlyFolds).
bpde::TensorNet curve_a(int n) {
  const double cuts[5] = {0.0, 1.45, 3.3, 4.75, 2 * std::numbers::pi};
  auto curve = [](double th) {
    const double r = 1 + 0.25 * std::cos(2 * th) + 0.2 * std::sin(3 * th);
    return Eigen::Vector3d(r * std::cos(th), r * std::sin(th),
                           0.3 * std::cos(2 * th) + 0.2 * std::sin(2 * th) - 0.25 * std::cos(3 * th));
  };
  bpde::BoundaryData data;
  for (int e = 0; e < 4; ++e) {
    Eigen::MatrixX3d q(61, 3);
    for (int k = 0; k <= 60; ++k) q.row(k) = curve(cuts[e] + (cuts[e + 1] - cuts[e]) * k / 60.0).transpose();
    if (e == 3) q.row(60) = curve(0.0).transpose();  // the first corner, bit for bit
    data.edges.push_back(bpde::BoundaryCurve::samples(q));
  }
  return bpde::fit_tensor_boundary(n, n, data).net;
}

// One side of the trust-region table: status and first variation, and, where the kept route's
// soft-mode phase ended at a degenerate bound or a stationary point, that end.
template <class Net>
std::string trust_region_cell(const bpde::CmcResult<Net>& r) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%s %.1e", status_cell(r.summary).c_str(), r.summary.residual);
  std::string s = buf;
  const bpde::AreaRouteRecord* k = r.routes.kept();
  if (k && k->soft_mode_end != bpde::SoftModeEnd::None) s += std::string(" (") + bpde::to_string(k->soft_mode_end) + ")";
  return s;
}

// The area functional with `o` solved with area_trust_region false and true: one row.
template <class Net>
void trust_region_row(const std::string& name, const Net& data, bpde::CmcOptions o) {
  o.functional = bpde::CmcFunctionalKind::Area;
  o.area_trust_region = false;
  const auto a = bpde::solve_cmc(data, o);
  o.area_trust_region = true;
  const auto b = bpde::solve_cmc(data, o);
  const bpde::MeanCurvatureStats ha = bpde::mean_curvature_stats(a.net, 40, 0.1),
                                  hb = bpde::mean_curvature_stats(b.net, 40, 0.1);
  std::printf("| %s | %s | %.3f … %.3f | %.1f | %s | %.3f … %.3f | %.1f |\n", name.c_str(), trust_region_cell(a).c_str(),
              ha.min, ha.max, a.summary.seconds, trust_region_cell(b).c_str(), hb.min, hb.max, b.summary.seconds);
  std::fflush(stdout);
}

// The trust-region part of the soft-mode phase on and off (docs/cmc_measurements.md, "The
// trust-region final phase on and off"; CmcOptions::area_trust_region), on the cases where the
// soft-mode loop stops above the tolerance; H min … max on the 40-grid at corner margin 0.1.
// "Routes from the D_H point": area_start Dirichlet. The
// catenoid boundary is the triangular catenoid piece; V_min the volume of its minimal surface (the
// area functional at H = 0, solved at the same degree).
void trust_region_table() {
  const GeneratedSection section("cmc-area-trust-region-full", "s without, s with");
  std::printf("| case | without | H without | s without | with | H with | s with |\n"
              "| --- | --- | --- | --- | --- | --- | --- |\n");
  const auto h_options = [](double H, bool dirichlet) {
    bpde::CmcOptions o;
    o.H = H;
    if (dirichlet) o.area_start = bpde::AreaStart::Dirichlet;
    return o;
  };
  trust_region_row("helicoid piece, tensor n = 4, H = 0, routes from the D_H point",
                   bpde::tensor_boundary(4, helicoid), h_options(0, true));
  trust_region_row("helicoid piece, tensor n = 8, H = 0.8", bpde::tensor_boundary(8, helicoid), h_options(0.8, false));
  trust_region_row("catenoid piece, tensor n = 6, H = 0, routes from the D_H point",
                   bpde::tensor_boundary(6, catenoid_square), h_options(0, true));
  trust_region_row("catenoid piece, tensor n = 10, H = 0", bpde::tensor_boundary(10, catenoid_square), h_options(0, false));
  trust_region_row("the same, routes from the D_H point", bpde::tensor_boundary(10, catenoid_square), h_options(0, true));
  trust_region_row("sphere triangle n = 8, H = 1", bpde::triangular_boundary(8, bpde::sphere_triangle), h_options(1, false));
  trust_region_row("sphere triangle n = 10, H = 1", bpde::triangular_boundary(10, bpde::sphere_triangle), h_options(1, false));
  trust_region_row("catenoid boundary, triangular n = 7, H = −0.1204", bpde::triangular_boundary(7, catenoid),
                   h_options(-0.1204, false));
  trust_region_row("the same at n = 8", bpde::triangular_boundary(8, catenoid), h_options(-0.1204, false));
  trust_region_row("the same at n = 8, H = 0.12", bpde::triangular_boundary(8, catenoid), h_options(0.12, false));
  for (const auto& [n, factors] : {std::pair{7, std::vector<double>{1.0, 1.05}}, std::pair{8, std::vector<double>{0.95, 1.05}}}) {
    const bpde::TriangularNet data = bpde::triangular_boundary(n, catenoid);
    const double v_min = solve(data, 0.0, true).V;
    for (double f : factors) {
      bpde::CmcOptions o;
      o.V = f * v_min;
      char name[128];
      std::snprintf(name, sizeof name, "catenoid boundary n = %d, V = %g V_min (V_min = %.5f)", n, f, v_min);
      trust_region_row(name, data, o);
    }
  }
  for (int n : {8, 10, 12}) {
    char name[96];
    std::snprintf(name, sizeof name, "curve A ([boundaries.md](boundaries.md)), tensor n = %d, H = 0", n);
    trust_region_row(name, curve_a(n), h_options(0, false));
  }
}

// The relative first variation of A_H at the D_H critical point of `data` (the gate of
// mean-curvature-start, docs/cmc_algorithm.md), measured on the plain rule with q points per
// direction: max |∇A + 2H∇V| over the free points against the same with |∇A| + 2|H||∇V|, as the
// probes above.
double dirichlet_point_first_variation(const bpde::TriangularNet& data, double H, int q) {
  const auto d = solve(data, H, bpde::CmcFunctionalKind::Dirichlet);
  const int n = data.n();
  const std::vector<int> idx = d.net.free_indices(bpde::FixedSet::Boundary);
  const bpde::AreaForm a = bpde::AreaForm::triangular(n, q, 1);
  const auto f = bpde::CmcFunctional::cached_triangular(n);
  Eigen::MatrixX3d GA, SA, GV, SV;
  a.gradient_rows_and_scale(d.net.points(), idx, &GA, &SA);
  f->volume_form().gradient_rows_and_scale(d.net.points(), idx, &GV, &SV);
  return (GA + 2 * H * GV).cwiseAbs().maxCoeff() / (SA + 2 * std::abs(H) * SV).maxCoeff();
}

// Conformal data: when mean-curvature-start is skipped (docs/cmc_measurements.md). The first
// variation at the D_H point (on the plain rule the area solve ends with), whether
// mean-curvature-start was tried and kept, and the area solve's seconds from the default start
// and with area_start Dirichlet.
void conformal_gate_table() {
  const GeneratedSection section("cmc-area-conformal-gate-full", "area solve s, dirichlet start s");
  std::printf("| data | n | H | first variation at the D_H point | mean-curvature-start | status | area solve s | "
              "dirichlet start s |\n| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  const auto row = [](const char* name, const bpde::TriangularNet& data, double H) {
    bpde::CmcOptions o;
    o.H = H;
    o.functional = bpde::CmcFunctionalKind::Area;
    const auto r = bpde::solve_cmc(data, o);
    o.area_start = bpde::AreaStart::Dirichlet;
    const auto rd = bpde::solve_cmc(data, o);
    const bpde::AreaRouteRecord* mc = r.routes.find(bpde::AreaRoute::MeanCurvatureStart);
    const char* gate = !mc || !mc->tried ? "not tried" : mc->kept ? "tried, kept" : "tried, gives way";
    std::printf("| %s | %d | %g | %.1e | %s | %s | %.3f | %.3f |\n", name, data.n(), H,
                dirichlet_point_first_variation(data, H, r.quadrature_points), gate, status_cell(r.summary).c_str(),
                r.summary.seconds, rd.summary.seconds);
    std::fflush(stdout);
  };
  for (int n : {8, 9, 10, 12, 14, 16}) row("sphere triangle", bpde::triangular_boundary(n, bpde::sphere_triangle), 1.0);
  for (int n : {8, 10, 12}) row("Fig. 1 circle", bpde::circle_three_arcs(n), -0.5);
}

// The small cap of H over the unit circle (H < 0): its radius R = 1/|H|, its centre c (on the z
// axis, below the plane: the cap bulges to +z) and its volume over the plane.
struct SmallCap {
  double R;
  Eigen::Vector3d c;
  double V;
  explicit SmallCap(double H) : R(1 / std::abs(H)), c(0, 0, -std::sqrt(R * R - 1)) {
    const double h = R - std::sqrt(R * R - 1);
    V = std::numbers::pi * h * h * (3 * R - h) / 3;
  }
  double dist(const bpde::TriangularNet& net) const {
    return worst(net, [&](const Eigen::Vector3d& x) { return (x - c).norm() - R; });
  }
};

// The area and the mean-curvature functional on the circle at degree 10, H = -0.5 and -0.9
// (docs/cmc_measurements.md, "The mean-curvature functional on the circle at degree 10"): the
// distance to the sphere (40-grid, corners included), H on the 40-grid at corner margin 0.1, the
// status with the residual of the functional solved, and the summary's seconds.
void mean_curvature_degree_10() {
  const GeneratedSection section("cmc-mean-curvature-circle-10-full", "seconds");
  std::printf("| H | functional | dist to the sphere | max \\|H_sampled − H\\| | status | residual | seconds |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- |\n");
  for (double H : {-0.5, -0.9}) {
    const SmallCap cap(H);
    for (const bpde::CmcFunctionalKind f : {bpde::CmcFunctionalKind::Area, bpde::CmcFunctionalKind::MeanCurvature}) {
      const auto r = solve(bpde::circle_three_arcs(10), H, f);
      const bpde::MeanCurvatureStats s = bpde::mean_curvature_stats(r.net, 40, 0.1);
      std::printf("| %g | %s | %.1e | %.1e | %s | %s %.1e | %.2f |\n", H, bpde::to_string(r.functional).c_str(),
                  cap.dist(r.net), std::max(std::abs(s.min - H), std::abs(s.max - H)), status_cell(r.summary).c_str(),
                  f == bpde::CmcFunctionalKind::MeanCurvature ? "√Φ" : "first variation", r.summary.residual,
                  r.summary.seconds);
      std::fflush(stdout);
    }
  }
}

// The mean-curvature functional's V form on the circle (docs/cmc_measurements.md, "The
// mean-curvature functional's V form on the circle"): v0 the volume of the small cap of H, solver
// newton and ceres, n = 8 … 14; the H found against the cap's, the distance to the cap's sphere.
void mean_curvature_volume_form() {
  const GeneratedSection section("cmc-mean-curvature-volume-form-full", "iterations, seconds");
  std::printf("| n | H of the cap | solver | iterations | status | √Φ | H error | dist | seconds |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (int n : {8, 10, 12, 14})
    for (double H : {-0.5, -0.9})
      for (const bpde::CmcSolver solver : {bpde::CmcSolver::Newton, bpde::CmcSolver::Ceres}) {
        const SmallCap cap(H);
        bpde::CmcOptions o;
        o.functional = bpde::CmcFunctionalKind::MeanCurvature;
        o.V = cap.V;
        o.solver = solver;
        const auto r = bpde::solve_cmc(bpde::circle_three_arcs(n), o);
        std::printf("| %d | %g | %s | %d | %s | %.1e | %.1e | %.1e | %.2f |\n", n, H, bpde::to_string(solver).c_str(),
                    r.summary.iterations, status_cell(r.summary).c_str(), r.summary.residual, std::abs(r.H - H),
                    cap.dist(r.net), r.summary.seconds);
        std::fflush(stdout);
      }
}

// The circle at n = 10 solved to tighter first-variation tolerances than the default 1e-11
// (docs/cmc_measurements.md, "Degree tables"): whether the distance and the H range at a degree are set by the
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

// The V form past the hemisphere (docs/cmc_algorithm.md, `smaller-volume-start`): v0 the
// volume of the larger cap of H over the unit circle (radius 1/|H|, centre √(R² − 1) above the
// plane, height R + √(R² − 1)), the area or the mean-curvature functional, solver newton or ceres;
// one row per (n, H) of `cases`.
void larger_caps(const std::vector<std::pair<int, double>>& cases, bpde::CmcSolver solver,
                 bpde::CmcFunctionalKind functional = bpde::CmcFunctionalKind::Area) {
  std::printf("| n | H of the larger cap | v0 | status | first variation | H found | dist | H range | "
              "continuation steps | seconds | route kept |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const auto& [n, H] : cases) {
    const double R = 1 / std::abs(H), hb = R + std::sqrt(R * R - 1);
    const Eigen::Vector3d c(0, 0, std::sqrt(R * R - 1));
    bpde::CmcOptions o;
    o.functional = functional;
    o.V = std::numbers::pi * hb * hb * (3 * R - hb) / 3;
    o.solver = solver;
    const auto r = bpde::solve_cmc(bpde::circle_three_arcs(n), o);
    const bpde::MeanCurvatureStats s = bpde::mean_curvature_stats(r.net, 40, 0.1);
    std::printf("| %d | %g | %.4g | %s | %.2e | %.10f | %.1e | %.5f … %.5f | %d | %.1f | %s |\n", n, H, *o.V,
                status_cell(r.summary).c_str(), r.summary.residual, r.H,
                worst(r.net, [&](const Eigen::Vector3d& x) { return (x - c).norm() - R; }), s.min, s.max,
                r.continuation_steps, r.summary.seconds,
                r.routes.kept() ? bpde::to_string(r.routes.kept()->route)
                                : (functional == bpde::CmcFunctionalKind::Area ? "none" : "-"));
    std::fflush(stdout);
  }
}

// The error of the rule q (its change to the next rule of the sequence, as area_rule.h measures it)
// on the solved circle nets, plain (grading 1) and graded (grading 3).
// The section cmc-area-rule-probe of docs/cmc_measurements.md; errors below 1e-13 (rounding, whose
// digits vary with the build) print as "< 1e-13".
void rule_probe() {
  const bpde::examples::GeneratedSection section("cmc-area-rule-probe");
  std::printf("| n | sine of the corner angle (data) | interior angle (deg) |\n| --- | --- | --- |\n");
  for (int n : {4, 5, 6, 7, 8, 10}) {
    const bpde::TriangularNet d = bpde::circle_three_arcs(n);
    const Eigen::Vector3d a = d.derivative(0, 0, 1, 0), b = d.derivative(0, 0, 0, 1);
    const double s = a.cross(b)(2) / (a.norm() * b.norm());  // > 0: below 180°
    std::printf("| %d | %.1e | %.3f |\n", n, std::abs(s), s > 0 ? 180 - std::asin(s) * 180 / M_PI : 180 + std::asin(-s) * 180 / M_PI);
  }
  const std::vector<int> qs = {11, 15, 20, 27, 36, 48, 64, 86};
  std::printf("\n| n | grading | q = 11 | 15 | 20 | 27 | 36 | 48 | 64 | 86 |\n| --- | --- |");
  for (size_t k = 0; k < qs.size(); ++k) std::printf(" --- |");
  std::printf("\n");
  for (int n : {4, 5, 8}) {
    const auto r = solve(bpde::circle_three_arcs(n), -0.5, true);
    const Eigen::MatrixX3d& P = r.net.points();
    const std::vector<int> idx = r.net.free_indices(bpde::FixedSet::Boundary);
    for (int g : {1, 3}) {
      std::printf("| %d | %d |", n, g);
      for (int q : qs) {
        const int qn = q + (q + 2) / 3;
        const bpde::AreaForm a = bpde::AreaForm::triangular(n, q, g), b = bpde::AreaForm::triangular(n, qn, g);
        Eigen::MatrixX3d Ga, Gb, Sb;
        a.gradient_rows_and_scale(P, idx, &Ga, nullptr);
        b.gradient_rows_and_scale(P, idx, &Gb, &Sb);
        const double Ab = b.value(P);
        const double c = std::max(std::abs(a.value(P) - Ab) / Ab, (Ga - Gb).cwiseAbs().maxCoeff() / Sb.maxCoeff());
        std::printf(" %s |", bpde::examples::stable_small(c, 1e-13).c_str());
      }
      std::printf("\n");
    }
  }
}

// A_H on the area route's circle (degree n, H), on the rule the solve ended with: the first
// variation over the free points as a 3k vector (entry 3a + c) and its relative size, and the
// Hessian. Used by the probes below.
struct CircleAreaProblem {
  double H;
  int n;
  bpde::CmcResult<bpde::TriangularNet> r;
  std::vector<int> idx;
  int k;
  std::shared_ptr<const bpde::CmcFunctional> f;
  bpde::AreaForm a;

  CircleAreaProblem(double H_, int n_)
      : H(H_),
        n(n_),
        r(solve(bpde::circle_three_arcs(n_), H_, true)),
        idx(r.net.free_indices(bpde::FixedSet::Boundary)),
        k(static_cast<int>(idx.size())),
        f(bpde::CmcFunctional::cached_triangular(n_)),
        a(bpde::AreaForm::triangular(n_, r.quadrature_points, 1)) {}

  double gradient(const Eigen::MatrixX3d& P, Eigen::VectorXd& g) const {
    Eigen::MatrixX3d GA, SA, GV, SV;
    a.gradient_rows_and_scale(P, idx, &GA, &SA);
    f->volume_form().gradient_rows_and_scale(P, idx, &GV, &SV);
    const Eigen::MatrixX3d G = GA + 2 * H * GV, S = SA + 2 * std::abs(H) * SV;
    g.resize(3 * k);
    for (int i = 0; i < k; ++i) g.segment<3>(3 * i) = G.row(i).transpose();
    return G.cwiseAbs().maxCoeff() / S.maxCoeff();
  }
  Eigen::MatrixXd hessian(const Eigen::MatrixX3d& P) const {
    return a.hessian(P, idx) + 2 * H * f->volume_form().hessian(P, idx);
  }
  // P with the free rows moved by d (3k).
  Eigen::MatrixX3d moved(const Eigen::MatrixX3d& P, const Eigen::VectorXd& d) const {
    Eigen::MatrixX3d Pn = P;
    for (int i = 0; i < k; ++i) Pn.row(idx[i]) += d.segment<3>(3 * i).transpose();
    return Pn;
  }
};

// From the solved circle (H = -0.5 at n = 8 and 10, converged; H = -0.9 at n = 10, stopped at its
// numerical limit): Newton steps on A_H restricted to the motion of each free point along the
// surface normal at its parameter (I/n), the gauge that removes the tangential (reparametrisation)
// modes. Prints the residual, the normal and tangential parts of the gradient (Euclidean) and the
// H deviation (40-grid, corner margin 0.1) before each step, on the rule the solve ended with.
// Then one full Newton step (all modes, exact Hessian, LU) from the H = -0.9 end point.
void gauge_probe() {
  std::printf("| H | n | step | residual | \\|g\\| normal part | \\|g\\| tangential part | reduced Hessian eigenvalues | max \\|H_sampled − H\\| |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const auto& [H, n] : {std::pair{-0.5, 8}, std::pair{-0.5, 10}, std::pair{-0.9, 10}}) {
    const CircleAreaProblem p(H, n);
    const int k = p.k;
    bpde::TriangularNet net = p.r.net;
    for (int step = 0; step <= 3; ++step) {
      const Eigen::MatrixX3d& P = net.points();
      Eigen::VectorXd g;
      const double rel = p.gradient(P, g);
      Eigen::MatrixXd Nm = Eigen::MatrixXd::Zero(3 * k, k);
      for (int i = 0; i < k; ++i) {
        const bpde::MultiIndex I = bpde::TriangularNet::multi_index(n, p.idx[i]);
        const double u = double(I[0]) / n, v = double(I[1]) / n;
        Nm.block<3, 1>(3 * i, i) = net.derivative(u, v, 1, 0).cross(net.derivative(u, v, 0, 1)).normalized();
      }
      const Eigen::MatrixXd K = p.hessian(P);
      const Eigen::MatrixXd Kr = Nm.transpose() * K * Nm;
      const Eigen::VectorXd gr = Nm.transpose() * g;
      const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(Kr).eigenvalues();
      const bpde::MeanCurvatureStats hs = bpde::mean_curvature_stats(net, 40, 0.1);
      std::printf("| %g | %d | %d | %.1e | %.1e | %.1e | %.1e … %.1e | %.1e |\n", H, n, step, rel, gr.norm(),
                  (g - Nm * gr).norm(), ev(0), ev(k - 1), std::max(std::abs(hs.min - H), std::abs(hs.max - H)));
      net.points() = p.moved(P, Nm * Kr.ldlt().solve(-gr));
    }
  }
  {
    // One full Newton step over all modes from the H = -0.9 end point (n = 10).
    const CircleAreaProblem p(-0.9, 10);
    const Eigen::MatrixX3d P = p.r.net.points();
    Eigen::VectorXd g, gn;
    const double r0 = p.gradient(P, g);
    const Eigen::VectorXd d = -p.hessian(P).fullPivLu().solve(g);
    const double r1 = p.gradient(p.moved(P, d), gn);
    std::printf("\nFull Newton step from the H = -0.9, n = 10 end point: residual %.1e -> %.1e, max |step| %.1e"
                " (the free points are O(1))\n", r0, r1, d.cwiseAbs().maxCoeff());
  }
  // The minimum-residual step over all modes, soft ones included: Levenberg–Marquardt on ‖g‖²,
  // (K² + μC) d = -K g (C the Dirichlet Gram), the μ in 1e-2, 1e-3, …, 1e-22 with the smallest
  // residual among those that lower ‖g‖, from the converged circle at n = 10 (H = -0.5).
  std::printf("\n| n | step | residual | best μ |\n| --- | --- | --- | --- |\n");
  const int n = 10;
  const CircleAreaProblem p(-0.5, n);
  const int k = p.k;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(3 * k, 3 * k);
  for (int i = 0; i < k; ++i)
    for (int j = 0; j < k; ++j) C.block<3, 3>(3 * i, 3 * j) = p.f->gram()(p.idx[i], p.idx[j]) * Eigen::Matrix3d::Identity();
  Eigen::MatrixX3d P = p.r.net.points();
  for (int step = 0; step <= 4; ++step) {
    Eigen::VectorXd g;
    const double r0 = p.gradient(P, g);
    const Eigen::MatrixXd K = p.hessian(P);
    double best = r0, best_mu = 0;
    Eigen::MatrixX3d best_P = P;
    for (double mu = 1e-2; mu >= 1e-22; mu *= 0.1) {
      const Eigen::MatrixX3d Pn = p.moved(P, -(K * K + mu * C).ldlt().solve(K * g));
      Eigen::VectorXd gn;
      const double rn = p.gradient(Pn, gn);
      if (gn.norm() < g.norm() && rn < best) {
        best = rn;
        best_mu = mu;
        best_P = Pn;
      }
    }
    std::printf("| %d | %d | %.2e | %.0e |\n", n, step, r0, best_mu);
    if (best_mu == 0) break;
    P = best_P;
  }
}

// Where the mean curvature of the area route deviates from H on the circle (docs/cmc_measurements.md,
// "Degree tables"): max |H_sampled - H| over the 40-grid for corner margins 0.1 … 0.3 (the margin of
// mean_curvature_stats: every barycentric coordinate <= 1 - margin), the same at margin 0.1 without
// the samples on the boundary edges, and the sample where the margin-0.1 maximum is taken.
void margin_probe() {
  const std::vector<double> margins = {0.1, 0.15, 0.2, 0.25, 0.3};
  std::printf("| H | n | status | margin 0.1 | 0.15 | 0.2 | 0.25 | 0.3 | 0.1, interior samples only | worst sample (u, v, w) |\n");
  std::printf("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  const int N = 40;
  for (double H : {-0.5, -0.9}) {
    for (int n : {10, 12, 14}) {
      const auto r = solve(bpde::circle_three_arcs(n), H, true);
      std::printf("| %g | %d | %s |", H, n, status_cell(r.summary).c_str());
      for (double m : margins) {
        const bpde::MeanCurvatureStats s = bpde::mean_curvature_stats(r.net, N, m);
        std::printf(" %.1e |", std::max(std::abs(s.min - H), std::abs(s.max - H)));
      }
      const bpde::TriangleMesh M = bpde::sample_mesh(r.net, N);
      double worst = 0, interior = 0;
      int wa = 0, wb = 0;
      for (int a = 0, k = 0; a <= N; ++a)
        for (int b = 0; a + b <= N; ++b, ++k) {
          if (std::max({a, b, N - a - b}) > 0.9 * N + 1e-9 || !(M.regular.size() == 0 || M.regular(k))) continue;
          const double d = std::abs(M.H(k) - H);
          if (d > worst) worst = d, wa = a, wb = b;
          if (a > 0 && b > 0 && a + b < N) interior = std::max(interior, d);
        }
      std::printf(" %.1e | (%.3f, %.3f, %.3f) |\n", interior, wa / double(N), wb / double(N), (N - wa - wb) / double(N));
    }
  }
}

// One library solve of the circle (H = -0.5, area functional, solver newton) at degree n and
// first-variation tolerance t, for scripts/evolver_compare.py --tolerances (docs/cmc_evolver.md,
// "Reproduce"): prints one JSON object with the summary and
// the net (FORMATS.md point order), whose error the script measures as it does for `bpde solve`.
// The CLI's jobs always solve to 1e-11 (FORMATS.md, "converged"); a looser tolerance is a library
// option only. Exit 0 converged (to t), 1 not converged, 2 bad arguments.
int solve_circle(int n, double tol) {
  bpde::CmcOptions o;
  o.H = -0.5;
  o.functional = bpde::CmcFunctionalKind::Area;
  o.tolerance = tol;
  o.validate();
  const auto r = bpde::solve_cmc(bpde::circle_three_arcs(n), o);
  std::printf("{\"degree\": %d, \"H\": %.17g, \"tolerance\": %.17g, \"status\": \"%s\", \"converged\": %s, \"residual\": %.17g, "
              "\"iterations\": %d, \"seconds\": %.17g, \"net\": {\"type\": \"triangular\", \"degree\": %d, \"points\": [",
              n, o.H, tol, bpde::to_string(r.summary.status), r.summary.converged ? "true" : "false", r.summary.residual,
              r.summary.iterations, r.summary.seconds, n);
  const Eigen::MatrixX3d& P = r.net.points();
  for (Eigen::Index i = 0; i < P.rows(); ++i)
    std::printf("%s[%.17g, %.17g, %.17g]", i ? ", " : "", P(i, 0), P(i, 1), P(i, 2));
  std::printf("]}}\n");
  return r.summary.converged ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--solve-circle") {
    int n = 0;
    double tol = 0;
    size_t used_n = 0, used_t = 0;
    try {
      if (argc == 4) n = std::stoi(argv[2], &used_n), tol = std::stod(argv[3], &used_t);
    } catch (const std::exception&) {
      used_n = used_t = 0;
    }
    if (argc != 4 || used_n != std::string(argv[2]).size() || used_t != std::string(argv[3]).size()) {
      std::fprintf(stderr, "error: --solve-circle needs a degree N (an integer) and a TOLERANCE (a number)\n");
      return 2;
    }
    try {
      return solve_circle(n, tol);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 2;
    }
  }
  if (argc > 1 && std::string(argv[1]) == "--rule-probe") {
    rule_probe();
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--gauge-probe") {
    gauge_probe();
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--margin-probe") {
    margin_probe();
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--larger-caps-mean-curvature") {
    // "--larger-caps-mean-curvature N H" runs one case.
    const auto mc = bpde::CmcFunctionalKind::MeanCurvature;
    if (argc == 4) {
      larger_caps({{std::stoi(argv[2]), std::stod(argv[3])}}, bpde::CmcSolver::Newton, mc);
      return 0;
    }
    larger_caps({{8, -0.99}, {10, -0.99}, {12, -0.99}, {8, -0.9}, {10, -0.9}, {12, -0.9}, {8, -0.7}, {10, -0.7},
                 {12, -0.7}, {10, -0.5}, {12, -0.5}, {10, -0.3}, {12, -0.3}},
                bpde::CmcSolver::Newton, mc);
    larger_caps({{10, -0.7}}, bpde::CmcSolver::Ceres, mc);
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--larger-caps") {
    // About 10 minutes in all; "--larger-caps N H" runs one case.
    if (argc == 4) {
      larger_caps({{std::stoi(argv[2]), std::stod(argv[3])}}, bpde::CmcSolver::Newton);
      return 0;
    }
    larger_caps({{8, -0.7}, {10, -0.7}, {12, -0.7}, {8, -0.9}, {10, -0.9}, {12, -0.9}, {10, -0.99}, {10, -0.5},
                 {12, -0.5}},
                bpde::CmcSolver::Newton);
    larger_caps({{10, -0.7}}, bpde::CmcSolver::Ceres);
    return 0;
  }
  if (argc > 1 && std::string(argv[1]) == "--tolerance-probe") {
    tolerance_probe();
    return 0;
  }
  const bool full = argc > 1 && std::string(argv[1]) == "--full";
  // "--full NAME ..." prints only the named "-full" sections (scripts/docs.py --full-sections).
  const std::vector<std::string> only(argv + std::min(argc, 2), argv + argc);
  const auto wants = [&](const char* name) {
    return only.empty() || std::find(only.begin(), only.end(), name) != only.end();
  };
  std::printf("### Circle in three arcs, H = -0.5, n = 4, 5\n\n");
  circle_table("cmc-area-circle", -0.5, {4, 5});
  std::printf("\n### Area rules at the circle's corners\n\n");
  rule_probe();
  if (!full) return 0;
  if (wants("cmc-area-circle-0.5-full")) {
    std::printf("\n### Circle in three arcs, H = -0.5\n\n");
    circle_table("cmc-area-circle-0.5-full", -0.5, {4, 6, 8, 10, 12, 14, 16});
  }
  if (wants("cmc-area-circle-0.9-full")) {
    std::printf("\n### Circle in three arcs, H = -0.9\n\n");
    circle_table("cmc-area-circle-0.9-full", -0.9, {4, 6, 8, 10, 12, 14, 16});
  }
  std::printf("\n### H = 0\n\n");
  minimal_tables({4, 6, 8, 10, 12}, {4, 6, 8, 10, 12, 14, 16}, wants);
  if (wants("cmc-area-trust-region-full")) {
    std::printf("\n### The trust-region final phase on and off\n\n");
    trust_region_table();
  }
  if (wants("cmc-area-conformal-gate-full")) {
    std::printf("\n### Conformal data: when the mean-curvature start is skipped\n\n");
    conformal_gate_table();
  }
  if (wants("cmc-area-starts-full")) {
    std::printf("\n### The starts of the area functional side by side\n\n");
    area_starts();
  }
  if (wants("cmc-mean-curvature-circle-10-full")) {
    std::printf("\n### The mean-curvature functional on the circle at degree 10\n\n");
    mean_curvature_degree_10();
  }
  if (wants("cmc-mean-curvature-volume-form-full")) {
    std::printf("\n### The mean-curvature functional's V form on the circle\n\n");
    mean_curvature_volume_form();
  }
  return 0;
}
