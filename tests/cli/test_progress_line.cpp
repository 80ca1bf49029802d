// The progress line of `bpde` (app/progress_line.h) driven with a test clock: the four forms of
// the line, an estimate of the time left only for a stage of known length from kEtaFromFraction
// on (elapsed × (1 − f) / f), the redraw rate into a file, and a stage's clock kept while other
// stages report in between. And the lines `bpde solve --progress` writes: only those forms, the
// percentages of a stage never falling, every stage ended.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "app/progress_line.h"
#include "tests/cli/cli_run.h"

namespace bpde::app {
namespace {

using Clock = ProgressLine::Clock;
using std::chrono::milliseconds;

// The whole lines a ProgressLine writes into a file, after `drive` ran on it.
template <class F>
std::vector<std::string> lines_of(F drive) {
  std::FILE* f = std::tmpfile();
  {
    ProgressLine line(f, false);
    drive(line);
  }
  std::rewind(f);
  std::vector<std::string> out;
  char buf[512];
  while (std::fgets(buf, sizeof buf, f)) {
    std::string s(buf);
    if (!s.empty() && s.back() == '\n') s.pop_back();
    out.push_back(s);
  }
  std::fclose(f);
  return out;
}

TEST(ProgressLine, TextShowsAnEstimateOnlyForAKnownFractionFromTheThreshold) {
  EXPECT_EQ(progress_text("sampling", 0, 0, 3.2), "bpde: sampling, 3 s elapsed");   // unknown length
  EXPECT_EQ(progress_text("sampling", 5, 0, 3.2), "bpde: sampling, 3 s elapsed");   // still unknown
  EXPECT_EQ(progress_text("sampling", 0, 10, 3.2), "bpde: sampling, 3 s elapsed");  // nothing done yet
  EXPECT_EQ(progress_text("checking", 0.02, 1, 4), "bpde: checking 2%, 4 s elapsed");  // below the threshold
  // 25% after 10 s: 30 s left; 50% after 10 s: 10 s left
  EXPECT_EQ(progress_text("checking", 1, 4, 10), "bpde: checking 25%, 10 s elapsed, ~30 s left");
  EXPECT_EQ(progress_text("cmc continuation", 0.75, 1.5, 10), "bpde: cmc continuation 50%, 10 s elapsed, ~10 s left");
  EXPECT_EQ(progress_text("writing files", 8, 8, 7.25), "bpde: writing files done in 7.2 s");
  // at the threshold the estimate appears
  const std::string at = progress_text("x", kEtaFromFraction, 1, 1);
  EXPECT_NE(at.find("left"), std::string::npos) << at;
  EXPECT_EQ(progress_text("x", 0.999 * kEtaFromFraction, 1, 1).find("left"), std::string::npos);
  // the percentage is rounded down: 100% only at the end
  EXPECT_EQ(progress_text("x", 0.998, 1, 10), "bpde: x 99%, 10 s elapsed, ~0 s left");
}

TEST(ProgressLine, IntoAFileOneLinePerStageStartEndAndSecond) {
  const Clock::time_point t0 = Clock::now();
  const std::vector<std::string> lines = lines_of([&](ProgressLine& p) {
    p.update("checking", 0, 1, t0);
    for (int k = 1; k <= 30; ++k) p.update("checking", k / 40.0, 1, t0 + milliseconds(100 * k));  // 3 s, 10 a second
    p.update("checking", 1, 1, t0 + milliseconds(4000));
  });
  // the start, one line a second (at 1, 2 and 3 s), the end
  ASSERT_EQ(lines.size(), 5u) << ::testing::PrintToString(lines);
  EXPECT_EQ(lines[0], "bpde: checking, 0 s elapsed");
  EXPECT_EQ(lines[1], "bpde: checking 25%, 1 s elapsed, ~3 s left");  // 10/40 after 1 s
  EXPECT_EQ(lines[2], "bpde: checking 50%, 2 s elapsed, ~2 s left");
  EXPECT_EQ(lines[3], "bpde: checking 75%, 3 s elapsed, ~1 s left");
  EXPECT_EQ(lines[4], "bpde: checking done in 4.0 s");
}

TEST(ProgressLine, AStageKeepsItsClockWhileAnotherReportsInBetween) {
  const Clock::time_point t0 = Clock::now();
  const std::vector<std::string> lines = lines_of([&](ProgressLine& p) {
    p.update("cmc area", 0, 1, t0);
    p.update("cmc least squares", 0, 1, t0 + milliseconds(2000));
    p.update("cmc least squares", 1, 1, t0 + milliseconds(6000));
    p.update("cmc area", 0.5, 1, t0 + milliseconds(8000));  // 8 s into "cmc area", not 0
    p.update("cmc area", 1, 1, t0 + milliseconds(9000));
    p.update("cmc area", 0, 1, t0 + milliseconds(9500));  // again after its end: a new clock (not drawn:
    p.update("cmc area", 1, 1, t0 + milliseconds(10000));  // the same stage, within a second)
  });
  ASSERT_EQ(lines.size(), 6u) << ::testing::PrintToString(lines);
  EXPECT_EQ(lines[2], "bpde: cmc least squares done in 4.0 s");
  EXPECT_EQ(lines[3], "bpde: cmc area 50%, 8 s elapsed, ~8 s left");
  EXPECT_EQ(lines[4], "bpde: cmc area done in 9.0 s");
  EXPECT_EQ(lines[5], "bpde: cmc area done in 0.5 s");
}

// The stages in `err` (the lines of `bpde ... --progress`), each line one of the four forms, the
// percentages of a stage never falling from its start to its end, and each stage ended.
std::vector<std::string> checked_stages(const std::string& err) {
  const std::regex form(
      "bpde: (.+?)(?:, ([0-9]+) s elapsed| ([0-9]+)%, ([0-9]+) s elapsed(?:, ~([0-9]+) s left)?| done in [0-9]+\\.[0-9] s)");
  std::map<std::string, int> percent;  // per stage, the last percentage shown since its start
  std::map<std::string, bool> open;    // stages started and not ended
  std::vector<std::string> stages;
  std::istringstream lines(err);
  std::string line;
  while (std::getline(lines, line)) {
    std::smatch m;
    EXPECT_TRUE(std::regex_match(line, m, form)) << line;
    if (m.empty()) continue;
    const std::string stage = m[1];
    if (!open.count(stage)) stages.push_back(stage);
    if (line.find(" done in ") != std::string::npos) {
      open[stage] = false;
      percent.erase(stage);
      continue;
    }
    open[stage] = true;
    if (m[3].matched) {
      const int p = std::stoi(m[3]);
      EXPECT_GE(p, percent[stage]) << line;
      percent[stage] = p;
      // an estimate only from kEtaFromFraction on
      if (m[5].matched) {
        EXPECT_GE(p, static_cast<int>(100 * kEtaFromFraction) - 1) << line;
      }
    }
  }
  for (const auto& [stage, running] : open) {
    EXPECT_FALSE(running) << stage << " never ended\n" << err;
  }
  return stages;
}

bool has(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

TEST(ProgressLine, TheCommandsWriteOnlyTheFormsAndEndEveryStage) {
  using bpde::testing::run;
  using bpde::testing::tmpdir;
  const std::string src = BPDE_SOURCE_DIR;
  const std::string solved = (tmpdir() / "progress_forms").string();
  const bpde::testing::CmdResult r =
      run("solve " + src + "/examples/004-cmc-circle/circle_area.json --out " + solved + " -q --progress --samples 200");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> stages = checked_stages(r.err);
  for (const char* stage : {"cmc area", "sampling", "mean curvature", "checking (CGAL)", "writing files"}) {
    EXPECT_TRUE(has(stages, stage)) << stage << "\n" << r.err;
  }
  // view and blend sample with progress too
  const bpde::testing::CmdResult v = run("view " + solved + " -q --progress");
  ASSERT_EQ(v.status, 0) << v.err;
  EXPECT_TRUE(has(checked_stages(v.err), "sampling")) << v.err;
  const bpde::testing::CmdResult b = run("blend " + src + "/examples/003-blend-cylinders/fig2a.json --out " +
                                         (tmpdir() / "progress_blend").string() + " --progress");
  ASSERT_EQ(b.status, 0) << b.err;
  const std::vector<std::string> blend = checked_stages(b.err);
  for (const char* stage : {"sampling", "checking (CGAL)", "writing files"}) {
    EXPECT_TRUE(has(blend, stage)) << stage << "\n" << b.err;
  }
}

}  // namespace
}  // namespace bpde::app
