// view.html in a real browser: headless Chromium opens the page that `bpde solve --html` wrote,
// from disk, with no network; the page must draw the surface (a screenshot, decoded here, has
// coloured pixels in the middle of the canvas) and report the mesh's vertex count (in the DOM);
// the report's lists of objects are tables of the right shape, nothing in the side panel is wider
// than the panel (measured by a probe script added to a copy of the page), and the legend has
// ticks at the right values. Skips only when no Chromium is installed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <regex>
#include <set>
#include <string>

#include "bezierpde/io/json_io.h"
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
  // the report's numbers are beside the surface (names may break after '_' and '.': <wbr>)
  const std::string text = std::regex_replace(html, std::regex("<wbr>"), "");
  EXPECT_NE(text.find("<th>energy</th>"), std::string::npos);
  EXPECT_NE(text.find("<th>check.self_intersections</th>"), std::string::npos);

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

namespace {

// An area solve from a boundary of three arcs: its report has boundary_fit (3 edges) and routes.
const char* kAreaJob = R"({"boundary": {"type": "triangular", "degree": 6, "builder": "circle-three-arcs",
  "radius": 1}, "fixed": "boundary", "samples": 20,
  "problem": {"kind": "cmc", "H": -0.5, "functional": "area", "solver": "newton"}})";

// Appended to a copy of the page, after its own script: writes into <body> how many elements of
// the side panel reach outside it (data-wide, and the first few: data-wide-names) and by how
// many pixels its content is wider than it (data-scroll).
const char* kProbe = R"(<script>(() => {
  const side = document.getElementById('bpde-side'), r = side.getBoundingClientRect();
  const wide = [];
  for (const e of side.querySelectorAll('*')) {
    const b = e.getBoundingClientRect();
    if (b.width > 0 && (b.right > r.right + 0.5 || b.left < r.left - 0.5))
      wide.push(e.tagName + (e.className ? '.' + e.className : '') + ':' + (e.textContent || '').slice(0, 20));
  }
  document.body.dataset.wide = String(wide.length);
  document.body.dataset.wideNames = wide.slice(0, 5).join(' | ');
  document.body.dataset.scroll = String(side.scrollWidth - side.clientWidth);
})();</script>)";

// The fields of a list of objects as the page shows them: nested objects flattened one level,
// fields null (or an empty object) in every object left out.
std::set<std::string> shown_fields(const bpde::Json& list) {
  std::set<std::string> fields;
  for (const bpde::Json& o : list)
    for (auto it = o.begin(); it != o.end(); ++it) {
      if (it.value().is_object() && !it.value().empty()) {
        for (auto in = it.value().begin(); in != it.value().end(); ++in)
          if (!in.value().is_null()) fields.insert(it.key() + "." + in.key());
      } else if (!it.value().is_null() && !(it.value().is_object() && it.value().empty())) {
        fields.insert(it.key());
      }
    }
  return fields;
}

// The table of the list `key` in the dumped DOM: its data-layout and its rows' cells ("th"/"td" counts).
struct ShownTable {
  std::string layout;
  std::vector<int> cells;  // per row
};
ShownTable shown_table(const std::string& html, const std::string& key) {
  ShownTable t;
  const std::string open = "<table class=\"bpde-list-table\" data-key=\"" + key + "\" data-layout=\"";
  const size_t at = html.find(open);
  if (at == std::string::npos) return t;
  const size_t layout_end = html.find('"', at + open.size()), end = html.find("</table>", at);
  if (layout_end == std::string::npos || end == std::string::npos) return t;
  t.layout = html.substr(at + open.size(), layout_end - at - open.size());
  const std::string body = html.substr(layout_end, end - layout_end);
  for (size_t r = body.find("<tr>"); r != std::string::npos; r = body.find("<tr>", r + 4)) {
    const size_t r_end = body.find("</tr>", r);
    const std::string row = body.substr(r, r_end - r);
    const std::regex cell("<t[hd][ >]");
    t.cells.push_back(static_cast<int>(std::distance(std::sregex_iterator(row.begin(), row.end(), cell), std::sregex_iterator())));
  }
  return t;
}

}  // namespace

TEST(Browser, ReportListsAreTablesTheSidePanelDoesNotOverflowAndTheLegendHasTicks) {
  const std::string exe = find_chromium();
  if (exe.empty()) GTEST_SKIP() << "no chromium installed (Debian package chromium)";
  const fs::path job = write("browser_area_job.json", kAreaJob), dir = tmpdir() / "browser_area";
  const CmdResult r = run("solve " + job.string() + " --out " + dir.string() + " -q");
  ASSERT_EQ(r.status, 0) << r.err;
  bpde::Json result = bpde::Json::parse(slurp(dir / "result.json"));
  bpde::Json& report = result["report"];
  const bpde::Json fit = report["boundary_fit"], routes = report["routes"];
  ASSERT_EQ(fit.size(), 3u);
  ASSERT_GE(routes.size(), 1u);
  // a longer list (seven objects, one with a long word) for the one-row-per-object layout
  bpde::Json many = bpde::Json::array();
  for (int k = 0; k < 7; ++k)
    many.push_back({{"name", "job-" + std::to_string(k)}, {"value", 0.1 * k}, {"nothing", nullptr},
                    {"note", k == 3 ? std::string(120, 'x') : std::string("short")}, {"sub", {{"a", k}, {"b", true}}}});
  report["many"] = many;
  // a long list of scalars: cut at 240 characters in its cell
  bpde::Json numbers = bpde::Json::array();
  for (int k = 0; k < 200; ++k) numbers.push_back(0.125 * k);
  report["numbers"] = numbers;
  { std::ofstream(dir / "result.json") << result.dump(); }
  ASSERT_EQ(run("view " + dir.string() + " --samples 10 -q").status, 0);

  std::string page = slurp(dir / "view.html");
  const size_t end = page.rfind("</body>");
  ASSERT_NE(end, std::string::npos);
  page.insert(end, kProbe);
  const fs::path probed = write("browser_probed.html", page), dom = tmpdir() / "area_dom.html";
  ASSERT_EQ(chromium(exe, probed, "--dump-dom", dom), 0) << slurp(tmpdir() / "chromium.err");
  const std::string html = slurp(dom);
  std::smatch m;
  ASSERT_TRUE(std::regex_search(html, m, std::regex("<div id=\"bpde-status\"([^>]*)>")));
  EXPECT_EQ(std::string(m[1]).find("data-error"), std::string::npos) << m[1];

  // boundary_fit, 3 objects: one column per edge (headed by it) after the names' column, one row
  // per field but edge
  const ShownTable f = shown_table(html, "boundary_fit");
  EXPECT_EQ(f.layout, "columns");
  ASSERT_EQ(f.cells.size(), shown_fields(fit).size()) << "a header row, then every field but edge";
  for (int c : f.cells) EXPECT_EQ(c, 1 + 3);
  for (int k = 0; k < 3; ++k) EXPECT_NE(html.find("<th title=\"edge: " + std::to_string(k) + "\">"), std::string::npos);
  // routes: one column per route
  const ShownTable rt = shown_table(html, "routes");
  EXPECT_EQ(rt.layout, "columns");
  ASSERT_FALSE(rt.cells.empty());
  for (int c : rt.cells) EXPECT_EQ(c, 1 + static_cast<int>(routes.size()));
  // seven objects: a header row and one row per object, one column per shown field
  // (name, value, note, sub.a, sub.b; "nothing" is null everywhere)
  const ShownTable mt = shown_table(html, "many");
  EXPECT_EQ(mt.layout, "rows");
  ASSERT_EQ(mt.cells.size(), 1u + 7u);
  for (int c : mt.cells) EXPECT_EQ(c, 5);
  // no raw JSON of a list in the page's tables
  EXPECT_EQ(html.find("<td>[{"), std::string::npos);
  const size_t numbers_at = html.find("<th>numbers</th><td title=\"[0, 0.125");
  ASSERT_NE(numbers_at, std::string::npos);
  const size_t cell = html.find("\">", numbers_at) + 2, cell_end = html.find("</td>", cell);
  EXPECT_EQ(html.substr(cell_end - 3, 3), "…");
  EXPECT_LE(cell_end - cell, 240u + 3u);

  // nothing in the side panel is wider than the panel, and it does not scroll sideways
  ASSERT_TRUE(std::regex_search(html, m, std::regex("data-wide=\"([0-9]+)\" data-wide-names=\"([^\"]*)\" data-scroll=\"(-?[0-9]+)\"")))
      << "the probe did not run";
  EXPECT_EQ(std::stoi(m[1]), 0) << m[2];
  EXPECT_LE(std::stoi(m[3]), 0);

  // the legend: 5 ticks at lo + k (hi - lo) / 4 over the report's mean_curvature {min, max},
  // each labelled with its value
  const double lo = report["mean_curvature"]["min"], hi = report["mean_curvature"]["max"], step = (hi - lo) / 4;
  const size_t ticks_at = html.find("<div id=\"bpde-ticks\">");
  ASSERT_NE(ticks_at, std::string::npos);
  const std::string legend = html.substr(ticks_at, html.find("</p>", ticks_at) - ticks_at);
  const std::regex tick("<div class=\"bpde-tick\" data-value=\"([^\"]+)\"[^>]*>([^<]*)</div>");
  std::vector<std::pair<double, double>> ticks;  // value, label
  for (auto it = std::sregex_iterator(legend.begin(), legend.end(), tick); it != std::sregex_iterator(); ++it)
    ticks.emplace_back(std::stod((*it)[1]), std::stod((*it)[2]));
  ASSERT_GE(ticks.size(), 3u);
  ASSERT_EQ(ticks.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_NEAR(ticks[k].first, lo + k * step, 1e-9 * std::abs(step)) << k;
    EXPECT_NEAR(ticks[k].second, lo + k * step, 0.1 * std::abs(step)) << k;
  }
}
