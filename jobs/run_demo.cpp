#include "bezierpde/jobs/run_demo.h"

#include <Eigen/Core>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <numbers>

#include "bezierpde/boundaries/reference_boundaries.h"

namespace bpde {

Job demo_job() {
  Job job{circle_three_arcs(8), FixedSet::Boundary, {}, 50};
  job.problem.kind = ProblemKind::CmcH;
  job.problem.H = -0.5;
  job.problem.solver = CmcSolver::Newton;
  return job;
}

Job demo_area_job() {
  Job job = demo_job();
  job.problem.functional = CmcFunctionalKind::Area;
  return job;
}

double unit_circle_cap_distance(const TriangularNet& net, double H) {
  if (!(std::abs(H) < 1.0) || H == 0.0) return INFINITY;
  const double R = 1.0 / std::abs(H);
  // H < 0 bulges to +z (FORMATS.md orientation): the small cap's centre is below the plane.
  const Eigen::Vector3d c(0, 0, (H < 0 ? -1.0 : 1.0) * std::sqrt(R * R - 1));
  const int N = 40;
  double d = 0;
  for (int a = 0; a <= N; ++a)
    for (int b = 0; b <= N - a; ++b)
      d = std::max(d, std::abs((net.evaluate(double(a) / N, double(b) / N) - c).norm() - R));
  return d;
}

namespace {

// printf into a string.
void append(std::string& s, const char* format, ...) {
  va_list args, copy;
  va_start(args, format);
  va_copy(copy, args);
  const int len = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  if (len > 0) {
    std::string line(static_cast<size_t>(len) + 1, '\0');
    std::vsnprintf(line.data(), line.size(), format, args);
    line.pop_back();
    s += line;
  }
  va_end(args);
}

double number_or_nan(const Json& j) { return j.is_number() ? j.get<double>() : NAN; }

}  // namespace

std::string demo_summary(const Json& d, const Json& a, double dist_d, double dist_a, const std::string& out_dir,
                         const std::string& area_dir) {
  std::string s;
  append(s,
         "bpde demo: the unit circle in three arcs (Arnal-Lluch-Monterde Fig. 1), triangular degree 8, H = -0.5.\n"
         "  The answer is the spherical cap of radius 2; the arcs are parametrised by angle (not conformally).\n\n");
  append(s, "  %-28s %-24s %-24s\n", "", "D + 2HV (the paper)", "A + 2HV (area)");
  auto yes = [](const Json& r) { return r["converged"].get<bool>() ? "yes" : "no"; };
  append(s, "  %-28s %-24s %-24s\n", "converged", yes(d), yes(a));
  append(s, "  %-28s %-24.3g %-24.3g\n", "first-variation residual", number_or_nan(d["residual"]),
         number_or_nan(a["residual"]));
  auto range = [](const Json& r) {
    if (!r["mean_curvature"].is_object()) return std::string("-");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f .. %.6f", r["mean_curvature"]["min"].get<double>(),
                  r["mean_curvature"]["max"].get<double>());
    return std::string(buf);
  };
  append(s, "  %-28s %-24s %-24s\n", "mean curvature (min .. max)", range(d).c_str(), range(a).c_str());
  append(s, "  %-28s %-24.3g %-24.3g\n", "distance to the exact cap", dist_d, dist_a);
  append(s, "  %-28s %-24.12g %-24.12g\n", "energy (its functional)", number_or_nan(d["energy"]),
         number_or_nan(a["energy"]));
  append(s, "  %-28s %-24.12g %-24.12g\n", "area A", number_or_nan(d["area"]), number_or_nan(a["area"]));
  append(s, "  %-28s %-24.12g %-24.12g\n", "Dirichlet energy D", number_or_nan(d["D"]), number_or_nan(a["D"]));
  append(s, "  %-28s %-24.12g %-24.12g\n", "volume V", number_or_nan(d["volume"]), number_or_nan(a["volume"]));
  append(s, "  %-28s %-24d %-24d\n", "CGAL self-intersections", d["check"]["self_intersections"].get<int>(),
         a["check"]["self_intersections"].get<int>());
  append(s, "  exact cap: A = %.12g, V = %.12g\n", 4 * std::numbers::pi * (2 - std::sqrt(3.0)),
         std::numbers::pi * (2 - std::sqrt(3.0)) * (2 - std::sqrt(3.0)) * (6 - (2 - std::sqrt(3.0))) / 3);
  if (a.contains("message")) append(s, "  area: %s\n", a["message"].get<std::string>().c_str());
  append(s, "  files               %s/ and %s/ {result.json, surface.obj, surface.ply, surface.vtp, net.obj}\n", out_dir.c_str(),
         area_dir.c_str());
  return s;
}

}  // namespace bpde
