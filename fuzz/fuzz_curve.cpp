// libFuzzer target: one boundary CURVE of a job (io/boundary_json.h curve_from_json: segments,
// arcs, helices, circles, Bézier and B-spline curves, samples), then what the fits ask of an
// accepted curve (its ends and a point inside), and one loop of it as a patch complex would take.
#include "fuzz/fuzz_reader.h"

#include "bezierpde/io/boundary_json.h"
#include "bezierpde/io/json_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return bpde::fuzz::run_reader(data, size, [](const std::string& text) {
    const bpde::BoundaryCurve c = bpde::curve_from_json(bpde::parse_json(text, "curve"), "curve");
    (void)c.evaluate(0.0);
    (void)c.evaluate(0.5);
    (void)c.evaluate(1.0);
  });
}
