#include "bezierpde/jobs/run_demo.h"

#include "bezierpde/core/eigen.h"
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

Job demo_mean_curvature_job() {
  Job job = demo_job();
  job.problem.functional = CmcFunctionalKind::MeanCurvature;
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

std::string demo_summary(const std::vector<DemoColumn>& cols) {
  std::string s;
  append(s,
         "bpde demo: the unit circle in three arcs (Arnal-Lluch-Monterde Fig. 1), triangular degree 8, H = -0.5.\n"
         "  The answer is the spherical cap of radius 2; the arcs are parametrised by angle (not conformally).\n\n");
  // One line: a label, then one cell per column.
  auto line = [&](const char* label, auto cell) {
    append(s, "  %-28s", label);
    for (const DemoColumn& c : cols) append(s, " %-24s", cell(c).c_str());
    s.erase(s.find_last_not_of(' ') + 1);
    s += "\n";
  };
  auto num = [](const char* format, double x) {
    char buf[64];
    std::snprintf(buf, sizeof buf, format, x);
    return std::string(buf);
  };
  line("", [](const DemoColumn& c) { return c.title; });
  line("converged", [](const DemoColumn& c) { return std::string(c.report["converged"].get<bool>() ? "yes" : "no"); });
  line("residual (its functional)", [&](const DemoColumn& c) { return num("%.3g", number_or_nan(c.report["residual"])); });
  line("mean curvature (min .. max)", [](const DemoColumn& c) {
    if (!c.report["mean_curvature"].is_object()) return std::string("-");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.6f .. %.6f", c.report["mean_curvature"]["min"].get<double>(),
                  c.report["mean_curvature"]["max"].get<double>());
    return std::string(buf);
  });
  line("distance to the exact cap", [&](const DemoColumn& c) { return num("%.3g", c.distance); });
  line("energy (its functional)", [&](const DemoColumn& c) { return num("%.12g", number_or_nan(c.report["energy"])); });
  line("area A", [&](const DemoColumn& c) { return num("%.12g", number_or_nan(c.report["area"])); });
  line("Dirichlet energy D", [&](const DemoColumn& c) { return num("%.12g", number_or_nan(c.report["D"])); });
  line("volume V", [&](const DemoColumn& c) { return num("%.12g", number_or_nan(c.report["volume"])); });
  line("CGAL self-intersections",
       [](const DemoColumn& c) { return std::to_string(c.report["check"]["self_intersections"].get<int>()); });
  append(s, "  exact cap: A = %.12g, V = %.12g\n", 4 * std::numbers::pi * (2 - std::sqrt(3.0)),
         std::numbers::pi * (2 - std::sqrt(3.0)) * (2 - std::sqrt(3.0)) * (6 - (2 - std::sqrt(3.0))) / 3);
  for (size_t k = 1; k < cols.size(); ++k)
    if (cols[k].report.contains("message"))
      append(s, "  %s: %s\n", cols[k].report["functional"].get<std::string>().c_str(),
             cols[k].report["message"].get<std::string>().c_str());
  std::string dirs;
  for (const DemoColumn& c : cols) dirs += (dirs.empty() ? "" : ", ") + c.dir + "/";
  append(s, "  files               %s {result.json, surface.obj, surface.ply, surface.vtp, net.obj}\n", dirs.c_str());
  return s;
}

}  // namespace bpde
