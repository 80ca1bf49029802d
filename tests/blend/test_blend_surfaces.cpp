// The "surfaces" form of the blend config: edges taken from two nets (smoothing PDE splines §6 as read in
// docs/errata.md: u(x,0) = f(x,1), u_y(x,0) = f_y(x,1), u(x,1) = g(x,0), u_y(x,1) = g_y(x,0)).
#include <gtest/gtest.h>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/blend_config.h"

using namespace bpde;

TEST(BlendSurfaces, NetsGiveTheSameEdgesAsExplicitData) {
  // f(x, y) = (x, y - 1, x^2 y) as a degree-(2,1) tensor net; g(x, y) = (x, y + 1, 2 y) as a
  // bspline of degree (1,1) on knots [0 0 2 2] x [0 0 1 1] (domain mapped onto [0,1]^2).
  const std::string text = R"({"kind": "blend", "partition": [4, 2], "a": 1, "epsilon": 0.1,
    "surfaces": {
      "f": {"type": "tensor", "degree": [2, 1], "points": [[0,-1,0],[0,0,0],[0.5,-1,0],[0.5,0,0],[1,-1,0],[1,0,1]]},
      "g": {"type": "bspline", "degree": [1, 1], "knots": [[0,0,2,2],[0,0,1,1]], "points": [[0,1,0],[0,2,2],[1,1,0],[1,2,2]]}}})";
  const BlendConfig c = parse_blend_config(text);
  const auto& p = c.problem;
  ASSERT_EQ(p.y0_value.rows(), 5);
  for (int i = 0; i <= 4; ++i) {
    const double x = i / 4.0;
    EXPECT_NEAR((p.y0_value.row(i) - Eigen::RowVector3d(x, 0, x * x)).norm(), 0, 1e-14) << i;
    EXPECT_NEAR((p.y0_dy.row(i) - Eigen::RowVector3d(0, 1, x * x)).norm(), 0, 1e-14) << i;
    EXPECT_NEAR((p.y1_value.row(i) - Eigen::RowVector3d(x, 1, 0)).norm(), 0, 1e-14) << i;
    EXPECT_NEAR((p.y1_dy.row(i) - Eigen::RowVector3d(0, 1, 2)).norm(), 0, 1e-14) << i;
  }
}

TEST(BlendSurfaces, ExactlyOneFormAndNoTriangularNets) {
  const std::string base = R"({"kind": "blend", "partition": [2, 2], "a": 1, "epsilon": 0.1)";
  EXPECT_THROW(parse_blend_config(base + "}"), ParseError);
  const std::string tri = R"({"type": "triangular", "degree": 1, "points": [[1,0,0],[0,1,0],[0,0,0]]})";
  EXPECT_THROW(parse_blend_config(base + R"(, "surfaces": {"f": )" + tri + R"(, "g": )" + tri + "}}"), ParseError);
}
