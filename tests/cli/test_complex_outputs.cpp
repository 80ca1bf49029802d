// bpde sample, check, view and export on a patch complex (FORMATS.md "Patch complexes"): the
// result.json of a complex job or its bare "net", read by io/complex_json.h. Exit codes, the files
// written, their vertex and triangle counts (from the layout's counts of vertices, edges and faces,
// not from the mesh code), the CGAL checks across patches and the STEP shell; and the reader's
// typed errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <utility>
#include <string>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/complex_json.h"
#include "bezierpde/io/json_io.h"
#include "bezierpde/io/step_export.h"
#include "tests/cli/cli_run.h"

namespace fs = std::filesystem;

namespace {

using bpde::Json;
using bpde::testing::CmdResult;
using bpde::testing::run;
using bpde::testing::slurp;
using bpde::testing::tmpdir;
using bpde::testing::write;

const std::string kCircle = R"({"type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "radius": 1})";

/// Solves a complex job over the unit circle and returns its folder.
fs::path solved(const std::string& name, const std::string& patch, int degree, int refine, const std::string& extra = "") {
  const fs::path job = write(name + ".json", R"({"boundary": {"type": "complex", "patch": ")" + patch +
                                                 R"(", "degree": )" + std::to_string(degree) + R"(, "refine": )" +
                                                 std::to_string(refine) + R"(, "loops": [[)" + kCircle +
                                                 R"(]]}, "problem": {"kind": "extremal", "energy": {"name": "dirichlet"}},
                                                 "samples": 4)" + extra + "}");
  const fs::path out = tmpdir() / ("complex_out_" + name);
  fs::remove_all(out);
  const CmdResult r = run("solve " + job.string() + " --out " + out.string() + " --quiet");
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

/// Lines of a text file that start with `prefix`.
long count_lines(const fs::path& p, const std::string& prefix) {
  const std::string s = slurp(p);
  long k = 0;
  for (std::size_t at = 0; at < s.size();) {
    const std::size_t end = std::min(s.find('\n', at), s.size());
    if (s.compare(at, prefix.size(), prefix) == 0) ++k;
    at = end + 1;
  }
  return k;
}

// The refined fan over the circle: 6 triangles around a centre, refined once: 24 patches,
// V = 19 vertices, E = 42 edges (12 on the boundary), F = 24 (V - E + F = 1, 3F = 2E - 12).
// Welded at N samples per edge: V + E (N - 1) + F (N - 1)(N - 2)/2 vertices, F N² triangles.
long fan_vertices(int N) { return 19 + 42L * (N - 1) + 24L * (N - 1) * (N - 2) / 2; }
// The O-grid of a circle: a ring of 4 quads around one: V = 8, E = 12, F = 5;
// V + E (N - 1) + F (N - 1)² vertices, 2 F N² triangles.
long ogrid_vertices(int N) { return 8 + 12L * (N - 1) + 5L * (N - 1) * (N - 1); }

void expect_bad_input(const std::string& args, const fs::path& never) {
  SCOPED_TRACE(args);
  const CmdResult r = run(args);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
  if (!never.empty()) {
    EXPECT_FALSE(fs::exists(never));
  }
}

/// Two triangular patches of degree 2 sharing the edge A -> B: patch 0 flat in z = 0 over the
/// triangle A, B, C; patch 1 (B, A, D) rises to D above patch 0 with its middle control points
/// pulled below z = 0, so that it passes through patch 0 away from their common edge.
std::string crossing_complex(double dip) {
  const std::string d = std::to_string(-dip);
  return R"({"type": "complex", "patch": "triangular", "degree": 2, "refine": 0,
    "layout": {"vertices": [[0,0,0], [1,0,0], [0.5,1,0], [0.5,-1,0]], "faces": [[0,1,2], [1,0,3]]},
    "patches": [
      {"type": "triangular", "degree": 2, "points": [[1,0,0], [0.75,0.5,0], [0.5,0,0], [0.5,1,0], [0.25,0.5,0], [0,0,0]]},
      {"type": "triangular", "degree": 2, "points": [[0,0,0], [0.25,0.4,)" + d + R"(], [0.5,0,0], [0.5,0.8,1], [0.75,0.4,)" +
         d + R"(], [1,0,0]]}]})";
}

}  // namespace

TEST(ComplexOutputs, SampleWritesTheWeldedMeshOfAResultAndOfItsBareNet) {
  const fs::path dir = solved("fan", "triangular", 4, 1);
  const Json result = bpde::read_json_file((dir / "result.json").string());
  const fs::path bare = write("fan_net.json", result["net"].dump());
  for (const fs::path& input : {dir / "result.json", bare}) {
    SCOPED_TRACE(input.string());
    const fs::path out = tmpdir() / ("fan_sample_" + input.stem().string());
    const CmdResult r = run("sample " + input.string() + " --out " + out.string() + " --samples 5");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(bpde::testing::printed_files(r.out),
              (std::vector<fs::path>{out / "surface.obj", out / "surface.ply", out / "surface.vtp", out / "net.obj"}));
    EXPECT_EQ(count_lines(out / "surface.obj", "v "), fan_vertices(5));
    EXPECT_EQ(count_lines(out / "surface.obj", "f "), 24 * 25);
    EXPECT_NE(slurp(out / "surface.vtp").find("Name=\"patch\""), std::string::npos);
    // net.obj: every control point once: 19 + 42·3 + 24·3 rows at degree 4
    EXPECT_EQ(count_lines(out / "net.obj", "v "), 19 + 42 * 3 + 24 * 3);
    EXPECT_EQ(r.err, "");
  }
}

TEST(ComplexOutputs, SampleOfATensorComplexAndTheSampleLimit) {
  const fs::path dir = solved("ogrid", "tensor", 3, 0);
  const fs::path out = tmpdir() / "ogrid_sample";
  const CmdResult r = run("sample " + (dir / "result.json").string() + " --out " + out.string() + " --samples 6 --quiet");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(count_lines(out / "surface.obj", "v "), ogrid_vertices(6));
  EXPECT_EQ(count_lines(out / "surface.obj", "f "), 2 * 5 * 36);
  // 5 patches at 2000 samples are 5 · 2001² vertices, more than one mesh may hold
  expect_bad_input("sample " + (dir / "result.json").string() + " --out " + (tmpdir() / "never_big").string() +
                       " --samples 2000",
                   tmpdir() / "never_big");
}

TEST(ComplexOutputs, CheckCountsIntersectionsBetweenPatches) {
  // the disc: no intersection, open
  const fs::path dir = solved("fan_check", "triangular", 3, 0);
  CmdResult r = run("check " + (dir / "result.json").string() + " --samples 8");
  ASSERT_EQ(r.status, 0) << r.err;
  Json j = Json::parse(r.out);
  EXPECT_EQ(j["self_intersections"], 0);
  EXPECT_FALSE(j["closed"].get<bool>());

  // two patches that pass through each other: each alone is free of intersections
  const Json crossing = Json::parse(crossing_complex(0.6));
  for (int p = 0; p < 2; ++p) {
    const fs::path single = write("crossing_patch" + std::to_string(p) + ".json", crossing["patches"][p].dump());
    r = run("check " + single.string() + " --samples 12");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(Json::parse(r.out)["self_intersections"], 0) << p;
  }
  r = run("check " + write("crossing.json", crossing.dump()).string() + " --samples 12");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GT(Json::parse(r.out)["self_intersections"].get<int>(), 0);
  // pulled up above z = 0 instead, patch 1 only meets patch 0 along their common edge
  r = run("check " + write("not_crossing.json", crossing_complex(-0.2)).string() + " --samples 12");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(Json::parse(r.out)["self_intersections"], 0);
}

TEST(ComplexOutputs, ExportAndJobExportsWriteOneSewnShell) {
  const fs::path dir = solved("fan_step", "triangular", 4, 1, R"(, "export": ["step", "html"])");
  for (const char* name : {"surface.step", "view.html"}) EXPECT_TRUE(fs::exists(dir / name)) << name;
  const fs::path step = tmpdir() / "fan_export.step";
  const CmdResult r = run("export " + (dir / "result.json").string() + " --step " + step.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(bpde::testing::printed_files(r.out), std::vector<fs::path>{step});
  for (const fs::path& file : {dir / "surface.step", step}) {
    SCOPED_TRACE(file.string());
    const bpde::StepTopology t = bpde::read_step_topology(file.string());
    EXPECT_TRUE(t.valid);
    EXPECT_EQ(t.shells, 1);
    EXPECT_EQ(t.faces, 24);
    EXPECT_EQ(t.free_edges, 12);  // the boundary edges of the refined fan
  }
}

TEST(ComplexOutputs, ViewWritesThePageOfAComplexResult) {
  const fs::path dir = solved("fan_view", "triangular", 3, 1);
  const CmdResult r = run("view " + dir.string() + " --samples 4");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(bpde::testing::printed_files(r.out), std::vector<fs::path>{dir / "view.html"});
  const std::string page = slurp(dir / "view.html");
  EXPECT_NE(page.find("\"seams\""), std::string::npos);
  EXPECT_NE(page.find("\"vertices\":" + std::to_string(fan_vertices(4))), std::string::npos);
}

TEST(ComplexOutputs, BadComplexNetsExitTwoAndWriteNothing) {
  const fs::path dir = solved("fan_bad", "triangular", 2, 0);
  const Json net = bpde::read_json_file((dir / "result.json").string())["net"];
  auto expect_refused = [&](const std::string& name, const Json& bad) {
    SCOPED_TRACE(name);
    const fs::path file = write("bad_" + name + ".json", bad.dump());
    const fs::path out = tmpdir() / ("never_" + name);
    expect_bad_input("sample " + file.string() + " --out " + out.string(), out);
    expect_bad_input("check " + file.string(), {});
    expect_bad_input("export " + file.string() + " --step " + out.string() + ".step", out.string() + ".step");
  };
  Json bad = net;
  bad["patches"][1]["points"][3][0] = nullptr;  // not a number
  expect_refused("null_point", bad);
  bad = net;
  bad["patches"].erase(bad["patches"].size() - 1);
  expect_refused("patch_missing", bad);
  bad = net;
  bad["patches"][0]["points"][0][2] = 0.5;  // a corner, which the neighbouring patches share
  expect_refused("seam_gap", bad);
  bad = net;
  bad["colour"] = "red";
  expect_refused("unknown_field", bad);
  bad = net;
  bad["degree"] = 3;
  expect_refused("degree_mismatch", bad);
  bad = net;
  bad["layout"]["faces"][0] = {0, 1};
  expect_refused("short_face", bad);
  bad = net;
  bad["layout"]["boundary"].erase(0);
  expect_refused("boundary_edge_missing", bad);
  // a single-net subcommand refuses a complex with its own line
  expect_bad_input("energy " + (dir / "result.json").string() + " --energy dirichlet", {});
}

TEST(ComplexNetReader, ResultNetReadsBackExactlyWithItsSharedRows) {
  const fs::path dir = solved("fan_read", "triangular", 3, 1);
  const Json net = bpde::read_json_file((dir / "result.json").string())["net"];
  const bpde::ComplexNetFile c = bpde::complex_net_from_json(net, "net");
  EXPECT_EQ(c.complex.patches.size(), 24u);
  EXPECT_EQ(c.refine, 1);
  // rows: 19 vertices + 42 edges · 2 + 24 inner points at degree 3
  EXPECT_EQ(c.complex.points.rows(), 19 + 42 * 2 + 24);
  EXPECT_EQ(bpde::complex_net_to_json(c), net);
}

TEST(ComplexNetReader, TypedErrors) {
  const fs::path dir = solved("fan_types", "triangular", 2, 0);
  const Json net = bpde::read_json_file((dir / "result.json").string())["net"];
  auto with = [&](auto&& change) {
    Json j = net;
    change(j);
    return j;
  };
  using namespace bpde;
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["degree"] = 21; }), "net"), DegreeError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["refine"] = 6; }), "net"), SizeError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["patches"].erase(0); }), "net"), SizeError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["patches"][0]["type"] = "tensor"; }), "net"), ParseError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["patch"] = "hexagonal"; }), "net"), ParseError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["layout"]["vertices"][0][0] = "x"; }), "net"), ParseError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["patches"][2]["points"][0][1] = 0.25; }), "net"),
               ParameterError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j["layout"]["faces"][1][0] = 99; }), "net"), ParameterError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) {
                                       Json& b = j["layout"]["boundary"][0];
                                       std::swap(b["from"], b["to"]);  // against its face's direction
                                     }),
                                     "net"),
               LayoutMismatchError);
  EXPECT_THROW(complex_net_from_json(with([](Json& j) { j.erase("layout"); }), "net"), ParseError);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(complex_net_from_json(with([&](Json& j) { j["patches"][1]["points"][4][2] = nan; }), "net"),
               NonFiniteError);
  EXPECT_THROW(complex_net_from_json(with([&](Json& j) { j["layout"]["vertices"][1][0] = nan; }), "net"),
               NonFiniteError);
  // the bare layout.boundary is optional
  const ComplexNetFile plain = complex_net_from_json(with([](Json& j) { j["layout"].erase("boundary"); }), "net");
  EXPECT_TRUE(plain.boundary.empty());
  EXPECT_EQ(plain.complex.patches.size(), 6u);
}
