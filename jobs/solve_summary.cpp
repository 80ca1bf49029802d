#include "bezierpde/jobs/solve_summary.h"

#include <cstdio>

namespace bpde {
namespace {

// One line "  label<padding>text\n" (labels padded to 20 columns, as `bpde demo` prints).
void line(std::string& s, const std::string& label, const std::string& text) {
  s += "  " + label + std::string(label.size() < 20 ? 20 - label.size() : 1, ' ') + text + "\n";
}

std::string number(const Json& j, const char* format = "%.12g") {
  if (!j.is_number()) return "none";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, j.get<double>());
  return buf;
}

std::string net_text(const Json& net) {
  if (!net.is_object() || !net.contains("type") || !net["type"].is_string()) return "";
  const Json& d = net.value("degree", Json());
  char buf[96];
  if (d.is_array() && d.size() == 2)
    std::snprintf(buf, sizeof buf, "net of degree [%d, %d]", d[0].get<int>(), d[1].get<int>());
  else
    std::snprintf(buf, sizeof buf, "net of degree %d", d.is_number() ? d.get<int>() : 0);
  return net["type"].get<std::string>() + " " + buf;
}

}  // namespace

std::string solve_summary(const Json& result, const std::string& job_path, const std::string& out_dir) {
  const Json& r = result.at("report");
  std::string s = "bpde solve: " + job_path + "\n";
  std::string detail;  // "biharmonic, method explicit"
  for (const char* k : {"energy_name", "method", "solver"})
    if (r.contains(k) && r[k].is_string())
      detail += (detail.empty() ? "" : ", ") + (k[0] == 'e' ? "" : std::string(k) + " ") + r[k].get<std::string>();
  const std::string net = net_text(result.value("net", Json()));
  line(s, "problem",
       r.value("problem", std::string("?")) + (detail.empty() ? "" : " (" + detail + ")") +
           (net.empty() ? "" : " on a " + net));
  const bool converged = r.value("converged", false);
  std::string how = converged ? "yes" : "no";
  if (r.contains("iterations")) how += " (" + std::to_string(r["iterations"].get<int>()) + " iterations";
  if (r.contains("continuation_steps"))
    how += std::string(r.contains("iterations") ? ", " : " (") + std::to_string(r["continuation_steps"].get<int>()) +
           " continuation steps";
  if (r.contains("iterations") || r.contains("continuation_steps")) how += ")";
  line(s, "converged", how);
  if (r.contains("message") && r["message"].is_string())
    line(s, converged ? "message" : "not converged", r["message"].get<std::string>());
  if (r.contains("energy")) line(s, "energy", number(r["energy"]));
  if (r.contains("D")) line(s, "Dirichlet energy D", number(r["D"]));
  if (r.contains("volume")) line(s, "volume V", number(r["volume"]));
  if (r.contains("H")) line(s, "H", number(r["H"]));
  if (r.contains("pde_residual")) line(s, "pde residual", number(r["pde_residual"], "%.3g"));
  if (r.contains("residual")) line(s, "residual", number(r["residual"], "%.3g"));
  if (r.contains("mean_curvature")) {
    const Json& h = r["mean_curvature"];
    line(s, "mean curvature",
         h.is_object() ? "min " + number(h["min"], "%.6g") + ", max " + number(h["max"], "%.6g") + ", mean " +
                             number(h["mean"], "%.6g") + " (away from the corners)"
                       : "none (no sample away from the corners)");
  }
  if (r.contains("check") && r["check"].is_object() && r["check"].contains("self_intersections"))
    line(s, "self-intersections", std::to_string(r["check"]["self_intersections"].get<int>()));
  line(s, "files", out_dir + "/{result.json, surface.obj, surface.ply, net.obj}");
  return s;
}

}  // namespace bpde
