// The annulus's inner-loop orientation through the bpde command (FORMATS.md "Patch complexes"):
// the catenoid job of examples/005-complex-exact with its inner circle the other way round (normal
// −z) solves; the same way round (normal +z) is refused with exit 2, one line, no files.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "bezierpde/io/json_io.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

bpde::Json catenoid_job() {
  bpde::Json j = bpde::read_json_file(std::string(BPDE_SOURCE_DIR) + "/examples/005-complex-exact/catenoid.json");
  j["boundary"]["degree"] = 4;
  j["samples"] = 4;
  return j;
}

}  // namespace

TEST(ComplexLoopOrientation, InnerLoopTheOtherWayRoundSolvesTheSameWayIsRefused) {
  using namespace bpde::testing;
  bpde::Json j = catenoid_job();
  ASSERT_EQ(j["boundary"]["loops"][1][0]["normal"][2].get<double>(), -1.0);
  const fs::path good = tmpdir() / "orientation_opposite";
  const CmdResult ok = run("solve " + write("orientation_opposite.json", j.dump()).string() + " --out " + good.string() + " --quiet");
  ASSERT_EQ(ok.status, 0) << ok.err;
  const bpde::Json rep = bpde::read_json_file((good / "result.json").string())["report"];
  EXPECT_NEAR(rep["area"].get<double>(), 5.99179697580228, 1e-6);  // degree 4: 6e-8 measured
  EXPECT_LT(rep["seam_angle_max"].get<double>(), 0.1);

  j["boundary"]["loops"][1][0]["normal"] = bpde::Json::array({0, 0, 1});
  const fs::path bad = tmpdir() / "orientation_same";
  const CmdResult refused = run("solve " + write("orientation_same.json", j.dump()).string() + " --out " + bad.string());
  EXPECT_EQ(refused.status, 2) << refused.err;
  EXPECT_EQ(refused.err.rfind("error: ", 0), 0u) << refused.err;
  EXPECT_EQ(std::count(refused.err.begin(), refused.err.end(), '\n'), 1) << refused.err;
  EXPECT_FALSE(fs::exists(bad));
}
