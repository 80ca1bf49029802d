#include "table1_report.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include <unistd.h>

namespace bpde_bench {
namespace {

// Arnal, Monterde, Ugail (explicit PDE solutions), Table 1: milliseconds on a 1.73 GHz laptop (2011).
struct PaperRow {
  int n;
  double explicit_ms, linear_ms;
};
constexpr PaperRow kPaper[] = {{4, 0.78, 1.12},   {5, 0.93, 1.94},   {8, 1.11, 2.83},    {10, 1.87, 3.12},
                               {12, 4.89, 11.11}, {15, 8.48, 15.49}, {18, 11.41, 22.91}, {20, 15.42, 28.75}};

double to_ms(double t, benchmark::TimeUnit u) {
  switch (u) {
    case benchmark::kNanosecond:
      return t * 1e-6;
    case benchmark::kMicrosecond:
      return t * 1e-3;
    case benchmark::kMillisecond:
      return t;
    case benchmark::kSecond:
      return t * 1e3;
  }
  return t;
}

// Console output as usual, plus the CPU time of every run by name ("Biharmonic/lu/20"). With
// repetitions the median aggregate wins over single iterations.
class Collector : public benchmark::ConsoleReporter {
 public:
  explicit Collector(OutputOptions options) : ConsoleReporter(options) {}
  std::map<std::string, double> ms, median_ms;
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.error_occurred) continue;
      const double t = to_ms(r.GetAdjustedCPUTime(), r.time_unit);
      std::string name = r.run_name.str();
      if (r.run_type == Run::RT_Aggregate) {
        if (r.aggregate_name == "median") median_ms[name] = t;
      } else if (!ms.count(name)) {
        ms[name] = t;
      } else {
        ms[name] = std::min(ms[name], t);
      }
    }
  }
  bool get(const std::string& name, double& t) const {
    if (auto it = median_ms.find(name); it != median_ms.end()) return t = it->second, true;
    if (auto it = ms.find(name); it != ms.end()) return t = it->second, true;
    return false;
  }
};

}  // namespace

int run_table1(int argc, char** argv) {
  std::vector<char*> args;
  bool filtered = false;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--table1") == 0) continue;
    if (std::strncmp(argv[i], "--benchmark_filter", 18) == 0) filtered = true;
    args.push_back(argv[i]);
  }
  static char filter[] = "--benchmark_filter=^Biharmonic/(explicit|lu|lu-bernstein|mould)/";
  if (!filtered) args.push_back(filter);
  int n_args = static_cast<int>(args.size());
  args.push_back(nullptr);
  benchmark::Initialize(&n_args, args.data());
  if (benchmark::ReportUnrecognizedArguments(n_args, args.data())) return 1;
  // Colour only on a terminal, as Google Benchmark's own default reporter does.
  Collector collector(isatty(fileno(stdout)) ? benchmark::ConsoleReporter::OO_Defaults
                                             : benchmark::ConsoleReporter::OO_Tabular);
  benchmark::RunSpecifiedBenchmarks(&collector);
  benchmark::Shutdown();

  std::printf("\nArnal-Monterde-Ugail Table 1: biharmonic, solve + 50x50 evaluation, CPU milliseconds\n");
  std::printf("(lu: the anti-diagonal block LU; lu-bernstein: the dense Bernstein system, solvers/pde/pde_lu.h)\n\n");
  std::printf(
      "| n | paper explicit | paper linear system | explicit | lu | lu-bernstein | mould |"
      " lu / explicit | lu / mould | lu-bernstein / explicit | lu-bernstein / mould |"
      " paper / explicit | paper / lu | paper / mould |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  bool ratio_dense = true, paper_goal = true, complete = true, have_dense = true;
  double lu_over_explicit_20 = 0;
  for (const PaperRow& p : kPaper) {
    double e = 0, l = 0, d = 0, m = 0;
    auto name = [&](const char* route) {  // snprintf: GCC 12 warns (-Wrestrict) on "lit" + string
      char buf[64];
      std::snprintf(buf, sizeof buf, "Biharmonic/%s/%d", route, p.n);
      return std::string(buf);
    };
    const bool he = collector.get(name("explicit"), e);
    const bool hl = collector.get(name("lu"), l);
    const bool hd = collector.get(name("lu-bernstein"), d);
    const bool hm = collector.get(name("mould"), m);
    if (!(he && hl && hm)) {
      complete = false;
      continue;
    }
    if (!hd) have_dense = false;
    const double best_paper = std::min(p.explicit_ms, p.linear_ms);
    char dense[96] = "-", dense_e[32] = "-", dense_m[32] = "-";
    if (hd) {
      std::snprintf(dense, sizeof dense, "%.4f", d);
      std::snprintf(dense_e, sizeof dense_e, "%.0f", d / e);
      std::snprintf(dense_m, sizeof dense_m, "%.0f", d / m);
    }
    std::printf("| %d | %.2f | %.2f | %.4f | %.4f | %s | %.4f | %.1f | %.1f | %s | %s | %.0f | %.0f | %.0f |\n", p.n,
                p.explicit_ms, p.linear_ms, e, l, dense, m, l / e, l / m, dense_e, dense_m, p.explicit_ms / e,
                p.linear_ms / l, best_paper / m);
    if (p.n == 20) lu_over_explicit_20 = l / e;
    if (p.n == 20 && hd && !(d >= 10 * e && d >= 10 * m)) ratio_dense = false;
    if (!(p.explicit_ms >= 100 * e && p.linear_ms >= 100 * l && best_paper >= 100 * m)) paper_goal = false;
  }
  if (!complete) {
    std::printf("\n(some Table 1 routes did not run: the goals below are not checked)\n");
    return 0;
  }
  // The goals as decided (docs/performance_measurements.md "Table 1"): the speed-up of explicit and mould is
  // measured against the dense linear system, the generic "LU solve" the paper times; the block
  // LU is a third, structured route whose closeness to explicit is a finding, not a goal.
  if (have_dense)
    std::printf("goal: at n = 20 explicit and mould >= 10x faster than lu-bernstein (the dense linear system): %s\n",
                ratio_dense ? "met" : "NOT met");
  else
    std::printf("goal: at n = 20 explicit and mould >= 10x faster than lu-bernstein: not checked (route not run)\n");
  std::printf("floor: every route (explicit, lu, mould) >= 100x faster than the paper at every degree: %s\n",
              paper_goal ? "met" : "NOT met");
  std::printf(
      "       (lu-bernstein, the dense system factored in long double, is the reference of the speed-up\n"
      "       goal, not a route held to the floor)\n");
  std::printf("finding: the structured block LU (lu) runs at %.1fx the time of explicit at n = 20\n",
              lu_over_explicit_20);
  return 0;
}

}  // namespace bpde_bench
