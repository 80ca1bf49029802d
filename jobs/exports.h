#pragma once
// The optional outputs of a result beside result.json and the surface files (FORMATS.md,
// bezierpde extensions): DIR/view.html (io/html_view.h) and DIR/surface.step (io/step_export.h).
#include <string>

#include "bezierpde/core/mesh.h"
#include "bezierpde/io/json_io.h"

namespace bpde {

struct Exports {
  bool step = false;  ///< DIR/surface.step: the exact patch (write_step)
  bool html = false;  ///< DIR/view.html: the web viewer (write_view_html)
};

/// The title of a result's view.html: "bezierpde: <problem> on a <kind> net".
std::string view_title(const Net& net, const Json& report);

}  // namespace bpde
