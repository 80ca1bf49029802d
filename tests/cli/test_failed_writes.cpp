// A failed write leaves the old file as it was (docs/FORMATS.md "Exit codes", docs/robustness.md):
// `bpde sweep` and `bpde export` rerun over finished outputs in a child whose files cannot grow
// (RLIMIT_FSIZE, SIGXFSZ ignored: every write fails as on a full disk) report exit 2 and leave the
// tables and the STEP file byte for byte, with no temporary beside them.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>
#include <string>

#include "bezierpde/io/atomic_file.h"
#include "bezierpde/core/errors.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;
using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::run_with_file_limit;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

namespace {

const char* kNet = R"({"type": "tensor", "degree": [2, 2], "points": [[0,0,0],[0,0.5,0],[0,1,0],[0.5,0,0],[0,0,0],)"
                   R"([0.5,1,0],[1,0,0],[1,0.5,0.5],[1,1,1]]})";

// The names in `dir` that are not in `expected` (temporaries left behind).
std::vector<std::string> extra_files(const fs::path& dir, const std::vector<std::string>& expected) {
  std::vector<std::string> extra;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string n = e.path().filename().string();
    if (std::find(expected.begin(), expected.end(), n) == expected.end()) extra.push_back(n);
  }
  return extra;
}

}  // namespace

TEST(FailedWrites, SweepTablesSurviveAFullDisk) {
  const std::string sweep = std::string(R"({"base": {"net": )") + kNet +
                            R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}},)"
                            R"( "axes": {"samples": [4, 5, 6]}})";
  const fs::path spec = write("fw_sweep.json", sweep);
  for (const int jobs : {1, 4}) {
    const fs::path out = tmpdir() / ("fw_sweep_out_" + std::to_string(jobs));
    fs::remove_all(out);
    const std::string args = "sweep " + spec.string() + " --out " + out.string() + " --jobs " + std::to_string(jobs);
    CmdResult r = run(args);
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string csv = slurp(out / "results.csv"), jsonl = slurp(out / "results.jsonl");
    ASSERT_FALSE(csv.empty());
    ASSERT_FALSE(jsonl.empty());
    for (const rlim_t limit : {rlim_t{0}, rlim_t{100}}) {
      r = run_with_file_limit(args, limit);
      EXPECT_EQ(r.status, 2) << "jobs " << jobs << ", limit " << limit;
      EXPECT_EQ(slurp(out / "results.csv"), csv);
      EXPECT_EQ(slurp(out / "results.jsonl"), jsonl);
      EXPECT_EQ(extra_files(out, {"results.csv", "results.jsonl", "jobs"}), std::vector<std::string>{});
    }
  }
}

TEST(FailedWrites, StepExportKeepsAnExistingTarget) {
  const fs::path net = write("fw_net.json", kNet);
  const fs::path dir = tmpdir() / "fw_step";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path step = dir / "t.step";
  const std::string old = "the old content of t.step\n";
  write("fw_step/t.step", old);
  const CmdResult r = run_with_file_limit("export " + net.string() + " --step " + step.string(), 1024);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(slurp(step), old);
  EXPECT_EQ(extra_files(dir, {"t.step"}), std::vector<std::string>{});
  // Without the limit the same command replaces it.
  ASSERT_EQ(run("export " + net.string() + " --step " + step.string()).status, 0);
  EXPECT_EQ(slurp(step).rfind("ISO-10303-21;", 0), 0u);
  EXPECT_EQ(extra_files(dir, {"t.step"}), std::vector<std::string>{});
}

TEST(FailedWrites, AtomicWriteRefusesADirectoryTargetAndLeavesNoTemporary) {
  const fs::path dir = tmpdir() / "fw_atomic";
  fs::remove_all(dir);
  fs::create_directories(dir / "target");
  EXPECT_THROW(bpde::write_file_atomically((dir / "target").string(), "x"), bpde::FileError);
  EXPECT_TRUE(fs::is_directory(dir / "target"));
  EXPECT_THROW(bpde::write_file_atomically((dir / "missing" / "f").string(), "x"), bpde::FileError);
  bpde::write_file_atomically((dir / "f").string(), "new");
  EXPECT_EQ(slurp(dir / "f"), "new");
  EXPECT_THROW(bpde::replace_file_atomically((dir / "f").string(),
                                             [](const std::string&) { throw bpde::FileError("no"); }),
               bpde::FileError);
  EXPECT_EQ(slurp(dir / "f"), "new");
  EXPECT_EQ(extra_files(dir, {"target", "f"}), std::vector<std::string>{});
}

// A table that cannot be replaced (results.csv is a folder) fails the sweep before any job runs:
// exit 2, no job folder, no temporary in --out.
TEST(FailedWrites, SweepChecksItsTablesBeforeRunningJobs) {
  const std::string sweep = std::string(R"({"base": {"net": )") + kNet +
                            R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}},)"
                            R"( "axes": {"samples": [4, 5]}})";
  const fs::path spec = write("fw_sweep_dir.json", sweep);
  const fs::path out = tmpdir() / "fw_sweep_csv_dir";
  fs::remove_all(out);
  fs::create_directories(out / "results.csv");
  const CmdResult r = run("sweep " + spec.string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_TRUE(fs::is_directory(out / "results.csv"));
  EXPECT_FALSE(fs::exists(out / "jobs"));
  EXPECT_EQ(extra_files(out, {"results.csv"}), std::vector<std::string>{});
  EXPECT_EQ(extra_files(out / "results.csv", {}), std::vector<std::string>{});
  // --out a file: exit 2, the file left as it was.
  const fs::path file = write("fw_sweep_out_file", "keep\n");
  EXPECT_EQ(run("sweep " + spec.string() + " --out " + file.string()).status, 2);
  EXPECT_EQ(slurp(file), "keep\n");
}

// SIGINT or SIGTERM while the files are being written into the staging folder: the process dies
// of the signal and leaves no `.bpde-staging-*` folder beside DIR (only SIGKILL may leave one).
TEST(FailedWrites, SignalDuringTheWritePhaseRemovesTheStagingFolder) {
  const fs::path net = write("fw_signal_net.json", kNet);
  const auto staging_in = [](const fs::path& dir) {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().rfind(".bpde-staging-", 0) == 0) return true;
    return false;
  };
  for (const int sig : {SIGTERM, SIGINT}) {
    const fs::path parent = tmpdir() / ("fw_signal_" + std::to_string(sig));
    fs::remove_all(parent);
    fs::create_directories(parent);
    const std::string out = (parent / "out").string();
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      // About 160 MB of surface files: the write phase lasts long enough to be caught.
      ::execl(BPDE_BINARY, "bpde", "sample", net.c_str(), "--out", out.c_str(), "--samples", "600",
              static_cast<char*>(nullptr));
      ::_exit(127);
    }
    bool seen = false;
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (!seen && std::chrono::steady_clock::now() < until) {
      int st = 0;
      if (::waitpid(pid, &st, WNOHANG) == pid) break;  // finished before the folder was seen
      seen = staging_in(parent);
      if (!seen) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    if (seen) ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!seen) GTEST_SKIP() << "the write phase ended before the staging folder was seen";
    EXPECT_TRUE(WIFSIGNALED(status));  // the handler re-raises the signal with its default action
    if (WIFSIGNALED(status)) {
      EXPECT_EQ(WTERMSIG(status), sig);
    }
    EXPECT_FALSE(staging_in(parent));
    fs::remove_all(parent);
  }
}

// `bpde solve` over an existing output folder whose files cannot grow past a limit: every limit
// fails one of the files the staging folder receives (result.json first, then the surface files),
// and each run exits 2 with DIR byte for byte as it was (its own files and a foreign one), no
// staging folder beside it; into a missing DIR, the folder is not created.
TEST(FailedWrites, SolveLeavesTheOutputFolderAsItWasOnAFullDisk) {
  const std::string job_text = std::string(R"({"net": )") + kNet +
                               R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}}, "samples": 30})";
  const fs::path job = write("fw_solve_job.json", job_text);
  const fs::path parent = tmpdir() / "fw_solve";
  fs::remove_all(parent);
  fs::create_directories(parent);
  const fs::path out = parent / "out";
  const std::string args = "solve " + job.string() + " --out " + out.string();
  CmdResult r = run(args);
  ASSERT_EQ(r.status, 0) << r.err;
  write("fw_solve/out/keep.txt", "a file of the user's");
  std::vector<std::string> names;
  std::vector<std::string> bytes;
  std::uintmax_t largest = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    names.push_back(e.path().filename().string());
    bytes.push_back(slurp(e.path()));
    largest = std::max<std::uintmax_t>(largest, fs::file_size(e.path()));
  }
  ASSERT_GE(names.size(), 6u);  // result.json, surface.obj/.ply/.vtp, net.obj and keep.txt
  ASSERT_GT(largest, 20000u);
  for (const rlim_t limit : {rlim_t{0}, rlim_t{100}, rlim_t{5000}, rlim_t{20000}}) {
    r = run_with_file_limit(args, limit);
    EXPECT_EQ(r.status, 2) << "limit " << limit;
    for (size_t k = 0; k < names.size(); ++k) EXPECT_EQ(slurp(out / names[k]), bytes[k]) << names[k] << ", limit " << limit;
    EXPECT_EQ(extra_files(out, names), std::vector<std::string>{}) << "limit " << limit;
    EXPECT_EQ(extra_files(parent, {"out"}), std::vector<std::string>{}) << "limit " << limit;
  }
  const fs::path fresh = parent / "fresh";
  r = run_with_file_limit("solve " + job.string() + " --out " + fresh.string(), 5000);
  EXPECT_EQ(r.status, 2);
  EXPECT_FALSE(fs::exists(fresh));
  EXPECT_EQ(extra_files(parent, {"out"}), std::vector<std::string>{});
  fs::remove_all(parent);
}
