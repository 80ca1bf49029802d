#include "app/sweep_command.h"

#include <unistd.h>

#include <cstdio>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/jobs/sweep.h"

namespace bpde::app {

namespace {

std::string clock_text(double seconds) {
  const long s = seconds < 0 ? 0 : static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

// The ETA from the jobs run in this invocation (resumed jobs took no time).
std::string eta_text(const SweepProgress& p) {
  const int ran = p.done - p.resumed;
  if (ran <= 0 || p.done >= p.total) return "--:--";
  return clock_text(p.seconds / ran * (p.total - p.done));
}

void print_progress(const SweepProgress& p, bool terminal) {
  if (terminal) {
    const int width = 30;
    const int filled = p.total ? width * p.done / p.total : width;
    std::string bar(static_cast<size_t>(filled), '#');
    bar.resize(width, '.');
    std::fprintf(stderr, "\r[%s] %d/%d %3d%%  %s elapsed, ETA %s ", bar.c_str(), p.done, p.total,
                 p.total ? 100 * p.done / p.total : 100, clock_text(p.seconds).c_str(), eta_text(p).c_str());
    if (p.done == p.total) std::fputc('\n', stderr);
  } else if (p.row) {
    const Json& r = *p.row;
    std::fprintf(stderr, "sweep: %d/%d %s %s (%.2f s) ETA %s\n", p.done, p.total, r.value("job", "").c_str(),
                 r.value("status", "").c_str(), r.value("seconds", 0.0), eta_text(p).c_str());
  } else {
    std::fprintf(stderr, "sweep: %d jobs, %d already done\n", p.total, p.resumed);
  }
  std::fflush(stderr);
}

}  // namespace

int cmd_sweep(const std::string& sweep_path, const std::string& out_dir, int jobs, bool lines) {
  if (jobs < 0 || jobs > kMaxSweepThreads)
    throw ParameterError("--jobs must be 0.." + std::to_string(kMaxSweepThreads) + " (0: every core), got " +
                         std::to_string(jobs));
  const SweepSpec spec = read_sweep_file(sweep_path);
  const bool terminal = !lines && isatty(fileno(stderr)) != 0;
  SweepRunOptions options;
  options.jobs = jobs;
  options.on_progress = [terminal](const SweepProgress& p) { print_progress(p, terminal); };
  const std::vector<Json> rows = run_sweep(spec, out_dir, options);
  int failed = 0;
  for (const Json& r : rows)
    if (r.value("exit_code", 3) != 0) ++failed;
  std::fprintf(stdout, "%d jobs, %d converged, %d not: %s/results.csv, %s/results.jsonl\n",
               static_cast<int>(rows.size()), static_cast<int>(rows.size()) - failed, failed, out_dir.c_str(),
               out_dir.c_str());
  return failed ? 1 : 0;
}

}  // namespace bpde::app
