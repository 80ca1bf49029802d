// 005-complex-exact: surfaces of several patches (FORMATS.md "Patch complexes") against exact
// answers, as complex jobs run in-process through the job runner (jobs/run_job.h: job_from_json,
// run_job, write_job_result; the path of `bpde solve`), over a grid of degrees p and refinements
// h (`refine` with `refit`: the boundary fitted again at every level).
//
// Usage: example_005_complex_exact [--tables] [--all] [--cases CASE,...] [--grid CASE=P:R,P:R,...]...
//                                  [EXAMPLE_DIR [OUT_DIR]]
//   Without --tables: usage only (the tables take minutes; scripts/docs.py runs them through the
//   complex-exact generator, scripts/complex_exact_tables.py).
//   --tables       the tables of docs/complex.md ("The exact cases"), one per case, over each
//                  case's grid of p x refine; the cells of the default run set are solved, the
//                  others printed as skipped for time.
//   --all          solve every cell of every grid (long: the area solves of fine grids take minutes each).
//   --cases C,...  only these cases (their sections alone).
//   --grid C=CELLS solve exactly these cells of case C (p:refine, comma-separated; the grid grows
//                  to hold them), e.g. --grid cap-circle=3:0,3:1,3:2.
//   EXAMPLE_DIR defaults to examples/005-complex-exact (the job files CASE.json), OUT_DIR to
//   out/005-complex-exact (each cell's files in OUT_DIR/CASE-pP-rR, as `bpde solve` writes them).
//
// The cases (job files): the spherical cap of radius 2 over the unit circle (|H| = 1/2) given as
// one circle (cap-circle) and as 5, 6 and 8 arcs (cap-arcs-K); Enneper's surface over the
// parameter disc of radius 0.8, its boundary as 3072 closed samples (enneper); the catenoid
// between the unit circles at z = ±1/2 (catenoid, two loops); the 4 x 0.5 rectangle at H = 0.2 on
// a user layout of 8 x 1 squares by the Dirichlet functional (rectangle) and by the area
// functional (rectangle-area, the same job file), no exact surface: its certificate, also over the
// middle third |x| ≤ 1.5 and the middle half |x| ≤ 1. Columns:
//   |A − A*|/A*   relative area error against the exact area;
//   dist          the largest closest-point distance of the sampled mesh's vertices (samples 16
//                 per patch edge) from the exact surface;
//   cert          report.certificate.mean_curvature_deviation, max |H(x) − H| over the welded
//                 mesh's regular vertices (corners and seams included);
//   seam          report.seam_angle_max (degrees);
//   h-rate        log2 of the ratio of the error to the one at refine − 1 (same p);
//   p-step        log2 of the ratio to the error at the previous degree of the grid (same
//                 refine), per degree step.
#include "bezierpde/core/eigen.h"
#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/jobs/run_job.h"
#include "examples/common/generated.h"

namespace fs = std::filesystem;
using bpde::Json;

namespace {

constexpr int kDistanceSamples = 16;
// The rectangle's corners: a smooth surface through two orthogonal straight lines has H = 0 where
// they cross, so no polynomial patch reaches H = 0.2 there (docs/complex.md); its certificate is
// also given over the samples farther than this from the four corners.
constexpr double kCornerMargin = 0.05;

// The cap of the sphere of radius 2 over the unit circle (centre (0, 0, −√3)): A = 2πRh,
// V = πh²(3R − h)/3 with h = 2 − √3.
const double kCapArea = 4 * std::numbers::pi * (2 - std::sqrt(3.0));
const double kCapVolume = std::numbers::pi * std::pow(2 - std::sqrt(3.0), 2) * (6 - (2 - std::sqrt(3.0))) / 3;

double sphere_distance(const Eigen::Vector3d& x) { return std::abs((x - Eigen::Vector3d(0, 0, -std::sqrt(3.0))).norm() - 2); }

// The catenoid ρ = a cosh(z/a) through the unit circles at z = ±1/2: a cosh(1/(2a)) = 1, the larger
// root (the stable catenoid; the smaller a = 0.235 has area 6.85).
double catenoid_neck() {
  double a = 0.8;
  for (int it = 0; it < 60; ++it) a -= (a * std::cosh(0.5 / a) - 1) / (std::cosh(0.5 / a) - 0.5 / a * std::sinh(0.5 / a));
  return a;
}
const double kNeck = catenoid_neck();
const double kCatenoidArea = std::numbers::pi * kNeck * kNeck * (std::sinh(1 / kNeck) + 1 / kNeck);

// Closest point on the profile (a cosh(s/a), s) to (ρ, z): Newton on the squared distance from s = z.
double catenoid_distance(const Eigen::Vector3d& x) {
  const double rho = std::hypot(x(0), x(1)), z = x(2);
  double s = z;
  for (int it = 0; it < 50; ++it) {
    const double c = std::cosh(s / kNeck), sh = std::sinh(s / kNeck), d = kNeck * c - rho;
    const double g1 = d * sh + (s - z), g2 = sh * sh + d * c / kNeck + 1;
    const double step = g1 / g2;
    s -= step;
    if (std::abs(step) < 1e-16) break;
  }
  return std::hypot(kNeck * std::cosh(s / kNeck) - rho, s - z);
}

// Enneper's surface X(u, v) = (u − u³/3 + uv², −v + v³/3 − vu², u² − v²) over the disc of radius
// r = 0.8: A = ∫ (1 + u² + v²)² = π/3 ((1 + r²)³ − 1).
constexpr double kEnneperR = 0.8;
const double kEnneperArea = std::numbers::pi / 3 * (std::pow(1 + kEnneperR * kEnneperR, 3) - 1);

// Closest point on Enneper's surface: Gauss–Newton in (u, v) from (x, −y).
double enneper_distance(const Eigen::Vector3d& x) {
  double u = x(0), v = -x(1);
  Eigen::Vector3d X;
  for (int it = 0; it < 60; ++it) {
    X << u - u * u * u / 3 + u * v * v, -v + v * v * v / 3 - v * u * u, u * u - v * v;
    Eigen::Matrix<double, 3, 2> J;
    J << 1 - u * u + v * v, 2 * u * v, -2 * u * v, -1 + v * v - u * u, 2 * u, -2 * v;
    const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(J.transpose() * (x - X));
    u += step(0), v += step(1);
    if (step.norm() < 1e-16) break;
  }
  X << u - u * u * u / 3 + u * v * v, -v + v * v * v / 3 - v * u * u, u * u - v * v;
  return (X - x).norm();
}

struct Case {
  std::string name, title;
  std::string file;  // the job file (CASE.json unless given)
  Json problem;      // replaces the job's problem when not null
  std::optional<double> area, volume;
  std::function<double(const Eigen::Vector3d&)> distance;  // empty: no exact surface
  std::vector<int> ps, rs;                                // the grid shown
  std::set<std::pair<int, int>> run;                      // the cells solved by default
};

std::vector<Case> cases() {
  std::vector<Case> c;
  const std::set<std::pair<int, int>> cap_run{{3, 0}, {3, 1}, {3, 2}, {4, 0}, {4, 1}, {6, 0}, {8, 0}};
  c.push_back({"cap-circle", "the cap, one circle (fan of 6 triangles)", "", nullptr, kCapArea, kCapVolume, sphere_distance,
               {3, 4, 6, 8}, {0, 1, 2}, cap_run});
  for (int k : {5, 6, 8})
    c.push_back({"cap-arcs-" + std::to_string(k),
                 "the cap, " + std::to_string(k) + " arcs (fan of " + std::to_string(k) + " triangles)", "", nullptr, kCapArea,
                 kCapVolume, sphere_distance, {3, 4, 6}, {0, 1}, {{3, 0}, {3, 1}, {4, 0}, {6, 0}}});
  c.push_back({"enneper", "Enneper's surface, r = 0.8 (fan of 6 triangles)", "", nullptr, kEnneperArea, std::nullopt,
               enneper_distance, {3, 4, 6, 8, 10}, {0, 1, 2}, {{3, 0}, {3, 1}, {4, 0}, {6, 0}, {8, 0}, {10, 0}}});
  c.push_back({"catenoid", "the catenoid (ring of 4 quads)", "", nullptr, kCatenoidArea, std::nullopt, catenoid_distance,
               {3, 4, 6, 8}, {0, 1, 2}, {{3, 0}, {3, 1}, {3, 2}, {4, 0}, {4, 1}, {4, 2}, {6, 0}, {8, 0}}});
  c.push_back({"rectangle", "the 4 x 0.5 rectangle at H = 0.2 (8 x 1 squares, the Dirichlet functional)", "", nullptr,
               std::nullopt, std::nullopt, {}, {4, 6, 8}, {0, 1}, {{4, 0}, {4, 1}, {6, 0}, {6, 1}, {8, 0}, {8, 1}}});
  // (start dirichlet: mean-curvature-start is not tried on this job anyway, 705 free coordinates at
  // degree 6 being above its 600, docs/complex.md)
  c.push_back({"rectangle-area", "the 4 x 0.5 rectangle at H = 0.2 (8 x 1 squares, the area functional, start dirichlet)",
               "rectangle", Json{{"kind", "cmc"}, {"H", 0.2}, {"functional", "area"}, {"start", "dirichlet"}}, std::nullopt,
               std::nullopt, {}, {4, 6, 8},
               {0, 1}, {{4, 0}, {6, 0}}});
  // The Dirichlet extremal of the unit circle (cap-circle.json's boundary, interpolation fits): a
  // planar disc, whose area error is the boundary fits' alone; dist: its largest |z|.
  c.push_back({"dirichlet-disc", "the Dirichlet extremal of the unit circle (fan of 6 triangles; A* = π)",
               "cap-circle", Json{{"kind", "extremal"}, {"energy", {{"name", "dirichlet"}}}}, std::numbers::pi,
               std::nullopt, [](const Eigen::Vector3d& x) { return std::abs(x(2)); }, {3, 4}, {0, 1, 2, 3},
               {{3, 0}, {3, 1}, {3, 2}, {3, 3}, {4, 0}, {4, 1}, {4, 2}, {4, 3}}});
  return c;
}

struct Cell {
  bool ran = false;
  int exit = 0, patches = 0;
  double area_error = NAN, distance = NAN, cert = NAN, seam = NAN, seconds = NAN;
  double cert_inside = NAN, cert_middle = NAN, cert_inner = NAN, net_spread = NAN;  // rectangle: away from the corners; the net's reach
  std::string error;
};

Cell solve(const Case& k, const Json& base, int p, int r, const fs::path& out) {
  Cell cell;
  Json j = base;
  j["boundary"]["degree"] = p;
  j["boundary"]["refine"] = r;
  if (!k.problem.is_null()) j["problem"] = k.problem;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const bpde::Job job = bpde::job_from_json(j, k.name);
    const bpde::SolveOutcome o = bpde::run_job(job);
    const bpde::WrittenResult w = bpde::write_job_result((out / (k.name + "-p" + std::to_string(p) + "-r" + std::to_string(r))).string(), job, o);
    cell.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    cell.ran = true;
    cell.exit = w.exit_code;
    const Json& rep = w.result["report"];
    cell.patches = rep.value("patches", 0);
    if (k.area && rep["area"].is_number()) cell.area_error = std::abs(rep["area"].get<double>() - *k.area) / *k.area;
    if (rep.contains("certificate")) cell.cert = rep["certificate"]["mean_curvature_deviation"].get<double>();
    cell.seam = rep.value("seam_angle_max", NAN);
    const bpde::ComplexMesh m = bpde::sample_complex(*o.complex, kDistanceSamples);
    if (k.distance) {
      cell.distance = 0;
      for (Eigen::Index v = 0; v < m.mesh.V.rows(); ++v)
        cell.distance = std::max(cell.distance, k.distance(m.mesh.V.row(v).transpose()));
    } else {
      // the rectangle: H away from its corners (farther than kCornerMargin), and the
      // control net's reach: the largest distance of a control point from the centre of the
      // sampled surface's bounding box over the box's diagonal
      const double H = j["problem"].value("H", 0.0);
      cell.cert_inside = cell.cert_middle = cell.cert_inner = 0;
      for (Eigen::Index v = 0; v < m.mesh.V.rows(); ++v) {
        const Eigen::Vector3d x = m.mesh.V.row(v).transpose();
        if (std::hypot(2 - std::abs(x(0)), 0.25 - std::abs(x(1))) < kCornerMargin) continue;
        if (m.mesh.regular.size() && !m.mesh.regular(v)) continue;
        cell.cert_inside = std::max(cell.cert_inside, std::abs(m.mesh.H(v) - H));
        if (std::abs(x(0)) <= 1.5) cell.cert_middle = std::max(cell.cert_middle, std::abs(m.mesh.H(v) - H));
        if (std::abs(x(0)) <= 1.0) cell.cert_inner = std::max(cell.cert_inner, std::abs(m.mesh.H(v) - H));
      }
      const Eigen::Vector3d lo = m.mesh.V.colwise().minCoeff(), hi = m.mesh.V.colwise().maxCoeff();
      const Eigen::Vector3d centre = 0.5 * (lo + hi);
      cell.net_spread = (o.complex->points.rowwise() - centre.transpose()).rowwise().norm().maxCoeff() / (hi - lo).norm();
    }
  } catch (const std::exception& e) {
    cell.error = e.what();
  }
  return cell;
}

std::string num(double x) {
  if (std::isnan(x)) return "—";
  return bpde::examples::stable_small(x, 1e-14);
}

// log2(coarse / fine) / steps, when both are above the rounding floor
std::string rate(double coarse, double fine, double steps, double floor) {
  if (!(coarse > floor && fine > floor)) return "—";
  char b[16];
  std::snprintf(b, sizeof b, "%.1f", std::log2(coarse / fine) / steps);
  return b;
}

void table(const Case& k, const std::map<std::pair<int, int>, Cell>& cells) {
  const std::string name = "complex-exact-" + k.name;
  const bpde::examples::GeneratedSection section(name.c_str(), "s");
  std::printf("#### %s\n\n", k.title.c_str());
  const bool exact = static_cast<bool>(k.distance);
  if (exact)
    std::printf("| p | refine | patches | exit | \\|A − A*\\|/A* | h-rate | p-step | dist | h-rate | p-step | cert | seam° | s |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  else
    std::printf("| p | refine | patches | exit | cert | cert, corners left out | cert, \\|x\\| ≤ 1.5 | h-rate | p-step | cert, \\|x\\| ≤ 1 | net reach | seam° | s |\n"
                "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (std::size_t pi = 0; pi < k.ps.size(); ++pi)
    for (std::size_t ri = 0; ri < k.rs.size(); ++ri) {
      const int p = k.ps[pi], r = k.rs[ri];
      const auto it = cells.find({p, r});
      if (it == cells.end() || !it->second.ran) {
        const std::string why = it == cells.end() ? "skipped for time" : "error: " + it->second.error;
        std::printf("| %d | %d | %s |%s\n", p, r, why.c_str(), exact ? " | | | | | | | | | |" : " | | | | | | | | | |");
        continue;
      }
      const Cell& c = it->second;
      const Cell* h = nullptr;  // refine − 1, same p
      const Cell* q = nullptr;  // previous degree, same refine
      if (ri > 0 && k.rs[ri - 1] == r - 1) {
        const auto f = cells.find({p, r - 1});
        if (f != cells.end() && f->second.ran) h = &f->second;
      }
      if (pi > 0) {
        const auto f = cells.find({k.ps[pi - 1], r});
        if (f != cells.end() && f->second.ran) q = &f->second;
      }
      const double dp = pi > 0 ? p - k.ps[pi - 1] : 1;
      char s[16];
      std::snprintf(s, sizeof s, "%.1f", c.seconds);
      if (exact)
        std::printf("| %d | %d | %d | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", p, r, c.patches, c.exit,
                    num(c.area_error).c_str(), h ? rate(h->area_error, c.area_error, 1, 1e-13).c_str() : "",
                    q ? rate(q->area_error, c.area_error, dp, 1e-13).c_str() : "", num(c.distance).c_str(),
                    h ? rate(h->distance, c.distance, 1, 1e-12).c_str() : "",
                    q ? rate(q->distance, c.distance, dp, 1e-12).c_str() : "", num(c.cert).c_str(), num(c.seam).c_str(), s);
      else
        std::printf("| %d | %d | %d | %d | %s | %s | %s | %s | %s | %s | %.2f | %s | %s |\n", p, r, c.patches, c.exit,
                    num(c.cert).c_str(), num(c.cert_inside).c_str(), num(c.cert_middle).c_str(),
                    h ? rate(h->cert_middle, c.cert_middle, 1, 1e-12).c_str() : "",
                    q ? rate(q->cert_middle, c.cert_middle, dp, 1e-12).c_str() : "", num(c.cert_inner).c_str(), c.net_spread,
                    num(c.seam).c_str(), s);
    }
}

}  // namespace

int main(int argc, char** argv) {
  bool tables = false, all = false;
  std::set<std::string> only;  // --cases: these cases alone
  std::map<std::string, std::set<std::pair<int, int>>> asked;
  std::vector<std::string> positional;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (arg == "--tables") {
      tables = true;
    } else if (arg == "--all") {
      all = true;
    } else if (arg == "--cases" && a + 1 < argc) {
      std::stringstream names(argv[++a]);
      for (std::string name; std::getline(names, name, ',');) only.insert(name);
    } else if (arg == "--grid" && a + 1 < argc) {
      const std::string g = argv[++a];
      const auto eq = g.find('=');
      if (eq == std::string::npos) {
        std::fprintf(stderr, "--grid: expected CASE=P:R,P:R,..., got %s\n", g.c_str());
        return 2;
      }
      auto& set = asked[g.substr(0, eq)];
      std::stringstream cells(g.substr(eq + 1));
      for (std::string cell; std::getline(cells, cell, ',');) {
        int p = 0, r = 0;
        if (std::sscanf(cell.c_str(), "%d:%d", &p, &r) != 2 || p < 1 || r < 0) {
          std::fprintf(stderr, "--grid: bad cell %s (expected P:R)\n", cell.c_str());
          return 2;
        }
        set.insert({p, r});
      }
    } else if (arg.rfind("--", 0) == 0) {
      std::fprintf(stderr, "unknown option %s\n", arg.c_str());
      return 2;
    } else {
      positional.push_back(arg);
    }
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // each table as it is done (the runs take minutes)
  if (!tables) {
    std::printf("example_005_complex_exact --tables [--all] [--grid CASE=P:R,...] [EXAMPLE_DIR [OUT_DIR]]\n"
                "  the exact cases of docs/complex.md as complex jobs (minutes; see main.cpp)\n");
    return 0;
  }
  const fs::path dir = positional.size() > 0 ? fs::path(positional[0]) : fs::path("examples/005-complex-exact");
  const fs::path out = positional.size() > 1 ? fs::path(positional[1]) : fs::path("out/005-complex-exact");
  std::vector<Case> list = cases();
  std::set<std::string> names = only;
  for (const auto& [name, set] : asked) names.insert(name);
  for (const std::string& name : names)
    if (std::none_of(list.begin(), list.end(), [&](const Case& k) { return k.name == name; })) {
      std::fprintf(stderr, "no case %s\n", name.c_str());
      return 2;
    }
  for (Case& k : list) {
    if (!only.empty() && !only.count(k.name)) continue;
    std::set<std::pair<int, int>> run = k.run;
    if (all)
      for (int p : k.ps)
        for (int r : k.rs) run.insert({p, r});
    if (asked.count(k.name)) run = asked[k.name];
    for (const auto& [p, r] : run) {
      if (std::find(k.ps.begin(), k.ps.end(), p) == k.ps.end()) k.ps.push_back(p);
      if (std::find(k.rs.begin(), k.rs.end(), r) == k.rs.end()) k.rs.push_back(r);
    }
    std::sort(k.ps.begin(), k.ps.end());
    std::sort(k.rs.begin(), k.rs.end());
    const Json base = bpde::read_json_file((dir / ((k.file.empty() ? k.name : k.file) + ".json")).string());
    std::map<std::pair<int, int>, Cell> cells;
    for (const auto& [p, r] : run) {
      cells[{p, r}] = solve(k, base, p, r, out);
      std::fprintf(stderr, "%s p = %d refine = %d: %.1f s\n", k.name.c_str(), p, r, cells[{p, r}].seconds);
    }
    table(k, cells);
  }
  return 0;
}
