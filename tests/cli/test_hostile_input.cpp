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
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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
