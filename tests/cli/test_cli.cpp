// The bpde command's contract (FORMATS.md "Exit status and errors"), by running the binary.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "bezierpde/core/eigen.h"
#include <Eigen/Core>
#include <cmath>

#include "bezierpde/boundaries/reference_boundaries.h"
#include "bezierpde/core/errors.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/jobs/exit_status.h"
#include "bezierpde/jobs/run_job.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

const char* kTensor = R"({"type": "tensor", "degree": [1, 1], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]})";

void expect_bad_input(const std::string& args, const std::string& needle) {
  const CmdResult r = run(args);
  EXPECT_EQ(r.status, 2) << args << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line: " << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << "message should mention '" << needle << "': " << r.err;
}

}  // namespace

TEST(Cli, SampleWritesTheFilesInTheDocumentedOrder) {
  const fs::path net = write("t.json", kTensor);
  const fs::path out = tmpdir() / "nested" / "sample";
  const CmdResult r = run("sample " + net.string() + " --out " + out.string() + " --samples 2");
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream obj(out / "surface.obj");
  std::string line;
  std::vector<std::string> v;
  while (std::getline(obj, line))
    if (line.rfind("v ", 0) == 0) v.push_back(line);
  ASSERT_EQ(v.size(), 9u);
  EXPECT_EQ(v[1], "v 0 0.5 0");    // a = 0, b = 1: (u, v) = (0, 1/2)
  EXPECT_EQ(v[5], "v 0.5 1 0.5");  // a = 1, b = 2
  EXPECT_TRUE(fs::exists(out / "surface.ply"));
  EXPECT_TRUE(fs::exists(out / "net.obj"));
}

TEST(Cli, BadInputExitsTwoWithOneLineAndWritesNothing) {
  const fs::path out = tmpdir() / "never";
  expect_bad_input("sample " + (tmpdir() / "missing.json").string() + " --out " + out.string(), "missing.json");
  expect_bad_input("sample " + write("m.json", "{\"type\": \"tensor\", ").string() + " --out " + out.string(),
                   "malformed JSON");
  expect_bad_input(
      "sample " +
          write("nan.json", R"({"type": "tensor", "degree": [1, 1], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1e999]]})")
              .string() +
          " --out " + out.string(),
      "overflow");
  expect_bad_input("sample " +
                       write("cnt.json", R"({"type": "tensor", "degree": [1, 1], "points": [[0,0,0]]})").string() +
                       " --out " + out.string(),
                   "needs 4 points");
  expect_bad_input("sample " + write("deg.json", R"({"type": "triangular", "degree": 0, "points": []})").string() +
                       " --out " + out.string(),
                   "degree");
  expect_bad_input("sample " + write("deg2.json", R"({"type": "triangular", "degree": 99, "points": []})").string() +
                       " --out " + out.string(),
                   "1..64");
  expect_bad_input(
      "sample " +
          write("unk.json",
                R"({"type": "tensor", "degree": [1, 1], "weights": [], "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]})")
              .string() +
          " --out " + out.string(),
      "unknown field");
  expect_bad_input("solve " +
                       write("job.json", std::string(R"({"net": )") + kTensor +
                                             R"(, "problem": {"kind": "extremal", "energy": {"name": "biharmonic"}}})")
                           .string() +
                       " --out " + out.string(),
                   "degrees >= 2");
  expect_bad_input(
      "solve " +
          write("job2.json",
                std::string(R"({"net": )") + kTensor +
                    R"(, "problem": {"kind": "extremal", "energy": {"name": "gnorm", "G": [[1, 2], [2, 4]]}}})")
              .string() +
          " --out " + out.string(),
      "singular");
  expect_bad_input("sample", "required");
  expect_bad_input("sample " + write("t2.json", kTensor).string() + " --out " + out.string() + " --samples 0",
                   "samples");
  EXPECT_FALSE(fs::exists(out));
}

TEST(Cli, HelpExitsZero) { EXPECT_EQ(run("--help").status, 0); }

namespace {
std::string slurp_file(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(Cli, SolvePdeAndExtremalWriteReports) {
  const fs::path ex = fs::path(BPDE_SOURCE_DIR) / "examples" / "001-pde-figures" / "fig1-biharmonic.json";
  const fs::path out = tmpdir() / "pde";
  const CmdResult r = run("solve " + ex.string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string res = slurp_file(out / "result.json");
  for (const char* key :
       {"\"pde_residual\"", "\"converged\": true", "\"energy\"", "\"self_intersections\"", "\"mean_curvature\""})
    EXPECT_NE(res.find(key), std::string::npos) << key;
  EXPECT_TRUE(fs::exists(out / "surface.ply"));
}

TEST(Cli, HarmonicEvenDegreeIncompatibleDataExitsOne) {
  // degree 2, u-boundaries: rows i = 0 and i = 2 given; a harmonic bidegree-(2,2) patch has
  // 2n+1 = 5 dimensions against 6 data values, so generic data are incompatible (docs/errata.md).
  const std::string job =
      R"({"net": {"type": "tensor", "degree": [2, 2], "points": [[0,0,0],[0,0.5,1],[0,1,0],[0.5,0,0],[0.5,0.5,0],[0.5,1,0],[1,0,0],[1,0.5,0.3],[1,1,2]]},
    "fixed": "u-boundaries", "problem": {"kind": "pde", "operator": {"name": "dirichlet"}}})";
  const fs::path out = tmpdir() / "harm";
  const CmdResult r = run("solve " + write("harm.json", job).string() + " --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string res = slurp_file(out / "result.json");
  EXPECT_NE(res.find("\"converged\": false"), std::string::npos);
  EXPECT_NE(res.find("\"message\""), std::string::npos);
}

TEST(Cli, EnergyCheckAndCmc) {
  // z = u v over [0,1]^2 as a degree-(1,1) net: Dirichlet energy 1/2 int (1 + v^2) + (1 + u^2) = 4/3;
  // coons energy 1/2 int |x_uv|^2 = 1/2.
  const fs::path net = write("saddle.json", kTensor);
  CmdResult r = run("energy " + net.string() + " --energy dirichlet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NEAR(std::stod(r.out.substr(r.out.find(':') + 1)), 4.0 / 3.0, 1e-12) << r.out;
  r = run("energy " + net.string() + " --energy coons");
  EXPECT_NEAR(std::stod(r.out.substr(r.out.find(':') + 1)), 0.5, 1e-12) << r.out;
  // V = 1/3 int <x_u ^ x_v, x> for (u, v, uv): x_u ^ x_v = (-v, -u, 1), <., x> = -uv - uv + uv = -uv,
  // so V = -1/12.
  r = run("energy " + net.string() + " --energy cmc --H 0.5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"V\""), std::string::npos);
  const double V = std::stod(r.out.substr(r.out.find("\"V\":") + 4));
  EXPECT_NEAR(V, -1.0 / 12.0, 1e-12) << r.out;
  expect_bad_input("energy " + net.string() + " --energy cmc", "--H");
  expect_bad_input("energy " + net.string() + " --energy thin-plate", "unknown energy");
  r = run("check " + net.string() + " --samples 8");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"self_intersections\":0"), std::string::npos) << r.out;
}

// The demo's table, one row per quantity and one column per functional (D + 2HV, A + 2HV, the least
// squares of the mean curvature), as the README's first section describes it: the paper's
// surface misses the cap of radius 2 by 5e-2 with a mean curvature up to +1.9, the other two lie
// on it to about 1e-8 with a mean curvature within about 2e-5 of H = −0.5, and none intersects
// itself. The printed numbers are read back from the table.
std::vector<std::string> demo_row(const std::string& out, const std::string& label) {
  const auto at = out.find("  " + label);
  if (at == std::string::npos) return {};
  std::string line = out.substr(at + 2 + label.size(), out.find('\n', at) - at - 2 - label.size());
  std::vector<std::string> cells;
  for (size_t i = 0; i < line.size();) {  // cells are separated by two or more spaces
    while (i < line.size() && line[i] == ' ') ++i;
    size_t j = i;
    while (j < line.size() && !(line[j] == ' ' && j + 1 < line.size() && line[j + 1] == ' ')) ++j;
    if (j > i) cells.push_back(line.substr(i, j - i));
    i = j;
  }
  return cells;
}

TEST(Cli, DemoPrintsTheFunctionalsSideBySide) {
  const CmdResult demo = run("demo --out " + (tmpdir() / "demo-table").string());
  ASSERT_EQ(demo.status, 0) << demo.err;
  const std::vector<std::string> dist = demo_row(demo.out, "distance to the exact cap");
  ASSERT_EQ(dist.size(), 3u) << demo.out;
  EXPECT_GT(std::stod(dist[0]), 1e-2) << demo.out;  // printed 0.0495
  EXPECT_LE(std::stod(dist[1]), 1e-7) << demo.out;  // printed 6.56e-09
  EXPECT_LE(std::stod(dist[2]), 1e-7) << demo.out;  // printed 8.67e-09
  const std::vector<std::string> range = demo_row(demo.out, "mean curvature (min .. max)");
  ASSERT_EQ(range.size(), 3u) << demo.out;
  const auto lo_hi = [](const std::string& cell) {
    const auto dots = cell.find(" .. ");
    return std::pair<double, double>(std::stod(cell.substr(0, dots)), std::stod(cell.substr(dots + 4)));
  };
  EXPECT_GT(lo_hi(range[0]).second, 1.0) << demo.out;  // printed -0.505062 .. 1.918494
  for (int c : {1, 2}) {
    EXPECT_NEAR(lo_hi(range[static_cast<size_t>(c)]).first, -0.5, 1e-4) << demo.out;
    EXPECT_NEAR(lo_hi(range[static_cast<size_t>(c)]).second, -0.5, 1e-4) << demo.out;
  }
  const std::vector<std::string> area = demo_row(demo.out, "area A");
  ASSERT_EQ(area.size(), 3u) << demo.out;
  const double cap_area = 4 * std::numbers::pi * (2 - std::sqrt(3.0));  // 2πR·h, R = 2, h = 2 − √3
  EXPECT_NEAR(std::stod(area[1]), cap_area, 1e-8) << demo.out;  // printed 3.36714885709 (cap 3.36714885791)
  EXPECT_LT(std::stod(area[0]), cap_area - 1e-2) << demo.out;   // printed 3.28463090237
  EXPECT_EQ(demo_row(demo.out, "CGAL self-intersections"), (std::vector<std::string>{"0", "0", "0"})) << demo.out;
}

TEST(Cli, CmcPastTheFoldExitsOneWithTheDocumentedMessage) {
  const fs::path out = tmpdir() / "fold";
  // the demo's circle in three arcs at degree 8; the D_H branch folds near |H| = 1.09
  const CmdResult demo = run("demo --out " + (tmpdir() / "demo").string());
  ASSERT_EQ(demo.status, 0) << demo.err;
  const std::string res = slurp_file(tmpdir() / "demo" / "result.json");
  // the demo's area and mean-curvature results (degree 8) reach their tolerances and say so (the
  // last cell of the "converged" line is the mean-curvature column)
  const auto cl = demo.out.find("  converged ");
  ASSERT_NE(cl, std::string::npos) << demo.out;
  const std::string line = demo.out.substr(cl, demo.out.find('\n', cl) - cl);
  EXPECT_EQ(line.substr(line.find_last_not_of(' ') - 2, 3), "yes") << line;
  EXPECT_NE(slurp_file(tmpdir() / "demo" / "area" / "result.json").find("\"converged\": true"), std::string::npos);
  EXPECT_NE(slurp_file(tmpdir() / "demo" / "mean-curvature" / "result.json").find("\"converged\": true"),
            std::string::npos);
  const auto p = res.find("\"net\"");
  ASSERT_NE(p, std::string::npos);
  // reuse the demo's net as the data of a job with H far past the fold
  std::string job = "{\"net\": " + res.substr(res.find('{', p), res.find('}', p) - res.find('{', p) + 1) +
                    ", \"problem\": {\"kind\": \"cmc\", \"H\": -5}}";
  const CmdResult r = run("solve " + write("fold.json", job).string() + " --out " + out.string());
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string fold = slurp_file(out / "result.json");
  EXPECT_NE(fold.find("no critical point on the branch from H = 0 beyond H"), std::string::npos) << fold.substr(0, 400);
  EXPECT_NE(fold.find("\"converged\": false"), std::string::npos);
}

TEST(Cli, PlateReproducesThePaperAndTetraharmonicJobsRun) {
  CmdResult r = run("plate --aspect 1 --degree 11 --method admissible-load");
  ASSERT_EQ(r.status, 0) << r.err;
  const double w = std::stod(r.out.substr(r.out.find("\"center_deflection\":") + 20));
  EXPECT_NEAR(w, 0.00126654, 5e-9);  // Centella et al., n = 11, square: every printed digit
  expect_bad_input("plate --aspect 1 --degree 3 --method ritz", "degree");
  expect_bad_input("plate --aspect 1 --degree 8 --method fem", "method");
  // C1 data from z = u^2 v^2 (degree 4, tetraharmonic and biharmonic-load jobs)
  std::ostringstream pts;
  pts.precision(17);
  for (int i = 0; i <= 4; ++i)
    for (int j = 0; j <= 4; ++j) {
      // Bernstein coefficients of u^2 at degree 4: i(i-1)/12
      const double z = (i * (i - 1) / 12.0) * (j * (j - 1) / 12.0);
      pts << (i + j == 0 ? "" : ",") << "[" << i / 4.0 << "," << j / 4.0 << "," << z << "]";
    }
  const std::string net = R"({"type": "tensor", "degree": [4, 4], "points": [)" + pts.str() + "]}";
  for (const char* kind : {"tetraharmonic", "biharmonic-load"}) {
    const std::string job =
        "{\"net\": " + net + ", \"fixed\": \"boundary+adjacent\", \"problem\": {\"kind\": \"" + kind + "\"}}";
    const fs::path out = tmpdir() / kind;
    r = run("solve " + write(std::string(kind) + ".json", job).string() + " --out " + out.string());
    EXPECT_EQ(r.status, 0) << kind << r.err;
    const std::string res = slurp_file(out / "result.json");
    EXPECT_NE(res.find("\"energy\": null"), std::string::npos) << kind;
    if (std::string(kind) == "biharmonic-load") {
      EXPECT_NE(res.find("\"load\""), std::string::npos);
    }
  }
}

TEST(Cli, BSplineJobs) {
  // biquintic, 2 x 2 spans (knots 0^6 0.5 1^6): 7 x 7 control points from a wavy boundary.
  std::ostringstream pts;
  pts.precision(17);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j)
      pts << (i + j == 0 ? "" : ",") << "[" << i / 6.0 << "," << j / 6.0 << "," << 0.1 * ((i * 7 + j * 3) % 5) << "]";
  const std::string net =
      R"({"type": "bspline", "degree": [5, 5], "knots": [[0,0,0,0,0,0,0.5,1,1,1,1,1,1],[0,0,0,0,0,0,0.5,1,1,1,1,1,1]], "points": [)" +
      pts.str() + "]}";
  // the extremal exists for any boundary
  CmdResult r = run("solve " +
                    write("bs_ext.json", "{\"net\": " + net +
                                             R"(, "problem": {"kind": "extremal", "energy": {"name": "biharmonic"}}})")
                        .string() +
                    " --out " + (tmpdir() / "bs_ext").string());
  EXPECT_EQ(r.status, 0) << r.err;
  // generic data on a multi-span net admit no spline solution of the biharmonic PDE (docs/errata.md): exit 1
  r = run(
      "solve " +
      write("bs_pde.json", "{\"net\": " + net + R"(, "problem": {"kind": "pde", "operator": {"name": "biharmonic"}}})")
          .string() +
      " --out " + (tmpdir() / "bs_pde").string());
  EXPECT_EQ(r.status, 1) << r.err;
  const std::string res = slurp_file(tmpdir() / "bs_pde" / "result.json");
  EXPECT_NE(res.find("\"rank\""), std::string::npos);
  EXPECT_NE(res.find("\"converged\": false"), std::string::npos);
  r = run("energy " + write("bs_net.json", net).string() + " --energy biharmonic");
  EXPECT_EQ(r.status, 0) << r.err;
  expect_bad_input(
      "solve " +
          write("bs_exp.json",
                "{\"net\": " + net +
                    R"(, "problem": {"kind": "pde", "operator": {"name": "biharmonic"}, "method": "explicit"}})")
              .string() +
          " --out " + (tmpdir() / "bs_exp").string(),
      "explicit");
}

TEST(Cli, InternalFailuresExitThreeWithOneLine) {
  // The mapping main applies to what escapes a command (jobs/exit_status.h, FORMATS.md exit 3).
  static_assert(!std::is_base_of_v<bpde::InvalidInput, bpde::InternalError>, "a broken invariant is not bad input");
  auto exit_of = [](auto e) { return bpde::error_exit(std::make_exception_ptr(e)); };
  bpde::ErrorExit x = exit_of(bpde::InternalError("summary: status \"converged\" with converged = false"));
  EXPECT_EQ(x.code, 3);
  EXPECT_EQ(x.line, "internal error: summary: status \"converged\" with converged = false\n");
  x = exit_of(std::bad_alloc());
  EXPECT_EQ(x.code, 3);
  EXPECT_EQ(x.line, "internal error: out of memory\n");
  x = exit_of(std::runtime_error("two\nlines"));
  EXPECT_EQ(x.code, 3);
  EXPECT_EQ(x.line, "internal error: two lines\n");
  x = exit_of(42);
  EXPECT_EQ(x.code, 3);
  EXPECT_EQ(x.line, "internal error: unknown exception\n");
  x = exit_of(bpde::DegreeError("job: needs degrees >= 2"));
  EXPECT_EQ(x.code, 2);
  EXPECT_EQ(x.line, "error: job: needs degrees >= 2\n");

  // A Summary that breaks its contract is an internal error, never exit 1.
  bpde::Summary s;
  s.set_converged();
  s.converged = false;
  EXPECT_THROW(bpde::checked_status(s), bpde::InternalError);
  s.set_failed(bpde::Status::Fold, "no critical point on the branch from H = 0 beyond H = -1.5");
  EXPECT_EQ(bpde::checked_status(s), bpde::Status::Fold);
  EXPECT_EQ(bpde::exit_code(bpde::Status::Fold), 1);
  EXPECT_EQ(bpde::exit_code(bpde::Status::Converged), 0);
}

TEST(Cli, OutOfMemoryExitsThreeAndWritesNothing) {
#ifdef __SANITIZE_ADDRESS__
  // An ASan binary reserves terabytes of address space for its shadow memory at start, so under
  // `ulimit -v` it cannot even start, and its allocator reports an exhausted heap instead of
  // throwing std::bad_alloc: this test is meaningless there (docs/robustness.md, Sanitizer pass).
  GTEST_SKIP() << "ulimit -v and AddressSanitizer's shadow memory do not mix";
#endif
  // A valid job whose surface files need ~1 GB (4M samples), under a 400 MB address-space limit.
  const std::string job = std::string(
      R"({"net": {"type": "tensor", "degree": [2, 2], "points": [[0,0,0],[0,0.5,1],[0,1,0],[0.5,0,0],[0.5,0.5,0],[0.5,1,0],[1,0,0],[1,0.5,0.3],[1,1,2]]},
    "problem": {"kind": "extremal", "energy": {"name": "biharmonic"}}, "samples": 2000})");
  const fs::path out = tmpdir() / "oom";
  const fs::path o = tmpdir() / "oom_stdout", e = tmpdir() / "oom_stderr";
  const std::string cmd = "sh -c 'ulimit -v 400000 && exec " + std::string(BPDE_BINARY) + " solve " +
                          write("oom.json", job).string() + " --out " + out.string() + "' >" + o.string() + " 2>" +
                          e.string();
  const int rc = std::system(cmd.c_str());
  ASSERT_TRUE(WIFEXITED(rc)) << "the command must not crash";
  EXPECT_EQ(WEXITSTATUS(rc), 3);
  const std::string err = slurp_file(e);
  EXPECT_EQ(err, "internal error: out of memory\n");
  EXPECT_FALSE(fs::exists(out / "result.json"));
}

namespace {
// Control points of x = (u, v, u^2 - v^2) on the B-spline basis of degree p with knots K in both
// directions: the Greville abscissae for u and the blossom of u^2, sum_{j<k} t_j t_k / C(p, 2),
// over each basis function's interior knots t_{i+1..i+p} (Marsden's identity).
std::string bspline_polynomial_net(int p, const std::vector<double>& K, std::vector<double>& z) {
  const int n = static_cast<int>(K.size()) - p - 1;
  std::vector<double> g(n), s(n);
  for (int i = 0; i < n; ++i) {
    double sum = 0, pairs = 0;
    for (int j = 1; j <= p; ++j) {
      sum += K[i + j];
      for (int k = j + 1; k <= p; ++k) pairs += K[i + j] * K[i + k];
    }
    g[i] = sum / p;
    s[i] = pairs / (p * (p - 1) / 2.0);
  }
  std::ostringstream knots, pts;
  knots.precision(17);
  pts.precision(17);
  for (size_t k = 0; k < K.size(); ++k) knots << (k ? "," : "") << K[k];
  z.clear();
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      z.push_back(s[i] - s[j]);
      pts << (i + j == 0 ? "" : ",") << "[" << g[i] << "," << g[j] << "," << s[i] - s[j] << "]";
    }
  return R"({"type": "bspline", "degree": [)" + std::to_string(p) + ", " + std::to_string(p) + R"(], "knots": [[)" +
         knots.str() + "],[" + knots.str() + R"(]], "points": [)" + pts.str() + "]}";
}
}  // namespace

TEST(Cli, BSplinePdeTakesBoundaryAdjacentData) {
  // Biquintic, 2 x 2 spans: the outer two rings of a global biharmonic polynomial prescribed, the
  // inner 3 x 3 control points solved for; the answer is the polynomial itself.
  std::vector<double> z;
  const std::string net = bspline_polynomial_net(5, {0, 0, 0, 0, 0, 0, 0.5, 1, 1, 1, 1, 1, 1}, z);
  const fs::path out = tmpdir() / "bs_pde_c1";
  const CmdResult r = run(
      "solve " +
      write("bs_pde_c1.json",
            "{\"net\": " + net +
                R"(, "fixed": "boundary+adjacent", "problem": {"kind": "pde", "operator": {"name": "biharmonic"}}})")
          .string() +
      " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(out / "result.json");
  std::stringstream text;
  text << in.rdbuf();
  const bpde::Json res = bpde::Json::parse(text.str());
  const bpde::Json& rep = res["report"];
  EXPECT_EQ(rep["converged"], true);
  for (const char* key : {"rank", "equations", "free_parameters", "compatibility_conditions", "pde_residual"})
    EXPECT_TRUE(rep.contains(key)) << key;
  EXPECT_EQ(rep["free_parameters"], 0);
  const bpde::Json& P = res["net"]["points"];
  ASSERT_EQ(P.size(), z.size());
  for (size_t k = 0; k < z.size(); ++k) EXPECT_NEAR(P[k][2].get<double>(), z[k], 1e-10) << k;
}

// The area functional as a job (FORMATS.md, problem "cmc" with "functional": "area"): the
// helicoid piece of tests/cmc/test_cmc_area.cpp at tensor degree 6, H = 0; and the bad input.
TEST(Cli, CmcAreaJobReportsTheAreaFunctional) {
  auto helicoid = [](double u, double v) {
    const double s = 0.3 + 0.7 * u, t = 1.2 * v;
    return Eigen::Vector3d(s * std::cos(t), s * std::sin(t), t);
  };
  const std::string net = bpde::net_to_json(bpde::tensor_boundary(6, helicoid)).dump();
  auto job = [&](const std::string& problem, const std::string& extra = "") {
    return "{\"net\": " + net + extra + ", \"problem\": " + problem + "}";
  };
  const fs::path out = tmpdir() / "area";
  const CmdResult r =
      run("solve " + write("area.json", job(R"({"kind": "cmc", "H": 0, "functional": "area"})")).string() +
          " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const bpde::Json rep = bpde::read_json_file((out / "result.json").string())["report"];
  EXPECT_EQ(rep["functional"], "area");
  EXPECT_TRUE(rep["converged"].get<bool>());
  EXPECT_NEAR(rep["energy"].get<double>(), rep["area"].get<double>(), 1e-14);  // H = 0: A_H = A
  EXPECT_GT(rep["D"].get<double>(), rep["area"].get<double>());                  // D >= A, not conformal
  EXPECT_TRUE(rep.contains("volume") && rep.contains("mean_curvature") && rep.contains("residual"));
  // The rule of the result: 8(L + 1)q² nodes on the tensor net.
  ASSERT_TRUE(rep.contains("quadrature")) << rep.dump();
  const int q = rep["quadrature"]["points_per_direction"].get<int>(), g = rep["quadrature"]["grading"].get<int>();
  const int L = rep["quadrature"]["levels"].get<int>();
  EXPECT_TRUE(q >= 1 && q <= 64) << q;
  EXPECT_TRUE(g == 1 || g == 3) << g;
  EXPECT_TRUE(L == 0 || (L == 10 && g == 1)) << L;
  EXPECT_EQ(rep["quadrature"]["nodes"].get<int>(), 8 * (L + 1) * q * q);
  // The Dirichlet default is unchanged: no "area" functional in its report, and no quadrature
  // (its matrices are exact).
  const CmdResult d = run("solve " + write("dir.json", job(R"({"kind": "cmc", "H": 0})")).string() + " --out " +
                          (tmpdir() / "dir").string());
  ASSERT_EQ(d.status, 0) << d.err;
  const bpde::Json drep = bpde::read_json_file((tmpdir() / "dir" / "result.json").string())["report"];
  EXPECT_EQ(drep["functional"], "dirichlet");
  EXPECT_FALSE(drep.contains("quadrature"));
  const fs::path none = tmpdir() / "never";
  auto bad = [&](const std::string& j, const std::string& needle) {
    expect_bad_input("solve " + write("bad.json", j).string() + " --out " + none.string(), needle);
    EXPECT_FALSE(fs::exists(none));
  };
  bad(job(R"({"kind": "cmc", "H": 0, "functional": "areal"})"), "functional");
  bad(job(R"({"kind": "cmc", "H": 0, "functional": "area", "solver": "nlopt"})"), "nlopt");
  bad(job(R"({"kind": "cmc", "H": 0, "functional": "area"})", R"(, "fixed": "u-boundaries")"), "fixed");
  bad(job(R"({"kind": "cmc", "V": 1, "functional": "area", "solver": "nlopt"})"), "nlopt");
}

// Every cmc result carries its certificate (FORMATS.md, report.certificate): the largest |H(x) − H|
// over the report's samples, where, and relative to max(|H|, 1/R). The Fig. 1 circle at H = −0.5
// (the exact surface: the cap of the sphere of radius 2, height h = 2 − √3): the area functional at
// degree 8 is a CMC surface to 1e-4; the paper's D_H approximation at degree 6 is not (its mean
// curvature leaves H next to the corners), and says so.
TEST(Cli, CmcResultsCarryTheirCertificate) {
  auto solve = [](const std::string& name, const std::string& functional, int degree) {
    const std::string job = R"({"boundary": {"type": "triangular", "degree": )" + std::to_string(degree) +
                            R"(, "builder": "circle-three-arcs"}, "problem": {"kind": "cmc", "H": -0.5, "functional": ")" +
                            functional + R"("}})";
    const fs::path out = tmpdir() / name;
    const CmdResult r = run("solve " + write(name + ".json", job).string() + " --out " + out.string());
    EXPECT_EQ(r.status, 0) << r.err;
    return bpde::read_json_file((out / "result.json").string())["report"];
  };
  const double h = 2 - std::sqrt(3.0), R = 0.5 * std::sqrt(8 + h * h);  // half the cap's box diagonal
  for (const auto& [functional, degree] : {std::pair<std::string, int>{"area", 8}, {"dirichlet", 6}}) {
    const bpde::Json rep = solve("cert-" + functional, functional, degree);
    ASSERT_TRUE(rep.contains("certificate")) << rep.dump();
    const bpde::Json& c = rep["certificate"];
    const bpde::Json& mc = rep["mean_curvature"];
    const double H = -0.5, lo = mc["min"].get<double>(), hi = mc["max"].get<double>();
    const double dev = c["mean_curvature_deviation"].get<double>();
    EXPECT_DOUBLE_EQ(c["H"].get<double>(), H);
    EXPECT_DOUBLE_EQ(dev, std::max(H - lo, hi - H));
    EXPECT_EQ(c["at"], H - lo >= hi - H ? mc["at_min"] : mc["at_max"]);
    const double u = c["at"][0].get<double>(), v = c["at"][1].get<double>();
    EXPECT_TRUE(u >= 0 && v >= 0 && u + v <= 1 + 1e-12) << u << ", " << v;
    EXPECT_NEAR(c["reference_curvature"].get<double>(), 1 / R, 2e-3);  // 1/R > |H| here
    EXPECT_NEAR(c["relative_deviation"].get<double>(), dev / c["reference_curvature"].get<double>(), 1e-15);
    if (functional == "area") {
      EXPECT_LT(dev, 1e-4);
      EXPECT_TRUE(c["near_constant"].get<bool>());
    } else {
      EXPECT_GT(c["relative_deviation"].get<double>(), 0.05);
      EXPECT_FALSE(c["near_constant"].get<bool>());
    }
  }
}

// The mean-curvature functional as a job (FORMATS.md, "functional": "mean-curvature"): the Fig. 1
// circle from the boundary builder; converged at degree 10 (exit 0), not at degree 6 with the
// default tolerance (exit 1, result.json written with converged false), and the bad input.
TEST(Cli, CmcMeanCurvatureJob) {
  auto job = [](int degree, const std::string& problem) {
    return R"({"boundary": {"type": "triangular", "degree": )" + std::to_string(degree) +
           R"(, "builder": "circle-three-arcs"}, "problem": )" + problem + "}";
  };
  // `bpde solve` of the job text into tmpdir()/name: the exit status and the result's report.
  auto solve = [](const std::string& name, const std::string& text) {
    const fs::path out = tmpdir() / name;
    const CmdResult r = run("solve " + write(name + ".json", text).string() + " --out " + out.string());
    const bpde::Json rep =
        fs::exists(out / "result.json") ? bpde::read_json_file((out / "result.json").string())["report"] : bpde::Json();
    return std::make_pair(r, rep);
  };
  // The V form: the volume of the exact cap of H = -0.9 gives back H = -0.9 (the cap of radius
  // 1/0.9 and height h over the unit circle: V = πh²(3R − h)/3).
  {
    const double R = 1 / 0.9, h = R - std::sqrt(R * R - 1), V0 = std::numbers::pi * h * h * (3 * R - h) / 3;
    char problem[160];
    std::snprintf(problem, sizeof problem, R"({"kind": "cmc", "V": %.17g, "functional": "mean-curvature"})", V0);
    const auto [rv, repv] = solve("mcv", job(10, problem));
    ASSERT_EQ(rv.status, 0) << rv.err;
    EXPECT_EQ(repv["solver"], "newton");
    EXPECT_TRUE(repv["converged"].get<bool>());
    EXPECT_NEAR(repv["H"].get<double>(), -0.9, 1e-5);
    EXPECT_NEAR(repv["volume"].get<double>(), V0, 1e-12);
    // The area functional's V form on the same boundary (degree 10, the cap of H = -0.5). It starts
    // from the least-squares mean-curvature surface at v0 (mean-curvature-start,
    // docs/cmc_algorithm.md, "The routes").
    const double R2 = 2.0, h2 = R2 - std::sqrt(R2 * R2 - 1), V2 = std::numbers::pi * h2 * h2 * (3 * R2 - h2) / 3;
    std::snprintf(problem, sizeof problem, R"({"kind": "cmc", "V": %.17g, "functional": "area"})", V2);
    const auto [ra, repa] = solve("av", job(10, problem));
    ASSERT_EQ(ra.status, 0) << ra.err;
    EXPECT_TRUE(repa["converged"].get<bool>());
    // report.routes (FORMATS.md): the route kept is mean-curvature-start, converged
    auto kept_route = [](const bpde::Json& rep) {
      std::string kept;
      for (const auto& r : rep["routes"])
        if (r["kept"].get<bool>()) kept = r["route"].get<std::string>() + ":" + r["status"].get<std::string>();
      return kept;
    };
    EXPECT_EQ(kept_route(repa), "mean-curvature-start:converged") << repa["routes"];
    EXPECT_NEAR(repa["H"].get<double>(), -0.5, 1e-8);
    EXPECT_NEAR(repa["volume"].get<double>(), V2, 1e-11);
    // "start": "dirichlet": the routes from the minimiser of D alone, the same cap.
    std::snprintf(problem, sizeof problem, R"({"kind": "cmc", "V": %.17g, "functional": "area", "start": "dirichlet"})",
                  V2);
    const auto [rd, repd] = solve("avd", job(10, problem));
    ASSERT_EQ(rd.status, 0) << rd.err;
    EXPECT_EQ(kept_route(repd), "dirichlet-volume-start:converged") << repd["routes"];
    EXPECT_EQ(repd["routes"][0]["route"], "dirichlet-volume-start") << repd["routes"];  // mean-curvature-start not considered
    EXPECT_NEAR(repd["H"].get<double>(), -0.5, 1e-8);
    // The same by Ceres (the free points on the manifold V = v0).
    std::snprintf(problem, sizeof problem,
                  R"({"kind": "cmc", "V": %.17g, "functional": "mean-curvature", "solver": "ceres"})", V0);
    const auto [rc, repc] = solve("mcvc", job(10, problem));
    ASSERT_EQ(rc.status, 0) << rc.err;
    EXPECT_EQ(repc["solver"], "ceres");
    EXPECT_TRUE(repc["converged"].get<bool>());
    EXPECT_NEAR(repc["H"].get<double>(), -0.9, 1e-5);
    EXPECT_NEAR(repc["volume"].get<double>(), V0, 1e-12);
    // Past the hemisphere, by Ceres: the larger cap of H = -0.7 (V = 11.5). From the minimiser of D
    // at v0 the parametrisation folds and Ceres stops on a failed Plus of its gradient-norm test,
    // which it logs to stderr through glog ("E… Terminating: projected_gradient_step = …"); the
    // continuation in V reaches the cap. stderr holds nothing: the CLI turns Ceres's log off
    // (solvers/cmc/ceres_log.h).
    const double R3 = 1 / 0.7, h3 = R3 + std::sqrt(R3 * R3 - 1), V3 = std::numbers::pi * h3 * h3 * (3 * R3 - h3) / 3;
    std::snprintf(problem, sizeof problem,
                  R"({"kind": "cmc", "V": %.17g, "functional": "mean-curvature", "solver": "ceres"})", V3);
    const auto [rl, repl] = solve("mcvl", job(10, problem));
    ASSERT_EQ(rl.status, 0) << rl.err;
    EXPECT_EQ(rl.err, "");
    EXPECT_NE(repl["message"].get<std::string>().find("continued in V"), std::string::npos);
    EXPECT_NEAR(repl["H"].get<double>(), -0.7, 1e-6);
  }
  const auto [r, rep] = solve("mc", job(10, R"({"kind": "cmc", "H": -0.9, "functional": "mean-curvature"})"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(rep["functional"], "mean-curvature");
  EXPECT_TRUE(rep["converged"].get<bool>());
  EXPECT_LE(rep["residual"].get<double>(), 1e-6);
  EXPECT_EQ(rep["quadrature"]["grading"], 1);  // the plain rules, 6q² nodes on the triangle
  EXPECT_EQ(rep["quadrature"]["levels"], 0);
  EXPECT_EQ(rep["quadrature"]["nodes"].get<int>(),
            6 * rep["quadrature"]["points_per_direction"].get<int>() * rep["quadrature"]["points_per_direction"].get<int>());
  EXPECT_LE(std::abs(rep["mean_curvature"]["max"].get<double>() + 0.9), 5e-5);
  EXPECT_LE(std::abs(rep["mean_curvature"]["min"].get<double>() + 0.9), 5e-5);
  // Degree 6 misses the default tolerance 1e-6: exit 1, a result with converged false; its own
  // tolerance, given in the job, is met.
  const auto [r6, rep6] = solve("mc6", job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature"})"));
  EXPECT_EQ(r6.status, 1) << r6.err;
  EXPECT_FALSE(rep6["converged"].get<bool>());
  EXPECT_NE(rep6["message"].get<std::string>().find("degree is too low"), std::string::npos);
  const auto [r6t, rep6t] = solve("mc6t", job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature",
                                                   "mean_curvature_tolerance": 1e-3})"));
  EXPECT_EQ(r6t.status, 0) << r6t.err;
  EXPECT_TRUE(rep6t["converged"].get<bool>());
  const fs::path none = tmpdir() / "never";
  auto bad = [&](const std::string& j, const std::string& needle) {
    expect_bad_input("solve " + write("bad.json", j).string() + " --out " + none.string(), needle);
    EXPECT_FALSE(fs::exists(none));
  };
  bad(job(6, R"({"kind": "cmc", "V": 1, "functional": "mean-curvature", "solver": "nlopt"})"),
      "newton or the ceres solver");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature", "solver": "nlopt"})"), "newton or the ceres solver");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "area", "mean_curvature_tolerance": 1e-3})"),
      "mean_curvature_tolerance");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature", "start": "dirichlet"})"),
      "start: only with \"functional\": \"area\"");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "area", "start": "plane"})"),
      "unknown start \"plane\" (expected mean-curvature, dirichlet or minimal-surface)");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature", "mean_curvature_tolerance": 0})"),
      "mean_curvature_tolerance");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature", "mean_curvature_tolerance": "1e-3"})"),
      "mean_curvature_tolerance");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature", "mean_curvature_tolerance": 1})"),
      "mean_curvature_tolerance");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature", "solver": "foo"})"), "unknown solver");
  bad(job(6, R"({"kind": "cmc", "H": -0.5, "functional": "mean-curvature"}, "fixed": "u-boundaries")"), "fixed");
}
