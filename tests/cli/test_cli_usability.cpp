// The command as a new user meets it (it behaves like the tools users know):
// --version, bare `bpde`, the summary of `bpde solve`, --quiet and --samples, result.json as a
// net input, and a file given to the wrong subcommand.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

const std::string kSource = BPDE_SOURCE_DIR;
const std::string kPdeJob = kSource + "/examples/001-pde-figures/fig1-biharmonic.json";
const std::string kBlend = kSource + "/examples/003-blend-cylinders/fig2a.json";
const std::string kFold = kSource + "/examples/004-cmc-circle/n6-H-1.5-past-fold.json";

// The count of `v ` lines of an OBJ file.
long vertices(const fs::path& obj) {
  std::ifstream in(obj);
  long n = 0;
  for (std::string line; std::getline(in, line);) n += line.rfind("v ", 0) == 0;
  return n;
}

void expect_one_error_line(const CmdResult& r, const std::string& needle) {
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << "should mention '" << needle << "': " << r.err;
}

}  // namespace

TEST(CliUsability, VersionIsTheProjectVersionOfCMakeLists) {
  std::smatch m;
  const std::string cmake = slurp(kSource + "/CMakeLists.txt");
  ASSERT_TRUE(std::regex_search(cmake, m, std::regex(R"(project\(bezierpde VERSION ([0-9.]+))")));
  for (const char* flag : {"--version", "-V"}) {
    const CmdResult r = run(flag);
    EXPECT_EQ(r.status, 0) << flag << r.err;
    EXPECT_EQ(r.out, "bpde " + m[1].str() + "\n") << flag;
    EXPECT_EQ(r.err, "");
  }
}

TEST(CliUsability, BareCommandPrintsTheUsageAndExitsZero) {
  const CmdResult r = run("");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("Usage: bpde"), std::string::npos) << r.out;
  for (const char* sub : {"solve", "sample", "energy", "check", "plate", "blend", "demo"})
    EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
  EXPECT_EQ(r.out, run("--help").out);  // the same text as --help
}

TEST(CliUsability, SolvePrintsASummaryUnlessQuiet) {
  const fs::path out = tmpdir() / "summary";
  const CmdResult r = run("solve " + kPdeJob + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  for (const std::string& needle : std::vector<std::string>{
           "problem             pde (biharmonic, method explicit) on a tensor net of degree [5, 5]",
           "converged           yes", "energy              174.55", "pde residual", "mean curvature      min ",
           "self-intersections  0", "files               " + out.string() + "/{result.json"})
    EXPECT_NE(r.out.find(needle), std::string::npos) << needle << "\n" << r.out;
  EXPECT_LE(std::count(r.out.begin(), r.out.end(), '\n'), 24) << "one screen";

  const CmdResult q = run("solve " + kPdeJob + " --out " + (tmpdir() / "quiet").string() + " --quiet");
  EXPECT_EQ(q.status, 0) << q.err;
  EXPECT_EQ(q.out, "");
  EXPECT_EQ(q.err, "");
  EXPECT_TRUE(fs::exists(tmpdir() / "quiet" / "result.json"));
}

TEST(CliUsability, SolveWithoutSolutionSaysWhyInTheSummary) {
  const CmdResult r = run("solve " + kFold + " --out " + (tmpdir() / "fold").string());
  ASSERT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.out.find("converged           no"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("not converged       no critical point on the branch"), std::string::npos) << r.out;
}

// The same job with the area functional: the caps over the unit circle exist for |H| ≤ 1 only
// (the hemisphere at H = −1 is the fold of their branch), so H = −1.5 has no solution: exit 1,
// `converged: false`, and the message says where the branch of A_H critical points ends.
TEST(CliUsability, AreaJobPastTheFoldExitsOneAndNamesTheFold) {
  std::string job = slurp(kFold);
  const auto at = job.find("\"solver\": \"newton\"");
  ASSERT_NE(at, std::string::npos);
  job.insert(at, "\"functional\": \"area\", ");
  const fs::path out = tmpdir() / "area_fold";
  const CmdResult r = run("solve " + write("area_fold.json", job).string() + " --out " + out.string());
  ASSERT_EQ(r.status, 1) << r.err;
  const std::string res = slurp((out / "result.json").string());
  EXPECT_NE(res.find("\"converged\": false"), std::string::npos);
  EXPECT_NE(res.find("\"functional\": \"area\""), std::string::npos);
  const std::smatch m = [&] {
    std::smatch mm;
    std::regex_search(res, mm, std::regex("no critical point of A_H on the branch from H = 0 beyond H ≈ (-?[0-9.e+-]+)"));
    return mm;
  }();
  ASSERT_EQ(m.size(), 2u) << res.substr(0, 600);
  EXPECT_NEAR(std::stod(m[1].str()), -1.0, 1e-3) << m[0];  // measured -0.999996
}

TEST(CliUsability, SolveSamplesOverridesTheJobAndIsValidated) {
  const fs::path out = tmpdir() / "samples";
  ASSERT_EQ(run("solve " + kPdeJob + " --out " + out.string() + " -q --samples 4").status, 0);
  EXPECT_EQ(vertices(out / "surface.obj"), 5 * 5);  // tensor: (N + 1)^2 vertices; the job says 50
  for (const char* bad : {"0", "2001", "-3"}) {
    const fs::path o = tmpdir() / (std::string("samples_bad") + bad);
    expect_one_error_line(run("solve " + kPdeJob + " --out " + o.string() + " --samples " + bad), "--samples");
    EXPECT_FALSE(fs::exists(o)) << bad;
  }
}

TEST(CliUsability, SampleAndCheckTakeTheResultBpdeWrote) {
  const fs::path solved = tmpdir() / "solved";
  ASSERT_EQ(run("solve " + kPdeJob + " --out " + solved.string() + " -q --samples 30").status, 0);
  const std::string result = (solved / "result.json").string();
  const fs::path resampled = tmpdir() / "resampled";
  const CmdResult s = run("sample " + result + " --out " + resampled.string() + " --samples 30");
  ASSERT_EQ(s.status, 0) << s.err;
  // The same net sampled the same way: the same surface as solve wrote.
  EXPECT_TRUE(slurp(resampled / "surface.obj") == slurp(solved / "surface.obj"));
  EXPECT_EQ(vertices(resampled / "surface.obj"), 31 * 31);
  const CmdResult c = run("check " + result + " --samples 10");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.out.find("\"self_intersections\":0"), std::string::npos) << c.out;
  const CmdResult e = run("energy " + result + " --energy biharmonic");
  ASSERT_EQ(e.status, 0) << e.err;
  EXPECT_NEAR(std::stod(e.out.substr(e.out.find(':') + 1)), 174.55115678, 1e-6) << e.out;
  // A result whose net is broken is still reported at its JSON path.
  const fs::path broken = write("broken_result.json", R"({"net": {"type": "tensor"}, "report": {}})");
  expect_one_error_line(run("check " + broken.string()), "broken_result.json.net: missing field \"degree\"");
}

TEST(CliUsability, AFileGivenToTheWrongSubcommandNamesTheRightOne) {
  const fs::path o = tmpdir() / "wrong";
  expect_one_error_line(run("solve " + kBlend + " --out " + o.string()), "this is a blend config: use `bpde blend`");
  expect_one_error_line(run("blend " + kPdeJob + " --out " + o.string()), "this is a job: use `bpde solve`");
  expect_one_error_line(run("check " + kPdeJob), "this is a job, not a net: use `bpde solve`");
  expect_one_error_line(run("sample " + kBlend + " --out " + o.string()), "use `bpde blend`");
  const fs::path net = write("plain_net.json", R"({"type": "tensor", "degree": [1, 1],
      "points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]})");
  expect_one_error_line(run("solve " + net.string() + " --out " + o.string()), "this is a net, not a job");
  EXPECT_FALSE(fs::exists(o));
  // Files that are none of these keep the strict readers' messages.
  const fs::path odd = write("odd_job.json", R"({"nett": 1})");
  expect_one_error_line(run("solve " + odd.string() + " --out " + o.string()), "unknown field \"nett\"");
}

TEST(CliUsability, ProgressGoesToStderrWhenForcedAndNothingOtherwise) {
  const std::string cmc = kSource + "/examples/004-cmc-circle/n4-b-H-1.json";
  const CmdResult p = run("solve " + cmc + " --out " + (tmpdir() / "progress").string() + " -q --progress");
  ASSERT_EQ(p.status, 0) << p.err;
  EXPECT_EQ(p.out, "");  // progress never goes to stdout
  for (const char* stage :
       {"bpde: cmc continuation", "bpde: sampling", "bpde: checking (CGAL) done in", "bpde: writing files done in"})
    EXPECT_NE(p.err.find(stage), std::string::npos) << stage << "\n" << p.err;
  EXPECT_EQ(p.err.find('\r'), std::string::npos) << "whole lines, not a terminal line";
  // stderr is not a terminal here: without --progress, nothing on stderr on success.
  const CmdResult q = run("solve " + cmc + " --out " + (tmpdir() / "no_progress").string());
  ASSERT_EQ(q.status, 0) << q.err;
  EXPECT_EQ(q.err, "");
  const std::string result = (tmpdir() / "progress" / "result.json").string();
  const CmdResult c = run("check " + result + " --progress");
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_NE(c.err.find("bpde: sampling"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("bpde: checking (CGAL) done in"), std::string::npos) << c.err;
  EXPECT_EQ(run("check " + result).err, "");
  EXPECT_EQ(run("sample " + result + " --out " + (tmpdir() / "resample").string()).err, "");
  // A bad input with --progress still ends in exactly one error line.
  const CmdResult bad = run("solve " + kBlend + " --out " + (tmpdir() / "p_bad").string() + " --progress");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
}

// Every command that writes files prints them, one `files` line, as `bpde solve` does (every file
// it wrote, no other), and --quiet prints nothing.
TEST(CliUsability, WritingCommandsPrintTheFilesTheyWroteUnlessQuiet) {
  using bpde::testing::printed_files;
  // the names in a folder, and the printed paths' names (each of them a file that exists)
  auto listing = [](const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  };
  auto printed = [](const CmdResult& r, const fs::path& dir) {
    std::vector<std::string> names;
    for (const fs::path& p : printed_files(r.out)) {
      EXPECT_TRUE(fs::is_regular_file(p)) << p << "\n" << r.out;
      EXPECT_EQ(p.parent_path(), dir) << p;
      names.push_back(p.filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
  };
  std::string job = slurp(kPdeJob);
  job = job.substr(0, job.rfind('}')) + R"(, "export": ["step", "html"]})";
  const fs::path job_path = write("files_job.json", job), solved = tmpdir() / "files_solve";
  CmdResult r = run("solve " + job_path.string() + " --out " + solved.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(printed(r, solved), listing(solved)) << r.out;
  EXPECT_EQ(listing(solved).size(), 7u);  // result.json, 3 surfaces, net.obj, surface.step, view.html

  const fs::path sampled = tmpdir() / "files_sample";
  r = run("sample " + (solved / "result.json").string() + " --samples 5 --out " + sampled.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(printed(r, sampled), listing(sampled)) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;

  fs::remove(solved / "view.html");
  r = run("view " + solved.string() + " --samples 5");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(printed(r, solved), std::vector<std::string>{"view.html"}) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;

  const fs::path net = write("files_net.json", R"({"type": "tensor", "degree": [1, 1], )"
                                               R"("points": [[0,0,0],[0,1,0],[1,0,0],[1,1,1]]})");
  const fs::path step = tmpdir() / "files_export" / "net.step";
  fs::create_directories(step.parent_path());
  r = run("export " + net.string() + " --step " + step.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(printed(r, step.parent_path()), std::vector<std::string>{"net.step"}) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;

  // --quiet (and -q): nothing on stdout, the same files written
  for (const std::string& cmd : {"sample " + net.string() + " --samples 3 --quiet --out " +
                                     (tmpdir() / "files_quiet").string(),
                                 "view " + solved.string() + " -q --samples 3",
                                 "export " + net.string() + " --quiet --step " + (tmpdir() / "quiet.step").string()}) {
    r = run(cmd);
    EXPECT_EQ(r.status, 0) << cmd << "\n" << r.err;
    EXPECT_EQ(r.out, "") << cmd;
    EXPECT_EQ(r.err, "") << cmd;
  }
  EXPECT_EQ(listing(tmpdir() / "files_quiet").size(), 4u);
  EXPECT_TRUE(fs::is_regular_file(tmpdir() / "quiet.step"));
}
