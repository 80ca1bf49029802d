// jobs/sweep.h: the expansion of a sweep (product, order, paths, the boundary builder), the rows of
// run_sweep_job, the thread pool against one thread, resume, and the CSV.
#include "bezierpde/jobs/sweep.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "bezierpde/core/errors.h"
#include "bezierpde/io/json_io.h"

namespace {

namespace fs = std::filesystem;
using bpde::Json;

fs::path tmp(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("bpde_sweep_" + std::to_string(::getpid())) / name;
  fs::remove_all(p);
  fs::create_directories(p.parent_path());
  return p;
}

Json circle_spec() {
  return Json::parse(R"({
    "base": {"net": {"type": "triangular", "degree": 4}, "fixed": "boundary",
             "problem": {"kind": "cmc", "solver": "newton", "H": -1.0}, "samples": 8},
    "boundary": "circle-three-arcs",
    "axes": {"problem.H": [-0.5, -3.0], "net.degree": [1, 3, 4]}})");
}

Json without_seconds(Json row) {
  row.erase("seconds");
  return row;
}

TEST(SweepExpand, ProductInPathOrderLastFastest) {
  const bpde::SweepSpec spec = bpde::sweep_from_json(circle_spec());
  ASSERT_EQ(spec.axes.size(), 2u);
  EXPECT_EQ(spec.axes[0].path, "net.degree");  // sorted paths
  EXPECT_EQ(spec.axes[1].path, "problem.H");
  const std::vector<bpde::SweepJob> jobs = bpde::expand_sweep(spec);
  ASSERT_EQ(jobs.size(), 6u);
  const int degrees[] = {1, 1, 3, 3, 4, 4};
  const double Hs[] = {-0.5, -3.0, -0.5, -3.0, -0.5, -3.0};
  for (int k = 0; k < 6; ++k) {
    EXPECT_EQ(jobs[k].index, k);
    EXPECT_EQ(jobs[k].id, "job-000" + std::to_string(k));
    EXPECT_EQ(jobs[k].values["net.degree"], degrees[k]);
    EXPECT_EQ(jobs[k].values["problem.H"], Hs[k]);
    EXPECT_EQ(jobs[k].job["problem"]["H"], Hs[k]);
    EXPECT_EQ(jobs[k].job["problem"]["solver"], "newton");  // the base's other fields stay
    EXPECT_TRUE(jobs[k].error.empty());
  }
}

TEST(SweepExpand, TheBoundaryFollowsTheDegree) {
  const std::vector<bpde::SweepJob> jobs = bpde::expand_sweep(bpde::sweep_from_json(circle_spec()));
  for (const bpde::SweepJob& j : jobs) {
    const int n = j.values["net.degree"].get<int>();
    const Json& net = j.job["net"];
    EXPECT_EQ(net["type"], "triangular");
    EXPECT_EQ(net["degree"], n);
    ASSERT_EQ(net["points"].size(), static_cast<size_t>((n + 1) * (n + 2) / 2));
    // P_{n00} (the first point) at angle 0 and P_{0n0} (index n: i = 0, j = n) at 2π/3, on the unit circle.
    EXPECT_NEAR(net["points"][0][0].get<double>(), 1.0, 1e-15);
    EXPECT_NEAR(net["points"][0][1].get<double>(), 0.0, 1e-15);
    const Json& p = net["points"][static_cast<size_t>(n * (n + 1) / 2 + 0)];  // i = 0 row starts here
    EXPECT_NEAR(p[0].get<double>(), std::cos(2 * std::numbers::pi / 3), 1e-15);
    EXPECT_NEAR(p[1].get<double>(), std::sin(2 * std::numbers::pi / 3), 1e-15);
  }
}

TEST(SweepExpand, PathsIntoArraysAndNewObjects) {
  Json spec = Json::parse(R"({"base": {"net": {"type": "tensor", "degree": [3, 3]}},
                             "axes": {"net.degree.1": [4, 5], "problem.kind": ["extremal"]}})");
  const std::vector<bpde::SweepJob> jobs = bpde::expand_sweep(bpde::sweep_from_json(spec));
  ASSERT_EQ(jobs.size(), 2u);
  EXPECT_EQ(jobs[1].job["net"]["degree"], Json::parse("[3, 5]"));
  EXPECT_EQ(jobs[0].job["problem"]["kind"], "extremal");
  // An index past the array is that job's error, not an exception.
  spec["axes"] = Json::parse(R"({"net.degree.7": [1]})");
  const std::vector<bpde::SweepJob> bad = bpde::expand_sweep(bpde::sweep_from_json(spec));
  ASSERT_EQ(bad.size(), 1u);
  EXPECT_NE(bad[0].error.find("out of range"), std::string::npos);
}

TEST(SweepExpand, NoAxesIsOneJob) {
  const Json spec = Json::parse(R"({"base": {"net": {"type": "triangular", "degree": 3}}})");
  EXPECT_EQ(bpde::expand_sweep(bpde::sweep_from_json(spec)).size(), 1u);
}

TEST(SweepSpec, BadSpecsThrowTypedErrors) {
  EXPECT_THROW(bpde::sweep_from_json(Json::parse(R"({"axes": {}})")), bpde::ParseError);  // no base
  EXPECT_THROW(bpde::sweep_from_json(Json::parse(R"({"base": {}, "extra": 1})")), bpde::ParseError);
  EXPECT_THROW(bpde::sweep_from_json(Json::parse(R"({"base": {}, "axes": {"a": []}})")), bpde::ParseError);
  EXPECT_THROW(bpde::sweep_from_json(Json::parse(R"({"base": {}, "axes": {"a..b": [1]}})")), bpde::ParseError);
  // an axis named like a column of the results table would overwrite it; a path into the job is fine
  for (const char* column : {"index", "job", "status", "H"})
    EXPECT_THROW(bpde::sweep_from_json(Json::parse(std::string(R"({"base": {}, "axes": {")") + column + R"(": [1]}})")),
                 bpde::ParseError)
        << column;
  EXPECT_NO_THROW(bpde::sweep_from_json(Json::parse(R"({"base": {}, "axes": {"problem.H": [1]}})")));
  EXPECT_THROW(bpde::sweep_from_json(Json::parse(R"({"base": {}, "boundary": "moebius"})")), bpde::ParameterError);
  EXPECT_THROW(bpde::sweep_from_json(Json::parse(R"({"base": "no-such-job.json"})")), bpde::FileError);
  Json big = Json::parse(R"({"base": {}, "axes": {}})");
  Json values = Json::array();
  for (int i = 0; i < 100; ++i) values.push_back(i);
  for (const char* a : {"a", "b", "c"}) big["axes"][a] = values;  // 10^6 jobs
  EXPECT_THROW(bpde::sweep_from_json(big), bpde::SizeError);
}

TEST(SweepSpec, AxisPathsAreAsDeepAsTheReadersTake) {
  const auto path_of = [](int segments) {
    std::string p = "a";
    for (int i = 1; i < segments; ++i) p += ".a";
    return p;
  };
  Json spec = Json::parse(R"({"base": {}, "axes": {}})");
  spec["axes"][path_of(bpde::kMaxJsonDepth)] = Json::array({1});
  const std::vector<bpde::SweepJob> jobs = bpde::expand_sweep(bpde::sweep_from_json(spec));
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].error, "");
  // The expanded job is one a reader takes back: its nesting is at the limit, not past it.
  EXPECT_NO_THROW(bpde::parse_json(jobs[0].job.dump(), "job"));
  for (const int segments : {bpde::kMaxJsonDepth + 1, 100000}) {
    spec["axes"] = Json::object();
    spec["axes"][path_of(segments)] = Json::array({1});
    EXPECT_THROW(bpde::sweep_from_json(spec), bpde::ParseError) << segments;
  }
}

TEST(SweepSpec, BaseFileRelativeToTheSweepFile) {
  const fs::path d = tmp("basefile");
  fs::create_directories(d);
  std::ofstream(d / "job.json") << R"({"net": {"type": "triangular", "degree": 3}, "problem": {"kind": "cmc"}})";
  std::ofstream(d / "sweep.json") << R"({"base": "job.json", "axes": {"problem.H": [-0.25]}})";
  const std::vector<bpde::SweepJob> jobs = bpde::expand_sweep(bpde::read_sweep_file((d / "sweep.json").string()));
  ASSERT_EQ(jobs.size(), 1u);
  EXPECT_EQ(jobs[0].job["problem"]["H"], -0.25);
  EXPECT_EQ(jobs[0].job["net"]["degree"], 3);
}

TEST(SweepBoundary, PluggableBuilders) {
  bpde::register_sweep_boundary("test-plane", [](const Json& degree) {
    const int n = degree.get<int>();
    Json pts = Json::array();
    for (int i = n; i >= 0; --i)
      for (int j = n - i; j >= 0; --j) pts.push_back({double(i) / n, double(j) / n, 0.0});
    return Json{{"type", "triangular"}, {"degree", n}, {"points", pts}};
  });
  const std::vector<std::string> names = bpde::sweep_boundary_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "test-plane"), names.end());
  EXPECT_NE(std::find(names.begin(), names.end(), "sphere-square"), names.end());
  EXPECT_EQ(bpde::build_sweep_boundary("test-plane", 2)["points"].size(), 6u);
  EXPECT_EQ(bpde::build_sweep_boundary("sphere-square", Json::parse("[3, 3]"))["points"].size(), 16u);
  EXPECT_THROW(bpde::build_sweep_boundary("sphere-square", Json::parse("[3, 4]")), bpde::DegreeError);
  EXPECT_THROW(bpde::build_sweep_boundary("circle-three-arcs", 0), bpde::DegreeError);
  EXPECT_THROW(bpde::build_sweep_boundary("nothing", 3), bpde::ParameterError);
}

TEST(SweepRun, RowsThreadsResume) {
  const bpde::SweepSpec spec = bpde::sweep_from_json(circle_spec());
  const fs::path a = tmp("one-thread"), b = tmp("two-threads");
  bpde::SweepRunOptions one;
  one.jobs = 1;
  int calls = 0, last_done = -1;
  one.on_progress = [&calls, &last_done](const bpde::SweepProgress& p) {
    ++calls;
    EXPECT_EQ(p.total, 6);
    EXPECT_EQ(p.done, last_done + 1);  // jobs done of jobs: 0, 1, ..., 6
    last_done = p.done;
  };
  const std::vector<Json> rows = bpde::run_sweep(spec, a.string(), one);
  EXPECT_EQ(calls, 7);  // once before, once per job
  EXPECT_EQ(last_done, 6);
  ASSERT_EQ(rows.size(), 6u);
  // Degree 1: the cmc requirements refuse it -> exit 2 row, no result.json.
  EXPECT_EQ(rows[0]["status"], "invalid-input");
  EXPECT_EQ(rows[0]["exit_code"], 2);
  EXPECT_NE(rows[0]["error"].get<std::string>().find("degree"), std::string::npos);
  EXPECT_FALSE(fs::exists(a / "jobs" / "job-0000" / "result.json"));
  EXPECT_TRUE(fs::exists(a / "jobs" / "job-0000" / "job.json"));
  // Degree 4 at H = -0.5 converges; at H = -3 it folds near |H| = 1.5558 (examples/004-cmc-circle).
  EXPECT_EQ(rows[4]["status"], "converged");
  EXPECT_EQ(rows[4]["exit_code"], 0);
  EXPECT_EQ(rows[5]["status"], "fold");
  EXPECT_EQ(rows[5]["exit_code"], 1);
  EXPECT_NEAR(rows[5]["H"].get<double>(), -1.5558, 1e-3);
  EXPECT_TRUE(rows[5]["error"].is_string());
  // The row's figures are result.json's.
  const Json result = bpde::read_json_file((a / "jobs" / "job-0004" / "result.json").string());
  EXPECT_EQ(rows[4]["energy"], result["report"]["energy"]);
  EXPECT_EQ(rows[4]["H_mean"], result["report"]["mean_curvature"]["mean"]);
  EXPECT_EQ(rows[4]["check_self_intersections"], result["report"]["check"]["self_intersections"]);
  EXPECT_GE(rows[4]["seconds"].get<double>(), 0.0);
  EXPECT_TRUE(rows[4]["boundary_error"].is_null());  // a net job: no boundary fit

  // Two threads: the same rows (but wall times), in index order.
  bpde::SweepRunOptions two;
  two.jobs = 2;
  std::vector<int> done2;  // serialised: never falling, also from two threads
  two.on_progress = [&done2](const bpde::SweepProgress& p) { done2.push_back(p.done); };
  const std::vector<Json> rows2 = bpde::run_sweep(spec, b.string(), two);
  ASSERT_EQ(done2.size(), 7u);
  for (size_t k = 0; k < done2.size(); ++k) EXPECT_EQ(done2[k], static_cast<int>(k));
  for (size_t k = 0; k < rows.size(); ++k) EXPECT_EQ(without_seconds(rows2[k]), without_seconds(rows[k])) << k;

  // Resume: nothing reruns (the rows, seconds included, are the stored ones) unless its job changed.
  int resumed = -1;
  two.on_progress = [&resumed](const bpde::SweepProgress& p) {
    if (!p.row) resumed = p.resumed;
  };
  EXPECT_EQ(bpde::run_sweep(spec, b.string(), two), rows2);
  EXPECT_EQ(resumed, 6);
  std::ofstream(b / "jobs" / "job-0003" / "job.json") << "{}";
  const std::vector<Json> rows3 = bpde::run_sweep(spec, b.string(), two);
  EXPECT_EQ(resumed, 5);
  EXPECT_EQ(without_seconds(rows3[3]), without_seconds(rows2[3]));

  // The tables.
  std::ifstream csv(b / "results.csv");
  std::string header;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("index,job,net.degree,problem.H,status,exit_code,converged,energy,residual,H,", 0), 0u)
      << header;
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 6);
  std::ifstream jsonl(b / "results.jsonl");
  int k = 0;
  for (std::string line; std::getline(jsonl, line); ++k) EXPECT_EQ(Json::parse(line), rows3[static_cast<size_t>(k)]);
  EXPECT_EQ(k, 6);
}

// A base job in the boundary form (FORMATS.md "Boundary curves") with the degree as an axis: the
// boundary is fitted at each job's degree, and the row's boundary_error is the largest max_error of
// the report's boundary_fit. Corners kept (smooth_corner_angle 0), so the Dirichlet jobs get the
// interpolant (docs/boundaries.md's table: 1.17e-3, 8.03e-6, 3.12e-8 at n = 4, 6, 8) and the area
// jobs the geometric fit by default (3.0e-6 at n = 4, 4.3e-11 at n = 6).
TEST(SweepRun, BoundaryFormWithTheDegreeAsAnAxis) {
  const double third = 2 * std::numbers::pi / 3;
  Json edges = Json::array();
  for (int e = 0; e < 3; ++e)
    edges.push_back({{"type", "arc"},
                     {"center", {0, 0, 0}},
                     {"normal", {0, 0, 1}},
                     {"radius", 1},
                     {"angles", {e == 0 ? -third : (e - 1) * third, e == 0 ? 0.0 : e * third}}});
  Json spec = {{"base",
                {{"boundary", {{"type", "triangular"}, {"degree", 3}, {"edges", edges}, {"smooth_corner_angle", 0}}},
                 {"fixed", "boundary"},
                 {"problem", {{"kind", "cmc"}, {"H", -0.5}}},
                 {"samples", 8}}},
               {"axes", {{"boundary.degree", {4, 6, 8}}, {"problem.functional", {"area", "dirichlet"}}}}};
  const fs::path dir = tmp("boundary-form");
  const std::vector<Json> rows = bpde::run_sweep(bpde::sweep_from_json(spec), dir.string());
  ASSERT_EQ(rows.size(), 6u);
  const double interpolated[3] = {1.17e-3, 8.03e-6, 3.12e-8};
  for (size_t k = 0; k < rows.size(); ++k) {
    const Json result =
        bpde::read_json_file((dir / "jobs" / rows[k]["job"].get<std::string>() / "result.json").string());
    double worst = 0;
    for (const Json& e : result["report"]["boundary_fit"]) worst = std::max(worst, e["max_error"].get<double>());
    EXPECT_EQ(rows[k]["boundary_error"].get<double>(), worst) << k;
    const bool area = rows[k]["problem.functional"] == "area";
    const double interp = interpolated[k / 2];
    if (area) {
      EXPECT_EQ(result["report"]["boundary_fit"][0]["method"], "geometric");
      EXPECT_LT(worst, 1e-2 * interp) << k;
    } else {
      EXPECT_EQ(result["report"]["boundary_fit"][0]["method"], "interpolation");
      EXPECT_NEAR(worst, interp, 0.01 * interp) << k;
    }
    EXPECT_EQ(rows[k]["status"], "converged") << k << " " << rows[k].dump();
  }
  // A row.json without a column (written by an older version) is run again on resume.
  const fs::path old_row = dir / "jobs" / rows[2]["job"].get<std::string>() / "row.json";
  Json r = bpde::read_json_file(old_row.string());
  r.erase("boundary_error");
  std::ofstream(old_row) << r.dump() << "\n";
  bpde::SweepRunOptions o;
  int resumed = -1;
  o.on_progress = [&resumed](const bpde::SweepProgress& p) {
    if (!p.row) resumed = p.resumed;
  };
  const std::vector<Json> again = bpde::run_sweep(bpde::sweep_from_json(spec), dir.string(), o);
  EXPECT_EQ(resumed, 5);
  EXPECT_EQ(again[2]["boundary_error"], rows[2]["boundary_error"]);
}

TEST(SweepCsv, QuotingAndNumbers) {
  bpde::SweepSpec spec;
  spec.axes.push_back({"net.degree", {Json::parse("[3, 4]")}});
  Json row = {{"index", 0},
              {"job", "job-0000"},
              {"net.degree", Json::parse("[3,4]")},
              {"energy", 0.1},
              {"error", "a, \"quoted\" message"},
              {"converged", false},
              {"residual", nullptr}};
  const std::string csv = bpde::sweep_csv(spec, {row});
  const std::string line = csv.substr(csv.find('\n') + 1);
  EXPECT_EQ(line.rfind("0,job-0000,\"[3,4]\",,,false,0.10000000000000001,,", 0), 0u) << line;
  EXPECT_NE(line.find("\"a, \"\"quoted\"\" message\""), std::string::npos) << line;
}

}  // namespace
