// Tests of the FORMATS.md blend config parser (io/blend_config.h).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <numbers>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/blend_config.h"

namespace bpde {
namespace {

using json = nlohmann::json;

json small_config() {
  return json::parse(R"({"kind": "blend", "partition": [2, 1], "a": 1.5, "epsilon": 0.01,
    "edges": {"y0": {"value": [[0,0,0],[1,0,0],[2,0,0]], "dy": [[0,1,0],[0,1,0],[0,1,0]]},
              "y1": {"value": [[0,1,0],[1,1,0],[2,1,0.5]], "dy": [[0,1,0],[0,1,0],[0,1,0]]}},
    "points": [[0.5, 0.5], [0.25, 1.0]], "data": [[1, 0.5, 0.1], [0.5, 1, 0]], "samples": 12})");
}

/// Expect exception type E whose message contains `needle`.
template <class E>
void expect_error(const json& j, const std::string& needle) {
  try {
    blend_config_from_json(j);
    ADD_FAILURE() << "no exception; expected one mentioning " << needle;
  } catch (const E& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

TEST(BlendConfig, ParsesTheFormatsForm) {
  const BlendConfig c = blend_config_from_json(small_config());
  EXPECT_EQ(c.problem.k, 2);
  EXPECT_EQ(c.problem.l, 1);
  EXPECT_EQ(c.problem.a, 1.5);
  EXPECT_EQ(c.problem.epsilon, 0.01);
  EXPECT_EQ(c.samples, 12);
  EXPECT_EQ(c.problem.y1_value(2, 2), 0.5);
  EXPECT_EQ(c.problem.points.rows(), 2);
  EXPECT_EQ(c.problem.points(1, 0), 0.25);
  EXPECT_EQ(c.problem.data(0, 1), 0.5);
  // optional fields
  json j = small_config();
  j.erase("points");
  j.erase("data");
  j.erase("samples");
  const BlendConfig d = blend_config_from_json(j);
  EXPECT_EQ(d.problem.points.rows(), 0);
  EXPECT_EQ(d.samples, 50);
  // empty arrays
  j["points"] = json::array();
  j["data"] = json::array();
  EXPECT_EQ(blend_config_from_json(j).problem.data.rows(), 0);
}

TEST(BlendConfig, RoundTripsThroughJson) {
  BlendConfig c = blend_config_from_json(small_config());
  c.problem.a = std::numbers::pi;
  c.problem.y0_value(1, 2) = 1.0 / 3.0;
  const BlendConfig d = parse_blend_config(blend_config_to_json(c).dump());
  EXPECT_EQ(d.problem.a, c.problem.a);
  EXPECT_EQ(d.problem.y0_value, c.problem.y0_value);
  EXPECT_EQ(d.problem.points, c.problem.points);
  EXPECT_EQ(d.samples, c.samples);
}

TEST(BlendConfig, StrictErrorsNameTheField) {
  json j = small_config();
  j["extra"] = 1;
  expect_error<ParseError>(j, "extra");
  j = small_config();
  j["edges"]["y0"]["ddy"] = json::array();
  expect_error<ParseError>(j, "edges.y0.ddy");
  j = small_config();
  j["edges"]["y2"] = json::object();
  expect_error<ParseError>(j, "edges.y2");
  j = small_config();
  j.erase("epsilon");
  expect_error<ParseError>(j, "epsilon");
  j = small_config();
  j["edges"]["y1"].erase("dy");
  expect_error<ParseError>(j, "edges.y1.dy");
  j = small_config();
  j["kind"] = "tensor";
  expect_error<ParseError>(j, "kind");
  j = small_config();
  j["a"] = "1";
  expect_error<ParseError>(j, "a must be a number");
  j = small_config();
  j["partition"] = {2.5, 1};
  expect_error<ParseError>(j, "partition[0]");
  j = small_config();
  j["partition"] = {2, 1, 3};
  expect_error<SizeError>(j, "partition");
  j = small_config();
  j["partition"] = {0, 1};
  expect_error<ParameterError>(j, "partition[0]");
  j = small_config();
  j["samples"] = 0;
  expect_error<ParameterError>(j, "samples");
  j = small_config();
  j["epsilon"] = 0.0;
  expect_error<ParameterError>(j, "epsilon");
  j = small_config();
  j["epsilon"] = -1e-3;
  expect_error<ParameterError>(j, "epsilon");
  j = small_config();
  j["a"] = -2;
  expect_error<ParameterError>(j, "a must be > 0");
  j = small_config();
  j["points"][1] = {1.25, 0.5};
  expect_error<ParameterError>(j, "points[1]");
  j = small_config();
  j["points"][0] = {0.5};
  expect_error<SizeError>(j, "points[0]");
  j = small_config();
  j["data"][1][2] = "z";
  expect_error<ParseError>(j, "data[1][2]");
  j = small_config();
  j["data"].push_back({1, 2, 3});
  expect_error<SizeError>(j, "data");
  j = small_config();
  j["edges"]["y1"]["value"].erase(2);
  expect_error<SizeError>(j, "edges.y1.value");
  j = small_config();
  j["edges"]["y0"]["dy"][1] = {0, 1};
  expect_error<SizeError>(j, "edges.y0.dy[1]");
  j = small_config();
  j["edges"]["y0"]["value"] = 3;
  expect_error<ParseError>(j, "edges.y0.value");
  j = small_config();
  j["a"] = 1e200;
  expect_error<ParameterError>(j, "a must be in");
  expect_error<ParseError>(json::array(), "object");
}

TEST(BlendConfig, MalformedOrOverflowingText) {
  EXPECT_THROW(parse_blend_config("{\"kind\": \"blend\", "), ParseError);
  std::string text = small_config().dump();
  const auto pos = text.find("\"a\":1.5");
  ASSERT_NE(pos, std::string::npos);
  text.replace(pos, 7, "\"a\":1e999");
  EXPECT_THROW(parse_blend_config(text), NonFiniteError);
  EXPECT_THROW(read_blend_config("/nonexistent/blend.json"), FileError);
}

TEST(BlendConfig, ExampleConfigsAreTheCylindersOfSection6) {
  const std::filesystem::path dir = std::filesystem::path(BPDE_SOURCE_DIR) / "examples" / "003-blend-cylinders";
  const char* names[4] = {"fig2a.json", "fig2b.json", "fig2c.json", "fig2d.json"};
  const double as[4] = {1, 10, 10, 10}, eps[4] = {1, 1, 1e-3, 1e-5};
  const int ms[4] = {0, 0, 9, 9};
  const double tp = 2 * std::numbers::pi;
  for (int c = 0; c < 4; ++c) {
    const BlendConfig cfg = read_blend_config((dir / names[c]).string());
    const SmoothingSplineProblem& p = cfg.problem;
    EXPECT_EQ(p.k, 8);
    EXPECT_EQ(p.l, 4);
    EXPECT_EQ(p.a, as[c]);
    EXPECT_EQ(p.epsilon, eps[c]);
    ASSERT_EQ(p.points.rows(), ms[c]);
    for (int i = 0; i <= 8; ++i) {
      const double x = i / 8.0;
      // u(x,0) = f(x,1), u_y(x,0) = f_y(x,1), u(x,1) = g(x,0), u_y(x,1) = g_y(x,0)
      EXPECT_LT((p.y0_value.row(i) - Eigen::RowVector3d(1, 2 * std::cos(tp * x), 2 * std::sin(tp * x))).norm(), 1e-15);
      EXPECT_LT((p.y0_dy.row(i) - Eigen::RowVector3d(2, 0, 0)).norm(), 1e-15);
      EXPECT_LT((p.y1_value.row(i) - Eigen::RowVector3d(1, std::cos(tp * x), std::sin(tp * x))).norm(), 1e-15);
      EXPECT_LT((p.y1_dy.row(i) - Eigen::RowVector3d(2, 0, 0)).norm(), 1e-15);
    }
    for (int i = 0; i < ms[c]; ++i) {
      EXPECT_NEAR(p.points(i, 0), i / 9.0, 1e-16);
      EXPECT_EQ(p.points(i, 1), 0.5);
      // β = h(i/9, 0.5), h(x, y) = (2y - 1, 0.5 cos 2πx, 0.5 sin 2πx)
      EXPECT_LT(
          (p.data.row(i) - Eigen::RowVector3d(0, 0.5 * std::cos(tp * i / 9.0), 0.5 * std::sin(tp * i / 9.0))).norm(),
          1e-15);
    }
    const auto r = solve_smoothing_spline(p);
    EXPECT_TRUE(r.summary.converged) << names[c] << ": " << r.summary.message;
  }
}

TEST(BlendConfig, ExampleConfigsReportTheEnergiesOfTheAssembledForm) {
  // J(σ) and |σ|_L² of examples/003-blend-cylinders as `bpde blend` printed them when the solver
  // read the energy from the assembled R (before it stopped storing R and the upper triangle of C):
  // the element-by-element energy must give the same numbers.
  const std::filesystem::path dir = std::filesystem::path(BPDE_SOURCE_DIR) / "examples" / "003-blend-cylinders";
  const char* names[4] = {"fig2a.json", "fig2b.json", "fig2c.json", "fig2d.json"};
  const double functional[4] = {2056.804947281693, 9510.032343342973, 20.985443936263355, 0.4485004239726369};
  const double energy[4] = {2056.804947281693, 9510.032343342973, 13303.825055085208, 44067.75566822331};
  const double misfit[4] = {0.0, 0.0, 7.681618881178145, 0.007822867290403757};
  for (int c = 0; c < 4; ++c) {
    const BlendConfig cfg = read_blend_config((dir / names[c]).string());
    const auto r = solve_smoothing_spline(cfg.problem);
    ASSERT_TRUE(r.summary.converged) << names[c] << ": " << r.summary.message;
    EXPECT_NEAR(r.functional, functional[c], 1e-12 * functional[c]) << names[c];
    EXPECT_NEAR(r.energy, energy[c], 1e-12 * energy[c]) << names[c];
    EXPECT_NEAR(r.data_misfit, misfit[c], 1e-12 * misfit[c]) << names[c];
  }
}

}  // namespace
}  // namespace bpde
