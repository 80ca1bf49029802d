#include "jobs/exports.h"

#include "io/html_view.h"
#include "io/step_export.h"

namespace bpde {

std::string view_title(const Net& net, const Json& report) {
  std::string problem = "surface";
  if (report.is_object() && report.contains("problem") && report["problem"].is_string())
    problem = report["problem"].get<std::string>();
  return "bezierpde: " + problem + " on a " + net_kind(net) + " net";
}

void write_exports(const std::string& dir, const Net& net, const TriangleMesh& mesh, const Json& result,
                   const Exports& exports) {
  const Json report = result.is_object() && result.contains("report") ? result["report"] : Json::object();
  if (exports.step) write_step(dir + "/surface.step", net);
  if (exports.html) write_view_html(dir + "/view.html", net, mesh, report, view_title(net, report));
}

}  // namespace bpde
