// 004-cmc-circle-sweep: the sweeps of README.md through the library (jobs/sweep.h, what
// `bpde sweep` runs): fold-vs-degree.json (the circle of triangular CMC Fig. 1 at H = -3 for
// degrees 3..8: every branch from H = 0 stops at its fold, and the row's H is where) and
// degree-axis-curves.json (the circle as three arcs in the boundary form, the degree as an axis,
// the Dirichlet and the area functional at H = -0.5).
//
// Usage: example_004_cmc_circle_sweep [EXAMPLE_DIR [OUT_DIR]]
//   EXAMPLE_DIR defaults to examples/004-cmc-circle-sweep, OUT_DIR to out/004-cmc-circle-sweep
//   (the sweeps' job folders and results.csv go to OUT_DIR/fold-vs-degree and
//   OUT_DIR/degree-axis-curves). Prints README.md's two tables as the generated sections
//   cmc-circle-sweep-fold and cmc-circle-sweep-degree-axis (scripts/docs.py); under a second.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bezierpde/io/json_io.h"
#include "bezierpde/jobs/sweep.h"
#include "examples/common/generated.h"

namespace fs = std::filesystem;

namespace {

std::vector<bpde::Json> run(const fs::path& dir, const fs::path& out, const char* name) {
  const bpde::SweepSpec spec = bpde::read_sweep_file((dir / (std::string(name) + ".json")).string());
  bpde::SweepRunOptions options;
  options.jobs = 1;
  options.resume = false;
  return bpde::run_sweep(spec, (out / name).string(), options);
}

double number(const bpde::Json& row, const char* key) { return row.at(key).get<double>(); }

}  // namespace

int main(int argc, char** argv) {
  const fs::path dir = argc > 1 ? argv[1] : "examples/004-cmc-circle-sweep";
  const fs::path out = argc > 2 ? argv[2] : "out/004-cmc-circle-sweep";

  {
    const bpde::examples::GeneratedSection section("cmc-circle-sweep-fold");
    std::printf("| degree | status | H reached | D_H at that H |\n|---|---|---|---|\n");
    for (const bpde::Json& row : run(dir, out, "fold-vs-degree"))
      std::printf("| %d | %s | %.6g | %.5f |\n", row.at("net.degree").get<int>(),
                  row.at("status").get<std::string>().c_str(), number(row, "H"), number(row, "energy"));
  }
  std::printf("\n");
  {
    const bpde::examples::GeneratedSection section("cmc-circle-sweep-degree-axis");
    std::printf("| n | functional | boundary_error | H_min | H_max | energy | status |\n|---|---|---|---|---|---|---|\n");
    for (const bpde::Json& row : run(dir, out, "degree-axis-curves"))
      std::printf("| %d | %s | %s | %.6f | %.6f | %.11f | %s |\n", row.at("boundary.degree").get<int>(),
                  row.at("problem.functional").get<std::string>().c_str(),
                  bpde::examples::stable_small(number(row, "boundary_error"), 1e-12).c_str(), number(row, "H_min"),
                  number(row, "H_max"), number(row, "energy"), row.at("status").get<std::string>().c_str());
  }
  return 0;
}
