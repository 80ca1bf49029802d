// libFuzzer target: a net file (io/json_io.h parse_json + net_from_json), then the cheap
// evaluations every command makes of an accepted net (a point and a derivative).
#include "fuzz/fuzz_reader.h"
#include <type_traits>
#include <variant>

#include "bezierpde/io/json_io.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return bpde::fuzz::run_reader(data, size, [](const std::string& text) {
    const bpde::Net net = bpde::net_from_json(bpde::parse_json(text, "net"));
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
