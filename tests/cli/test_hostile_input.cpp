// Hostile input: each class that once crashed the command, read without bound or gave
// a wrong exit status, run through the `bpde` binary. Bad input must exit 2 with one line
// `error: ...` on stderr and leave the output folder as it was.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "bezierpde/io/json_io.h"
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

// The hostile inputs below are meant to run under the sanitizers too (the asan preset): the
// command they run must be the one of this build, instrumented exactly when this test is, and a
// sanitizer report must not pass for the exit 1 of a valid input without solution. GCC and clang
// define __SANITIZE_ADDRESS__ under -fsanitize=address; an ASan binary prints its flags at start
// with ASAN_OPTIONS=help=1, with the exit status of a report (86: cmake/sanitizer_defaults.cpp).
TEST(HostileInput, RunsTheCommandOfThisBuild) {
  const fs::path err = tmpdir() / "asan_help";
  const std::string cmd = "ASAN_OPTIONS=help=1 " + std::string(BPDE_BINARY) + " --version >/dev/null 2>" + err.string();
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string help = slurp(err);
#ifdef __SANITIZE_ADDRESS__
  EXPECT_NE(help.find("Available flags for AddressSanitizer"), std::string::npos) << help.substr(0, 400);
  const std::size_t at = help.find("\n\texitcode\n");
  ASSERT_NE(at, std::string::npos) << "no exitcode flag in the ASan help";
  const std::size_t value = help.find("(Current Value: ", at);
  ASSERT_NE(value, std::string::npos);
  EXPECT_EQ(help.substr(value, 19), "(Current Value: 86)") << help.substr(at, 200);
#else
  EXPECT_EQ(help.find("AddressSanitizer"), std::string::npos) << "an instrumented bpde in a plain build";
#endif
}

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

namespace {
// Every entry under `dir` (recursively): relative path -> bytes, or "<dir>" for a folder.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> s;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    s[fs::relative(e.path(), dir).string()] = e.is_directory() ? "<dir>" : slurp(e.path());
  return s;
}

// No staging folder may be left beside an output folder.
void expect_no_staging(const fs::path& parent) {
  for (const auto& e : fs::directory_iterator(parent))
    EXPECT_EQ(e.path().filename().string().rfind(".bpde-staging", 0), std::string::npos) << e.path();
}

const char* kBlendConfig = R"({"kind": "blend", "partition": [1, 1], "a": 1, "epsilon": 0.01,
  "edges": {"y0": {"value": [[0,0,0],[1,0,0]], "dy": [[0,1,0],[0,1,0]]},
            "y1": {"value": [[0,1,0],[1,1,0]], "dy": [[0,1,0],[0,1,0]]}}, "samples": 4})";

// The four commands that write an output folder, with their arguments up to `--out`.
std::vector<std::pair<std::string, std::string>> writing_commands() {
  const fs::path job = write("atomic_job.json", high_degree_pde_job(4, "lu"));
  const fs::path net = write("atomic_net.json", kTensor);
  const fs::path blend = write("atomic_blend.json", kBlendConfig);
  return {{"solve", "solve " + job.string()},
          {"sample", "sample " + net.string() + " --samples 4"},
          {"blend", "blend " + blend.string()},
          {"demo", "demo"}};
}
}  // namespace

// DIR/surface.obj was a directory: the command exited 2 but left result.json (and surface.obj of
// sample) behind. Now every writing command leaves an existing DIR byte for byte as it was.
TEST(HostileInput, UnwritableOutputLeavesTheFolderAsItWas) {
  for (const auto& [name, args] : writing_commands())
    for (const char* blocked : {"surface.obj", "surface.ply", "net.obj"}) {
      const fs::path out = tmpdir() / ("atomic_" + name);
      fs::remove_all(out);
      fs::create_directories(out / blocked);
      std::ofstream(out / blocked / "inside.txt") << "mine\n";
      std::ofstream(out / "result.json") << "{\"old\": true}\n";
      std::ofstream(out / "keep.txt") << "untouched\n";
      const auto before = snapshot(out);
      const CmdResult r = run(args + " --out " + out.string());
      EXPECT_EQ(r.status, 2) << name << " " << blocked << ": " << r.err;
      EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
      EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_EQ(snapshot(out), before) << name << " " << blocked;
      expect_no_staging(tmpdir());
    }
  // The output folder itself a file: refused, the file as it was.
  const fs::path file = write("atomic_file", "a file\n");
  for (const auto& [name, args] : writing_commands()) {
    const CmdResult r = run(args + " --out " + file.string());
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_EQ(slurp(file), "a file\n");
  }
}

// A successful run into an existing DIR replaces its result files and keeps its other files; a
// missing DIR is created with its parents; no staging folder stays behind.
TEST(HostileInput, OutputFolderIsReplacedOnlyOnSuccess) {
  for (const auto& [name, args] : writing_commands()) {
    const fs::path out = tmpdir() / ("replace_" + name);
    fs::remove_all(out);
    fs::create_directories(out);
    std::ofstream(out / "surface.obj") << "old surface\n";
    std::ofstream(out / "keep.txt") << "untouched\n";
    const CmdResult r = run(args + " --out " + out.string());
    ASSERT_EQ(r.status, 0) << name << ": " << r.err;
    EXPECT_EQ(slurp(out / "keep.txt"), "untouched\n");
    const std::string obj = slurp(out / "surface.obj");
    EXPECT_NE(obj, "old surface\n") << name;
    EXPECT_NE(obj.find("\nv "), std::string::npos) << name;
    EXPECT_TRUE(fs::exists(out / "surface.ply"));
    EXPECT_TRUE(fs::exists(out / "net.obj"));
    EXPECT_EQ(fs::exists(out / "result.json"), name != "sample");
    expect_no_staging(tmpdir());
    const fs::path nested = tmpdir() / ("nested_" + name) / "a" / "b";
    fs::remove_all(tmpdir() / ("nested_" + name));
    const CmdResult n = run(args + " --out " + nested.string());
    ASSERT_EQ(n.status, 0) << name << ": " << n.err;
    EXPECT_TRUE(fs::exists(nested / "surface.obj"));
    expect_no_staging(nested.parent_path());
  }
}

// A failing run with a long or nested output name created the missing parents and left them
// behind empty.
TEST(HostileInput, FailedRunsCreateNoParentFolders) {
  for (const auto& [name, args] : writing_commands()) {
    const fs::path top = tmpdir() / ("parents_" + name);
    fs::remove_all(top);
    const fs::path too_long = top / "a" / "b" / std::string(300, 'x');
    const CmdResult r = run(args + " --out " + too_long.string());
    EXPECT_EQ(r.status, 2) << name << ": " << r.err;
    EXPECT_NE(r.err.find("longer than"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(top)) << name;
    // Bad input with a nested missing output folder: nothing created either.
    const CmdResult b = run("solve " + write("bad_job.json", "{").string() + " --out " + (top / "c" / "d").string());
    EXPECT_EQ(b.status, 2);
    EXPECT_FALSE(fs::exists(top)) << name;
    // A parent that is a file.
    const fs::path file = write("parent_file", "x\n");
    const CmdResult f = run(args + " --out " + (file / "sub").string());
    EXPECT_EQ(f.status, 2) << name << ": " << f.err;
    EXPECT_EQ(slurp(file), "x\n");
  }
}

namespace {
// A job on a triangular net of degree n whose boundary is a bent triangle (interior points 0).
std::string triangular_job(int n, const std::string& problem) {
  std::ostringstream s;
  s.precision(17);
  s << R"({"net": {"type": "triangular", "degree": )" << n << R"(, "points": [)";
  bool first = true;
  for (int i = n; i >= 0; --i)
    for (int j = n - i; j >= 0; --j) {
      const int k = n - i - j;
      const double u = double(i) / n, v = double(j) / n;
      const double z = (i == 0 || j == 0 || k == 0) ? 0.2 * std::sin(3 * u) * std::cos(2 * v) : 0.0;
      s << (first ? "" : ", ") << "[" << u + 0.5 * v << ", " << v * 0.8660254037844386 << ", " << z << "]";
      first = false;
    }
  s << R"(]}, "problem": )" << problem << R"(, "samples": 8})";
  return s.str();
}

std::string tensor_job(int n, const std::string& problem) {
  std::ostringstream s;
  s.precision(17);
  s << R"({"net": {"type": "tensor", "degree": [)" << n << ", " << n << R"(], "points": [)";
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const bool edge = i == 0 || j == 0 || i == n || j == n;
      s << (i + j ? ", " : "") << "[" << double(i) / n << ", " << double(j) / n << ", "
        << (edge ? 0.2 * std::sin(3.0 * i / n) * std::cos(2.0 * j / n) : 0.0) << "]";
    }
  s << R"(]}, "problem": )" << problem << R"(, "samples": 8})";
  return s.str();
}

// `job` must run (exit 0, converged) and `over` must be refused up front naming the limit.
void expect_limit(const std::string& name, const std::string& job, const std::string& over, const std::string& limit) {
  const fs::path out = tmpdir() / ("limit_ok_" + name);
  const CmdResult ok = run("solve " + write("limit_ok_" + name + ".json", job).string() + " --out " + out.string());
  EXPECT_EQ(ok.status, 0) << name << ": " << ok.err;
  const fs::path bad = prepared_out("limit_" + name);
  expect_bad_input("solve " + write("limit_over_" + name + ".json", over).string() + " --out " + bad.string(), bad,
                   "takes degrees up to " + limit);
}
}  // namespace

// The triangular Dirichlet extremal exited 2 ("Q_ff is singular") at n = 25 and 30, valid degrees
// by the contract; a triangular cmc at degree 64 ran past 5 minutes and 2.2 GB. Now each solver's
// degree limit is documented and checked up front (exit 2 naming it), the same for every kind.
TEST(HostileInput, DegreeLimitsAreCheckedUpFront) {
  const std::string dirichlet = R"({"kind": "extremal", "energy": {"name": "dirichlet"}})";
  const std::string cmc = R"({"kind": "cmc", "H": 0.5, "solver": "newton"})";
  expect_limit("tri_extremal", triangular_job(20, dirichlet), triangular_job(21, dirichlet), "20");
  expect_limit("tri_cmc", triangular_job(25, cmc), triangular_job(26, cmc), "25");
  expect_limit("tensor_cmc", tensor_job(16, cmc), tensor_job(17, cmc), "16");
  const fs::path out = prepared_out("limit_far");
  for (int n : {25, 30, 64})
    expect_bad_input("solve " + write("tri_far.json", triangular_job(n, dirichlet)).string() + " --out " + out.string(),
                     out, "takes degrees up to 20");
  expect_bad_input("solve " + write("tri_cmc64.json", triangular_job(64, cmc)).string() + " --out " + out.string(), out,
                   "takes degrees up to 25");
  // The C1 methods' dense solve (86 s at 40): 41 is refused before anything runs.
  for (const char* c1 : {R"({"kind": "tetraharmonic"})", R"({"kind": "biharmonic-load"})"}) {
    std::string job = tensor_job(41, c1);
    job.replace(job.find(R"("problem": )"), 11, R"("fixed": "boundary+adjacent", "problem": )");
    expect_bad_input("solve " + write("c1_41.json", job).string() + " --out " + out.string(), out,
                     "takes degrees up to 40");
  }
}

// samples: 4096 in a blend config ran 15 minutes and 7.6 GB: the limit is the jobs' 2000, and the
// message gives the memory the request would need; 2^64-1 is reported as written.
TEST(HostileInput, SamplesAreBoundedByTheMemoryTheyNeed) {
  const fs::path out = prepared_out("samples");
  std::string blend = kBlendConfig;
  const auto with_samples = [&](const std::string& n) {
    std::string t = blend;
    t.replace(t.find(R"("samples": 4)"), 12, "\"samples\": " + n);
    return t;
  };
  expect_bad_input("blend " + write("blend4096.json", with_samples("4096")).string() + " --out " + out.string(), out,
                   "samples must be in 1..2000, got 4096 (a mesh of N samples needs about 450 (N+1)^2 bytes: 7.6 GB");
  expect_bad_input("blend " + write("blend2001.json", with_samples("2001")).string() + " --out " + out.string(), out,
                   "1..2000, got 2001");
  expect_bad_input("blend " + write("blend0.json", with_samples("0")).string() + " --out " + out.string(), out,
                   "1..2000, got 0");
  expect_bad_input("blend " + write("blendmax.json", with_samples("18446744073709551615")).string() + " --out " +
                       out.string(),
                   out, "18446744073709551615");
  const fs::path job = write("job_u64.json", R"({"net": )" + std::string(kTensor) +
                                                 R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}},)"
                                                 R"( "samples": 18446744073709551615})");
  expect_bad_input("solve " + job.string() + " --out " + out.string(), out, "integer 18446744073709551615 is out");
  const fs::path deg = write("deg_u64.json", R"({"type": "tensor", "degree": [18446744073709551615, 1], "points": []})");
  const CmdResult r = run("check " + deg.string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("18446744073709551615"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("-1"), std::string::npos) << r.err;
}

// A blend config with a key twice was accepted (the last value won); jobs already refused it.
TEST(HostileInput, DuplicateKeysAreBadInputInEveryReader) {
  const fs::path out = prepared_out("dup");
  std::string blend = kBlendConfig;
  for (const char* dup : {R"("epsilon": 0.5)", R"("samples": 8)"}) {
    std::string t = blend;
    t.insert(t.rfind('}'), std::string(", ") + dup);
    expect_bad_input("blend " + write("dup_blend.json", t).string() + " --out " + out.string(), out, "duplicate key");
  }
  std::string net = kTensor;
  net.insert(net.rfind('}'), R"(, "degree": [1, 1])");
  expect_bad_input("sample " + write("dup_net.json", net).string() + " --out " + out.string(), out, "duplicate key");
  const fs::path job = write("dup_job.json", R"({"net": )" + std::string(kTensor) +
                                                 R"(, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"},)"
                                                 R"( "kind": "extremal"}})");
  expect_bad_input("solve " + job.string() + " --out " + out.string(), out, "duplicate key");
}

namespace {
// The numbers of a JSON value; `nulls` counts nulls (how nlohmann writes a non-finite double).
void json_numbers(const nlohmann::json& j, std::vector<double>& out, int& nulls) {
  if (j.is_number()) out.push_back(j.get<double>());
  if (j.is_null()) ++nulls;
  if (j.is_structured())
    for (const auto& v : j) json_numbers(v, out, nulls);
}

// Every coordinate on the `v` lines of an OBJ file (strtod reads "nan" and "inf" as non-finite).
std::vector<double> obj_vertex_numbers(const fs::path& p) {
  std::istringstream in(slurp(p));
  std::vector<double> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("v ", 0) != 0) continue;
    std::istringstream s(line.substr(2));
    std::string tok;
    while (s >> tok) out.push_back(std::strtod(tok.c_str(), nullptr));
  }
  return out;
}

void expect_finite_obj(const fs::path& p, const std::string& what) {
  const std::vector<double> v = obj_vertex_numbers(p);
  EXPECT_FALSE(v.empty()) << what << ": no vertices in " << p;
  EXPECT_TRUE(std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); })) << what << ": " << p;
}

// A degree-2 bspline net over the knots `u` (3 + k knots for k + ... points) and [0,0,0,.5,1,1,1].
std::string bspline2_net(const std::vector<std::string>& u) {
  const int nu = static_cast<int>(u.size()) - 3;
  std::ostringstream s;
  s << R"({"type": "bspline", "degree": [2, 2], "knots": [[)";
  for (std::size_t i = 0; i < u.size(); ++i) s << (i ? ", " : "") << u[i];
  s << R"(], [0, 0, 0, 0.5, 1, 1, 1]], "points": [)";
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < 4; ++j) s << (i + j ? ", " : "") << "[" << i << ", " << j << ", " << 0.3 * ((i * j) % 3) << "]";
  s << "]}";
  return s.str();
}
}  // namespace

// The knot scale rules of FORMATS.md "Input limits" at their limit and just past it: at the limit
// sample, check and a fourth-order extremal run, converge and write finite numbers (the
// fundamental forms scale like width^-4: a width of 1e-50 must not overflow them); past it the
// input is refused (exit 2, output untouched).
TEST(HostileInput, KnotScaleLimitsHoldAtTheLimitAndRefuseJustPastIt) {
  struct Case {
    std::string name;
    std::vector<std::string> at, past;
    std::string needle;
  };
  const std::vector<Case> cases = {
      // |knot| <= 1e50 (1.0000000000000002e50 is the next double).
      {"magnitude",
       {"-1e50", "-1e50", "-1e50", "1e50", "1e50", "1e50"},
       {"-1e50", "-1e50", "-1e50", "1.0000000000000002e50", "1.0000000000000002e50", "1.0000000000000002e50"},
       "too large"},
      // domain width >= 1e-50.
      {"width",
       {"0", "0", "0", "1e-50", "1e-50", "1e-50"},
       {"0", "0", "0", "9.9e-51", "9.9e-51", "9.9e-51"},
       "badly scaled"},
      // width >= 1e-8 max |knot|: at 2^20 the limit is 0.01048576.
      {"resolution",
       {"1048576", "1048576", "1048576", "1048576.0105", "1048576.0105", "1048576.0105"},
       {"1048576", "1048576", "1048576", "1048576.0104", "1048576.0104", "1048576.0104"},
       "badly scaled"},
      // a non-zero span >= 1e-12 (last - first).
      {"span", {"0", "0", "0", "1e-12", "1", "1", "1"}, {"0", "0", "0", "0.99e-12", "1", "1", "1"}, "badly scaled"},
  };
  for (const Case& c : cases) {
    const fs::path net = write("knot_at_" + c.name + ".json", bspline2_net(c.at));
    const fs::path sampled = tmpdir() / ("knot_at_" + c.name);
    fs::remove_all(sampled);
    const CmdResult s = run("sample " + net.string() + " --samples 6 --out " + sampled.string());
    ASSERT_EQ(s.status, 0) << c.name << ": " << s.err;
    expect_finite_obj(sampled / "surface.obj", c.name);
    const CmdResult k = run("check " + net.string());
    EXPECT_EQ(k.status, 0) << c.name << ": " << k.err;
    EXPECT_EQ(k.out.find("nan"), std::string::npos) << c.name << ": " << k.out;
    const fs::path job =
        write("knot_at_job_" + c.name + ".json",
              job_with_net(bspline2_net(c.at), R"({"kind": "extremal", "energy": {"name": "biharmonic"}})"));
    const fs::path solved = tmpdir() / ("knot_at_job_" + c.name);
    fs::remove_all(solved);
    const CmdResult r = run("solve " + job.string() + " --out " + solved.string());
    ASSERT_EQ(r.status, 0) << c.name << ": " << r.err;
    const auto result = nlohmann::json::parse(slurp(solved / "result.json"));
    EXPECT_EQ(result["report"]["converged"], true) << c.name;
    std::vector<double> xs;
    int nulls = 0;
    json_numbers(result["net"], xs, nulls);
    EXPECT_EQ(nulls, 0) << c.name << ": a non-finite number in the converged net";
    EXPECT_TRUE(std::all_of(xs.begin(), xs.end(), [](double x) { return std::isfinite(x); })) << c.name;
    expect_finite_obj(solved / "surface.obj", c.name);

    const fs::path out = prepared_out("knot_past_" + c.name);
    const fs::path bad = write("knot_past_" + c.name + ".json", bspline2_net(c.past));
    expect_bad_input("sample " + bad.string() + " --out " + out.string(), out, c.needle);
    expect_bad_input("check " + bad.string(), out, c.needle);
    const fs::path bad_job =
        write("knot_past_job_" + c.name + ".json",
              job_with_net(bspline2_net(c.past), R"({"kind": "extremal", "energy": {"name": "biharmonic"}})"));
    expect_bad_input("solve " + bad_job.string() + " --out " + out.string(), out, c.needle);
  }
}

namespace {
// A bspline pde job of degree [4, 4] with nu x nv control points (uniform knots).
std::string bspline_pde_job(int nu, int nv) {
  const auto knots = [](int n) {
    std::ostringstream s;
    s.precision(17);
    s << "[0, 0, 0, 0, 0";
    for (int i = 1; i < n - 4; ++i) s << ", " << double(i) / (n - 4);
    s << ", 1, 1, 1, 1, 1]";
    return s.str();
  };
  std::ostringstream s;
  s.precision(17);
  s << R"({"net": {"type": "bspline", "degree": [4, 4], "knots": [)" << knots(nu) << ", " << knots(nv)
    << R"(], "points": [)";
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j)
      s << (i + j ? ", " : "") << "[" << double(i) / (nu - 1) << ", " << double(j) / (nv - 1) << ", "
        << 0.1 * std::sin(3.0 * i / (nu - 1)) * std::cos(2.0 * j / (nv - 1)) << "]";
  s << R"(]}, "problem": {"kind": "pde", "operator": {"name": "biharmonic"}, "method": "lu"}, "samples": 8})";
  return s.str();
}

std::string blend_config(int k, int l) {
  std::ostringstream s;
  const auto edge = [&](int y) {
    std::ostringstream e;
    e << R"({"value": [)";
    for (int i = 0; i <= k; ++i) e << (i ? ", " : "") << "[" << double(i) / k << ", " << y << ", 0]";
    e << R"(], "dy": [)";
    for (int i = 0; i <= k; ++i) e << (i ? ", " : "") << "[0, 1, 0]";
    e << "]}";
    return e.str();
  };
  s << R"({"kind": "blend", "partition": [)" << k << ", " << l << R"(], "a": 1, "epsilon": 0.01, "edges": {"y0": )"
    << edge(0) << R"(, "y1": )" << edge(1) << R"(}, "samples": 4})";
  return s.str();
}
}  // namespace

// The size limits that do not depend on a degree, at the limit and one past it: the B-spline pde's
// dense solve (1500 control points: the 30 x 50 net runs, and its data being incompatible it
// answers converged: false, exit 1; 19 x 79 = 1501 is refused), the blend partition (256 per
// direction; [256, 1] and [1, 256] are cheap, 257 is refused; 256 x 256 itself takes 0.8 GB, so
// the suite does not run it) and `bpde plate` (degree 4..30, aspect [0.01, 100]).
TEST(HostileInput, SizeLimitsHoldAtTheLimitAndRefuseOnePastIt) {
  const fs::path at = tmpdir() / "bspline_pde_1500";
  fs::remove_all(at);
  const CmdResult r =
      run("solve " + write("bspline_pde_1500.json", bspline_pde_job(30, 50)).string() + " --out " + at.string());
  EXPECT_TRUE(r.status == 0 || r.status == 1) << r.err;
  EXPECT_TRUE(fs::exists(at / "result.json")) << r.err;
  const fs::path out = prepared_out("size_limits");
  expect_bad_input(
      "solve " + write("bspline_pde_1501.json", bspline_pde_job(19, 79)).string() + " --out " + out.string(), out,
      "limit of 1500 points");

  for (const auto& [k, l] : {std::pair{256, 1}, std::pair{1, 256}}) {
    const fs::path dir = tmpdir() / ("blend_" + std::to_string(k) + "_" + std::to_string(l));
    fs::remove_all(dir);
    const CmdResult b = run("blend " + write("blend_at.json", blend_config(k, l)).string() + " --out " + dir.string());
    EXPECT_EQ(b.status, 0) << k << " x " << l << ": " << b.err;
    expect_finite_obj(dir / "surface.obj", "blend");
  }
  expect_bad_input("blend " + write("blend_k257.json", blend_config(257, 1)).string() + " --out " + out.string(), out,
                   "(k) must be in 1..256");
  expect_bad_input("blend " + write("blend_l257.json", blend_config(1, 257)).string() + " --out " + out.string(), out,
                   "(l) must be in 1..256");

  for (const char* ok :
       {"--aspect 1 --degree 4", "--aspect 1 --degree 30", "--aspect 0.01 --degree 4", "--aspect 100 --degree 4"}) {
    const CmdResult p = run(std::string("plate ") + ok + " --method admissible-load");
    EXPECT_EQ(p.status, 0) << ok << ": " << p.err;
  }
  for (const auto& [bad, needle] :
       {std::pair{"--aspect 1 --degree 3", "4..30"}, std::pair{"--aspect 1 --degree 31", "4..30"},
        std::pair{"--aspect 0.0099 --degree 4", "[0.01, 100]"},
        std::pair{"--aspect 100.01 --degree 4", "[0.01, 100]"}}) {
    const CmdResult p = run(std::string("plate ") + bad + " --method admissible-load");
    EXPECT_EQ(p.status, 2) << bad << ": " << p.err;
    EXPECT_EQ(std::count(p.err.begin(), p.err.end(), '\n'), 1) << p.err;
    EXPECT_NE(p.err.find(needle), std::string::npos) << p.err;
  }
}

// The issue's crashes reached `blend` too (knots at ±1e308 in "surfaces", 100000 levels in
// surfaces.f.degree), and every reader takes the same bounds: blend configs, `--energy`, sweep
// files, and endless input to `sample`, `check`, `blend` and `sweep`.
TEST(HostileInput, BlendConfigsEnergyArgumentsAndSweepsGetTheSameReaderBounds) {
  const fs::path out = prepared_out("blend_reader");
  const auto blend_with_f = [](const std::string& f) {
    return R"({"kind": "blend", "partition": [2, 2], "a": 1, "epsilon": 0.01, "surfaces": {"f": )" + f +
           R"(, "g": {"type": "tensor", "degree": [1, 1], "points": [[0,2,0],[0,3,0],[1,2,0],[1,3,1]]}}, "samples": 4})";
  };
  int k = 0;
  for (const char* knots : {"[-1e308, -1e308, 1e308, 1e308]", "[0, 0, 1.7e308, 1.7e308]"})
    expect_bad_input(
        "blend " + write("blend_knots" + std::to_string(k++) + ".json", blend_with_f(bspline_net(knots))).string() +
            " --out " + out.string(),
        out, "too large");
  const std::string deep = std::string(100000, '[') + "1" + std::string(100000, ']');
  expect_bad_input(
      "blend " +
          write("blend_deep.json", blend_with_f(R"({"type": "tensor", "degree": )" + deep + R"(, "points": []})"))
              .string() +
          " --out " + out.string(),
      out, "nest deeper");
  expect_bad_input("blend /dev/zero --out " + out.string(), out, "64 MiB");
  expect_bad_input("sample /dev/stdin --out " + out.string() + " </dev/zero", out, "64 MiB");
  expect_bad_input("check /dev/zero", out, "64 MiB");
  const fs::path net = write("energy_net.json", kTensor);
  const auto energy = [&](const std::string& spec, const std::string& needle) {
    expect_bad_input("energy " + net.string() + " --energy '" + spec + "'", out, needle);
  };
  energy(R"({"name": "dirichlet", "name": "biharmonic"})", "duplicate key");
  energy(R"({"name": )" + std::string(300, '[') + std::string(300, ']') + "}", "nest deeper");
  energy(R"({"name": "gnorm", "rho": 1e999, "t": 1})", "overflows a double");
  expect_bad_input("sweep " + write("sweep_dup.json", R"({"base": "a.json", "base": "b.json", "axes": {}})").string() +
                       " --out " + out.string(),
                   out, "duplicate key");
  expect_bad_input("sweep " + write("sweep_deep.json", R"({"base": {"net": )" + deep + R"(}, "axes": {}})").string() +
                       " --out " + out.string(),
                   out, "nest deeper");
  expect_bad_input("sweep /dev/zero --out " + out.string(), out, "64 MiB");
  // an axis path deeper than the readers' nesting limit: refused before anything runs
  std::string path = "a";
  for (int i = 0; i < 100000; ++i) path += ".a";
  const CmdResult deep_axis =
      run("sweep " + write("sweep_deep_axis.json", R"({"base": {}, "axes": {")" + path + R"(": [1]}})").string() +
          " --out " + out.string());
  EXPECT_EQ(deep_axis.status, 2);
  expect_untouched(out);
}

// An epsilon at the edge of double's range: exit 2 with one line on stderr, and nothing on stdout
// (CHOLMOD printed "CHOLMOD warning: matrix not positive definite" there).
TEST(HostileInput, HugeEpsilonIsOneErrorLineAndNoSolverOutput) {
  std::string blend = kBlendConfig;
  blend.replace(blend.find("\"epsilon\": 0.01"), 15, "\"epsilon\": 1.7e308");
  const fs::path out = tmpdir() / "huge_epsilon";
  const CmdResult r = run("blend " + write("huge_epsilon.json", blend).string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// A volume no boundary of this size encloses (V = 1e200, the D_H V form): a valid request with no
// solution, so exit 1 with result.json converged false and its message, the data net written and
// no figure of the net that ran out of range (was: exit 2 from the mesh check of a net at 1e200).
TEST(HostileInput, UnreachableVolumeIsNoSolutionNotBadInput) {
  const fs::path out = tmpdir() / "huge_volume";
  const CmdResult r =
      run("solve " +
          write("huge_volume.json",
                R"({"boundary": {"type": "triangular", "degree": 6, "builder": "circle-three-arcs"}, "problem": {"kind": "cmc", "V": 1e200}})")
              .string() +
          " --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.err;
  ASSERT_TRUE(fs::exists(out / "result.json"));
  const bpde::Json res = bpde::read_json_file((out / "result.json").string());
  EXPECT_FALSE(res["report"]["converged"].get<bool>());
  EXPECT_FALSE(res["report"]["message"].get<std::string>().empty());
  EXPECT_TRUE(res["report"]["volume"].is_null());
  for (const auto& p : res["net"]["points"])
    for (const auto& x : p) EXPECT_LE(std::abs(x.get<double>()), 2.0);  // the unit circle's data net
}
