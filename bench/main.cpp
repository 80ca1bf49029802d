// bpde_bench: Google Benchmark program. Each bench/bench_*.cpp registers its routes; the route of
// a benchmark is its own '/'-separated token and the degree is the last token (FORMATS.md).
// `bpde_bench --table1` runs the Table 1 routes (Arnal–Monterde–Ugail) and prints them beside the paper
// (bench/table1_report.h); every other invocation is plain Google Benchmark.
#include <benchmark/benchmark.h>

#include <cstring>

#include "bezierpde/core/row_major_product.h"
#include "table1_report.h"

int main(int argc, char** argv) {
  // The evaluation kernel's path decides every route's speed: record it beside the CPU context.
  benchmark::AddCustomContext("row_major_product", bpde::row_major_product_uses_fma() ? "avx2-fma" : "portable");
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--table1") == 0) return bpde_bench::run_table1(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
