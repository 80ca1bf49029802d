#include "jobs/run_demo.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "boundaries/reference_boundaries.h"

namespace bpde {

Job demo_job() {
  Job job{circle_three_arcs(4), FixedSet::Boundary, {}, 50};
  job.problem.kind = ProblemKind::CmcH;
  job.problem.H = -1.0;
  job.problem.solver = CmcSolver::Newton;
  return job;
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

std::string demo_summary(const Json& r, const std::string& out_dir) {
  std::string s;
  append(s,
         "bpde demo: CMC approximation (Arnal-Lluch-Monterde Fig. 1): circle in three arcs, triangular degree 4, H = "
         "-1\n");
  append(s, "  converged           %s (%d Newton iterations, %d continuation steps)\n",
         r["converged"].get<bool>() ? "yes" : "no", r.value("iterations", 0), r.value("continuation_steps", 0));
  if (r.contains("message")) append(s, "  message             %s\n", r["message"].get<std::string>().c_str());
  append(s, "  energy D + 2HV      %.12g\n", number_or_nan(r["energy"]));
  append(s, "  Dirichlet energy D  %.12g\n", number_or_nan(r["D"]));
  append(s, "  volume V            %.12g\n", number_or_nan(r["volume"]));
  if (r["mean_curvature"].is_object())
    append(s, "  mean curvature      min %.6g, max %.6g, mean %.6g (away from the corners)\n",
           r["mean_curvature"]["min"].get<double>(), r["mean_curvature"]["max"].get<double>(),
           r["mean_curvature"]["mean"].get<double>());
  append(s, "  self-intersections  %d\n", r["check"]["self_intersections"].get<int>());
  append(s, "  files               %s/{result.json, surface.obj, surface.ply, surface.vtp, net.obj}\n", out_dir.c_str());
  return s;
}

}  // namespace bpde
