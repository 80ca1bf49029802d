// libFuzzer target: a sweep file (io/sweep_spec.h parse_sweep_spec: the base, the axes and their
// limits, the boundary name), then the first, middle and last of its jobs built from the axes and
// read as jobs (io/job.h parse_job), as `bpde sweep` builds them before running any. No file is
// read: a string "base" named "job.json" is a small job, any other name a missing file.
#include "fuzz/fuzz_reader.h"

#include "bezierpde/io/job.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/sweep_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return bpde::fuzz::run_reader(data, size, [](const std::string& text) {
    const auto load = [](const std::string& name) -> bpde::Json {
      if (name != "job.json") throw bpde::FileError("cannot open '" + name.substr(0, 80) + "'");
      return bpde::parse_json(
          R"({"net": {"type": "triangular", "degree": 3}, "fixed": "boundary",
              "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, "samples": 4})",
          "job.json");
    };
    const bpde::SweepSpec spec = bpde::parse_sweep_spec(bpde::parse_json(text, "sweep"), "sweep", load,
                                                        {"circle-three-arcs", "sphere-square", "sphere-triangle"});
    const std::size_t n = bpde::sweep_job_count(spec);
    for (const std::size_t k : {std::size_t{0}, n / 2, n - 1}) {
      bpde::Json job, values;
      try {
        bpde::sweep_job_json(spec, k, job, values, "job");
      } catch (const bpde::ParameterError&) {
        continue;  // this job cannot be built (a row with its error); the others can
      }
      if (spec.boundary.empty()) (void)bpde::parse_job(job, "job");
    }
  });
}
