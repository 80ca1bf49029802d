// The "boundary" form of jobs (io/boundary_json.h): every CURVE form read into the curve it names,
// the report's boundary_fit, and the typed errors with their JSON paths.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/boundary_json.h"

namespace {

using bpde::Json;
using Eigen::Vector3d;

bpde::BoundaryCurve curve(const std::string& text) { return bpde::curve_from_json(Json::parse(text), "c"); }

TEST(BoundaryJson, EveryCurveFormReadsIntoItsCurve) {
  const auto b = curve(R"({"type": "bezier", "points": [[0,0,0], [1,1,0], [2,0,0]]})");
  EXPECT_LT((b.evaluate(0.5) - Vector3d(1, 0.5, 0)).norm(), 1e-15);
  const auto s = curve(R"({"type": "bspline", "degree": 2, "knots": [0,0,0,1,2,2,2],
                           "points": [[0,0,0], [1,0,0], [1,1,0], [0,1,1]]})");
  EXPECT_LT((s.evaluate(0.5) - Vector3d(1, 0.5, 0)).norm(), 1e-15);
  const auto p = curve(R"({"type": "samples", "points": [[0,0,0], [1,0,0], [3,0,0]], "parameters": [0, 2, 4]})");
  EXPECT_DOUBLE_EQ(p.as_samples()->params(1), 0.5);
  const auto g = curve(R"({"type": "segment", "from": [0,0,0], "to": [0,0,2]})");
  EXPECT_LT((g.evaluate(0.25) - Vector3d(0, 0, 0.5)).norm(), 1e-15);
  const auto a =
      curve(R"({"type": "arc", "center": [0,0,0], "normal": [0,0,1], "radius": 2, "angles": [0, 3.141592653589793],
                           "reference": [0,1,0]})");
  EXPECT_LT((a.evaluate(0.5) - Vector3d(-2, 0, 0)).norm(), 1e-15);
  const auto t = curve(R"({"type": "arc", "through": [[1,0,0], [0,1,0], [-1,0,0]]})");
  EXPECT_LT((t.evaluate(0.5) - Vector3d(0, 1, 0)).norm(), 1e-15);
  const auto h = curve(R"({"type": "helix", "center": [0,0,0], "axis": [0,0,1], "radius": 1,
                           "angles": [0, 6.283185307179586], "pitch": 2})");
  EXPECT_LT((h.evaluate(0.5) - Vector3d(-1, 0, 1)).norm(), 1e-15);
  EXPECT_EQ(h.kind(), "helix");
}

TEST(BoundaryJson, SampleParametersAreGivenChordLengthOrCorrected) {
  // Samples of y = x² at x_k = (k/8)², three ways: the parameters given (t = x, exact at degree 2),
  // "chord-length" (kept: the parabola is missed), and none (the chord length, corrected).
  std::string pts = "[", par = "[";
  auto num = [](double v) { return Json(v).dump(); };  // shortest round-trip form
  for (int k = 0; k <= 8; ++k) {
    const double x = (k / 8.0) * (k / 8.0);
    pts += (k ? ", [" : "[") + num(x) + ", " + num(x * x) + ", 0]";
    par += (k ? ", " : "") + num(x);
  }
  pts += "]";
  par += "]";
  auto fit = [&](const std::string& extra) {
    const bpde::BoundaryCurve c = curve(R"({"type": "samples", "points": )" + pts + extra + "}");
    return bpde::edge_error(c, bpde::fit_edge(c, 2));
  };
  EXPECT_LT(fit(R"(, "parameters": )" + par), 1e-12);
  EXPECT_GT(fit(R"(, "parameters": "chord-length")"), 1e-3);
  EXPECT_LT(fit(""), 1e-9);
}

TEST(BoundaryJson, BoundaryObjectBuildsTheNetAndReportsTheFit) {
  const auto b = bpde::boundary_from_json(Json::parse(R"({"type": "tensor", "degree": [3, 2], "fit": "least-squares",
      "edges": [{"type": "segment", "from": [0,0,0], "to": [1,0,0]},
                {"type": "arc", "through": [[1,0,0], [1.2,0.5,0.1], [1,1,0]]},
                {"type": "segment", "from": [1,1,0], "to": [0,1,0]},
                {"type": "samples", "points": [[0,1,0], [0,0.6,0.1], [0,0.3,0.1], [0,0,0]]}]})"),
                                          "b");
  const auto& net = std::get<bpde::TensorNet>(b.net);
  EXPECT_EQ(net.n(), 3);
  EXPECT_EQ(net.m(), 2);
  EXPECT_FALSE(b.c1);
  const Json r = bpde::boundary_fit_to_json(b.fits);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0]["method"], "elevation");
  EXPECT_EQ(r[1]["method"], "least-squares");
  EXPECT_EQ(r[1]["curve"], "arc");
  EXPECT_EQ(r[3]["curve"], "samples");
  EXPECT_EQ(r[3]["parameters"], "corrected");  // samples without parameters (fit_boundary.h)
  EXPECT_TRUE(r[3].contains("corrections"));
  EXPECT_FALSE(r[1].contains("parameters"));
  EXPECT_LT(r[0]["max_error"].get<double>(), 1e-15);
  EXPECT_GT(r[1]["max_error"].get<double>(), 1e-6);  // an arc at degree 2 is not exact
  EXPECT_FALSE(r[0].contains("tangent_max_error"));
  EXPECT_EQ(net.point(3, 0), Vector3d(1, 0, 0));
  // Sphere builders: tensor and triangular, their corners on the unit sphere.
  for (const char* text : {R"({"type": "tensor", "degree": [6, 6], "builder": "sphere-square"})",
                           R"({"type": "triangular", "degree": 6, "builder": "sphere-triangle"})"}) {
    const auto s = bpde::boundary_from_json(Json::parse(text), "b");
    for (const auto& f : s.fits) EXPECT_LT(f.max_error, 4e-3) << text;  // 1.3e-4 .. 1.9e-3 at degree 6
    const Eigen::MatrixX3d& P = std::visit([](const auto& x) -> const Eigen::MatrixX3d& { return x.points(); }, s.net);
    EXPECT_NEAR(P.row(0).norm(), 1.0, 1e-15) << text;
  }
}

template <class E>
void expect_error(const std::string& text, const std::string& needle) {
  try {
    bpde::boundary_from_json(Json::parse(text), "b");
    ADD_FAILURE() << "no error for " << text;
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong type: " << e.what();
  }
}

TEST(BoundaryJson, BadBoundariesThrowTypedErrorsWithTheirPath) {
  const std::string s0 = R"({"type": "segment", "from": [0,0,0], "to": [1,0,0]})";
  const std::string s1 = R"({"type": "segment", "from": [1,0,0], "to": [0,1,0]})";
  const std::string s2 = R"({"type": "segment", "from": [0,1,0], "to": [0,0,0]})";
  auto tri = [&](const std::string& e2, const std::string& extra = "") {
    return R"({"type": "triangular", "degree": 3, "edges": [)" + s0 + ", " + s1 + ", " + e2 + "]" + extra + "}";
  };
  expect_error<bpde::ParseError>(tri(R"({"type": "spiral"})"), "b.edges[2].type: unknown curve type");
  expect_error<bpde::ParseError>(tri(R"({"type": "segment", "from": [0,1,0], "to": [0,0,0], "via": [1,1,1]})"),
                                 "b.edges[2]: unknown field \"via\"");
  expect_error<bpde::SizeError>(tri(R"({"type": "segment", "from": [0,1,0], "to": [0,0]})"), "b.edges[2].to");
  expect_error<bpde::DegreeError>(tri(R"({"type": "bezier", "points": [[0,1,0]]})"), "b.edges[2]: a Bézier curve");
  expect_error<bpde::DegreeError>(tri(R"({"type": "bspline", "degree": 0, "knots": [0, 1], "points": [[0,1,0]]})"),
                                  "b.edges[2].degree");
  expect_error<bpde::ParameterError>(
      tri(R"({"type": "arc", "center": [0,0,0], "normal": [0,0,1], "radius": -1, "angles": [0, 1]})"),
      "b.edges[2]: radius");
  expect_error<bpde::ParameterError>(tri(R"({"type": "samples", "points": [[0,1,0], [0,0,0]], "parameters": [1, 0]})"),
                                     "b.edges[2]: samples: parameters must increase");
  expect_error<bpde::SizeError>(tri(R"({"type": "samples", "points": [[0,1,0], [0,0.5,0], [0,0,0]]})"),
                                "needs at least 4 samples, got 3");
  expect_error<bpde::ParseError>(
      tri(R"({"type": "samples", "points": [[0,1,0], [0,0.5,0], [0,0.2,0], [0,0,0]], "parameters": "arc"})"),
      "b.edges[2].parameters: unknown parameters \"arc\" (expected an array of numbers, or \"chord-length\")");
  expect_error<bpde::ParameterError>(tri(R"({"type": "segment", "from": [0,1,0], "to": [0,0,0.5]})"),
                                     "b: edges 2 and 0 do not meet");
  expect_error<bpde::ParameterError>(tri(s2, R"(, "corner_tolerance": 0)"), "b.corner_tolerance");
  expect_error<bpde::ParameterError>(
      tri(s2, R"(, "smooth_corner_angle": 120)"),
      "b.smooth_corner_angle: smooth_corner_angle: must be a number of degrees in [0, 90]");
  expect_error<bpde::ParseError>(tri(s2, R"(, "smooth_corner_angle": "yes")"), "b.smooth_corner_angle");
  expect_error<bpde::SizeError>(tri(s2, ", \"tangents\": [" + s0 + "]"), "b.tangents: a triangular net has 3 edges");
  expect_error<bpde::ParseError>(R"({"type": "bspline", "degree": [3, 3], "edges": []})", "b.type");
  expect_error<bpde::DegreeError>(R"({"type": "tensor", "degree": [3, 65], "edges": []})", "b.degree[1]");
  expect_error<bpde::ParseError>(R"({"type": "tensor", "degree": [3, 3], "builder": "sphere-square", "radius": 2})",
                                 "unknown field \"radius\"");
}

}  // namespace
