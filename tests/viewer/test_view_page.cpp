// view.html's content without a browser: one self-contained page (no external script, style or
// URL), its data as float32/uint32 base64 that decode to the mesh, the report and the range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "bezierpde/io/html_view.h"
#include "bezierpde/io/mesh_io.h"
#include "bezierpde/jobs/run_demo.h"
#include "bezierpde/jobs/run_job.h"
#include "tests/io/mesh_readers.h"
#include "tests/viewer/page_data.h"

using namespace bpde;
using namespace bpde::testing;

TEST(ViewPage, SelfContainedWithTheMeshAsFloat32) {
  const SolveOutcome out = run_job(demo_job());
  const TriangleMesh mesh = sample_net(out.net, 10);
  const SurfaceFields f = surface_fields(out.net, mesh);
  Json report = out.report;
  report["mean_curvature"] = {{"min", -2.5}, {"max", -0.5}};
  report["note"] = "a </script> in a string must not end the data";
  const std::string page = view_html(out.net, mesh, f, report, "demo <&>");

  // nothing fetched from outside: no src=, no href=, no http(s) URL outside the bundled library's
  // own strings (which name the XHTML namespace)
  EXPECT_EQ(page.find(" src="), std::string::npos);
  EXPECT_EQ(page.find(" href="), std::string::npos);
  EXPECT_EQ(page.find("<script type=\"module\""), std::string::npos);
  EXPECT_NE(page.find("<title>demo &lt;&amp;&gt;</title>"), std::string::npos);
  EXPECT_NE(page.find("three.js " + viewer_three_version()), std::string::npos);
  EXPECT_NE(page.find("OrbitControls"), std::string::npos);  // inlined
  EXPECT_EQ(page.find("@BPDE_"), std::string::npos);

  const Json data = page_data(page);
  EXPECT_EQ(data["vertices"], mesh.V.rows());
  EXPECT_EQ(data["triangles"], mesh.F.rows());
  const auto P = decode<float>(data["positions"]), N = decode<float>(data["normals"]), H = decode<float>(data["H"]);
  const auto T = decode<std::uint32_t>(data["indices"]);
  const auto R = decode<std::uint8_t>(data["regular"]);
  ASSERT_EQ(P.size(), 3u * mesh.V.rows());
  ASSERT_EQ(N.size(), 3u * mesh.V.rows());
  ASSERT_EQ(H.size(), static_cast<size_t>(mesh.V.rows()));
  ASSERT_EQ(R.size(), static_cast<size_t>(mesh.V.rows()));
  ASSERT_EQ(T.size(), 3u * mesh.F.rows());
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(P[3 * k + c], static_cast<float>(mesh.V(k, c)));
      EXPECT_EQ(N[3 * k + c], static_cast<float>(f.normal(k, c)));
    }
    EXPECT_EQ(H[k], static_cast<float>(f.H(k)));
    EXPECT_EQ(R[k], f.regular(k));
  }
  for (Eigen::Index t = 0; t < mesh.F.rows(); ++t)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(T[3 * t + c], static_cast<std::uint32_t>(mesh.F(t, c)));
  const auto NP = decode<float>(data["net"]["points"]);
  const auto NL = decode<std::uint32_t>(data["net"]["lines"]);
  const auto& tri = std::get<TriangularNet>(out.net);
  EXPECT_EQ(NP.size(), 3u * tri.points().rows());
  EXPECT_EQ(NL.size(), 2 * net_segments(out.net).size());
  const size_t n = static_cast<size_t>(tri.n());
  EXPECT_EQ(NL.size(), 2u * 3 * n * (n + 1) / 2);  // degree n: 3 n(n+1)/2 segments
  // the colour range is the report's (away from the corners), and the report is carried whole
  EXPECT_EQ(data["range"], Json::array({-2.5, -0.5}));
  EXPECT_EQ(data["report"]["note"], report["note"]);
  EXPECT_EQ(data["report"]["energy"], report["energy"]);

  // without report statistics: the range of H over the regular vertices
  const Json bare = page_data(view_html(out.net, mesh, f, Json::object(), "x"));
  double lo = 1e300, hi = -1e300;
  for (Eigen::Index k = 0; k < mesh.V.rows(); ++k) {
    if (f.regular(k)) lo = std::min(lo, f.H(k)), hi = std::max(hi, f.H(k));
  }
  EXPECT_EQ(bare["range"][0].get<double>(), lo);
  EXPECT_EQ(bare["range"][1].get<double>(), hi);
}

// Report strings and a title that look like markup or like the template's markers reach the page
// as data: the data script holds no "<", ">" or "&" (so "<!--<script>" cannot swallow its end
// tag), reads back to the same strings, and the markers in values are never substituted.
TEST(ViewPage, MarkupAndMarkersInTheReportAreData) {
  const SolveOutcome out = run_job(demo_job());
  const TriangleMesh mesh = sample_net(out.net, 4);
  const SurfaceFields f = surface_fields(out.net, mesh);
  Json report = out.report;
  const std::vector<std::string> strings = {"<!--<script>", "</script><script>alert(1)</script>", "@BPDE_DATA@",
                                            "@BPDE_BUNDLE@", "a & b > c", "line\u2028separator"};
  const std::vector<std::string> keys = {"s0", "s1", "s2", "s3", "s4", "s5"};
  for (std::size_t k = 0; k < strings.size(); ++k) report[keys[k]] = strings[k];
  std::string page;
  ASSERT_NO_THROW(page = view_html(out.net, mesh, f, report, "title @BPDE_RANGE_NOTE@ @BPDE_DATA@"));
  const std::string open = "<script id=\"bpde-data\" type=\"application/json\">";
  const size_t a = page.find(open), b = page.find("</script>", a);
  ASSERT_NE(a, std::string::npos);
  const std::string text = page.substr(a + open.size(), b - a - open.size());
  EXPECT_EQ(text.find_first_of("<>&"), std::string::npos);
  const Json data = Json::parse(text);
  for (std::size_t k = 0; k < strings.size(); ++k) EXPECT_EQ(data["report"][keys[k]], strings[k]);
  EXPECT_NE(page.find("<title>title @BPDE_RANGE_NOTE@ @BPDE_DATA@</title>"), std::string::npos);
  EXPECT_NE(page.find("OrbitControls"), std::string::npos);  // the bundle is there once
}
