#include "bezierpde/jobs/solve_summary.h"

#include <cmath>
#include <cstdio>

namespace bpde {
namespace {

// One line "  label<padding>text\n" (labels padded to 20 columns, as `bpde demo` prints).
void line(std::string& s, const std::string& label, const std::string& text) {
  s += "  " + label + std::string(label.size() < 20 ? 20 - label.size() : 1, ' ') + text + "\n";
}

std::string number(double x, const char* format = "%.12g") {
  char buf[64];
  std::snprintf(buf, sizeof buf, format, x);
  return buf;
}

// A figure as the report writes it: "none" where it is written as null.
std::string figure(double x, const char* format = "%.12g") { return std::isfinite(x) ? number(x, format) : "none"; }

std::string net_text(const Net& net) {
  const NetShape shape = net_shape(net);
  char buf[96];
  if (shape.kind == NetKind::Triangular)
    std::snprintf(buf, sizeof buf, "net of degree %d", shape.n);
  else
    std::snprintf(buf, sizeof buf, "net of degree [%d, %d]", shape.n, shape.m);
  return std::string(to_string(shape.kind)) + " " + buf;
}

}  // namespace

std::string files_line(const std::string& dir, const std::vector<std::string>& names) {
  std::string list;
  for (const std::string& name : names) list += (list.empty() ? "" : ", ") + name;
  if (names.size() != 1) list = "{" + list + "}";
  std::string s;
  line(s, "files", dir.empty() ? list : dir + "/" + list);
  return s;
}

std::string solve_summary(const SolveOutcome& out, const WrittenResult& written, const std::string& job_path,
                          const std::string& out_dir, const std::vector<std::string>& files) {
  const SolveFigures& f = out.figures;
  std::string s = "bpde solve: " + job_path + "\n";
  std::string detail;  // "biharmonic, method explicit"
  auto add = [&](const std::string& text) { detail += (detail.empty() ? "" : ", ") + text; };
  if (!f.energy_name.empty()) add(f.energy_name);
  if (!f.method.empty()) add("method " + f.method);
  if (!f.solver.empty()) add("solver " + f.solver);
  line(s, "problem",
       to_string(f.problem) + (detail.empty() ? "" : " (" + detail + ")") + " on a " +
           (out.complex ? "complex of " + std::to_string(out.complex->patches.size()) + " " +
                              (out.complex->patches.front().kind == PatchKind::triangular ? "triangular" : "tensor") +
                              " patches of degree " + std::to_string(out.complex->patches.front().degree)
                        : net_text(out.net)));
  const bool converged = f.summary.converged;
  std::string how = converged ? "yes" : "no";
  if (f.iterations) how += " (" + std::to_string(*f.iterations) + " iterations";
  if (f.continuation_steps)
    how += std::string(f.iterations ? ", " : " (") + std::to_string(*f.continuation_steps) + " continuation steps";
  if (f.iterations || f.continuation_steps) how += ")";
  line(s, "converged", how);
  if (!f.summary.message.empty()) line(s, converged ? "message" : "not converged", f.summary.message);
  if (f.energy) line(s, "energy", figure(*f.energy));
  if (f.D) line(s, "Dirichlet energy D", figure(*f.D));
  if (f.volume) line(s, "volume V", figure(*f.volume));
  if (f.H) line(s, "H", figure(*f.H));
  if (f.pde_residual) line(s, "pde residual", figure(*f.pde_residual, "%.3g"));
  if (f.residual) line(s, "residual", figure(*f.residual, "%.3g"));
  if (const auto& h = written.mean_curvature)
    line(s, "mean curvature",
         h->count > 0 ? "min " + number(h->min, "%.6g") + ", max " + number(h->max, "%.6g") + ", mean " +
                            number(h->mean, "%.6g") + " (away from the corners)"
                      : "none (no sample away from the corners)");
  if (const auto& c = written.certificate) {
    std::string where =
        c->at[0] >= 0 ? " at (u, v) = (" + number(c->at[0], "%.3g") + ", " + number(c->at[1], "%.3g") + ")" : "";
    if (c->patch >= 0) where += " of patch " + std::to_string(c->patch);
    const std::string off = "|H(x) - H| up to " + number(c->deviation, "%.3g") + where + ", " +
                            number(100 * c->relative, "%.3g") + " % of the reference curvature";
    line(s, "certificate",
         c->near_constant() ? off
                            : "NOT a constant-mean-curvature surface: " + off + " (more than " +
                                  number(100 * kCmcDeviationLimit, "%g") +
                                  " %); a critical point of the discrete problem, not a CMC surface at this degree");
  }
  // The boundary's distance from the job's curves (a job in the boundary form).
  const Json& rep = written.result.contains("report") ? written.result["report"] : out.report;
  if (rep.contains("boundary_error") && rep["boundary_error"].is_object()) {
    const Json& b = rep["boundary_error"];
    std::string text = b["max_error"].is_number() ? number(b["max_error"].get<double>(), "%.3g") : "none";
    text += " (edge " + std::to_string(b["edge"].get<int>());
    if (b["loop"].is_number())
      text += ": loop " + std::to_string(b["loop"].get<int>()) + ", curve " + std::to_string(b["curve"].get<int>()) +
              " at t = " + number(b["t"].get<double>(), "%.4g");
    line(s, "boundary error", text + ")");
  }
  // The refinement rounds of a tolerance.
  if (rep.contains("rounds") && rep["rounds"].is_array() && !rep["rounds"].empty()) {
    const Json& r = rep["rounds"];
    const Json &first = r.front(), &last = r.back();
    line(s, "rounds",
         std::to_string(r.size()) + " (degree " + std::to_string(first["degree"].get<int>()) + " to " +
             std::to_string(last["degree"].get<int>()) + ", refine " + std::to_string(first["refine"].get<int>()) +
             " to " + std::to_string(last["refine"].get<int>()) + "): tolerance " +
             (last["failed"].empty() ? "met" : "NOT met"));
  }
  if (written.check) line(s, "self-intersections", std::to_string(written.check->self_intersections));
  return s + files_line(out_dir, files);
}

}  // namespace bpde
