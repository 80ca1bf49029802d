// Complex jobs through the bpde command: the certificate located on the surface, the boundary
// error, and the refinement rounds of a `tolerance` (FORMATS.md "Patch complexes").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "bezierpde/io/json_io.h"
#include "bezierpde/triangular/triangular_net.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using bpde::Json;
using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::tmpdir;
using bpde::testing::write;

const std::string kCircle = R"({"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1})";

/// A complex job over the unit circle (one `circle` curve) on the automatic triangular fan.
std::string circle_job(int degree, const std::string& problem, const std::string& extra = "") {
  return R"({"boundary": {"type": "complex", "patch": "triangular", "degree": )" + std::to_string(degree) +
         R"(, "loops": [[)" + kCircle + "]]}, " + problem + extra + "}";
}

const std::string kAreaCap = R"("problem": {"kind": "cmc", "H": -0.5, "functional": "area"})";
const std::string kDirichletCap = R"("problem": {"kind": "cmc", "H": -0.5, "functional": "dirichlet"})";
const std::string kExtremal = R"("problem": {"kind": "extremal", "energy": {"name": "dirichlet"}})";

struct Solved {
  int status = -1;
  Json result;
  std::string out;  // stdout (the summary)
};

Solved solve(const std::string& name, const std::string& text, bool quiet = true) {
  const fs::path job = write(name + ".json", text), out = tmpdir() / ("out_" + name);
  const CmdResult r = run("solve " + job.string() + " --out " + out.string() + (quiet ? " --quiet" : ""));
  Solved s;
  s.status = r.status;
  s.out = r.out;
  if (fs::exists(out / "result.json")) s.result = bpde::read_json_file((out / "result.json").string());
  return s;
}

double num(const Json& j) { return j.get<double>(); }

/// The distance of x from the spherical cap of radius 2 over the unit circle that bulges towards
/// +z (H = -0.5 with the circle counter-clockwise about +z): the sphere's centre is (0, 0, -√3).
double off_cap(const Eigen::Vector3d& x) { return std::abs((x - Eigen::Vector3d(0, 0, -std::sqrt(3.0))).norm() - 2); }

}  // namespace

// The spherical cap (A = 3.36714885790773) with a mean-curvature tolerance that degree 4 misses
// (max |H(x) - H| about 2e-4 on the fan) and degree 5 meets (about 1e-4): two rounds, the first
// above the tolerance, the last below, the certificate the last round's and located on the surface.
TEST(ComplexTolerance, CapMeetsAMeanCurvatureToleranceByRaisingTheDegree) {
  const double tol = 1.5e-4;
  const Solved s = solve("cap_tol", circle_job(4, kAreaCap,
                                               R"(, "tolerance": {"mean_curvature": 1.5e-4, "max_degree": 6})"),
                         false);
  ASSERT_EQ(s.status, 0) << s.out;
  const Json& rep = s.result["report"];
  EXPECT_TRUE(rep["converged"].get<bool>());
  const Json& rounds = rep["rounds"];
  ASSERT_GE(rounds.size(), 2u);
  EXPECT_EQ(rounds[0]["degree"], 4);
  EXPECT_GT(num(rounds[0]["mean_curvature_deviation"]), tol);
  EXPECT_EQ(rounds[0]["failed"], Json::array({"mean_curvature"}));
  const Json& last = rounds.back();
  EXPECT_GT(last["degree"].get<int>(), 4);
  EXPECT_LE(last["degree"].get<int>(), 6);
  EXPECT_TRUE(last["failed"].empty());
  EXPECT_EQ(last["status"], "converged");
  // the result is the last round's: its degree, and its certificate below the tolerance
  EXPECT_EQ(rep["degree"], last["degree"]);
  EXPECT_EQ(s.result["net"]["degree"], last["degree"]);
  const Json& cert = rep["certificate"];
  EXPECT_LT(num(cert["mean_curvature_deviation"]), tol);
  EXPECT_NEAR(num(cert["mean_curvature_deviation"]), num(last["mean_curvature_deviation"]), 1e-15);
  EXPECT_NEAR(num(rep["area"]), 3.36714885790773, 1e-7);
  // the location: patch p at (u, v) of result.json's net is the certificate's point, on the cap
  const int p = cert["patch"].get<int>();
  ASSERT_GE(p, 0);
  ASSERT_LT(p, rep["patches"].get<int>());
  const auto net = std::get<bpde::TriangularNet>(bpde::net_from_json(s.result["net"]["patches"][p]));
  const Eigen::Vector3d x = net.evaluate(num(cert["at"][0]), num(cert["at"][1]));
  const Eigen::Vector3d point(num(cert["point"][0]), num(cert["point"][1]), num(cert["point"][2]));
  EXPECT_LT((x - point).norm(), 1e-12);
  EXPECT_LT(off_cap(point), 1e-5);
  // the summary says where and how many rounds
  EXPECT_NE(s.out.find("of patch " + std::to_string(p)), std::string::npos) << s.out;
  EXPECT_NE(s.out.find("rounds"), std::string::npos) << s.out;
  // mean_curvature has its locations, each in a patch
  EXPECT_TRUE(rep["mean_curvature"].contains("patch_at_min"));
  EXPECT_TRUE(rep["mean_curvature"].contains("at_max"));
  EXPECT_EQ(cert["boundary"], rep["boundary_error"]);
}

// The boundary error of the unit circle fitted at degree n (interpolation at the Chebyshev nodes
// of 60° arcs): small, falling with n, and equal (to first order) to an independent measure, the
// largest distance of the solved boundary edges' samples from the circle.
TEST(ComplexTolerance, BoundaryErrorOfACircleIsSmallAndFallsWithTheDegree) {
  double previous = 1;
  for (int n : {3, 4, 5, 6}) {
    SCOPED_TRACE(n);
    const Solved s = solve("circle_bnd_" + std::to_string(n), circle_job(n, kExtremal));
    ASSERT_EQ(s.status, 0);
    const Json& e = s.result["report"]["boundary_error"];
    const double err = num(e["max_error"]);
    EXPECT_LT(err, 1e-2);
    EXPECT_LT(err, previous / 3);
    previous = err;
    EXPECT_EQ(e["loop"], 0);
    EXPECT_EQ(e["curve"], 0);
    const double t = num(e["t"]);
    EXPECT_NEAR(num(e["point"][0]), std::cos(2 * std::numbers::pi * t), 1e-12);  // the circle's own point
    EXPECT_NEAR(num(e["point"][1]), std::sin(2 * std::numbers::pi * t), 1e-12);
    // independent: the patches' edges that lie on the circle, sampled, and their distance from it
    double off = 0;
    for (const Json& pj : s.result["net"]["patches"]) {
      const auto net = std::get<bpde::TriangularNet>(bpde::net_from_json(pj));
      const auto edge_point = [&](int edge, double s) -> Eigen::Vector3d {
        if (edge == 0) return net.evaluate(s, 0);
        if (edge == 1) return net.evaluate(1 - s, s);
        return net.evaluate(0, 1 - s);
      };
      for (int edge = 0; edge < 3; ++edge) {
        if (edge_point(edge, 0.5).head<2>().norm() < 0.9) continue;  // an inner edge
        for (int k = 0; k <= 2000; ++k) {
          const Eigen::Vector3d x = edge_point(edge, k / 2000.0);
          off = std::max(off, std::hypot(x.head<2>().norm() - 1, x(2)));
        }
      }
    }
    EXPECT_GT(err, off / 2);
    EXPECT_LT(err, off * 2);
  }
}

// A tolerance no round within the limits meets (the Dirichlet functional's D_H critical points of
// a circle in its angle parametrisation are not CMC surfaces at any degree): exit 1, converged
// false, a message, every round in the report, the last at the limits.
TEST(ComplexTolerance, ToleranceImpossibleWithinTheLimitsExitsOne) {
  const Solved s = solve("impossible", circle_job(4, kDirichletCap,
                                                  R"(, "tolerance": {"mean_curvature": 1e-3, "max_degree": 5, "max_refine": 1})"));
  ASSERT_EQ(s.status, 1);
  const Json& rep = s.result["report"];
  EXPECT_FALSE(rep["converged"].get<bool>());
  EXPECT_TRUE(rep["message"].is_string());
  const Json& rounds = rep["rounds"];
  ASSERT_EQ(rounds.size(), 3u);  // degree 4, degree 5, degree 5 refined once
  EXPECT_EQ(rounds[1]["degree"], 5);
  EXPECT_EQ(rounds[1]["refine"], 0);
  EXPECT_EQ(rounds[2]["degree"], 5);
  EXPECT_EQ(rounds[2]["refine"], 1);
  EXPECT_EQ(rounds[2]["patches"], 24);
  for (const Json& r : rounds) {
    EXPECT_GT(num(r["mean_curvature_deviation"]), 1e-3);
    EXPECT_EQ(r["failed"], Json::array({"mean_curvature"}));
  }
  EXPECT_EQ(rep["tolerance"]["mean_curvature"], 1e-3);
  EXPECT_FALSE(rep["certificate"]["near_constant"].get<bool>());
  // a boundary tolerance fails at the degree limit without h rounds (h keeps the fitted edges)
  const Solved b = solve("boundary_limit", circle_job(3, kExtremal,
                                                      R"(, "tolerance": {"boundary": 1e-12, "max_degree": 4})"));
  ASSERT_EQ(b.status, 1);
  ASSERT_EQ(b.result["report"]["rounds"].size(), 2u);
  EXPECT_EQ(b.result["report"]["rounds"][1]["refine"], 0);
  EXPECT_LT(num(b.result["report"]["rounds"][1]["boundary_error"]), num(b.result["report"]["rounds"][0]["boundary_error"]));
}

// A boundary tolerance met by degree: the boundary is fitted again at each round's degree.
TEST(ComplexTolerance, BoundaryToleranceIsMetByRefittingAtAHigherDegree) {
  const Solved s = solve("boundary_tol", circle_job(3, kExtremal, R"(, "tolerance": {"boundary": 1e-7})"));
  ASSERT_EQ(s.status, 0);
  const Json& rep = s.result["report"];
  ASSERT_GE(rep["rounds"].size(), 2u);
  EXPECT_GT(num(rep["rounds"][0]["boundary_error"]), 1e-7);
  EXPECT_LT(num(rep["boundary_error"]["max_error"]), 1e-7);
  // boundary_fit is the last round's fit
  double fit = 0;
  for (const Json& f : rep["boundary_fit"]) fit = std::max(fit, num(f["max_error"]));
  EXPECT_LT(fit, 1e-6);
}

// A single net from curves reports the same boundary field (from its fit, without a location), in
// the certificate of a cmc result too; a single net takes no tolerance.
TEST(ComplexTolerance, SingleNetsReportTheirFitErrorAndRefuseATolerance) {
  const std::string single = R"({"boundary": {"type": "triangular", "degree": 6, "builder": "circle-three-arcs"}, )" +
                             kDirichletCap;
  const Solved s = solve("single_net", single + "}");
  ASSERT_EQ(s.status, 0);
  const Json& rep = s.result["report"];
  double worst = 0;
  for (const Json& f : rep["boundary_fit"]) worst = std::max(worst, num(f["max_error"]));
  EXPECT_EQ(num(rep["boundary_error"]["max_error"]), worst);
  EXPECT_TRUE(rep["boundary_error"]["point"].is_null());
  EXPECT_EQ(rep["certificate"]["boundary"], rep["boundary_error"]);
  EXPECT_FALSE(rep["certificate"].contains("patch"));
  EXPECT_TRUE(rep["certificate"]["point"].is_array());

  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"tol_single", single + R"(, "tolerance": {"mean_curvature": 1e-3}})"},
           {"tol_extremal_mc", circle_job(4, kExtremal, R"(, "tolerance": {"mean_curvature": 1e-3})")},
           {"tol_unknown", circle_job(4, kExtremal, R"(, "tolerance": {"area": 1e-3})")},
           {"tol_negative", circle_job(4, kExtremal, R"(, "tolerance": {"boundary": -1})")},
           {"tol_degree", circle_job(4, kExtremal, R"(, "tolerance": {"boundary": 1e-3, "max_degree": 21})")}}) {
    SCOPED_TRACE(name);
    const fs::path job = write(name + ".json", text), out = tmpdir() / ("never_" + name);
    const CmdResult r = run("solve " + job.string() + " --out " + out.string());
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

// A seam tolerance: the D_H critical point's normals jump across the fan's seams by 3.7° at degree
// 4 and 1.2° at degree 6; a tolerance of 2° is met by raising the degree.
TEST(ComplexTolerance, SeamAngleToleranceIsMetByRaisingTheDegree) {
  const Solved s = solve("seam_tol", circle_job(4, kDirichletCap, R"(, "tolerance": {"seam_angle": 2})"));
  ASSERT_EQ(s.status, 0);
  const Json& rounds = s.result["report"]["rounds"];
  ASSERT_GE(rounds.size(), 2u);
  EXPECT_GT(num(rounds[0]["seam_angle_max"]), 2);
  EXPECT_EQ(rounds[0]["failed"], Json::array({"seam_angle"}));
  EXPECT_LT(num(rounds.back()["seam_angle_max"]), 2);
  EXPECT_EQ(num(s.result["report"]["seam_angle_max"]), num(rounds.back()["seam_angle_max"]));
  for (std::size_t k = 1; k < rounds.size(); ++k) EXPECT_GT(rounds[k]["degree"], rounds[k - 1]["degree"]);
}
