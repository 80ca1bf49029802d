#include "bezierpde/jobs/exports.h"

#include "bezierpde/io/html_view.h"
#include "bezierpde/io/step_export.h"

namespace bpde {

std::string view_title(const Net& net, const Json& report) {
  std::string problem = "surface";
  if (report.is_object() && report.contains("problem") && report["problem"].is_string())
    problem = report["problem"].get<std::string>();
  return "bezierpde: " + problem + " on a " + net_kind(net) + " net";
}


}  // namespace bpde
