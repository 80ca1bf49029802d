// Jobs whose boundary is a patch complex (FORMATS.md "Patch complexes"), through the bpde command:
// results, files and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>

#include "bezierpde/io/json_io.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using bpde::Json;
using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

const std::string kDirichlet = R"("problem": {"kind": "extremal", "energy": {"name": "dirichlet"}})";

/// The regular k-gon on the unit circle at height z as a loop of segments (JSON), counter-clockwise
/// about +z, or clockwise when `reverse`.
std::string polygon_loop(int k, double z = 0, bool reverse = false) {
  std::string s = "[";
  for (int i = 0; i < k; ++i) {
    int a = i, b = i + 1;
    if (reverse) a = k - i, b = k - i - 1;
    auto pt = [&](int j) {
      const double t = 2 * std::numbers::pi * j / k;
      std::string p = "[";
      p += std::to_string(std::cos(t));
      p += ", ";
      p += std::to_string(std::sin(t));
      p += ", ";
      p += std::to_string(z);
      return p + "]";
    };
    s += std::string(i ? ", " : "") + R"({"type": "segment", "from": )" + pt(a % k) + R"(, "to": )" +
         pt(b % k) + "}";
  }
  return s + "]";
}

Json solve(const std::string& name, const std::string& text, int expected = 0) {
  const fs::path job = write(name + ".json", text), out = tmpdir() / ("out_" + name);
  const CmdResult r = run("solve " + job.string() + " --out " + out.string() + " --quiet");
  EXPECT_EQ(r.status, expected) << r.err;
  return bpde::read_json_file((out / "result.json").string());
}

void expect_refused(const std::string& name, const std::string& text) {
  SCOPED_TRACE(name);
  const fs::path job = write(name + ".json", text), out = tmpdir() / ("never_" + name);
  const CmdResult r = run("solve " + job.string() + " --out " + out.string());
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace

TEST(ComplexJobs, PentagonRefinedOnceIsAPlanarComplexOfTwentyTriangles) {
  const Json r = solve("pentagon", R"({"boundary": {"type": "complex", "patch": "triangular", "degree": 4,
      "refine": 1, "loops": [)" + polygon_loop(5) + "]}, " + kDirichlet + R"(, "samples": 6})");
  EXPECT_EQ(r["net"]["type"], "complex");
  EXPECT_EQ(r["net"]["patches"].size(), 20u);
  EXPECT_EQ(r["net"]["patches"][0]["type"], "triangular");
  EXPECT_EQ(r["net"]["layout"]["faces"].size(), 5u);
  EXPECT_EQ(r["net"]["layout"]["boundary"].size(), 5u);
  const Json& rep = r["report"];
  EXPECT_TRUE(rep["converged"].get<bool>());
  EXPECT_EQ(rep["patches"], 20);
  EXPECT_EQ(rep["refine"], 1);
  EXPECT_NEAR(rep["area"].get<double>(), 2.5 * std::sin(2 * std::numbers::pi / 5), 1e-5);  // polygon_loop prints 6 digits
  EXPECT_LT(rep["seam_angle_max"].get<double>(), 1e-9);
  EXPECT_NEAR(rep["volume"].get<double>(), 0.0, 1e-12);
  EXPECT_EQ(rep["check"]["self_intersections"], 0);
  EXPECT_EQ(rep["boundary_fit"].size(), 5u);
  const std::string vtp = slurp(tmpdir() / "out_pentagon" / "surface.vtp");
  EXPECT_NE(vtp.find("<CellData Scalars=\"patch\">"), std::string::npos);
  // the welded OBJ: each of the 20 patches' 6² triangles once
  const std::string obj = slurp(tmpdir() / "out_pentagon" / "surface.obj");
  std::size_t faces = 0;
  for (std::size_t at = obj.find("\nf "); at != std::string::npos; at = obj.find("\nf ", at + 1)) ++faces;
  EXPECT_EQ(faces, 20u * 36u);
}

TEST(ComplexJobs, CircleAndClosedSamplesAndAnnulusSolve) {
  const Json circle = solve("circle", R"({"boundary": {"type": "complex", "patch": "tensor", "degree": 8,
      "loops": [[{"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]}, )" + kDirichlet + "}");
  EXPECT_EQ(circle["report"]["patches"], 5);
  EXPECT_NEAR(circle["report"]["area"].get<double>(), std::numbers::pi, 1e-6);  // quarter arcs at n = 8
  std::string samples = "[";
  for (int k = 0; k < 64; ++k) {
    const double t = 2 * std::numbers::pi * k / 64;
    samples += std::string(k ? ", " : "") + "[" + std::to_string(std::cos(t)) + ", " + std::to_string(std::sin(t)) + ", 0]";
  }
  samples += "]";
  const Json closed = solve("closed_samples", R"({"boundary": {"type": "complex", "patch": "triangular", "degree": 4,
      "loops": [[{"type": "samples", "points": )" + samples + R"(, "closed": true}]]}, )" + kDirichlet + "}");
  EXPECT_EQ(closed["report"]["patches"], 6);
  EXPECT_NEAR(closed["report"]["area"].get<double>(), std::numbers::pi, 5e-3);
  const Json tube = solve("annulus", R"({"boundary": {"type": "complex", "patch": "tensor", "degree": 6,
      "loops": [[{"type": "circle", "center": [0, 0, 0.5], "normal": [0, 0, 1], "radius": 1}],
                [{"type": "circle", "center": [0, 0, -0.5], "normal": [0, 0, -1], "radius": 1}]]}, )" +
                                                  kDirichlet + "}");
  EXPECT_EQ(tube["report"]["patches"], 4);
  // a tube between the two circles, narrower than the cylinder (area 2π) but not by half
  EXPECT_LT(tube["report"]["area"].get<double>(), 2 * std::numbers::pi);
  EXPECT_GT(tube["report"]["area"].get<double>(), std::numbers::pi);
}

TEST(ComplexJobs, UserLayoutJobSolves) {
  const Json r = solve("user_layout", R"({"boundary": {"type": "complex", "patch": "tensor", "degree": 3,
      "loops": [[{"type": "segment", "from": [0,0,0], "to": [2,0,0]}, {"type": "segment", "from": [2,0,0], "to": [2,2,0]},
                 {"type": "segment", "from": [2,2,0], "to": [0,2,0]}, {"type": "segment", "from": [0,2,0], "to": [0,0,0]}]],
      "layout": {"vertices": [[0,0,0],[0,0,0],[0,0,0],[0,0,0],[1.2,0.9,0.3],[0,0,0],[0,0,0],[0,0,0],[0,0,0]],
        "faces": [[0,3,4,1],[3,6,7,4],[4,7,8,5],[1,4,5,2]],
        "boundary": [{"from": 0, "to": 3, "loop": 0, "curve": 0, "range": [0, 0.5]},
                     {"from": 3, "to": 6, "loop": 0, "curve": 0, "range": [0.5, 1]},
                     {"from": 6, "to": 7, "loop": 0, "curve": 1, "range": [0, 0.5]},
                     {"from": 7, "to": 8, "loop": 0, "curve": 1, "range": [0.5, 1]},
                     {"from": 8, "to": 5, "loop": 0, "curve": 2, "range": [0, 0.5]},
                     {"from": 5, "to": 2, "loop": 0, "curve": 2, "range": [0.5, 1]},
                     {"from": 2, "to": 1, "loop": 0, "curve": 3, "range": [0, 0.5]},
                     {"from": 1, "to": 0, "loop": 0, "curve": 3, "range": [0.5, 1]}]}}, )" + kDirichlet + "}");
  EXPECT_EQ(r["report"]["patches"], 4);
  EXPECT_NEAR(r["report"]["area"].get<double>(), 4.0, 1e-12);
  EXPECT_LT(r["report"]["seam_angle_max"].get<double>(), 1e-9);
}

TEST(ComplexJobs, BadInputExitsTwoWithOneLineAndNoFiles) {
  auto job = [&](const std::string& boundary_extra, const std::string& loops, const std::string& rest = kDirichlet) {
    return R"({"boundary": {"type": "complex", "patch": "triangular", "degree": 4)" + boundary_extra +
           R"(, "loops": [)" + loops + "]}, " + rest + "}";
  };
  const std::string pentagon = polygon_loop(5);
  expect_refused("refine_past_limit", job(R"(, "refine": 6)", pentagon));
  expect_refused("too_many_patches", job(R"(, "refine": 5)", pentagon));  // 5 · 4⁵ = 5120 > 4096
  expect_refused("degree_past_limit", job("", pentagon).replace(job("", pentagon).find("\"degree\": 4"), 11, "\"degree\": 21"));
  expect_refused("gram_past_limit", job(R"(, "refine": 4)", pentagon).replace(job("", pentagon).find("\"degree\": 4"), 11, "\"degree\": 20"));
  expect_refused("samples_past_limit", job(R"(, "refine": 3)", pentagon, kDirichlet + R"(, "samples": 1000)"));
  expect_refused("open_loop", job("", R"([{"type": "segment", "from": [0,0,0], "to": [1,0,0]},
                                         {"type": "segment", "from": [1,0,0], "to": [0,1,0]}])"));
  expect_refused("out_of_order", job("", R"([{"type": "segment", "from": [0,0,0], "to": [1,0,0]},
                                            {"type": "segment", "from": [0,1,0], "to": [0,0,0]},
                                            {"type": "segment", "from": [1,0,0], "to": [0,1,0]}])"));
  expect_refused("three_loops", job("", pentagon + ", " + polygon_loop(5, 1) + ", " + polygon_loop(5, 2)));
  expect_refused("cmc_mean_curvature_ceres",
                 job("", pentagon,
                     R"("problem": {"kind": "cmc", "H": 0.5, "functional": "mean-curvature", "solver": "ceres"})"));
  expect_refused("export_unknown", job("", pentagon, kDirichlet + R"(, "export": ["stl"])"));
  expect_refused("unknown_patch", job("", pentagon).replace(job("", pentagon).find("triangular"), 10, "hexagonal"));
  expect_refused("circle_without_radius", job("", R"([{"type": "circle", "center": [0,0,0], "normal": [0,0,1]}])"));
  expect_refused("layout_mismatch",
                 job(R"(, "layout": {"vertices": [[0,0,0],[1,0,0],[0,1,0]], "faces": [[0,1,2]],
                        "boundary": [{"from": 0, "to": 1, "loop": 0, "curve": 0}]})",
                     R"([{"type": "segment", "from": [0,0,0], "to": [1,0,0]}, {"type": "segment", "from": [1,0,0], "to": [0,1,0]},
                         {"type": "segment", "from": [0,1,0], "to": [0,0,0]}])"));
}

TEST(ComplexJobs, SweepOverDegreeAndRefinement) {
  const std::string base = R"({"boundary": {"type": "complex", "patch": "triangular", "degree": 3, "loops": [)" +
                           polygon_loop(5) + "]}, " + kDirichlet + R"(, "samples": 4})";
  const fs::path sweep = write("complex_sweep.json", R"({"base": )" + base +
                                                         R"(, "axes": {"boundary.degree": [3, 5], "boundary.refine": [0, 1]}})");
  const fs::path out = tmpdir() / "complex_sweep_out";
  const CmdResult r = run("sweep " + sweep.string() + " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<double> energy;
  for (int k = 0; k < 4; ++k) {
    char id[16];
    std::snprintf(id, sizeof id, "job-%04d", k);
    const Json res = bpde::read_json_file((out / "jobs" / id / "result.json").string());
    EXPECT_EQ(res["net"]["type"], "complex");
    energy.push_back(res["report"]["energy"].get<double>());
  }
  // rows: (3, 0), (3, 1), (5, 0), (5, 1): the spaces of a row's refinement and of the higher degree
  // (with the same exact segment boundary) contain the coarser ones, so the minimum falls
  EXPECT_LT(energy[1], energy[0]);
  EXPECT_LT(energy[2], energy[0]);
  EXPECT_LT(energy[3], energy[2]);
}

// The cmc problem on a complex (FORMATS.md "Patch complexes"): the spherical cap of radius 2 over
// the unit circle given as one circle curve, |H| = 0.5, by the area functional on the automatic
// fan of 6 triangular patches at degree 4: A = 3.36714885790773 and V = 0.430966541037603
// (exact), the certificate near constant, the seams nearly tangent.
TEST(ComplexJobs, CmcCapFromOneCircleMatchesTheExactCap) {
  const fs::path out = tmpdir() / "complex_cap";
  const CmdResult r = run("solve " +
                          write("complex_cap.json",
                                R"({"boundary": {"type": "complex", "patch": "triangular", "degree": 4, "loops": [[)"
                                R"({"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]},)"
                                R"( "problem": {"kind": "cmc", "H": -0.5, "functional": "area"}})")
                              .string() +
                          " --out " + out.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const Json rep = bpde::read_json_file((out / "result.json").string())["report"];
  EXPECT_EQ(rep["patches"], 6);
  EXPECT_NEAR(rep["area"].get<double>(), 3.36714885790773, 1e-7);
  EXPECT_NEAR(rep["volume"].get<double>(), 0.430966541037603, 1e-7);
  EXPECT_LT(rep["seam_angle_max"].get<double>(), 0.01);  // degrees
  ASSERT_TRUE(rep.contains("certificate")) << rep.dump();
  EXPECT_TRUE(rep["certificate"]["near_constant"].get<bool>());
  EXPECT_LT(rep["certificate"]["mean_curvature_deviation"].get<double>(), 1e-3);
}
