// Ctrl-C during the long solves of the command (docs/robustness.md, "Interrupting a solve"): SIGINT
// sent to `bpde solve` and `bpde blend` inside the dense tetraharmonic operator (degree 40, the
// largest the limits allow), the largest tensor extremal (degree 64) and a 256 x 256 blend ends the
// process by the signal within a second, leaves the output folder byte for byte as it was and no
// staging folder beside it.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>

#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

namespace {

std::string tensor_net(int n) {
  std::string s = R"({"type": "tensor", "degree": [)" + std::to_string(n) + ", " + std::to_string(n) + R"(], "points": [)";
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      if (i || j) s += ", ";
      const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
      // appended piece by piece: GCC 12's -Wrestrict misreads "literal" + std::to_string(...)
      s += '[';
      s += std::to_string(x);
      s += ", ";
      s += std::to_string(y);
      s += ", ";
      s += std::to_string(0.2 * std::sin(3 * x) * std::cos(2 * y));
      s += ']';
    }
  return s + "]}";
}

// Every file of a folder with its content.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) m[fs::relative(e.path(), dir).string()] = slurp(e.path());
  return m;
}

bool staging_in(const fs::path& dir) {
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().rfind(".bpde-staging-", 0) == 0) return true;
  return false;
}

}  // namespace

TEST(Interrupts, CtrlCInTheLongSolvesLeavesTheOutputFolderAsItWas) {
  const std::string extremal = R"("problem": {"kind": "extremal", "energy": {"name": "biharmonic"}})";
  const std::string blend =
      R"({"kind": "blend", "partition": [256, 256], "a": 1, "epsilon": 0.01, "surfaces": {)"
      R"("f": {"type": "tensor", "degree": [1, 1], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,0.5]]},)"
      R"("g": {"type": "tensor", "degree": [1, 1], "points": [[0,2,0],[0,3,0],[1,2,0],[1,3,1]]}}, "samples": 4})";
  const struct {
    const char* name;
    const char* command;
    std::string input;
  } cases[] = {
      {"tetraharmonic", "solve",
       R"({"net": )" + tensor_net(40) + R"(, "fixed": "boundary+adjacent", "problem": {"kind": "tetraharmonic"}, "samples": 4})"},
      {"extremal", "solve", R"({"net": )" + tensor_net(64) + R"(, "fixed": "boundary", )" + extremal + R"(, "samples": 4})"},
      {"blend", "blend", blend},
  };
  // The folder holds the result of an earlier, small run (and a file of the user's).
  const fs::path small = write("int_small.json", R"({"net": )" + tensor_net(3) + R"(, "fixed": "boundary", )" + extremal + "}");
  for (const auto& c : cases) {
    const fs::path parent = tmpdir() / (std::string("int_") + c.name);
    fs::remove_all(parent);
    fs::create_directories(parent);
    const fs::path out = parent / "out";
    ASSERT_EQ(run("solve " + small.string() + " --out " + out.string()).status, 0);
    { std::ofstream(out / "notes.txt") << "the user's\n"; }
    const auto before = contents(out);
    const fs::path input = write(std::string("int_") + c.name + ".json", c.input);
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      const int null = ::open("/dev/null", O_WRONLY);
      ::dup2(null, 1);
      ::dup2(null, 2);
      ::execl(BPDE_BINARY, "bpde", c.command, input.c_str(), "--out", out.c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // One second into the solve (the input is read and checked in milliseconds; each solve takes
    // seconds to minutes).
    std::this_thread::sleep_for(std::chrono::seconds(1));
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, WNOHANG), 0) << c.name << ": ended before the signal";
    const auto sent = std::chrono::steady_clock::now();
    ::kill(pid, SIGINT);
    ::waitpid(pid, &status, 0);
    const double latency = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
    RecordProperty(std::string(c.name) + "_latency_s", std::to_string(latency));
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << c.name << ": status " << status;
    EXPECT_LT(latency, 1.0) << c.name;
    EXPECT_EQ(contents(out), before) << c.name;
    EXPECT_FALSE(staging_in(parent)) << c.name;
    fs::remove_all(parent);
  }
}
