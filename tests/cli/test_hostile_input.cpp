// Hostile input (issue 14): each class that once crashed the command, read without bound or gave
// a wrong exit status, run through the `bpde` binary. Bad input must exit 2 with one line
// `error: ...` on stderr and leave the output folder as it was.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

// An output folder that already holds a file: a bad-input run must leave exactly that.
fs::path prepared_out(const std::string& name) {
  const fs::path out = tmpdir() / name;
  fs::remove_all(out);
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "untouched\n";
  return out;
}

void expect_untouched(const fs::path& out) {
  int entries = 0;
  for (const auto& e : fs::directory_iterator(out)) {
    (void)e;
    ++entries;
  }
  EXPECT_EQ(entries, 1) << out;
  EXPECT_EQ(slurp(out / "keep.txt"), "untouched\n");
}

// `args` must exit 2 with one line `error: ...` mentioning `needle`, and write nothing to `out`.
void expect_bad_input(const std::string& args, const fs::path& out, const std::string& needle) {
  const CmdResult r = run(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err.substr(0, 400);
  EXPECT_NE(r.err.find(needle), std::string::npos) << "message should mention '" << needle << "': " << r.err;
  expect_untouched(out);
}

const char* kTensor = R"({"type": "tensor", "degree": [1, 1], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]})";

std::string bspline_net(const std::string& u_knots) {
  return R"({"type": "bspline", "degree": [1, 1], "knots": [)" + u_knots +
         R"(, [0, 0, 1, 1]], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]})";
}

std::string job_with_net(const std::string& net, const std::string& problem) {
  return R"({"net": )" + net + R"(, "problem": )" + problem + "}";
}

}  // namespace

// The knot arithmetic overflowed (a width of inf, then NaN parameters) and basis_table wrote
// past its table: glibc aborted with "malloc(): invalid size" or the command segfaulted.
TEST(HostileInput, HugeAndOverflowingKnotsAreBadInput) {
  const fs::path out = prepared_out("knots");
  const std::string bad[] = {"[-1e308, -1e308, 1e308, 1e308]", "[0, 0, 1e308, 1e308]", "[0, 0, 1.7e308, 1.7e308]",
                             "[0, 0, 1e51, 1e51]"};
  int k = 0;
  for (const std::string& knots : bad) {
    const std::string tag = std::to_string(k++);
    const fs::path net = write("knots" + tag + ".json", bspline_net(knots));
    expect_bad_input("sample " + net.string() + " --out " + out.string(), out, "too large");
    expect_bad_input("check " + net.string(), out, "too large");
    const fs::path job =
        write("knotjob" + tag + ".json",
              job_with_net(bspline_net(knots), R"({"kind": "extremal", "energy": {"name": "dirichlet"}})"));
    expect_bad_input("solve " + job.string() + " --out " + out.string(), out, "too large");
  }
  // Badly scaled although every number is moderate: a domain of 1e-6 at 1e6, a span of 1e-15.
  expect_bad_input("sample " +
                       write("knots_res.json", bspline_net("[1e6, 1e6, 1000000.000001, 1000000.000001]")).string() +
                       " --out " + out.string(),
                   out, "badly scaled");
  expect_bad_input(
      "sample " +
          write("knots_span.json", R"({"type": "bspline", "degree": [1, 1], "knots": [[0, 0, 1e-15, 1, 1],)"
                                   R"( [0, 0, 1, 1]], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1],[2,0,0],[2,1,1]]})")
              .string() +
          " --out " + out.string(),
      out, "badly scaled");
  // Just inside the limits the same net is fine.
  const CmdResult ok = run("check " + write("knots_ok.json", bspline_net("[-1e50, -1e50, 1e50, 1e50]")).string());
  EXPECT_EQ(ok.status, 0) << ok.err;
}

// 100000 nested arrays: every reader that walked or printed the value recursed once per level.
TEST(HostileInput, DeepNestingIsBadInput) {
  const fs::path out = prepared_out("deep");
  const std::string deep = std::string(100000, '[') + "1" + std::string(100000, ']');
  const fs::path net = write("deep_net.json", R"({"type": "tensor", "degree": )" + deep + R"(, "points": []})");
  expect_bad_input("sample " + net.string() + " --out " + out.string(), out, "nest deeper");
  expect_bad_input("check " + net.string(), out, "nest deeper");
  const fs::path job = write("deep_job.json", job_with_net(kTensor, R"({"kind": "extremal", "energy": )" + deep + "}"));
  expect_bad_input("solve " + job.string() + " --out " + out.string(), out, "nest deeper");
  // 256 levels are read (and then refused as the wrong type, not as too deep); 257 are too deep.
  const auto nested = [](int levels) { return std::string(levels, '[') + std::string(levels, ']'); };
  const fs::path at = write("at_limit.json", R"({"type": "tensor", "degree": [1, 1], "points": )" + nested(255) + "}");
  const CmdResult r = run("check " + at.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err.find("nest deeper"), std::string::npos) << r.err;
  const fs::path over =
      write("over_limit.json", R"({"type": "tensor", "degree": [1, 1], "points": )" + nested(256) + "}");
  expect_bad_input("check " + over.string(), out, "nest deeper");
}

// /dev/zero as the job read until out of memory; a file over the cap is refused after 64 MiB.
TEST(HostileInput, EndlessAndOversizedInputIsBadInput) {
  const fs::path out = prepared_out("big");
  expect_bad_input("solve /dev/zero --out " + out.string(), out, "64 MiB");
  expect_bad_input("solve /dev/stdin --out " + out.string() + " </dev/zero", out, "64 MiB");
  // A sparse file one byte over the limit (the size check, not the JSON, rejects it).
  const fs::path big = tmpdir() / "big.json";
  { std::ofstream(big) << "{"; }
  fs::resize_file(big, (std::uintmax_t{64} << 20) + 1);
  expect_bad_input("solve " + big.string() + " --out " + out.string(), out, "64 MiB");
  // Exactly at the limit it is read and parsed (and is malformed JSON: the NUL bytes).
  fs::resize_file(big, std::uintmax_t{64} << 20);
  expect_bad_input("solve " + big.string() + " --out " + out.string(), out, "malformed JSON");
  fs::remove(big);
}

// gnorm (rho, t) with sin t = 0 is a singular G (e1 parallel to e2): bad input, as for G itself.
TEST(HostileInput, GnormWithParallelAxesIsBadInput) {
  const fs::path out = prepared_out("gnorm");
  for (const char* t : {"0", "3.141592653589793", "-3.141592653589793", "1e-14"}) {
    const fs::path job =
        write("gnorm.json",
              job_with_net(kTensor, std::string(R"({"kind": "extremal", "energy": {"name": "gnorm", "rho": 2, "t": )") +
                                        t + "}}"));
    expect_bad_input("solve " + job.string() + " --out " + out.string(), out, "singular");
  }
}

namespace {
// A pde job of degree [n, n] on generic boundary data (the interior points are ignored).
std::string high_degree_pde_job(int n, const char* method) {
  std::mt19937 gen(1234u + static_cast<unsigned>(n));
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::ostringstream s;
  s.precision(17);
  s << R"({"net": {"type": "tensor", "degree": [)" << n << ", " << n << R"(], "points": [)";
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      s << (i + j ? ", " : "") << "[" << double(i) / n + 0.1 * U(gen) << ", " << double(j) / n + 0.1 * U(gen) << ", "
        << 0.5 * U(gen) << "]";
  s << R"(]}, "problem": {"kind": "pde", "operator": {"name": "biharmonic"}, "method": ")" << method << R"("}})";
  return s.str();
}
}  // namespace

// converged: true promised a pde_residual <= 1e-11 that high-degree solutions did not have (from
// n = 15 with explicit, n = 18 with lu; vertices of 1e57 at [64, 64]). Past that limit the job
// must say converged: false (exit 1) and name the numerical limit.
TEST(HostileInput, HighDegreePdeReportsTheNumericalLimit) {
  for (const char* method : {"explicit", "lu"})
    for (int n : {25, 64}) {
      const fs::path job =
          write(std::string("pde_") + method + std::to_string(n) + ".json", high_degree_pde_job(n, method));
      const fs::path out = tmpdir() / (std::string("pde_") + method + std::to_string(n));
      const CmdResult r = run("solve " + job.string() + " --out " + out.string());
      ASSERT_EQ(r.status, 1) << method << " n=" << n << ": " << r.err;
      const auto result = nlohmann::json::parse(slurp(out / "result.json"));
      const auto& report = result.contains("report") ? result["report"] : result;
      EXPECT_EQ(report["converged"], false) << method << " n=" << n;
      EXPECT_NE(report["message"].get<std::string>().find("numerical limit"), std::string::npos) << report["message"];
    }
  // Below the limit the same kind of job converges, and then its residual keeps the promise.
  for (const char* method : {"explicit", "lu"}) {
    const fs::path job = write(std::string("pde_ok_") + method + ".json", high_degree_pde_job(8, method));
    const fs::path out = tmpdir() / (std::string("pde_ok_") + method);
    const CmdResult r = run("solve " + job.string() + " --out " + out.string());
    ASSERT_EQ(r.status, 0) << method << ": " << r.err;
    const auto result = nlohmann::json::parse(slurp(out / "result.json"));
    const auto& report = result.contains("report") ? result["report"] : result;
    EXPECT_EQ(report["converged"], true);
    EXPECT_LE(report["pde_residual"].get<double>(), 1e-11);
  }
}
