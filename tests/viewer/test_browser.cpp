// view.html in a real browser: headless Chromium opens the page that `bpde solve --html` wrote,
// from disk, with no network; the page must draw the surface (a screenshot, decoded here, has
// coloured pixels in the middle of the canvas) and report the mesh's vertex count (in the DOM).
// Skips only when no Chromium is installed.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "png_reader.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;
using namespace bpde::testing;

namespace {

std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    const std::string cmd = std::string("command -v ") + name + " >/dev/null 2>&1";
    if (std::system(cmd.c_str()) == 0) return name;
  }
  return "";
}

// Run headless Chromium on `page` with extra `args` (software WebGL; --no-sandbox: tests run as
// root in CI), its own profile folder, and a time limit.
int chromium(const std::string& exe, const fs::path& page, const std::string& args, const fs::path& out) {
  const fs::path profile = tmpdir() / "chromium-profile";
  const std::string cmd = "timeout 90 " + exe +
                          " --headless --no-sandbox --disable-gpu-sandbox --use-angle=swiftshader "
                          "--enable-unsafe-swiftshader --no-first-run --disable-extensions --hide-scrollbars "
                          "--window-size=900,600 --user-data-dir=" +
                          profile.string() + " " + args + " file://" + fs::absolute(page).string() + " >" +
                          out.string() + " 2>" + (tmpdir() / "chromium.err").string();
  return std::system(cmd.c_str());
}

const char* kJob = R"({"net": {"type": "tensor", "degree": [3, 3], "points": [
  [0,0,0],[0,0.33,0.1],[0,0.67,0.1],[0,1,0], [0.33,0,0.1],[0,0,0],[0,0,0],[0.33,1,0.1],
  [0.67,0,0.1],[0,0,0],[0,0,0],[0.67,1,0.1], [1,0,0],[1,0.33,0.1],[1,0.67,0.1],[1,1,0]]},
  "problem": {"kind": "extremal", "energy": {"name": "biharmonic"}}, "samples": 20})";

}  // namespace

TEST(Browser, ChromiumDrawsTheSurfaceAndReportsTheVertexCount) {
  const std::string exe = find_chromium();
  if (exe.empty()) GTEST_SKIP() << "no chromium installed (Debian package chromium)";
  const fs::path job = write("browser_job.json", kJob), dir = tmpdir() / "browser";
  const CmdResult r = run("solve " + job.string() + " --out " + dir.string() + " --html");
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path page = dir / "view.html";
  ASSERT_TRUE(fs::exists(page));
  const int vertices = 21 * 21, triangles = 2 * 20 * 20;

  // the DOM after the first frame: the page's own report of what it drew
  const fs::path dom = tmpdir() / "dom.html";
  ASSERT_EQ(chromium(exe, page, "--dump-dom", dom), 0) << slurp(tmpdir() / "chromium.err");
  const std::string html = slurp(dom);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(html, m, std::regex("<div id=\"bpde-status\"([^>]*)>"))) << html.substr(0, 2000);
  const std::string status = m[1];
  EXPECT_EQ(status.find("data-error"), std::string::npos) << status;
  EXPECT_NE(status.find("data-vertices=\"" + std::to_string(vertices) + "\""), std::string::npos) << status;
  EXPECT_NE(status.find("data-triangles=\"" + std::to_string(triangles) + "\""), std::string::npos) << status;
  ASSERT_TRUE(std::regex_search(status, m, std::regex("data-drawn=\"([0-9]+)\" data-sampled=\"([0-9]+)\"")));
  EXPECT_GT(std::stod(m[1]), 0.3 * std::stod(m[2])) << "the middle of the canvas is mostly background";
  EXPECT_NE(html.find("<title>bezierpde: extremal on a tensor net (" + std::to_string(vertices) + " vertices)</title>"),
            std::string::npos);
  // the report's numbers are beside the surface
  EXPECT_NE(html.find("<th>energy</th>"), std::string::npos);
  EXPECT_NE(html.find("<th>check.self_intersections</th>"), std::string::npos);

  // a screenshot: the middle of the canvas (left of the 300 px side panel) shows the coloured
  // surface, not the white background
  const fs::path shot = tmpdir() / "shot.png";
  fs::remove(shot);
  ASSERT_EQ(chromium(exe, page, "--screenshot=" + shot.string(), tmpdir() / "shot.out"), 0)
      << slurp(tmpdir() / "chromium.err");
  const Image img = decode_png(slurp(shot));
  ASSERT_EQ(img.width, 900);
  ASSERT_EQ(img.height, 600);
  int drawn = 0, total = 0;
  std::set<int> colours;
  for (int y = 200; y < 400; ++y)
    for (int x = 200; x < 380; ++x, ++total) {
      const std::uint8_t* p = img.at(x, y);
      if (765 - p[0] - p[1] - p[2] > 24) ++drawn;
      colours.insert((p[0] >> 3) << 10 | (p[1] >> 3) << 5 | (p[2] >> 3));
    }
  EXPECT_GT(drawn, total / 2) << "non-background pixels in the middle: " << drawn << " of " << total;
  EXPECT_GT(colours.size(), 20u) << "a shaded, curvature-coloured surface has many colours";
  // and the side panel's background is untouched white at its bottom right corner
  const std::uint8_t* corner = img.at(img.width - 320, img.height - 5);
  EXPECT_GT(corner[0] + corner[1] + corner[2], 700);
}
