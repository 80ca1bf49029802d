#pragma once
// `bpde_bench --table1`: run the Table 1 routes of Arnal–Monterde–Ugail
// (Biharmonic/{explicit,lu,lu-bernstein,mould}/<n>) and print them beside the paper's milliseconds,
// with the ratios and the goals as decided (docs/performance_measurements.md "Table 1"): the speed-up goal, at
// n = 20 explicit and mould >= 10x faster than lu-bernstein (the dense linear system, the generic
// "LU solve" the paper times); the cross-machine floor, every route (explicit, lu, mould) >= 100x
// faster than the paper's own time for it (explicit vs. the paper's explicit column, lu vs. its
// linear-system column, mould vs. the faster of the two); and, as a finding, how close the
// structured block LU (lu) comes to explicit at n = 20.
namespace bpde_bench {

/// argv without "--table1"; other Google Benchmark flags pass through (a --benchmark_filter of
/// the caller's replaces the default ^Biharmonic/(explicit|lu|lu-bernstein|mould)/ filter).
/// Returns the exit code.
int run_table1(int argc, char** argv);

}  // namespace bpde_bench
