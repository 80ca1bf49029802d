// `bpde sweep` against its resources (docs/robustness.md): `--jobs` is bounded (kMaxSweepThreads,
// exit 2 above), a thread the system refuses to start leaves the sweep to the threads it has, and
// memory running out is exit 3, never an abort.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "bezierpde/jobs/sweep.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;
using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::run_with_limit;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

namespace {

// A sweep of `n` quick jobs (a biquadratic Dirichlet extremal at 2 samples, one corner moved).
fs::path quick_sweep(const std::string& name, int n) {
  std::string values;
  for (int k = 0; k < n; ++k) {
    if (k > 0) values += ',';
    values += std::to_string(k * 0.001);
  }
  return write(name, R"({"base": {"net": {"type": "tensor", "degree": [2, 2], "points": [[0,0,0],[0,0.5,0],)"
                     R"([0,1,0],[0.5,0,0],[0,0,0],[0.5,1,0],[1,0,0],[1,0.5,0.5],[1,1,1]]},)"
                     R"( "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, "samples": 2},)"
                     R"( "axes": {"net.points.0.2": [)" + values + "]}}");
}

}  // namespace

TEST(SweepResources, JobsAreBounded) {
  const fs::path spec = quick_sweep("sr_bound.json", 3);
  const fs::path out = tmpdir() / "sr_bound_out";
  fs::remove_all(out);
  for (const long jobs : {-1L, static_cast<long>(bpde::kMaxSweepThreads) + 1, 1000000L}) {
    const CmdResult r = run("sweep " + spec.string() + " --out " + out.string() + " --jobs " + std::to_string(jobs));
    EXPECT_EQ(r.status, 2) << jobs;
    EXPECT_FALSE(fs::exists(out)) << jobs;  // refused before anything runs
  }
  const CmdResult r = run("sweep " + spec.string() + " --out " + out.string() + " --jobs " +
                          std::to_string(bpde::kMaxSweepThreads));
  EXPECT_EQ(r.status, 0) << r.err;
}

// The rows of DIR/results.jsonl without their wall times.
std::vector<bpde::Json> rows_without_seconds(const fs::path& dir) {
  std::vector<bpde::Json> rows;
  std::istringstream in(slurp(dir / "results.jsonl"));
  for (std::string line; std::getline(in, line);) {
    bpde::Json row = bpde::Json::parse(line);
    row.erase("seconds");
    rows.push_back(row);
  }
  return rows;
}

// `--progress` is accepted as by `solve`: one `sweep: K/N ...` line per job on stderr (FORMATS.md
// "Sweeps"), the same results as without it.
TEST(SweepResources, ProgressGivesOneLinePerJob) {
  const fs::path spec = quick_sweep("sr_progress.json", 3);
  const fs::path plain = tmpdir() / "sr_progress_plain", with = tmpdir() / "sr_progress_with";
  fs::remove_all(plain);
  fs::remove_all(with);
  ASSERT_EQ(run("sweep " + spec.string() + " --out " + plain.string()).status, 0);
  const CmdResult r = run("sweep " + spec.string() + " --out " + with.string() + " --progress");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(rows_without_seconds(with), rows_without_seconds(plain));
  EXPECT_EQ(rows_without_seconds(with).size(), 3u);
  const std::regex job_line("sweep: [0-9]+/3 .*"), header("sweep: 3 jobs, 0 already done");
  std::istringstream err(r.err);
  int job_lines = 0, headers = 0, lines = 0;
  for (std::string line; std::getline(err, line); ++lines) {
    job_lines += std::regex_match(line, job_line);
    headers += std::regex_match(line, header);
  }
  EXPECT_EQ(job_lines, 3) << r.err;
  EXPECT_EQ(headers, 1) << r.err;
  EXPECT_EQ(lines, 4) << r.err;  // no stage lines of the jobs in between
}

// 300 threads of 8 MiB stacks do not fit a 1 GiB address space: the pool stops growing where the
// system refuses a thread, and the sweep still runs every job (exit 0) or, when memory runs out
// in a job, exits 3 with one line. The limit cannot hold an ASan binary's shadow memory.
TEST(SweepResources, RefusedThreadsAndMemoryAreNotAnAbort) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "RLIMIT_AS and ASan";
#endif
  const fs::path spec = quick_sweep("sr_threads.json", 300);
  const fs::path out = tmpdir() / "sr_threads_out";
  fs::remove_all(out);
  const CmdResult r = run_with_limit("sweep " + spec.string() + " --out " + out.string() + " --jobs " +
                                         std::to_string(bpde::kMaxSweepThreads),
                                     RLIMIT_AS, rlim_t{1} << 30);
  ASSERT_TRUE(r.status == 0 || r.status == 1 || r.status == 3) << r.status << "\n" << r.err;  // never a signal
  if (r.status == 0) {
    const std::string csv = slurp(out / "results.csv");
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 301);
  }
  // Larger meshes on 64 threads in the same space: some jobs run out of memory (their rows say
  // internal-error and the sweep exits 1, as for any job that did not converge), and memory may run
  // out where C++ cannot throw (a JSON value freed under a noexcept destructor: exit 3). Which one
  // happens depends on timing; never a signal.
  std::string samples;
  for (int k = 2; k < 66; ++k) {
    if (k > 2) samples += ',';
    samples += std::to_string(k);
  }
  std::string big = slurp(quick_sweep("sr_mem.json", 1));
  big = big.substr(0, big.rfind("\"axes\"")) + R"("axes": {"samples": [)" + samples + "]}}";
  const fs::path out2 = tmpdir() / "sr_mem_out";
  fs::remove_all(out2);
  const CmdResult m = run_with_limit("sweep " + write("sr_mem.json", big).string() + " --out " + out2.string() +
                                         " --jobs 64",
                                     RLIMIT_AS, rlim_t{1} << 30);
  EXPECT_TRUE(m.status == 0 || m.status == 1 || m.status == 3) << m.status << "\n" << m.err;
}
