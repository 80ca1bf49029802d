// libFuzzer target: a blend config (io/blend_config.h parse_blend_config).
#include "fuzz/fuzz_reader.h"
#include "bezierpde/io/blend_config.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return bpde::fuzz::run_reader(data, size, [](const std::string& text) { (void)bpde::parse_blend_config(text); });
}
