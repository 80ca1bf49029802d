#pragma once
// The blend config of FORMATS.md (`bpde blend CONFIG.json --out DIR`, Pasadas–Rodríguez, smoothing PDE splines):
//
//   {"kind": "blend", "partition": [k, l], "a": a, "epsilon": eps,
//    "edges": {"y0": {"value": [[x, y, z], ...], "dy": [[x, y, z], ...]},
//              "y1": {"value": [...], "dy": [...]}},
//    "points": [[x, y], ...], "data": [[x, y, z], ...], "samples": N}
//
// - partition: k intervals in x, l in y (integers in 1..BfsSpace::kMaxPartition);
// - 1e-6 <= a <= 1e6: the operator ∂⁴_x + 2a ∂²_x∂²_y + a² ∂⁴_y; epsilon > 0;
// - edges: value and ∂/∂y at the k+1 nodes x_i = i/k of y = 0 and y = 1 (all four required);
//   or, instead of "edges", "surfaces": {"f": NET, "g": NET} with the two surfaces to blend as
//   tensor or bspline nets (parameters mapped onto [0,1]²): the edges are then f(x,1), f_y(x,1)
//   and g(x,0), g_y(x,0) at the nodes (docs/errata.md, smoothing PDE splines §6);
// - points / data: the approximation points A ⊂ [0,1]² and their values β; optional (default
//   empty), equal lengths;
// - samples: optional mesh resolution N (default 50, 1..kMaxSamples = 2000 of core/mesh.h: a mesh
//   of N needs about 450 (N+1)^2 bytes; 4096 took 7.6 GB).
// Parsing is strict and bounded like every JSON reader (io/json_io.h parse_json: 64 MiB, 256
// levels, a duplicate key is a ParseError): an unknown field, a missing field or a value of the
// wrong JSON type is a ParseError; a number that overflows (1e999: NumberOverflowError) or is not
// finite is a NonFiniteError; arrays of the
// wrong length are a SizeError; ε <= 0, a outside [1e-6, 1e6], a partition or samples out of range or a point
// outside [0,1]² is a ParameterError. Every message names the field (a JSON path such as
// `edges.y0.value[3][1]`).
#include <nlohmann/json_fwd.hpp>
#include <string>

#include "bezierpde/solvers/blend/smoothing_spline.h"

namespace bpde {

struct BlendConfig {
  SmoothingSplineProblem problem;  ///< load stays empty (f = 0)
  int samples = 50;
};

/// Parse and validate a blend config given as JSON text.
BlendConfig parse_blend_config(const std::string& text);
/// Validate a blend config already parsed as JSON.
BlendConfig blend_config_from_json(const nlohmann::json& j);
/// Read a file (FileError if it cannot be read) and parse it.
BlendConfig read_blend_config(const std::string& path);
/// The config as FORMATS.md JSON (round-trips through parse_blend_config exactly: doubles are
/// written with 17 significant digits).
nlohmann::json blend_config_to_json(const BlendConfig& config);

}  // namespace bpde
