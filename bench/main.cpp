// bpde_bench: Google Benchmark program. Each bench/bench_*.cpp registers its routes; the route of
// a benchmark is its own '/'-separated token and the degree is the last token (FORMATS.md).
#include <benchmark/benchmark.h>

BENCHMARK_MAIN();
