// libFuzzer target: a job file (io/job.h parse_job: the net, the fixed set, the problem).
#include "fuzz/fuzz_reader.h"
#include "bezierpde/io/job.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return bpde::fuzz::run_reader(data, size, [](const std::string& text) {
    (void)bpde::parse_job(bpde::parse_json(text, "job"), "job");
  });
}
