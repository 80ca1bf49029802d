// view.html of a patch complex without a browser (io/html_view.h): the welded mesh, every patch's
// control net, and the seams: each complex edge once as a polyline of N segments, on the patches'
// edges (the boundary ones on the boundary circle, to its fit's accuracy), and the page's data
// still safe inside its <script> element; and the page of a complex job in headless Chromium
// (skipped without Chromium, as tests/viewer/test_browser.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <regex>
#include <set>

#include "bezierpde/complex/complex_mesh.h"
#include "bezierpde/io/complex_job.h"
#include "bezierpde/io/html_view.h"
#include "bezierpde/jobs/complex_exports.h"
#include "bezierpde/solvers/complex/complex_extremal.h"
#include "tests/cli/cli_run.h"
#include "tests/io/mesh_readers.h"
#include "tests/viewer/page_data.h"

using namespace bpde;
using namespace bpde::testing;

namespace {

/// The fan over the unit circle, refined `refine` times, its inside the Dirichlet extremal.
PatchComplex fan(int degree, int refine) {
  const Json j = parse_json(R"({"type": "complex", "patch": "triangular", "degree": )" + std::to_string(degree) +
                                R"(, "refine": )" + std::to_string(refine) +
                                R"(, "loops": [[{"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]})",
                            "boundary");
  return solve_complex_extremal(complex_from_json(j, "boundary", FitMethod::Interpolation).complex,
                                EnergySpec::dirichlet())
      .complex;
}

}  // namespace

TEST(ViewComplex, SeamsAreEveryComplexEdgeOnceAsPolylines) {
  const PatchComplex c = fan(4, 1);
  const int N = 7;
  const ComplexMesh m = sample_complex(c, N);
  Json report = {{"problem", "extremal"}, {"note", "</script><!-- must stay inside the data"}};
  const std::string page = view_html(c, m, complex_surface_fields(c, m), report, view_title(c, report), N);
  EXPECT_EQ(page.find("</script><!--"), std::string::npos);
  const Json d = page_data(page);
  EXPECT_EQ(d["report"]["note"], report["note"]);

  // the refined fan: 24 patches, 42 edges of which 12 on the boundary (V - E + F = 1, 3F = 2E - 12)
  ASSERT_TRUE(d.contains("seams"));
  const Json& s = d["seams"];
  EXPECT_EQ(s["edges"], 42);
  EXPECT_EQ(s["interior"], 30);
  EXPECT_EQ(s["samples"], N);
  const std::vector<float> points = decode<float>(s["points"]);
  const std::vector<std::uint32_t> lines = decode<std::uint32_t>(s["lines"]);
  ASSERT_EQ(points.size(), 3u * 42 * (N + 1));
  ASSERT_EQ(lines.size(), 2u * 42 * N);
  for (std::uint32_t k : lines) ASSERT_LT(k, 42u * (N + 1));
  // the last 12 polylines are the boundary: on the unit circle to the fit's error at degree 4
  // (interpolation of a 60° arc: below 1e-4) in the plane z = 0; the interior seams reach inside
  double boundary_error = 0, inner_radius = 1;
  for (int e = 0; e < 42; ++e)
    for (int k = 0; k <= N; ++k) {
      const float* x = &points[3 * (static_cast<size_t>(e) * (N + 1) + k)];
      const double r = std::hypot(x[0], x[1]);
      if (e >= 30) boundary_error = std::max(boundary_error, std::abs(r - 1) + std::abs(x[2]));
      else inner_radius = std::min(inner_radius, r);
    }
  EXPECT_LT(boundary_error, 1e-4);
  EXPECT_LT(inner_radius, 1e-6);  // the seams meet at the centre of the fan

  // the mesh is the welded one, the net every patch's control net on the complex's rows
  EXPECT_EQ(d["vertices"], m.mesh.V.rows());
  EXPECT_EQ(d["triangles"], m.mesh.F.rows());
  EXPECT_EQ(decode<float>(d["net"]["points"]).size(), 3u * c.points.rows());
  const std::vector<std::uint32_t> net = decode<std::uint32_t>(d["net"]["lines"]);
  std::set<std::pair<std::uint32_t, std::uint32_t>> unique;
  for (size_t k = 0; k < net.size(); k += 2) unique.insert({net[k], net[k + 1]});
  EXPECT_EQ(unique.size(), net.size() / 2);  // each segment once
  // degree 4: every patch has 3·(4·5/2) = 30 net segments; the 4 on each of its edges are shared
  // along the 30 interior edges: 24·30 − 30·4
  EXPECT_EQ(net.size() / 2, 24u * 30 - 30 * 4);
  EXPECT_NE(page.find("bpde-show-seams"), std::string::npos);
}

TEST(ViewComplex, ASingleNetPageHasNoSeams) {
  const PatchComplex c = fan(3, 0);
  const Net net = triangular_net(c, 0);
  const TriangleMesh mesh = sample_net(net, 5);
  const Json d = page_data(view_html(net, mesh, surface_fields(net, mesh), Json::object(), "one"));
  EXPECT_FALSE(d.contains("seams"));
}

TEST(ViewComplex, SeamSamplesOutsideTheLimitAreRefused) {
  const PatchComplex c = fan(2, 0);
  const ComplexMesh m = sample_complex(c, 2);
  EXPECT_THROW(view_html(c, m, complex_surface_fields(c, m), Json::object(), "t", 0), ParameterError);
}

TEST(ViewComplex, ChromiumDrawsAComplexResultWithItsSeams) {
  std::string exe;
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"})
    if (std::system((std::string("command -v ") + name + " >/dev/null 2>&1").c_str()) == 0) {
      exe = name;
      break;
    }
  if (exe.empty()) GTEST_SKIP() << "no chromium installed (Debian package chromium)";
  namespace fs = std::filesystem;
  const fs::path job = write("complex_view_job.json", R"({"boundary": {"type": "complex", "patch": "triangular",
      "degree": 3, "refine": 1, "loops": [[{"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1}]]},
      "problem": {"kind": "cmc", "H": -0.5}, "samples": 6})");
  const fs::path dir = tmpdir() / "complex_view";
  const CmdResult r = run("solve " + job.string() + " --out " + dir.string() + " --html --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path dom = tmpdir() / "complex_dom.html", profile = tmpdir() / "chromium-profile-complex";
  const std::string cmd = "timeout 90 " + exe +
                          " --headless --no-sandbox --disable-gpu-sandbox --use-angle=swiftshader "
                          "--enable-unsafe-swiftshader --no-first-run --disable-extensions --hide-scrollbars "
                          "--window-size=900,600 --user-data-dir=" + profile.string() + " --dump-dom file://" +
                          fs::absolute(dir / "view.html").string() + " >" + dom.string() + " 2>/dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string html = slurp(dom);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(html, m, std::regex("<div id=\"bpde-status\"([^>]*)>"))) << html.substr(0, 2000);
  const std::string status = m[1];
  EXPECT_EQ(status.find("data-error"), std::string::npos) << status;
  // the refined fan welded at N = 6: 19 + 42·5 + 24·10 vertices, 24·36 triangles
  EXPECT_NE(status.find("data-vertices=\"" + std::to_string(19 + 42 * 5 + 24 * 10) + "\""), std::string::npos) << status;
  EXPECT_NE(status.find("data-triangles=\"" + std::to_string(24 * 36) + "\""), std::string::npos) << status;
  ASSERT_TRUE(std::regex_search(status, m, std::regex("data-drawn=\"([0-9]+)\" data-sampled=\"([0-9]+)\"")));
  EXPECT_GT(std::stod(m[1]), 0.3 * std::stod(m[2]));
  // the seams' check box is shown (hidden on a single net's page)
  ASSERT_TRUE(std::regex_search(html, m, std::regex("<label id=\"bpde-seams-label\"([^>]*)>")));
  EXPECT_EQ(std::string(m[1]).find("hidden"), std::string::npos) << m[1];
}
