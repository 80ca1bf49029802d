// Every example input of examples/ (jobs and blend configs) and the demo, run through the `bpde`
// binary: an answer reported as converged never carries a non-finite number, neither in
// result.json (where nlohmann writes NaN and infinities as null) nor in the surface files.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;
using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;

namespace {

// The numbers of a JSON value; `nulls` counts nulls (how a non-finite double is written).
void numbers(const nlohmann::json& j, std::vector<double>& out, int& nulls) {
  if (j.is_number()) out.push_back(j.get<double>());
  if (j.is_null()) ++nulls;
  if (j.is_structured())
    for (const auto& v : j) numbers(v, out, nulls);
}

// Every number on the `v` lines of an OBJ file, or on the vertex lines of an ASCII PLY file (the
// lines between end_header and the faces): strtod reads "nan" and "inf" as non-finite.
std::vector<double> vertex_numbers(const fs::path& p, bool ply) {
  std::ifstream in(p);
  std::vector<double> out;
  std::string line;
  long vertices = -1, seen = 0;
  bool body = !ply;
  while (std::getline(in, line)) {
    if (ply && !body) {
      if (line.rfind("element vertex ", 0) == 0) vertices = std::stol(line.substr(15));
      if (line == "end_header") body = true;
      continue;
    }
    if (!ply && line.rfind("v ", 0) != 0) continue;
    if (ply && seen++ >= vertices) break;
    std::istringstream s(line.substr(ply ? 0 : 2));
    std::string tok;
    while (s >> tok) out.push_back(std::strtod(tok.c_str(), nullptr));
  }
  return out;
}

void expect_finite_outputs(const fs::path& out, const std::string& what) {
  const auto result = nlohmann::json::parse(slurp(out / "result.json"));
  const auto& report = result["report"];
  if (!report["converged"].get<bool>()) return;
  std::vector<double> xs;
  int nulls = 0;
  numbers(result["net"], xs, nulls);
  EXPECT_EQ(nulls, 0) << what << ": a null in the converged net";
  // The report's own numbers: the figures that may legitimately be null (no sample away from
  // the corners, an open surface's volume) are not solver output.
  // (The C1 problems have no energy: their "energy" is null by design, not a non-finite value.)
  const std::string problem = report.value("problem", "");
  const bool no_energy = problem == "tetraharmonic" || problem == "biharmonic-load";
  for (const char* k : {"energy", "D", "volume", "H", "residual", "pde_residual", "data_misfit", "L_energy",
                        "max_data_error", "center_deflection"})
    if (report.contains(k) && !(no_energy && std::string(k) == "energy")) {
      EXPECT_TRUE(report[k].is_number()) << what << ": report." << k << " = " << report[k];
    }
  numbers(report, xs, nulls);
  for (const char* f : {"surface.obj", "net.obj"}) {
    const auto v = vertex_numbers(out / f, false);
    EXPECT_FALSE(v.empty()) << what << ": " << f;
    xs.insert(xs.end(), v.begin(), v.end());
  }
  const auto v = vertex_numbers(out / "surface.ply", true);
  EXPECT_FALSE(v.empty()) << what << ": surface.ply";
  xs.insert(xs.end(), v.begin(), v.end());
  for (double x : xs) ASSERT_TRUE(std::isfinite(x)) << what << ": a non-finite number in a converged answer";
}

}  // namespace

TEST(ExamplesFinite, NoConvergedAnswerHasANonFiniteNumber) {
  int ran = 0;
  for (const auto& e : fs::recursive_directory_iterator(fs::path(BPDE_SOURCE_DIR) / "examples")) {
    if (e.path().extension() != ".json") continue;
    const auto input = nlohmann::json::parse(slurp(e.path()));
    if (input.is_object() && input.contains("axes")) continue;  // a sweep: its jobs are examples' jobs
    const bool blend = input.is_object() && input.value("kind", "") == "blend";
    const fs::path out = tmpdir() / ("example_" + e.path().parent_path().filename().string() + "_" +
                                     e.path().stem().string());
    const CmdResult r = run(std::string(blend ? "blend " : "solve ") + e.path().string() + " --out " + out.string());
    const std::string what = e.path().lexically_relative(BPDE_SOURCE_DIR).string();
    ASSERT_TRUE(r.status == 0 || r.status == 1) << what << ": exit " << r.status << " " << r.err;
    EXPECT_EQ(r.status == 0, nlohmann::json::parse(slurp(out / "result.json"))["report"]["converged"].get<bool>())
        << what;
    expect_finite_outputs(out, what);
    ++ran;
  }
  EXPECT_GE(ran, 40);
  const fs::path demo = tmpdir() / "example_demo";
  const CmdResult d = run("demo --out " + demo.string());
  ASSERT_EQ(d.status, 0) << d.err;
  expect_finite_outputs(demo, "demo");
}
