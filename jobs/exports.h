#pragma once
// The optional outputs of a result beside result.json and the surface files (FORMATS.md,
// bezierpde extensions): DIR/view.html (io/html_view.h) and DIR/surface.step (io/step_export.h).
#include <string>

#include "core/mesh.h"
#include "io/json_io.h"

namespace bpde {

struct Exports {
  bool step = false;  ///< DIR/surface.step: the exact patch (write_step)
  bool html = false;  ///< DIR/view.html: the web viewer (write_view_html)
};

/// Write the requested exports of a written result (`result`: the result.json object, whose
/// `report` the page shows) for `net` and its sampled `mesh` into `dir` (which exists).
void write_exports(const std::string& dir, const Net& net, const TriangleMesh& mesh, const Json& result,
                   const Exports& exports);

/// The title of a result's view.html: "bezierpde: <problem> on a <kind> net".
std::string view_title(const Net& net, const Json& report);

}  // namespace bpde
