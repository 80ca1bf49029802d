// libFuzzer target: a net file (io/json_io.h parse_json + net_from_json, or for a patch complex
// io/complex_json.h complex_net_from_json), then the cheap evaluations every command makes of an
// accepted net (a point and a derivative; of a complex, its coarsest welded mesh).
#include "fuzz/fuzz_reader.h"
#include <type_traits>
#include <variant>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/io/complex_json.h"
#include "bezierpde/io/json_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return bpde::fuzz::run_reader(data, size, [](const std::string& text) {
    const bpde::Json j = bpde::parse_json(text, "net");
    if (bpde::is_complex_net(j)) {
      const bpde::ComplexNetFile c = bpde::complex_net_from_json(j, "net");
      (void)bpde::sample_complex(c.complex, 1);
      return;
    }
    const bpde::Net net = bpde::net_from_json(j);
    std::visit(
        [](const auto& n) {
          if constexpr (std::is_same_v<std::decay_t<decltype(n)>, bpde::BSplineNet>) {
            (void)n.evaluate(0.5 * (n.u_min() + n.u_max()), 0.5 * (n.v_min() + n.v_max()));
          } else if constexpr (std::is_same_v<std::decay_t<decltype(n)>, bpde::TensorNet>) {
            (void)n.evaluate(0.5, 0.5);
          }
        },
        net);
  });
}
